"""Search designs and print them ranked: gear pairs (every candidate checked as GearPair.check
does) or multi-stage planetary gearboxes. The work runs in chunks on every local core, or on a
Dask cluster with --scheduler. The exit status is 1 when nothing meets the request.

Examples:
    geartrain search pairs --ratio 3.2 --center-distance 100 --module 2 2.5 3 --teeth 12 120
    geartrain search pairs --ratio 2 --module 2 --teeth 14 40 --objective sliding,-contact_ratio
    geartrain search pairs --ratio 3 --module 2 2.5 --teeth 14 80 --torque 60 --speed 1500 \
        --face-width 10:40:5 --min-pitting 1.1 --min-bending 1.5 --objective volume
    geartrain search pairs --ratio 3.2 --module 1 2 3 4 --teeth 12 200 --estimate
    geartrain search gearbox --ratio 37 --stages 2 --schemes simple stepped --z-max 120
    geartrain search gearbox --ratio 20 --stages 2 --torque 50 --speed 1500 --face-width 10:30:5
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
from trains.cli._types import bounded, exact, finite, integer, non_negative, positive

HELP = "search gear pairs or multi-stage planetary gearboxes and print them ranked"

NAMES = {
    r"ratio(?=\s*=)": "--ratio",
    r"center_distance(?=\s*=)": "--center-distance",
    r"module(?=\s*=)": "--module",
    r"helix(?=\s*=)": "--helix",
    r"teeth(?=\s*=)": "--teeth",
    r"shifts(?=\s*=)": "--shifts",
    "max_seconds": "--max-seconds",
    r"objective": "--objective",
    r"top(?=\s*=)": "--top",
    "z_max": "--z-max",
    "z_min": "--z-min",
    r"stages(?=\s*=)": "--stages",
    r"tolerance(?=\s*=)": "--tolerance",
    **LOAD_NAMES,
    r"dataset(?=\s*=)": "--output",
    r"top=None": "--all",
}
"""The library's names in error messages -> this command's options."""

_SUFFIXES = (".parquet", ".csv")


def _ratio(text: str):
    try:
        return exact("--ratio", text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def _table_or_folder(text: str):
    """-o: a .parquet/.csv file (checked now), or with --all a folder (ending in '/', or an
    existing folder) for a Parquet dataset the chunks write (checked by the search)."""
    import os

    if text.endswith(("/", os.sep)) or os.path.isdir(text):
        return text
    return output_file(_SUFFIXES)(text)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    sub = parser.add_subparsers(dest="what", required=True, metavar="WHAT")
    p = sub.add_parser("pairs", help="gear pairs", description="Search gear pairs.")
    p.add_argument("--ratio", "-r", type=positive("--ratio"), default=None,
                   help="target gear ratio z2/z1")  # fmt: skip
    p.add_argument("--ratio-tolerance", type=non_negative("--ratio-tolerance"), default=0.01,
                   help="allowed relative ratio error (default 0.01)")  # fmt: skip
    p.add_argument("--center-distance", "-a", type=positive("--center-distance", "mm"),
                   default=None, help="centre distance in mm: the shift sum is solved exactly "
                   "and split by --split")  # fmt: skip
    p.add_argument("--split", choices=("proportional", "equal_sliding", "keep"),
                   default=None, help="with --center-distance: how the shift sum is split "
                   "(default proportional)")  # fmt: skip
    p.add_argument("--module", "-m", type=positive("--module", "mm"), nargs="+", default=[1.0],
                   help="normal modules to try, mm")  # fmt: skip
    p.add_argument(
        "--helix",
        type=bounded("--helix", -60, 60, low_open=True, high_open=True),
        nargs="+",
        default=[0.0],
        help="helix angles of gear 1 to try, degrees",
    )
    p.add_argument(
        "--teeth",
        type=integer("--teeth"),
        nargs=2,
        default=[12, 60],
        metavar=("Z_MIN", "Z_MAX"),
        help="tooth-count range of both gears",
    )
    p.add_argument(
        "--shifts",
        type=finite("--shifts"),
        nargs=3,
        default=[-0.5, 1.0, 0.1],
        metavar=("LOW", "HIGH", "STEP"),
        help="profile-shift grid",
    )
    p.add_argument("--min-contact-ratio", type=non_negative("--min-contact-ratio"), default=1.1)
    p.add_argument("--min-tip-land", type=non_negative("--min-tip-land"), default=0.2,
                   help="smallest normal tip land, modules")  # fmt: skip
    p.add_argument("--allow-undercut", action="store_true", help="accept undercut gears")
    p.add_argument("--max-sliding", type=positive("--max-sliding"), default=None,
                   help="largest specific sliding allowed")  # fmt: skip
    p.add_argument("--objective", default=None,
                   help="a column to minimise (sliding, contact_ratio, center_distance, "
                   "efficiency, with --face-width volume and mass, with --torque -S_H and -S_F; "
                   "a leading '-' maximises: --objective=-contact_ratio), or 2-3 of them, "
                   "comma-separated, for a Pareto front (default sliding; volume with "
                   "--face-width)")  # fmt: skip
    p.add_argument("--max-seconds", type=positive("--max-seconds", "s"), default=600.0,
                   help="refuse a local search estimated to take longer")  # fmt: skip
    load_arguments(p, "each pair")
    p.add_argument(
        "--every-width", action="store_true",
        help="with --torque: keep every face width that carries the load as a candidate of its "
        "own (for a front of volume against safety), not only each pair's smallest",
    )  # fmt: skip
    p.add_argument(
        "--all", action="store_true",
        help="every feasible row, not the --top best; with -o FOLDER/ each chunk writes its "
        "rows there as a Parquet dataset (on a cluster: the workers write, in a folder they "
        "can reach)",
    )  # fmt: skip
    p.add_argument(
        "--estimate", action="store_true",
        help="print the number of candidates and the expected time (locally and per Dask "
        "worker, measured on a sample) and exit without searching",
    )  # fmt: skip
    _common(p)
    g = sub.add_parser("gearbox", help="planetary stages in series",
                       description="Search multi-stage planetary gearboxes.")  # fmt: skip
    g.add_argument("--ratio", "-r", type=_ratio, required=True, help="total reduction (> 1)")
    g.add_argument("--stages", type=integer("--stages", 1, 3), default=2)
    g.add_argument("--planets", "-k", type=integer("--planets"), default=3)
    g.add_argument("--schemes", nargs="+", default=["simple"],
                   help="schemes allowed for each stage")  # fmt: skip
    g.add_argument("--tolerance", type=non_negative("--tolerance"), default=0.0)
    g.add_argument("--z-min", type=integer("--z-min"), default=17)
    g.add_argument("--z-max", type=integer("--z-max"), default=150)
    g.add_argument("--module", "-m", type=positive("--module", "mm"), nargs="+", default=None,
                   help="module of every stage (default 1); with --torque the modules to choose "
                   "from (default the ISO 54 series I)")  # fmt: skip
    g.add_argument("--objective", default=None,
                   choices=("ring", "teeth", "efficiency", "volume", "mass", "mesh_efficiency"),
                   help="what to minimise (default ring; with --torque volume; mesh_efficiency: "
                   "the highest efficiency from the meshes at the load)")  # fmt: skip
    load_arguments(g, "each stage")
    _common(g)


def _common(p: argparse.ArgumentParser) -> None:
    p.add_argument("--top", type=integer("--top"), default=20, help="rows to print")
    dask_arguments(p)
    p.add_argument(
        "-o",
        "--output",
        type=_table_or_folder,
        default=None,
        help="also write the ranked table (.parquet, the parquet extra's pyarrow; .csv); "
        "checked before the search starts",
    )


def run(args: argparse.Namespace) -> int:
    from trains.errors import TrainError

    if args.connect_timeout is not None and not args.scheduler:
        raise TrainError("--connect-timeout applies with --scheduler only")
    if getattr(args, "split", None) is not None and args.center_distance is None:
        raise TrainError("--split divides the shift sum a --center-distance needs: it applies "
                         "with --center-distance only")  # fmt: skip
    folder = isinstance(args.output, str)
    if folder and not getattr(args, "all", False):
        raise TrainError(f"--output {args.output!r} is a folder: a Parquet dataset of every "
                         "feasible row, with --all; give a .parquet or .csv file")  # fmt: skip
    if args.output is not None and not folder:  # before the search: Parquet needs pyarrow
        from gears.search.tables import check_table_output

        check_table_output(args.output)
    load = load_options(args, widths_alone=args.what == "pairs")
    with dask_session(args, announce=not getattr(args, "estimate", False)) as client:
        return _search(args, client, load)


def _search(args: argparse.Namespace, client, load: dict) -> int:
    if args.what == "pairs":
        from gears.search.engine import estimate, pairs

        kwargs = _pair_arguments(args, client, load)
        if args.estimate:
            print(estimate(**kwargs))
            return OK
        with progress_bar("pair search", unit="candidate") as progress:
            found = pairs(**kwargs, progress=progress, max_seconds=args.max_seconds)
        table = found.table
        print(found)
        if found.dataset is not None:
            return OK if found.feasible else CHECK_FAILED
    else:
        from trains.design.gearbox import synthesize_gearbox

        module = args.module
        if module is not None and (len(module) == 1 and not load):
            module = module[0]
        with progress_bar("gearbox search", unit="task") as progress:
            found = synthesize_gearbox(
                args.ratio, args.stages, args.planets, tuple(args.schemes),
                tolerance=args.tolerance, z_min=args.z_min, z_max=args.z_max, module=module,
                objective=args.objective, top=args.top, client=client, progress=progress,
                **load,
            )  # fmt: skip
        table = found.to_array()
        print(found.table())
    if args.output is not None:
        from gears.search.tables import write_table

        write_table(table, args.output)
    return OK if len(found) else CHECK_FAILED


def _pair_arguments(args: argparse.Namespace, client, load: dict) -> dict:
    """The keyword arguments of ``gears.search.engine.pairs`` the options give."""
    from trains.errors import TrainError

    names = [o.strip() for o in args.objective.split(",") if o.strip()] if args.objective else []
    obj = None if not names else names[0] if len(names) == 1 else tuple(names)
    if args.every_width and not load:
        raise TrainError("--every-width keeps the widths that carry a load: give --torque")
    widths = load.pop("face_width", None)
    if load:
        load["smallest_width"] = not args.every_width
    dataset = args.output if isinstance(args.output, str) else None
    return dict(
        ratio=args.ratio, center_distance=args.center_distance, module=args.module,
        teeth=tuple(args.teeth), shifts=tuple(args.shifts), helix=args.helix,
        ratio_tolerance=args.ratio_tolerance, split=args.split or "proportional",
        limits={"min_contact_ratio": args.min_contact_ratio,
                "min_tip_land": args.min_tip_land,
                "allow_undercut": args.allow_undercut,
                "max_sliding": args.max_sliding},
        objective=obj, top=None if args.all else args.top, client=client,
        face_width=widths, dataset=dataset, **load,
    )  # fmt: skip
