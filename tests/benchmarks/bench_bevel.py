"""Benchmark of the bevel solids (issue 19): one gear at 10 um, the differential scene, and the
peers' straight bevel gears at equal measured accuracy, as ratios in the same run.

Run: ``python tests/benchmarks/bench_bevel.py`` (writes ``tests/benchmarks/results/bevel.json``).

- geartrain: KHK's pinion 20/40 (m 3, b 22, tapered clearance, spherical involute so that every
  tool is held to the same exact surface), ``BevelGear.mesh(tolerance=0.01)``, median of 7 runs
  (a new pair each run: nothing is cached); the differential 16/10 with two pinions,
  ``Differential.scene(tolerance=0.01)``, a new differential each run.
- Accuracy is *measured*, the same way for every tool: the solid is cut by the sphere of the
  mean cone distance about the apex (exact, edge by edge), its points are folded onto one tooth
  space (the turn about the axis fitted) and compared with the exact spherical involute of the
  design on the working flank: the largest distance, mm.
- BOSL2's ``bevel_gear()`` (OpenSCAD from the Debian packages, BOSL2 from its repository: give
  its folder's parent as OPENSCADPATH, default /tmp; never part of this repository), straight
  teeth, apex at the origin; timed as the whole ``openscad -o gear.stl`` process.
- py_gearworks 0.0.24 ``BevelGear`` (spherical involute, NURBS through build123d/OCC) where it is
  installed (give its Python as PGW_PYTHON), timed in its own process after its import, STL at
  build123d's tolerance 0.01 mm.
- For each peer, geartrain is timed again at a tolerance equal to the peer's measured deviation
  (equal accuracy), and the ratio peer time / geartrain time is reported.
"""

from __future__ import annotations

import json
import math
import os
import pathlib
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

from gears import BevelPair
from gears.bevel.spherical import polar
from trains import Differential

RESULTS = pathlib.Path(__file__).with_name("results") / "bevel.json"
Z1, Z2, MODULE, FACE = 20, 40, 3.0, 22.0


def _pair(face: float = FACE) -> BevelPair:
    return BevelPair(Z1, Z2, MODULE, face, clearance="tapered", profile="spherical_involute")


def timed(fn, runs: int = 7) -> float:
    """Median wall time of ``fn()`` in seconds."""
    out = []
    for _ in range(runs):
        t = time.perf_counter()
        fn()
        out.append(time.perf_counter() - t)
    return statistics.median(out)


def sphere_section(v: np.ndarray, f: np.ndarray, radius: float) -> np.ndarray:
    """Points where the sphere of ``radius`` about the origin cuts the triangle edges."""
    d = np.linalg.norm(v, axis=1) - radius
    pts = []
    for a, b in ((0, 1), (1, 2), (2, 0)):
        va, vb = v[f[:, a]], v[f[:, b]]
        cross = (d[f[:, a]] < 0) != (d[f[:, b]] < 0)
        va, vb = va[cross], vb[cross]
        e = vb - va
        qa = np.einsum("ij,ij->i", e, e)
        qb = 2 * np.einsum("ij,ij->i", va, e)
        qc = np.einsum("ij,ij->i", va, va) - radius**2
        t = (-qb + np.sqrt(np.maximum(qb * qb - 4 * qa * qc, 0))) / (2 * qa)
        t = np.where((t >= 0) & (t <= 1), t, (-qb - np.sqrt(np.maximum(qb * qb - 4 * qa * qc, 0)))
                     / (2 * qa))  # fmt: skip
        pts.append(va + t[:, None] * e)
    return np.concatenate(pts)


def exact_eta(pair: BevelPair):
    """Azimuth from the space centre of the exact spherical involute flank, as a function of the
    polar angle (the closed form of docs/bevel.md), for the pinion."""
    g = pair.g1
    delta = math.radians(g.pitch_angle)
    alpha = math.radians(pair.pressure_angle)
    r_m, m_m = pair.mean_cone_distance, pair.mean_module
    eta_p = (math.pi * m_m - g.mean_thickness) / (2 * r_m) / math.sin(delta)
    db = math.asin(math.sin(delta) * math.cos(alpha))

    def inv_s(th):
        psi = np.arccos(np.clip(np.cos(th) / math.cos(db), -1, 1))
        return psi / math.sin(db) - np.arctan2(np.sin(psi), np.cos(psi) * math.sin(db))

    return lambda th: eta_p + inv_s(th) - inv_s(delta)


def flank_deviation(v: np.ndarray, f: np.ndarray, pair: BevelPair) -> float:
    """Largest distance (mm) of a solid's section on the mean sphere from the exact flank, the
    solid given with its axis +z and the pitch apex at the origin; the turn about the axis is
    fitted (the median distance minimised over one pitch, then refined)."""
    g = pair.g1
    radius = pair.mean_cone_distance
    th, az = polar(sphere_section(v, f, radius) / radius)
    delta, d_f, d_a = (math.radians(a) for a in (g.pitch_angle, g.root_angle, g.face_angle))
    keep = (th > delta - 0.3 * (delta - d_f)) & (th < delta + 0.8 * (d_a - delta))
    th, az = th[keep], az[keep]
    eta_x = exact_eta(pair)(th)
    pitch = 2 * math.pi / g.teeth

    def dev(offset: float) -> np.ndarray:
        psi = (az - offset + pitch / 2) % pitch - pitch / 2
        return radius * np.sin(th) * np.abs((math.pi / g.teeth - np.abs(psi)) - eta_x)

    grid = np.linspace(0, pitch, 721)
    best = min(grid, key=lambda o: float(np.median(dev(o))))
    fine = np.linspace(best - pitch / 720, best + pitch / 720, 201)
    best = min(fine, key=lambda o: float(np.median(dev(o))))
    return float(dev(best).max())


def geartrain_runs() -> dict:
    out = {}
    m = _pair().g1.mesh(0.01)
    out["gear_10um_s"] = timed(lambda: _pair().g1.mesh(0.01))
    out["gear_10um_triangles"] = len(m.faces)
    out["gear_10um_deviation_mm"] = flank_deviation(m.vertices, m.faces, _pair())
    out["differential_scene_s"] = timed(
        lambda: Differential(16, 10, module=3, gleason=True).scene(tolerance=0.01), runs=5
    )
    return out


def at_deviation(target: float) -> tuple[float, float, float]:
    """geartrain's time at the tolerance whose measured deviation is ``target`` (the tolerance
    is lowered until the measured deviation is at most the target): (seconds, deviation,
    tolerance)."""
    tol = max(target, 1e-4)
    for _ in range(12):
        m = _pair().g1.mesh(tol)
        d = flank_deviation(m.vertices, m.faces, _pair())
        if d <= target:
            break
        tol /= 1.5
    return timed(lambda: _pair().g1.mesh(tol)), d, tol


def bosl2_run(work: pathlib.Path) -> dict | None:
    scad_path = os.environ.get("OPENSCADPATH", "/tmp")
    if shutil.which("openscad") is None or not (pathlib.Path(scad_path) / "BOSL2").is_dir():
        print("BOSL2: openscad or BOSL2 not found (apt-get install openscad; OPENSCADPATH)")
        return None
    scad = work / "bevel.scad"
    scad.write_text(
        "include <BOSL2/std.scad>\ninclude <BOSL2/gears.scad>\n"
        f"bevel_gear(mod={MODULE}, teeth={Z1}, mate_teeth={Z2}, face_width={FACE}, spiral=0, "
        'cutter_radius=0, anchor="apex");\n'
    )
    stl = work / "bosl2.stl"
    env = {**os.environ, "OPENSCADPATH": scad_path}

    def run():
        subprocess.run(["openscad", "-o", str(stl), str(scad)], check=True, env=env,
                       capture_output=True)  # fmt: skip

    seconds = timed(run, runs=3)
    import trimesh

    m = trimesh.load(stl)
    v = np.asarray(m.vertices) * [1.0, -1.0, -1.0]  # BOSL2's teeth point down: turn 180 about x
    return {"s": seconds, "triangles": len(m.faces),
            "deviation_mm": flank_deviation(v, np.asarray(m.faces), _pair())}  # fmt: skip


PGW_SCRIPT = """
import json, math, sys, time
import py_gearworks as pgw
from build123d import export_stl
d1 = math.atan({z1} / {z2})
times = []
for _ in range(3):
    t = time.perf_counter()
    g = pgw.BevelGear(number_of_teeth={z1}, cone_angle=2 * d1, module={m}, height={b},
                      tip_truncation=0.0, dedendum_coefficient=1.25)
    export_stl(g.build_part(), sys.argv[1], tolerance=0.01, angular_tolerance=0.1)
    times.append(time.perf_counter() - t)
print(json.dumps(sorted(times)[1]))
"""


def pgw_run(work: pathlib.Path) -> dict | None:
    python = os.environ.get("PGW_PYTHON", "/tmp/venv-peers/bin/python")
    if not pathlib.Path(python).exists():
        print("py_gearworks: not installed (give its Python as PGW_PYTHON)")
        return None
    stl = work / "pgw.stl"
    script = PGW_SCRIPT.format(z1=Z1, z2=Z2, m=MODULE, b=FACE)
    res = subprocess.run([python, "-c", script, str(stl)], capture_output=True, text=True,
                         timeout=3000)  # fmt: skip
    if res.returncode != 0:
        print("py_gearworks failed:", res.stderr[-400:])
        return None
    seconds = json.loads(res.stdout.strip().splitlines()[-1])
    import trimesh

    m = trimesh.load(stl)
    apex = MODULE * Z1 / 2 / math.tan(math.atan(Z1 / Z2))  # its pitch circle lies in z = 0
    v = (np.asarray(m.vertices) - [0.0, 0.0, apex]) * [1.0, -1.0, -1.0]
    return {"s": seconds, "triangles": len(m.faces),
            "deviation_mm": flank_deviation(v, np.asarray(m.faces), _pair())}  # fmt: skip


def main() -> None:
    load0 = os.getloadavg()
    out = {"load_start": load0, "cores": os.cpu_count()}
    out.update(geartrain_runs())
    with tempfile.TemporaryDirectory() as tmp:
        work = pathlib.Path(tmp)
        for name, run in (("bosl2", bosl2_run), ("py_gearworks", pgw_run)):
            peer = run(work)
            if peer is None:
                continue
            g_s, g_dev, g_tol = at_deviation(peer["deviation_mm"])
            peer.update(geartrain_s=g_s, geartrain_deviation_mm=g_dev, geartrain_tolerance=g_tol,
                        ratio=peer["s"] / g_s)  # fmt: skip
            out[name] = peer
    out["load_end"] = os.getloadavg()
    RESULTS.parent.mkdir(exist_ok=True)
    RESULTS.write_text(json.dumps(out, indent=2) + "\n")
    print(json.dumps(out, indent=2))


if __name__ == "__main__":
    sys.exit(main())
