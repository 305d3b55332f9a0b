"""Benchmark of the gearbox search's mesh losses (a script; not collected by pytest). Issue 30.

What the stages' efficiency from their meshes costs the rated gearbox search: the lightest
2-stage 1:20 gearbox for 50 N m at 1500 rpm (as ``bench_load.py``), simple + stepped, z <= 150,
local threads, timed with the losses (``objective="mass"`` and ``"mesh_efficiency"``) and,
as the baseline, with ``trains.design.sizing.stage_efficiency`` replaced by zeros (the sizing
without the losses, the search before issue 30). The machine is shared: the runs interleave,
``ROUNDS`` rounds, best of each, and the load average is printed before and after. Run:
``python tests/benchmarks/bench_gearbox_losses.py`` (writes
``tests/benchmarks/results/gearbox_losses.json``).
"""

from __future__ import annotations

import json
import os
import pathlib
import time

import numpy as np

import trains.design.sizing
from trains import synthesize_gearbox

ROUNDS = 3
GEARBOX = dict(ratio=20, stages=2, torque=50, speed=1500, face_width=range(10, 45, 5),
               schemes=("simple", "stepped"), z_max=150, progress=False)  # fmt: skip


def _zeros(load, scheme, z1, *args, **kwargs):
    return np.zeros(np.shape(z1))


def main() -> None:
    print("load average before", os.getloadavg())
    real = trains.design.sizing.stage_efficiency
    best = {"baseline (no losses), mass": np.inf, "mass": np.inf, "mesh_efficiency": np.inf}
    found = {}
    for _ in range(ROUNDS):
        for case in best:
            objective = case.split(", ")[-1]
            stub = case.startswith("baseline")
            trains.design.sizing.stage_efficiency = _zeros if stub else real
            t0 = time.perf_counter()
            boxes = synthesize_gearbox(**GEARBOX, objective=objective)
            best[case] = min(best[case], time.perf_counter() - t0)
            found[case] = (boxes.sized, str(boxes[0]))
    trains.design.sizing.stage_efficiency = real
    base = best["baseline (no losses), mass"]
    for case, t in best.items():
        print(f"{case}: {t:.2f} s ({t / base:.2f} x baseline), {found[case][0]} stage loads sized")
        print(f"    best: {found[case][1]}")
    print("load average after", os.getloadavg())
    out = pathlib.Path(__file__).parent / "results" / "gearbox_losses.json"
    out.write_text(json.dumps({"seconds": best, "load_after": os.getloadavg()}, indent=1))


if __name__ == "__main__":
    main()
