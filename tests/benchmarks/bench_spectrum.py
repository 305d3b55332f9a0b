"""Benchmark: load spectra (ISO 6336-6) and mesh losses (ISO/TR 14179-2) over arrays (issue 30).

Run as ``python tests/benchmarks/bench_spectrum.py [n] [rounds]``. Prints rated pairs per
second for ``n`` random external helical pairs (as bench_rating.py: z 14 ... 40 / 40 ... 120,
m 1 ... 8, x 0 ... 0.5 / -0.2 ... 0.3, beta 15 deg, b 10 m) under a 10-bin spectrum (torques
10 ... 500 m^2 N m scaled by 0.2 ... 1.4, 1500 rpm, 10 ... 10^4 h a bin) through
``gears.rating.rate_spectrum`` on 1 and 2 threads, beside the baseline of the same pairs rated
once at one load by ``rate_pairs`` (the four safeties), interleaved round by round; and the
mesh losses of the same pairs by ``gears.rating.pair_losses``, at one load and over the 10
bins (pairs of shape (n, 1), bins of shape (10,): each pair's geometry and H_V once).

``python tests/benchmarks/bench_spectrum.py n rounds --tree PATH`` runs the same cases in this
source tree and in the tree at PATH (e.g. ``git archive`` of an older commit: before/after),
each round a fresh process of each in turn, so that both see the same machine load, and prints
the best of each with the ratios and ``uptime``'s load at the start and the end; each case's
wall time and its CPU time (``... cpu``: on a shared machine the less disturbed of the two),
and the spectrum's cost in one-load ratings on 1 and 2 threads.

Not a test: pytest does not collect ``bench_*.py``. Results: docs/performance.md.
"""

from __future__ import annotations

import json
import math
import os
import pathlib
import subprocess
import sys
import time

import numpy as np

from gears import rate_pairs
from gears.rating.losses import pair_losses
from gears.rating.spectrum import rate_spectrum

SAFETIES = ("S_H1", "S_H2", "S_F1", "S_F2")


def pairs(n: int, seed: int = 1):
    rng = np.random.default_rng(seed)
    z1 = rng.integers(14, 41, n)
    z2 = rng.integers(40, 121, n)
    m = rng.choice([1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0], n)
    x1 = rng.uniform(0.0, 0.5, n)
    x2 = rng.uniform(-0.2, 0.3, n)
    b = 10.0 * m
    return z1, z2, m, x1, x2, b


def timed(n: int = 200_000, rounds: int = 3) -> dict[str, list[float]]:
    """Seconds of each case, round by round, wall time and (keys ending in " cpu") the
    process's CPU time, which other processes on a shared machine disturb less (each case run
    once on 500 pairs first: imports, thread pools and caches warm)."""
    z1, z2, m, x1, x2, b = pairs(n)
    scale = float(np.median(m)) ** 2
    spectrum = [(scale * 100 * f, 1500.0, h) for f, h in
                zip(np.linspace(0.2, 1.4, 10), np.geomspace(1e4, 10, 10), strict=True)]  # fmt: skip
    bins_torque = np.array([t for t, _, _ in spectrum])
    bins_speed = np.array([v for _, v, _ in spectrum])

    def cases(k):
        p = [v[:k] for v in (z1, z2, m, x1, x2, b)]
        col = [v[:, None] for v in p]  # each pair's geometry and H_V once for the bins
        torque = 10.0 * p[2] ** 2
        return {
            "one load, 1 thread": lambda: rate_pairs(
                p[0], p[1], p[2], p[5], torque, 1500.0, x1=p[3], x2=p[4], helix_angle=15.0,
                fields=SAFETIES, threads=1),
            "one load, 2 threads": lambda: rate_pairs(
                p[0], p[1], p[2], p[5], torque, 1500.0, x1=p[3], x2=p[4], helix_angle=15.0,
                fields=SAFETIES, threads=2),
            "losses": lambda: pair_losses(torque, 1500.0, p[0], p[1], p[2], p[5], p[3], p[4],
                                          20.0, 15.0),
            "losses, 10 bins": lambda: pair_losses(bins_torque, bins_speed, col[0], col[1],
                                                   col[2], col[5], col[3], col[4], 20.0, 15.0),
            "spectrum 1 thread": lambda: rate_spectrum(p[0], p[1], p[2], p[5], spectrum, x1=p[3],
                                                       x2=p[4], helix_angle=15.0, threads=1),
            "spectrum 2 threads": lambda: rate_spectrum(p[0], p[1], p[2], p[5], spectrum,
                                                        x1=p[3], x2=p[4], helix_angle=15.0,
                                                        threads=2),
        }  # fmt: skip

    for run in cases(min(n, 500)).values():
        run()
    work = cases(n)
    times: dict[str, list[float]] = {k: [] for key in work for k in (key, f"{key} cpu")}
    for _ in range(rounds):
        for key, run in work.items():
            t0, c0 = time.perf_counter(), time.process_time()
            run()
            times[key].append(time.perf_counter() - t0)
            times[f"{key} cpu"].append(time.process_time() - c0)
    return times


def main(n: int = 200_000, rounds: int = 3) -> None:
    times = timed(n, rounds)
    print(f"{n} pairs, 10-bin spectrum, {rounds} rounds (best), load {os.getloadavg()}")
    for key, ts in times.items():
        best = min(ts)
        print(f"{key:24s} {best:8.3f} s  {n / best:12.4g} pairs/s")


def before_after(n: int, rounds: int, tree: str) -> None:
    """The cases in this tree and in ``tree``, a fresh process each in turn."""
    here = str(pathlib.Path(__file__).resolve().parents[2])
    trees = {"after": here, "before": str(pathlib.Path(tree).resolve())}
    best: dict[str, dict[str, float]] = {k: {} for k in trees}
    load0 = os.getloadavg()
    for _ in range(rounds):
        for name, path in trees.items():
            env = dict(os.environ, PYTHONPATH=path)
            out = subprocess.run([sys.executable, __file__, str(n), "1", "--worker"], env=env,
                                 check=True, capture_output=True, text=True).stdout  # fmt: skip
            for key, ts in json.loads(out.splitlines()[-1]).items():
                best[name][key] = min(best[name].get(key, math.inf), *ts)
    load1 = os.getloadavg()
    print(f"{n} pairs, 10-bin spectrum, best of {rounds} rounds; load average {load0[0]:.2f} "
          f"{load0[1]:.2f} {load0[2]:.2f} at the start, {load1[0]:.2f} {load1[1]:.2f} "
          f"{load1[2]:.2f} at the end (uptime)")  # fmt: skip
    for key in best["after"]:
        a, b = best["after"][key], best["before"].get(key, math.nan)
        print(f"{key:22s} after {a:7.3f} s {n / a:10.4g} pairs/s   before {b:7.3f} s "
              f"{n / b:10.4g} pairs/s   before/after {b / a:6.2f}")  # fmt: skip
    for what in ("1 thread", "2 threads", "1 thread cpu", "2 threads cpu"):
        one, spec = f"one load, {what}", f"spectrum {what}"
        ratios = [best[t][spec] / best[t][one] for t in ("after", "before")]
        print(f"10-bin spectrum / one load ({what}): {ratios[0]:.2f} after, {ratios[1]:.2f} "
              "before")  # fmt: skip


if __name__ == "__main__":
    numbers = [int(a) for a in sys.argv[1:3] if a.isdigit()]
    if "--worker" in sys.argv:  # the cases of one round, as JSON (before_after)
        print(json.dumps(timed(*numbers)))
    elif "--tree" in sys.argv:
        before_after(*numbers, sys.argv[sys.argv.index("--tree") + 1])
    else:
        main(*numbers)
