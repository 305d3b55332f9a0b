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
"""

from __future__ import annotations

import argparse

from trains.commands._common import (
    CHECK_FAILED,
    OK,
    RATING_NAMES,
    bounded,
    exact,
    finite,
    integer,
    non_negative,
    output_file,
    positive,
    progress_bar,
    rating_arguments,
    show_progress,
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
    **{rf"\b{k}(?=\s*=)": v for k, v in RATING_NAMES.items()},
    r"face_width": "--face-width",
    r"min_safety\['pitting'\]": "--min-pitting",
    r"min_safety\['bending'\]": "--min-bending",
    r"dataset(?=\s*=)": "--output",
    r"top=None": "--all",
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


def _widths(text: str) -> list[float]:
    """A face width in mm, or ``LOW:HIGH:STEP`` (every width from LOW to HIGH)."""
    parts = text.split(":")
    value = finite("--face-width")
    if len(parts) == 1:
        return [value(text)]
    if len(parts) != 3:
        raise argparse.ArgumentTypeError(
            f"--face-width {text!r}; give widths in mm (10 15 20) or LOW:HIGH:STEP (10:40:5)"
        )
    lo, hi, step = (value(p) for p in parts)
    if step <= 0 or hi < lo:
        raise argparse.ArgumentTypeError(
            f"--face-width {text!r}; LOW:HIGH:STEP needs HIGH >= LOW and STEP > 0"
        )
    n = int((hi - lo) / step + 1e-9) + 1
    return [round(lo + i * step, 12) for i in range(n)]


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
    rating_arguments(p, required=False)
    p.add_argument(
        "--face-width", "-b", type=_widths, nargs="+", default=None, metavar="B",
        help="face widths to try, mm (10 15 20, or LOW:HIGH:STEP like 10:40:5): adds the "
        "volume and mass; with --torque each pair is rated at each width and sized to the "
        "smallest that meets --min-pitting and --min-bending",
    )  # fmt: skip
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
        type=_table_or_folder,
        default=None,
        help="also write the ranked table (.parquet, the parquet extra's pyarrow; .csv); "
        "checked before the search starts",
    )


def run(args: argparse.Namespace) -> int:
    import contextlib
    import sys

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
            link = getattr(client, "dashboard_link", None)
            if link and show_progress() and not getattr(args, "estimate", False):
                print(f"Dask dashboard: {link}", file=sys.stderr)  # beside the bar
        return _search(args, client)


def _search(args: argparse.Namespace, client) -> int:
    if args.what == "pairs":
        from gears.search import estimate, pairs

        kwargs = _pair_arguments(args, client)
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


def _pair_arguments(args: argparse.Namespace, client) -> dict:
    """The keyword arguments of ``gears.search.pairs`` the options give."""
    names = [o.strip() for o in args.objective.split(",") if o.strip()] if args.objective else []
    obj = None if not names else names[0] if len(names) == 1 else tuple(names)
    widths = None
    if args.face_width is not None:
        widths = sorted({w for ws in args.face_width for w in ws})
    from trains.commands._common import rating_given
    from trains.errors import TrainError

    given = rating_given(args) + (["--speed"] if args.speed is not None else [])
    if args.torque is None and given:
        raise TrainError(f"{', '.join(given)} rate the pairs under a load: they apply with "
                         "--torque only")  # fmt: skip
    if args.torque is not None and (args.speed is None or widths is None):
        raise TrainError("--torque rates each pair at its face widths and speed: give --speed "
                         "(rpm of gear 1) and --face-width (mm)")  # fmt: skip
    load = {}
    if args.torque is not None:
        load = {"torque": args.torque, "speed": args.speed,
                "smallest_width": not args.every_width}  # fmt: skip
    elif args.every_width:
        raise TrainError("--every-width keeps the widths that carry a load: give --torque")
    minimums = {k: getattr(args, f"min_{k}") for k in ("pitting", "bending")
                if getattr(args, f"min_{k}") is not None}  # fmt: skip
    if minimums:
        load["min_safety"] = minimums
    for key in ("material", "life", "quality", "roughness", "oil_viscosity", "tip_relief",
                "application_factor"):  # fmt: skip
        if getattr(args, key) is not None:
            load[key] = getattr(args, key)
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
