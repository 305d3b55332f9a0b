"""Benchmark of the searches under a load (a script; not collected by pytest). Issue 20.

Targets on 2 cores: a rated pair search >= 3 x 10^5 candidates per second; a rated 2-stage
1:20 gearbox with every stage's module chosen (ISO 54) in <= 20 s; a Dask scaling efficiency
of the gearbox search from 1 to 2 workers >= 0.8 (measured with the machine otherwise idle).

Method: the machine is shared, so every figure is the best of ``REPEAT`` runs, the load average
is printed before and after, and each rate is given beside its baseline measured in the same
run (the unrated search of the same geometry; the same gearbox on local threads). The
Dask comparison keeps a 1-worker and a 2-worker ``LocalCluster`` alive together and
interleaves their runs with local threads, ``DASK_ROUNDS`` rounds, best of each. Run:
``python tests/benchmarks/bench_load.py`` (writes ``tests/benchmarks/results/load.json``).
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
#: interleaved rounds of the Dask comparison (best of each)
DASK_ROUNDS = 5
#: ratio 3.2 +- 1 %, 8 modules, z 12 ... 100, shifts -0.5 ... 1.0 step 0.02, 7 face widths
PAIRS = dict(ratio=3.2, module=[1, 1.25, 1.5, 2, 2.5, 3, 4, 5], teeth=(12, 100),
             shifts=(-0.5, 1.0, 0.02), top=20, progress=False)  # fmt: skip
LOAD = dict(torque=60, speed=1500, face_width=(10, 40, 5),
            min_safety={"pitting": 1.1, "bending": 1.5})  # fmt: skip
#: the lightest 2-stage 1:20 gearboxes for 50 N m, modules of ISO 54, widths 10 ... 40 mm
GEARBOX = dict(ratio=20, stages=2, torque=50, speed=1500, face_width=range(10, 45, 5),
               objective="mass", progress=False)  # fmt: skip


def best_of(fn, repeat=REPEAT):
    best, out = float("inf"), None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def load() -> str:
    return "load average " + " / ".join(f"{v:.2f}" for v in os.getloadavg())


def main() -> None:
    cores = len(os.sched_getaffinity(0))
    results = {"machine": f"{platform.processor() or platform.machine()}, {cores} cores",
               "python": platform.python_version(), "load_before": os.getloadavg()}  # fmt: skip
    print(f"{results['machine']}; {load()}")
    threads = default_threads()
    out = {}
    cases = (
        ("unrated", {}),
        ("rated, each pair sized", LOAD),
        ("rated, every width a candidate", dict(LOAD, smallest_width=False)),
    )
    for name, extra in cases:
        for n in (1, threads):
            t, r = best_of(lambda n=n, e=extra: pairs(**PAIRS, **e, threads=n, client=False))
            rate = r.examined / t
            out[f"{name}, {n} thread(s)"] = {"s": t, "candidates": r.examined, "rate": rate,
                                             "feasible": r.feasible}  # fmt: skip
            print(f"pairs {name}, {n} thread(s): {r.examined:,} candidates, {r.feasible:,} "
                  f"feasible, {t:.2f} s, {r.examined / t:,.0f} candidates/s")  # fmt: skip
    results["pairs"] = out

    gb = {}
    for schemes in (("simple",), ("simple", "stepped")):
        t, g = best_of(lambda s=schemes: synthesize_gearbox(**GEARBOX, schemes=s, z_max=150),
                       repeat=2)  # fmt: skip
        key = "+".join(schemes)
        gb[key] = {"s": t, "tasks": g.tasks, "sized": g.sized, "best": str(g[0])}
        print(f"gearbox 1:20 rated ({key}, z <= 150): {t:.2f} s, {g.tasks} tasks, {g.sized:,} "
              f"stage loads sized; best {g[0].modules} mass {g[0].mass:.3f} kg")  # fmt: skip
    results["gearbox"] = gb

    from distributed import Client, LocalCluster

    cases = {
        "rated 1:20, simple+stepped, z <= 150": dict(GEARBOX, schemes=("simple", "stepped"),
                                                     z_max=150),
        "rated 1:20, simple+stepped, z <= 200": dict(GEARBOX, schemes=("simple", "stepped"),
                                                     z_max=200),
        "rated 1:20, simple+stepped, z <= 250": dict(GEARBOX, schemes=("simple", "stepped"),
                                                     z_max=250),
        "unrated 1:37, simple+stepped, z <= 150": dict(ratio=37, stages=2, z_max=150,
                                                       schemes=("simple", "stepped"),
                                                       progress=False),
    }  # fmt: skip
    # both clusters alive at once and the runs interleaved round by round (1 worker, 2
    # workers, local threads), so that a drift in the machine's load falls on each alike
    dask = {name: {1: float("inf"), 2: float("inf")} for name in cases}
    local = {name: float("inf") for name in cases}
    c1 = LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None)
    c2 = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    with c1, c2, Client(c1, set_as_default=False) as k1, Client(c2, set_as_default=False) as k2:
        for client in (k1, k2):
            synthesize_gearbox(**dict(GEARBOX, z_max=100), client=client)  # warm the workers
        for _ in range(DASK_ROUNDS):
            for name, kw in cases.items():
                for workers, client in ((1, k1), (2, k2)):
                    t, g = best_of(lambda c=client, kw=kw: synthesize_gearbox(**kw, client=c), 1)
                    dask[name][workers] = min(dask[name][workers], t)
                t, _ = best_of(lambda kw=kw: synthesize_gearbox(**kw, client=False), 1)
                local[name] = min(local[name], t)
    for name in cases:
        t_local = local[name]
        eff = dask[name][1] / (2 * dask[name][2])
        dask[name].update(local_s=t_local, efficiency=eff)
        print(f"{name}: scaling efficiency 1 -> 2 workers {eff:.2f}; local threads "
              f"{t_local:.2f} s, 2 workers {dask[name][2]:.2f} s")  # fmt: skip
    results["dask"] = {k: {str(w): v for w, v in d.items()} for k, d in dask.items()}
    results["load_after"] = os.getloadavg()
    print(load())
    path = pathlib.Path(__file__).parent / "results" / "load.json"
    path.parent.mkdir(exist_ok=True)
    path.write_text(json.dumps(results, indent=2))


if __name__ == "__main__":
    main()
