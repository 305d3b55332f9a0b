"""The cycloidal drive and cycloidal tooth profiles: ratio by the Willis solver against an
independent count (the disc fitted among the pins by geometry alone), the compound drive, all
pins touching the unmodified disc, the clearance modifications, the load shared among the lobes
(Kudryavtsev's closed form), the classical cycloids, and hypothesis sweeps."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.optimize import minimize_scalar
from shapely import affinity

from gears import GearError, transmission_error
from gears.noncircular.cycloid import (
    cycloidal_gear_outline,
    cycloidal_tooth_flank,
    epicycloid,
    hypocycloid,
    path_curvature,
    pin_path,
)
from trains import CycloidalDrive

SWEEP = settings(
    max_examples=30, deadline=None, derandomize=True, database=None,
    suppress_health_check=list(HealthCheck),
)  # fmt: skip


def _fitted_disc_angle(drive, disc, theta_deg, guess):
    """The disc's rotation (deg) that seats it among the pins at the eccentric angle theta,
    found from geometry alone: the least squares of each pin centre's distance to the disc
    less the pin radius (no ratio formula used)."""
    alpha = 2 * np.pi * np.arange(drive.pins) / drive.pins
    centres = drive.pin_circle_radius * np.stack([np.cos(alpha), np.sin(alpha)], axis=-1)
    t = math.radians(theta_deg)
    shift = drive.eccentricity * np.array([math.cos(t), math.sin(t)])
    points = shapely.points(centres - shift)

    def misfit(beta):
        placed = affinity.rotate(disc.exterior, beta, origin=(0.0, 0.0))
        return float(np.sum((shapely.distance(placed, points) - drive.pin_radius) ** 2))

    span = 180.0 / drive.lobes
    res = minimize_scalar(misfit, bounds=(guess - span / 2, guess + span / 2), method="bounded",
                          options={"xatol": 1e-7})  # fmt: skip
    return res.x, res.fun


@pytest.mark.parametrize("pins", [8, 12])
def test_ratio_against_the_disc_fitted_among_the_pins(pins):
    # Willis (khv): i = -(N - 1). Independent count: seat the disc among the pins by geometry
    # at eccentric angles 0 ... 90 deg (continuation from 0), and read the disc's turn
    drive = CycloidalDrive(pins, 3.0, 1.5, 40.0)
    assert drive.ratio == Fraction(-(pins - 1))
    disc = drive.disc_outline(0.002)
    beta, angles = 0.0, np.linspace(0.0, 90.0, 10)
    turned = []
    for th in angles:
        beta, misfit = _fitted_disc_angle(drive, disc, th, beta)
        assert misfit < 1e-5
        turned.append(beta)
    slope = np.polyfit(angles, turned, 1)[0]
    assert 1 / slope == pytest.approx(float(drive.ratio), rel=1e-4)


def test_compound_ratio():
    # compound discs of 8 and 7 lobes (9 and 8 pins): 1 / (1 - 9 * 7 / (8 * 8)) = 64 (the
    # Willis formula by hand; a published generator gave 56:1 for these discs)
    d = CycloidalDrive(9, 3.0, 1.0, 40.0, output_pins=8, output_pin_circle_radius=36.0)
    assert d.ratio == Fraction(64)
    assert d.disc_outline(0.01, stage=2).is_valid


def test_every_pin_touches_the_unmodified_disc():
    # the disc is the pin path's parallel curve: at any eccentric angle every pin centre lies at
    # the pin radius from the disc (brute force on the placed outline, tolerance 0.001 mm)
    d = CycloidalDrive(10, 2.5, 1.2, 30.0)
    for a in (0.0, 17.0, 123.0):
        disc, pins = d.outlines(a, 0.001)
        gaps = [disc.exterior.distance(p.centroid) - 2.5 for p in pins.geoms]
        assert np.max(np.abs(gaps)) < 0.002
        assert disc.intersection(pins).area < 1e-4


def test_modifications_give_clearance():
    # an equidistant modification of 0.05 mm leaves a gap of about 0.05 mm at the nearest pins
    d = CycloidalDrive(10, 2.5, 1.2, 30.0, equidistant=0.05)
    disc, pins = d.outlines(40.0, 0.001)
    gaps = np.array([disc.exterior.distance(p.centroid) - 2.5 for p in pins.geoms])
    assert disc.intersection(pins).area < 1e-12  # mm^2: no overlap, to rounding
    assert gaps.min() == pytest.approx(0.05, abs=0.003)
    assert d.check()["clearance"].margin == pytest.approx(0.05)


def test_load_shared_among_the_lobes():
    # equal rigidity (Kudryavtsev): the moments balance the torque and the largest force is
    # F_max = 4 T / (e (N - 1) N) for many pins (sum of sin^2 over half the pins = N/4)
    d = CycloidalDrive(40, 2.0, 1.0, 60.0)
    f = d.contact_forces(1000.0, 7.0)
    assert np.count_nonzero(f) == pytest.approx(20, abs=1)
    assert f.max() == pytest.approx(4 * 1000 / (1.0 * 39 * 40), rel=0.02)
    t = math.radians(7.0)
    u = np.array([math.cos(t), math.sin(t)])
    alpha = 2 * np.pi * np.arange(40) / 40
    pins = 60.0 * np.stack([np.cos(alpha), np.sin(alpha)], axis=-1)
    normal = pins - 40 * u
    normal /= np.hypot(*normal.T)[:, None]
    lever = (40 * u - u)[0] * normal[:, 1] - (40 * u - u)[1] * normal[:, 0]
    assert np.sum(f * lever) == pytest.approx(1000.0, rel=1e-12)


def test_undercut_and_refusals():
    # a pin radius above the pin path's least convex radius of curvature undercuts the disc
    theta = np.linspace(0, 2 * np.pi, 2001)
    rho = 1 / path_curvature(theta, 12, 2.5, 31.0).max()
    bad = CycloidalDrive(12, rho * 1.05, 2.5, 31.0)
    assert not bad.check()["undercut"].ok
    assert CycloidalDrive(12, rho * 0.95, 2.5, 31.0).check()["undercut"].ok
    with pytest.raises(GearError, match="pin_circle_radius"):
        CycloidalDrive(12, 1.0, 2.0, 20.0)  # R < e N: not curtate
    with pytest.raises(GearError, match="pins"):
        CycloidalDrive(2, 1.0, 1.0, 20.0)
    with pytest.raises(GearError, match="output_pins"):
        CycloidalDrive(9, 1.0, 1.0, 20.0, output_pins=8)


def test_classical_cycloids():
    # one arch of an epicycloid is 8 r (R + r) / R long; the hypocycloid of r = R/2 is a
    # diameter (Cardano); both start and cusp on the base circle (classical geometry)
    big, r = 30.0, 5.0
    t = np.linspace(0, 2 * np.pi * r / big, 20001)
    arch = epicycloid(t, big, r)
    length = np.sum(np.hypot(*np.diff(arch, axis=0).T))
    assert length == pytest.approx(8 * r * (big + r) / big, rel=1e-7)
    assert np.hypot(*arch[-1]) == pytest.approx(big, rel=1e-12)
    line = hypocycloid(np.linspace(0, 2 * np.pi, 50), 20.0, 10.0)
    assert np.allclose(line[:, 1], 0.0, atol=1e-12)
    # the pin path at theta = 0: pin 0 at R - e from the disc's centre
    assert np.allclose(pin_path(0.0, 10, 2.0, 50.0), [48.0, 0.0])


def test_cycloidal_gears_are_conjugate():
    # clock gearing (Joldasbekov section 7): two gears of one rolling circle (radius 5 mm,
    # module 2, 20 and 40 teeth) at zero backlash turn at a constant ratio: the geometric
    # transmission error is zero to the outline tolerance (0.01 mm), and the drawn flank lies
    # within the tolerance of the exact cycloids
    one = cycloidal_gear_outline(20, 2.0, 5.0, 0.01)
    two = cycloidal_gear_outline(40, 2.0, 5.0, 0.01)
    two = affinity.translate(affinity.rotate(two, 180 + 180 / 40, origin=(0, 0)), 60.0, 0.0)
    assert one.is_valid and two.is_valid and one.intersection(two).area < 1e-4
    te = transmission_error(one, two, ((0, 0), (60.0, 0)), np.linspace(0, 18, 5), 2.0)
    assert np.abs(np.radians(te) * 40.0).max() < 0.01
    exact = cycloidal_tooth_flank(20, 2.0, 5.0, samples=20000)
    assert shapely.distance(one.exterior, shapely.points(exact)).max() < 0.01
    # the tooth is p/2 thick on the pitch circle: its flank crosses it at -90/z deg
    r = np.hypot(*exact.T)
    k = np.argmin(np.abs(r - 20.0))
    assert math.degrees(math.atan2(exact[k, 1], exact[k, 0])) == pytest.approx(-4.5, abs=1e-3)
    with pytest.raises(GearError, match="rolling_radius"):
        cycloidal_gear_outline(20, 2.0, 25.0)


_num = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-3, 50), st.none())


@SWEEP
@given(n=_num, rp=_num, e=_num, big=_num, dr=st.one_of(st.just(0.0), _num))
def test_drive_sweep(n, rp, e, big, dr):
    try:
        d = CycloidalDrive(n, rp, e, big, equidistant=dr)
    except GearError:
        return
    r = d.check()
    assert all(math.isfinite(f.margin) for f in r.values())
    assert np.all(np.isfinite(d.contact_forces(10.0, 3.0)))
    assert d.ratio == -(d.pins - 1)


def test_scene_and_animation(tmp_path):
    # the disc and 12 pins, one pin mesh shared; a GIF of 3 frames
    from PIL import Image

    d = CycloidalDrive(12, 3.0, 1.5, 40.0, equidistant=0.05)
    s = d.scene(10.0, 8.0, 0.02)
    assert len(s.geometry) == 2 and len(s.graph.nodes_geometry) == 13
    assert all(g.is_watertight for g in s.geometry.values())
    with Image.open(d.animate(tmp_path / "drive.gif", frames=3)) as im:
        assert im.n_frames == 3


@SWEEP
@given(t=st.lists(st.floats(-100, 100), max_size=5), big=st.floats(1, 100),
       r=st.floats(0.01, 50), d=st.one_of(st.none(), st.floats(0, 50)),
       n=st.integers(3, 60), e=st.floats(0.01, 5), rp=st.floats(0.01, 20))  # fmt: skip
def test_curves_sweep(t, big, r, d, n, e, rp):
    # the vectorised curves: finite for finite input (a point on a rolling circle, the pin path)
    for f in (epicycloid, hypocycloid):
        assert np.all(np.isfinite(f(np.array(t), big, r, d)))
    assert np.all(np.isfinite(pin_path(np.array(t), n, e, big)))
    k = path_curvature(np.array(t), n, e, max(big, e * n * 1.01))
    assert np.all(np.isfinite(k))


@SWEEP
@given(torque=_num, angle=_num, tol=_num)
def test_loads_and_outline_sweep(torque, angle, tol):
    d = CycloidalDrive(10, 2.5, 1.2, 30.0)
    try:
        f = d.contact_forces(torque, angle)
        assert np.all(np.isfinite(f)) and f.sum() > 0
    except GearError:
        pass
    try:
        assert d.disc_outline(tol).is_valid
    except GearError:
        pass


@SWEEP
@given(z=_num, m=_num, rho=_num, tol=st.sampled_from([0.05, 0.0, -1.0, 1e-9]))
def test_cycloidal_gear_sweep(z, m, rho, tol):
    try:
        g = cycloidal_gear_outline(z, m, rho, tol)
    except GearError:
        return
    assert g.is_valid or g.area > 0
