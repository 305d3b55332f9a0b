"""Design search: pairs for a housing and a load, on threads or a Dask cluster.

The names below are imported on first use (:mod:`gears.lazy`): importing one module of the
family does not load the rest.
"""

from gears.lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "check_table_output": "gears.search.engine",
        "dask_client": "gears.search.engine",
        "dask_results": "gears.search.engine",
        "Estimate": "gears.search.engine",
        "estimate": "gears.search.engine",
        "evaluate_chunk": "gears.search.engine",
        "in_kept_heap": "gears.search.engine",
        "kept_heap": "gears.search.engine",
        "Limits": "gears.search.engine",
        "pairs": "gears.search.engine",
        "SearchResult": "gears.search.engine",
        "write_table": "gears.search.engine",
    },
)
