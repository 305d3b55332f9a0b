"""Non-circular teeth cut by a rolled rack, the geometric transmission error of any two outlines
and conjugate profiles (Ozols 19-2), with hypothesis sweeps of every entry point."""

from __future__ import annotations

import math

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from shapely import affinity

from gears import Gear, GearError, GearPair, NonCircularPair, conjugate, transmission_error
from gears.noncircular.conjugate import normal_miss
from gears.noncircular.teeth import RackCutter, rack_tooth

SWEEP = settings(
    max_examples=25, deadline=None, derandomize=True, database=None,
    suppress_health_check=list(HealthCheck),
)  # fmt: skip


@pytest.fixture(scope="module")
def ellipses():
    # Litvin's elliptical pair, A = 40, e = 0.2, cut at module 2 (40 teeth fitted to the ellipse)
    p = NonCircularPair.elliptical(40.0, 0.2, module=2.0)
    return p, p.outlines(0.0, 0.02)


@pytest.fixture(scope="module")
def involutes():
    # the library's own involute pair at zero backlash, analytic outlines to 0.001 mm
    pair = GearPair(Gear(20, 2), Gear(40, 2))
    return pair, pair.outlines(angle=0.0, tolerance=0.001)


# --- the rack rolled along the pitch curve -------------------------------------------------------
def test_rack_tooth_is_the_basic_rack():
    # ISO 53 A: tooth thickness p/2 at the pitch line, flanks at 20 deg, tip at -1.25 m
    c = RackCutter(2.0)
    t = rack_tooth(c, 0.001)
    right = t[t[:, 0] > 0]
    right = right[np.argsort(right[:, 1])]

    def width_at(v):
        return np.interp(v, right[:, 1], right[:, 0])

    assert 2 * width_at(0.0) == pytest.approx(math.pi, rel=1e-9)
    assert 2 * width_at(1.0) == pytest.approx(math.pi + 2 * math.tan(math.radians(20)), rel=1e-9)
    assert t[:, 1].min() == pytest.approx(-2.5, rel=1e-12)


def test_generated_teeth_follow_the_law(ellipses):
    # the generated teeth's transmission error against the prescribed law stays within the
    # tolerance asked (both gears are conjugate to one rack: Litvin's generation of elliptical
    # gears); measured as the arc at gear 2's pitch curve over a turn of gear 1
    p, (one, two) = ellipses
    phi = np.linspace(0.0, 360.0, 37)
    te = transmission_error(one, two, ((0, 0), (p.center_distance, 0)), phi, p.output_angle)
    arc = np.abs(np.radians(te)) * p.radius2(phi)
    assert arc.max() < 0.02
    # the tooth count is whole and the teeth are there: 40 teeth at 360/40 deg intervals of arc
    assert p.teeth == (40, 40)
    assert len(one.interiors) == 0 and one.is_valid and two.is_valid


def test_generated_pair_does_not_overlap_and_does_after_a_turn(ellipses):
    # a machinist's check: in mesh the outlines touch without overlap (to the tolerance), and a
    # small extra turn of gear 2 against gear 1 makes them overlap
    p, (one, two) = ellipses
    for phi in (0.0, 50.0, 170.0):
        psi = float(p.output_angle(phi))
        a = affinity.rotate(one, phi, origin=(0, 0))
        b = affinity.rotate(two, -psi, origin=(p.center_distance, 0))
        assert a.intersection(b).area < 0.02 * p.module
        b2 = affinity.rotate(two, -psi + 0.5, origin=(p.center_distance, 0))
        assert a.intersection(b2).area > 0.05


def test_tooth_thickness_on_the_pitch_curve(ellipses):
    # the rack's tooth is p/2 thick on its pitch line, so the generated space is p/2 along the
    # pitch curve: half the pitch curve's length lies inside the teeth (brute force)
    p, (one, _) = ellipses
    c1, _ = p.pitch_curves(20000)
    curve = shapely.LineString(np.vstack([c1, c1[:1]]))
    inside = curve.intersection(one).length
    assert inside / curve.length == pytest.approx(0.5, abs=0.01)


def test_scene_is_two_watertight_prisms(ellipses):
    # each gear extruded over 6 mm: watertight, volume = outline area x face width
    p, (one, two) = ellipses
    scene = p.scene(0.0, 6.0, 0.02)
    solids = list(scene.geometry.values())
    assert len(solids) == 2 and all(s.is_watertight for s in solids)
    assert sorted(s.volume for s in solids) == pytest.approx(
        sorted([one.area * 6.0, two.area * 6.0]), rel=1e-6
    )


# --- transmission error of any two outlines ------------------------------------------------------
def test_involute_pair_has_zero_transmission_error(involutes):
    # the library's involute pair at zero backlash: zero to the outline tolerance (0.001 mm)
    _pair, (one, two) = involutes
    phi = np.linspace(0.0, 18.0, 7)
    te = transmission_error(one, two, ((0, 0), (60.0, 0)), phi, 2.0)
    assert np.all(np.abs(np.radians(te) * 40.0) <= 0.001)


def test_backlash_shows_as_half_the_circular_backlash():
    # each gear thinned by half of j_n: the driven gear lags by half the circular backlash
    # j_t = j_n / cos(alpha) at the pitch circle (ISO 21771 backlash, independent derivation)
    pair = GearPair(Gear(20, 2), Gear(40, 2))
    one, two = pair.outlines(angle=0.0, tolerance=0.001, backlash=0.1)
    te = transmission_error(one, two, ((0, 0), (60.0, 0)), [0.0, 5.0], 2.0)
    lag = -np.radians(te) * 40.0
    assert np.allclose(lag, 0.05 / math.cos(math.radians(20)), atol=0.0015)


def test_transmission_error_sees_a_wrong_ratio(involutes):
    # the same outlines against a law 1 % off: the error grows with the angle
    _, (one, two) = involutes
    te = transmission_error(one, two, ((0, 0), (60.0, 0)), [0.0, 9.0], 2.0 * 1.01)
    assert abs(te[1] - te[0]) == pytest.approx(9.0 / 2.0 - 9.0 / 2.02, rel=0.05)


# --- conjugate profiles --------------------------------------------------------------------------
def test_conjugate_of_an_involute_is_the_librarys_involute(involutes):
    # Ozols 19-2 (inversion): the envelope on gear 2 of gear 1's involute flank (as drawn by the
    # library) lies on gear 2's involute outline within the outline tolerance
    pair, (one, two) = involutes
    xy = np.asarray(one.exterior.coords)
    r = np.hypot(*xy.T)
    th = np.degrees(np.arctan2(xy[:, 1], xy[:, 0]))
    sel = (r > pair.g1.base_diameter / 2 + 0.3) & (r < pair.g1.tip_diameter / 2 - 0.05)
    sel &= np.abs(th) < 12
    idx = np.where(sel)[0]
    for run in np.split(idx, np.where(np.diff(idx) != 1)[0] + 1):
        pts, phi, miss, index = conjugate(xy[run], 60.0, 2.0)
        assert index.size == run.size  # every flank point passes the pole within +-120 deg
        rr = np.hypot(pts[:, 0] - 60, pts[:, 1])
        active = (rr < pair.g2.tip_diameter / 2 - 0.01) & (rr > pair.g2.base_diameter / 2 + 0.3)
        assert active.sum() >= 8
        assert shapely.distance(two.exterior, shapely.points(pts[active])).max() < 0.001
        assert miss.max() < 1e-9
        assert np.all(np.abs(phi[active]) < 20)


def test_normal_miss():
    # the normal through (0, 1) along +x misses the point (3, 0) by 1 (geometry)
    assert float(normal_miss([0.0, 1.0], [1.0, 0.0], [3.0, 0.0])) == pytest.approx(1.0)
    assert float(normal_miss([0.0, 1.0], [3.0, -1.0], [3.0, 0.0])) == pytest.approx(0.0, abs=1e-15)


# --- refusals and sweeps --------------------------------------------------------------------------
def test_refusals():
    with pytest.raises(GearError, match="no module"):
        NonCircularPair.elliptical(40.0, 0.2).outline()
    with pytest.raises(GearError, match="outline1"):
        transmission_error("square", shapely.box(0, 0, 1, 1), ((0, 0), (1, 0)), [0.0], 1.0)
    with pytest.raises(GearError, match="centers"):
        transmission_error(shapely.box(0, 0, 1, 1), shapely.box(0, 0, 1, 1), (0, 0), [0.0], 1.0)
    with pytest.raises(GearError, match="do not mesh"):
        transmission_error(shapely.box(-1, -1, 1, 1), shapely.box(9, -1, 11, 1),
                           ((0, 0), (10, 0)), [0.0], 1.0)  # fmt: skip
    with pytest.raises(GearError, match="internal"):
        NonCircularPair.from_ratio(lambda d: 3.0 / (1 + 0.1 * np.cos(np.radians(d))), 50.0,
                                   kind="internal", module=1.0).outline()  # fmt: skip


_any = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-5, 5),
                 st.text(max_size=2), st.none())  # fmt: skip


@SWEEP
@given(phi=st.lists(_any, max_size=3), out=_any, cx=_any, kind=st.sampled_from(["external", "x"]))
def test_transmission_error_sweep(phi, out, cx, kind):
    one, two = shapely.box(-1, -1, 1, 1), affinity.rotate(shapely.box(1.2, -1, 3.2, 1), 10)
    try:
        te = transmission_error(one, two, ((0, 0), (cx, 0)), phi, out, kind=kind)
    except GearError:
        return
    assert np.all(np.isfinite(te))


@SWEEP
@given(out=_any, a=_any, pts=st.lists(st.tuples(st.floats(-50, 50), st.floats(-50, 50)),
                                       max_size=6))  # fmt: skip
def test_conjugate_sweep(out, a, pts):
    try:
        found = conjugate(np.array(pts, dtype=float).reshape(-1, 2), a, out, steps=50)
    except GearError:
        return
    for v in found:
        assert np.all(np.isfinite(v))


@settings(max_examples=4, deadline=None, derandomize=True, database=None,
          suppress_health_check=list(HealthCheck))  # fmt: skip
@given(e=st.floats(0.0, 0.5), m=st.floats(1.5, 6.0), tol=st.sampled_from([0.05, 1e-9, -1.0]))
def test_outline_sweep(e, m, tol):
    try:
        poly = NonCircularPair.elliptical(30.0, e, module=m).outline(2, tol)
    except GearError:
        return
    assert poly.is_valid and poly.area > 0


def test_animation_is_written(ellipses, tmp_path):
    # a few frames of the pair turning: a GIF with that many frames (Pillow reads it back)
    from PIL import Image

    p, _ = ellipses
    path = p.animate(tmp_path / "pair.gif", frames=2, tolerance=0.02)
    with Image.open(path) as im:
        assert im.n_frames == 2
    with pytest.raises(GearError, match="frames"):
        p.animate(tmp_path / "pair.gif", frames=0)


@SWEEP
@given(angle=_any, width=_any, tol=_any)
def test_scene_and_outlines_sweep(angle, width, tol):
    # bad arguments are refused before the work; the coarse pair's outlines are cached
    p = NonCircularPair.elliptical(20.0, 0.2, module=3.0)
    try:
        one, two = p.outlines(angle, tol)
    except GearError:
        return
    assert one.is_valid and two.is_valid
    try:
        s = p.scene(angle, width, tol)
    except GearError:
        return
    assert all(g.is_watertight for g in s.geometry.values())


def test_a_tolerance_past_eight_moduli_is_drawn():
    # regression: the blank's buffer took its segments from 2 acos(1 - tol / (4 m)), a math
    # domain error (a ValueError) past tol = 8 m; the chord angle is a whole turn there
    # (gears.cutting.sampling.chord_angle: the sagitta passes the diameter), so the coarsest
    # outlines come out valid, each of an area within 5 % of the same outline's at 0.02 mm
    # (the fixture's; a coarse outline's chords cut its area by a few per cent at most)
    p = NonCircularPair.elliptical(40.0, 0.2, module=2.0)
    fine = p.outlines(0.0, 0.02)
    coarse = p.outlines(0.0, 20.0)  # ten moduli
    for c, f in zip(coarse, fine, strict=True):
        assert c.is_valid and c.area == pytest.approx(f.area, rel=0.05)
