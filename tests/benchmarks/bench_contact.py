"""Benchmark: loaded tooth contact analysis (issue 29).

Run as ``python tests/benchmarks/bench_contact.py [rounds]``. Prints the best time of

* one loaded transmission-error curve, 64 positions x 30 slices (target <= 20 ms): a spur pair
  (20/50, m 3, b 30, 300 N m) and the helical pair of ISO/TR 6336-30 Example 1 (17/103, m_n 8,
  beta 15.8 deg, b 100, 9000 N m), through ``gears.contact.contact``, the whole call (geometry,
  compliance table, active-set solve, the ideal pair for K_Halpha, factors);
* the same spur curve with tip relief on both gears (the gaps and a second, ideal solve);
* a Harris map of 20 reliefs x 20 torques (target <= 2 s), spur, with 1 slice (the default for
  spur pairs: every slice alike) and with 30 slices;
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
    cases = {
        "TE curve 64 x 30, spur": lambda: contact(p_spur, 300.0),
        "TE curve 64 x 30, helical (TR 6336-30 Ex. 1)": lambda: contact(p_hel, 9000.0),
        "TE curve 64 x 30, spur, tip relief": lambda: contact(relieved, 300.0),
        "Harris map 20 x 20, spur, 1 slice": lambda: harris(p_spur, torques, reliefs),
        "Harris map 20 x 20, spur, 30 slices": lambda: harris(p_spur, torques, reliefs, slices=30),
        "baseline: the spur curve's solve by nnls per position": nnls_curve(p_spur, 300.0),
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
    load = os.getloadavg()
    print(f"load average at the end {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
