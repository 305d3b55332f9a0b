"""Layer 2, load capacity: the life factors Z_NT (ISO 6336-2 §10) and Y_NT (ISO 6336-3 §12).

The allowable stresses of ISO 6336 hold at the endurance limit; fewer load cycles allow more.
The curves depend on the material group (:data:`gears.rating.materials.KINDS`), given by name or
by its integer code.

>>> round(float(pitting_life_factor(1.08e9, "Eh")), 3)   # ISO/TR 6336-30 Ex. 1: Z_NT1 0.91
0.91
"""

from __future__ import annotations

import math

import numpy as np

from gears.namespace import SCALAR
from gears.rating.materials import KINDS, kind_code

__all__ = ["bending_life_factor", "pitting_life_factor"]

# Life curves: knots (N_L, factor) joined linearly in log-log, constant outside (ISO 6336-2
# Table 2, curves for "no pitting permitted"; ISO 6336-3 Table 3). The 0.85 at 10^10 is the
# standard's value for usual conditions (1.0 only with optimum lubrication, material and
# manufacturing and experience); ISO/TR 6336-30 Ex. 1 uses it.
_PITTING_CURVES = {
    # St, V, GGG (perl., bai.), Eh, IF
    0: ((1e5, 1.6), (5e7, 1.0), (1e10, 0.85)),
    # GG, GGG (ferr.), NT (nitr.)
    1: ((1e5, 1.3), (2e6, 1.0), (1e10, 0.85)),
    # NV (nitrocar.)
    2: ((1e5, 1.1), (2e6, 1.0), (1e10, 0.85)),
}
_PITTING_CURVE_OF = {"St": 0, "V": 0, "GGG": 0, "Eh": 0, "IF": 0, "GG": 1, "NT": 1, "NV": 2}
_BENDING_CURVES = {
    # St, V, GGG (perl., bai.)
    0: ((1e4, 2.5), (3e6, 1.0), (1e10, 0.85)),
    # Eh, IF (root)
    1: ((1e3, 2.5), (3e6, 1.0), (1e10, 0.85)),
    # GG, GGG (ferr.), NT (nitr.)
    2: ((1e3, 1.6), (3e6, 1.0), (1e10, 0.85)),
    # NV (nitrocar.)
    3: ((1e3, 1.1), (3e6, 1.0), (1e10, 0.85)),
}
_BENDING_CURVE_OF = {"St": 0, "V": 0, "GGG": 0, "Eh": 1, "IF": 1, "GG": 2, "NT": 2, "NV": 3}


def _curve_table(curves, curve_of):
    """(knots log N, knots log factor) per kind code, as (n_kinds, 3) arrays."""
    logn = np.array([[math.log(n) for n, _ in curves[curve_of[k]]] for k in KINDS])
    logy = np.array([[math.log(y) for _, y in curves[curve_of[k]]] for k in KINDS])
    return logn, logy


_PITTING_TABLE = _curve_table(_PITTING_CURVES, _PITTING_CURVE_OF)
_BENDING_TABLE = _curve_table(_BENDING_CURVES, _BENDING_CURVE_OF)


def _life(cycles, code, table):
    """The curve of ``table`` at ``cycles``: linear in log-log between the knots, constant
    outside them (one material group: ``np.interp``; groups per row: the same by branches)."""
    logn, logy = table
    if isinstance(code, int | np.integer):
        if type(cycles) is float or type(cycles) is np.float64:  # one number: no array
            y = math.exp(SCALAR.interp(math.log(max(cycles, 1.0)), *_KNOTS[id(table)][code]))
            # one pair on Python floats gets a Python float, a numpy number a numpy number
            return y if type(cycles) is float and type(code) is int else np.float64(y)
        n = np.log(np.maximum(cycles, 1.0))
        out = np.exp(np.interp(n, logn[code], logy[code]))
        return out[()] if np.ndim(out) == 0 else out
    code = np.asarray(code)
    n = np.log(np.maximum(np.asarray(cycles, float), 1.0))
    k0, k1, k2 = (logn[code, i] for i in range(3))
    y0, y1, y2 = (logy[code, i] for i in range(3))
    first = y0 + (y1 - y0) * (n - k0) / (k1 - k0)
    second = y1 + (y2 - y1) * (n - k1) / (k2 - k1)
    out = np.where(n <= k0, y0, np.where(n <= k1, first, np.where(n <= k2, second, y2)))
    out = np.exp(out)
    return out[()] if out.ndim == 0 else out


# the same knots as Python floats, per table and code (gears.namespace.SCALAR.interp)
_KNOTS = {
    id(t): [(tuple(t[0][c].tolist()), tuple(t[1][c].tolist())) for c in range(len(KINDS))]
    for t in (_PITTING_TABLE, _BENDING_TABLE)
}


def _code(kind):
    """The material group's integer code from its name or code (or an array of codes)."""
    if type(kind) is int or isinstance(kind, np.integer):
        return kind
    return kind if np.issubdtype(np.asarray(kind).dtype, np.integer) else kind_code(kind)


def pitting_life_factor(cycles, kind):
    """Life factor Z_NT at ``cycles`` load cycles (ISO 6336-2 Table 2; arrays broadcast).

    ``kind`` is a material group name or its integer code
    (:func:`gears.rating.materials.kind_code`).

    >>> round(float(pitting_life_factor(1.783e8, "Eh")), 3)   # ISO/TR 6336-30 Ex. 1: 0.962
    0.962
    """
    return _life(cycles, _code(kind), _PITTING_TABLE)


def bending_life_factor(cycles, kind):
    """Life factor Y_NT at ``cycles`` load cycles (ISO 6336-3 Table 3; arrays broadcast).

    >>> float(bending_life_factor(3e6, "Eh")), float(bending_life_factor(1e3, "Eh"))
    (1.0, 2.5)
    """
    return _life(cycles, _code(kind), _BENDING_TABLE)
