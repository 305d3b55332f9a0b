"""A 3D gear mesh (spur, helical, herringbone, ring) written as STL, 3MF, GLB, OBJ or PLY.

The gear axis is +z with the mid-plane at z = 0; a helical gear's section turns by
2 z tan(beta) / d (right hand for a positive --helix). --tolerance (mm) bounds both the outline's
deviation and the helix chords between axial slices.

Examples:
    geartrain mesh 20 --module 1 --helix 20 --face-width 10 --tolerance 0.01 -o gear.stl
    geartrain mesh 20 --module 2 --helix 25 --herringbone --face-width 20 -o herringbone.glb
    geartrain mesh 80 --module 2 --internal --helix -15 --face-width 15 -o ring.3mf
    geartrain mesh 12 --module 3 --shift 0.6 --method rack --bore 10 --face-width 12 -o pinion.stl
"""

from __future__ import annotations

import argparse

from gears import Gear, ShaperCutter

HELP = "3D mesh of one gear (spur, helical, herringbone, ring) to .stl/.3mf/.glb/.obj/.ply"

FORMATS = (".stl", ".3mf", ".glb", ".obj", ".ply")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("teeth", type=int, help="number of teeth")
    parser.add_argument("--module", "-m", type=float, default=1.0, help="normal module, mm")
    parser.add_argument("--shift", "-x", type=float, default=0.0, help="profile-shift coefficient")
    parser.add_argument("--helix", type=float, default=0.0, help="helix angle, degrees (+ right)")
    parser.add_argument("--pressure-angle", type=float, default=20.0, help="degrees")
    parser.add_argument("--face-width", "-b", type=float, default=None,
                        help="mm (default 10 modules)")  # fmt: skip
    parser.add_argument("--herringbone", action="store_true", help="two opposite-hand halves")
    parser.add_argument("--internal", action="store_true", help="an internal (ring) gear")
    parser.add_argument("--rim", type=float, default=None, help="ring width outside the roots, mm")
    parser.add_argument(
        "--method", choices=("analytic", "rack", "shaper"), default="analytic",
        help="analytic envelope or simulated cutting (default analytic)",
    )  # fmt: skip
    parser.add_argument("--cutter-teeth", type=int, default=None, metavar="Z0",
                        help="shaper cutter teeth (the gear is shaper-cut)")  # fmt: skip
    parser.add_argument("--tolerance", type=float, default=0.01, help="mm (default 0.01)")
    parser.add_argument("--backlash", type=float, default=0.0, help="pair normal backlash, mm")
    parser.add_argument("--bore", type=float, default=None, help="bore diameter, mm")
    parser.add_argument(
        "-o", "--output", default="gear.stl", help="file (.stl .3mf .glb .obj .ply)"
    )


def run(args: argparse.Namespace) -> int:
    from gears.export import check_output, save

    out = check_output(args.output, FORMATS)
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
    save(out, mesh)
    kind = "herringbone" if args.herringbone else ("helical" if args.helix else "spur")
    print(
        f"wrote {out} ({kind}, {len(mesh.faces)} triangles, {out.stat().st_size} bytes, "
        f"volume {mesh.volume:.6g} mm^3, watertight {mesh.is_watertight}, "
        f"tolerance {args.tolerance:g} mm)"
    )
    return 0
