"""Layer 8, command line: the ``geartrain`` command line.

Each sub-command is a module in :mod:`trains.commands` exposing ``HELP`` (one line),
``add_arguments(parser)`` and ``run(args) -> int``; the modules are discovered, so adding a
command is adding a file.
"""

from __future__ import annotations

import argparse
import importlib
import pkgutil
import sys

from gears.errors import GearError
from trains import commands
from trains.errors import TrainError


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="geartrain",
        description="Involute gear geometry, tooth profiles and gear-train solving.",
    )
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for info in sorted(pkgutil.iter_modules(commands.__path__), key=lambda m: m.name):
        module = importlib.import_module(f"trains.commands.{info.name}")
        p = sub.add_parser(info.name, help=module.HELP, description=module.__doc__)
        module.add_arguments(p)
        p.set_defaults(run=module.run)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return int(args.run(args) or 0)
    except (GearError, TrainError) as exc:
        print(f"geartrain {args.command}: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
