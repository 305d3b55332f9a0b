"""Benchmark: tooth outlines, speed versus accuracy (issue 5; standards.md §3.2, §5 (b)-(c)).

z = 20, m = 1, ISO 53 A, full outline (all teeth, shapely Polygon). For tolerances 1e-1 ...
1e-4 mm, both methods: best-of-N wall time and the *achieved* deviation, measured as the
Hausdorff distance to the analytic outline at tolerance / 1000 (for the analytic method this
measures the chord sag; for the rack simulation the scallops, tool polygon and tip circle).
Writes the log-log chart ``docs/images/profile_speed_accuracy.png``. Run:
``python tests/benchmarks/bench_profile.py``. Not collected by pytest.
"""

from __future__ import annotations

import os
import pathlib
import platform
import time

import numpy as np

from gears import Gear
from gears.generate import rack_outline
from gears.profile import outline

HERE = pathlib.Path(__file__).resolve().parent
CHART = HERE.parent.parent / "docs" / "images" / "profile_speed_accuracy.png"
TOLERANCES = [1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4]


def best_of(fn, repeat):
    best = np.inf
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t)
    return best


def measure(gear):
    rows = []
    for tol in TOLERANCES:
        ref = outline(gear, tol / 1000).exterior
        for name, fn, rep in [("analytic", outline, 30), ("rack", rack_outline, 7)]:
            poly = fn(gear, tol)
            dev = poly.exterior.hausdorff_distance(ref)
            t = best_of(lambda fn=fn, tol=tol: fn(gear, tol), rep)
            n = len(poly.exterior.coords) - 1
            rows.append((name, tol, t, dev, n))
    return rows


def chart(rows, path=CHART):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4.2))
    for i, name in enumerate(["analytic", "rack"]):
        r = np.array([(tol, t, dev) for n, tol, t, dev, _ in rows if n == name])
        a1.loglog(r[:, 2] * 1e3, r[:, 1] * 1e3, "o-", color=f"C{i}", label=name)
        a2.loglog(r[:, 0] * 1e3, r[:, 2] * 1e3, "o-", color=f"C{i}", label=name)
    a1.set_xlabel("achieved deviation, um")
    a1.set_ylabel("time per full outline, ms")
    a1.axhline(5, color="C0", ls=":", lw=0.8)
    a1.axhline(150, color="C1", ls=":", lw=0.8)
    a1.set_title("z = 20, m = 1: speed vs accuracy (targets dotted)")
    a2.loglog([0.1, 100], [0.1, 100], "k:", lw=0.8, label="deviation = tolerance")
    a2.set_xlabel("requested tolerance, um")
    a2.set_ylabel("achieved deviation, um")
    a2.set_title("tolerance honoured")
    for a in (a1, a2):
        a.grid(True, which="both", lw=0.3)
        a.legend()
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def main():
    print(f"{platform.processor() or platform.machine()}, {os.cpu_count()} CPUs")
    rows = measure(Gear(20, 1))
    print("| method | tolerance, mm | time, ms | achieved deviation, um | vertices |")
    print("|---|---|---|---|---|")
    for name, tol, t, dev, n in rows:
        print(f"| {name} | {tol:g} | {t * 1e3:.2f} | {dev * 1e3:.3f} | {n} |")
    print("chart:", chart(rows))


if __name__ == "__main__":
    main()
