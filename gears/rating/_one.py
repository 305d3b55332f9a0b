"""Layer 2, load capacity: one pair's kept rating, its key and its Python numbers (private).

Private to the rating family. One pair of plain arguments keeps its checked arguments and its
gears' part (:mod:`gears.rating.iso6336`) by a :class:`Key` of its arguments
(:func:`plain_key`), and computes on Python floats (:data:`gears.namespace.SCALAR`): its
checked numbers become Python numbers (:func:`plain_numbers`, :func:`plain_or_array`).
"""

from __future__ import annotations

import numpy as np

from gears.rating.materials import Material

#: the types of one number of one pair (Python's and numpy's)
PLAIN = frozenset({int, float, bool, type(None), np.float64, np.int64, np.bool_})
_KEYED = PLAIN | {str, Material}
_PYTHON_NUMBERS = frozenset({float, int, bool})


def plain_numbers(a: dict) -> dict:
    """One pair's checked arguments as Python floats and bools, which its formulas compute on
    through ``math`` (:data:`gears.namespace.SCALAR`); arrays stay arrays."""
    if _PYTHON_NUMBERS.issuperset(map(type, a.values())):
        return a  # the usual case: checked as Python numbers already
    out = {}
    for k, v in a.items():
        t = type(v)
        if t is np.float64:
            v = float(v)
        elif t is np.ndarray and v.ndim == 0:
            v = v.item()
        elif t is np.bool_:
            v = bool(v)
        out[k] = v
    return out


def plain_key(args, skip):
    """The :class:`Key` of one pair's arguments but those named in ``skip``, typed, when they are
    plain numbers, names, materials and tuples of them (else None): one flat tuple, each value
    after its type (a tuple's or a dict's after its type and length), so that 1, 1.0 and True
    differ."""
    key = []
    add = key.append

    def put(v):
        t = type(v)
        if t in _KEYED:
            add(t)
            add(v)
        elif t is tuple or t is list or isinstance(v, tuple):
            add(t)
            add(len(v))
            for x in v:
                tx = type(x)
                if tx in _KEYED:
                    add(tx)
                    add(x)
                else:
                    put(x)
        elif t is dict:
            add(dict)
            add(len(v))
            for k in sorted(v):
                add(k)
                put(v[k])
        elif t is np.ndarray and v.ndim == 0:
            add(v.dtype.str)
            add(v.item())
        else:
            raise TypeError  # an array or another object: not kept

    try:
        for k, v in args.items():
            if k in skip:  # the load's, and what the others fix
                continue
            t = type(v)
            if t in _KEYED:  # most are: no call
                add(t)
                add(v)
            else:
                put(v)
        return Key(tuple(key))
    except TypeError:
        return None


class Key:
    """A key of kept parts, its hash computed once (it holds two materials, whose hash is a
    dataclass's: five look-ups a rating)."""

    __slots__ = ("hash", "values")

    def __init__(self, values: tuple):
        self.values = values
        self.hash = hash(values)

    def __hash__(self) -> int:
        return self.hash

    def __eq__(self, other) -> bool:
        return type(other) is Key and self.hash == other.hash and self.values == other.values


def plain_or_array(value):
    """One number as a Python float, else an array."""
    if type(value) is np.float64 or type(value) is float:
        return float(value)
    value = np.asarray(value)
    return float(value) if value.ndim == 0 else value
