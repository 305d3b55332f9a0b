"""Layer 9, scheduling: a search's chunks run on a thread pool of the local cores (numpy releases
the GIL) or as Dask tasks, their reductions merged as they arrive, so memory never grows with the
number of candidates; a local search estimated over ``max_seconds`` is refused before any work.
"""

from __future__ import annotations

import contextlib
import itertools
from concurrent.futures import FIRST_COMPLETED, ThreadPoolExecutor, wait

import numpy as np

from gears.errors import GearError
from gears.geometry import check_real
from gears.report import format_duration
from gears.search.candidates import _dtype, _Space
from gears.search.checks import _LOCAL_BLOCK, evaluate_chunk
from gears.search.cluster import (
    _announce_dashboard,
    dask_results,
    dask_timeout,
    progress_callback,
)
from gears.search.reduction import _merge

#: candidates per second per local thread assumed by the size check (measured 1.2e6 on one
#: shared core, docs/performance.md)
LOCAL_RATE = 1.0e6
#: rated candidates (pair and face width) per second per local thread assumed by the size check
#: when a torque is given (measured 2-5 x 10^5 on one shared core, docs/performance.md)
RATED_RATE = 1.5e5
#: default limit on the estimated time of a local search, seconds
MAX_SECONDS = 600.0


def run_chunks(
    space: _Space, client, threads: int, chunk_size: int, progress, max_seconds: float
) -> tuple[np.ndarray, int, int, int]:
    """Run the search of ``space`` in chunks of ``chunk_size`` on ``threads`` local threads or on
    the Dask ``client``: ``(table, feasible, examined, chunks)``. A local search estimated over
    ``max_seconds`` is a GearError before any work; ``progress`` as in
    :func:`gears.search.pairs`."""
    check_real("max_seconds", max_seconds, 0.0)
    n = space.candidates
    if client is None:
        rate = (RATED_RATE if space.load is not None else LOCAL_RATE) * threads
        estimate = n / rate
        if estimate > max_seconds:
            raise GearError(
                f"the search has {n:,} candidates: about {format_duration(estimate)} on "
                f"{threads} local thread(s) at {rate / threads:.3g} candidates/s each, over the "
                f"limit max_seconds = {max_seconds:g} s; pass client= (a dask.distributed "
                "Client or scheduler address), narrow the space, or raise max_seconds"
            )
    if space.dataset is not None:
        _open_dataset(space.dataset)
    bounds = [(i, min(i + chunk_size, space.size)) for i in range(0, space.size, chunk_size)]
    report = progress_callback(progress, unit="candidate")
    if report is not None and client is not None and progress is not False:
        _announce_dashboard(client, progress)
    if client is None:
        parts = _run_local(space, bounds, threads, report)
    else:
        parts = _run_dask(space, bounds, client, report)
    table, feasible, examined = parts
    if space.pareto and space.top is not None:  # the front is whole until here; then its head
        table = table[: space.top]
    return table, feasible, examined, len(bounds)


def _open_dataset(path: str) -> None:
    import os

    try:
        os.makedirs(path, exist_ok=True)
    except OSError as exc:
        raise GearError(f"dataset = {path!r} cannot be made: {exc}") from None


def _run_local(space, bounds, threads, report):
    acc, feasible, examined, done = None, 0, 0, 0
    total = space.candidates
    if not bounds:
        return np.empty(0, _dtype(space.columns)), 0, 0
    if threads == 1:
        results = (evaluate_chunk(space, *b, _LOCAL_BLOCK) for b in bounds)
        for rows, f, c in results:
            acc, feasible, examined, done = _merge(acc, rows, space), feasible + f, examined + c, \
                done + 1  # fmt: skip
            if report:
                report(examined, total)
        return acc, feasible, examined
    pool = ThreadPoolExecutor(threads, thread_name_prefix="gears.search.engine")
    try:
        pending = set()
        queue = iter(bounds)
        for b in itertools.islice(queue, 2 * threads):
            pending.add(pool.submit(evaluate_chunk, space, *b, _LOCAL_BLOCK))
        while pending:
            finished, pending = wait(pending, return_when=FIRST_COMPLETED)
            for fut in finished:
                rows, f, c = fut.result()
                acc = _merge(acc, rows, space)
                feasible, examined, done = feasible + f, examined + c, done + 1
                nxt = next(queue, None)
                if nxt is not None:
                    pending.add(pool.submit(evaluate_chunk, space, *nxt, _LOCAL_BLOCK))
                if report:
                    report(examined, total)
    finally:
        pool.shutdown(wait=True, cancel_futures=True)
    return acc, feasible, examined


def _run_dask(space, bounds, client, report):
    if not bounds:
        return np.empty(0, _dtype(space.columns)), 0, 0
    seconds = dask_timeout()
    try:
        spec = client.scatter(space, broadcast=True, hash=False, timeout=seconds)
    except (TimeoutError, OSError) as exc:
        raise GearError(
            f"the Dask cluster took no work within {seconds:g} s "
            f"(distributed.comm.timeouts.connect): {exc}; start workers, or run without client="
        ) from None
    try:
        return _run_on(client, spec, space, bounds, report)
    except BaseException:  # Ctrl-C too: the shared data leaves the scheduler with the tasks
        with contextlib.suppress(Exception):
            client.cancel([spec])
        raise


def _run_on(client, spec, space, bounds, report):
    total = space.candidates
    window = max(4, 4 * len(client.scheduler_info().get("workers", {}) or [0]))
    queue = iter(bounds)
    first = [client.submit(evaluate_chunk, spec, *b, pure=False) for b in
             itertools.islice(queue, window)]  # fmt: skip
    acc, feasible, examined, done = None, 0, 0, 0
    pending = set(first)
    for fut, (rows, f, c) in dask_results(client, pending):
        fut.release()
        acc = _merge(acc, rows, space)
        feasible, examined, done = feasible + f, examined + c, done + 1
        nxt = next(queue, None)
        if nxt is not None:
            pending.add(client.submit(evaluate_chunk, spec, *nxt, pure=False))
        if report:
            report(examined, total)
    return acc, feasible, examined
