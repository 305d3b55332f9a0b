"""Rate a gear pair by ISO 6336 method B: the safety against pitting (ISO 6336-2) and against
tooth-root breakage (ISO 6336-3) of both gears for a torque on gear 1 at its speed, with every
load factor, Z factor and Y factor, its value and its clause. Internal gears are rated from the
root their shaper cutter leaves. The exit status is 1 when a safety is below its minimum
(--min-pitting, --min-bending). With --spectrum FILE (one bin a line: torque N m, speed
rpm, hours) the pair is rated under that load spectrum by ISO 6336-6: Miner's sum per gear and
failure mode, the equivalent safeties and the lives. With --fzg-stage (the oil's FZG load stage,
test A/8.3/90) and --oil-temperature the pair is also rated against scuffing by the flash
temperature method (ISO/TS 6336-20) and the integral temperature method (ISO/TS 6336-21); the
exit status is 1 when S_B or S_intS is below --min-scuffing (2.0 1.8).

Examples:
    geartrain rate 19 61 --module 3 --face-width 30 --torque 150 --speed 1450
    geartrain rate 20 80 -m 2 --internal --face-width 20 --torque 60 --speed 1500 --life 5000
"""

from __future__ import annotations

import argparse

from trains.cli._common import CHECK_FAILED, OK, PAIR_NAMES, build_pair, pair_arguments
from trains.cli._rating import (
    RATING_NAMES,
    SCUFFING_NAMES,
    edition_argument,
    edition_option,
    rating_arguments,
    rating_minimums,
    rating_options,
    scuffing_arguments,
    scuffing_minimum,
    scuffing_options,
)

HELP = "ISO 6336 pitting and bending rating of a gear pair: safety factors and every factor"

NAMES = {**PAIR_NAMES, **RATING_NAMES, **SCUFFING_NAMES, "spectrum": "--spectrum"}
"""The library's names in error messages -> this command's options (see trains.cli.app)."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    pair_arguments(
        parser,
        face_width_help="face width in mm (needed for the overlap ratio of a helical pair and a "
        "rating)",
    )
    rating_arguments(parser, required=False)
    edition_argument(parser)
    parser.add_argument(
        "--spectrum", default=None, metavar="FILE",
        help="load spectrum (ISO 6336-6): a file of bins, one a line: torque N m, speed rpm, "
        "hours (instead of --torque, --speed and --life)",
    )  # fmt: skip
    scuffing_arguments(parser)


def run(args: argparse.Namespace) -> int:
    from gears.errors import GearError
    from gears.rating.spectrum import read_spectrum

    pair = build_pair(args)
    options = rating_options(args) | edition_option(args)
    options |= scuffing_options(args, options["oil_viscosity"])
    try:
        if args.spectrum is not None:
            if args.torque is not None or args.speed is not None or args.life is not None:
                raise GearError("spectrum = FILE replaces --torque, --speed and --life; give one")
            bins = read_spectrum(args.spectrum)
            options.pop("life")
            rating = pair.rating(spectrum=bins, **options)
        else:
            if args.torque is None or args.speed is None:
                raise GearError("torque = None: give --torque and --speed, or --spectrum FILE")
            rating = pair.rating(args.torque, args.speed, **options)
    except GearError as exc:  # a pair that cannot be rated: say which of its options made it
        x1, x2 = pair.g1.profile_shift, pair.g2.profile_shift
        if (x1 or x2) and "--shift" not in str(exc) and "x1" not in str(exc):
            raise GearError(f"{exc} (with --shift {x1:g} {x2:g})") from None
        raise
    report = rating.check(*rating_minimums(args), **scuffing_minimum(args))
    print(rating)
    print()
    print("checks: " + str(report))
    return OK if report.ok else CHECK_FAILED
