"""Check a cylindrical worm pair (DIN 3975, shaft angle 90 deg): the worm's lead angle, moduli,
pitches and diameters, the wheel's throat, root and outside diameters, the centre distance, the
mid-plane contact ratio, and every check with its margin (the wheel's undercut and tip, the
worm's tip land, ZI's base cylinder, the face width's wrap angle, the threaded length); then the
efficiency with the worm driving and with the wheel driving, self-locking, and the lead angle of
the best efficiency at the friction coefficient --friction.

--torque T (N m on the worm, whichever member drives) adds the mesh forces at the worm's
reference cylinder (DIN 3996): tangential F_t, radial F_r, axial F_a and normal F_n on the worm
and on the wheel (the worm's axial force is the wheel's tangential force), their components in
the pair's frame, and the torque on the wheel that balances T at --friction. --driving wheel
gives the forces with the wheel driving the worm backwards (the friction turns: Ozols (14.18));
a self-locking worm cannot be driven so, and the command says so (exit status 2).

--module is the worm's axial module m_x; give the worm's size by --q (the diameter quotient
q = d_m1 / m_x, default 10) or by --worm-diameter d_m1. --pressure-angle is taken in the section
the flank form names: axial for ZA, normal for ZN, ZI and ZK. --shift is the wheel's profile
shift x_2. The exit status is 1 when a check fails. Load capacity (ISO/TS 14521) is not rated.

--scene FILE also writes the worm and its wheel (the envelope of the worm's thread, the worm
acting as the hob) in mesh at zero backlash; --animate FILE writes the pair turning.

Examples:
    geartrain worm 2 40 --module 5 --q 10 --friction 0.05
    geartrain worm 1 50 --module 4 --q 16 --flank ZA --friction 0.08 --speed 1450
    geartrain worm 2 40 --module 5 --q 10 --friction 0.05 --torque 12
    geartrain worm 2 40 --module 5 --q 10 --friction 0.05 --torque 12 --driving wheel
"""

from __future__ import annotations

import argparse

from trains.cli._common import (
    CHECK_FAILED,
    OK,
    drawing_arguments,
    progress_bar,
    refuse_undrawn,
    write_animation,
    write_scene,
)
from trains.cli._types import bounded, finite, integer, positive

HELP = (
    "check a worm pair (STARTS TEETH): geometry, checks, efficiency both ways, self-locking, "
    "mesh forces"
)

NAMES = {
    "starts": "STARTS",
    "wheel_teeth": "TEETH",
    "module": "--module",
    "diameter_quotient": "--q",
    "worm_diameter": "--worm-diameter",
    "pressure_angle": "--pressure-angle",
    "flank": "--flank",
    "profile_shift": "--shift",
    "face_width": "--face-width",
    "worm_length": "--worm-length",
    "hand": "--hand",
    "tool_radius": "--tool-radius",
    r"friction(?! angle)": "--friction",
    "worm_speed": "--speed",
    "torque": "--torque",
    "tolerance": "--tolerance",
}
"""The library's names in error messages -> this command's options (see trains.cli.app)."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "starts", type=integer("STARTS"), metavar="STARTS", help="starts (threads) of the worm, z_1"
    )
    parser.add_argument(
        "teeth", type=integer("TEETH"), metavar="TEETH", help="teeth of the wheel, z_2"
    )
    parser.add_argument(
        "--module",
        "-m",
        type=positive("--module", "mm"),
        default=1.0,
        help="axial module m_x of the worm, mm",
    )
    size = parser.add_mutually_exclusive_group()
    size.add_argument(
        "--q",
        type=positive("--q"),
        default=None,
        help="diameter quotient q = d_m1 / m_x (default 10)",
    )
    size.add_argument(
        "--worm-diameter",
        type=positive("--worm-diameter", "mm"),
        default=None,
        help="the worm's reference diameter d_m1, mm (instead of --q)",
    )
    parser.add_argument(
        "--pressure-angle",
        type=finite("--pressure-angle"),
        default=20.0,
        help="profile angle alpha_0, deg (axial for ZA, normal otherwise)",
    )
    parser.add_argument(
        "--flank", choices=("ZA", "ZN", "ZI", "ZK"), default="ZI", help="flank form (DIN 3975)"
    )
    parser.add_argument(
        "--shift", "-x", type=finite("--shift"), default=0.0, help="the wheel's profile shift x_2"
    )
    parser.add_argument(
        "--face-width",
        "-b",
        type=positive("--face-width", "mm"),
        default=None,
        help="the wheel's face width b_2, mm (default 0.75 d_a1)",
    )
    parser.add_argument(
        "--worm-length",
        type=positive("--worm-length", "mm"),
        default=None,
        help="the threaded length b_1, mm (default: what the wheel needs + p_x)",
    )
    parser.add_argument(
        "--hand", choices=("right", "left"), default="right", help="hand of the thread"
    )
    parser.add_argument(
        "--tool-radius",
        type=positive("--tool-radius", "mm"),
        default=None,
        help="ZK: the grinding cone's radius, mm (default 10 m_x)",
    )
    parser.add_argument(
        "--friction",
        "-f",
        type=bounded("--friction", 0, 1, low_open=False, high_open=True),
        default=0.05,
        help="friction coefficient mu of the flanks (phi' = atan(mu / cos alpha_n))",
    )
    parser.add_argument(
        "--speed",
        type=finite("--speed"),
        default=None,
        help="the worm's speed, rpm: also print the sliding speed",
    )
    parser.add_argument(
        "--torque",
        type=positive("--torque", "N m"),
        default=None,
        help="torque on the worm, N m (whichever member drives): print the mesh forces",
    )
    parser.add_argument(
        "--driving",
        choices=("worm", "wheel"),
        default=None,
        help="the member that drives, for --torque's forces (default worm; wheel: the wheel "
        "driving the worm backwards)",
    )
    _scene_arguments(parser)


#: the default --tolerance of --scene, mm
SCENE_TOLERANCE = 0.05

#: the default --frames of --animate (the worm's turn that moves the wheel by one pitch)
FRAMES = 24


def _scene_arguments(parser: argparse.ArgumentParser) -> None:
    drawing_arguments(
        parser, "the worm and its wheel in mesh", "the pair turning (the wheel by one pitch)",
        FRAMES, SCENE_TOLERANCE,
    )  # fmt: skip


def run(args: argparse.Namespace) -> int:
    from gears import WormPair
    from trains.errors import TrainError

    if args.driving is not None and args.torque is None:
        raise TrainError("--driving applies with --torque (the mesh forces): give --torque too")
    pair = WormPair(
        args.starts,
        args.teeth,
        args.module,
        diameter_quotient=args.q,
        worm_diameter=args.worm_diameter,
        pressure_angle=args.pressure_angle,
        flank=args.flank,
        profile_shift=args.shift,
        face_width=args.face_width,
        hand=args.hand,
        worm_length=args.worm_length,
        tool_radius=args.tool_radius,
    )
    report = pair.check()
    forces = None
    if args.torque is not None:  # before any printing: a self-locking worm is refused
        forces = pair.forces(args.torque, args.friction, args.driving or "worm")
    print(pair.describe())
    print(report)
    print(pair.describe_efficiency(args.friction, args.speed))
    if forces is not None:
        print(forces)
    refuse_undrawn(args)
    with progress_bar("building the wheel", unit="step") as progress:
        write_scene(
            args, lambda tol: pair.scene(tolerance=tol, progress=progress), SCENE_TOLERANCE,
            lambda sc, tol: f"worm and wheel at zero backlash, "
            f"{sum(len(g.faces) for g in sc.geometry.values())} triangles, tolerance {tol:g} mm",
        )  # fmt: skip
    write_animation(args, pair.animate, FRAMES, ": the wheel turning by one pitch")
    return OK if report.ok else CHECK_FAILED
