"""Design a non-circular gear pair: its centre distance, lobes, teeth fitted to the pitch curve,
the ratio's range over a cycle, and every check with its margin (closure, convexity of each
pitch curve, undercut and tip land of the worst tooth of each gear). KIND is the pitch curve:

  elliptical  two identical ellipses turning about their foci (--semi-major, --eccentricity);
  lobed       an oval of --lobes N1 N2 (gear 1's r = A (1 - e^2)/(1 - e cos(N1 phi)), gear 2 the
              closed curve of N2 lobes that rolls on it; the centre distance is solved);
  eccentric   a circle of radius --semi-major turning --eccentricity mm off its centre, on the
              closed curve of N2 lobes (--lobes 1 N2).

--module fits whole teeth to the pitch curve (the module is adjusted to the curve's length).
--output writes both gears in mesh as SVG, DXF or PNG (teeth cut by a rack rolled along the
pitch curve, to --tolerance); --scene writes a 3D scene (GLB, 3MF, STL, ...). The exit status is
1 when a check fails.

Examples:
    geartrain noncircular elliptical --semi-major 40 --eccentricity 0.2 --module 2
    geartrain noncircular lobed --semi-major 40 --eccentricity 0.15 --lobes 2 3 --module 1.5
"""

from __future__ import annotations

import argparse

from trains.cli._common import CHECK_FAILED, OK, SCENE_FORMATS, output_file
from trains.cli._types import bounded, finite, integer, positive

HELP = "design a non-circular pair (elliptical, lobed, eccentric): centrodes, teeth, checks"

NAMES = {
    "semi_major": "--semi-major",
    "radius": "--semi-major",
    "eccentricity": "--eccentricity",
    "offset": "--eccentricity",
    "module": "--module",
    "lobes1": "--lobes",
    "lobes2": "--lobes",
    "tolerance": "--tolerance",
    "face_width": "--face-width",
    "angle": "--angle",
}
"""The library's names in error messages -> this command's options (see trains.cli.app)."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("kind", choices=("elliptical", "lobed", "eccentric"), metavar="KIND",
                        help="elliptical, lobed or eccentric")  # fmt: skip
    parser.add_argument("--semi-major", "-a", type=positive("--semi-major", "mm"), default=50.0,
                        help="the ellipse's semi-major axis A (eccentric: the circle's radius), "
                        "mm")  # fmt: skip
    parser.add_argument("--eccentricity", "-e", type=finite("--eccentricity"), default=0.2,
                        help="eccentricity e (eccentric: the centre's offset, mm)")  # fmt: skip
    parser.add_argument(
        "--lobes",
        nargs=2,
        type=integer("--lobes"),
        default=None,
        metavar=("N1", "N2"),
        help="lobes of gear 1 and gear 2 (lobed, eccentric)",
    )
    parser.add_argument(
        "--module",
        "-m",
        type=positive("--module", "mm"),
        default=None,
        help="module of the teeth, mm (fitted to the pitch curve's length)",
    )
    parser.add_argument(
        "--output",
        "-o",
        type=output_file((".svg", ".dxf", ".png")),
        default=None,
        help="write both gears in mesh (.svg, .dxf, .png)",
    )
    parser.add_argument(
        "--scene",
        type=output_file(SCENE_FORMATS, "--scene"),
        default=None,
        help="write both gears as a 3D scene (.glb, .3mf, .stl, .obj, .ply)",
    )
    parser.add_argument(
        "--angle",
        type=finite("--angle"),
        default=0.0,
        help="gear 1's angle in the drawing, degrees",
    )
    parser.add_argument(
        "--face-width",
        type=positive("--face-width", "mm"),
        default=10.0,
        help="face width of the scene's gears, mm",
    )
    parser.add_argument(
        "--tolerance",
        type=bounded("--tolerance", 0, 10),
        default=0.01,
        help="largest deviation of the drawn teeth, mm",
    )


def run(args: argparse.Namespace) -> int:
    import numpy as np

    from gears import NonCircularPair
    from gears.errors import GearError

    if args.kind == "elliptical":
        if args.lobes is not None:
            raise GearError("--lobes applies to lobed and eccentric pairs: an elliptical pair "
                            "has one lobe each")  # fmt: skip
        pair = NonCircularPair.elliptical(args.semi_major, args.eccentricity, module=args.module)
    elif args.kind == "lobed":
        lobes = tuple(args.lobes or (2, 2))
        pair = NonCircularPair.lobed(args.semi_major, args.eccentricity, lobes, module=args.module)
    else:
        n1, n2 = args.lobes or (1, 1)
        if n1 != 1:
            raise GearError(f"--lobes {n1} {n2}: an eccentric circle has one lobe; valid is 1 N2")
        pair = NonCircularPair.eccentric(args.semi_major, args.eccentricity, n2,
                                         module=args.module)  # fmt: skip
    if (args.output or args.scene) and args.module is None:
        raise GearError("--output and --scene draw teeth: give --module")
    ratio = pair.ratio(np.linspace(0.0, 360.0, 3601))
    print(f"non-circular pair: {pair.name}")
    print(f"  centre distance    {pair.center_distance:.6g} mm")
    print(f"  lobes              {pair.lobes[0]} / {pair.lobes[1]}")
    print(f"  ratio w1/w2        {ratio.min():.6g} ... {ratio.max():.6g}")
    print(f"  pitch curves       {pair.pitch_lengths[0]:.6g} / {pair.pitch_lengths[1]:.6g} mm")
    if pair.teeth is not None:
        print(f"  teeth              {pair.teeth[0]} / {pair.teeth[1]}")
        print(f"  module (fitted)    {pair.module:.6g} mm")
    report = pair.check()
    print(report)
    if args.output is not None:
        from gears.solid.export import save

        save(args.output, *pair.outlines(args.angle, args.tolerance))
        print(f"\nwrote {args.output}")
    if args.scene is not None:
        from gears.solid.export import save

        save(args.scene, pair.scene(args.angle, args.face_width, args.tolerance))
        print(f"\nwrote {args.scene}")
    return OK if report.ok else CHECK_FAILED
