"""Benchmark: loaded tooth contact analysis (issue 29).

Run as ``python tests/benchmarks/bench_contact.py [rounds]``. Prints the best time of

* one loaded transmission-error curve, 64 positions x 30 slices (target <= 20 ms): a spur pair
  (20/50, m 3, b 30, 300 N m) and the helical pair of ISO/TR 6336-30 Example 1 (17/103, m_n 8,
  beta 15.8 deg, b 100, 9000 N m), through ``gears.contact.contact``, the whole call (geometry,
  compliance table, active-set solve, the ideal pair for K_Halpha, factors);
* the same spur curve with tip relief on both gears (the gaps and a second, ideal solve);
* a Harris map of 20 reliefs x 20 torques (target <= 2 s), spur, with 1 slice (the default for
  spur pairs: every slice alike) and with 30 slices;
* an internal pair's curve (the planet-ring mesh 29/77, m 2, b 20, 60 N m), and a planetary
  stage's (19/29/77, three planets: both meshes and the net transmission error,
  ``Planetary.contact``);
* the design search ``GearPair.best_modification`` at 300 N m: 41 tip reliefs (aligned, 1
  slice) and 41 tip reliefs x 9 crownings under a 20 um tilt (20 slices), beside the second
  baseline: the same 41 x 9 grid as one ``contact`` call per cell (same positions and slices);
* the baseline, measured in the same rounds: the same spur curve's load sharing solved position
  by position with ``scipy.optimize.nnls`` (the complementary-energy least squares of
  tests/gears/test_contact.py), the stiffness and gaps taken from the vectorised analysis, so
  the ratio is the solve's alone.

Not a test: pytest does not collect ``bench_*.py``. Results: docs/performance.md.
"""

from __future__ import annotations

import math
import os
import platform
import sys
import time

import numpy as np
from scipy.optimize import nnls

from gears import BasicRack, Gear, GearPair
from gears.contact.analysis import loaded_contact
from gears.contact.result import contact, contact_geometry, harris


def spur(modification=None):
    kw = {} if modification is None else {"modification": modification}
    return GearPair(Gear(20, 3, face_width=30, **kw), Gear(50, 3, face_width=30, **kw))


def helical():
    rack = BasicRack.iso53("D")
    g1 = Gear(17, 8, helix_angle=15.8, profile_shift=0.14522, face_width=100, rack=rack)
    g2 = Gear(103, 8, helix_angle=-15.8, profile_shift=0.0, face_width=100, rack=rack)
    return GearPair(g1, g2)


def nnls_curve(pair, torque, positions=64, slices=30):
    """The baseline: each position's load sharing by scipy.optimize.nnls."""
    geometry = contact_geometry(pair)
    a = loaded_contact(geometry, 1000 * torque / geometry["rb1"], None, positions, slices)
    k = a["stiffness"].reshape(positions, -1)
    g = np.where(np.isfinite(a["gaps"]), a["gaps"], 0.0).reshape(positions, -1)
    load = 1000 * torque / geometry["rb1"]

    def run():
        out = np.empty(positions)
        for i in range(positions):
            on = k[i] > 0
            ki, gi = k[i][on], g[i][on]
            w = 1e4 * math.sqrt(np.max(1 / ki))
            mat = np.vstack([np.diag(1 / np.sqrt(ki)), w * np.ones(ki.size)])
            rhs = np.concatenate([-gi * np.sqrt(ki), [w * load]])
            f, _ = nnls(mat, rhs, maxiter=10 * ki.size)
            live = f > 0
            out[i] = np.mean(gi[live] + f[live] / ki[live])
        return out

    return run


def best(fn, rounds: int, calls: int = 1) -> float:
    out = math.inf
    for _ in range(rounds):
        t0 = time.perf_counter()
        for _ in range(calls):
            fn()
        out = min(out, (time.perf_counter() - t0) / calls)
    return out


def main(rounds: int = 7) -> dict[str, float]:
    try:
        from gears.contact.modification import Modification

        relieved = spur(Modification(tip_relief=0.02))
    except TypeError:  # a Gear without modification=: the unmodified pair twice
        relieved = spur()
    p_spur, p_hel = spur(), helical()
    reliefs = np.linspace(0, 0.04, 20)
    torques = np.linspace(20, 400, 20)
    from gears.contact.result import best_modification
    from trains import Planetary

    stage = Planetary(19, 29, 77, n_planets=3, module=2)
    ring = stage.meshes["planet-ring"]
    ring = GearPair(ring.g1.with_(face_width=20), ring.g2.with_(face_width=20))
    grid_r, grid_c = np.linspace(0, 0.04, 41), np.linspace(0, 0.02, 9)

    def per_cell():
        from gears.contact.modification import Modification

        for ca in grid_r:
            for cb in grid_c:
                m1 = Modification(tip_relief=ca, crowning=cb)
                m2 = Modification(tip_relief=ca)
                pair = GearPair(p_spur.g1.with_(modification=m1), p_spur.g2.with_(modification=m2))
                contact(pair, 300.0, misalignment=0.02, positions=32, slices=20)

    cases = {
        "TE curve 64 x 30, spur": lambda: contact(p_spur, 300.0),
        "TE curve 64 x 30, helical (TR 6336-30 Ex. 1)": lambda: contact(p_hel, 9000.0),
        "TE curve 64 x 30, spur, tip relief": lambda: contact(relieved, 300.0),
        "Harris map 20 x 20, spur, 1 slice": lambda: harris(p_spur, torques, reliefs),
        "Harris map 20 x 20, spur, 30 slices": lambda: harris(p_spur, torques, reliefs, slices=30),
        "baseline: the spur curve's solve by nnls per position": nnls_curve(p_spur, 300.0),
        "TE curve 64 x 30, internal 29/77": lambda: contact(ring, 60.0),
        "Planetary.contact 19/29/77 x 3, 64 x 30": lambda: stage.contact(40.0, face_width=20),
        "best_modification 41 reliefs, spur, 1 slice": lambda: best_modification(p_spur, 300.0),
        "best_modification 41 x 9, tilt 20 um, 20 slices": lambda: best_modification(
            p_spur, 300.0, misalignment=0.02, tip_reliefs=grid_r, crownings=grid_c
        ),
        "baseline: the 41 x 9 grid, one contact per cell": per_cell,
    }
    for fn in cases.values():
        fn()  # warm up
    times = dict.fromkeys(cases, math.inf)
    for _ in range(rounds):  # interleaved, so that the machine's load falls on each alike
        for name, fn in cases.items():
            times[name] = min(times[name], best(fn, 1, 3))
    return times


if __name__ == "__main__":
    rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 7
    load = os.getloadavg()
    print(f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores, Python "
          f"{platform.python_version()}, numpy {np.__version__}; load average "
          f"{load[0]:.2f} {load[1]:.2f} {load[2]:.2f} (uptime)")  # fmt: skip
    times = main(rounds)
    for name, s in times.items():
        print(f"{name:55s} {s * 1e3:9.2f} ms")
    base = times["baseline: the spur curve's solve by nnls per position"]
    print(
        f"nnls per position / whole vectorised curve: {base / times['TE curve 64 x 30, spur']:.1f}"
    )
    grid = times["best_modification 41 x 9, tilt 20 um, 20 slices"]
    print(f"one contact per cell / the grid at once: "
          f"{times['baseline: the 41 x 9 grid, one contact per cell'] / grid:.1f}")  # fmt: skip
    load = os.getloadavg()
    print(f"load average at the end {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
