"""Layer 1, base: the rating family's array helpers and its one check of a number.

Private to the rating family. ``where`` and ``out`` keep one pair's numbers numpy scalars
(rating one pair is mostly their cost); ``number`` checks a value or an array against its range
and names the first bad entry; ``pair_of`` splits a per-gear value; ``reducer`` checks what a
reduced rating is handed.
"""

from __future__ import annotations

import inspect
import math

import numpy as np

from gears.errors import GearError


def out(a):
    """``a`` as an array, or its one number where it has no dimension."""
    if type(a) is np.float64 or type(a) is float:  # one pair's number already
        return a
    a = np.asarray(a)
    return a[()] if a.ndim == 0 else a


_NUMBERS = frozenset({float, int, bool, np.float64, np.bool_, np.int64})


def scalar(v) -> bool:
    """Whether ``v`` is one number (``np.ndim(v) == 0`` without its cost on numbers)."""
    t = type(v)
    if t in _NUMBERS:
        return True
    if t is np.ndarray:
        return v.ndim == 0
    return isinstance(v, (float, int, np.generic)) or np.ndim(v) == 0


def where(cond, a, b):
    """``np.where`` that keeps one pair's numbers numpy scalars (a Python branch: ten times
    faster than 0-d arrays, which is most of rating one pair)."""
    if type(cond) in _NUMBERS and type(a) in _NUMBERS and type(b) in _NUMBERS:
        return a if cond else b  # the usual numbers, without a call per argument
    if scalar(cond) and scalar(a) and scalar(b):
        return a if cond else b
    return np.where(cond, a, b)


def number(name, value, low, high, low_open=True, high_open=True, integer=False, plain=False):
    """``value`` as a float array, or a GearError naming the first bad entry and the range; a
    Python number stays a Python float with ``plain`` (one pair's rating computes on those,
    :data:`gears.namespace.SCALAR`), else it becomes a numpy float."""
    if type(value) is float or type(value) is int:  # the one-pair path: no array needed
        try:
            v = float(value)
        except OverflowError:  # an int beyond the range of floats (10**400)
            raise GearError(
                f"{name} = {shown(value)}; valid is {_range(name, low, high, low_open, high_open)}"
            ) from None
        if (
            math.isfinite(v) and (v > low if low_open else v >= low)
            and (v < high if high_open else v <= high) and (not integer or v == round(v))
        ):  # fmt: skip
            return v if plain else np.float64(v)
    if isinstance(value, str | bytes | bool | np.bool_):
        raise GearError(f"{name} = {value!r}; valid is a number")
    try:
        a = np.asarray(value, float)
    except (TypeError, ValueError, OverflowError):
        raise GearError(
            f"{name} = {shown(value)}; valid is a number in floating-point range"
        ) from None
    if a.dtype == object or np.asarray(value).dtype.kind in "USb":
        raise GearError(f"{name} = {value!r}; valid is a number")
    ok = np.isfinite(a) & ((a > low) if low_open else (a >= low))
    ok &= (a < high) if high_open else (a <= high)
    if integer:
        ok &= a == np.round(a)
    if not np.all(ok):
        bad = np.ravel(a)[np.argmax(~np.ravel(ok))]
        at = "" if a.ndim == 0 else f" at row {int(np.argmax(~np.ravel(ok)))}"
        kind = "an integer " if integer else ""
        valid = _range(name, low, high, low_open, high_open)
        raise GearError(f"{name} = {float(bad):g}{at}; valid is {kind}{valid}")
    return a


def _range(name, low, high, low_open, high_open) -> str:
    return f"{low:g} {'<' if low_open else '<='} {name} {'<' if high_open else '<='} {high:g}"


def shown(value) -> str:
    """A value for a message: a huge int by its magnitude, not its 400 digits."""
    if isinstance(value, int) and abs(value) > 10**20:
        return f"{'-' if value < 0 else ''}10^{int(abs(value).bit_length() * 0.30103)} (about)"
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def one_number(name, value):
    """``value`` when it is one real number (a rating of one pair), else a GearError naming it:
    arrays go to :func:`gears.rating.iso6336.rate_pairs`."""
    if isinstance(value, str | bytes | bool | np.bool_) or not (
        isinstance(value, int | float | np.integer | np.floating)
        or (isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind in "iuf")
    ):
        raise GearError(
            f"{name} = {shown(value)}; valid is one number (rate many pairs with gears.rate_pairs)"
        )
    return value


def pair_of(name, value):
    """A per-gear value: a scalar/array for both gears or a pair ``(gear 1, gear 2)``."""
    if isinstance(value, tuple | list) and len(value) == 2:
        return value[0], value[1]
    if isinstance(value, tuple | list):
        raise GearError(f"{name} = {value!r}; give one value or a pair (gear 1, gear 2)")
    return value, value


#: the public name of each checked argument of the array route (their keys are ISO symbols), for
#: the message of arrays that do not broadcast together
PUBLIC = {"T": "torque", "n": "speed", "K_A": "application_factor", "K_gamma": "load_sharing",
          "b": "face_width", "Q": "quality", "Ra": "roughness", "Ra_root": "root_roughness",
          "nu40": "oil_viscosity", "C_a": "tip_relief", "F_bx": "misalignment"} | {
    f"{k}{i}": f"{name}[{i - 1}]"
    for k, name in (("c", "contacts"), ("idler", "idler"), ("k", "tip_alteration"),
                    ("hf", "dedendum"), ("rho", "root_radius"), ("spr", "protuberance"),
                    ("sH", "sigma_Hlim"), ("sF", "sigma_Flim"))
    for i in (1, 2)
}  # fmt: skip


def public_name(key: str) -> str:
    """The public name of the array route's argument ``key`` (:data:`PUBLIC`); a given factor's
    ``o_K_A`` is ``factors["K_A"]``, a per-gear one's ``o_Y_X1`` ``factors["Y_X"][0]``."""
    if not key.startswith("o_"):
        return PUBLIC.get(key, key)
    name = key[2:].replace("_prime", "'")  # no factor's symbol ends in a digit but a gear's
    return f'factors["{name[:-1]}"][{int(name[-1]) - 1}]' if name[-1] in "12" else (
        f'factors["{name}"]')  # fmt: skip


def reducer(reduce, chunk, arguments: dict, function) -> int:
    """``chunk`` of :func:`gears.rating.iso6336.rate_reduced`, checked with the rest: ``reduce``
    a callable, ``chunk`` an integer >= 1, ``arguments`` those of ``function`` by name (none
    unknown, none missing); else a GearError naming the first that is not."""
    if not callable(reduce):
        raise GearError(f"reduce = {reduce!r}; valid is a callable reduce(q, i0, i1)")
    if not (type(chunk) is int or isinstance(chunk, np.integer)) or chunk < 1:
        raise GearError(f"chunk = {chunk!r}; valid is an integer >= 1 (ratings a block)")
    params = inspect.signature(function).parameters
    unknown = [k for k in arguments if k not in params]
    missing = [k for k, v in params.items() if v.default is v.empty and k not in arguments]
    if unknown or missing:
        what = f"{unknown[0]} is not an argument" if unknown else f"{missing[0]} is missing"
        raise GearError(f"{what}; valid are the arguments of {function.__name__} by name: "
                        f"{', '.join(params)}")  # fmt: skip
    return int(chunk)
