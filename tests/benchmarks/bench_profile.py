"""Benchmark: tooth outlines, speed versus accuracy (issue 5; standards.md §3.2, §5 (b)-(c)).

Full outlines (all teeth, shapely Polygon), ISO 53 A, m = 1, tolerances 1e-1 ... 1e-4 mm, for
each method the best-of-N wall time and the *achieved* deviation, measured as the Hausdorff
distance to the exact outline of the same tool at tolerance / 1000:

* ``analytic``: z = 20, the rack envelope (`gears.cutting.profile.outline`); against itself at
  tolerance / 1000, so this measures the chord sag;
* ``rack``: z = 20, the simulated rack cutting (`rack_outline`), against the analytic outline
  (scallops, tool polygon, tip circle);
* ``shaper``: z = 20, the simulated shaper cutting (`shaper_outline`) with the default cutter
  (z0 = 76), against the analytic shaper envelope (``outline(gear, tol / 1000, cutter=c)``);
* ``shaper internal``: a ring z = 80 with its default cutter (z0 = 40), the toothed boundary
  (``interiors[0]``) against that of the analytic shaper envelope.

Writes the log-log chart ``docs/images/profile_speed_accuracy.png``. Run:
``python tests/benchmarks/bench_profile.py``. Not collected by pytest.
"""

from __future__ import annotations

import os
import pathlib
import platform
import time

import numpy as np
import shapely

from gears import Gear
from gears.arguments import min_tolerance
from gears.cutting.cutter import ShaperCutter
from gears.cutting.generate import rack_outline, shaper_outline
from gears.cutting.profile import outline

HERE = pathlib.Path(__file__).resolve().parent
CHART = HERE.parent.parent / "docs" / "images" / "profile_speed_accuracy.png"
TOLERANCES = [1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4]
METHODS = ["analytic", "rack", "shaper", "shaper internal"]


def best_of(fn, repeat):
    best = np.inf
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t)
    return best


def _directed(a, b):
    """Largest distance from a vertex of ring ``a`` to ring ``b`` (its segments, indexed)."""
    pb = shapely.get_coordinates(b)
    tree = shapely.STRtree(shapely.linestrings(np.stack([pb[:-1], pb[1:]], axis=1)))
    _, d = tree.query_nearest(shapely.points(shapely.get_coordinates(a)), return_distance=True)
    return float(d.max())


def hausdorff(a, b):
    """The (discrete, vertex-to-segment) Hausdorff distance of GEOS, ``a.hausdorff_distance(b)``,
    with a segment index: GEOS compares every vertex with every segment, minutes at 1e-4 mm."""
    return max(_directed(a, b), _directed(b, a))


def _ring(poly, internal):
    """The toothed boundary: the exterior of a disc, the hole of a ring."""
    return poly.interiors[0] if internal else poly.exterior


def cases():
    """(name, gear, outline function (gear, tolerance) -> Polygon, reference cutter, repeats)."""
    ext, ring = Gear(20, 1), Gear(80, 1, internal=True)
    c_ext, c_ring = ShaperCutter.default_for(ext), ShaperCutter.default_for(ring)
    return [
        ("analytic", ext, outline, None, 30),
        ("rack", ext, rack_outline, None, 7),
        ("shaper", ext, lambda g, tol: shaper_outline(g, tol, cutter=c_ext), c_ext, 7),
        ("shaper internal", ring, lambda g, tol: shaper_outline(g, tol, cutter=c_ring), c_ring, 5),
    ]


def measure():
    rows = []
    for name, gear, fn, cutter, rep in cases():
        for tol in TOLERANCES:
            # the reference 1000 times finer, down to the finest tolerance honoured (1e-6 mm)
            fine = max(tol / 1000, min_tolerance(gear.module))
            ref = _ring(outline(gear, fine, cutter=cutter), gear.internal)
            ring = _ring(fn(gear, tol), gear.internal)
            dev = hausdorff(ring, ref)
            t = best_of(lambda fn=fn, gear=gear, tol=tol: fn(gear, tol), rep)
            rows.append((name, tol, t, dev, len(ring.coords) - 1))
    return rows


def chart(rows, path=CHART):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(8, 4))  # readable at the page width
    labels = {"analytic": "analytic, z = 20", "rack": "rack simulation, z = 20",
              "shaper": "shaper simulation, z = 20 (z0 = 76)",
              "shaper internal": "shaper simulation, ring z = 80 (z0 = 40)"}  # fmt: skip
    for i, name in enumerate(METHODS):
        r = np.array([(tol, t, dev) for n, tol, t, dev, _ in rows if n == name])
        kw = dict(color=f"C{i}", label=labels[name], ls="--" if "internal" in name else "-")
        a1.loglog(r[:, 2] * 1e3, r[:, 1] * 1e3, "o", **kw)
        a2.loglog(r[:, 0] * 1e3, r[:, 2] * 1e3, "o", **kw)
    a1.set_xlabel("achieved deviation, um")
    a1.set_ylabel("time per full outline, ms")
    a1.axhline(5, color="C0", ls=":", lw=0.8)
    a1.axhline(150, color="C1", ls=":", lw=0.8)
    a1.set_title("m = 1: speed vs accuracy (targets dotted)")
    a2.loglog([0.1, 100], [0.1, 100], "k:", lw=0.8, label="deviation = tolerance")
    a2.set_xlabel("requested tolerance, um")
    a2.set_ylabel("achieved deviation, um")
    a2.set_title("tolerance honoured")
    for a in (a1, a2):
        a.grid(True, which="both", lw=0.3)
    fig.legend(*a2.get_legend_handles_labels(), loc="lower center", ncol=3, fontsize=8)
    fig.tight_layout(rect=(0, 0.12, 1, 1))
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def main():
    print(f"{platform.processor() or platform.machine()}, {os.cpu_count()} CPUs")
    rows = measure()
    print("| method | tolerance, mm | time, ms | achieved deviation, um | vertices |")
    print("|---|---|---|---|---|")
    for name, tol, t, dev, n in rows:
        print(f"| {name} | {tol:g} | {t * 1e3:.2f} | {dev * 1e3:.3f} | {n} |")
    print("chart:", chart(rows))


if __name__ == "__main__":
    main()
