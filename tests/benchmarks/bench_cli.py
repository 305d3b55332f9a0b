"""Benchmark: start-up time of the ``geartrain`` command line.

Run as ``python tests/benchmarks/bench_cli.py [--runs N] [--tree PATH]``. Each command is a
fresh process, timed with ``time.perf_counter`` around ``subprocess.run``; reported is the median
of N runs (after one warm-up run that fills the OS file cache), next to the baseline of the same
run: ``python -c pass``, the interpreter's own start-up on this machine. ``--tree`` puts another
source tree first on ``PYTHONPATH`` (e.g. an export of an older commit, for before/after).

The target (issue 11): ``geartrain --help`` under 0.3 s. What it costs beyond the interpreter is
the import of ``trains.cli.app``; the rows ``import trains`` and ``import numpy`` show how much of
it
is the package facade (now lazy: PEP 562) and numpy. The row "CLI alone" runs ``--help`` with
that facade replaced by an empty package: the cost of the command line's own modules.
"""

from __future__ import annotations

import argparse
import os
import platform
import shutil
import statistics
import subprocess
import sys
import time

# ``geartrain --help`` with the ``trains`` package facade (trains/__init__.py) replaced by an empty
# package: what the CLI itself costs once the facade no longer imports the whole library
STUB = (
    "import importlib.util, sys, types\n"
    "spec = importlib.util.find_spec('trains')\n"
    "pkg = types.ModuleType('trains'); pkg.__path__ = list(spec.submodule_search_locations)\n"
    "sys.modules['trains'] = pkg\n"
    "from trains.cli.app import main\n"
    "sys.exit(main(['--help']))\n"
)

COMMANDS = [
    ("python -c pass (baseline)", ["-c", "pass"]),
    ("python -c 'import numpy'", ["-c", "import numpy"]),
    ("python -c 'import trains'", ["-c", "import trains"]),
    ("python -m trains.cli.app --help", ["-m", "trains.cli.app", "--help"]),
    ("CLI alone: --help, trains facade not run", ["-c", STUB]),
    ("python -m trains.cli.app pair --help", ["-m", "trains.cli.app", "pair", "--help"]),
    (
        "python -m trains.cli.app pair 12 24 (a report)",
        ["-m", "trains.cli.app", "pair", "12", "24"],
    ),
]


def _env(tree: str | None) -> dict[str, str]:
    env = dict(os.environ)
    if tree:
        env["PYTHONPATH"] = os.pathsep.join([tree, env.get("PYTHONPATH", "")])
    return env


def medians(argv: list[str], runs: int, trees: list[str | None]) -> list[float]:
    """Median seconds of ``argv`` per tree; the trees' runs alternate, so a busy machine
    slows them alike."""
    envs = [_env(t) for t in trees]
    for env in envs:
        subprocess.run(argv, capture_output=True, env=env, check=False)  # warm-up
    times: list[list[float]] = [[] for _ in trees]
    for _ in range(runs):
        for k, env in enumerate(envs):
            t0 = time.perf_counter()
            p = subprocess.run(argv, capture_output=True, env=env, check=False)
            times[k].append(time.perf_counter() - t0)
            if p.returncode not in (0, 1):
                raise SystemExit(f"{argv} exited {p.returncode}: {p.stderr.decode()[-500:]}")
    return [statistics.median(t) for t in times]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=15)
    ap.add_argument(
        "--tree", action="append", default=[],
        help="another source tree to time alongside (put first on PYTHONPATH); repeatable",
    )  # fmt: skip
    args = ap.parse_args()
    trees: list[str | None] = [None, *args.tree]
    names = ["this checkout", *args.tree]
    print(f"python {platform.python_version()}, {os.cpu_count()} CPUs, median of {args.runs}")
    rows = [(name, [sys.executable, *argv]) for name, argv in COMMANDS]
    script = shutil.which("geartrain")
    if script:
        rows.insert(4, ("geartrain --help (console script)", [script, "--help"]))
    print(f"  {'command':<44s} " + " ".join(f"{n[-24:]:>26s}" for n in names))
    base = None
    for name, argv in rows:
        ts = medians(argv, args.runs, trees)
        base = ts if base is None else base
        cells = [
            f"{t * 1000:7.0f} ms (+{(t - b) * 1000:5.0f})" for t, b in zip(ts, base, strict=True)
        ]
        print(f"  {name:<44s} " + " ".join(f"{c:>26s}" for c in cells))
    print("(+N: milliseconds over the python -c pass baseline of the same tree)")


if __name__ == "__main__":
    main()
