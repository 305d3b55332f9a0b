"""Layer 6, design: the tasks of a gearbox search, on local threads or a Dask cluster.

:class:`_Runner` runs lists of tasks (stage-set blocks, sizing and combination chunks, check
batches of :func:`trains.design.gearbox.synthesize_gearbox`) on a thread pool or as Dask tasks
that keep their heap on the workers (:func:`gears.search.cluster.in_kept_heap`), reports the
progress and counts the tasks.
"""

from __future__ import annotations

import uuid
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from typing import Any

from gears.errors import GearError
from gears.search.cluster import dask_results, in_kept_heap
from trains.errors import TrainError


class _Runner:
    """Runs lists of tasks on the local threads or as Dask tasks, reporting progress (tasks
    done of tasks planned so far) and counting the tasks."""

    def __init__(self, client, threads: int, report):
        self.client = client
        self.threads = threads
        self.report = report
        self.tasks = 0
        self.done = 0
        self.planned = 0

    @property
    def parallel(self) -> int:
        """Threads that run tasks at once (the workers' threads on a cluster)."""
        if self.client is None:
            return self.threads
        try:
            return max(1, sum(self.client.nthreads().values()))
        except (OSError, TimeoutError, AttributeError):
            return 1

    def map(self, fn: Callable, args: list[tuple]) -> list:
        self.tasks += len(args)
        self.planned += len(args)
        if not args:
            return []
        results: list = [None] * len(args)
        if self.client is not None:
            name = fn.__name__.strip("_").replace("_", "-")  # the dashboard's task name
            futures = {self.client.submit(in_kept_heap, fn, *a, key=f"{name}-{uuid.uuid4().hex}"):
                       i for i, a in enumerate(args)}  # fmt: skip
            try:
                for fut, value in dask_results(self.client, set(futures)):
                    results[futures[fut]] = value
                    fut.release()
                    self._tick()
            except GearError as exc:  # the cluster failed under the work
                raise TrainError(str(exc)) from None
            return results
        if self.threads == 1 or len(args) == 1:
            for i, a in enumerate(args):
                results[i] = fn(*a)
                self._tick()
            return results
        with ThreadPoolExecutor(min(self.threads, len(args)),
                                thread_name_prefix="trains.design.gearbox") as pool:  # fmt: skip
            futures = {pool.submit(fn, *a): i for i, a in enumerate(args)}
            for fut in _completed(futures):
                results[futures[fut]] = fut.result()
                self._tick()
        return results

    def share(self, value: Any) -> Any:
        """``value`` for the tasks of :meth:`map` to share: on a cluster scattered to every
        worker once (a future the tasks receive resolved), locally the value itself."""
        if self.client is None:
            return value
        try:
            return self.client.scatter([value], broadcast=True, hash=False)[0]
        except (TimeoutError, OSError) as exc:
            raise TrainError(
                f"the Dask cluster took no data: {exc}; check the cluster, or "
                "run without client= (local threads)"
            ) from None

    def finish(self) -> None:
        """Report every planned task done."""
        if self.report:
            self.report(self.planned, self.planned)

    def _tick(self) -> None:
        self.done += 1
        if self.report:
            self.report(self.done, self.planned)


def _completed(futures):
    from concurrent.futures import as_completed

    return as_completed(futures)
