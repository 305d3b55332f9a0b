"""Benchmark: a bevel gear export as a whole process, geartrain against OpenSCAD + BOSL2.

Run: ``python tests/benchmarks/bench_process.py [--runs N] [--tree PATH]`` (writes
``tests/benchmarks/results/process.json``).

- geartrain: ``geartrain bevel 20 40 -m 3 -b 20 --scene x.stl`` (the pair 20/40, m 3, b 20: its
  checks, its table and both gears written as one STL), a fresh ``python -m trains.cli.app``
  process each run, timed with ``time.perf_counter`` around ``subprocess.run``. ``--tree`` times
  another source tree in the same run (e.g. ``git archive`` of an older commit: before/after).
- Beside it, the start-up it cannot avoid, each a fresh process: ``python -c pass`` (the
  interpreter), and the imports the command needs (numpy; scipy.optimize, for the tool's tip
  round; trimesh, for the STL).
- OpenSCAD (Debian's package) with BOSL2 (its repository; give the folder that holds ``BOSL2``
  as OPENSCADPATH; never part of this repository): ``bevel_gear(mod=3, teeth=20, mate_teeth=40,
  face_width=20, spiral=0)``, the pinion alone and the pair, timed as the whole ``openscad -o``
  process. BOSL2's straight bevel is a planar tooth scaled towards the apex (see
  ``bench_bevel.py`` for its measured deviation).

Every command runs once to warm the file cache, then the commands take turns, ``--runs`` times
each, so that all see the same machine load; the median is reported, with ``uptime``'s load at
the start and the end.
"""

from __future__ import annotations

import argparse
import json
import os
import pathlib
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
RESULTS = pathlib.Path(__file__).with_name("results") / "process.json"
GEAR = ["bevel", "20", "40", "-m", "3", "-b", "20"]
SCAD = (
    "include <BOSL2/std.scad>\ninclude <BOSL2/gears.scad>\n"
    'bevel_gear(mod=3, teeth=20, mate_teeth=40, face_width=20, spiral=0, anchor="apex");\n'
)
SCAD_PAIR = SCAD + (
    "rot([0, 90, 0]) bevel_gear(mod=3, teeth=40, mate_teeth=20, face_width=20, spiral=0, "
    'anchor="apex");\n'
)


def load() -> str:
    with open("/proc/loadavg") as f:
        return " ".join(f.read().split()[:3])


def commands(work: pathlib.Path, trees: dict[str, pathlib.Path]) -> dict[str, tuple]:
    """name -> (argv, env) of every timed process."""
    py = sys.executable
    base = {**os.environ, "PYTHONPATH": str(ROOT)}
    out = {
        "python -c pass": ([py, "-c", "pass"], base),
        "python -c 'import numpy'": ([py, "-c", "import numpy"], base),
        "python -c 'import scipy.optimize'": ([py, "-c", "import scipy.optimize"], base),
        "python -c 'import trimesh'": ([py, "-c", "import trimesh"], base),
    }
    for name, tree in trees.items():
        env = {**os.environ, "PYTHONPATH": str(tree), "COLUMNS": "100"}
        stl = work / f"{name}.stl"
        out[f"geartrain {' '.join(GEAR)} --scene x.stl ({name})"] = (
            [py, "-m", "trains.cli.app", *GEAR, "--scene", str(stl)], env,
        )  # fmt: skip
    scad_path = os.environ.get("OPENSCADPATH", "")
    if shutil.which("openscad") and scad_path and (pathlib.Path(scad_path) / "BOSL2").is_dir():
        env = {**os.environ, "OPENSCADPATH": scad_path}
        for name, text in (("pinion", SCAD), ("pair", SCAD_PAIR)):
            scad = work / f"{name}.scad"
            scad.write_text(text)
            out[f"openscad -o x.stl: BOSL2 bevel_gear, the {name}"] = (
                ["openscad", "-o", str(work / f"bosl2_{name}.stl"), str(scad)], env,
            )  # fmt: skip
    else:
        print("OpenSCAD + BOSL2 not found (apt-get install openscad; OPENSCADPATH)")
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--tree", type=pathlib.Path, default=None,
                        help="another source tree timed as 'before'")  # fmt: skip
    args = parser.parse_args()
    trees = {"this tree": ROOT}
    if args.tree:
        trees = {"before": args.tree.resolve(), **trees}
    start = load()
    with tempfile.TemporaryDirectory() as tmp:
        cmds = commands(pathlib.Path(tmp), trees)
        times: dict[str, list[float]] = {name: [] for name in cmds}
        for argv, env in cmds.values():  # warm the file cache; fail loudly
            subprocess.run(argv, env=env, check=True, capture_output=True, cwd=tmp)
        for _ in range(args.runs):
            for name, (argv, env) in cmds.items():
                t = time.perf_counter()
                subprocess.run(argv, env=env, check=True, capture_output=True, cwd=tmp)
                times[name].append(time.perf_counter() - t)
        sizes = {p.name: p.stat().st_size for p in pathlib.Path(tmp).glob("*.stl")}
    end = load()
    medians = {name: statistics.median(ts) for name, ts in times.items()}
    width = max(len(n) for n in medians)
    print(f"load average {start} at the start, {end} at the end; median of {args.runs} runs")
    for name, s in medians.items():
        print(f"{name:{width}s}  {s:7.3f} s")
    RESULTS.parent.mkdir(exist_ok=True)
    RESULTS.write_text(json.dumps({"load_start": start, "load_end": end, "runs": args.runs,
                                   "median_s": medians, "stl_bytes": sizes,
                                   "python": sys.version.split()[0]}, indent=1))  # fmt: skip


if __name__ == "__main__":
    main()
