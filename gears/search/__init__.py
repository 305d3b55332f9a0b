"""Design search: pairs for a housing and a load, on threads or a Dask cluster.

The names below are imported on first use (:mod:`gears.lazy`): importing one module of the
family does not load the rest.
"""

from gears.lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "check_table_output": "gears.search.tables",
        "dask_client": "gears.search.cluster",
        "dask_results": "gears.search.cluster",
        "Estimate": "gears.search.engine",
        "estimate": "gears.search.engine",
        "evaluate_chunk": "gears.search.checks",
        "in_kept_heap": "gears.search.cluster",
        "kept_heap": "gears.search.cluster",
        "Limits": "gears.search.candidates",
        "pairs": "gears.search.engine",
        "SearchResult": "gears.search.result",
        "write_table": "gears.search.tables",
    },
)
