"""Benchmark: solve a 20-member train for 10^5 time steps of input speeds.

Run as ``python tests/benchmarks/bench_trains.py``. The train: a differential input stage, five
stepped planetary stages in series with their carriers driving the next sun, and a fixed-axis
tail, 20 moving members, mobility 2 (two input speed series). Reported: the exact elimination
(once per set of known members), the first solve and the best of repeated solves (map cached:
one float matrix product of (members x 2) by (2 x 10^5)).
"""

from __future__ import annotations

import os
import platform
import time

import numpy as np

from trains import Train


def build() -> Train:
    t = Train()
    t.mesh("in1", "p0", teeth=(23, 31), carrier="c0")
    t.mesh("p0", "in2", teeth=(31, 85), carrier="c0", internal=True)
    prev = "c0"
    for k in range(1, 6):
        t.couple(prev, f"s{k}")
        t.mesh(f"s{k}", f"p{k}", teeth=(17 + k, 29 + k), carrier=f"c{k}")
        t.mesh(f"p{k}", f"r{k}", teeth=(25 + k, 71 + 2 * k), carrier=f"c{k}", internal=True)
        t.couple(f"r{k}", "frame")  # rings held by the housing
        prev = f"c{k}"
    t.mesh(prev, "out", teeth=(19, 57))
    return t


def main() -> None:
    t = build()
    moving = len(t.members) - 1
    assert moving >= 20 and t.mobility == 2, (moving, t.mobility)
    n = 100_000
    rng = np.random.default_rng(0)
    w1 = 1500 + rng.standard_normal(n)
    w2 = 10 * np.sin(np.linspace(0, 20, n))

    t0 = time.perf_counter()
    t._map(("in1", "in2"))
    t_map = time.perf_counter() - t0

    t0 = time.perf_counter()
    m = t.solve(in1=w1, in2=w2)
    t_first = time.perf_counter() - t0

    times = []
    for _ in range(30):
        t0 = time.perf_counter()
        m = t.solve(in1=w1, in2=w2)
        times.append(time.perf_counter() - t0)
    best, median = min(times), float(np.median(times))

    # check against an independent dense float solve of one time step
    exact = t.solve(in1=float(w1[123]), in2=float(w2[123]))
    assert abs(m["out"][123] - exact["out"]) <= 1e-12 * abs(exact["out"])

    print(f"python {platform.python_version()}, numpy {np.__version__}, {os.cpu_count()} CPUs")
    print(f"train: {moving} moving members, {len(t.relations)} relations, mobility {t.mobility}")
    print(f"exact elimination (once per known set): {t_map * 1e3:.2f} ms")
    print(f"first solve, 10^5 steps:                {t_first * 1e3:.2f} ms")
    print(f"solve, 10^5 steps (best of 30):         {best * 1e3:.2f} ms")
    print(f"solve, 10^5 steps (median of 30):       {median * 1e3:.2f} ms")
    print(f"per time step: {best / n * 1e9:.1f} ns for {moving} speeds")


if __name__ == "__main__":
    main()
