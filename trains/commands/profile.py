"""Tooth outline of one gear (or a pair in mesh) written as SVG, DXF, PNG or NPZ.

Example: ``geartrain profile 12 --module 3 --shift 0.6 --method rack --tolerance 0.001 -o
gear.svg``. With ``--mate Z2`` (and ``--mate-shift``) both gears of the pair are drawn in mesh.
``--cutter-teeth Z0`` (with ``--cutter-shift``) makes the gear(s) shaper-cut by that cutter (for
``--method shaper`` or ``analytic``); without it ``--method shaper`` uses the default cutter.
"""

from __future__ import annotations

import argparse

from gears.cutter import ShaperCutter
from gears.export import save
from gears.gear import Gear
from gears.pair import GearPair

HELP = "tooth outline (analytic, simulated rack or shaper cutting) to .svg/.dxf/.png/.npz"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("teeth", type=int, help="number of teeth")
    parser.add_argument("--module", "-m", type=float, default=1.0, help="normal module, mm")
    parser.add_argument("--shift", "-x", type=float, default=0.0, help="profile-shift coefficient")
    parser.add_argument("--helix", type=float, default=0.0, help="helix angle, degrees")
    parser.add_argument("--pressure-angle", type=float, default=20.0, help="degrees")
    parser.add_argument("--internal", action="store_true", help="an internal (ring) gear")
    parser.add_argument(
        "--method", choices=("analytic", "rack", "shaper"), default="analytic",
        help="analytic envelope or simulated cutting (default analytic)",
    )  # fmt: skip
    parser.add_argument("--tolerance", type=float, default=0.001, help="mm (default 0.001)")
    parser.add_argument("--backlash", type=float, default=0.0, help="pair normal backlash, mm")
    parser.add_argument("--bore", type=float, default=None, help="bore diameter, mm")
    parser.add_argument("--mate", type=int, default=None, metavar="Z2", help="draw a pair")
    parser.add_argument("--mate-shift", type=float, default=0.0, metavar="X2")
    parser.add_argument(
        "--cutter-teeth", type=int, default=None, metavar="Z0",
        help="shaper cutter teeth (the gear is shaper-cut; default cutter: 76 mm pitch diameter)",
    )  # fmt: skip
    parser.add_argument("--cutter-shift", type=float, default=0.0, metavar="X0")
    parser.add_argument("-o", "--output", default="gear.svg", help="file (.svg .dxf .png .npz)")


def run(args: argparse.Namespace) -> int:
    cutter = None
    if args.cutter_teeth is not None:
        cutter = ShaperCutter(args.cutter_teeth, shift=args.cutter_shift)
    g = Gear(
        args.teeth, args.module, args.pressure_angle, args.helix, args.shift,
        internal=args.internal, cutter=cutter,
    )  # fmt: skip
    if args.mate is None:
        shapes = [g.outline(args.tolerance, args.method, args.backlash, bore=args.bore)]
    else:
        mate = Gear(
            args.mate, args.module, args.pressure_angle, -args.helix, args.mate_shift,
            cutter=cutter,
        )  # fmt: skip
        shapes = list(GearPair(g, mate).outlines(0.0, args.tolerance, args.method, args.backlash))
    path = save(args.output, *shapes)
    n = sum(len(p.exterior.coords) + sum(len(h.coords) for h in p.interiors) for p in shapes)
    print(f"wrote {path} ({n} vertices, tolerance {args.tolerance:g} mm, {args.method})")
    return 0
