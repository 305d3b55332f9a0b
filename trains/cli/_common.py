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
import math
import os
import re
import sys
from collections.abc import Callable, Iterator, Mapping
from pathlib import Path
from typing import TYPE_CHECKING

from trains.cli._text import wrap

if TYPE_CHECKING:
    from fractions import Fraction

# exit statuses, the same for every sub-command
OK, CHECK_FAILED, BAD_INPUT, INTERNAL_ERROR = 0, 1, 2, 3


def _float(name: str, text: str) -> float:
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{name} {text!r} is not a number") from None
    if not math.isfinite(v):
        raise argparse.ArgumentTypeError(f"{name} {text} is not a finite number")
    return v


def finite(name: str) -> Callable[[str], float]:
    """An option type: any finite float."""

    def parse(text: str) -> float:
        return _float(name, text)

    parse.__name__ = "number"
    return parse


def bounded(
    name: str, low: float | None = None, high: float | None = None, *, low_open: bool = False,
    high_open: bool = False, unit: str = "",
) -> Callable[[str], float]:  # fmt: skip
    """An option type: a finite float in ``[low, high]`` (``low_open``/``high_open``: open end).

    >>> bounded("--friction", 0, 1, high_open=True)("1")
    Traceback (most recent call last):
    ...
    argparse.ArgumentTypeError: --friction 1 is out of range; valid is 0 <= --friction < 1
    """
    lo = "" if low is None else f"{low:g} {'<' if low_open else '<='} "
    hi = "" if high is None else f" {'<' if high_open else '<='} {high:g}"
    valid = f"valid is {lo}{name}{hi}{f' ({unit})' if unit else ''}"

    def parse(text: str) -> float:
        v = _float(name, text)
        if (low is not None and (v <= low if low_open else v < low)) or (
            high is not None and (v >= high if high_open else v > high)
        ):
            raise argparse.ArgumentTypeError(f"{name} {text} is out of range; {valid}")
        return v

    parse.__name__ = "number"
    return parse


def positive(name: str, unit: str = "") -> Callable[[str], float]:
    """An option type: a finite float > 0."""
    return bounded(name, 0, low_open=True, unit=unit)


def non_negative(name: str, unit: str = "") -> Callable[[str], float]:
    """An option type: a finite float >= 0."""
    return bounded(name, 0, unit=unit)


def _whole_number(name: str, text: str, valid: str) -> int:
    """A whole number in float notation (``1e3``, ``20.0``) as an int."""
    try:
        f = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{name} {text!r} is not an integer") from None
    if not math.isfinite(f):
        raise argparse.ArgumentTypeError(f"{name} {text} is not a finite number; {valid}")
    if f != int(f):
        raise argparse.ArgumentTypeError(f"{name} {text} is not a whole number; {valid}")
    return int(f)


def integer(name: str, low: int = 1, high: int | None = None) -> Callable[[str], int]:
    """An option type: an integer in ``[low, high]``.

    >>> integer("Z1")("0")
    Traceback (most recent call last):
    ...
    argparse.ArgumentTypeError: Z1 0 is out of range; valid is an integer >= 1
    """
    valid = f"valid is an integer >= {low}" + ("" if high is None else f" and <= {high}")

    def parse(text: str) -> int:
        try:
            v = int(text.strip())
        except ValueError:
            v = _whole_number(name, text, valid)
        if v < low or (high is not None and v > high):
            raise argparse.ArgumentTypeError(f"{name} {text} is out of range; {valid}")
        return v

    parse.__name__ = "integer"
    return parse


def exact(name: str, text: str) -> Fraction:
    """``text`` as an exact finite number (``1500``, ``2.5``, ``22/3``); ``ValueError`` naming
    ``name`` otherwise (the caller turns it into its own error)."""
    from fractions import Fraction

    try:
        v = Fraction(text.strip())
    except (ValueError, ZeroDivisionError):
        raise ValueError(f"{name} {text!r} is not a number (e.g. 1500, 2.5 or 22/3)") from None
    try:
        if math.isfinite(float(v)):
            return v
    except OverflowError:
        pass
    raise ValueError(f"{name} {text} is too large; valid is a finite number below 1e308")


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


#: the library's names in rating errors -> the options of rating_arguments
RATING_NAMES = {
    "torque": "--torque",
    "speed": "--speed",
    "life": "--life",
    "quality": "--quality",
    "roughness": "--roughness",
    "root_roughness": "--root-roughness",
    "oil_viscosity": "--oil-viscosity",
    "tip_relief": "--tip-relief",
    "application_factor": "--application-factor",
    "material": "--material",
    "min_pitting": "--min-pitting",
    "min_bending": "--min-bending",
}


RATING_DEFAULTS = {
    "material": "case-carburized",
    "life": 20000.0,
    "quality": 6,
    "roughness": 1.0,
    "root_roughness": None,
    "oil_viscosity": 220.0,
    "tip_relief": None,
    "application_factor": 1.0,
    "min_pitting": 1.0,
    "min_bending": 1.4,
}


def rating_arguments(parser: argparse.ArgumentParser, required: bool = True, *,
                     torque: bool = True, speed: bool = True) -> None:  # fmt: skip
    """The operating conditions of an ISO 6336 rating (``rate``, ``planetary``; the ISO 10300
    rating of ``bevel`` and ``differential``): ``--torque`` and ``--speed`` (unless the
    command has its own: ``torque=False``, ``speed=False``), ``--material``, ``--life``,
    ``--quality``, ``--roughness``, ``--root-roughness``, ``--oil-viscosity``,
    ``--tip-relief``, ``--application-factor``, ``--min-pitting`` and ``--min-bending``. Their
    defaults (:data:`RATING_DEFAULTS`) are filled in by :func:`rating_options`, so a command
    can tell which were given (:func:`rating_given`)."""
    need = "" if required else " (with --speed: rate every mesh)"
    d = RATING_DEFAULTS
    if torque:
        parser.add_argument(
            "--torque", type=positive("--torque", "N m"), required=required, default=None,
            metavar="T", help=f"input torque in N m{need}",
        )  # fmt: skip
    if speed:
        parser.add_argument(
            "--speed", type=positive("--speed", "rpm"), required=required, default=None,
            metavar="N", help="input speed in rpm",
        )  # fmt: skip
    parser.add_argument(
        "--material", default=None,
        help="ISO 6336-5 material of the gears: case-carburized, nitrided, induction-hardened, "
        f"flame-hardened, through-hardened, nodular-cast-iron or grey-cast-iron (default "
        f"{d['material']})",
    )  # fmt: skip
    parser.add_argument(
        "--life", type=positive("--life", "hours"), default=None,
        help=f"required life, hours (default {d['life']:g})",
    )  # fmt: skip
    parser.add_argument(
        "--quality", type=integer("--quality", 1, 12), default=None,
        help=f"ISO 1328 accuracy grade (default {d['quality']})",
    )  # fmt: skip
    parser.add_argument(
        "--roughness", type=positive("--roughness", "um"), default=None,
        help=f"flank roughness Ra, um (default {d['roughness']:g})",
    )  # fmt: skip
    parser.add_argument(
        "--root-roughness", type=positive("--root-roughness", "um"), default=None,
        metavar="RA", help="root fillet roughness Ra, um (default: --roughness; a ground flank "
        "with a hobbed root has a rougher root)",
    )  # fmt: skip
    parser.add_argument(
        "--oil-viscosity", type=positive("--oil-viscosity", "mm^2/s"), default=None,
        help=f"oil viscosity nu_40 at 40 deg C, mm^2/s (default {d['oil_viscosity']:g})",
    )  # fmt: skip
    parser.add_argument(
        "--tip-relief", type=non_negative("--tip-relief", "mm"), default=None, metavar="C_A",
        help="tip relief in mm (default: the running-in amount of ISO 6336-1)",
    )  # fmt: skip
    parser.add_argument(
        "--application-factor", type=bounded("--application-factor", 1, 10), default=None,
        metavar="K_A", help=f"application factor K_A (default {d['application_factor']:g})",
    )  # fmt: skip
    parser.add_argument(
        "--min-pitting", type=non_negative("--min-pitting"), default=None,
        help=f"required safety against pitting S_Hmin (default {d['min_pitting']:g})",
    )  # fmt: skip
    parser.add_argument(
        "--min-bending", type=non_negative("--min-bending"), default=None,
        help=f"required safety against tooth-root breakage S_Fmin (default {d['min_bending']:g})",
    )  # fmt: skip


def rating_given(args: argparse.Namespace) -> list[str]:
    """The rating options given on the command line (other than --torque and --speed)."""
    return [f"--{k.replace('_', '-')}" for k in RATING_DEFAULTS if getattr(args, k) is not None]


def rating_options(args: argparse.Namespace) -> dict:
    """The keyword arguments of ``GearPair.rating`` / ``Planetary.rating`` the options of
    :func:`rating_arguments` give (torque, speed and the minimums aside), defaults filled in."""
    keys = ("material", "life", "quality", "roughness", "root_roughness", "oil_viscosity",
            "tip_relief", "application_factor")  # fmt: skip
    return {k: RATING_DEFAULTS[k] if getattr(args, k) is None else getattr(args, k) for k in keys}


def rating_minimums(args: argparse.Namespace) -> tuple[float, float]:
    """``(min_pitting, min_bending)`` of the options, defaults filled in."""
    return tuple(
        RATING_DEFAULTS[k] if getattr(args, k) is None else getattr(args, k)
        for k in ("min_pitting", "min_bending")
    )


#: the library's names in ISO 10300 errors -> the options of :func:`bevel_rating_arguments`
BEVEL_RATING_NAMES = {
    "mounting": "--mounting",
    "pattern": "--pattern",
    "effective_width": "--effective-width",
}


def bevel_rating_arguments(parser: argparse.ArgumentParser) -> None:
    """What ISO 10300 adds to :func:`rating_arguments` (``bevel``, ``differential``):
    ``--mounting`` and ``--pattern`` (the mounting factor K_Hbeta-be) and
    ``--effective-width`` (b_eff / b)."""
    parser.add_argument(
        "--mounting", choices=("both-straddle", "one-straddle", "neither-straddle"),
        default=None, help="how pinion and wheel are mounted (ISO 10300-1 mounting factor; "
        "default both-straddle)",
    )  # fmt: skip
    parser.add_argument(
        "--pattern", choices=("full-load", "light-load", "estimated"), default=None,
        help="how the contact pattern was checked: each set under full load, under a light "
        "test load (default), or on a sample set and estimated",
    )  # fmt: skip
    parser.add_argument(
        "--effective-width", type=bounded("--effective-width", 0, 1, low_open=True),
        default=None, metavar="B_EFF",
        help="share of the face the loaded contact pattern covers, b_eff / b (default 0.85)",
    )  # fmt: skip


#: the defaults of :func:`bevel_rating_arguments`
BEVEL_RATING_DEFAULTS = {"mounting": "both-straddle", "pattern": "light-load",
                         "effective_width": 0.85}  # fmt: skip


def bevel_rating_given(args: argparse.Namespace) -> list[str]:
    """The rating options of an ISO 10300 rating given on the command line (other than
    --torque and --speed)."""
    own = [f"--{k.replace('_', '-')}" for k in BEVEL_RATING_DEFAULTS
           if getattr(args, k) is not None]  # fmt: skip
    return rating_given(args) + own


def bevel_rating_options(args: argparse.Namespace) -> dict:
    """The keyword arguments of ``BevelPair.rating`` / ``Differential.rating`` of the options of
    :func:`rating_arguments` and :func:`bevel_rating_arguments` (torque, speed and the minimums
    aside), defaults filled in."""
    own = {k: d if getattr(args, k) is None else getattr(args, k)
           for k, d in BEVEL_RATING_DEFAULTS.items()}  # fmt: skip
    return {**rating_options(args), **own}


#: The scuffing options' library names in error messages -> the options (``rate``, ``planetary``).
SCUFFING_NAMES = {
    "fzg_stage": "--fzg-stage", "oil temperature": "--oil-temperature",
    "oil viscosity_100": "--oil-viscosity-100", "oil viscosity_40": "--oil-viscosity",
    "oil base": "--oil", "oil density": "--oil-density", "welding_factor": "--welding-factor",
    "min_scuffing": "--min-scuffing",
}  # fmt: skip


def scuffing_arguments(parser: argparse.ArgumentParser) -> None:
    """The oil of a scuffing rating (ISO/TS 6336-20/-21): ``--fzg-stage``, ``--oil-temperature``,
    ``--oil-viscosity-100`` (``--oil-viscosity`` is its nu_40), ``--oil``, ``--oil-density``,
    ``--spray``, ``--welding-factor`` and ``--min-scuffing`` (:func:`scuffing_options`)."""
    group = parser.add_argument_group(
        "scuffing (ISO/TS 6336-20 flash temperature, ISO/TS 6336-21 integral temperature)"
    )
    group.add_argument(
        "--fzg-stage", type=int, default=None, metavar="STAGE",
        help="the oil's failure load stage in the FZG test A/8.3/90 (ISO 14635-1), 1 ... 12: "
        "rate against scuffing",
    )  # fmt: skip
    group.add_argument(
        "--oil-temperature", type=float, default=None, metavar="C",
        help="oil temperature before the mesh, deg C (needed with --fzg-stage)",
    )  # fmt: skip
    group.add_argument(
        "--oil-viscosity-100", type=float, default=None, metavar="NU100",
        help="the oil's kinematic viscosity at 100 deg C, mm^2/s (needed with --fzg-stage; "
        "--oil-viscosity is its nu_40)",
    )  # fmt: skip
    group.add_argument(
        "--oil", default="mineral", metavar="BASE",
        help="base oil: mineral, polyalphaolefin, polyglycol, polyglycol-water-soluble, "
        "traction, phosphate-ester (default mineral)",
    )  # fmt: skip
    group.add_argument(
        "--oil-density", type=float, default=890.0, metavar="KG_M3",
        help="the oil's density at 15 deg C, kg/m^3 (default 890.0)",
    )  # fmt: skip
    group.add_argument(
        "--spray", action="store_true", help="spray lubrication (default: dip lubrication)"
    )
    group.add_argument(
        "--welding-factor", type=float, default=1.0, metavar="X_W",
        help="welding factor X_W of the flanks (default 1.0, case-carburized)",
    )  # fmt: skip
    group.add_argument(
        "--min-scuffing", type=float, nargs=2, default=None, metavar=("S_B", "S_INTS"),
        help="minimum scuffing safeties, flash and integral (default 2.0 1.8)",
    )  # fmt: skip


def scuffing_options(args: argparse.Namespace, nu40: float) -> dict:
    """``{"scuffing": Oil, "welding_factor": X_W}`` of the scuffing options (the oil's nu_40
    ``nu40``), or ``{}`` without ``--fzg-stage``; an oil option without it, or ``--fzg-stage``
    without the oil's temperature and nu_100, is a GearError naming the option."""
    from gears.errors import GearError
    from gears.rating.scuffing import Oil

    needed = ("oil_temperature", "oil_viscosity_100")
    if args.fzg_stage is None:
        for option in needed:
            if getattr(args, option) is not None:
                raise GearError(f"--{option.replace('_', '-')} needs --fzg-stage STAGE")
        return {}
    for option in needed:
        if getattr(args, option) is None:
            raise GearError(f"--fzg-stage needs --{option.replace('_', '-')}")
    lubrication = "spray" if args.spray else "dip"
    oil = Oil(args.fzg_stage, args.oil_temperature, nu40, args.oil_viscosity_100,
              args.oil_density, args.oil, lubrication)  # fmt: skip
    return {"scuffing": oil, "welding_factor": args.welding_factor}


def scuffing_minimum(args: argparse.Namespace) -> dict:
    """``{"min_scuffing": (S_B, S_intS)}`` when ``--min-scuffing`` was given, else ``{}``
    (``Rating.check``'s defaults)."""
    return {} if args.min_scuffing is None else {"min_scuffing": tuple(args.min_scuffing)}


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
    and ``--face-width``."""
    rating_arguments(parser, required=False)
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
                "tip_relief", "application_factor"):  # fmt: skip
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
