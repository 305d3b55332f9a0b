"""Rate a gear pair by ISO 6336 method B: the safety against pitting (ISO 6336-2) and against
tooth-root breakage (ISO 6336-3) of both gears for a torque on gear 1 at its speed, with every
load factor, Z factor and Y factor, its value and its clause. Internal gears are rated from the
root their shaper cutter leaves. The exit status is 1 when a safety is below its minimum
(--min-pitting, --min-bending).

Examples:
    geartrain rate 19 61 --module 3 --face-width 30 --torque 150 --speed 1450
    geartrain rate 20 80 -m 2 --internal --face-width 20 --torque 60 --speed 1500 --life 5000
"""

from __future__ import annotations

import argparse

from trains.cli._common import (
    CHECK_FAILED,
    OK,
    PAIR_NAMES,
    RATING_NAMES,
    build_pair,
    pair_arguments,
    rating_arguments,
    rating_minimums,
    rating_options,
)

HELP = "ISO 6336 pitting and bending rating of a gear pair: safety factors and every factor"

NAMES = {**PAIR_NAMES, **RATING_NAMES}
"""The library's names in error messages -> this command's options (see trains.cli.app)."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    pair_arguments(
        parser,
        face_width_help="face width in mm (needed for the overlap ratio of a helical pair and a "
        "rating)",
    )
    rating_arguments(parser, required=True)


def run(args: argparse.Namespace) -> int:
    from gears.errors import GearError

    pair = build_pair(args)
    try:
        rating = pair.rating(args.torque, args.speed, **rating_options(args))
    except GearError as exc:  # a pair that cannot be rated: say which of its options made it
        x1, x2 = pair.g1.profile_shift, pair.g2.profile_shift
        if (x1 or x2) and "--shift" not in str(exc) and "x1" not in str(exc):
            raise GearError(f"{exc} (with --shift {x1:g} {x2:g})") from None
        raise
    report = rating.check(*rating_minimums(args))
    print(rating)
    print()
    print("checks: " + str(report))
    return OK if report.ok else CHECK_FAILED
