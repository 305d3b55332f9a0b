"""Search designs and print them ranked: gear pairs (every candidate checked as GearPair.check
does) or multi-stage planetary gearboxes. The work runs in chunks on every local core, or on a
Dask cluster with --scheduler. The exit status is 1 when nothing meets the request.

Examples:
    geartrain search pairs --ratio 3.2 --center-distance 100 --module 2 2.5 3 --teeth 12 120
    geartrain search pairs --ratio 2 --module 2 --teeth 14 40 --objective sliding,-contact_ratio
    geartrain search gearbox --ratio 37 --stages 2 --schemes simple stepped --z-max 120
"""

from __future__ import annotations

import argparse

from trains.commands._common import (
    CHECK_FAILED,
    OK,
    bounded,
    exact,
    finite,
    integer,
    non_negative,
    output_file,
    positive,
    progress_bar,
)

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
    r"client=": "--scheduler",
    r"distributed\.comm\.timeouts\.connect": "--connect-timeout",
}
"""The library's names in error messages -> this command's options."""

_SUFFIXES = (".parquet", ".csv")

#: seconds --connect-timeout waits by default (Dask's own default is 30 s)
CONNECT_TIMEOUT = 5.0


def _ratio(text: str):
    try:
        return exact("--ratio", text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


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
    p.add_argument("--objective", default="sliding",
                   help="a column to minimise (sliding, contact_ratio, center_distance, "
                   "efficiency, ...; a leading '-' maximises: --objective=-contact_ratio), or "
                   "2-3 of them, comma-separated, for a Pareto front")  # fmt: skip
    p.add_argument("--max-seconds", type=positive("--max-seconds", "s"), default=600.0,
                   help="refuse a local search estimated to take longer")  # fmt: skip
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
    g.add_argument("--module", "-m", type=positive("--module", "mm"), default=1.0)
    g.add_argument("--objective", choices=("ring", "teeth", "efficiency"), default="ring")
    _common(g)


def _common(p: argparse.ArgumentParser) -> None:
    p.add_argument("--top", type=integer("--top"), default=20, help="rows to print")
    p.add_argument(
        "--scheduler",
        default=None,
        metavar="ADDRESS",
        help="a Dask scheduler address (tcp://host:8786): run the chunks there",
    )
    p.add_argument(
        "--connect-timeout", type=positive("--connect-timeout", "s"), default=None,
        metavar="SECONDS",
        help=f"with --scheduler: how long to wait for the scheduler to answer, and for a worker "
        f"when the cluster has none left (default {CONNECT_TIMEOUT:g} s); then exit 2",
    )  # fmt: skip
    p.add_argument(
        "-o",
        "--output",
        type=output_file(_SUFFIXES),
        default=None,
        help="also write the ranked table (.parquet, the parquet extra's pyarrow; .csv); "
        "checked before the search starts",
    )


def run(args: argparse.Namespace) -> int:
    import contextlib

    from trains.errors import TrainError

    if args.connect_timeout is not None and not args.scheduler:
        raise TrainError("--connect-timeout applies with --scheduler only")
    if getattr(args, "split", None) is not None and args.center_distance is None:
        raise TrainError("--split divides the shift sum a --center-distance needs: it applies "
                         "with --center-distance only")  # fmt: skip
    if args.output is not None:  # before the search: a Parquet file needs pyarrow
        from gears.search import check_table_output

        check_table_output(args.output)
    with contextlib.ExitStack() as stack:
        client = None
        if args.scheduler:
            import dask

            from gears.search import dask_client

            seconds = args.connect_timeout or CONNECT_TIMEOUT
            stack.enter_context(dask.config.set({"distributed.comm.timeouts.connect": seconds}))
            client = dask_client(args.scheduler)
            stack.callback(client.close)
        return _search(args, client)


def _search(args: argparse.Namespace, client) -> int:
    if args.what == "pairs":
        from gears.search import pairs

        names = [o.strip() for o in args.objective.split(",") if o.strip()]
        obj = names[0] if len(names) == 1 else tuple(names)
        with progress_bar("pair search") as progress:
            found = pairs(
                ratio=args.ratio, center_distance=args.center_distance, module=args.module,
                teeth=tuple(args.teeth), shifts=tuple(args.shifts), helix=args.helix,
                ratio_tolerance=args.ratio_tolerance, split=args.split or "proportional",
                limits={"min_contact_ratio": args.min_contact_ratio,
                        "min_tip_land": args.min_tip_land,
                        "allow_undercut": args.allow_undercut,
                        "max_sliding": args.max_sliding},
                objective=obj, top=args.top, client=client, progress=progress,
                max_seconds=args.max_seconds,
            )  # fmt: skip
        table = found.table
        print(found)
    else:
        from trains.gearbox import synthesize_gearbox

        with progress_bar("gearbox search") as progress:
            found = synthesize_gearbox(
                args.ratio, args.stages, args.planets, tuple(args.schemes),
                tolerance=args.tolerance, z_min=args.z_min, z_max=args.z_max, module=args.module,
                objective=args.objective, top=args.top, client=client, progress=progress,
            )  # fmt: skip
        table = found.to_array()
        print(found.table())
    if args.output is not None:
        from gears.search import write_table

        write_table(table, args.output)
    return OK if len(found) else CHECK_FAILED
