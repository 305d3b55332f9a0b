"""Non-circular gears: the centrodes of a motion law (Ozols section 19-1, (19.1)-(19.5)), the
closed forms of the elliptical pair (Litvin), the closure of n-lobed pairs, the per-tooth checks,
and hypothesis sweeps of every entry point."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from gears import GearError, NonCircularPair
from gears.geometry import min_profile_shift
from gears.noncircular.centrode import (
    eccentric_radius,
    polar_curvature,
    pole_radii,
    pole_radius,
    rack_centrode,
)
from gears.noncircular.checks import equivalent_teeth, tooth_margins

SWEEP = settings(
    max_examples=40, deadline=None, derandomize=True, database=None,
    suppress_health_check=list(HealthCheck),
)  # fmt: skip


# --- (19.1)-(19.5) -------------------------------------------------------------------------------
def test_ozols_19_2_example():
    # Ozols (19.2), worked example: a = 100, omega1/omega2 = 2 (external) -> O1P = 33.33;
    # omega1/omega2 = 0.5 (internal) -> O1P = 200
    assert float(pole_radius(2.0, 100.0)) == pytest.approx(100 / 3, rel=1e-12)
    assert float(pole_radius(0.5, 100.0, "internal")) == pytest.approx(200.0, rel=1e-12)
    # (19.1): O1P/O2P = omega2/omega1, and O1P + O2P = a (external), |O2P - O1P| = a (internal)
    i = np.array([0.3, 0.5, 2.0, 7.0])
    r1, r2 = pole_radii(i, 100.0)
    assert np.allclose(r1 / r2, 1 / i, rtol=1e-12) and np.allclose(r1 + r2, 100.0, rtol=1e-12)
    r1, r2 = pole_radii(i, 100.0, "internal")
    assert np.allclose(np.abs(r2 - r1), 100.0, rtol=1e-12)


def test_rack_centrode_19_4():
    # Ozols (19.4), (19.5): O1P = v/omega = ds/dphi; a uniform law s = r phi gives the circle of
    # radius r rolling on a straight rack line at height r (the involute gear's rack, a limit case)
    phi = np.linspace(0, 2 * math.pi, 50)
    r1, curve = rack_centrode(30.0 * phi, np.full_like(phi, 30.0))
    assert np.allclose(r1, 30.0) and np.allclose(curve[:, 1], 30.0)
    assert np.allclose(curve[:, 0], 30.0 * phi)


def test_constant_ratio_gives_circles():
    # a constant ratio omega1/omega2 = 2 (gear 2, a circle, counts as 2 lobes of the law):
    # the centrodes are the pitch circles of (19.2), r1 = a/(1 + i) = 30 (limit case)
    p = NonCircularPair.from_ratio(2.0, 90.0)
    assert p.lobes == (1, 2)
    phi = np.linspace(0, 360, 13)
    assert np.allclose(p.radius1(phi), 30.0, rtol=1e-12)
    assert np.allclose(p.radius2(phi), 60.0, rtol=1e-12)
    assert np.allclose(p.output_angle(phi), phi / 2, rtol=1e-10)
    assert np.allclose(p.curvature(phi, 1), 1 / 30, rtol=1e-9)
    assert np.allclose(p.curvature(phi, 2), 1 / 60, rtol=1e-9)
    assert p.pitch_lengths[0] == pytest.approx(2 * math.pi * 30, rel=1e-10)
    assert p.pitch_lengths[1] == pytest.approx(2 * math.pi * 60, rel=1e-10)
    # gear 2 faster than gear 1 needs gear 1's period shortened: refused with the remedy
    with pytest.raises(GearError, match="turns gear 2 by 720 deg"):
        NonCircularPair.from_ratio(0.5, 90.0)
    assert NonCircularPair.from_ratio(0.5, 90.0, lobes=2).lobes == (2, 1)


# --- the elliptical pair: Litvin's closed forms ---------------------------------------------------
@pytest.mark.parametrize("e", [0.1, 0.3, 0.5])
def test_elliptical_pair_closed_forms(e):
    # Litvin, elliptical gears: r1 = A(1 - e^2)/(1 - e cos phi) from the focus, a = 2A, the
    # ratio between (1 - e)/(1 + e) and (1 + e)/(1 - e); the output angle integrates
    # (1 - e^2)/(1 - 2e cos phi + e^2) (Poisson's kernel): psi = 2 atan((1 + e)/(1 - e) tan(phi/2))
    big_a = 50.0
    p = NonCircularPair.elliptical(big_a, e)
    assert p.center_distance == pytest.approx(2 * big_a, rel=1e-12)
    assert p.lobes == (1, 1)
    phi = np.linspace(-170, 170, 35)
    t = np.radians(phi)
    assert np.allclose(p.radius1(phi), big_a * (1 - e * e) / (1 - e * np.cos(t)), rtol=1e-9)
    assert np.allclose(p.radius1(phi) + p.radius2(phi), 2 * big_a, rtol=1e-12)
    ratio = p.ratio(np.linspace(0, 360, 721))
    assert ratio.max() == pytest.approx((1 + e) / (1 - e), rel=1e-9)
    assert ratio.min() == pytest.approx((1 - e) / (1 + e), rel=1e-6)
    psi = 2 * np.degrees(np.arctan((1 + e) / (1 - e) * np.tan(t / 2)))
    assert np.allclose(p.output_angle(phi), psi, atol=1e-7)
    # both curves are the same ellipse: length 4 A E(e) (complete elliptic integral)
    from scipy.special import ellipe

    assert p.pitch_lengths[0] == pytest.approx(4 * big_a * ellipe(e * e), rel=1e-9)
    assert p.pitch_lengths[1] == pytest.approx(p.pitch_lengths[0], rel=1e-9)
    # an ellipse's curvature at the major vertex is A/b^2 (the spline's second derivative is
    # good to O(h^2): 1e-4 relative)
    b = big_a * math.sqrt(1 - e * e)
    assert float(p.curvature(0.0)) == pytest.approx(big_a / b**2, rel=1e-4)
    c1, _ = p.pitch_curves(360, phi=0.0)
    assert np.hypot(*c1.T).max() == pytest.approx(big_a * (1 + e), rel=1e-9)


def test_elliptical_curvature_matches_the_polar_formula():
    # independent route: the curvature of the parametric ellipse about its focus by finite
    # differences of its points, against polar_curvature of the spline
    p = NonCircularPair.elliptical(40.0, 0.4)
    t = np.radians(np.linspace(5, 355, 36))
    r = lambda x: 40 * (1 - 0.16) / (1 - 0.4 * np.cos(x))  # noqa: E731
    h = 1e-4
    k = polar_curvature(r(t), (r(t + h) - r(t - h)) / (2 * h),
                        (r(t + h) - 2 * r(t) + r(t - h)) / h**2)  # fmt: skip
    assert np.allclose(p.curvature(np.degrees(t)), k, rtol=1e-5)


# --- closure of n-lobed pairs --------------------------------------------------------------------
@pytest.mark.parametrize("lobes", [(1, 1), (2, 2), (1, 2), (2, 3), (3, 3)])
def test_lobed_pairs_close(lobes):
    # Litvin's closure condition: over one period of gear 1 (360/n1 deg) gear 2 turns 360/n2;
    # the two pitch curves roll without slipping, so their lengths per period agree (brute
    # force: the placed curves' polygon perimeters)
    p = NonCircularPair.lobed(40.0, 0.15, lobes)
    n1, n2 = lobes
    assert p.lobes == lobes
    assert float(p.output_angle(360 / n1)) == pytest.approx(360 / n2, abs=1e-9)
    assert float(p.output_angle(360)) == pytest.approx(360 * n1 / n2, abs=1e-8)
    c1, c2 = p.pitch_curves(20000)
    per1 = np.sum(np.hypot(*np.diff(np.vstack([c1, c1[:1]]), axis=0).T))
    per2 = np.sum(np.hypot(*np.diff(np.vstack([c2, c2[:1]]), axis=0).T))
    assert per1 / n1 == pytest.approx(per2 / n2, rel=1e-6)
    assert p.pitch_lengths[0] == pytest.approx(per1, rel=1e-6)
    # the (1, 1) oval is the elliptical pair: a = 2A
    if lobes == (1, 1):
        assert p.center_distance == pytest.approx(80.0, rel=1e-9)


def test_pitch_curves_touch_at_the_pole():
    # placed at any input angle, the pole (radius1 from O1 along O1O2) lies on both curves and
    # the curves are tangent there (brute force on the placed points)
    p = NonCircularPair.eccentric(40.0, 12.0, 2)
    for phi in (0.0, 37.0, 200.0):
        c1, c2 = p.pitch_curves(20000, phi)
        pole = np.array([float(p.radius1(phi)), 0.0])
        d1 = np.min(np.hypot(*(c1 - pole).T))
        d2 = np.min(np.hypot(*(c2 - pole).T))
        assert d1 < 0.02 and d2 < 0.02
        # no crossing: every point of curve 2 stays outside curve 1 (tangency, not overlap)
        from shapely import Point, Polygon

        inner = Polygon(c1)
        assert not any(inner.contains(Point(xy)) for xy in c2[::50])


def test_eccentric_circle_radius():
    # a circle of radius R about a point e off its centre: r(0) = R + e, r(180) = R - e,
    # r(90) = sqrt(R^2 - e^2) (Pythagoras)
    r = eccentric_radius(np.radians([0, 90, 180]), 40.0, 12.0)
    assert np.allclose(r, [52.0, math.sqrt(40**2 - 12**2), 28.0])
    p = NonCircularPair.eccentric(40.0, 12.0)
    assert float(p.radius1(90.0)) == pytest.approx(math.sqrt(40**2 - 12**2), rel=1e-9)
    # gear 1 is a circle: curvature 1/R everywhere
    assert np.allclose(p.curvature(np.linspace(0, 350, 36)), 1 / 40, rtol=1e-6)


def test_internal_pair():
    # internal: O1P = a/|1 - i|; a law with omega1/omega2 > 1 makes gear 2 the ring around
    # gear 1, and |O2P - O1P| = a at every angle (Ozols (19.1), (19.2))
    p = NonCircularPair.from_ratio(lambda d: 3.0 / (1 + 0.1 * np.cos(np.radians(d))), 50.0,
                                   kind="internal")  # fmt: skip
    assert p.lobes == (1, 3)
    phi = np.linspace(0, 360, 25)
    assert np.allclose(p.radius2(phi) - p.radius1(phi), 50.0, rtol=1e-12)


def test_output_law():
    # psi(phi) = phi + 0.2 sin(phi) rad (degrees: phi + 0.2 * 180/pi sin phi): the ratio is
    # 1/(1 + 0.2 cos phi) (its derivative)
    psi = lambda d: d + np.degrees(0.2 * np.sin(np.radians(d)))  # noqa: E731
    p = NonCircularPair.from_output(psi, 100.0)
    phi = np.linspace(0, 360, 37)
    assert np.allclose(p.ratio(phi), 1 / (1 + 0.2 * np.cos(np.radians(phi))), rtol=1e-7)
    assert np.allclose(p.output_angle(phi), psi(phi), atol=1e-6)
    assert np.allclose(p.output_speed(phi, 1), -0.2 * np.sin(np.radians(phi)), atol=1e-6)


# --- refusals -------------------------------------------------------------------------------------
def test_law_that_cannot_close_is_refused():
    # one period turns gear 2 by 360/1.5 deg: no whole number of lobes
    with pytest.raises(GearError, match=r"cannot close.*360/1\.5"):
        NonCircularPair.from_ratio(1.5, 100.0)
    with pytest.raises(GearError, match="omega1/omega2 > 0"):
        NonCircularPair.from_ratio(lambda d: np.cos(np.radians(d)), 100.0)
    with pytest.raises(GearError, match="not positive"):
        NonCircularPair.from_ratio(lambda d: 1 + 0.5 * np.cos(np.radians(d)), 100.0,
                                   kind="internal")  # fmt: skip
    with pytest.raises(GearError, match="turns backwards"):
        NonCircularPair.from_output(lambda d: d + 90 * np.sin(np.radians(d)), 100.0)
    with pytest.raises(GearError, match="eccentricity"):
        NonCircularPair.elliptical(50.0, 1.0)
    with pytest.raises(GearError, match="center_distance"):
        NonCircularPair.from_ratio(1.0, -1.0)


# --- per-tooth checks -----------------------------------------------------------------------------
def test_tooth_margins_match_the_circular_gear():
    # a curvature of 1/r is the circle of r: z_eq = 2 r/m and the undercut margin is the circular
    # gear's -x_min (ISO 21771, 17 teeth the limit at 20 deg with h_a* = 1)
    k = 1 / np.array([10.0, 17.0, 30.0])
    z = equivalent_teeth(1 / k, 2.0)
    assert np.allclose(z, [10, 17, 30])
    undercut, tip, conv = tooth_margins(k, 2.0)
    assert np.allclose(undercut, -min_profile_shift(z))
    assert undercut[0] < 0 < undercut[2] and abs(undercut[1]) < 0.03
    assert np.all(np.isfinite(tip)) and np.allclose(conv, k)


def test_check_finds_an_undercut_tooth():
    # a flat ellipse with a coarse module: the major vertex's radius of curvature b^2/A is small
    # against the module (z_eq = 2 b^2/(A m) < 17 teeth) and the report names it
    p = NonCircularPair.elliptical(30.0, 0.6, module=3.0)
    r = p.check()
    b2_over_a = 30 * (1 - 0.36)
    z_eq = 2 * b2_over_a / p.module
    assert z_eq < 17
    assert not r["gear1.undercut"].ok
    assert r["gear1.undercut"].margin == pytest.approx(-float(min_profile_shift(z_eq)), rel=1e-4)
    assert r["closure"].ok and r["gear1.convexity"].ok
    assert p.teeth[0] == round(p.pitch_lengths[0] / (math.pi * 3.0))


def test_check_finds_a_concave_pitch_curve():
    # a 3-lobed oval of large eccentricity is concave between its lobes (r r'' > r^2 + 2 r'^2)
    p = NonCircularPair.lobed(40.0, 0.4, (3, 3), module=1.0)
    r = p.check()
    assert not r["gear1.convexity"].ok and r["gear1.convexity"].margin < 0


# --- hypothesis sweeps ----------------------------------------------------------------------------
_finite = st.floats(allow_nan=True, allow_infinity=True, width=64)


@SWEEP
@given(a=_finite, e=_finite, m=st.one_of(st.none(), _finite))
def test_elliptical_sweep(a, e, m):
    try:
        p = NonCircularPair.elliptical(a, e, module=m)
    except GearError:
        return
    phi = np.linspace(0, 360, 9)
    for v in (p.radius1(phi), p.radius2(phi), p.output_angle(phi), p.curvature(phi, 2)):
        assert np.all(np.isfinite(v))
    r = p.check()
    assert all(math.isfinite(f.margin) for f in r.values())


@SWEEP
@given(
    c=st.floats(-3, 3), amp=st.floats(-2, 2), n=st.integers(-1, 5), kind=st.sampled_from(
        ["external", "internal", "bad"]), a=_finite,
)  # fmt: skip
def test_from_ratio_sweep(c, amp, n, kind, a):
    try:
        p = NonCircularPair.from_ratio(
            lambda d: c + amp * np.cos(np.radians(d)), a, lobes=n, kind=kind
        )
    except GearError:
        return
    phi = np.linspace(0, 720, 9)
    assert np.all(np.isfinite(p.radius1(phi))) and np.all(p.radius1(phi) > 0)
    assert np.all(np.isfinite(p.output_angle(phi)))


@settings(SWEEP, max_examples=15)
@given(
    e=st.floats(0, 0.95), n1=st.integers(0, 4), n2=st.integers(0, 4), m=st.floats(0.01, 20),
    samples=st.lists(st.floats(-5, 5), min_size=0, max_size=12),
)  # fmt: skip
def test_lobed_and_samples_sweep(e, n1, n2, m, samples):
    try:
        p = NonCircularPair.lobed(30.0, e, (n1, n2), module=m)
        assert all(math.isfinite(f.margin) for f in p.check().values())
    except GearError:
        pass
    try:
        p = NonCircularPair.from_ratio(samples, 50.0)
        assert np.all(np.isfinite(p.radius2(np.linspace(0, 360, 7))))
    except GearError:
        pass


@SWEEP
@given(
    amp=st.floats(-200, 200), n=st.integers(0, 4), a=st.floats(-10, 1e4),
    kind=st.sampled_from(["external", "internal"]),
    samples=st.lists(st.floats(-400, 400), min_size=0, max_size=8),
)  # fmt: skip
def test_from_output_sweep(amp, n, a, kind, samples):
    for psi in (lambda d: d + amp * np.sin(np.radians(d)), samples):
        try:
            p = NonCircularPair.from_output(psi, a, lobes=n, kind=kind)
        except GearError:
            continue
        phi = np.linspace(0, 360, 7)
        assert np.all(np.isfinite(p.output_speed(phi, 1))) and np.all(p.radius2(phi) > 0)


@SWEEP
@given(r=_finite, off=_finite, n2=st.integers(-1, 5), m=st.one_of(st.none(), _finite),
       land=_finite, samples=st.integers(-2, 100))  # fmt: skip
def test_eccentric_and_pitch_curve_sweep(r, off, n2, m, land, samples):
    try:
        p = NonCircularPair.eccentric(r, off, n2, module=m)
    except GearError:
        return
    try:
        report = p.check(land)
        assert all(math.isfinite(f.margin) for f in report.values())
    except GearError:
        pass
    try:
        c1, c2 = p.pitch_curves(samples)
        assert np.all(np.isfinite(c1)) and np.all(np.isfinite(c2))
    except GearError:
        pass
