"""Benchmark: Planetary.coaxial on the stage of issue 26 (sun 96, planet 5, ring 103, one
planet, module 0.1, split "equal_sliding"), where no centre distance of the 301-point grid
passes every check, so every candidate is built and checked.

Run as ``python tests/benchmarks/bench_coaxial.py``. Reported, best of 3: the whole call, and
the equal-sliding split of the sun-planet pair over the grid solved at once (what coaxial does
now) against one solve per centre distance (``GearPair.at_center_distance`` per candidate, the
former route, measured in the same run as the baseline).
"""

from __future__ import annotations

import os
import time

import numpy as np

from gears import Gear, GearError, GearPair
from trains import Planetary
from trains.planetary.shifts import _equal_sliding_suns


def best_of(fn, runs: int = 3) -> float:
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def per_candidate(sun: Gear, planet: Gear, grid) -> list:
    out = []
    for a in grid:
        try:
            out.append(GearPair.at_center_distance(sun, planet, float(a)).g1.profile_shift)
        except GearError:
            out.append(None)
    return out


def main() -> None:
    print(f"load: {os.getloadavg()}")
    sun, planet = Gear(96, 0.1), Gear(5, 0.1)
    mean = (GearPair(sun, planet).center_distance + 4.9) / 2
    steps = np.arange(-150, 151) * 0.01 * 0.1
    grid = mean + steps
    whole = best_of(lambda: Planetary.coaxial(96, 5, 103, 1, 0.1, split="equal_sliding"))
    at_once = best_of(lambda: _equal_sliding_suns(sun, planet, grid))
    one_by_one = best_of(lambda: per_candidate(sun, planet, grid), runs=1)
    print(f"Planetary.coaxial(96, 5, 103, 1, 0.1): {whole:.2f} s")
    print(f"equal-sliding split on {len(grid)} centre distances: at once {at_once:.3f} s, one "
          f"per candidate {one_by_one:.2f} s ({one_by_one / at_once:.0f}x)")  # fmt: skip


if __name__ == "__main__":
    main()
