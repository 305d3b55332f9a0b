"""Layer 6, command line: what the ``geartrain`` sub-commands share: option types, output
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
import math
import os
import re
import shutil
import sys
import textwrap
from collections.abc import Callable, Iterator, Mapping
from pathlib import Path
from typing import TYPE_CHECKING

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
            raise argparse.ArgumentTypeError(f"{name} {text!r} is not an integer") from None
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


#: what a 3D scene can be written as (trimesh's exporters, gears.export.save)
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


def wrap(text: str, width: int | None = None) -> str:
    """``text`` with every line longer than ``width`` (default: the terminal's, or 100) wrapped;
    the continuation lines are indented past the line's own indent (past ``[FAIL] `` for a
    finding), so tables and findings stay readable.

    >>> print(wrap("[FAIL] a_long_finding margin -1: " + "word " * 8, width=40))
    [FAIL] a_long_finding margin -1: word
           word word word word word word
           word
    """
    width = width or shutil.get_terminal_size((100, 24)).columns
    width = max(width, 40)
    out = []
    for line in text.splitlines():
        if len(line) <= width:
            out.append(line)
            continue
        lead = line[: len(line) - len(line.lstrip())]
        body = line.lstrip()
        hang = lead + (" " * (body.index("]") + 2) if body.startswith("[") else "    ")
        out.extend(
            textwrap.wrap(
                body,
                width,
                initial_indent=lead,
                subsequent_indent=hang,
                break_long_words=False,
                break_on_hyphens=False,
            )
        )
    return "\n".join(out)


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
    desc: str, total: int | None = None, delay: float = 1.0
) -> Iterator[Callable[[int, int], None]]:
    """A tqdm bar on stderr (off when stderr is not a terminal; shown after ``delay`` s) and its
    ``(done, total)`` callback, the signature of the library's ``progress=`` parameters."""
    if not show_progress():
        yield lambda done, total: None
        return
    from tqdm import tqdm

    bar = tqdm(total=total, desc=desc, file=sys.stderr, leave=False, unit="block", delay=delay)

    def update(done: int, total: int) -> None:
        bar.total = total
        bar.n = done
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
        "--shift", "-x", type=finite("--shift"), default=0.0, help="profile-shift coefficient"
    )
    parser.add_argument(
        "--helix", type=finite("--helix"), default=0.0, help="helix angle, deg (+ right hand)"
    )
    parser.add_argument(
        "--pressure-angle", type=finite("--pressure-angle"), default=20.0,
        help="normal pressure angle, deg",
    )  # fmt: skip
    parser.add_argument("--internal", action="store_true", help="an internal (ring) gear")
