"""Mesh forces (gears/forces.py): the textbook example, the standard formulas, statics.

Sources: Ozols, *Mehanismu un masinu teorija* (1974) section 11-2 (11.8) and section 21-4
(21.15)-(21.18); ISO 6336-1 (1) F_t = 2000 T / d; ISO 10300-1 bevel forces at the mean cone
(F_r = F_t tan alpha cos delta, F_a = F_t tan alpha sin delta); independent derivations named
at each test (torque balance about each axis, the line of action tangent to the base circle);
Joldasbekov, Ch. VII section 10 (7.65)-(7.68) and the mesh force constant P = 97400 N / (n r0).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import BevelPair, Gear, GearError, GearPair, Rack
from gears.forces import (
    bearing_reactions,
    bevel_mesh_forces,
    bevel_pair_forces,
    friction_mesh_force,
    mesh_forces,
    pair_forces,
    rotate_forces,
    tangential_force,
    worm_mesh_forces,
    worm_torque_forces,
)

REL = 1e-12  # floats of one formula evaluated two ways
HELICAL = GearPair(Gear(20, 2, helix_angle=10), Gear(30, 2, helix_angle=-10))


def test_ozols_11_8_mesh_reaction():
    # Ozols section 11-2 (11.8): M1 = 100 N m, r1 = 0.05 m, alpha = 20 deg:
    # R = M1 / (r1 cos alpha) = 2128.36 N along the line of action
    pair = GearPair(Gear(20, 5), Gear(40, 5))  # r1 = 50 mm
    f = pair_forces(pair, 100.0)
    assert f.normal[0] == pytest.approx(2128.36, abs=0.005)
    assert f.normal[0] == pytest.approx(100.0 / (0.05 * math.cos(math.radians(20))), rel=REL)
    # M2 = M1 r2 / r1 (11.8): the torque that holds gear 2
    assert f.torque_2 == pytest.approx(200.0, rel=REL)


@settings(max_examples=60, deadline=None)
@given(
    z1=st.integers(12, 60), dz=st.integers(1, 80), module=st.floats(0.5, 10),
    x1=st.floats(-0.3, 0.6), x2=st.floats(-0.3, 0.6), beta=st.floats(-40, 40),
    internal=st.booleans(), torque=st.floats(-1e4, 1e4).filter(lambda t: abs(t) > 1e-3),
)  # fmt: skip
def test_standard_formulas_and_torque_balance(z1, dz, module, x1, x2, beta, internal, torque):
    # ISO 6336-1 (1) at the working pitch circle: F_t = 2000 T / d_w1, F_r = F_t tan alpha_wt,
    # F_a = F_t tan beta_w; independent checks: the normal force is T / (r_b cos beta_b) (the
    # line of action touches the base circle, ISO 21771), and the force's moment about gear 2's
    # axis is -+ T z2 / z1 (torque balance of gear 2)
    z2 = z1 + dz + (8 if internal else 0)
    g1 = Gear(z1, module, profile_shift=x1, helix_angle=beta)
    g2 = Gear(z2, module, profile_shift=0.0 if internal else x2,
              helix_angle=beta if internal else -beta, internal=internal)  # fmt: skip
    try:
        pair = GearPair(g1, g2)
    except GearError:
        return
    f = pair_forces(pair, torque)
    d_w1 = pair.working_diameters[0]
    at = math.radians(pair.working_pressure_angle)
    ft = 2000 * abs(torque) / d_w1
    bw = math.atan(math.tan(math.radians(g1.base_helix_angle)) / math.cos(at))
    assert f.tangential[0] == pytest.approx(ft, rel=1e-12)
    assert f.radial[0] == pytest.approx(ft * math.tan(at), rel=1e-12)
    assert f.axial[0] == pytest.approx(ft * abs(math.tan(bw)), rel=1e-9, abs=1e-9 * ft)
    rb = g1.base_diameter / 2
    fn = 1000 * abs(torque) / (rb * math.cos(math.radians(g1.base_helix_angle)))
    assert f.normal[0] == pytest.approx(fn, rel=1e-9)
    sign = 1.0 if internal else -1.0
    assert f.torque_2 == pytest.approx(-sign * torque * z2 / z1, rel=1e-9)
    # Newton's third law, and the force's moment about gear 1's axis is -T
    np.testing.assert_allclose(f.vectors[0], -f.vectors[1], rtol=0, atol=1e-12 * fn)
    moment = np.cross(f.point, f.vectors[0])[2] / 1000
    assert moment == pytest.approx(-torque, rel=1e-12)


def test_helix_hand_sets_the_axial_direction():
    # independent derivation: the normal force is perpendicular to the tooth line; a right-hand
    # tooth at the pitch point runs along (0, sin beta_w, cos beta_w), so F . t = 0 there
    pinion = Gear(20, 3, helix_angle=20)  # right hand
    pair = GearPair(pinion, Gear(45, 3, helix_angle=-20))
    bw = math.radians(pair_forces(pair, 50.0).working_helix_angle)
    tooth = np.array([0.0, math.sin(bw), math.cos(bw)])
    for torque in (50.0, -50.0):
        v = pair_forces(pair, torque).vectors[0]
        assert abs(np.dot(v, tooth)) < 1e-9 * np.linalg.norm(v)
    assert pair_forces(pair, 50.0).vectors[0, 2] > 0  # right hand, T > 0: thrust on gear 1 +z
    left = GearPair(Gear(20, 3, helix_angle=-20), Gear(45, 3, helix_angle=20))
    assert pair_forces(left, 50.0).vectors[0, 2] < 0


def test_rack_has_no_second_axis():
    f = pair_forces(GearPair(Gear(20, 2), Rack(2)), 10.0)
    assert f.torque_2 is None and f.kind == "rack"
    assert f.tangential[0] == pytest.approx(2000 * 10 / 40, rel=REL)  # ISO 6336-1 (1)


@settings(max_examples=40, deadline=None)
@given(z1=st.integers(10, 40), z2=st.integers(10, 60), sigma=st.floats(45, 135),
       torque=st.floats(-500, 500).filter(lambda t: abs(t) > 1e-3))  # fmt: skip
def test_bevel_iso_10300_and_torque_balance(z1, z2, sigma, torque):
    # ISO 10300-1 at the mean cone; independent checks: the force on gear 2 projected on its
    # axis is its axial force (away from the apex), and its moment about that axis balances
    # T z2 / z1 (the pitch cones roll: z1 w1 + z2 w2 = 0, docs/bevel.md)
    try:
        pair = BevelPair(z1, z2, module=3, face_width=8, shaft_angle=sigma)
    except GearError:
        return
    f = bevel_pair_forces(pair, torque)
    d1, d2 = (math.radians(d) for d in pair.pitch_angles)
    ft = 2000 * abs(torque) / pair.g1.mean_diameter
    ta = math.tan(math.radians(20))
    assert f.tangential[0] == pytest.approx(ft, rel=1e-12)
    assert f.radial == pytest.approx((ft * ta * math.cos(d1), ft * ta * math.cos(d2)), rel=1e-9)
    assert f.axial == pytest.approx((ft * ta * math.sin(d1), ft * ta * math.sin(d2)), rel=1e-9)
    assert np.dot(f.vectors[1], f.axes[1]) == pytest.approx(f.axial[1], rel=1e-9, abs=1e-9 * ft)
    assert f.torque_2 == pytest.approx(torque * z2 / z1, rel=1e-9)


def test_friction_ozols_21_17_21_18_at_the_pitch_point():
    # Ozols (21.17) Q = P / cos(alpha + phi), (21.18) P_0 = P tan(alpha + phi)
    p, a, f = 2000.0, 20.0, 0.08
    q = friction_mesh_force(p, a, f)
    lean = math.radians(a) + math.atan(f)
    assert float(q.resultant) == pytest.approx(p / math.cos(lean), rel=REL)
    assert float(q.radial) == pytest.approx(p * math.tan(lean), rel=REL)
    assert float(q.tangential) == pytest.approx(p, rel=REL)
    # without friction, (11.8)
    assert float(friction_mesh_force(p, a, 0.0).resultant) == pytest.approx(
        p / math.cos(math.radians(a)), rel=REL
    )


@pytest.mark.parametrize("alpha_y", [5.0, 12.0, 19.0, 21.0, 28.0, 35.0])
def test_friction_ozols_21_16_by_torque_balance(alpha_y):
    # independent derivation: on the driver the normal force N (arm r_b) and the friction f N
    # (arm u = r_b tan alpha_y, the distance N1-S) balance the torque M1 = P r_w:
    # N (r_b -+ f u) = M1, minus in the approach (sliding towards the root), plus in the recess
    r_w, a, f, p = 50.0, 20.0, 0.1, 2000.0
    rb = r_w * math.cos(math.radians(a))
    u = rb * math.tan(math.radians(alpha_y))
    q = friction_mesh_force(p, a, f, alpha_y)
    sign = -1.0 if alpha_y < a else 1.0
    assert float(q.normal) * (rb + sign * f * u) == pytest.approx(p * r_w, rel=1e-12)
    assert bool(q.approach) == (alpha_y < a)


def test_mesh_forces_broadcast_over_arrays():
    # one formula for one pair and for many: the array call equals the scalar calls
    t = np.array([10.0, -20.0, 30.0])
    d = np.array([[40.0], [80.0]])
    f = mesh_forces(t, d, 21.0, 12.0)
    assert f.vector.shape == (2, 3, 3)
    one = mesh_forces(-20.0, 80.0, 21.0, 12.0)
    np.testing.assert_allclose(f.vector[1, 1], one.vector, rtol=1e-15)
    assert float(tangential_force(1.0, 2000.0)) == pytest.approx(1.0, rel=REL)


@settings(max_examples=40, deadline=None)
@given(
    forces=st.lists(st.tuples(*[st.floats(-1e4, 1e4)] * 3), min_size=1, max_size=4),
    zs=st.lists(st.floats(-200, 200), min_size=4, max_size=4),
    span=st.floats(10, 500),
)
def test_bearing_reactions_balance(forces, zs, span):
    # statics of a rigid shaft: forces and reactions sum to zero, and their moments about any
    # point leave only the torque about the shaft's axis
    f = np.array(forces)
    pts = np.array([[20.0, -5.0, z] for z in zs[: len(f)]])
    r, torque = bearing_reactions(f, pts, [0.0, span])
    assert np.allclose(f.sum(0) + r.sum(0), 0.0, atol=1e-9 * (1 + np.abs(f).sum()))
    where = np.array([[0, 0, 0.0], [0, 0, span]])
    m = np.cross(pts, f).sum(0) + np.cross(where, r).sum(0)
    scale = 1 + np.abs(f).sum() * (span + 300)
    assert np.allclose(m[:2], 0.0, atol=1e-9 * scale)
    assert m[2] / 1000 == pytest.approx(torque, rel=1e-12, abs=1e-12 * scale)
    assert abs(r[1, 2]) <= 1e-12 * scale  # the floating bearing takes no axial force


def test_rotate_forces_keeps_length_and_z():
    v = np.array([[3.0, 4.0, 5.0]])
    w = rotate_forces(v, 37.0)
    assert np.linalg.norm(w[0, :2]) == pytest.approx(5.0, rel=REL) and w[0, 2] == 5.0


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda: tangential_force(float("nan"), 10), "torque"),
        (lambda: tangential_force(1.0, 0.0), "diameter"),
        (lambda: mesh_forces(1.0, 10.0, 95.0), "working_pressure_angle"),
        (lambda: friction_mesh_force(1.0, 20.0, 1.5), "friction"),
        (lambda: bevel_mesh_forces(1.0, 10.0, 100.0, 90.0), "pitch_angle"),
        (lambda: bearing_reactions([[1.0, 0, 0]], [[0.0, 0, 0]], [5.0, 5.0]), "bearings"),
        (lambda: bearing_reactions([[1.0, 0]], [[0.0, 0]], [0.0, 5.0]), "forces"),
        (lambda: rotate_forces([1.0, 2.0], 3.0), "vectors"),
        (lambda: pair_forces(GearPair(Gear(20, 2), Gear(30, 2)), 0.0), "torque"),
        (lambda: pair_forces(GearPair(Gear(20, 2), Gear(30, 2)), "1"), "torque"),
        (lambda: pair_forces(HELICAL, 1.0, friction=0.1), "friction"),
    ],
)
def test_bad_input_names_the_value(call, name):
    with pytest.raises(GearError, match=name):
        call()


@settings(max_examples=60, deadline=None)
@given(
    torque=st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-10, 10)),
    d=st.floats(allow_nan=True, allow_infinity=True),
    a=st.floats(allow_nan=True, allow_infinity=True),
    b=st.floats(allow_nan=True, allow_infinity=True),
    f=st.floats(allow_nan=True, allow_infinity=True),
)
def test_property_finite_or_gear_error(torque, d, a, b, f):
    # every entry point: a finite answer or GearError, never NaN or a foreign exception
    for call in (
        lambda: mesh_forces(torque, d, a, b),
        lambda: bevel_mesh_forces(torque, d, a, b),
        lambda: friction_mesh_force(abs(torque), a, f, b),
        lambda: rotate_forces([torque, d, a], b),
        lambda: worm_mesh_forces(torque, d, a, b, f),
        lambda: worm_mesh_forces(torque, d, a, 20.0, f, "wheel"),
        lambda: worm_torque_forces(torque, f, d, 2 * d, a, b),
    ):
        try:
            out = call()
        except GearError:
            continue
        for arr in out if isinstance(out, tuple) else (out,):
            assert np.all(np.isfinite(np.asarray(arr, float)))


def test_pair_forces_figure():
    pytest.importorskip("matplotlib")
    import matplotlib.pyplot as plt

    from gears.figures.forces import pair_forces_figure

    pair = GearPair(Gear(20, 5), Gear(40, 5))
    fig = pair_forces_figure(pair_forces(pair, 100.0), pair.outlines(tolerance=0.05))
    assert len(fig.axes[0].texts) == 8 and "F_t 2000 N" in fig.axes[0].get_title()
    plt.close(fig)
    with pytest.raises(GearError, match="finite"):
        from gears.figures.forces import forces_figure

        forces_figure([], [(0.0, 0.0, float("nan"), 1.0, "x", "mesh")])


def test_thin_views_are_the_functions():
    # GearPair.forces and BevelPair.forces are pair_forces and bevel_pair_forces
    pair = GearPair(Gear(20, 5), Gear(40, 5))
    a, b = pair.forces(100.0, friction=0.05), pair_forces(pair, 100.0, 0.05)
    np.testing.assert_allclose(a.vectors, b.vectors, rtol=1e-15)
    bevel = BevelPair(20, 40, 3, 20)
    np.testing.assert_allclose(bevel.forces(-30.0).vectors, bevel_pair_forces(bevel, -30.0).vectors,
                               rtol=1e-15)  # fmt: skip
    assert "<table>" in a._repr_html_() and "tangential F_t" in str(a)


def test_pair_forces_figure_method():
    pytest.importorskip("matplotlib")
    import matplotlib.pyplot as plt

    from gears.figures.forces import pair_forces_figure

    pair = GearPair(Gear(20, 5), Gear(40, 5))
    fig = pair_forces_figure(pair.forces(100.0), pair.outlines(tolerance=0.05))
    assert len(fig.axes[0].texts) == 8
    plt.close(fig)


@pytest.mark.parametrize("hand", ["right", "left"])
@pytest.mark.parametrize("starts, q", [(1, 10), (2, 8), (4, 9)])
def test_worm_forces_against_the_efficiency(starts, q, hand):
    # frictionless: F_t1 = F_a1 tan gamma and F_r = F_a1 tan alpha_n / cos gamma (the normal
    # force is perpendicular to the thread); with friction the wheel's torque over the worm's
    # ideal one is the efficiency of Ozols (14.15) (worm driving) or its inverse (14.18)
    from gears import WormPair
    from gears.forces import worm_pair_forces

    pair = WormPair(starts, 40, 4, diameter_quotient=q, hand=hand)
    g, an = math.radians(pair.lead_angle), math.radians(pair.normal_pressure_angle)
    f = worm_pair_forces(pair, 12.0)
    assert f.tangential[0] == pytest.approx(f.axial[0] * math.tan(g), rel=1e-12)
    assert f.radial[0] == pytest.approx(f.axial[0] * math.tan(an) / math.cos(g), rel=1e-12)
    u = 40 / starts
    sign = 1.0 if hand == "right" else -1.0  # the wheel turns the other way about +y
    assert f.torque_2 == pytest.approx(sign * 12.0 * u, rel=1e-12)
    for driving in ("worm", "wheel"):
        fr = worm_pair_forces(pair, 12.0, 0.04, driving)
        eta = pair.efficiency(0.04, driving)
        ideal = sign * 12.0 * u
        expected = ideal * eta if driving == "worm" else ideal / eta
        assert fr.torque_2 == pytest.approx(expected, rel=1e-12)
    # the normal force is perpendicular to the thread (lead angle gamma, its hand)
    bw = g if hand == "right" else -g
    thread = np.array([0.0, math.cos(bw), math.sin(bw)])
    assert abs(np.dot(f.vectors[0], thread)) < 1e-9 * f.normal[0]


@pytest.mark.parametrize("driving", ["worm", "wheel"])
@pytest.mark.parametrize("gamma, mu, an", [(11.309932, 0.05, 20.0), (30.0, 0.1, 15.0),
                                           (5.0, 0.02, 25.0)])  # fmt: skip
def test_worm_torque_forces_is_worm_mesh_forces_read_backwards(driving, gamma, mu, an):
    # independent route: worm_mesh_forces builds the force from W and the friction mu W along
    # the thread (DIN 3996); its wheel torque T_2 = F_a1 d_2 / 2000 and the worm's torque
    # given back to worm_torque_forces must give the same force, W and F_r
    d1, d2, t1 = 50.0, 200.0, 12.0
    f = worm_mesh_forces(t1, d1, gamma, an, mu, driving)
    t2 = float(f.axial) * d2 / 2000.0
    g = worm_torque_forces(t1, t2, d1, d2, gamma, an)
    for a, b in zip(f, g, strict=True):
        np.testing.assert_allclose(b, a, rtol=1e-12)


def test_worm_torque_forces_locked_pair_driven_backwards():
    # Ozols (14.18) with gamma < phi': a self-locking pair lowered by pushing its worm round.
    # Hand derivation (DIN 3996 components with the friction of the wheel driving): tan gamma
    # = 1/16, mu 0.06, alpha_n 20 deg, T_2 = 24.5 N m at d_2 = 160 mm: F_a1 = 2000 T_2 / d_2
    # = 306.25 N, W = F_a1 / (cos a_n cos g + mu sin g) = 325.24 N, F_t1 = W (cos a_n sin g -
    # mu cos g) = -0.412 N (the worm's torque reverses: -0.0132 N m at d_1 = 64 mm)
    g, an, mu = math.atan(1 / 16), math.radians(20), 0.06
    fa = 2000 * 24.5 / 160
    w = fa / (math.cos(an) * math.cos(g) + mu * math.sin(g))
    ft = w * (math.cos(an) * math.sin(g) - mu * math.cos(g))
    assert ft < 0 and w == pytest.approx(325.24, abs=0.005)
    f = worm_torque_forces(ft * 64 / 2000, 24.5, 64.0, 160.0, math.degrees(g))
    assert float(f.normal) == pytest.approx(w, rel=1e-12)
    assert float(f.radial) == pytest.approx(w * math.sin(an), rel=1e-12)
    np.testing.assert_allclose(f.vector, [-w * math.sin(an), -ft, fa], rtol=1e-12)
    # the same torques through worm_mesh_forces are refused (the wheel cannot drive it)
    with pytest.raises(GearError, match="self-locking"):
        worm_mesh_forces(abs(ft) * 64 / 2000, 64.0, math.degrees(g), 20.0, mu, "wheel")
    # torques that would pull the flanks apart are refused, naming them
    with pytest.raises(GearError, match="torque = -50 N m"):
        worm_torque_forces(-50.0, 1.0, 64.0, 160.0, 3.0)


def test_worm_self_locking_wheel_cannot_drive():
    from gears import WormPair
    from gears.forces import worm_pair_forces

    pair = WormPair(1, 40, 4, diameter_quotient=12)  # gamma = 4.76 deg
    with pytest.raises(GearError, match="self-locking"):
        worm_pair_forces(pair, 5.0, 0.1, "wheel")
    with pytest.raises(GearError, match="driving"):
        worm_pair_forces(pair, 5.0, 0.1, "nobody")


def test_worm_pair_forces_name_the_driving_member():
    # PairForces.driving: "worm" or "wheel" for a worm pair, None for the other kinds; the
    # table heads its columns worm and wheel and names the driving member in its title. The
    # value by hand (Ozols (14.18), the wheel driving: F_a1 = F_t1 / tan(gamma - phi'),
    # tan gamma = z_1 / q = 0.1, tan phi' = mu / cos alpha_n, F_t1 = 2000 T_1 / d_m1 = 400 N)
    from gears import WormPair
    from gears.forces import worm_pair_forces

    pair = WormPair(1, 40, 5, diameter_quotient=10)
    phi = math.atan(0.05 / math.cos(math.radians(20.0)))
    for driving, sign in (("worm", 1.0), ("wheel", -1.0)):
        f = worm_pair_forces(pair, 10.0, 0.05, driving)
        assert f.driving == driving
        assert float(f.axial[0]) == pytest.approx(400.0 / math.tan(math.atan(0.1) + sign * phi),
                                                  rel=1e-12)  # fmt: skip
        title, heads = str(f).splitlines()[:2]
        assert f"the {driving} driving" in title and heads.split() == ["worm", "wheel"]
        assert "<th>worm</th>" in f._repr_html_().replace(" ", "")
    spur = GearPair(Gear(20, 2), Gear(40, 2)).forces(50.0)
    assert spur.driving is None and str(spur).splitlines()[1].split() == ["gear", "1", "gear", "2"]


@pytest.mark.parametrize("x", [-6.0, -2.0, 0.5, 3.0, 7.0])
def test_friction_joldasbekov_7_65_7_67(x):
    # Joldasbekov (7.65), (7.67): N21 = M1 / [r1 cos a -+ f (r1 sin a -+ x)], x the distance of
    # the contact point from the pitch point along the line of action (approach before it)
    r1, a, f, m1 = 50.0, math.radians(20), 0.08, 100.0  # mm, rad, -, N m
    approach = x < 0
    arm = r1 * math.sin(a) + x  # N1 to the contact point, mm (x < 0 in the approach)
    den = r1 * math.cos(a) - f * arm if approach else r1 * math.cos(a) + f * arm
    n21 = 1000 * m1 / den
    rb = r1 * math.cos(a)
    alpha_y = math.degrees(math.atan(arm / rb))
    q = friction_mesh_force(1000 * m1 / r1, 20.0, f, alpha_y)
    assert float(q.normal) == pytest.approx(n21, rel=1e-12)
    assert float(q.friction) == pytest.approx(f * n21, rel=1e-12)


def test_joldasbekov_mesh_force_constant():
    # Joldasbekov, the mesh force P = 97400 N / (n r0) (kgf from kW, rpm, cm; the constant is
    # 60 * 100 * 1000 / (2 pi g) = 97 376 rounded): 10 kW at 1000 rpm on r0 = 5 cm
    p_kgf = 97400 * 10 / (1000 * 5)
    torque = 10e3 / (2 * math.pi * 1000 / 60)  # N m
    assert float(tangential_force(torque, 100.0)) == pytest.approx(p_kgf * 9.80665, rel=3e-4)


@settings(max_examples=40, deadline=None)
@given(
    torque=st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-5, 5)),
    friction=st.one_of(st.floats(-1, 2), st.just(float("nan"))),
    mass=st.floats(allow_nan=True, allow_infinity=True),
    speed=st.floats(allow_nan=True, allow_infinity=True),
)
def test_property_views_finite_or_gear_error(torque, friction, mass, speed):
    # the pair views and the centrifugal force: a finite answer or GearError, never NaN
    from gears import WormPair
    from gears.forces import centrifugal_force, worm_pair_forces

    calls = (
        lambda: pair_forces(GearPair(Gear(20, 5), Gear(40, 5)), torque, friction),
        lambda: bevel_pair_forces(BevelPair(20, 40, 3, 20), torque),
        lambda: worm_pair_forces(WormPair(1, 40, 5, diameter_quotient=10), torque, friction),
        lambda: centrifugal_force(mass, speed, 57.0),
    )
    for call in calls:
        try:
            out = call()
        except GearError:
            continue
        values = (out.vectors, out.normal, out.torque_2) if hasattr(out, "vectors") else (out,)
        for v in values:
            assert np.all(np.isfinite(np.asarray(v, float)))


def test_worm_pair_forces_view_is_the_formula():
    # WormPair.forces is the thin view of gears.forces.worm_pair_forces (same numbers), and its
    # tangential force on the worm is F_t1 = 2000 T / d_1 (DIN 3996; worm W1: z1 2, q 10, m 5)
    from gears import WormPair
    from gears.forces import worm_pair_forces

    pair = WormPair(2, 40, 5, diameter_quotient=10)
    view = pair.forces(12.0, 0.05)
    formula = worm_pair_forces(pair, 12.0, 0.05)
    assert view.rows() == formula.rows()
    d1 = pair.worm_diameter  # q m = 50 mm
    assert abs(view.tangential[0] - 2000 * 12.0 / d1) < 1e-9 * 2000 * 12.0 / d1
