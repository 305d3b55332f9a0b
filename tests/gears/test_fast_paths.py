"""Accuracy of the speed paths: the inverse-involute fast path and the threaded, chunked
pair_geometry, each against an independent slow route (issue 2, standards.md §2 and §5)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from gears import involute
from gears.involute import inv, inv_inverse
from gears.meshing import _PARALLEL_MIN, pair_geometry


def test_fast_inverse_round_trips_through_the_series_inv():
    # independent route: the forward inv (Taylor series below 0.25 rad, so no cancellation;
    # standards.md §2.1) applied to the fast-path angle. Relative angle error = residual / (inv'
    # alpha) = (inv(a) - y) / (tan^2 a * a).
    a_true = np.concatenate([np.geomspace(1e-6, 0.3, 2000), np.linspace(0.3, 0.97, 4000)])
    y = inv(a_true)
    assert y.max() <= involute._FAST_MAX  # all on the fast path
    a = inv_inverse(y)
    rel = np.abs(a - a_true) / a_true
    assert rel.max() < 1e-13
    # and the fast path is what ran: it agrees with the private fast function bit for bit
    np.testing.assert_array_equal(a, involute._inv_inverse_fast(y))


def test_fast_and_slow_paths_meet_at_the_switch():
    # just below and above _FAST_MAX the two methods must agree to 1e-14 (standards.md §2.2)
    y = np.array([involute._FAST_MAX * (1 - 1e-12), involute._FAST_MAX * (1 + 1e-12)])
    a = inv_inverse(y)
    assert abs(a[1] - a[0]) / a[0] < 1e-11
    assert inv(a[0]) == pytest.approx(y[0], rel=1e-14)
    assert inv(a[1]) == pytest.approx(y[1], rel=1e-14)


def _scalar_reference(z1, z2, m, x1, x2, an_deg=20.0):
    """One external spur pair by the textbook formulas in plain floats (standards.md §1.2,
    §1.3, §1.5), the inverse involute by brentq: an independent slow route."""
    an = math.radians(an_deg)
    y_inv = 2 * math.tan(an) * (x1 + x2) / (z1 + z2) + (math.tan(an) - an)
    awt = brentq(lambda t: math.tan(t) - t - y_inv, 1e-9, 1.5, xtol=1e-16, rtol=1e-15)
    a = (z1 + z2) * m / 2 * math.cos(an) / math.cos(awt)
    y = (a - (z1 + z2) * m / 2) / m
    k = min(y - (x1 + x2), 0.0)
    ra1 = (z1 * m + 2 * m * (1 + x1 + k)) / 2
    ra2 = (z2 * m + 2 * m * (1 + x2 + k)) / 2
    rb1, rb2 = z1 * m * math.cos(an) / 2, z2 * m * math.cos(an) / 2
    eps = (math.sqrt(ra1**2 - rb1**2) + math.sqrt(ra2**2 - rb2**2) - a * math.sin(awt)) / (
        math.pi * m * math.cos(an)
    )
    return math.degrees(awt), a, 2 * ra1, 2 * ra2, eps


@pytest.fixture(scope="module")
def many():
    rng = np.random.default_rng(7)
    n = 2 * _PARALLEL_MIN + 1001  # large enough to take the threaded path
    z1 = rng.integers(10, 150, n).astype(float)
    z2 = rng.integers(10, 150, n).astype(float)
    x1 = rng.uniform(-0.1, 1.0, n)
    x2 = rng.uniform(-0.1, 1.0, n)
    m = rng.uniform(0.3, 20.0, n)
    return z1, z2, m, x1, x2, pair_geometry(z1, z2, m, x1, x2)


def test_threaded_pair_geometry_matches_plain_float_reference(many):
    z1, z2, m, x1, x2, g = many
    for i in np.linspace(0, len(z1) - 1, 200).astype(int):
        ref = _scalar_reference(z1[i], z2[i], m[i], x1[i], x2[i])
        got = (
            g.working_pressure_angle[i], g.center_distance[i], g.tip_diameter_1[i],
            g.tip_diameter_2[i], g.contact_ratio[i],
        )  # fmt: skip
        for r, v in zip(ref, got, strict=True):
            assert v == pytest.approx(r, rel=1e-12, abs=1e-12), i


def test_threaded_pair_geometry_equals_one_element_calls(many):
    z1, z2, m, x1, x2, g = many
    for i in np.linspace(0, len(z1) - 1, 50).astype(int):
        one = pair_geometry(z1[i], z2[i], m[i], x1[i], x2[i])
        for field, value in zip(g, one, strict=True):
            # the same formulas per element; numpy's SIMD loops over a long array and its scalar
            # loop over one element may round the last bit differently, hence 1e-13 relative
            assert field[i] == pytest.approx(value, rel=1e-13, abs=1e-13)


def test_threaded_pair_geometry_mixed_internal_and_helical_broadcasts():
    rng = np.random.default_rng(11)
    n = 2 * _PARALLEL_MIN + 17
    internal = rng.random(n) < 0.3
    z1 = rng.integers(12, 30, n)
    z2 = np.where(internal, z1 + rng.integers(30, 80, n), rng.integers(12, 80, n))
    beta = rng.uniform(-30, 30, (1, n))  # broadcasts against (n,) -> shape (1, n)
    g = pair_geometry(z1, z2, 2.0, 0.1, 0.0, 20.0, beta, internal)
    assert g.center_distance.shape == (1, n)
    for i in (0, 5, n // 2, n - 1):
        one = pair_geometry(z1[i], z2[i], 2.0, 0.1, 0.0, 20.0, beta[0, i], internal[i])
        for field, value in zip(g, one, strict=True):
            assert field[0, i] == pytest.approx(value, rel=1e-13, abs=1e-13)  # as above


def test_threaded_pair_geometry_raises_the_gear_error():
    n = 2 * _PARALLEL_MIN + 5
    x = np.zeros(n)
    x[-1] = -5.0  # inv alpha_wt < 0 in the last chunk: no such pair (standards.md §1.2)
    with pytest.raises(involute.GearError, match=r"x1 \+ x2"):
        pair_geometry(12, 28, 1.0, x, x)
