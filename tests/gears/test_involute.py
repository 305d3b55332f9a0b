"""gears.involute: the involute function and its inverse (radians).

Reference values come from an independent 60-digit computation in :mod:`decimal` (sin and cos
by their Taylor series, no floating point involved), the seed digests (Joldasbekov §5.1,
lecture digest §2.7) and standards.md §2 / §6 item 1.
"""

from decimal import Decimal, localcontext

import numpy as np
import pytest

from gears.errors import GearError
from gears.involute import INV_MAX, inv, inv_inverse, involute_polar, pressure_angle_at

_DIGITS = 60
_TINY = Decimal(10) ** -(_DIGITS + 10)


def _sin_cos(x: Decimal) -> tuple[Decimal, Decimal]:
    """sin and cos of 0 <= x < 1.6 by their Taylor series (independent of numpy/libm)."""
    x2 = x * x
    c, t, k = Decimal(0), Decimal(1), 0
    while abs(t) > _TINY:
        c += t
        k += 2
        t = -t * x2 / (k * (k - 1))
    s, t, k = Decimal(0), x, 1
    while abs(t) > _TINY:
        s += t
        k += 2
        t = -t * x2 / (k * (k - 1))
    return s, c


def _reference_pairs(alphas):
    """For each float angle a: (y, alpha_true) where y = float(inv(a)) computed in 60 digits,
    and alpha_true the exact root of inv(alpha) = y (first-order correction from a; the
    second-order term is ~1e-32 relative)."""
    out = []
    with localcontext() as ctx:
        ctx.prec = _DIGITS
        for a in alphas:
            ad = Decimal(float(a))
            s, c = _sin_cos(ad)
            tan = s / c
            y_exact = tan - ad
            y = float(y_exact)
            alpha_true = ad + (Decimal(y) - y_exact) / (tan * tan)
            out.append((a, y, y_exact, alpha_true))
    return out


# log-spaced below 1 deg, dense 1-69 deg, log-spaced towards 89.9 deg (standards.md §2.2 bands)
_ALPHAS = np.concatenate(
    [
        np.geomspace(1e-9, np.radians(1.0), 80),
        np.linspace(np.radians(1.0), np.radians(69.0), 200),
        np.pi / 2 - np.geomspace(np.radians(21.0), np.radians(0.1), 120),
    ]
)
_REF = _reference_pairs(_ALPHAS)


def test_inverse_accurate_to_1e12_over_full_range():
    # independent derivation: 60-digit Decimal reference (see _reference_pairs)
    ys = np.array([y for _, y, _, _ in _REF])
    assert ys.max() <= INV_MAX * (1 + 1e-15)
    got = inv_inverse(ys)  # vectorised call
    worst = max(
        abs((Decimal(float(g)) - at) / at) for g, (_, _, _, at) in zip(got, _REF, strict=True)
    )
    assert worst < Decimal("1e-12")


def test_inverse_scalar_equals_vector():
    ys = np.array([y for _, y, _, _ in _REF[::25]])
    # one implementation for both; numpy's scalar and SIMD array loops may differ in the last bit
    scalar = [float(inv_inverse(y)) for y in ys]
    np.testing.assert_allclose(scalar, inv_inverse(ys), rtol=1e-15, atol=0)


def test_forward_inv_has_no_cancellation_near_zero():
    # tan(a) - a would lose log10(3/a^2) digits (standards.md §2.1); the series must not
    worst = max(abs((Decimal(float(inv(a))) - ye) / ye) for a, _, ye, _ in _REF)
    assert worst < Decimal("1e-14")
    assert float(inv(1e-9)) == pytest.approx(1e-27 / 3, rel=1e-15)


def test_forward_inv_of_an_array_meets_the_same_reference():
    # one angle is evaluated on Python floats, an array by numpy's loops: both to 1e-14 of the
    # 60-digit reference (the scalar path is the one tested above)
    got = inv(_ALPHAS)
    worst = max(
        abs((Decimal(float(g)) - ye) / ye) for g, (_, _, ye, _) in zip(got, _REF, strict=True)
    )
    assert worst < Decimal("1e-14")


def test_inv_reference_values():
    # Joldasbekov digest §5.1: inv 20 deg = 0.0149043839, inv 15 deg = 0.0061498046
    assert float(inv(np.radians(20.0))) == pytest.approx(0.0149043839, abs=1e-10)
    assert float(inv(np.radians(15.0))) == pytest.approx(0.0061498046, abs=1e-10)
    # lecture digest §2.7: inv 20 deg = 0.014904383867
    assert float(inv(np.radians(20.0))) == pytest.approx(0.014904383867, abs=1e-12)


def test_round_trips():
    # standards.md §2.3 pytest ideas: invinv(inv(20 deg)) to 1e-15; inv(invinv(y)), y in 1e-15..1e8
    a20 = np.radians(20.0)
    assert float(inv_inverse(inv(a20))) == pytest.approx(a20, rel=2e-15)
    y = np.geomspace(1e-15, INV_MAX, 400)
    assert np.allclose(inv(inv_inverse(y)), y, rtol=1e-12, atol=0)
    # above inv(89.9 deg) the forward map amplifies one ulp of alpha by tan^2(alpha): allow that
    y = np.geomspace(INV_MAX, 1e8, 100)
    a = inv_inverse(y)
    assert np.all(np.abs(inv(a) - y) <= 4 * np.tan(a) ** 2 * np.spacing(a))
    a = np.linspace(1e-6, np.radians(89.9), 2000)
    assert np.allclose(inv_inverse(inv(a)), a, rtol=1e-12, atol=0)


def test_limits_zero_and_infinity():
    # standards.md §2.3: y = 0 -> 0, y = inf -> pi/2
    assert float(inv_inverse(0.0)) == pytest.approx(0.0, abs=1e-300)
    assert float(inv_inverse(np.inf)) == pytest.approx(np.pi / 2, rel=1e-15)
    ends = inv_inverse([0.0, 1e-300, np.inf])[::2]
    np.testing.assert_allclose(ends, [0.0, np.pi / 2], rtol=1e-15, atol=1e-300)
    assert 0 < float(inv_inverse(1e-300)) < 1e-99
    assert float(inv_inverse(1e15)) < np.pi / 2


@pytest.mark.parametrize("bad", [-1e-300, -0.01, -np.inf, np.nan, [0.1, -1.0], [np.nan, 0.2]])
def test_negative_or_nan_raises(bad):
    # DESIGN.md: nothing returns NaN silently; the message names the offending value
    with pytest.raises(GearError, match="inv"):
        inv_inverse(bad)


def test_monotonic():
    y = np.concatenate([[0.0], np.geomspace(1e-20, 1e6, 5000)])
    a = inv_inverse(y)
    assert np.all(np.diff(a) > 0)
    assert np.all((a >= 0) & (a < np.pi / 2))


def test_pressure_angle_and_polar():
    # Joldasbekov (6.15): r_x = r0 / cos alpha_x; (6.16): theta_x = inv alpha_x
    rb = 10.0
    r = rb / np.cos(np.radians(20.0))
    assert float(pressure_angle_at(rb, r)) == pytest.approx(np.radians(20.0), rel=1e-14)
    assert float(involute_polar(rb, r)) == pytest.approx(0.0149043839, abs=1e-10)
    assert float(pressure_angle_at(rb, rb)) == pytest.approx(0.0, abs=1e-15)
    with pytest.raises(GearError, match="base circle"):
        pressure_angle_at(rb, rb * 0.99)
