"""Benchmark of the design searches (a script; not collected by pytest). Issue 13.

Targets on 2 cores: >= 10^6 fully checked pairs per second, parallel efficiency >= 0.8 from 1 to
2 Dask workers, the 2-stage gearbox search for 1:37 (z <= 150) in <= 10 s.

Method: one pair-search space (ratio 3.2 +- 1 %, modules 1 ... 5, z 12 ... 100, shifts
-0.5 ... 1.0 step 0.01: 4.7 million candidates, each checked with every finding of
GearPair.check()); each configuration is timed ``REPEAT`` times and the best kept. The machine
may be shared, so compare the ratios within one run. Run:
``python tests/benchmarks/bench_search.py`` (writes ``tests/benchmarks/results/search.json``).
"""

from __future__ import annotations

import json
import os
import pathlib
import platform
import time

from gears.meshing import default_threads
from gears.search.engine import pairs
from trains import synthesize_gearbox

REPEAT = 3
SPACE = dict(ratio=3.2, module=[1, 1.25, 1.5, 2, 2.5, 3, 4, 5], teeth=(12, 100),
             shifts=(-0.5, 1.0, 0.01), top=20, progress=False)  # fmt: skip


def best_of(fn, repeat=REPEAT):
    best, out = float("inf"), None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def main() -> None:
    cores = len(os.sched_getaffinity(0))
    machine = f"{platform.processor() or platform.machine()}, {cores} cores"
    results = {"machine": machine, "python": platform.python_version()}
    t1, r = best_of(lambda: pairs(**SPACE, threads=1, client=False))
    n = r.examined
    print(f"pair search: {n:,} candidates, {r.feasible:,} feasible")
    print(f"  1 thread: {t1:.2f} s, {n / t1:,.0f} checked pairs/s")
    threads = default_threads()
    tn, _ = best_of(lambda: pairs(**SPACE, threads=threads, client=False))
    print(f"  {threads} threads: {tn:.2f} s, {n / tn:,.0f} checked pairs/s "
          f"(speed-up {t1 / tn:.2f})")  # fmt: skip
    results["pairs"] = {"candidates": n, "threads_1_s": t1, f"threads_{threads}_s": tn,
                        "rate_1": n / t1, f"rate_{threads}": n / tn}  # fmt: skip

    from distributed import Client, LocalCluster

    dask = {}
    for workers in (1, 2):
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                               dashboard_address=None)  # fmt: skip
        with cluster, Client(cluster) as client:
            pairs(**SPACE, client=client, chunk_size=1 << 17)  # warm the workers
            t, _ = best_of(lambda c=client: pairs(**SPACE, client=c, chunk_size=1 << 17))
        dask[workers] = t
        print(f"  LocalCluster, {workers} worker(s): {t:.2f} s, {n / t:,.0f} checked pairs/s")
    eff = dask[1] / (2 * dask[2])
    print(f"  scaling efficiency 1 -> 2 workers: {eff:.2f}")
    results["dask"] = {"workers_1_s": dask[1], "workers_2_s": dask[2], "efficiency": eff}

    tg, g = best_of(lambda: synthesize_gearbox(37, stages=2, schemes=("simple", "stepped"),
                                               z_max=150, top=10, progress=False))  # fmt: skip
    print(f"gearbox 1:37, 2 stages (simple, stepped), z <= 150: {tg:.2f} s; best: {g[0]}")
    ts, _ = best_of(lambda: synthesize_gearbox(37, stages=2, z_max=150, progress=False))
    print(f"gearbox 1:37, 2 simple stages, z <= 150: {ts:.2f} s ({len(_)} found)")
    results["gearbox"] = {"simple_stepped_s": tg, "simple_s": ts, "best": str(g[0])}
    out = pathlib.Path(__file__).parent / "results" / "search.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps(results, indent=2))


if __name__ == "__main__":
    main()
