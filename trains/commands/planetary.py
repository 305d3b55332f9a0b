"""Check a planetary stage: ratios, planet speed, coaxiality, assembly, neighbours, every mesh.

Examples::

    geartrain planetary 18 45 108 --planets 3 --module 2
    geartrain planetary 26 70 21 117 --planets 3 --scheme stepped
    geartrain planetary 21 43 108 --planets 3 --module 2 --coaxial
"""

from __future__ import annotations

import argparse

from trains.errors import TrainError
from trains.planetary import SCHEMES, Planetary

HELP = "check a planetary stage (sun planet [planet2] ring) and print its report"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "teeth", type=int, nargs="+", metavar="Z",
        help="sun, planet, ring; or sun, planet (on the sun), planet (on the ring), ring",
    )  # fmt: skip
    parser.add_argument("--planets", "-k", type=int, default=3, help="planet count (3)")
    parser.add_argument("--module", "-m", type=float, default=1.0, help="module in mm (1)")
    parser.add_argument("--scheme", default=None, help=f"one of {', '.join(SCHEMES)}")
    parser.add_argument("--clearance", type=float, default=0.5, help="tip gap, modules (0.5)")
    parser.add_argument(
        "--coaxial", action="store_true",
        help="choose profile shifts for a common working centre distance",
    )  # fmt: skip
    parser.add_argument("--center-distance", type=float, default=None, help="with --coaxial, mm")


def run(args: argparse.Namespace) -> int:
    z = args.teeth
    if len(z) == 3:
        sun, planet, ring = z
        scheme = args.scheme or "simple"
    elif len(z) == 4:
        sun, planet, ring = z[0], (z[1], z[2]), z[3]
        scheme = args.scheme or "stepped"
    else:
        raise TrainError(f"give 3 tooth counts (sun planet ring) or 4; got {len(z)}")
    kw = {"scheme": scheme, "clearance": args.clearance}
    if args.coaxial:
        stage = Planetary.coaxial(sun, planet, ring, args.planets, args.module,
                                  center_distance=args.center_distance, **kw)  # fmt: skip
    else:
        stage = Planetary(sun, planet, ring, args.planets, args.module, **kw)
    print(stage.describe())
    return 0 if stage.check().ok else 1
