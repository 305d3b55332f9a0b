"""Check a bevel (car) differential built on real straight bevel gears: the side gears and pinions
as a bevel pair at 90 deg (every check of 'geartrain bevel'), the pinions' assembly (2 z_side /
pinions an integer) and their neighbour gap, and the speeds when cornering (Ozols (7.9):
left + right = 2 case); optionally write it in 3D and an animation of it turning through a
corner (the wheels at --left and --right).

Speeds are counted about the axle for the wheels and the case, and about its own axis for each
pinion (its spin in the case). With --torque (N m on the case; --left and --right are then in
rpm) every mesh is rated by ISO 10300 method B1 (the case torque split between the side gears
and among the pinions). The exit status is 1 when a check fails or a safety is below
--min-pitting / --min-bending.

Examples:
    geartrain differential --side 16 --pinion 10 --module 3 --gleason
    geartrain differential --side 16 --pinion 10 --module 3 --gleason --scene diff.glb
    geartrain differential --side 15 --pinion 10 --pinions 3 --gleason --pressure-angle 22.5
    geartrain differential --side 16 --pinion 10 --module 3 --gleason --torque 60 --life 1000
"""

from __future__ import annotations

import argparse
import functools

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
from trains.cli._types import finite, integer, positive

HELP = "check a bevel differential (side gears, pinions) and its cornering speeds; 3D and GIF"

NAMES = {
    "side": "--side",
    "pinion": "--pinion",
    "n_pinions": "--pinions",
    **BEVEL_NAMES,
    **DRAWING_NAMES,
    "left": "--left",
    "right": "--right",
    **RATING_NAMES,
    **BEVEL_RATING_NAMES,
}
"""The library's names in error messages -> this command's options (see trains.cli.app)."""

#: the defaults of --frames and of --tolerance for --scene (mm)
FRAMES, SCENE_TOLERANCE = 36, 0.02


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--side", type=integer("--side"), default=16, help="teeth of each side gear"
    )
    parser.add_argument(
        "--pinion", type=integer("--pinion"), default=10, help="teeth of each pinion"
    )
    parser.add_argument(
        "--pinions", "-k", type=integer("--pinions"), default=2,
        help="equally spaced pinions on the case",
    )  # fmt: skip
    bevel_arguments(
        parser, module=1.0, shaft_angle=False,
        face_width_help="face width of the bevel gears, mm (default: R_e / 3.5)",
        shift_help="the pinions' profile shift x_hm (the side gears get its negative)",
    )  # fmt: skip
    parser.add_argument(
        "--gleason", action="store_true",
        help="the Gleason proportions of KHK Table 4.11 (replaces --shift)",
    )  # fmt: skip
    parser.add_argument(
        "--left", type=finite("--left"), default=90.0, help="speed of the left wheel (any unit)"
    )
    parser.add_argument(
        "--right", type=finite("--right"), default=110.0,
        help="speed of the right wheel (the same unit)",
    )  # fmt: skip
    drawing_arguments(parser, "the differential", "it turning through a corner at --left/--right",
                      FRAMES, SCENE_TOLERANCE)  # fmt: skip
    parser.add_argument(
        "--torque", type=positive("--torque", "N m"), default=None, metavar="T",
        help="torque on the case, N m: rate every mesh by ISO 10300 (--left, --right in rpm)",
    )  # fmt: skip
    rating_arguments(parser, required=False, torque=False, speed=False)
    bevel_rating_arguments(parser)


def run(args: argparse.Namespace) -> int:
    from trains.differential import Differential
    from trains.errors import TrainError

    refuse_undrawn(args)
    if args.torque is None and bevel_rating_given(args):
        raise TrainError(f"{bevel_rating_given(args)[0]} applies with --torque: a rating")
    if args.gleason and args.shift:
        raise TrainError("--gleason sets the shift: give --shift without --gleason")
    kw = {} if args.gleason else {"profile_shift": args.shift}
    d = Differential(args.side, args.pinion, args.pinions, args.module, args.face_width,
                     args.pressure_angle, args.gleason, **kw)  # fmt: skip
    m = d.solve(left=args.left, right=args.right)
    report = d.check()
    print(f"{d.train.name}, module {d.module:g} mm, face width {d.face_width:g} mm")
    print(d.pair.describe())
    spin = float(m.relative("pinion", "case"))
    print(f"speeds: left {args.left:g}, right {args.right:g}, case {float(m['case']):g} "
          f"(Ozols (7.9): left + right = 2 case), pinions spin {spin:+g} in the case")  # fmt: skip
    print(report)
    ok = report.ok
    if args.torque is not None:
        ratings = d.rating(args.torque, args.left, args.right, **bevel_rating_options(args))
        checks = [r.check(*rating_minimums(args)).prefixed(name) for name, r in ratings.items()]
        for name, r in ratings.items():
            (s_h1, s_h2), (s_f1, s_f2) = r.safety_pitting, r.safety_bending
            print(f"{name}: S_H {s_h1:.3f} / {s_h2:.3f}, S_F {s_f1:.3f} / {s_f2:.3f} "
                  "(pinion / side gear)")  # fmt: skip
        first = next(iter(ratings))
        print()
        print(f"every mesh carries the same load; {first}:")
        print(ratings[first])
        print()
        total = sum(checks[1:], checks[0])
        print("checks: " + str(total))
        ok = ok and total.ok
    # a failing design is drawn too: the report above says what fails, the exit status is 1
    write_scene(args, lambda tol: d.scene(tolerance=tol, check=False), SCENE_TOLERANCE,
                lambda _, tol: f"side gears and {d.n_pinions} pinions phased, instanced; "
                f"tolerance {tol:g} mm")  # fmt: skip
    turning = functools.partial(d.animate, left=args.left, right=args.right, check=False)
    write_animation(args, turning, FRAMES, " turning through a corner")
    return OK if ok else CHECK_FAILED
