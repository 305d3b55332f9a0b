"""Check a bevel (car) differential built on real straight bevel gears: the side gears and pinions
as a bevel pair at 90 deg (every check of 'geartrain bevel'), the pinions' assembly (2 z_side /
pinions an integer) and their neighbour gap, and the speeds when cornering (Ozols (7.9):
left + right = 2 case); optionally write it in 3D and an animation of it turning through a
corner (the wheels at --left and --right).

Speeds are counted about the axle for the wheels and the case, and about its own axis for each
pinion (its spin in the case). The exit status is 1 when a check fails.

Examples:
    geartrain differential --side 16 --pinion 10 --module 3 --gleason
    geartrain differential --side 16 --pinion 10 --module 3 --gleason --scene diff.glb
    geartrain differential --side 15 --pinion 10 --pinions 3 --gleason --pressure-angle 22.5
"""

from __future__ import annotations

import argparse

from trains.commands._common import (
    CHECK_FAILED,
    OK,
    SCENE_FORMATS,
    finite,
    integer,
    output_file,
    positive,
)

HELP = "check a bevel differential (side gears, pinions) and its cornering speeds; 3D and GIF"

NAMES = {
    "side": "--side",
    "pinion": "--pinion",
    "n_pinions": "--pinions",
    "module": "--module",
    "face_width": "--face-width",
    "pressure_angle": "--pressure-angle",
    "profile_shift": "--shift",
    "tolerance": "--tolerance",
    "frames": "--frames",
    "left": "--left",
    "right": "--right",
}
"""The library's names in error messages -> this command's options (see trains.cli)."""


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
    parser.add_argument(
        "--module", "-m", type=positive("--module", "mm"), default=3.0,
        help="outer transverse module m_et, mm",
    )  # fmt: skip
    parser.add_argument(
        "--face-width", "-b", type=positive("--face-width", "mm"), default=None,
        help="face width of the bevel gears, mm (default: R_e / 3.5)",
    )  # fmt: skip
    parser.add_argument(
        "--pressure-angle", type=finite("--pressure-angle"), default=20.0,
        help="pressure angle of the generating crown gear, deg",
    )  # fmt: skip
    parser.add_argument(
        "--shift", "-x", type=finite("--shift"), default=0.0,
        help="the pinions' profile shift x_hm (the side gears get its negative)",
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
    parser.add_argument(
        "--scene", type=output_file(SCENE_FORMATS, "--scene"), default=None, metavar="FILE",
        help="also write the differential in 3D (.glb .3mf .stl .obj .ply)",
    )  # fmt: skip
    parser.add_argument(
        "--animate", type=output_file((".gif", ".mp4"), "--animate"), default=None,
        metavar="FILE", help="also write it turning through a corner at --left/--right (.gif .mp4)",
    )  # fmt: skip
    parser.add_argument(
        "--frames", type=integer("--frames"), default=None, metavar="N",
        help="frames of --animate (default: 36)",
    )  # fmt: skip
    parser.add_argument(
        "--tolerance", type=positive("--tolerance", "mm"), default=None,
        help="largest deviation of the 3D teeth from the exact ones, mm (default: 0.02 for "
        "--scene, 0.05 for --animate)",
    )  # fmt: skip


def run(args: argparse.Namespace) -> int:
    from trains.differential import Differential
    from trains.errors import TrainError

    if args.tolerance is not None and args.scene is None and args.animate is None:
        raise TrainError("--tolerance applies with --scene or --animate only")
    if args.frames is not None and args.animate is None:
        raise TrainError("--frames counts the frames of --animate: it applies with --animate only")
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
    if args.scene is not None:
        from gears.export import save

        tol = 0.02 if args.tolerance is None else args.tolerance
        save(args.scene, d.scene(tolerance=tol))
        print(f"\nwrote {args.scene} (side gears and {d.n_pinions} pinions phased, instanced; "
              f"tolerance {tol:g} mm)")  # fmt: skip
    if args.animate is not None:
        tol = 0.05 if args.tolerance is None else args.tolerance
        frames = 36 if args.frames is None else args.frames
        from trains.commands._common import progress_bar

        with progress_bar("frames", frames) as bar:
            d.animate(args.animate, frames=frames, left=args.left, right=args.right,
                      tolerance=tol, progress=bar)  # fmt: skip
        print(f"wrote {args.animate} ({frames} frames turning through a corner)")
    return OK if report.ok else CHECK_FAILED
