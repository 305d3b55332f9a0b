"""A 3D gear mesh (spur, helical, herringbone, ring) written as STL, 3MF, GLB, OBJ or PLY.

The gear axis is +z with the mid-plane at z = 0; a helical gear's section turns by
2 z tan(beta) / d (right hand for a positive --helix). --tolerance (mm) bounds both the outline's
deviation and the helix chords between axial slices. The face width defaults to 10 modules, a
ring's rim (--internal) to 3 modules outside its root circle.

The gear's checks run too (undercut, pointed tip, ...): when one fails the file is still written,
the failing checks are printed on stderr and the exit status is 1; --no-check skips them.
Options that mean nothing for the gear are refused (exit 2): --rim without --internal, --bore
with it, --herringbone on a spur gear, --cutter-teeth with --method rack.

Examples:
    geartrain mesh 20 --module 1 --helix 20 --face-width 10 --tolerance 0.01 -o gear.stl
    geartrain mesh 20 --module 2 --helix 25 --herringbone --face-width 20 -o herringbone.glb
    geartrain mesh 80 --module 2 --internal --helix -15 --face-width 15 -o ring.3mf
    geartrain mesh 12 --module 3 --shift 0.6 --method rack --bore 10 --face-width 12 -o pinion.stl
"""

from __future__ import annotations

import argparse

from trains.cli._common import (
    GEAR_NAMES,
    SCENE_FORMATS,
    design_status,
    gear_arguments,
    no_check_argument,
    output_file,
)
from trains.cli._types import integer, non_negative, positive

HELP = "3D mesh of one gear (spur, helical, herringbone, ring) to .stl/.3mf/.glb/.obj/.ply"

FORMATS = SCENE_FORMATS  # one mesh or a scene: the same exporters

NAMES = {
    **GEAR_NAMES,
    "face_width": "--face-width",
    "tolerance": "--tolerance",
    "backlash": "--backlash",
    "bore": "--bore",
    "rim": "--rim",
    "method": "--method",
    "z0": "--cutter-teeth",
}
"""The library's names in error messages -> this command's options (see trains.cli.app)."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    gear_arguments(parser)
    parser.add_argument(
        "--face-width", "-b", type=positive("--face-width", "mm"), default=None,
        help="face width, mm (default: 10 modules)",
    )  # fmt: skip
    parser.add_argument(
        "--herringbone", action="store_true", help="two opposite-hand halves meeting mid-face"
    )
    parser.add_argument(
        "--rim", type=positive("--rim", "mm"), default=None,
        help="ring width outside the tooth roots, mm (with --internal; default 3 modules)",
    )  # fmt: skip
    parser.add_argument(
        "--method", choices=("analytic", "rack", "shaper"), default="analytic",
        help="analytic envelope or simulated cutting",
    )  # fmt: skip
    parser.add_argument(
        "--cutter-teeth", type=integer("--cutter-teeth"), default=None, metavar="Z0",
        help="teeth of the shaper cutter (the gear is shaper-cut)",
    )  # fmt: skip
    parser.add_argument(
        "--tolerance", type=positive("--tolerance", "mm"), default=0.01,
        help="largest deviation of the outline and of the helix chords from the true ones, mm",
    )  # fmt: skip
    parser.add_argument(
        "--backlash", type=non_negative("--backlash", "mm"), default=0.0,
        help="normal backlash of the pair, mm (this gear takes half)",
    )  # fmt: skip
    parser.add_argument(
        "--bore", type=positive("--bore", "mm"), default=None,
        help="bore diameter of an external gear, mm (default: none, a solid disc)",
    )  # fmt: skip
    parser.add_argument(
        "-o", "--output", type=output_file(FORMATS, "--output"), default="gear.stl",
        help="file to write: .stl (binary), .3mf, .glb, .obj (its materials in a .mtl of the "
        "same name) or .ply",
    )  # fmt: skip
    no_check_argument(parser)


def refuse_unused(args: argparse.Namespace) -> None:
    """A TrainError (exit 2) for an option that means nothing for this gear."""
    from trains.errors import TrainError

    if args.rim is not None and not args.internal:
        raise TrainError("--rim is the width of a ring outside its tooth roots: it applies "
                         "with --internal only")  # fmt: skip
    if args.bore is not None and args.internal:
        raise TrainError("--bore is a hole in an external gear; a ring (--internal) has none "
                         "(its outside is set by --rim)")  # fmt: skip
    if getattr(args, "herringbone", False) and not args.helix:
        raise TrainError("--herringbone joins two helical halves of opposite hand; a spur gear "
                         "(--helix 0) has no helix to mirror: give --helix")  # fmt: skip
    if args.cutter_teeth is not None and args.method == "rack":
        raise TrainError("--cutter-teeth gives a shaper cutter, but --method rack cuts with a "
                         "rack: use --method shaper (or analytic, its exact envelope)")  # fmt: skip


def run(args: argparse.Namespace) -> int:
    from gears import Gear, ShaperCutter
    from gears.solid.export import save

    refuse_unused(args)
    cutter = None if args.cutter_teeth is None else ShaperCutter(args.cutter_teeth)
    g = Gear(
        args.teeth, args.module, args.pressure_angle, args.helix, args.shift,
        internal=args.internal, cutter=cutter,
    )  # fmt: skip
    b = 10.0 * g.module if args.face_width is None else args.face_width
    mesh = g.mesh(
        b, args.tolerance, args.method, args.backlash, bore=args.bore,
        herringbone=args.herringbone, rim=args.rim,
    )  # fmt: skip
    out = save(args.output, mesh)
    kind = "herringbone" if args.herringbone else ("helical" if args.helix else "spur")
    print(
        f"wrote {out} ({kind}, {len(mesh.faces)} triangles, {out.stat().st_size} bytes, "
        f"volume {mesh.volume:.6g} mm^3, watertight {mesh.is_watertight}, "
        f"tolerance {args.tolerance:g} mm)"
    )
    if args.no_check:
        return 0
    return design_status(g.check(), f"geartrain {args.command}", f"the gear z = {g.teeth}")
