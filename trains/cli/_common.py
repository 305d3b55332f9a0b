"""Layer 8, command line: what the ``geartrain`` sub-commands share: option types, output
paths, progress, message translation and line wrapping.

This module imports only the standard library (and ``tqdm`` when a bar is actually shown), so
building the parser, and so ``geartrain --help``, stays fast. The option types raise
:class:`argparse.ArgumentTypeError`, which argparse reports as
``geartrain CMD: error: argument --option: ...`` with exit status 2.

>>> positive("--module")("3")
3.0
>>> finite("--shift")("nan")
Traceback (most recent call last):
...
argparse.ArgumentTypeError: --shift nan is not a finite number
"""

from __future__ import annotations

import argparse
import contextlib
import logging
import os
import re
import sys
from collections.abc import Callable, Iterator, Mapping
from pathlib import Path

from trains.cli._rating import RATING_NAMES, edition_argument, rating_arguments, rating_given
from trains.cli._text import wrap
from trains.cli._types import (
    bounded,
    finite,
    integer,
    positive,
)

# exit statuses, the same for every sub-command
OK, CHECK_FAILED, BAD_INPUT, INTERNAL_ERROR = 0, 1, 2, 3


#: what a 3D scene can be written as (trimesh's exporters, gears.solid.export.save)
SCENE_FORMATS = (".glb", ".3mf", ".stl", ".obj", ".ply")


def output_file(suffixes: tuple[str, ...], name: str = "--output") -> Callable[[str], Path]:
    """An option type for a file to write, checked before any work by the library's own check
    (:func:`gears.files.check_output`): its suffix is one of ``suffixes``, it is not a
    directory, and its directory exists and is writable."""

    def parse(text: str) -> Path:
        from gears.errors import GearError
        from gears.files import check_output

        try:
            return check_output(text, suffixes, name)
        except GearError as exc:
            raise argparse.ArgumentTypeError(str(exc)) from None

    parse.__name__ = "file name"
    return parse


def input_file(name: str = "FILE") -> Callable[[str], Path]:
    """An option type for a file to read: it exists, is a file and is readable."""

    def parse(text: str) -> Path:
        p = Path(text)
        if not p.exists():
            raise argparse.ArgumentTypeError(f"{name} {text!r} does not exist")
        if not p.is_file():
            raise argparse.ArgumentTypeError(f"{name} {text!r} is not a file")
        if not os.access(p, os.R_OK):
            raise argparse.ArgumentTypeError(f"{name} {text!r} is not readable")
        return p

    parse.__name__ = "file name"
    return parse


def translate(message: str, names: Mapping[str, str]) -> str:
    """``message`` with each API name of ``names`` (a regular expression) replaced by the CLI's
    words; a name is replaced only as a whole word and not inside quotes (a quoted name is a
    field of a file, which keeps its own name).

    >>> translate("split='keep' needs x1", {r"split='(\\w+)'": r"--split \\1", "x1": "X1"})
    '--split keep needs X1'
    >>> translate("[run], 'mesh_efficiency': must be a number", {"mesh_efficiency": "--efficiency"})
    "[run], 'mesh_efficiency': must be a number"
    """
    for api, cli in names.items():
        message = re.sub(rf"(?<![\w.'-]){api}(?![\w('])", cli, message)
    return message


def no_check_argument(parser: argparse.ArgumentParser) -> None:
    """``--no-check``, for a command that writes a design's file (``mesh``, ``profile``)."""
    parser.add_argument(
        "--no-check", action="store_true",
        help="skip the design's checks: exit 0 even when one fails (default: run them; when one "
        "fails the file is still written, the failing checks go to stderr and the exit status "
        "is 1)",
    )  # fmt: skip


def design_status(report, prog: str, what: str) -> int:
    """The exit status of a design whose file was written: OK when every finding of ``report``
    (a :class:`gears.report.Report`) holds; otherwise CHECK_FAILED, with the failing findings
    on stderr under a line naming ``what`` and the way to skip the checks."""
    if report.ok:
        return OK
    lines = [f"{prog}: {what} fails its checks (the file is written; --no-check skips them):"]
    lines += [str(f) for f in report.values() if not f.ok]
    print(wrap("\n".join(lines)), file=sys.stderr)
    return CHECK_FAILED


def show_progress() -> bool:
    """Progress bars are shown only when stderr is a terminal."""
    try:
        return sys.stderr.isatty()
    except (AttributeError, ValueError):
        return False


@contextlib.contextmanager
def progress_bar(
    desc: str, total: int | None = None, delay: float = 1.0, unit: str = "block"
) -> Iterator[Callable[[int, int], None]]:
    """A tqdm bar on stderr (off when stderr is not a terminal; shown after ``delay`` s) and its
    ``(done, total)`` callback, the signature of the library's ``progress=`` parameters; it
    shows the units done, their rate and the time left."""
    if not show_progress():
        yield lambda done, total: None
        return
    from tqdm import tqdm

    bar = tqdm(total=total, desc=desc, file=sys.stderr, leave=False, unit=unit, delay=delay,
               unit_scale=unit != "block")  # fmt: skip

    def update(done: int, total: int) -> None:
        bar.total = total
        bar.update(done - bar.n)  # update(), not n =: tqdm's rate and time left follow it
        bar.refresh()

    try:
        yield update
    finally:
        bar.close()


#: the library's names for one gear's fields -> the options of gear_arguments
GEAR_NAMES = {
    "profile_shift": "--shift",
    "module": "--module",
    "pressure_angle": "--pressure-angle",
    "helix_angle": "--helix",
}


def gear_arguments(parser: argparse.ArgumentParser) -> None:
    """The options that describe one gear, shared by ``profile`` and ``mesh``: TEETH,
    ``--module``, ``--shift``, ``--helix``, ``--pressure-angle`` and ``--internal``."""
    parser.add_argument("teeth", type=integer("TEETH"), metavar="TEETH", help="number of teeth")
    parser.add_argument(
        "--module", "-m", type=positive("--module", "mm"), default=1.0, help="normal module, mm"
    )
    parser.add_argument(
        "--shift", "-x", type=finite("--shift"), default=0.0,
        help="profile-shift coefficient (a ring's in the sign of DIN 3960 / ISO 21771: positive "
        "thickens its teeth)",
    )  # fmt: skip
    parser.add_argument(
        "--helix", type=finite("--helix"), default=0.0, help="helix angle, deg (+ right hand)"
    )
    parser.add_argument(
        "--pressure-angle", type=finite("--pressure-angle"), default=20.0,
        help="normal pressure angle, deg",
    )  # fmt: skip
    parser.add_argument("--internal", action="store_true", help="an internal (ring) gear")


#: the library's names for a pair's fields -> the options of pair_arguments
PAIR_NAMES = {
    r"split\s*=\s*'(\w+)'": r"--split \1",
    r"x1 \+ x2": "--shift X1 + X2",  # a sum of shifts names the option that gives both
    "x1": "X1",
    "x2": "X2",
    "z1": "Z1",
    "z2": "Z2",
    "g1": "gear 1",
    "g2": "gear 2",
    "profile_shift": "--shift",
    "module": "--module",
    "pressure_angle": "--pressure-angle",
    "helix_angle": "--helix",
    "face_width": "--face-width",
    "center_distance": "--center-distance",
    "at_center_distance": "--center-distance",
}

SPLITS = ("equal_sliding", "proportional", "keep")


def pair_arguments(parser: argparse.ArgumentParser, face_width_help: str) -> None:
    """The options that describe one pair (``pair``, ``rate``): Z1, Z2, ``--module``,
    ``--shift X1 X2``, ``--internal``, ``--helix``, ``--pressure-angle``, ``--face-width`` (its
    help saying what the command uses it for), ``--center-distance`` and ``--split`` (built by
    :func:`build_pair`)."""
    parser.add_argument("z1", type=integer("Z1"), metavar="Z1", help="teeth of gear 1 (pinion)")
    parser.add_argument(
        "z2", type=integer("Z2"), metavar="Z2", help="teeth of gear 2 (the ring with --internal)"
    )
    parser.add_argument(
        "--module", "-m", type=positive("--module", "mm"), default=1.0, help="normal module, mm"
    )
    parser.add_argument(
        "--shift", "-x", type=finite("--shift"), nargs=2, default=(0.0, 0.0), metavar=("X1", "X2"),
        help="profile-shift coefficients of gear 1 and gear 2 (a ring's X2 in the sign of DIN 3960"
        " / ISO 21771: positive thickens its teeth)",
    )  # fmt: skip
    parser.add_argument("--internal", action="store_true", help="gear 2 is an internal ring")
    parser.add_argument(
        "--helix", type=finite("--helix"), default=0.0, metavar="BETA",
        help="helix angle of gear 1 in degrees (+ right hand); gear 2 gets the mating hand",
    )  # fmt: skip
    parser.add_argument(
        "--pressure-angle", type=finite("--pressure-angle"), default=20.0, metavar="ALPHA",
        help="normal pressure angle in degrees",
    )  # fmt: skip
    parser.add_argument(
        "--face-width", type=positive("--face-width", "mm"), default=None, metavar="B",
        help=face_width_help,
    )  # fmt: skip
    parser.add_argument(
        "--center-distance", type=positive("--center-distance", "mm"), default=None, metavar="A",
        help="working centre distance in mm: the shifts follow from it (overrides --shift X2)",
    )  # fmt: skip
    parser.add_argument(
        "--split", choices=SPLITS, default=None,
        help="with --center-distance: how it divides the shift sum ('keep' keeps X1 of --shift; "
        "default equal_sliding)",
    )  # fmt: skip


def build_pair(args: argparse.Namespace):
    """The :class:`gears.GearPair` the options of :func:`pair_arguments` describe."""
    from gears import Gear, GearPair

    x1, x2 = args.shift
    beta = args.helix
    g1 = Gear(args.z1, args.module, args.pressure_angle, beta, x1, args.face_width, internal=False)
    g2 = Gear(
        args.z2, args.module, args.pressure_angle, beta if args.internal else -beta, x2,
        args.face_width, internal=args.internal,
    )  # fmt: skip
    if args.center_distance is not None:
        split = args.split or "equal_sliding"
        return GearPair.at_center_distance(g1, g2, args.center_distance, split=split)
    refuse_split_alone(args)
    return GearPair(g1, g2)


def refuse_split_alone(args: argparse.Namespace) -> None:
    """A TrainError (exit 2) for ``--split`` without the ``--center-distance`` it divides."""
    from trains.errors import TrainError

    if args.split is not None and args.center_distance is None:
        raise TrainError("--split divides the shift sum a --center-distance needs: it applies "
                         "with --center-distance only")  # fmt: skip


#: the library's names for a bevel pair's fields -> the options of bevel_arguments
BEVEL_NAMES = {
    "module": "--module",
    "face_width": "--face-width",
    "pressure_angle": "--pressure-angle",
    "profile_shift": "--shift",
}


def bevel_arguments(
    parser: argparse.ArgumentParser, module: float, face_width_help: str, shift_help: str,
    shaft_angle: bool,
) -> None:  # fmt: skip
    """The options of a straight bevel pair (``bevel``, ``differential``): ``--module`` m_et
    (default ``module``), ``--face-width`` (default R_e / 3.5), ``--shaft-angle`` (when
    ``shaft_angle``), ``--pressure-angle`` and ``--shift`` x_hm of the pinion."""
    parser.add_argument(
        "--module", "-m", type=positive("--module", "mm"), default=module,
        help="outer transverse module m_et, mm",
    )  # fmt: skip
    parser.add_argument(
        "--face-width", "-b", type=positive("--face-width", "mm"), default=None,
        help=face_width_help,
    )  # fmt: skip
    if shaft_angle:
        parser.add_argument(
            "--shaft-angle", type=bounded("--shaft-angle", 0, 180, low_open=True,
                                          high_open=True, unit="deg"),
            default=90.0, help="angle between the axes, deg",
        )  # fmt: skip
    parser.add_argument(
        "--pressure-angle", type=finite("--pressure-angle"), default=20.0,
        help="pressure angle of the generating crown gear, deg",
    )  # fmt: skip
    parser.add_argument("--shift", "-x", type=finite("--shift"), default=0.0, help=shift_help)


# --- a design drawn in 3D (--scene) and animated (--animate) --------------------------------

#: what an animation can be written as (matplotlib's writers)
ANIMATION_FORMATS = (".gif", ".mp4")

#: the --tolerance of --animate by default, mm (a picture needs less than a 3D file)
ANIMATION_TOLERANCE = 0.05

#: the library's names in drawing errors -> the options of drawing_arguments
DRAWING_NAMES = {"tolerance": "--tolerance", "frames": "--frames"}


def scene_argument(parser: argparse.ArgumentParser, what: str) -> None:
    """``--scene FILE``: also write ``what`` in 3D (see :func:`write_scene`)."""
    parser.add_argument(
        "--scene", type=output_file(SCENE_FORMATS, "--scene"), default=None, metavar="FILE",
        help=f"also write {what} in 3D ({' '.join(SCENE_FORMATS)})",
    )  # fmt: skip


def drawing_arguments(
    parser: argparse.ArgumentParser, scene: str, animate: str, frames: int, tolerance: float
) -> None:
    """``--scene FILE`` (``scene`` in 3D), ``--animate FILE`` (``animate``), ``--frames N`` and
    ``--tolerance`` of the 3D teeth; ``frames`` and ``tolerance`` (of ``--scene``) are the
    defaults the help shows, the same the command gives :func:`write_animation` and
    :func:`write_scene`. :func:`refuse_undrawn` refuses them without their file."""
    scene_argument(parser, scene)
    parser.add_argument(
        "--animate", type=output_file(ANIMATION_FORMATS, "--animate"), default=None,
        metavar="FILE", help=f"also write {animate} ({' '.join(ANIMATION_FORMATS)})",
    )  # fmt: skip
    parser.add_argument(
        "--frames", type=integer("--frames"), default=None, metavar="N",
        help=f"frames of --animate (default: {frames})",
    )  # fmt: skip
    parser.add_argument(
        "--tolerance", type=positive("--tolerance", "mm"), default=None,
        help=f"largest deviation of the 3D teeth from the exact ones, mm (default: {tolerance:g} "
        f"for --scene, {ANIMATION_TOLERANCE:g} for --animate)",
    )  # fmt: skip


def refuse_undrawn(
    args: argparse.Namespace, drawing: tuple[str, ...] = ("--tolerance",),
    scene: tuple[str, ...] = (),
) -> None:  # fmt: skip
    """A TrainError (exit 2) for an option of :func:`drawing_arguments` given without its file:
    each option of ``drawing`` without ``--scene`` or ``--animate``, then each of ``scene``
    without ``--scene``, then ``--frames`` without ``--animate``. An option counts as given when
    it is neither None nor 0 (the defaults)."""
    from trains.errors import TrainError

    def given(option: str) -> bool:
        return bool(getattr(args, option[2:].replace("-", "_")))

    for option in drawing:
        if given(option) and args.scene is None and args.animate is None:
            raise TrainError(f"{option} applies with --scene or --animate only")
    for option in scene:
        if given(option) and args.scene is None:
            raise TrainError(f"{option} applies with --scene only")
    if args.frames is not None and args.animate is None:
        raise TrainError("--frames counts the frames of --animate: it applies with --animate only")


def write_scene(
    args: argparse.Namespace, make: Callable[[float], object], tolerance: float,
    note: Callable[[object, float], str],
) -> None:  # fmt: skip
    """With ``--scene``: the scene ``make(tolerance)`` at ``--tolerance`` (default
    ``tolerance``) written to that file, and a line naming it and ``note(scene, tolerance)``."""
    if args.scene is None:
        return
    from gears.solid.export import save

    tol = tolerance if args.tolerance is None else args.tolerance
    scene = make(tol)
    save(args.scene, scene)
    print(f"\nwrote {args.scene} ({note(scene, tol)})")


def write_animation(
    args: argparse.Namespace, animate: Callable[..., object], frames: int, note: str
) -> None:
    """With ``--animate``: ``animate(file, frames=, tolerance=, progress=)`` at ``--frames``
    (default ``frames``) and ``--tolerance`` (default :data:`ANIMATION_TOLERANCE`) with a
    progress bar, and a line naming the file, the frames and ``note``."""
    if args.animate is None:
        return
    tol = ANIMATION_TOLERANCE if args.tolerance is None else args.tolerance
    n = frames if args.frames is None else args.frames
    with progress_bar("frames", n) as bar:
        animate(args.animate, frames=n, tolerance=tol, progress=bar)
    print(f"wrote {args.animate} ({n} frames{note})")


# --- sizing for a load and running on a Dask cluster (search, synthesize --stages) -------------

#: seconds --connect-timeout waits by default (Dask's own default is 30 s)
CONNECT_TIMEOUT = 5.0


def dask_arguments(parser: argparse.ArgumentParser) -> None:
    """``--scheduler ADDRESS`` and ``--connect-timeout SECONDS`` (see :func:`dask_session`)."""
    parser.add_argument(
        "--scheduler", default=None, metavar="ADDRESS",
        help="a Dask scheduler address (tcp://host:8786): run the chunks there",
    )  # fmt: skip
    parser.add_argument(
        "--connect-timeout", type=positive("--connect-timeout", "s"), default=None,
        metavar="SECONDS",
        help=f"with --scheduler: how long to wait for the scheduler to answer, and for a worker "
        f"when the cluster has none left (default {CONNECT_TIMEOUT:g} s); then exit 2",
    )  # fmt: skip


@contextlib.contextmanager
def dask_session(args: argparse.Namespace, announce: bool = True) -> Iterator[object]:
    """The Dask client of ``--scheduler`` (None without), with ``--connect-timeout`` as Dask's
    ``distributed.comm.timeouts.connect`` for the whole run; closed afterwards. The dashboard's
    address is printed on stderr when a progress bar shows (``announce``)."""
    from trains.errors import TrainError

    if args.connect_timeout is not None and not args.scheduler:
        raise TrainError("--connect-timeout applies with --scheduler only")
    if not args.scheduler:
        yield None
        return
    import dask

    from gears.search.cluster import dask_client

    seconds = args.connect_timeout or CONNECT_TIMEOUT
    # a scheduler lost mid-run is told in one line (the library's error); Dask's own log of it
    # (a traceback per failed reconnection) would bury that line
    # (Dask sets the levels of its own loggers, so the log is switched off for the command)
    before = logging.root.manager.disable
    logging.disable(logging.CRITICAL)
    try:
        with dask.config.set({"distributed.comm.timeouts.connect": seconds}):
            client = dask_client(args.scheduler)
            try:
                link = getattr(client, "dashboard_link", None)
                if announce and link and show_progress():
                    print(f"Dask dashboard: {link}", file=sys.stderr)  # beside the bar
                yield client
            finally:
                with contextlib.suppress(Exception):  # a scheduler gone cannot be told
                    client.close(timeout=seconds)
    finally:
        logging.disable(before)


def face_widths(text: str) -> list[float]:
    """An option type: a face width in mm, or ``LOW:HIGH:STEP`` (every width from LOW to HIGH)."""
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


def load_arguments(parser: argparse.ArgumentParser, what: str) -> None:
    """The options of a design searched for a load: :func:`rating_arguments` (none required)
    and ``--face-width``, and :func:`edition_argument`."""
    rating_arguments(parser, required=False)
    edition_argument(parser)
    parser.add_argument(
        "--face-width", "-b", type=face_widths, nargs="+", default=None, metavar="B",
        help=f"face widths to choose from, mm (10 15 20, or LOW:HIGH:STEP like 10:40:5); with "
        f"--torque {what} takes the smallest that carries the load",
    )  # fmt: skip


def load_options(args: argparse.Namespace, widths_alone: bool = False) -> dict:
    """The keyword arguments of a search for a load (``torque``, ``speed``, ``face_width``,
    ``min_safety`` and the rating options given), or {} without ``--torque`` (with
    ``widths_alone`` just the face widths, when given); a rating option without ``--torque``
    and ``--torque`` without ``--speed`` or ``--face-width`` are refused."""
    from trains.errors import TrainError

    widths = None
    if args.face_width is not None:
        widths = sorted({w for ws in args.face_width for w in ws})
    given = rating_given(args) + (["--speed"] if args.speed is not None else [])
    if args.edition is not None:
        given.append("--edition")
    if widths is not None and not widths_alone:
        given.append("--face-width")
    if args.torque is None:
        if widths_alone and widths is not None and not given:
            return {"face_width": widths}
        if given:
            raise TrainError(f"{', '.join(given)} size the design for a load: they apply with "
                             "--torque only")  # fmt: skip
        return {}
    if args.speed is None or widths is None:
        raise TrainError("--torque rates each design at its face widths and speed: give "
                         "--speed (rpm of the input) and --face-width (mm)")  # fmt: skip
    out = {"torque": args.torque, "speed": args.speed, "face_width": widths}
    minimums = {k: getattr(args, f"min_{k}") for k in ("pitting", "bending")
                if getattr(args, f"min_{k}") is not None}  # fmt: skip
    if minimums:
        out["min_safety"] = minimums
    for key in ("material", "life", "quality", "roughness", "root_roughness", "oil_viscosity",
                "tip_relief", "application_factor", "edition"):  # fmt: skip
        if getattr(args, key) is not None:
            out[key] = getattr(args, key)
    return out


#: the library's names in the errors of a search for a load -> the options
LOAD_NAMES = {
    **{rf"\b{k}(?=\s*=)": v for k, v in RATING_NAMES.items()},
    r"face_width": "--face-width",
    r"min_safety\['pitting'\]": "--min-pitting",
    r"min_safety\['bending'\]": "--min-bending",
    r"client=": "--scheduler",
    r"distributed\.comm\.timeouts\.connect": "--connect-timeout",
}
