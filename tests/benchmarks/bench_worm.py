"""Benchmark of the worm solids: the worm's helicoid solid and the wheel cut by simulated
hobbing, at two tolerances, with the measured accuracy of the hobbed wheel.

Run: ``python tests/benchmarks/bench_worm.py`` (writes ``tests/benchmarks/results/worm.json``).

- The pairs: z1 1, z2 10 and 16, m_x 2, q 10, ZA, x2 0.3 (the mid-plane conjugate of a ZA worm
  is the involute of r_2 cos(alpha_x): exact reference).
- Timed: ``WormPair.worm_mesh`` and ``WormPair.wheel_mesh`` on a new pair each run (nothing
  cached), wall time; the machine's load (``os.getloadavg``) is recorded with each run.
- Accuracy: the wheel is cut by its mid-plane (manifold3d's slice), and the tooth thickness on
  four circles between the root form and the tip is compared with the involute's
  (``gears.geometry.tooth_thickness``): the largest excess and the largest deficit, mm.
- Off the mid-plane (3 mm): the wheel's section against a dense 2D simulation of the same
  hobbing in that plane (600 hob positions, each hob's section in the plane drawn from the
  flank's axial section, united with shapely): the Hausdorff distance of the two boundaries
  within 30 degrees of the worm, mm.
- OpenSCAD + BOSL2 ``worm_gear(mod=2, teeth=16, worm_diam=20, worm_starts=1, crowning=0,
  profile_shift=0)`` where OpenSCAD is installed (give BOSL2's parent folder as OPENSCADPATH,
  default /tmp/bosl; never part of this repository): the whole ``openscad -o wheel.stl``
  process timed, its wheel's mid-plane measured against the involute the same way (x2 0).
  The ``wormgear`` package was not run.
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
from gears.worm.flank import axial_half_thickness

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


def dense_section(w: WormPair, zeta: float, positions: int = 600, samples: int = 200):
    """The wheel's section at ``zeta`` by a dense 2D simulation of the hobbing (ZA worm)."""
    g = w.geometry
    a, m = float(g.center_distance), w.module
    rt = float(g.worm_tip_diameter) / 2 + w.clearance * m
    p = float(g.lead) / (2 * math.pi)
    y = np.linspace(a - math.sqrt(rt**2 - zeta**2), a, samples)
    r, th = np.hypot(y - a, zeta), np.arctan2(zeta, y - a)
    h = axial_half_thickness("ZA", r, w.starts, m, w.diameter_quotient, w.pressure_angle)
    tools = []
    for phi2 in np.linspace(-0.9, 0.9, positions):
        phi1 = phi2 * w.wheel_teeth / w.starts
        c, s = math.cos(-phi2), math.sin(-phi2)
        turn = np.array([[c, s], [-s, c]])
        polys = []
        for k in range(-8, 9):
            xc = p * (th - phi1) + k * float(g.lead)
            ring = np.concatenate([np.stack([xc - h, y], 1), np.stack([xc + h, y], 1)[::-1]])
            polys.append(shapely.Polygon(ring @ turn))
        tools.append(shapely.union_all(polys))
    rk, re2 = float(g.throat_radius), float(g.wheel_outside_diameter) / 2
    rho = min(re2, a - math.sqrt(max(rk**2 - zeta**2, 0.0)))
    return shapely.Point(0, 0).buffer(rho, 2048).difference(shapely.union_all(tools))


def off_plane(w: WormPair, wheel, zeta: float = 3.0) -> float:
    rings = to_manifold(wheel).slice(zeta).to_polygons()
    hobbed = max((shapely.Polygon(r) for r in rings), key=lambda q: q.area)
    far = 30.0 * w.center_distance
    corners = [
        (far * math.cos(math.radians(t)), far * math.sin(math.radians(t))) for t in (60, 120)
    ]
    win = shapely.Polygon([(0.0, 0.0), *corners])
    exact = dense_section(w, zeta).boundary.intersection(win)
    return float(shapely.hausdorff_distance(exact, hobbed.boundary.intersection(win), densify=0.05))


def run(z2: int, tolerance: float, dense: bool = False) -> dict:
    load0 = os.getloadavg()[0]
    w = WormPair(1, z2, 2.0, diameter_quotient=10, flank="ZA", profile_shift=0.3)
    t0 = time.perf_counter()
    worm = w.worm_mesh(tolerance)
    t1 = time.perf_counter()
    wheel = w.wheel_mesh(tolerance)
    t2 = time.perf_counter()
    excess, deficit = accuracy(w, wheel)
    off = off_plane(w, wheel) if dense else None
    return {
        "off_plane_hausdorff_mm": off,
        "z2": z2, "tolerance": tolerance, "worm_s": t1 - t0, "wheel_s": t2 - t1,
        "worm_vertices": len(worm.vertices), "wheel_vertices": len(wheel.vertices),
        "watertight": bool(worm.is_watertight and wheel.is_watertight),
        "thickness_excess_mm": excess, "thickness_deficit_mm": deficit,
        "load_before": load0, "load_after": os.getloadavg()[0],
    }  # fmt: skip


def bosl2() -> dict | None:
    """BOSL2's worm wheel z 16, m 2, worm diameter 20, timed and measured (None without
    OpenSCAD)."""
    import shutil
    import subprocess
    import tempfile

    import trimesh

    exe, lib = shutil.which("openscad"), os.environ.get("OPENSCADPATH", "/tmp/bosl")
    if exe is None or not os.path.isdir(os.path.join(lib, "BOSL2")):
        return None
    with tempfile.TemporaryDirectory() as tmp:
        scad, stl = os.path.join(tmp, "wheel.scad"), os.path.join(tmp, "wheel.stl")
        with open(scad, "w") as f:
            f.write("include <BOSL2/std.scad>\ninclude <BOSL2/gears.scad>\n"
                    "worm_gear(mod=2, teeth=16, worm_diam=20, worm_starts=1, crowning=0, "
                    "profile_shift=0, pressure_angle=20);\n")  # fmt: skip
        load0 = os.getloadavg()[0]
        t0 = time.perf_counter()
        subprocess.run([exe, "-o", stl, scad], env=dict(os.environ, OPENSCADPATH=lib),
                       check=True, capture_output=True)  # fmt: skip
        seconds = time.perf_counter() - t0
        wheel = trimesh.load(stl)
    w = WormPair(1, 16, 2.0, diameter_quotient=10, flank="ZA")
    excess, deficit = accuracy(w, wheel)
    return {
        "peer": "BOSL2 worm_gear", "z2": 16, "wheel_s": seconds,
        "wheel_vertices": len(wheel.vertices),
        "watertight": bool(wheel.is_watertight), "thickness_excess_mm": excess,
        "thickness_deficit_mm": deficit, "load_before": load0,
    }  # fmt: skip


def main() -> None:
    rows = [run(10, 0.1, dense=True), run(16, 0.05)]
    peer = bosl2()
    if peer is not None:
        rows.append(peer)
    for r in rows:
        print(r)
    OUT.parent.mkdir(exist_ok=True)
    OUT.write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
