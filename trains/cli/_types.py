"""Layer 0, command line: the option types of the ``geartrain`` sub-commands (finite, bounded,
positive and integer numbers, exact fractions). Each raises :class:`argparse.ArgumentTypeError`
naming its option, which argparse reports as ``geartrain CMD: error: argument --option: ...``
with exit status 2.

>>> positive("--module")("3")
3.0
>>> finite("--shift")("nan")
Traceback (most recent call last):
...
argparse.ArgumentTypeError: --shift nan is not a finite number
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from fractions import Fraction


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
