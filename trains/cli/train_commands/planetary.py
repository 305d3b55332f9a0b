"""Check a planetary stage: ratios, planet speed, efficiency, coaxiality, assembly, neighbours
and every mesh, each with its margin. Give three tooth counts (sun, planet, ring) or four (sun,
the planet gear on the sun, the planet gear on the ring, ring) for a stepped planet. With
--torque and --speed (on the sun, ring fixed) every mesh is also rated by ISO 6336 method B
(pitting and bending, planets sharing the load with K_gamma) and the stage's loads are printed:
every mesh force, the planet pin with the centrifugal force of the planet's solid, the carrier
torque and the net radial force on the sun and the carrier. The exit status is 1 when a check
fails or a safety is below its minimum.

Examples:
    geartrain planetary 18 45 108 --planets 3 --module 2
    geartrain planetary 26 70 21 117 --planets 3 --scheme stepped
    geartrain planetary 21 43 108 --planets 3 --module 2 --coaxial
    geartrain planetary 21 36 93 --planets 3 --module 2 --face-width 20 --torque 120 --speed 1500
"""

from __future__ import annotations

import argparse

from trains.cli._common import (
    ANIMATION_FORMATS,
    CHECK_FAILED,
    OK,
    SCENE_FORMATS,
    output_file,
    write_scene,
)
from trains.cli._rating import (
    RATING_NAMES,
    SCUFFING_NAMES,
    edition_argument,
    edition_option,
    rating_arguments,
    rating_given,
    rating_minimums,
    rating_options,
    scuffing_arguments,
    scuffing_minimum,
    scuffing_options,
)
from trains.cli._types import integer, non_negative, positive

HELP = "check a planetary stage (sun planet [planet2] ring) and print its report"


SCHEME_HELP = (
    "simple, stepped, external, internal or double-planet (or a textbook alias A, B, C, D); "
    "default: simple for three tooth counts, stepped for four"
)

NAMES = {
    "n_planets": "--planets",
    "module": "--module",
    "clearance": "--clearance",
    "center_distance": "--center-distance",
    "scheme": "--scheme",
    "frames": "--frames",
    "face_width": "--face-width",
    "tolerance": "--tolerance",
    **RATING_NAMES,
    **SCUFFING_NAMES,
}
"""The library's names in error messages -> this command's options (see trains.cli.app)."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "teeth", type=integer("Z"), nargs="+", metavar="Z",
        help="sun, planet, ring; or sun, planet (on the sun), planet (on the ring), ring",
    )  # fmt: skip
    parser.add_argument(
        "--planets", "-k", type=integer("--planets"), default=3, help="number of planets"
    )
    parser.add_argument(
        "--module", "-m", type=positive("--module", "mm"), default=1.0, help="module in mm"
    )
    parser.add_argument("--scheme", default=None, help=SCHEME_HELP)
    parser.add_argument(
        "--clearance", type=non_negative("--clearance", "modules"), default=0.5,
        help="least tip gap between neighbouring planets, in modules",
    )  # fmt: skip
    parser.add_argument(
        "--coaxial", action="store_true",
        help="choose profile shifts for a common working centre distance",
    )  # fmt: skip
    parser.add_argument(
        "--center-distance", type=positive("--center-distance", "mm"), default=None,
        help="with --coaxial: the common working centre distance in mm (default: the larger "
        "reference centre distance)",
    )  # fmt: skip
    parser.add_argument(
        "--scene", type=output_file(SCENE_FORMATS, "--scene"), default=None, metavar="FILE",
        help="also write the stage in 3D, planets phased and instanced (.glb .3mf .stl .obj .ply)",
    )  # fmt: skip
    parser.add_argument(
        "--animate", type=output_file(ANIMATION_FORMATS, "--animate"), default=None,
        metavar="FILE", help="also write the stage turning through one mesh cycle (.gif, .mp4)",
    )  # fmt: skip
    parser.add_argument(
        "--frames", type=integer("--frames"), default=None, metavar="N",
        help="frames of the --animate picture (one mesh cycle; default 48)",
    )  # fmt: skip
    parser.add_argument(
        "--face-width", type=positive("--face-width", "mm"), default=None, metavar="B",
        help="face width of the gears, mm (for the rating; --scene defaults to 10 modules)",
    )  # fmt: skip
    parser.add_argument(
        "--tolerance", type=positive("--tolerance", "mm"), default=None,
        help="mesh tolerance of --scene and --animate, mm (default 0.02)",
    )  # fmt: skip
    rating_arguments(parser, required=False)
    edition_argument(parser)
    scuffing_arguments(parser)


def run(args: argparse.Namespace) -> int:
    from trains.errors import TrainError
    from trains.planetary.stage import Planetary

    z = args.teeth
    if len(z) == 3:
        sun, planet, ring = z
        scheme = args.scheme or "simple"
    elif len(z) == 4:
        sun, planet, ring = z[0], (z[1], z[2]), z[3]
        scheme = args.scheme or "stepped"
    else:
        raise TrainError(f"give 3 tooth counts Z (sun planet ring) or 4; got {len(z)}")
    if args.center_distance is not None and not args.coaxial:
        raise TrainError("--center-distance applies with --coaxial only")
    if args.frames is not None and args.animate is None:
        raise TrainError("--frames counts the frames of --animate: it applies with --animate only")
    if args.face_width is not None and args.scene is None and args.torque is None:
        raise TrainError("--face-width is the width of the --scene gears and of the rated "
                         "meshes: it applies with --scene or --torque only (--animate draws the "
                         "stage in 2D)")  # fmt: skip
    if args.torque is None and args.speed is None and rating_given(args):
        raise TrainError(f"{rating_given(args)[0]} is a rating condition: it applies with "
                         "--torque and --speed only")  # fmt: skip
    if args.torque is None and args.speed is None and args.edition is not None:
        raise TrainError("--edition is a rating condition: it applies with --torque and --speed "
                         "only")  # fmt: skip
    if args.torque is None and args.speed is None and args.fzg_stage is not None:
        raise TrainError("--fzg-stage is a rating condition (scuffing): it applies with --torque "
                         "and --speed only")  # fmt: skip
    if args.tolerance is not None and args.scene is None and args.animate is None:
        raise TrainError("--tolerance is the mesh tolerance of --scene and --animate: it "
                         "applies with one of them only")  # fmt: skip
    tolerance = 0.02 if args.tolerance is None else args.tolerance
    frames = 48 if args.frames is None else args.frames
    kw = {"scheme": scheme, "clearance": args.clearance}
    if args.coaxial:
        stage = Planetary.coaxial(sun, planet, ring, args.planets, args.module,
                                  center_distance=args.center_distance, **kw)  # fmt: skip
    else:
        stage = Planetary(sun, planet, ring, args.planets, args.module, **kw)
    if (args.torque is None) != (args.speed is None):
        given, missing = ("--torque", "--speed") if args.speed is None else ("--speed", "--torque")
        raise TrainError(
            f"{given} needs {missing} too: the rating takes the input's torque and speed"
        )
    ok = stage.check().ok
    ratings = None
    if args.torque is not None:
        options = rating_options(args) | edition_option(args)
        options |= scuffing_options(args, options["oil_viscosity"])
        ratings = stage.rating(args.torque, args.speed, args.face_width, **options)
    print(stage.describe())
    if ratings is not None:
        print()
        ok = _print_ratings(ratings, args, rating_options(args)) and ok
        print()
        print(_loads(stage, args))
    # a failing stage is drawn too: the report says what fails, the exit status is 1
    write_scene(args, lambda tol: stage.scene(face_width=args.face_width, tolerance=tol,
                                              check=False),
                tolerance, lambda _, tol: f"planets phased, tolerance {tol:g} mm")  # fmt: skip
    if args.animate is not None:
        stage.animate(args.animate, frames=frames, tolerance=tolerance, check=False)
        print(f"wrote {args.animate} (one mesh cycle: carrier turning, ring fixed)")
    return OK if ok else CHECK_FAILED


def _loads(stage, args: argparse.Namespace):
    """The stage's loads at the rating's torque and speed (sun in, ring fixed), the planets'
    mass from their solids of --face-width and the rating material's density."""
    print(f"loads: {args.torque:g} N m at {args.speed:g} rpm on the sun (ring fixed)")
    return stage.loads(args.torque, args.speed, face_width=args.face_width,
                       material=rating_options(args)["material"])  # fmt: skip


def _print_ratings(ratings: dict, args: argparse.Namespace, options: dict) -> bool:
    """The rating of every mesh as a table and its checks; True when every safety holds."""
    print(
        f"ISO 6336 method B rating: {args.torque:g} N m at {args.speed:g} rpm on the sun (ring "
        f"fixed), {options['material']}, life {options['life']:g} h, ISO 6336-1/-2/-3:"
        f"{next(iter(ratings.values())).edition}"
    )
    head = ("mesh", "T1 [N m]", "n1 [rpm]", "K_gamma", "S_H1", "S_H2", "S_F1", "S_F2")
    oiled = args.fzg_stage is not None
    head += ("S_B", "S_intS") if oiled else ()
    print(f"{head[0]:14s}" + "".join(f"{h:>10s}" for h in head[1:]))
    findings = []
    for name, r in ratings.items():
        scuffing = r.safety_scuffing if oiled else ()
        row = (r.settings["torque"], r.settings["speed"], r.factors["K_gamma"],
               *r.safety_pitting, *r.safety_bending, *scuffing)  # fmt: skip
        print(f"{name:14s}" + "".join(f"{v:10.4g}" if i < 2 else f"{v:10.3f}"
                                      for i, v in enumerate(row)))  # fmt: skip
        findings.append(r.check(*rating_minimums(args), **scuffing_minimum(args)).prefixed(name))
    report = findings[0]
    for more in findings[1:]:
        report = report + more
    print()
    print("rating checks: " + str(report))
    return report.ok
