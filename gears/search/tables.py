"""Layer 2, tables: a search's rows written to a file (Parquet or CSV), the path checked first.

:func:`gears.search.pairs` and ``trains.synthesize_gearbox`` write their tables with these (and
each chunk of a ``dataset=`` search its part file).
"""

from __future__ import annotations

import numpy as np

from gears.errors import GearError
from gears.files import check_output, writing

__all__ = ["TABLE_FORMATS", "check_table_output", "write_table"]

#: the suffixes a result table can be written as
TABLE_FORMATS = (".parquet", ".csv")


def check_table_output(path, suffix: str | None = None):
    """``path`` checked for :func:`write_table` before any work: a writable file name with a
    suffix of :data:`TABLE_FORMATS` (or ``suffix``) and, for Parquet, pyarrow importable
    (the ``parquet`` extra); a GearError saying which otherwise."""
    path = check_output(path, (suffix,) if suffix else TABLE_FORMATS)
    if (suffix or path.suffix).lower() == ".parquet":
        try:
            import pyarrow.parquet  # noqa: F401
        except ImportError:
            raise GearError(
                f"path {str(path)!r}: writing Parquet needs pyarrow: pip install "
                "'geartrain[parquet]' (or write .csv)"
            ) from None
    return path


def write_table(table: np.ndarray, path, suffix: str | None = None) -> None:
    """Write a structured array to ``path``: Parquet (``.parquet``, needs pyarrow, the
    ``parquet`` extra) or CSV (``.csv``, a header line of column names); the format follows
    the suffix. The path is checked first (:func:`check_table_output`)."""
    path = check_table_output(path, suffix)
    if (suffix or path.suffix).lower() == ".csv":
        import csv

        with writing(path), path.open("w", newline="") as f:
            out = csv.writer(f)
            out.writerow(table.dtype.names)
            out.writerows(row.tolist() if hasattr(row, "tolist") else row for row in table)
        return
    import pyarrow as pa
    import pyarrow.parquet as pq

    with writing(path):
        pq.write_table(pa.table({c: table[c] for c in table.dtype.names}), str(path))
