"""gears.namespace: SCALAR gives numpy's answers on one Python float, and one pair's rating on
Python floats equals the same pair rated in an array (the same formulas, two namespaces)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import rate_pairs
from gears.namespace import SCALAR, all_plain, of
from gears.rating.iso6336 import PairRatings
from gears.rating.materials import MATERIALS

SPECIAL = [0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 2.0, -2.0, 1e-300, 1e300, math.inf, -math.inf,
           math.nan, 0.3, 7.25, -3.5]  # fmt: skip
ONE = ["sqrt", "cbrt", "cos", "sin", "tan", "arctan", "arccos", "arcsin", "radians", "degrees",
       "abs", "exp", "exp2", "log", "isnan", "isfinite"]  # fmt: skip
TWO = ["maximum", "minimum", "power", "arctan2"]


def _same(a, b):
    """Equal within 4e-16 relative (libm and numpy's loops may differ in the last bit), or
    both NaN."""
    a, b = float(a), float(b)
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return a == b or abs(a - b) <= 4e-16 * max(abs(a), abs(b))


def _numpy(name, *args):
    with np.errstate(all="ignore"):
        return getattr(np, name)(*(np.float64(a) for a in args))


def _scalar(name, *args):
    try:
        return getattr(SCALAR, name)(*args)
    except (ValueError, OverflowError, ZeroDivisionError) as e:  # the caller's fallback
        return e


@pytest.mark.parametrize("name", ONE)
def test_one_argument_functions_answer_as_numpy(name):
    # the reference is numpy itself on the same number (NaN outside the domain, inf on
    # overflow); where math raises instead (cos(inf)), the rating falls back to numpy
    for x in SPECIAL:
        got = _scalar(name, x)
        if isinstance(got, Exception):
            assert name in ("cos", "sin", "tan") and math.isinf(x)
            continue
        assert _same(got, _numpy(name, x)), (name, x, got)


@pytest.mark.parametrize("name", TWO)
def test_two_argument_functions_answer_as_numpy(name):
    for x in SPECIAL:
        for y in SPECIAL:
            if name == "power" and x == -math.inf:
                continue  # numpy's loops give NaN or 0 there, C's pow inf or 0; no rating has it
            got = _scalar(name, x, y)
            if isinstance(got, Exception):  # 0 ** -1, overflow: numpy's inf comes by fallback
                assert name == "power"
                continue
            assert _same(got, _numpy(name, x, y)), (name, x, y, got)


def test_clip_where_logical_not_and_interp_answer_as_numpy():
    knots, values = (1.0, 3.0, 10.0), (2.0, -1.0, 5.0)
    for x in SPECIAL:
        assert _same(SCALAR.clip(x, -1.0, 2.0), _numpy("clip", x, -1.0, 2.0))
        assert _same(SCALAR.interp(x, knots, values), np.interp(x, knots, values))
        assert SCALAR.logical_not(x > 0) == bool(np.logical_not(np.float64(x) > 0))
        assert _same(SCALAR.where(x > 0, 1.0, 2.0), np.where(np.float64(x) > 0, 1.0, 2.0))


def test_of_picks_math_for_python_numbers_only():
    assert of(1.0, 2, True) is SCALAR
    assert of(1.0, np.float64(2.0)) is np
    assert of(1.0, np.array([1.0])) is np
    assert of() is SCALAR and all_plain([1.0, 2]) and not all_plain([1.0, np.float64(2.0)])


# --- one pair on Python floats == the same pair in an array --------------------------------
PAIRS = st.fixed_dictionaries({
    "z1": st.integers(5, 60), "dz": st.integers(0, 150), "m": st.floats(0.3, 12),
    "b_per_m": st.floats(0.5, 40), "x1": st.floats(-0.6, 1.2), "x2": st.floats(-0.6, 1.2),
    "helix": st.sampled_from([0.0, 8.0, 15.8, 30.0, 44.0]), "pa": st.floats(12.0, 32.0),
    "internal": st.booleans(), "log_t": st.floats(-6, 6), "log_n": st.floats(-1, 5),
    "quality": st.integers(1, 12), "mat1": st.sampled_from(list(MATERIALS)),
    "mat2": st.sampled_from(list(MATERIALS)),
})  # fmt: skip


@settings(max_examples=150, deadline=None)
@given(PAIRS)
def test_one_pair_on_python_floats_equals_the_array_route(p):
    # independent route: the same formulas on numpy arrays (a block of two equal pairs),
    # every field of PairRatings to 1e-12 relative, rows without a rating alike
    z2 = p["z1"] + p["dz"] + (8 if p["internal"] else 0)
    kw = dict(x1=p["x1"], x2=p["x2"], helix_angle=p["helix"], pressure_angle=p["pa"],
              internal=p["internal"], quality=p["quality"], material=(p["mat1"], p["mat2"]),
              errors="mask")  # fmt: skip
    b, t, n = p["m"] * p["b_per_m"], 10.0 ** p["log_t"], 10.0 ** p["log_n"]
    try:
        one = rate_pairs(p["z1"], z2, p["m"], b, t, n, **kw)
    except ValueError as error:  # the same GearError on the array route
        with pytest.raises(type(error)):
            rate_pairs([p["z1"]] * 2, z2, p["m"], b, t, n, **kw)
        return
    rows = rate_pairs([p["z1"]] * 2, z2, p["m"], b, t, n, **kw)
    for name in PairRatings._fields:
        x, y = float(getattr(one, name)), float(getattr(rows, name)[0])
        assert _same(x, y) or x == pytest.approx(y, rel=1e-12), (name, x, y)


def test_a_pair_python_floats_cannot_rate_falls_back_to_numpy_alike():
    # an internal 11/21 pair whose tips do not reach: eps_alpha = 0, so Z_eps's eps_beta /
    # eps_alpha divides by zero on Python floats (ZeroDivisionError); the block runs again on
    # numpy numbers. Reference: the same pair in an array (numpy throughout), every field
    kw = dict(x1=-0.0526, x2=0.0384, pressure_angle=22.7, internal=True, quality=4,
              material=("nodular-cast-iron", "nitrided"), errors="mask")  # fmt: skip
    one = rate_pairs(11, 21, 4.13, 7.62, 0.0382, 693.5, **kw)
    rows = rate_pairs([11, 11], 21, 4.13, 7.62, 0.0382, 693.5, **kw)
    assert int(one.reason) == 1 and not bool(one.valid)  # eps_alpha < 1, masked
    for name in PairRatings._fields:
        x, y = float(getattr(one, name)), float(getattr(rows, name)[0])
        assert _same(x, y) or x == pytest.approx(y, rel=1e-12), (name, x, y)


# --- properties: any float, any mix of argument types ------------------------------------------
def _close(a, b):
    """Equal within 1e-15 relative (about 4 ulp: libm's and numpy's loops round differently;
    cbrt differs by up to 6e-16 over 60 000 random numbers), subnormals to 1e-300, or both
    NaN."""
    a, b = float(a), float(b)
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return a == b or abs(a - b) <= 1e-15 * max(abs(a), abs(b)) + 1e-300


ANY = st.floats(allow_nan=True, allow_infinity=True)


@settings(max_examples=200, deadline=None)
@given(x=ANY, y=ANY)
def test_property_scalar_is_numpy_on_any_float(x, y):
    # reference: numpy on the same numbers. Where math raises instead (an overflow, 0 ** -y,
    # cos of inf), numpy's answer is inf or NaN and the rating falls back to numpy: allowed
    # only there
    for name, args in [*((n, (x,)) for n in ONE), *((n, (x, y)) for n in TWO)]:
        if name == "power" and x == -math.inf:
            continue  # numpy's loops and C's pow differ there (see above); no rating has it
        want = _numpy(name, *args)
        got = _scalar(name, *args)
        if isinstance(got, Exception):
            assert not np.isfinite(want) or name in ("cos", "sin", "tan"), (name, args, got)
            continue
        assert _close(got, want), (name, args, got, float(want))
    assert _close(SCALAR.clip(x, -1.0, 2.0), _numpy("clip", x, -1.0, 2.0))
    assert _close(SCALAR.interp(x, (1.0, 3.0, 10.0), (2.0, -1.0, 5.0)),
                  np.interp(x, (1.0, 3.0, 10.0), (2.0, -1.0, 5.0)))  # fmt: skip


KINDS = st.sampled_from(["float", "int", "bool", "np.float64", "np.int64", "array"])


@settings(max_examples=100, deadline=None)
@given(kinds=st.lists(KINDS, max_size=6), v=st.floats(-1e6, 1e6))
def test_property_of_picks_math_exactly_for_python_numbers(kinds, v):
    # independent rule: SCALAR exactly when every argument's type is float, int or bool
    make = {"float": float, "int": lambda t: int(t), "bool": lambda t: t > 0,
            "np.float64": np.float64, "np.int64": lambda t: np.int64(int(t)),
            "array": lambda t: np.array([t])}  # fmt: skip
    values = [make[k](v) for k in kinds]
    plain = all(k in ("float", "int", "bool") for k in kinds)
    assert (of(*values) is SCALAR) == plain
    assert all_plain(values) == plain
