"""Layer 1, base: the rating family's array helpers and its one check of a number.

Private to the rating family. ``where`` and ``out`` keep one pair's numbers numpy scalars
(rating one pair is mostly their cost); ``number`` checks a value or an array against its range
and names the first bad entry; ``pair_of`` splits a per-gear value.
"""

from __future__ import annotations

import math

import numpy as np

from gears.errors import GearError


def out(a):
    """``a`` as an array, or its one number where it has no dimension."""
    a = np.asarray(a)
    return a[()] if a.ndim == 0 else a


def scalar(v) -> bool:
    """Whether ``v`` is one number (``np.ndim(v) == 0`` without its cost on numbers)."""
    if type(v) is np.ndarray:
        return v.ndim == 0
    return isinstance(v, (float, int, np.generic)) or np.ndim(v) == 0


def where(cond, a, b):
    """``np.where`` that keeps one pair's numbers numpy scalars (a Python branch: ten times
    faster than 0-d arrays, which is most of rating one pair)."""
    if scalar(cond) and scalar(a) and scalar(b):
        return a if cond else b
    return np.where(cond, a, b)


def number(name, value, low, high, low_open=True, high_open=True, integer=False):
    """``value`` as a float array, or a GearError naming the first bad entry and the range."""
    if type(value) is float or type(value) is int:  # the one-pair path: no array needed
        v = float(value)
        if (
            math.isfinite(v) and (v > low if low_open else v >= low)
            and (v < high if high_open else v <= high) and (not integer or v == round(v))
        ):  # fmt: skip
            return np.float64(v)
    try:
        a = np.asarray(value, float)
    except (TypeError, ValueError):
        raise GearError(f"{name} = {value!r}; valid is a number") from None
    if isinstance(value, bool | np.bool_) or a.dtype == object:
        raise GearError(f"{name} = {value!r}; valid is a number")
    ok = np.isfinite(a) & ((a > low) if low_open else (a >= low))
    ok &= (a < high) if high_open else (a <= high)
    if integer:
        ok &= a == np.round(a)
    if not np.all(ok):
        bad = np.ravel(a)[np.argmax(~np.ravel(ok))]
        at = "" if a.ndim == 0 else f" at row {int(np.argmax(~np.ravel(ok)))}"
        lo = f"{low:g} {'<' if low_open else '<='} "
        hi = f" {'<' if high_open else '<='} {high:g}"
        kind = "an integer " if integer else ""
        raise GearError(f"{name} = {float(bad):g}{at}; valid is {kind}{lo}{name}{hi}")
    return a


def pair_of(name, value):
    """A per-gear value: a scalar/array for both gears or a pair ``(gear 1, gear 2)``."""
    if isinstance(value, tuple | list) and len(value) == 2:
        return value[0], value[1]
    if isinstance(value, tuple | list):
        raise GearError(f"{name} = {value!r}; give one value or a pair (gear 1, gear 2)")
    return value, value
