"""Check a straight bevel gear pair (ISO 23509 / DIN 3971): pitch cones, cone distances, tip and
root angles, outside diameters, the virtual (Tredgold) pair's contact ratio, undercut and tip
land, and the face width against R_e / 3, each with its margin; optionally write the pair in 3D
(common apex, the shaft angle between the axes, teeth phased) and an animation of it turning.

The module is the outer transverse module m_et; the face width defaults to R_e / 3.5. --shift is
the pinion's profile shift at the mean cone (the wheel gets its negative), --gleason the Gleason
proportions of KHK Table 4.11. With --torque (N m on the pinion) the mesh forces at the mean
cone follow (ISO 10300-1); with --speed too (rpm of the pinion) the pair is rated by ISO 10300
method B1 (pitting and bending safety of both gears, every factor and where it comes from;
--mounting and --pattern give the mounting factor). The exit status is 1 when a check fails or
a safety is below --min-pitting / --min-bending.

Examples:
    geartrain bevel 20 40 --module 3 --face-width 22
    geartrain bevel 20 40 --module 3 --face-width 22 --gleason --scene pair.glb
    geartrain bevel 17 43 --module 2.5 --face-width 12 --shaft-angle 70 --shift 0.2
    geartrain bevel 20 40 --module 3 --face-width 22 --torque 50
    geartrain bevel 20 40 -m 3 -b 22 --torque 50 --speed 1500 --mounting one-straddle
"""

from __future__ import annotations

import argparse

from trains.cli._common import (
    BEVEL_NAMES,
    CHECK_FAILED,
    DRAWING_NAMES,
    OK,
    bevel_arguments,
    drawing_arguments,
    refuse_undrawn,
    write_animation,
    write_scene,
)
from trains.cli._rating import (
    BEVEL_RATING_NAMES,
    RATING_NAMES,
    bevel_rating_arguments,
    bevel_rating_given,
    bevel_rating_options,
    rating_arguments,
    rating_minimums,
)
from trains.cli._types import finite, integer, non_negative, positive

HELP = "check a straight bevel pair (Z1 Z2): geometry, report, ISO 10300 rating; 3D scene"

NAMES = {
    "z1": "Z1",
    "z2": "Z2",
    **BEVEL_NAMES,
    "shaft_angle": "--shaft-angle",
    "thickness_modification": "--thickness-mod",
    "tool_radius": "--tool-radius",
    "backlash": "--backlash",
    "bore": "--bore",
    **DRAWING_NAMES,
    **RATING_NAMES,
    **BEVEL_RATING_NAMES,
}
"""The library's names in error messages -> this command's options (see trains.cli.app)."""

#: the defaults of --frames and of --tolerance for --scene (mm)
FRAMES, SCENE_TOLERANCE = 24, 0.01


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("z1", type=integer("Z1"), metavar="Z1", help="teeth of the pinion")
    parser.add_argument("z2", type=integer("Z2"), metavar="Z2", help="teeth of the wheel")
    bevel_arguments(
        parser, module=1.0, shaft_angle=True,
        face_width_help="face width along the pitch cone, mm (default: R_e / 3.5)",
        shift_help="the pinion's profile shift x_hm (the wheel gets its negative)",
    )  # fmt: skip
    parser.add_argument(
        "--thickness-mod", type=finite("--thickness-mod"), default=0.0,
        help="the pinion's thickness modification x_sm (the wheel gets its negative)",
    )  # fmt: skip
    parser.add_argument(
        "--clearance", choices=("constant", "tapered"), default="constant",
        help="constant (face cone parallel to the mate's root cone) or tapered (all cones meet "
        "the apex)",
    )  # fmt: skip
    parser.add_argument(
        "--gleason", action="store_true",
        help="the Gleason proportions of KHK Table 4.11 (replaces --shift and --clearance)",
    )  # fmt: skip
    parser.add_argument(
        "--profile", choices=("octoid", "spherical_involute"), default="octoid",
        help="tooth form of the 3D teeth",
    )  # fmt: skip
    parser.add_argument(
        "--tool-radius", type=non_negative("--tool-radius", "mean modules"), default=None,
        help="tip radius of the generating crown gear (default: the full round of the clearance)",
    )  # fmt: skip
    drawing_arguments(parser, "the pair", "the pair turning by one pitch of the pinion", FRAMES,
                      SCENE_TOLERANCE)  # fmt: skip
    parser.add_argument(
        "--backlash", type=non_negative("--backlash", "mm"), default=0.0,
        help="normal backlash of the --scene pair at the mean cone, mm (each gear takes half)",
    )  # fmt: skip
    parser.add_argument(
        "--bore", type=positive("--bore", "mm"), default=None,
        help="bore diameter of both --scene gears, mm (default: none)",
    )  # fmt: skip
    parser.add_argument(
        "--torque", type=finite("--torque"), default=None,
        help="torque on the pinion, N m: print the mesh forces at the mean cone (with --speed: "
        "rate the pair by ISO 10300)",
    )  # fmt: skip
    rating_arguments(parser, required=False, torque=False)
    bevel_rating_arguments(parser)


def run(args: argparse.Namespace) -> int:
    from gears import BevelPair
    from trains.errors import TrainError

    refuse_undrawn(args, drawing=("--tolerance", "--bore"), scene=("--backlash",))
    if args.speed is None and bevel_rating_given(args):
        raise TrainError(
            f"{bevel_rating_given(args)[0]} applies with --speed (and --torque): a rating"
        )
    if args.speed is not None and args.torque is None:
        raise TrainError("--speed rates the pair: give --torque (N m on the pinion) too")
    if args.gleason and (args.shift or args.clearance != "constant"):
        raise TrainError("--gleason sets the shift and the clearance: give neither with it")
    face = args.face_width
    if face is None:
        face = BevelPair(args.z1, args.z2, args.module, 1e-6, args.shaft_angle).cone_distance
        face = int(10 * face / 3.5) / 10 or face / 3.5
    kw = {"profile": args.profile}
    if args.tool_radius is not None:
        kw["tool_radius"] = args.tool_radius
    if args.gleason:
        pair = BevelPair.gleason(args.z1, args.z2, args.module, face, args.shaft_angle,
                                 args.pressure_angle, args.thickness_mod, **kw)  # fmt: skip
    else:
        pair = BevelPair(args.z1, args.z2, args.module, face, args.shaft_angle,
                         args.pressure_angle, args.shift, args.thickness_mod,
                         clearance=args.clearance, **kw)  # fmt: skip
    report = pair.check()
    print(pair.describe())
    print(report)
    if args.torque is not None:
        print()
        print(pair.forces(args.torque))
    ok = report.ok
    if args.speed is not None:
        rating = pair.rating(args.torque, args.speed, **bevel_rating_options(args))
        checks = rating.check(*rating_minimums(args))
        print()
        print(rating)
        print()
        print("checks: " + str(checks))
        ok = ok and checks.ok
    write_scene(
        args, lambda tol: pair.scene(tolerance=tol, backlash=args.backlash, bore=args.bore),
        SCENE_TOLERANCE,
        lambda sc, tol: f"common apex, shaft angle {pair.shaft_angle:g} deg, "
        f"{sum(len(g.faces) for g in sc.geometry.values())} triangles, tolerance {tol:g} mm",
    )  # fmt: skip
    write_animation(args, pair.animate, FRAMES, ": the pinion turning by one pitch")
    return OK if ok else CHECK_FAILED
