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

NAMES = {
    **PAIR_NAMES, **RATING_NAMES, "spectrum": "--spectrum", "fzg_stage": "--fzg-stage",
    "oil temperature": "--oil-temperature", "oil viscosity_100": "--oil-viscosity-100",
    "oil viscosity_40": "--oil-viscosity", "oil base": "--oil", "oil density": "--oil-density",
    "welding_factor": "--welding-factor", "min_scuffing": "--min-scuffing",
}  # fmt: skip
"""The library's names in error messages -> this command's options (see trains.cli.app)."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    pair_arguments(
        parser,
        face_width_help="face width in mm (needed for the overlap ratio of a helical pair and a "
        "rating)",
    )
    rating_arguments(parser, required=False)
    parser.add_argument(
        "--spectrum", default=None, metavar="FILE",
        help="load spectrum (ISO 6336-6): a file of bins, one a line: torque N m, speed rpm, "
        "hours (instead of --torque, --speed and --life)",
    )  # fmt: skip
    scuffing = parser.add_argument_group(
        "scuffing (ISO/TS 6336-20 flash temperature, ISO/TS 6336-21 integral temperature)"
    )
    scuffing.add_argument(
        "--fzg-stage", type=int, default=None, metavar="STAGE",
        help="the oil's failure load stage in the FZG test A/8.3/90 (ISO 14635-1), 1 ... 12: "
        "rate against scuffing",
    )  # fmt: skip
    scuffing.add_argument(
        "--oil-temperature", type=float, default=None, metavar="C",
        help="oil temperature before the mesh, deg C (needed with --fzg-stage)",
    )  # fmt: skip
    scuffing.add_argument(
        "--oil-viscosity-100", type=float, default=None, metavar="NU100",
        help="the oil's kinematic viscosity at 100 deg C, mm^2/s (needed with --fzg-stage; "
        "--oil-viscosity is its nu_40)",
    )  # fmt: skip
    scuffing.add_argument(
        "--oil", default="mineral", metavar="BASE",
        help="base oil: mineral, polyalphaolefin, polyglycol, polyglycol-water-soluble, "
        "traction, phosphate-ester (default mineral)",
    )  # fmt: skip
    scuffing.add_argument(
        "--oil-density", type=float, default=890.0, metavar="KG_M3",
        help="the oil's density at 15 deg C, kg/m^3 (default 890.0)",
    )  # fmt: skip
    scuffing.add_argument(
        "--spray", action="store_true", help="spray lubrication (default: dip lubrication)"
    )
    scuffing.add_argument(
        "--welding-factor", type=float, default=1.0, metavar="X_W",
        help="welding factor X_W of the flanks (default 1.0, case-carburized)",
    )  # fmt: skip
    scuffing.add_argument(
        "--min-scuffing", type=float, nargs=2, default=None, metavar=("S_B", "S_INTS"),
        help="minimum scuffing safeties, flash and integral (default 2.0 1.8)",
    )  # fmt: skip


def _oil(args: argparse.Namespace, nu40: float):
    """The Oil of the scuffing options, or None without --fzg-stage."""
    from gears.errors import GearError
    from gears.rating.scuffing import Oil

    if args.fzg_stage is None:
        for option in ("oil_temperature", "oil_viscosity_100"):
            if getattr(args, option) is not None:
                raise GearError(f"--{option.replace('_', '-')} needs --fzg-stage STAGE")
        return None
    for option in ("oil_temperature", "oil_viscosity_100"):
        if getattr(args, option) is None:
            raise GearError(f"--fzg-stage needs --{option.replace('_', '-')}")
    lubrication = "spray" if args.spray else "dip"
    return Oil(args.fzg_stage, args.oil_temperature, nu40, args.oil_viscosity_100,
               args.oil_density, args.oil, lubrication)  # fmt: skip


def run(args: argparse.Namespace) -> int:
    from gears.errors import GearError
    from gears.rating.capacity import MIN_SCUFFING
    from gears.rating.spectrum import read_spectrum

    pair = build_pair(args)
    options = rating_options(args)
    oil = _oil(args, options["oil_viscosity"])
    if oil is not None:
        options |= {"scuffing": oil, "welding_factor": args.welding_factor}
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
    if oil is not None:
        min_scuffing = MIN_SCUFFING if args.min_scuffing is None else tuple(args.min_scuffing)
        report = rating.check(*rating_minimums(args), min_scuffing=min_scuffing)
    else:
        report = rating.check(*rating_minimums(args))
    print(rating)
    print()
    print("checks: " + str(report))
    return OK if report.ok else CHECK_FAILED
