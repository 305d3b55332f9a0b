"""Benchmark of trains.synthesize (a script; not collected by pytest).

Targets (issue 4): <= 10 ms per simple search (z_max = 200) over 100 ratios, and <= 2 s for one
stepped search with z_max = 100. Run: ``python tests/benchmarks/bench_synthesis.py``.
"""

import os
import platform
import time

import numpy as np

from trains import synthesize


def best_of(fn, repeat=3):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return min(times), out


def main() -> None:
    ratios = np.round(np.linspace(3.0, 12.0, 100), 2)
    t0 = time.perf_counter()
    found = sum(bool(synthesize(float(r), n_planets=3, scheme="simple", z_max=200)) for r in ratios)
    per = (time.perf_counter() - t0) / len(ratios)
    print(f"simple, z_max=200, 100 ratios 3..12: {per * 1e3:.2f} ms per search "
          f"({found} with a result; target <= 10 ms)")  # fmt: skip
    t0 = time.perf_counter()
    found = sum(
        bool(synthesize(float(r), 3, scheme="simple", z_max=200, tolerance=0.01)) for r in ratios
    )
    per = (time.perf_counter() - t0) / len(ratios)
    print(
        f"simple, z_max=200, tolerance 1 %: {per * 1e3:.2f} ms per search ({found} with a result)"
    )
    t, res = best_of(lambda: synthesize(10, n_planets=3, scheme="stepped", z_max=100))
    print(
        f"stepped, ratio 10, z_max=100: {t:.3f} s ({len(res)} candidates, {res.examined} sets;"
        " target <= 2 s)"
    )
    t, res = best_of(lambda: synthesize(16, n_planets=3, scheme="stepped", z_max=200), 1)
    print(f"stepped, ratio 16, z_max=200: {t:.3f} s ({res.examined} sets)")
    t, res = best_of(lambda: synthesize(7, n_planets=3, allow_shift=True, z_max=200))
    print(f"simple with allow_shift, ratio 7, z_max=200: {t * 1e3:.1f} ms")
    t, res = best_of(lambda: synthesize(-3, 3, scheme="double-planet", z_max=100))
    print(f"double-planet, ratio -3, z_max=100: {t * 1e3:.1f} ms ({res.examined} sets)")
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cpus, "
          f"numpy {np.__version__}")  # fmt: skip


if __name__ == "__main__":
    main()
