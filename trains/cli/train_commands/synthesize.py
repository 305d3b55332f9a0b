"""Search the tooth numbers of a planetary stage for a target ratio and print the best sets,
ranked: smallest ring, smallest ratio error, most hunting-tooth meshes, unshifted first. Every
set meets the ratio, coaxiality, assembly, neighbour and mesh conditions. The exit status is 1
when no set meets them all (the summary names the condition that removed the most sets).

Examples:
    geartrain synthesize --ratio 7 --planets 3
    geartrain synthesize --ratio 16 --planets 3 --scheme stepped --z-max 120
    geartrain synthesize --ratio 7.2 --planets 3-5 --tolerance 0.01 --allow-shift
    geartrain synthesize --ratio 37 --stages 2 --limit 3
    geartrain synthesize --ratio 20 --stages 2 --torque 50 --speed 1500 --face-width 10:30:5
"""

from __future__ import annotations

import argparse

from trains.cli._common import (
    CHECK_FAILED,
    LOAD_NAMES,
    OK,
    dask_arguments,
    dask_session,
    load_arguments,
    load_options,
    output_file,
    progress_bar,
)
from trains.cli._types import exact, integer, non_negative, positive

HELP = "search planetary tooth numbers for a target ratio and print them ranked"

LEGEND = (
    "columns: z1 sun; z2 planet gear on the sun; z2p planet gear on the ring (the outer planet "
    "of a double-planet stage; equal to z2 for a one-gear planet); z3 ring; k planets; ratio "
    "achieved; error |ratio - target| / target; hunt number of meshes whose tooth counts have "
    "no common factor (hunting tooth: every tooth meets every tooth of its mate, which evens "
    "out wear); shift yes when profile shifts make the set coaxial (--allow-shift)"
)
"""What the columns of the synthesis table mean (printed under it)."""

NAMES = {
    r"ratio(?=\s*=)": "--ratio",
    "n_planets": "--planets",
    "z_min": "--z-min",
    "z_max": "--z-max",
    "limit": "--limit",
    r"tolerance(?=\s*=)": "--tolerance",
    r"module(?=\s*=)": "--module",
    "mesh_checks": "--mesh-checks",
    "max_seconds": "--max-seconds",
    "allow_shift": "--allow-shift",
    r"scheme(?=\s*=)": "--scheme",
    r"fixed(?=\s*=)": "--fixed",
    r"input(?=\s*=)": "--input",
    r"output(?=\s*=)": "--output",
    **LOAD_NAMES,
    r"objective(?=\s*=)": "--objective",
}
"""The library's names in error messages -> this command's options (see trains.cli.app)."""


def _ratio(text: str):
    try:
        return exact("--ratio", text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def _planets(text: str) -> int | range:
    """A planet count (``3``) or an inclusive range (``3-5``)."""
    bad = argparse.ArgumentTypeError(
        f"--planets {text!r}; give a count like 3 or a range like 3-5 (integers >= 1)"
    )
    lo, sep, hi = text.strip().partition("-")
    try:
        a, b = int(lo), int(hi) if sep else None
    except ValueError:
        raise bad from None
    if a < 1 or (b is not None and b < a):
        raise bad
    return a if b is None else range(a, b + 1)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--ratio", "-r", type=_ratio, required=True,
        help="target ratio w_input / w_output, e.g. 7, 7.2 or 22/3 (required)",
    )  # fmt: skip
    parser.add_argument(
        "--planets", "-k", type=_planets, default="3",
        help="planet count, or a range like 3-5 (every count in it is searched)",
    )  # fmt: skip
    parser.add_argument(
        "--scheme", default="simple",
        help="simple, stepped, external, internal or double-planet (or a textbook alias A-D)",
    )  # fmt: skip
    parser.add_argument(
        "--tolerance", type=non_negative("--tolerance"), default=0.0,
        help="allowed relative ratio error |i - target| / target (0: exact)",
    )  # fmt: skip
    parser.add_argument(
        "--z-min", type=integer("--z-min"), default=17,
        help="fewest teeth of any gear (17 avoids undercut of zero-shift 20 deg gears)",
    )  # fmt: skip
    parser.add_argument(
        "--z-max", type=integer("--z-max"), default=200,
        help="most teeth of any gear, the ring included (the search grows with it)",
    )  # fmt: skip
    parser.add_argument(
        "--module", "-m", type=positive("--module", "mm"), nargs="+", default=None,
        help="module of the stages in mm, for their dimensions (default: 1, lengths in "
        "modules); with --stages and --torque the modules to choose from (default ISO 54)",
    )  # fmt: skip
    parser.add_argument(
        "--allow-shift", action="store_true",
        help="also accept sets one or two teeth off coaxiality, made coaxial by profile shifts",
    )  # fmt: skip
    parser.add_argument("--fixed", default=None, help="member held fixed (default: the ring)")
    parser.add_argument(
        "--input", default=None, help="input member (default: the sun when the ring is fixed)"
    )
    parser.add_argument(
        "--output", default=None, help="output member (default: the carrier when it turns)"
    )
    parser.add_argument(
        "--mesh-checks", default="geometry", choices=("geometry", "textbook", "full"),
        help="which mesh conditions filter the sets: contact ratio and interference on the real "
        "geometry, the textbook's tooth-count rules only, or every check of each stage",
    )  # fmt: skip
    parser.add_argument("--limit", type=integer("--limit"), default=10, help="rows to print")
    parser.add_argument(
        "--max-seconds", type=positive("--max-seconds", "s"), default=30.0,
        help="refuse, before any work, a search estimated to take longer than this",
    )  # fmt: skip
    parser.add_argument(
        "--stages", type=integer("--stages", 1, 3), default=1,
        help="stages in series (2 or 3: the ranked gearboxes of trains.synthesize_gearbox, "
        "every stage of --scheme, ring fixed, sun in, carrier out; as 'search gearbox')",
    )  # fmt: skip
    parser.add_argument(
        "--objective", default=None,
        choices=("ring", "teeth", "efficiency", "volume", "mass", "mesh_efficiency"),
        help="with --stages: what to minimise (default ring; with --torque volume; "
        "mesh_efficiency: the highest efficiency from the meshes at the load, ISO/TR 14179-2)",
    )  # fmt: skip
    load_arguments(parser, "each stage (with --stages)")
    dask_arguments(parser)
    parser.add_argument(
        "-o", "--table", type=output_file((".parquet", ".csv"), "-o"), default=None,
        metavar="FILE",
        help="with --stages: also write the ranked gearboxes (.parquet, the parquet extra's "
        "pyarrow; .csv); checked before the search starts",
    )  # fmt: skip


def run(args: argparse.Namespace) -> int:
    from trains.errors import TrainError

    if args.stages > 1:
        options = {"--allow-shift": args.allow_shift, "--fixed": args.fixed,
                   "--input": args.input, "--output": args.output}  # fmt: skip
        given = [o for o, v in options.items() if v]
        if given:
            raise TrainError(f"{', '.join(given)} shape one stage; --stages {args.stages} "
                             "searches gearboxes of stages with the ring fixed, the sun in and "
                             "the carrier out, and no shifted sets")  # fmt: skip
        return _gearboxes(args)
    one_stage = {"--objective": args.objective, "--torque": args.torque,
                 "--scheduler": args.scheduler, "--connect-timeout": args.connect_timeout,
                 "-o": args.table, "--face-width": args.face_width}  # fmt: skip
    given = [o for o, v in one_stage.items() if v is not None]
    if given:
        raise TrainError(f"{', '.join(given)} apply to gearboxes: give --stages 2 or 3")
    if args.module is not None and len(args.module) > 1:
        raise TrainError("--module takes one module for one stage (a list with --stages and "
                         "--torque)")  # fmt: skip
    args.module = None if args.module is None else args.module[0]
    from trains.design.synthesis import synthesize

    with progress_bar("synthesize") as progress:
        found = synthesize(
            args.ratio, args.planets, scheme=args.scheme, tolerance=args.tolerance,
            z_min=args.z_min, z_max=args.z_max, module=args.module, allow_shift=args.allow_shift,
            fixed=args.fixed or "ring", input=args.input, output=args.output,
            mesh_checks=args.mesh_checks,
            limit=args.limit, max_seconds=args.max_seconds, progress=progress,
        )  # fmt: skip
    if not found:
        print(found.reason)
        return CHECK_FAILED
    print(found.table())
    print(LEGEND)
    print()
    print(found.reason)
    return OK


def _gearboxes(args: argparse.Namespace) -> int:
    """``--stages k`` (k > 1): k stages in series for the total ratio, ranked by ring size (or
    with ``--torque`` each stage sized for its load, ranked by volume); on a Dask cluster with
    ``--scheduler``; the table also written with ``-o``."""
    from trains.design.gearbox import synthesize_gearbox

    if args.table is not None:  # before the search: Parquet needs pyarrow
        from gears.search.tables import check_table_output

        check_table_output(args.table)
    load = load_options(args)
    module = args.module
    if module is not None and len(module) == 1 and not load:
        module = module[0]
    with dask_session(args) as client, progress_bar("gearbox search", unit="task") as progress:
        found = synthesize_gearbox(
            args.ratio, args.stages, args.planets, args.scheme, tolerance=args.tolerance,
            z_min=args.z_min, z_max=args.z_max, module=module, objective=args.objective,
            top=args.limit, mesh_checks=args.mesh_checks, client=client, progress=progress,
            max_seconds=args.max_seconds, **load,
        )  # fmt: skip
    print(found.table())
    if args.table is not None and len(found):
        from gears.search.tables import write_table

        write_table(found.to_array(), args.table)
    return OK if len(found) else CHECK_FAILED
