"""Benchmark of the worm solids: the worm's helicoid solid and the wheel cut by simulated
hobbing, at two tolerances, with the measured accuracy of the hobbed wheel.

Run: ``python tests/benchmarks/bench_worm.py`` (writes ``tests/benchmarks/results/worm.json``).

- The pair: z1 1, z2 16 (and 30), m_x 2, q 10, ZA, x2 0 (the mid-plane conjugate of a ZA worm
  is the involute of r_2 cos(alpha_x): exact reference).
- Timed: ``WormPair.worm_mesh`` and ``WormPair.wheel_mesh`` on a new pair each run (nothing
  cached), wall time; the machine's load (``os.getloadavg``) is recorded with each run.
- Accuracy: the wheel is cut by its mid-plane (manifold3d's slice), and the tooth thickness on
  four circles between the root form and the tip is compared with the involute's
  (``gears.geometry.tooth_thickness``): the largest excess and the largest deficit, mm.
- Peers (OpenSCAD + BOSL2 ``worm_gear()``, the ``wormgear`` package) were not run in this round.
"""

from __future__ import annotations

import json
import math
import os
import pathlib
import time

import numpy as np
import shapely

from gears import WormPair
from gears.cutting.measure import thickness_on
from gears.geometry import tooth_thickness
from gears.solid.mesh import to_manifold

OUT = pathlib.Path(__file__).parent / "results" / "worm.json"


def accuracy(w: WormPair, wheel) -> tuple[float, float]:
    rings = to_manifold(wheel).slice(0.0).to_polygons()
    section = max((shapely.Polygon(r) for r in rings), key=lambda p: p.area)
    base = w.wheel_diameter * math.cos(math.radians(w.axial_pressure_angle))
    lo, hi = max(w.wheel_root_diameter, base) + 0.5, w.wheel_tip_diameter - 0.5
    dev = []
    for d in np.linspace(lo, hi, 4):
        s = thickness_on(section, d)
        exact = float(tooth_thickness(d, w.wheel_teeth, w.module, w.profile_shift,
                                      w.axial_pressure_angle))  # fmt: skip
        dev.append(s - exact)
    dev = np.concatenate(dev)
    return float(dev.max()), float(dev.min())


def run(z2: int, tolerance: float) -> dict:
    load0 = os.getloadavg()[0]
    w = WormPair(1, z2, 2.0, diameter_quotient=10, flank="ZA")
    t0 = time.perf_counter()
    worm = w.worm_mesh(tolerance)
    t1 = time.perf_counter()
    wheel = w.wheel_mesh(tolerance)
    t2 = time.perf_counter()
    excess, deficit = accuracy(w, wheel)
    return {
        "z2": z2, "tolerance": tolerance, "worm_s": t1 - t0, "wheel_s": t2 - t1,
        "worm_vertices": len(worm.vertices), "wheel_vertices": len(wheel.vertices),
        "watertight": bool(worm.is_watertight and wheel.is_watertight),
        "thickness_excess_mm": excess, "thickness_deficit_mm": deficit,
        "load_before": load0, "load_after": os.getloadavg()[0],
    }  # fmt: skip


def main() -> None:
    rows = [run(16, 0.1), run(16, 0.05), run(30, 0.05)]
    for r in rows:
        print(r)
    OUT.parent.mkdir(exist_ok=True)
    OUT.write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
