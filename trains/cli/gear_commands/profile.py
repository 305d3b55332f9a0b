"""Tooth outline of one gear, or of a pair in mesh, written as SVG, DXF, PNG or NPZ (the format
follows the file name). The outline is the exact envelope (--method analytic) or a simulated
cutting by a rack or a shaper cutter, to the given tolerance in mm.

With --mate Z2 both gears of the pair are drawn in mesh (the mate is the pinion when the gear is
--internal). --cutter-teeth Z0 makes the gear(s) shaper-cut by that cutter (with --method
shaper or analytic); without it --method shaper uses the default cutter. A ring (--internal)
is drawn with a rim of 3 modules outside its root circle.

The design's checks run too (the gear's, or the pair's with --mate): when one fails the file is
still written, the failing checks are printed on stderr and the exit status is 1; --no-check
skips them. Options that mean nothing here are refused (exit 2): --cutter-teeth with --method
rack, --bore on a ring or with --mate, --mate-shift and --backlash without --mate.

Examples:
    geartrain profile 12 --module 3 --shift 0.6 --method rack --tolerance 0.001 -o gear.svg
    geartrain profile 80 --module 2 --internal --method shaper --cutter-teeth 30 -o ring.svg
    geartrain profile 80 -m 2 --internal --shift -0.5 --mate 20 --tolerance 0.01 -o internal.svg
"""

from __future__ import annotations

import argparse

from trains.cli._common import (
    GEAR_NAMES,
    design_status,
    gear_arguments,
    no_check_argument,
    output_file,
    progress_bar,
)
from trains.cli._types import finite, integer, non_negative, positive

HELP = "tooth outline (analytic, simulated rack or shaper cutting) to .svg/.dxf/.png/.npz"

FORMATS = (".svg", ".dxf", ".png", ".npz")

NAMES = {
    **GEAR_NAMES,
    "tolerance": "--tolerance",
    "backlash": "--backlash",
    "bore": "--bore",
    "method": "--method",
    "z0": "--cutter-teeth",
    "x0": "--cutter-shift",
    "x1": "--shift",
    "x2": "--mate-shift",
    "z1": "TEETH",
    "z2": "--mate",
    "g1": "the gear",
    "g2": "the mate",
}
"""The library's names in error messages -> this command's options (see trains.cli.app)."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    gear_arguments(parser)
    parser.add_argument(
        "--method", choices=("analytic", "rack", "shaper"), default="analytic",
        help="analytic envelope or simulated cutting",
    )  # fmt: skip
    parser.add_argument(
        "--tolerance", type=positive("--tolerance", "mm"), default=0.001,
        help="largest deviation of the drawn outline from the true one, mm",
    )  # fmt: skip
    parser.add_argument(
        "--backlash", type=non_negative("--backlash", "mm"), default=0.0,
        help="normal backlash of the pair, mm (with --mate)",
    )  # fmt: skip
    parser.add_argument(
        "--bore", type=positive("--bore", "mm"), default=None,
        help="bore diameter of an external gear drawn alone, mm (default: none)",
    )  # fmt: skip
    parser.add_argument(
        "--mate", type=integer("--mate"), default=None, metavar="Z2",
        help="teeth of a mating gear: draw the pair in mesh",
    )  # fmt: skip
    parser.add_argument(
        "--mate-shift", type=finite("--mate-shift"), default=0.0, metavar="X2",
        help="profile-shift coefficient of the mate (with --mate)",
    )  # fmt: skip
    parser.add_argument(
        "--cutter-teeth", type=integer("--cutter-teeth"), default=None, metavar="Z0",
        help="shaper cutter teeth: the gear is shaper-cut by it (without it, --method shaper "
        "uses a cutter of about 76 mm pitch diameter)",
    )  # fmt: skip
    parser.add_argument(
        "--cutter-shift", type=finite("--cutter-shift"), default=0.0, metavar="X0",
        help="profile-shift coefficient of the shaper cutter (with --cutter-teeth)",
    )  # fmt: skip
    parser.add_argument(
        "-o", "--output", type=output_file(FORMATS), default="gear.svg",
        help="file to write; the format follows its suffix (" + " ".join(FORMATS) + ")",
    )  # fmt: skip
    no_check_argument(parser)


def run(args: argparse.Namespace) -> int:
    from gears import Gear, GearPair, ShaperCutter
    from gears.solid.export import save
    from trains.errors import TrainError

    if args.mate is None and (args.mate_shift or args.backlash):
        raise TrainError("--mate-shift and --backlash need --mate Z2")
    if args.bore is not None and (args.internal or args.mate is not None):
        raise TrainError("--bore is a hole in an external gear drawn alone; a ring (--internal) "
                         "has none and a pair (--mate) is drawn without bores")  # fmt: skip
    if args.cutter_teeth is not None and args.method == "rack":
        raise TrainError("--cutter-teeth gives a shaper cutter, but --method rack cuts with a "
                         "rack: use --method shaper (or analytic, its exact envelope)")  # fmt: skip
    cutter = None
    if args.cutter_teeth is not None:
        cutter = ShaperCutter(args.cutter_teeth, shift=args.cutter_shift)
    elif args.cutter_shift:
        raise TrainError("--cutter-shift needs --cutter-teeth Z0")
    g = Gear(
        args.teeth, args.module, args.pressure_angle, args.helix, args.shift,
        internal=args.internal, cutter=cutter,
    )  # fmt: skip
    if args.mate is None:
        with progress_bar(f"{args.method} outline") as progress:
            shapes = [
                g.outline(args.tolerance, args.method, args.backlash, bore=args.bore,
                          progress=progress)
            ]  # fmt: skip
        design, report = f"the gear z = {g.teeth}", g.check
    else:
        with progress_bar(f"{args.method} outlines") as progress:
            # the mate is external; an internal gear is the ring of the pair (gear 2)
            helix = args.helix if args.internal else -args.helix
            mate = Gear(
                args.mate, args.module, args.pressure_angle, helix, args.mate_shift,
                cutter=cutter,
            )  # fmt: skip
            pair = GearPair(mate, g) if args.internal else GearPair(g, mate)
            shapes = list(
                pair.outlines(0.0, args.tolerance, args.method, args.backlash, progress=progress)
            )
        design, report = f"the pair {pair.g1.teeth}/{pair.g2.teeth}", pair.check
    path = save(args.output, *shapes)
    n = sum(len(p.exterior.coords) + sum(len(h.coords) for h in p.interiors) for p in shapes)
    print(f"wrote {path} ({n} vertices, tolerance {args.tolerance:g} mm, {args.method})")
    if args.no_check:
        return 0
    return design_status(report(), f"geartrain {args.command}", design)
