"""Worm pairs (DIN 3975) and crossed axes: the textbooks' worked values, the DIN 3975 relations
by independent derivations, the flank forms against their definitions, the checks against the
core's spur formulas, and hypothesis sweeps of every new entry point.

Sources named in each test: the lecture course §8.15 (vector W1: z1 2, q 10, f' 0.05 gives
gamma 11.309932 deg, eta 0.7920, i 20); Ozols (14.15)-(14.18) and §14-3's text example;
Ozols (21.41)-(21.45); Joldasbekov (6.1)-(6.10) and its digest's table; brute force.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from gears import Gear, GearError, GearPair, Rack, WormPair
from gears.bevel.cone import pitch_angles
from gears.geometry import min_profile_shift, tooth_thickness
from gears.worm.checks import worm_margins
from gears.worm.crossed import (
    axodes,
    crossed_efficiency,
    crossed_helical,
    crossed_sliding_velocity,
    reduced_friction_angle,
)
from gears.worm.flank import axial_half_thickness
from gears.worm.geometry import (
    best_lead_angle,
    self_locking,
    sliding_velocity,
    worm_efficiency,
    worm_geometry,
)

SWEEP = settings(
    max_examples=60, deadline=None, derandomize=True, database=None,
    suppress_health_check=list(HealthCheck),
)  # fmt: skip


# --- W1 and Ozols' screw formulas ----------------------------------------------------------------
def test_w1_lead_angle_efficiency_and_ratio():
    # lecture course §8.15, vector W1: z1 = 2, q = 10, f' = 0.05 -> gamma 11.309932, eta 0.7920,
    # z2 = 40 -> i = 20. f' is the reduced friction coefficient: mu = f' cos(alpha_n).
    w = WormPair(2, 40, 5.0, diameter_quotient=10)
    assert w.lead_angle == pytest.approx(11.309932, abs=5e-7)
    assert w.ratio == pytest.approx(20.0, rel=1e-15)
    eta = w.efficiency(0.05 * math.cos(math.radians(w.normal_pressure_angle)))
    assert round(eta, 4) == pytest.approx(0.7920, abs=1e-12)
    # Ozols (14.15) written out: tan(gamma) / tan(gamma + atan f')
    g, phi = math.atan(0.2), math.atan(0.05)
    assert eta == pytest.approx(math.tan(g) / math.tan(g + phi), rel=1e-12)
    # Ozols (14.18), the wheel driving
    back = w.efficiency(0.05 * math.cos(math.radians(20)), driving="wheel")
    assert back == pytest.approx(math.tan(g - phi) / math.tan(g), rel=1e-12)


def test_best_lead_angle_ozols_14_16_and_text_example():
    # Ozols §14-3: f = 0.1 -> phi = 5.711 deg, alpha_m = 45 - phi/2 = 42.145 deg,
    # eta_max = tan^2(alpha_m) = 0.8190 (the digest's recomputation of the book's 0.81)
    phi = float(reduced_friction_angle(0.1, 0.0))
    assert phi == pytest.approx(5.710593, abs=1e-6)
    gm = float(best_lead_angle(phi))
    assert gm == pytest.approx(42.1447, abs=1e-4)
    eta = float(worm_efficiency(gm, phi))
    assert eta == pytest.approx(math.tan(math.radians(gm)) ** 2, rel=1e-12)  # (14.17)
    assert eta == pytest.approx(0.8190, abs=5e-5)
    # it is the maximum: brute force over lead angles
    grid = np.linspace(1.0, 80.0, 79001)
    assert grid[np.argmax(worm_efficiency(grid, phi))] == pytest.approx(gm, abs=1e-3)


@given(st.floats(0.5, 40.0))
@SWEEP
def test_at_the_self_locking_limit_forward_efficiency_is_below_one_half(phi):
    # Ozols §14-3: at gamma = phi the reverse efficiency is 0 and the forward one
    # 1/2 - tan^2(gamma)/2 < 0.5
    assert float(worm_efficiency(phi, phi, "wheel")) == pytest.approx(0.0, abs=1e-12)
    fwd = float(worm_efficiency(phi, phi))
    assert fwd == pytest.approx(0.5 - math.tan(math.radians(phi)) ** 2 / 2, abs=1e-12)
    assert bool(self_locking(phi * (1 - 1e-9), phi)) and not bool(self_locking(phi * 1.001, phi))


def test_self_locking_worm_of_one_start():
    # Ozols §21-12: a self-locking worm has z1 = 1...2 and eta < 0.5: z1 = 1, q = 16,
    # gamma = atan(1/16) = 3.58 deg below phi' of mu = 0.08 (4.87 deg)
    w = WormPair(1, 40, 4.0, diameter_quotient=16)
    assert w.self_locking(0.08) and w.efficiency(0.08, "wheel") < 0.0
    assert 0.0 < w.efficiency(0.08) < 0.5
    assert not WormPair(4, 40, 4.0, diameter_quotient=8).self_locking(0.08)


# --- DIN 3975 relations by independent derivation ------------------------------------------------
def test_din3975_relations_by_independent_derivation():
    w = WormPair(3, 47, 6.3, diameter_quotient=9, profile_shift=0.3, flank="ZA")
    m, x2 = 6.3, 0.3
    # the lead on the unrolled reference cylinder: tan(gamma) = p_z / (pi d_m1)
    assert math.tan(math.radians(w.lead_angle)) == pytest.approx(
        3 * math.pi * m / (math.pi * w.worm_diameter), rel=1e-14
    )
    # normal pitch: two neighbouring threads on the unrolled cylinder are parallel lines
    # p_x apart along the axis; their distance along the normal is the normal pitch pi m_n
    d = np.array([math.pi * w.worm_diameter, 3 * math.pi * m])  # direction of one thread line
    normal = np.array([-d[1], d[0]]) / np.hypot(*d)
    assert abs(np.array([0.0, math.pi * m]) @ normal) == pytest.approx(
        math.pi * w.normal_module, rel=1e-13
    )
    # radial clearance c* m at both roots: from the centre distance and the four diameters
    a = w.center_distance
    assert a - w.wheel_tip_diameter / 2 - w.worm_root_diameter / 2 == pytest.approx(0.2 * m)
    assert a - w.worm_tip_diameter / 2 - w.wheel_root_diameter / 2 == pytest.approx(0.2 * m)
    # the worm's reference line rolls on the wheel's circle shifted by x2 m
    assert a == pytest.approx(w.worm_diameter / 2 + 47 * m / 2 + x2 * m, rel=1e-14)
    assert w.throat_radius == pytest.approx(a - w.wheel_tip_diameter / 2, rel=1e-14)
    # the wheel in the mid-plane is an involute gear of z2, m_x, alpha_x, x2 on a rack:
    # the core's rack mesh gives the same contact ratio, thickness and undercut limit
    spur = Gear(47, m, pressure_angle=w.axial_pressure_angle, profile_shift=x2)
    assert spur.tip_diameter == pytest.approx(w.wheel_tip_diameter, rel=1e-14)
    core = GearPair(spur, Rack(m, pressure_angle=w.axial_pressure_angle))
    assert w.contact_ratio == pytest.approx(core.contact_ratio, rel=1e-12)
    s_a = float(tooth_thickness(w.wheel_tip_diameter, 47, m, x2, w.axial_pressure_angle))
    assert float(w.geometry.wheel_tip_thickness) == pytest.approx(s_a, rel=1e-12)
    x_min = float(min_profile_shift(47, w.axial_pressure_angle))
    assert float(w.margins().wheel_undercut) == pytest.approx(x2 - x_min, rel=1e-12)


def test_pressure_angles_follow_the_flank_form():
    # DIN 3975: ZA gives alpha in the axial section, ZN/ZI/ZK in the normal section;
    # tan(alpha_n) = tan(alpha_x) cos(gamma)
    za = WormPair(2, 30, 4.0, diameter_quotient=8, flank="ZA")
    zi = WormPair(2, 30, 4.0, diameter_quotient=8, flank="ZI")
    g = math.radians(za.lead_angle)
    assert za.axial_pressure_angle == pytest.approx(20.0, abs=1e-12)
    assert math.tan(math.radians(za.normal_pressure_angle)) == pytest.approx(
        math.tan(math.radians(20)) * math.cos(g), rel=1e-13
    )
    assert zi.normal_pressure_angle == pytest.approx(20.0, abs=1e-12)
    assert math.tan(math.radians(zi.axial_pressure_angle)) == pytest.approx(
        math.tan(math.radians(20)) / math.cos(g), rel=1e-13
    )


# --- flank forms against their definitions -------------------------------------------------------
def _helicoid_normal_angle(flank, z1, m, q, r, **kw):
    """The normal pressure angle at radius r of the helicoid z = h(r) + p theta, from its
    surface normal by finite differences (independent of the base-cylinder formulas)."""
    p = z1 * m / 2.0  # lead / (2 pi) = z1 pi m / (2 pi)
    e = 1e-6 * r
    dh = (axial_half_thickness(flank, r + e, z1, m, q, **kw)
          - axial_half_thickness(flank, r - e, z1, m, q, **kw)) / (2 * e)  # fmt: skip
    # at theta = 0: d/dr = (1, 0, h'), d/dtheta = (0, r, p); normal = cross product
    n = np.cross([1.0, 0.0, float(dh)], [0.0, r, p])
    n /= np.linalg.norm(n)
    return math.degrees(math.asin(abs(n[0])))  # the radial component is sin(alpha_n)


@pytest.mark.parametrize("z1, q", [(1, 10.0), (2, 10.0), (4, 7.5)])
def test_zi_and_za_normal_pressure_angle_on_the_reference_cylinder(z1, q):
    # the flank's normal at the reference cylinder lies in the normal section and makes
    # alpha_n with the cylinder's tangent plane (ZI: alpha_n = 20; ZA: atan(tan 20 cos gamma))
    m = 3.0
    rm = q * m / 2
    gamma = math.atan(z1 / q)
    assert _helicoid_normal_angle("ZI", z1, m, q, rm) == pytest.approx(20.0, abs=1e-6)
    za = math.degrees(math.atan(math.tan(math.radians(20)) * math.cos(gamma)))
    assert _helicoid_normal_angle("ZA", z1, m, q, rm) == pytest.approx(za, abs=1e-6)


def test_zi_transverse_section_is_an_involute():
    # independent: in a transverse plane the ZI flank is the involute of r_b: its polar angle
    # grows as inv(acos(r_b / r)); r_b from the base lead angle cos(gamma_b) = cos gamma cos
    # alpha_n (DIN 3975) must make the transverse sections involutes of that very circle
    w = WormPair(2, 40, 5.0, diameter_quotient=10, flank="ZI")
    rb = w.worm_base_diameter / 2
    p = w.lead / (2 * math.pi)
    r = np.linspace(w.worm_root_diameter / 2, w.worm_tip_diameter / 2, 50)
    r = r[r > rb]
    theta = -np.asarray(w.axial_profile(r)) / p  # the flank's polar angle in the plane z = 0
    a = np.arccos(rb / r)
    spread = theta - (np.tan(a) - a)  # constant along an involute
    assert np.ptp(spread) < 1e-12


def test_zn_normal_section_is_straight():
    # ZN: the flank cut by the normal plane of the thread at the reference cylinder is a
    # straight line at alpha_n to the radial direction
    z1, m, q = 3, 4.0, 9.0
    rm, p, gamma = q * m / 2, z1 * m / 2, math.atan(z1 / q)
    t = np.array([0.0, math.cos(gamma), math.sin(gamma)])
    pts = []
    for r in np.linspace(rm - 2.2 * m, rm + m, 25):
        h = float(axial_half_thickness("ZN", r, z1, m, q))

        def dist(th, r=r, h=h):  # the helix of the flank at radius r against the plane
            return np.array([r * math.cos(th), r * math.sin(th), h + p * th]) @ t

        lo, hi = -0.5, 0.5
        for _ in range(80):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if dist(lo) * dist(mid) > 0 else (lo, mid)
        th = (lo + hi) / 2
        pts.append([r * math.cos(th), r * math.sin(th), h + p * th])
    pts = np.array(pts)
    centred = pts - pts.mean(axis=0)
    s = np.linalg.svd(centred, compute_uv=False)
    assert s[1] < 1e-9 * s[0] and s[2] < 1e-9 * s[0]  # collinear
    direction = np.linalg.svd(centred)[2][0]
    assert math.degrees(math.acos(abs(direction[0]))) == pytest.approx(20.0, abs=1e-9)


def test_zk_with_a_flat_wheel_is_the_involute_helicoid():
    # limit: a grinding cone of infinite radius is a plane, and a plane in screw motion
    # envelopes the involute helicoid (the ZI worm is ground by a flat wheel face)
    r = np.linspace(17.0, 22.0, 11)
    zk = axial_half_thickness("ZK", r, 2, 4.0, 10.0, tool_radius=1e7)
    zi = axial_half_thickness("ZI", r, 2, 4.0, 10.0)
    assert np.max(np.abs(zk - zi)) < 1e-6


def test_zk_cone_touches_the_flank_along_a_line_without_cutting_it():
    # independent: sample the grinding cone's lower face (placed as the module docstring
    # says), take every point to the axial section by the screw motion and measure its axial
    # gap to the flank. An envelope touches the cone along a line: the smallest gap of every
    # circle of the cone is the same (the flank may be shifted axially as a whole to set the
    # thread thickness), and no point of the cone lies inside the thread.
    z1, m, q, r0 = 2, 4.0, 10.0, 30.0
    rm, p, gamma = q * m / 2, z1 * m / 2, math.atan(z1 / q)
    s, c, t = math.sin(gamma), math.cos(gamma), math.tan(math.radians(20))
    k, b = np.array([0.0, -s, c]), np.array([0.0, -c, -s])
    space = math.pi * m / 4
    centre = np.array([rm + r0, 0.0, math.pi * m / 4 + space])
    rho, psi = np.meshgrid(np.linspace(r0 - 2.2 * m, r0 + 0.9 * m, 40),
                           np.linspace(-0.12, 0.12, 2401), indexing="ij")  # fmt: skip
    e = np.cos(psi)[..., None] * np.array([-1.0, 0, 0]) + np.sin(psi)[..., None] * b
    pts = centre + rho[..., None] * e + (-space * c + (rho - r0) * t)[..., None] * k
    r = np.hypot(pts[..., 0], pts[..., 1])
    z_ax = pts[..., 2] - p * np.arctan2(pts[..., 1], pts[..., 0])
    gap = z_ax - axial_half_thickness("ZK", r, z1, m, q, tool_radius=r0)
    touch = gap.min(axis=1)  # per circle of the cone (the grid's spacing is 1e-4 rad)
    assert np.ptp(touch) < 2e-5
    assert abs(touch.mean()) < 0.01 * m  # the thickness setting moves it by a hair only


# --- crossed axes --------------------------------------------------------------------------------
def test_joldasbekov_axodes_table():
    # Joldasbekov (6.1)-(6.10), the digest's table: omega1 3, omega2 1, l 2
    ax = axodes(3.0, 90.0, 2.0, speed=3.0)
    assert float(ax.relative_speed) == pytest.approx(3.162278, abs=1e-6)
    assert math.tan(math.radians(float(ax.angle1))) == pytest.approx(1 / 3, rel=1e-12)
    assert math.tan(math.radians(float(ax.angle2))) == pytest.approx(3.0, rel=1e-12)
    assert float(ax.throat_radius1) == pytest.approx(0.2, rel=1e-12)
    assert float(ax.throat_radius2) == pytest.approx(1.8, rel=1e-12)
    assert float(ax.axial_sliding) == pytest.approx(1.897367, abs=1e-6)
    ax = axodes(3.0, 45.0, 2.0, speed=3.0)  # r1/r2 = 0.280661, tan phi1 = 0.190744
    assert float(ax.throat_radius1 / ax.throat_radius2) == pytest.approx(0.280661, abs=1e-6)
    assert math.tan(math.radians(float(ax.angle1))) == pytest.approx(0.190744, abs=1e-6)


@given(st.floats(0.05, 20.0), st.floats(0.0, 170.0), st.floats(0.0, 100.0))
@SWEEP
def test_axodes_equal_a_brute_force_screw_axis(i, sigma, l_):
    # independent: in 3D, axis 1 along z through the origin, axis 2 through (l, 0, 0) at the
    # angle Sigma (omega1 and -omega2 at Sigma); the screw axis is where the relative velocity
    # (of body 1 with respect to body 2) is parallel to omega1 - omega2
    w1 = 1.0
    s = math.radians(sigma)
    o1 = np.array([0.0, 0.0, w1])
    o2 = -(w1 / i) * np.array([0.0, -math.sin(s), math.cos(s)])
    c2 = np.array([l_, 0.0, 0.0])
    w12 = o1 - o2

    def rel(x):  # velocity of the point (x, 0, 0) of body 1 relative to body 2
        pt = np.array([x, 0.0, 0.0])
        return np.cross(o1, pt) - np.cross(o2, pt - c2)

    # rel(x) x w12 = 0 is linear in x: solve by least squares on two samples
    f0, f1 = np.cross(rel(0.0), w12), np.cross(rel(1.0), w12)
    x = -float(f0 @ (f1 - f0)) / float((f1 - f0) @ (f1 - f0)) if l_ > 0 else 0.0
    ax = axodes(i, sigma, l_, speed=w1)
    assert float(ax.throat_radius1) == pytest.approx(x, abs=1e-9 * (1 + l_))
    assert float(ax.relative_speed) == pytest.approx(np.linalg.norm(w12), rel=1e-12)
    along = rel(x) @ w12 / np.linalg.norm(w12)
    assert float(ax.axial_sliding) == pytest.approx(abs(along), abs=1e-9 * (1 + l_))


def test_axodes_special_cases_cylinders_and_bevel_cones():
    # Sigma = 0: pitch cylinders r1 / r2 = omega2 / omega1 (Joldasbekov §6-2)
    ax = axodes(2.5, 0.0, 70.0)
    assert float(ax.throat_radius1) == pytest.approx(20.0, rel=1e-14)
    assert float(ax.throat_radius2) == pytest.approx(50.0, rel=1e-14)
    # l = 0: the pitch cones of the bevel pair (gears.bevel.cone.pitch_angles)
    for z1, z2, sigma in [(20, 40, 90.0), (20, 60, 60.0), (13, 31, 115.0)]:
        ax = axodes(z2 / z1, sigma, 0.0)
        d1, d2 = pitch_angles(z1, z2, sigma)
        assert float(ax.angle1) == pytest.approx(float(d1), abs=1e-12)
        assert float(ax.angle2) == pytest.approx(float(d2), abs=1e-12)
        assert abs(float(ax.throat_radius1)) < 1e-12 and abs(float(ax.throat_radius2)) < 1e-12


def test_ozols_crossed_helical_example():
    # Ozols (21.41)-(21.44), the digest's case: Sigma 90, i 2, a 100 -> beta1 26.565,
    # beta2 63.435, r1 20, r2 80, r2 cos(beta2) / (r1 cos(beta1)) = 2; these are the axodes'
    ax = axodes(2.0, 90.0, 100.0)
    b1, b2 = float(ax.angle1), float(ax.angle2)
    assert b1 == pytest.approx(26.565, abs=5e-4) and b2 == pytest.approx(63.435, abs=5e-4)
    mn = 40.0 * math.cos(math.radians(b1)) / 20
    g = crossed_helical(20, 40, mn, b1, b2)
    assert float(g.shaft_angle) == pytest.approx(90.0, abs=1e-12)
    assert float(g.reference_diameter1) / 2 == pytest.approx(float(ax.throat_radius1), rel=1e-12)
    assert float(g.reference_diameter2) / 2 == pytest.approx(float(ax.throat_radius2), rel=1e-12)
    assert float(g.center_distance) == pytest.approx(100.0, rel=1e-12)
    r1, r2 = float(g.reference_diameter1) / 2, float(g.reference_diameter2) / 2
    assert r2 * math.cos(math.radians(b2)) / (r1 * math.cos(math.radians(b1))) == pytest.approx(2)
    # parallel helical (beta2 = -beta1): a = m_t (z1 + z2) / 2, no lengthwise sliding, eta 1
    h = crossed_helical(20, 40, 2.0, 15.0, -15.0)
    assert float(h.center_distance) == pytest.approx(60 * 2 / math.cos(math.radians(15)) / 2)
    assert float(crossed_sliding_velocity(3.0, 15.0, -15.0)) == pytest.approx(0.0, abs=1e-15)
    assert float(crossed_efficiency(15.0, -15.0, 6.0)) == pytest.approx(1.0, abs=1e-15)


@given(st.floats(-80.0, 80.0), st.floats(-80.0, 80.0), st.floats(0.0, 30.0))
@SWEEP
def test_crossed_efficiency_equals_a_brute_force_force_balance(b1, b2, phi):
    # independent: in the tangent plane, velocities of both pitch points rolling (equal normal
    # components), the tooth force with friction opposing the sliding; power out / power in
    t, n = np.array([1.0, 0.0]), np.array([0.0, 1.0])
    r1, r2 = math.radians(b1), math.radians(b2)
    e1 = math.sin(r1) * t + math.cos(r1) * n  # gear 1's peripheral direction
    e2 = -math.sin(r2) * t + math.cos(r2) * n
    v1 = 1.0
    v2 = v1 * math.cos(r1) / math.cos(r2)
    slide = (v1 * e1 - v2 * e2) @ t  # 1 relative to 2 along the teeth
    force = n + math.tan(math.radians(phi)) * np.sign(slide) * t  # on gear 2, N = 1
    p_in, p_out = force @ (v1 * e1), force @ (v2 * e2)
    eta = float(crossed_efficiency(b1, b2, phi))
    if p_in > 1e-9:
        assert eta == pytest.approx(p_out / p_in, rel=1e-9, abs=1e-12)
    assert math.isfinite(eta) and eta <= 1.0 + 1e-12
    assert float(crossed_sliding_velocity(v1, b1, b2)) == pytest.approx(abs(slide), abs=1e-9)


def test_sliding_velocity_of_a_worm():
    # DIN 3975: v_g = v_1 / cos(gamma); d_m1 50, 1500 rpm, gamma 11.309932 deg
    v1 = math.pi * 50 * 1500 / 60000
    assert float(sliding_velocity(50.0, 11.309932, 1500.0)) == pytest.approx(
        v1 / math.cos(math.radians(11.309932)), rel=1e-12
    )
    w = WormPair(2, 40, 5.0)
    assert w.sliding_velocity(1500) == pytest.approx(v1 / math.cos(math.atan(0.2)), rel=1e-12)


# --- checks, errors, sweeps ----------------------------------------------------------------------
def test_check_reports_every_failing_condition_with_its_margin():
    # z2 = 20 with x2 = -0.5 is undercut (z_min = 2 (1 + 0.5) / sin^2(alpha_x)); the report
    # says so instead of raising
    w = WormPair(1, 20, 2.0, diameter_quotient=8, profile_shift=-0.5)
    r = w.check()
    assert not r.ok and "wheel_undercut" in r.failed()
    assert r["wheel_undercut"].margin < 0
    assert WormPair(2, 40, 5.0).check().ok
    # a face width past the wrap-angle rule and a short worm fail as findings
    r = WormPair(2, 40, 5.0, face_width=55.0, worm_length=60.0).check()
    assert {"face_width", "worm_length"} <= set(r.failed())


@pytest.mark.parametrize(
    "kwargs, word",
    [
        ({"starts": 0}, "starts"),
        ({"wheel_teeth": 2.5}, "wheel_teeth"),
        ({"module": -1}, "module"),
        ({"diameter_quotient": 2.0}, "diameter_quotient"),
        ({"diameter_quotient": 10, "worm_diameter": 40}, "worm_diameter"),
        ({"flank": "ZX"}, "flank"),
        ({"hand": "up"}, "hand"),
        ({"pressure_angle": 50}, "pressure_angle"),
        ({"profile_shift": -30}, "profile_shift"),
        ({"face_width": float("nan")}, "face_width"),
        ({"flank": "ZK", "tool_radius": 1.0}, "tool_radius"),
    ],
)
def test_bad_input_names_the_value(kwargs, word):
    args = {"starts": 2, "wheel_teeth": 40, "module": 5.0, **kwargs}
    with pytest.raises(GearError) as info:
        WormPair(args.pop("starts"), args.pop("wheel_teeth"), args.pop("module"), **args)
    assert word in str(info.value)


def test_efficiency_refuses_bad_friction_and_driver():
    w = WormPair(2, 40, 5.0)
    for bad in (-0.1, 1.0, float("nan"), "0.1"):
        with pytest.raises(GearError, match="friction"):
            w.efficiency(bad)
    with pytest.raises(GearError, match="driving"):
        w.efficiency(0.05, driving="both")


numbers = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(-5, 200),
    st.sampled_from([0, 1, 2, 0.5, 1e-9, 1e9, "1", None]),
)


@given(
    st.one_of(st.integers(-1, 8), numbers), st.one_of(st.integers(1, 300), numbers),
    st.one_of(st.floats(0.1, 30.0), numbers), st.one_of(st.floats(2.5, 30.0), numbers),
    st.sampled_from(["ZA", "ZN", "ZI", "ZK"]), st.one_of(st.floats(-1.5, 1.5), numbers),
    st.one_of(st.floats(0.0, 0.5), numbers),
)  # fmt: skip
@SWEEP
def test_worm_pair_answers_or_refuses(z1, z2, m, q, flank, x2, mu):
    # every call: a finite answer or the library's own error; check() never raises for a
    # pair the constructor accepted, and its margins are the vectorised ones
    try:
        w = WormPair(z1, z2, m, diameter_quotient=q, flank=flank, profile_shift=x2)
    except GearError:
        return
    for v in w.geometry:
        assert np.all(np.isfinite(v))
    r = w.check()
    assert all(math.isfinite(f.margin) for f in r.values())
    mg = worm_margins(w.starts, w.wheel_teeth, w.module, w.diameter_quotient, 20.0, flank,
                      w.profile_shift, w.face_width, w.worm_length)  # fmt: skip
    assert float(mg.contact_ratio) == pytest.approx(r["contact_ratio"].margin, rel=1e-9)
    try:
        for d in ("worm", "wheel"):
            eta = w.efficiency(mu, d)
            assert math.isfinite(eta) and eta <= 1.0
        assert isinstance(w.self_locking(mu), bool)
        assert math.isfinite(w.best_lead_angle(mu))
    except GearError as exc:
        assert "friction" in str(exc)


@given(
    st.floats(1e-3, 1e3), st.floats(0.0, 179.0), st.floats(0.0, 1e4),
    st.floats(-89.0, 89.0), st.floats(-89.0, 89.0), st.floats(0.0, 45.0),
)  # fmt: skip
@SWEEP
def test_crossed_formulas_are_finite(i, sigma, l_, b1, b2, phi):
    for v in axodes(i, sigma, l_):
        assert np.all(np.isfinite(v))
    for v in crossed_helical(10, 30, 2.0, b1, b2):
        assert np.all(np.isfinite(v))
    assert np.isfinite(crossed_efficiency(b1, b2, phi))
    assert np.isfinite(crossed_sliding_velocity(1.0, b1, b2))


def test_formulas_broadcast_over_arrays():
    # a sweep over arrays calls the same code as one WormPair
    z1 = np.array([1, 2, 3, 4])
    g = worm_geometry(z1, 40, 5.0, 10.0)
    for i, z in enumerate(z1):
        one = WormPair(int(z), 40, 5.0)
        assert float(g.lead_angle[i]) == pytest.approx(one.lead_angle, rel=1e-15)
        assert float(g.contact_ratio[i]) == pytest.approx(one.contact_ratio, rel=1e-15)
    mg = worm_margins(z1, 40, 5.0, 10.0, flank="ZK")
    assert mg.worm_tip_land.shape == (4,)
