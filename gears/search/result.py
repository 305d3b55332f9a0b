"""Layer 10, results: :class:`SearchResult`, the ranked (or Pareto) pairs of a search as a table."""

from __future__ import annotations

import math
from collections.abc import Sequence

from gears.display import html_table
from gears.errors import GearError
from gears.search.candidates import _KEYS, _Space
from gears.search.tables import write_table

__all__ = ["SearchResult"]

#: rows a notebook shows of a search result (its text form has them all)
_HTML_ROWS = 50


class SearchResult:
    """The ranked (or Pareto) pairs of a search: a numpy structured array with named columns.

    ``result.table`` is the array (``result["z1"]``, ``len(result)``, iteration work on it);
    ``result.pair(i)`` builds row ``i`` as a :class:`gears.GearPair`; ``to_pandas()`` and
    ``to_parquet(path)`` export it.

    Attributes
    ----------
    examined : int
        Candidates checked.
    feasible : int
        Candidates that met every limit.
    chunks : int
    seconds : float
        Wall time of the search.
    """

    def __init__(self, table, examined, feasible, chunks, seconds, space: _Space):
        self.table = table
        self.examined = int(examined)
        self.feasible = int(feasible)
        self.chunks = int(chunks)
        self.seconds = float(seconds)
        self._space = space

    @property
    def columns(self) -> tuple[str, ...]:
        return tuple(self.table.dtype.names)

    def __len__(self) -> int:
        return len(self.table)

    def __getitem__(self, key):
        return self.table[key]

    def __iter__(self):
        return iter(self.table)

    @property
    def rate(self) -> float:
        """Candidates checked per second."""
        return self.examined / self.seconds if self.seconds > 0 else math.inf

    @property
    def dataset(self) -> str | None:
        """The folder the rows were written to (``dataset=``), else None."""
        return self._space.dataset

    def pair(self, i: int = 0):
        """Row ``i`` as a :class:`gears.GearPair` (its ``check()`` gives the same margins; with
        a face width, both gears carry it)."""
        from gears.gear import Gear
        from gears.pair import GearPair

        r = self.table[i]
        sp = self._space
        beta = float(r["helix_angle"])
        common = {"module": float(r["module"]), "pressure_angle": sp.pressure_angle,
                  "rack": sp.rack}  # fmt: skip
        if "face_width" in self.columns:
            common["face_width"] = float(r["face_width"])
        g1 = Gear(int(r["z1"]), profile_shift=float(r["x1"]), helix_angle=beta, **common)
        g2 = Gear(int(r["z2"]), profile_shift=float(r["x2"]), internal=sp.internal,
                  helix_angle=beta if sp.internal else -beta, **common)  # fmt: skip
        return GearPair(g1, g2, sp.tip_shortening)

    def rating(self, i: int = 0):
        """Row ``i`` rated on its own: ``pair(i).rating(...)`` under the search's load case
        (torque, speed, materials, life, options, the row's face width, ``root="standard"``,
        the route the search rates by; a :class:`gears.rating.spectrum.SpectrumRating` for a
        search under a spectrum): the same safeties as the row's ``S_H1 ... S_F2``."""
        load = self._space.load
        if load is None:
            raise GearError("this search had no torque=: rate a row with "
                            "result.pair(i).rating(torque, speed, ...)")  # fmt: skip
        if load.spectrum is not None:  # the equivalent safeties of ISO 6336-6
            return self.pair(i).rating(material=load.materials, **load.rating_options())
        return self.pair(i).rating(load.torque, load.speed, load.materials,
                                   **load.rating_options())  # fmt: skip

    def to_pandas(self):
        """The table as a ``pandas.DataFrame`` (needs pandas: ``pip install pandas``)."""
        try:
            import pandas as pd
        except ImportError:
            raise GearError("to_pandas needs pandas: pip install pandas") from None
        return pd.DataFrame.from_records(self.table)

    def to_parquet(self, path) -> None:
        """Write the table to a ``.parquet`` file (needs pyarrow: the ``parquet`` extra)."""
        write_table(self.table, path, ".parquet")

    def format(self, columns: Sequence[str] | None = None) -> str:
        """A ranked text table (default: the parameters, a, eps, sliding, efficiency; with a
        face width b and the volume, with a load the smaller safeties S_H and S_F)."""
        head, body = self._cells(columns)
        widths = [max(len(x) for x in col) for col in zip(head, *body, strict=False)]
        lines = ["  ".join(h.rjust(w) for h, w in zip(row, widths, strict=True))
                 for row in [head, *body]]  # fmt: skip
        return "\n".join(lines)

    def _cells(self, columns: Sequence[str] | None = None, rows: int | None = None):
        """Header and body cells (text) of the first ``rows`` ranked rows."""
        if not columns:
            columns = (*_KEYS, "center_distance", "contact_ratio", "sliding", "efficiency")
            if "face_width" in self.columns:
                columns = (*_KEYS, "face_width", "center_distance", "contact_ratio", "volume")
            if "S_H" in self.columns:
                columns = (*columns, "S_H", "S_F")
        body = []
        for i, r in enumerate(self.table[:rows], 1):
            cells = [str(i)]
            for c in columns:
                v = r[c]
                cells.append(str(int(v)) if c in ("z1", "z2") else f"{float(v):.6g}")
            body.append(cells)
        return ["#", *columns], body

    def _repr_html_(self) -> str:
        """The ranked table in HTML (the first 50 rows), what a notebook shows."""
        head, body = self._cells(rows=_HTML_ROWS)
        more = len(self) - len(body)
        caption = self._summary() + (f"; the first {len(body)} shown" if more > 0 else "")
        return html_table(head, body, caption=caption)

    def _summary(self) -> str:
        if self.dataset is not None:
            return (f"{self.feasible} feasible pairs among {self.examined} candidates "
                    f"({self.seconds:.3g} s), every one written to {self.dataset}")  # fmt: skip
        return (f"{len(self)} pairs of {self.feasible} feasible among {self.examined} candidates "
                f"({self.seconds:.3g} s)")  # fmt: skip

    def __str__(self) -> str:
        if self.dataset is not None:
            return self._summary()
        return f"{self._summary()}\n" + self.format()

    def __repr__(self) -> str:
        return (f"SearchResult({len(self)} rows, examined={self.examined}, "
                f"feasible={self.feasible})")  # fmt: skip
