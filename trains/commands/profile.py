"""Tooth outline of one gear, or of a pair in mesh, written as SVG, DXF, PNG or NPZ (the format
follows the file name). The outline is the exact envelope (--method analytic) or a simulated
cutting by a rack or a shaper cutter, to the given tolerance in mm.

With --mate Z2 both gears of the pair are drawn in mesh (the mate is the pinion when the gear is
--internal). --cutter-teeth Z0 makes the gear(s) shaper-cut by that cutter (with --method
shaper or analytic); without it --method shaper uses the default cutter.

Examples:
    geartrain profile 12 --module 3 --shift 0.6 --method rack --tolerance 0.001 -o gear.svg
    geartrain profile 80 --module 2 --internal --method shaper --cutter-teeth 30 -o ring.svg
    geartrain profile 80 --module 2 --internal --mate 20 --tolerance 0.01 -o internal.svg
"""

from __future__ import annotations

import argparse

from trains.commands._common import (
    GEAR_NAMES,
    OK,
    finite,
    gear_arguments,
    integer,
    non_negative,
    output_file,
    positive,
    progress_bar,
)

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
"""The library's names in error messages -> this command's options (see trains.cli)."""


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
        "--bore", type=positive("--bore", "mm"), default=None, help="bore diameter, mm"
    )
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


def run(args: argparse.Namespace) -> int:
    from gears import Gear, GearPair, ShaperCutter
    from gears.export import save
    from trains.errors import TrainError

    if args.mate is None and (args.mate_shift or args.backlash):
        raise TrainError("--mate-shift and --backlash need --mate Z2")
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
    path = save(args.output, *shapes)
    n = sum(len(p.exterior.coords) + sum(len(h.coords) for h in p.interiors) for p in shapes)
    print(f"wrote {path} ({n} vertices, tolerance {args.tolerance:g} mm, {args.method})")
    return OK
