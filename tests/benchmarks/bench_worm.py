"""Benchmark of the worm solids: the worm's helicoid solid and the wheel built on the envelope
of its thread, at three tolerances, with the measured accuracy, against OpenSCAD + BOSL2 and the
``wormgear`` package where they run.

Run: ``python tests/benchmarks/bench_worm.py`` (writes ``tests/benchmarks/results/worm.json``).

- The pairs: z1 1, m_x 2, q 10, ZA; z2 10 (x2 0.3, face 10 mm) and z2 16 (x2 0 like BOSL2's,
  and 0.3). The mid-plane conjugate of a ZA worm is the involute of r_2 cos(alpha_x): exact.
- Timed: ``WormPair.wheel_mesh`` on a new pair each run (nothing cached), the best of three wall
  times (the worm once); the machine's load (``os.getloadavg``) is recorded with each row.
- Speed against the peer (:func:`speed`): rounds interleaving BOSL2's ``worm_gear()`` (the whole
  ``openscad`` process, and the same process with BOSL2 included but only a cube drawn: its
  library's parse), our wheel z2 16, x2 0 at 0.1 mm in this warm process, our whole fresh
  process (``python -c``: the imports, trimesh's above all, then the wheel) and, where
  GEARTRAIN_BEFORE names an older tree of this library (``git archive``), the same warm wheel
  timed by that tree in its own interpreter; the best of each.
- Mid-plane accuracy: the wheel cut by its mid-plane (manifold3d's slice), the tooth thickness
  on four circles between the root form and the tip against the involute's
  (``gears.geometry.tooth_thickness``): the largest excess and deficit, mm.
- Off the mid-plane: the contact lines of the worm's helicoid found in 3D by n . v_12 = 0 (the
  tests' independent reference, tests/gears/test_worm_wheel.py), their exact signed distances to
  the wheel's mesh on the working flank (inside the faces, 0.1 mm below the tip, above the pitch
  circle; the tip lowered where a pointed tooth's flanks cross, as the mesh's planes have it).
- Overlap at zero backlash: the volume the worm and the wheel share in ``WormPair.scene``'s
  placement at four angles (manifold3d), the largest.
- OpenSCAD + BOSL2 ``worm_gear(mod=2, teeth=16, worm_diam=20, worm_starts=1, crowning=0,
  profile_shift=0)`` where OpenSCAD is installed (BOSL2's parent folder in OPENSCADPATH,
  default /tmp/bosl; never part of this repository): the whole ``openscad -o wheel.stl``
  process timed, its wheel's mid-plane measured against the involute the same way. Its
  off-plane accuracy and overlap are not measured (its placement conventions differ).
- The ``wormgear`` package, from a separate virtual environment given by WORMGEAR_PYTHON, if
  it runs (see docs/performance.md).
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


def off_plane(w: WormPair, wheel) -> tuple[float, float]:
    """Signed distances (min, max) of the 3D contact lines to the wheel's mesh, mm."""
    import sys

    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2]))
    from tests.gears.test_worm_wheel import contact_points, signed_distance, working_flank

    out = []
    for flank in (1.0, -1.0):
        q = working_flank(w, wheel, contact_points(w, flank, n_r=30, n_phi=120))
        out.append(signed_distance(wheel, q))
    d = np.concatenate(out)
    return float(d.min()), float(d.max())


def peer_off_plane(w: WormPair, wheel, turns: int = 91) -> dict:
    """A peer's wheel against the exact conjugate off the mid-plane: the signed distances of
    the 3D contact lines (both flanks) on the working flank within the peer's faces and below
    its tip, at the turn about its axis (a tooth pitch in ``turns`` steps, then 0.01 deg) that
    fits them best (least mean square: the peer's phase is its own), and ours on the same
    points at 0.01 mm."""
    import sys

    import trimesh

    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2]))
    from tests.gears.test_worm_wheel import contact_points, signed_distance, working_flank

    q = np.concatenate([contact_points(w, f, n_r=20, n_phi=90) for f in (1.0, -1.0)])
    half = min(float(np.abs(wheel.bounds[:, 2]).min()), w.face_width / 2) - 0.3
    q = working_flank(w, wheel, q)
    q = q[np.abs(q[:, 2]) < half]

    def turned(deg):
        m = wheel.copy()
        m.apply_transform(trimesh.transformations.rotation_matrix(math.radians(deg), [0, 0, 1]))
        return signed_distance(m, q)

    pitch = 360.0 / w.wheel_teeth
    coarse = min(np.linspace(0.0, pitch, turns, endpoint=False),
                 key=lambda a: float(np.mean(turned(a)[::5] ** 2)))  # fmt: skip
    fine = min(np.linspace(coarse - pitch / turns, coarse + pitch / turns, 41),
               key=lambda a: float(np.mean(turned(a) ** 2)))  # fmt: skip
    d, ours = turned(fine), signed_distance(w.wheel_mesh(0.01), q)
    return {"points": len(q), "turn_deg": float(fine), "min_mm": float(d.min()),
            "max_mm": float(d.max()), "rms_mm": float(np.sqrt(np.mean(d**2))),
            "ours_0.01_min_mm": float(ours.min()),
            "ours_0.01_max_mm": float(ours.max())}  # fmt: skip


def overlap(w: WormPair, worm, wheel) -> float:
    worst = 0.0
    for angle in (0.0, 7.0, 90.0, 200.0):
        at1, at2 = w.placements(angle)
        worst = max(worst, (to_manifold(worm, at1) ^ to_manifold(wheel, at2)).volume())
    return worst


def run(z2: int, tolerance: float, shift: float = 0.3, face: float | None = None) -> dict:
    load0 = os.getloadavg()[0]
    times = []
    for _ in range(3):
        w = WormPair(1, z2, 2.0, diameter_quotient=10, flank="ZA", profile_shift=shift,
                     face_width=face)  # fmt: skip
        t0 = time.perf_counter()
        wheel = w.wheel_mesh(tolerance)
        times.append(time.perf_counter() - t0)
    t0 = time.perf_counter()
    worm = w.worm_mesh(tolerance)
    worm_s = time.perf_counter() - t0
    excess, deficit = accuracy(w, wheel)
    lo, hi = off_plane(w, wheel)
    return {
        "z2": z2, "x2": shift, "tolerance": tolerance, "worm_s": worm_s, "wheel_s": min(times),
        "wheel_vertices": len(wheel.vertices),
        "watertight": bool(worm.is_watertight and wheel.is_watertight),
        "thickness_excess_mm": excess, "thickness_deficit_mm": deficit,
        "off_plane_min_mm": lo, "off_plane_max_mm": hi, "overlap_mm3": overlap(w, worm, wheel),
        "load_before": load0, "load_after": os.getloadavg()[0],
    }  # fmt: skip


def _openscad(source: str, read=None):
    """Seconds of one whole ``openscad -o x.stl`` process on ``source``, and with ``read`` what
    ``read(path)`` makes of its STL as well (None without OpenSCAD or BOSL2)."""
    import shutil
    import subprocess
    import tempfile

    exe, lib = shutil.which("openscad"), os.environ.get("OPENSCADPATH", "/tmp/bosl")
    if exe is None or not os.path.isdir(os.path.join(lib, "BOSL2")):
        return None
    with tempfile.TemporaryDirectory() as tmp:
        scad, stl = os.path.join(tmp, "x.scad"), os.path.join(tmp, "x.stl")
        with open(scad, "w") as f:
            f.write(source)
        t0 = time.perf_counter()
        subprocess.run([exe, "-o", stl, scad], env=dict(os.environ, OPENSCADPATH=lib),
                       check=True, capture_output=True)  # fmt: skip
        seconds = time.perf_counter() - t0
        return seconds if read is None else (seconds, read(stl))


BOSL2_WHEEL = (
    "include <BOSL2/std.scad>\ninclude <BOSL2/gears.scad>\n"
    "worm_gear(mod=2, teeth=16, worm_diam=20, worm_starts=1, crowning=0, profile_shift=0, "
    "pressure_angle=20);\n"
)
BOSL2_CUBE = "include <BOSL2/std.scad>\ninclude <BOSL2/gears.scad>\ncube(1);\n"
WARM = """
import sys, time
from gears import WormPair
best = []
for _ in range(4):
    w = WormPair(1, 16, 2.0, diameter_quotient=10, flank="ZA")
    t0 = time.perf_counter()
    w.wheel_mesh(0.1)
    best.append(time.perf_counter() - t0)
print(min(best[1:]))
"""
COLD = """
from gears import WormPair
WormPair(1, 16, 2.0, diameter_quotient=10, flank="ZA").wheel_mesh(0.1)
"""


def _warm() -> float:
    w = WormPair(1, 16, 2.0, diameter_quotient=10, flank="ZA")
    t0 = time.perf_counter()
    w.wheel_mesh(0.1)
    return time.perf_counter() - t0


def _python(code: str, tree: str) -> tuple[float, str]:
    """Seconds of a whole ``python -c code`` process run in ``tree`` (``-c`` puts the working
    folder first on the path), and its output."""
    import subprocess
    import sys

    t0 = time.perf_counter()
    done = subprocess.run([sys.executable, "-c", code], env=dict(os.environ, PYTHONPATH=tree),
                          cwd=tree, check=True, capture_output=True, text=True)  # fmt: skip
    return time.perf_counter() - t0, done.stdout


def speed(rounds: int = 5) -> dict | None:
    """Our wheel z2 16, x2 0 at 0.1 mm against BOSL2's on the same pair, interleaved rounds, the
    best of each (module docstring); None without OpenSCAD."""
    if _openscad(BOSL2_CUBE) is None:
        return None
    here = str(pathlib.Path(__file__).resolve().parents[2])
    before = os.environ.get("GEARTRAIN_BEFORE")
    _warm()
    times: dict[str, list[float]] = {}
    load0 = os.getloadavg()
    for _ in range(rounds):
        runs = {
            "bosl2_s": lambda: _openscad(BOSL2_WHEEL),
            "bosl2_include_only_s": lambda: _openscad(BOSL2_CUBE),
            "ours_warm_s": lambda: min(_warm() for _ in range(3)),
            "ours_fresh_process_s": lambda: _python(COLD, here)[0],
        }
        if before:
            runs["before_warm_s"] = lambda: float(_python(WARM, before)[1].split()[-1])
        for key, run_ in runs.items():
            times.setdefault(key, []).append(run_())
    best = {k: min(v) for k, v in times.items()}
    out = {"peer": "speed, z2 16, x2 0, 0.1 mm", **best, "rounds": rounds,
           "load_before": load0, "load_after": os.getloadavg()}  # fmt: skip
    out["ratio_bosl2_to_ours_warm"] = best["bosl2_s"] / best["ours_warm_s"]
    out["ratio_bosl2_geometry_to_ours_warm"] = (
        best["bosl2_s"] - best["bosl2_include_only_s"]
    ) / best["ours_warm_s"]
    out["ratio_bosl2_to_ours_fresh_process"] = best["bosl2_s"] / best["ours_fresh_process_s"]
    if before:
        out["ratio_before_to_ours_warm"] = best["before_warm_s"] / best["ours_warm_s"]
    return out


def bosl2() -> dict | None:
    """BOSL2's worm wheel z 16, m 2, worm diameter 20, timed and measured (None without
    OpenSCAD)."""
    import trimesh

    load0 = os.getloadavg()[0]
    done = _openscad(BOSL2_WHEEL, trimesh.load)
    if done is None:
        return None
    seconds, wheel = done
    w = WormPair(1, 16, 2.0, diameter_quotient=10, flank="ZA")
    excess, deficit = accuracy(w, wheel)
    return {
        "peer": "BOSL2 worm_gear", "z2": 16, "wheel_s": seconds,
        "wheel_vertices": len(wheel.vertices),
        "watertight": bool(wheel.is_watertight), "thickness_excess_mm": excess,
        "thickness_deficit_mm": deficit, "off_plane": peer_off_plane(w, wheel),
        "overlap": bosl2_overlap(), "load_before": load0,
    }  # fmt: skip


BOSL2_WORM = (
    "include <BOSL2/std.scad>\ninclude <BOSL2/gears.scad>\n"
    "worm(mod=2, d=20, starts=1, l=40, orient=BACK);\n"
)


def bosl2_overlap() -> dict | None:
    """The volume BOSL2's worm (``worm()``, its axis along y) and wheel (``worm_gear()`` as in
    :data:`BOSL2_WHEEL`, its axis z through x = a = 26 mm, ``worm_dist``) share in mesh: the
    wheel at the turn where they share the least (a tooth pitch in 91 steps, then bounded to
    1e-4 deg; BOSL2's documented ``zrot`` phase is that of its own 30-tooth example), then the
    worm turned by phi and the wheel by phi z1 / z2 (None without OpenSCAD)."""
    import trimesh

    worm = _openscad(BOSL2_WORM, trimesh.load)
    wheel = _openscad(BOSL2_WHEEL, trimesh.load)
    if worm is None or wheel is None:
        return None
    a = 26.0
    w, g = to_manifold(worm[1]), to_manifold(wheel[1]).translate([a, 0.0, 0.0])

    def shared(phi, turn):
        gear = g.translate([-a, 0.0, 0.0]).rotate([0.0, 0.0, turn + phi / 16.0])
        return (w.rotate([0.0, phi, 0.0]) ^ gear.translate([a, 0.0, 0.0])).volume()

    from scipy.optimize import minimize_scalar

    coarse = min(np.linspace(-11.25, 11.25, 91), key=lambda t: shared(0.0, t))
    turn = minimize_scalar(lambda t: shared(0.0, t), bounds=(coarse - 0.25, coarse + 0.25),
                           method="bounded", options={"xatol": 1e-4}).x  # fmt: skip
    return {"turn_deg": float(turn),
            "shared_mm3": {phi: shared(phi, turn) for phi in (0.0, 7.0, 90.0, 200.0)}}  # fmt: skip


WORMGEAR = """
import sys, time
from wormgear.calculator.core import design_from_module
from wormgear.core.wheel import WheelGeometry
from build123d import export_stl
d = design_from_module(2.0, 16, worm_pitch_diameter=20.0, clearance_factor=0.2, profile="ZA")
t0 = time.perf_counter()
part = WheelGeometry(d.wheel, d.worm, d.assembly, throated=True).build()
seconds = time.perf_counter() - t0
export_stl(part, sys.argv[1], tolerance=0.01, angular_tolerance=0.1)
print(seconds)
"""


def wormgear() -> dict | None:
    """The ``wormgear`` package's throated wheel z 16, m 2, worm diameter 20 (its
    ``WheelGeometry(throated=True)``, build123d), timed in its own interpreter
    (WORMGEAR_PYTHON), centred and measured like ours; None where it is not installed."""
    import subprocess
    import tempfile

    import trimesh

    exe = os.environ.get("WORMGEAR_PYTHON")
    if not exe or not os.path.exists(exe):
        return None
    with tempfile.TemporaryDirectory() as tmp:
        stl = os.path.join(tmp, "wheel.stl")
        load0 = os.getloadavg()[0]
        done = subprocess.run([exe, "-c", WORMGEAR, stl], capture_output=True, text=True)
        if done.returncode != 0:
            return {"peer": "wormgear", "error": done.stderr.strip().splitlines()[-1]}
        wheel = trimesh.load(stl)
    wheel.apply_translation(-wheel.bounds.mean(axis=0))
    excess, deficit = accuracy(WormPair(1, 16, 2.0, diameter_quotient=10, flank="ZA"), wheel)
    return {
        "peer": "wormgear WheelGeometry(throated=True)", "z2": 16,
        "wheel_s": float(done.stdout.split()[-1]), "wheel_vertices": len(wheel.vertices),
        "watertight": bool(wheel.is_watertight), "thickness_excess_mm": excess,
        "thickness_deficit_mm": deficit, "load_before": load0,
    }  # fmt: skip


def main() -> None:
    rows = [run(10, 0.1, face=10.0)]
    rows += [run(16, tol, shift=0.0) for tol in (0.1, 0.05, 0.01)]
    rows += [run(16, 0.05)]
    for peer in (bosl2(), wormgear(), speed()):
        if peer is not None:
            rows.append(peer)
    for r in rows:
        print(r)
    OUT.parent.mkdir(exist_ok=True)
    OUT.write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
