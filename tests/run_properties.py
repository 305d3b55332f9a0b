"""The large property run of tests/test_properties.py (issue 17): every count scaled.

    python tests/run_properties.py [SCALE]      # default 32: about 20 000 examples

Runs the sweep with GEARTRAIN_PROPERTY_SCALE=SCALE and fresh random examples, and prints (and
writes to tests/benchmarks/results/properties.json) the examples run per entry point, how many
were answered and how many refused with the library's own error, the failures (the run fails
on any), the time and the machine load.
"""

from __future__ import annotations

import json
import os
import pathlib
import re
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent


def main(scale: float = 32.0) -> int:
    env = dict(os.environ, GEARTRAIN_PROPERTY_SCALE=str(scale))
    load = os.getloadavg()
    t0 = time.perf_counter()
    run = subprocess.run(
        [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-q",
         "--hypothesis-show-statistics", str(ROOT / "tests" / "test_properties.py")],
        cwd=ROOT, env=env, capture_output=True, text=True, check=False,
    )  # fmt: skip
    seconds = time.perf_counter() - t0
    rows, name = {}, None
    for line in run.stdout.splitlines():
        if m := re.match(r"tests/test_properties.py::(\w+):", line):
            name = m.group(1)
            rows[name] = {"passing": 0, "failing": 0, "answered %": None, "refused %": None}
        elif name and (m := re.search(r"(\d+) passing, (\d+) failing", line)):
            rows[name]["passing"] += int(m.group(1))
            rows[name]["failing"] += int(m.group(2))
        elif name and (m := re.search(r"([\d.]+)%, (answered|refused)", line)):
            rows[name][f"{m.group(2)} %"] = float(m.group(1))
    total = sum(r["passing"] + r["failing"] for r in rows.values())
    failures = sum(r["failing"] for r in rows.values())
    result = {
        "scale": scale, "examples": total, "failures": failures, "exit": run.returncode,
        "seconds": round(seconds, 1), "load before": [round(v, 2) for v in load],
        "load after": [round(v, 2) for v in os.getloadavg()], "entry points": rows,
    }  # fmt: skip
    out = ROOT / "tests" / "benchmarks" / "results" / "properties.json"
    out.write_text(json.dumps(result, indent=1) + "\n")
    for k, r in rows.items():
        print(f"{k:<52s} {r['passing'] + r['failing']:>6d} examples, {r['failing']} failing"
              f" (answered {r['answered %']}%, refused {r['refused %']}%)")  # fmt: skip
    print(
        f"{total} examples, {failures} failures, {seconds:.0f} s, load {load} -> "
        f"{os.getloadavg()}; pytest exit {run.returncode}"
    )
    if run.returncode:
        print(run.stdout[-20000:])
    return run.returncode


if __name__ == "__main__":
    raise SystemExit(main(float(sys.argv[1]) if len(sys.argv) > 1 else 32.0))
