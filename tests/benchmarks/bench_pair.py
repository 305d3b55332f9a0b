"""Benchmark: pair geometry for 10^6 random external spur pairs (issue 2, standards.md §5 (a)).

Run as ``python tests/benchmarks/bench_pair.py [n] [repeats]``. Prints the best-of-``repeats``
wall time of :func:`gears.meshing.pair_geometry` (working pressure angle, centre distance, y, k, tip
diameters, working diameters, transverse contact ratio) in ns per pair. Not a test: pytest does
not collect ``bench_*.py``.
"""

from __future__ import annotations

import os
import platform
import sys
import time

import numpy as np

from gears.meshing import default_threads, pair_geometry


def random_pairs(n: int, seed: int = 1):
    """Random external spur pairs: z in [12, 120], x in [0, 0.8], module in [0.5, 10]."""
    rng = np.random.default_rng(seed)
    z1 = rng.integers(12, 121, n).astype(float)
    z2 = rng.integers(12, 121, n).astype(float)
    x1 = rng.uniform(0.0, 0.8, n)
    x2 = rng.uniform(0.0, 0.8, n)
    m = rng.uniform(0.5, 10.0, n)
    return z1, z2, m, x1, x2


def bench(n: int = 1_000_000, repeats: int = 7, threads: int | None = None) -> float:
    """Best wall time per pair in ns (``threads``: None = :func:`default_threads`)."""
    z1, z2, m, x1, x2 = random_pairs(n)
    pair_geometry(z1[:1000], z2[:1000], m[:1000], x1[:1000], x2[:1000])  # warm up
    best = np.inf
    for _ in range(repeats):
        t0 = time.perf_counter()
        g = pair_geometry(z1, z2, m, x1, x2, threads=threads)
        best = min(best, time.perf_counter() - t0)
    assert np.isfinite(g.contact_ratio).all()
    return best / n * 1e9


def thread_scaling(n: int = 1_000_000, rounds: int = 5, counts=(1, 2, 4)) -> dict[int, float]:
    """Best ns/pair per thread count, the counts interleaved round by round so a shared
    machine's load falls on all of them alike."""
    best = dict.fromkeys(counts, np.inf)
    for _ in range(rounds):
        for k in counts:
            best[k] = min(best[k], bench(n, 1, threads=k))
    return best


if __name__ == "__main__":
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000
    repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 7
    ns = bench(n, repeats)
    scaling = thread_scaling(n)
    print(
        f"pair_geometry: {n} external pairs, best of {repeats}: {ns:.1f} ns/pair "
        f"({ns * n / 1e6:.1f} ms); numpy {np.__version__}, Python {platform.python_version()}, "
        f"{os.cpu_count()} CPUs, {platform.processor() or platform.machine()}"
    )
    print(f"default threads here: {default_threads()}")
    for k, v in scaling.items():
        print(f"  threads = {k}: {v:.1f} ns/pair ({scaling[1] / v:.2f}x the 1-thread speed)")
