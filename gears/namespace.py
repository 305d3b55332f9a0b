"""Layer 0, base: the namespace a formula computes in, numpy for arrays or ``math`` for one pair.

Every formula lives once, written against a namespace ``xp`` (``xp.sqrt``, ``xp.cos``,
``xp.arctan``, ``xp.maximum``, ...) that :func:`of` picks from its arguments: numpy itself where
any argument is an array or a numpy number, :data:`SCALAR` where every argument is a Python
``float``, ``int`` or ``bool``. :data:`SCALAR` has numpy's names and numpy's answers on one
number (NaN outside a function's domain, NaN propagated by ``maximum`` and ``minimum``), through
``math`` on Python floats: a numpy function costs about ten times as much on one number as on
nothing, and rating one pair is a few hundred of them.

Python floats differ from numpy's in three ways a caller must allow for: division by zero raises
ZeroDivisionError, ``**`` and ``math.exp`` can raise OverflowError, and ``~`` on a ``bool`` is
not a logical not (write ``xp.logical_not``). A caller that runs a formula on Python floats runs
it again on numpy numbers where one of the first two happens (:data:`FLOAT_ERRORS`): the
formulas are the same, only the namespace changes.
"""

from __future__ import annotations

import bisect
import math
from types import SimpleNamespace

import numpy as np

__all__ = ["FLOAT_ERRORS", "SCALAR", "all_plain", "of"]

_PLAIN = frozenset({float, int, bool})
_ALL_PLAIN = _PLAIN.issuperset  # over map(type, values): the loop in C
_NAN = math.nan
_INF = math.inf

#: What Python floats raise where numpy numbers give inf or NaN (math's domain errors are a
#: ValueError; a caller re-raises its own GearError, a ValueError too).
FLOAT_ERRORS = (ArithmeticError, ValueError)


def of(*values):
    """:data:`SCALAR` when every value is a Python ``float``, ``int`` or ``bool``, else numpy."""
    return SCALAR if _ALL_PLAIN(map(type, values)) else np


def all_plain(values) -> bool:
    """Whether every one of ``values`` (an iterable) is a Python ``float``, ``int`` or ``bool``:
    numbers :data:`SCALAR` computes on."""
    return _ALL_PLAIN(map(type, values))


def _sqrt(x):
    return math.sqrt(x) if x >= 0.0 else _NAN  # NaN fails the test too


def _arccos(x):
    return math.acos(x) if -1.0 <= x <= 1.0 else _NAN


def _arcsin(x):
    return math.asin(x) if -1.0 <= x <= 1.0 else _NAN


def _maximum(a, b):
    return a if a >= b or a != a else b  # NaN in either gives NaN, as numpy


def _minimum(a, b):
    return a if a <= b or a != a else b


def _clip(x, low, high):
    return _minimum(_maximum(x, low), high)


def _exp(x):
    try:
        return math.exp(x)
    except OverflowError:
        return _INF


def _exp2(x):
    try:
        return math.exp2(x)
    except OverflowError:
        return _INF


def _log(x):
    if x > 0.0:
        return math.log(x)
    return -_INF if x == 0.0 else _NAN


def _power(x, y):
    try:
        return math.pow(x, y)  # C's pow, as numpy's (Python's ** gives a complex number)
    except ValueError:
        if x == 0.0:
            raise  # 0 ** -y: numpy's inf on the caller's fallback
        return _NAN  # a negative number to a fraction


def _where(cond, a, b):
    return a if cond else b


def _logical_not(x):
    return not x


class _Quiet:
    """``errstate`` of Python floats: nothing to silence (they raise or give inf and NaN)."""

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False


_QUIET = _Quiet()


def _errstate(**_):
    return _QUIET


def _interp(x, xp, fp):
    """``np.interp`` of one number on knots ``xp`` (ascending) with values ``fp``."""
    if x != x:
        return _NAN
    if x <= xp[0]:
        return fp[0]
    if x >= xp[-1]:
        return fp[-1]
    j = bisect.bisect_right(xp, x) - 1
    slope = (fp[j + 1] - fp[j]) / (xp[j + 1] - xp[j])
    return slope * (x - xp[j]) + fp[j]


#: numpy's names over one Python float each (see the module docstring).
SCALAR = SimpleNamespace(
    pi=math.pi,
    nan=math.nan,
    inf=math.inf,
    sqrt=_sqrt,
    cbrt=math.cbrt,
    cos=math.cos,
    sin=math.sin,
    tan=math.tan,
    arctan=math.atan,
    arctan2=math.atan2,
    arccos=_arccos,
    arcsin=_arcsin,
    radians=math.radians,
    degrees=math.degrees,
    abs=abs,
    maximum=_maximum,
    minimum=_minimum,
    clip=_clip,
    exp=_exp,
    exp2=_exp2,
    log=_log,
    power=_power,
    isnan=math.isnan,
    isfinite=math.isfinite,
    where=_where,
    logical_not=_logical_not,
    interp=_interp,
    errstate=_errstate,
)
