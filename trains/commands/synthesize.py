"""Search the tooth numbers of a planetary stage for a target ratio; print a ranked table.

Examples::

    geartrain synthesize --ratio 7 --planets 3
    geartrain synthesize --ratio 16 --planets 3 --scheme stepped --z-max 120
    geartrain synthesize --ratio 7.2 --planets 3-5 --tolerance 0.01 --allow-shift
"""

from __future__ import annotations

import argparse

from trains.errors import TrainError
from trains.planetary import SCHEMES
from trains.synthesis import synthesize

HELP = "search planetary tooth numbers for a target ratio and print them ranked"


def _planets(text: str):
    if "-" in text:
        lo, hi = text.split("-", 1)
        try:
            return range(int(lo), int(hi) + 1)
        except ValueError:
            raise TrainError(
                f"--planets {text!r}; give a count like 3 or a range like 3-5"
            ) from None
    try:
        return int(text)
    except ValueError:
        raise TrainError(f"--planets {text!r}; give a count like 3 or a range like 3-5") from None


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--ratio", "-r", required=True, help="target ratio, e.g. 7 or 22/3")
    parser.add_argument("--planets", "-k", default="3", help="planet count or range (3, 3-5)")
    parser.add_argument("--scheme", default="simple", help=f"one of {', '.join(SCHEMES)}")
    parser.add_argument("--tolerance", type=float, default=0.0, help="relative ratio error (0)")
    parser.add_argument("--z-min", type=int, default=17)
    parser.add_argument("--z-max", type=int, default=200)
    parser.add_argument("--module", "-m", type=float, default=None)
    parser.add_argument("--allow-shift", action="store_true", help="accept shifted coaxial sets")
    parser.add_argument("--fixed", default="ring", help="fixed member (ring)")
    parser.add_argument("--input", default=None, help="input member (sun when the ring is fixed)")
    parser.add_argument("--output", default=None, help="output member")
    parser.add_argument(
        "--mesh-checks", default="geometry", choices=("geometry", "textbook", "full"),
        help="which mesh conditions filter the sets (geometry)",
    )  # fmt: skip
    parser.add_argument("--limit", type=int, default=10, help="rows to print (10)")


def run(args: argparse.Namespace) -> int:
    found = synthesize(
        args.ratio, _planets(args.planets), scheme=args.scheme, tolerance=args.tolerance,
        z_min=args.z_min, z_max=args.z_max, module=args.module, allow_shift=args.allow_shift,
        fixed=args.fixed, input=args.input, output=args.output, mesh_checks=args.mesh_checks,
        limit=args.limit,
    )  # fmt: skip
    print(found.table())
    if found:
        print(found.reason)
    return 0 if found else 1
