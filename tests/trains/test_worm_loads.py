"""Worm meshes in a train's loads (trains/loading.py, trains/crossing.py): forces in 3D.

Sources: Ozols (14.15) and (14.18) (F_t1 = F_a1 tan(gamma +- phi'), tan phi' = mu / cos alpha_n)
and the DIN 3996 / ISO/TR 14521 components of the normal force W and the friction mu W along
the thread (F_t1 = W (cos a_n sin g +- mu cos g), F_a1 = W (cos a_n cos g -+ mu sin g),
F_r = W sin a_n), written out by hand in the tests; gears.forces.worm_mesh_forces, which
builds the force from the friction rather than from the torques (an independent route);
statics derived independently with numpy (the sum of the forces and of their moments on every
shaft, its bearings included, vanishes); kinematics: the velocities of the two members'
material points at the pitch point from the power flow's speeds about the axes the drawing
gives them: the friction mu W lies along their relative sliding, against the worm's.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import Gear, GearError, WormPair
from gears.forces import worm_mesh_forces
from trains import Train, TrainError, loads

MU = 0.06  # the hoist example's friction (bronze on hardened steel, well lubricated)
SPUR = {"pinion-drum": 0.98}


def _sliding(ld, name="worm-wheel"):
    """The worm's velocity relative to the wheel at the pitch point (independent kinematics)."""
    mesh = ld.meshes[name]
    worm, wheel = (ld.members[m] for m in mesh.members)
    p = mesh.points[worm.name][0]
    v1 = ld.flow.speeds[worm.name] * np.cross(worm.axis, p - worm.position)
    v2 = ld.flow.speeds[wheel.name] * np.cross(wheel.axis, p - wheel.position)
    return v1 - v2


def _assert_balance(ld, bearings):
    """Every shaft: its mesh forces, its bearings' reactions and its torque balance, forces and
    moments about its first bearing (numpy, independent of the library's route)."""
    scale = max(1.0, max(float(np.abs(m.force).max()) for m in ld.members.values()))
    for name, (za, zb) in bearings.items():
        m = ld.members[name]
        a, b = m.position + za * m.axis, m.position + zb * m.axis
        forces = [f for mesh in ld.meshes.values() for f in mesh.forces.get(name, [])]
        points = [p for mesh in ld.meshes.values() for p in mesh.points.get(name, [])]
        ra, rb = m.reactions
        total = np.sum(forces, axis=0) + ra + rb
        np.testing.assert_allclose(total, 0.0, atol=1e-9 * scale)
        moment = sum(np.cross(p - a, f) for p, f in zip(points, forces, strict=True))
        moment = moment + np.cross(b - a, rb) + 1000.0 * m.torque * m.axis  # N mm
        np.testing.assert_allclose(moment, 0.0, atol=1e-9 * scale * 1e3)
        assert abs(np.dot(rb, m.axis)) <= 1e-9 * scale  # B floats: A takes the thrust
    for m in ld.members.values():
        assert m.moment + m.torque == pytest.approx(0.0, abs=1e-9 * scale)
        np.testing.assert_allclose(m.force + m.bearing, 0.0, atol=1e-12 * scale)
    for mesh in ld.meshes.values():
        if mesh.forces:  # Newton's third law
            f1, f2 = mesh.forces.values()
            np.testing.assert_allclose(f1, -f2, atol=1e-12 * scale)
    held = [m.bearing for m in ld.members.values() if m.carried_by == "frame"]
    np.testing.assert_allclose(np.sum(held, axis=0), 0.0, atol=1e-9 * scale)


def test_hoist_holds_its_load_backwards(worm_hoist):
    # The gallery's self-locking hoist (z1 1, q 16, m 4, z2 40; gamma 3.576 deg < phi' 3.653
    # deg) lowering: the drum (100 N m) drives, the worm must be pushed round. Hand derivation
    # from Ozols (14.18) and DIN 3996 with the wheel driving: the spur stage gives the wheel
    # T_2 = 100 * 17/68 * 0.98 = 24.5 N m, so F_a1 = 2000 T_2 / d_2 = 2000 * 24.5 / 160 =
    # 306.25 N; W = F_a1 / (cos a_n cos g + mu sin g) = 325.24 N; F_t1 = W (cos a_n sin g -
    # mu cos g) = -0.412 N (= F_a1 tan(g - phi') < 0); F_r = W sin a_n = 111.24 N.
    worm = WormPair(1, 40, 4.0, diameter_quotient=16)
    ld = loads(worm_hoist(worm), "drum", "worm", torque=100.0, friction=MU, mesh_efficiency=SPUR)
    assert ld.flow.self_locking
    mesh = ld.meshes["worm-wheel"]
    assert mesh.kind == "worm" and mesh.driver == "wheel"
    g, an = math.atan(1 / 16), math.radians(20.0)
    phi = math.atan(MU / math.cos(an))
    fa = 2000 * 24.5 / 160
    w = fa / (math.cos(an) * math.cos(g) + MU * math.sin(g))
    ft = w * (math.cos(an) * math.sin(g) - MU * math.cos(g))
    assert ft == pytest.approx(fa * math.tan(g - phi), rel=1e-12)  # Ozols (14.18)
    assert w == pytest.approx(325.24, abs=0.005) and ft == pytest.approx(-0.412, abs=5e-4)
    assert mesh.axial[0] == pytest.approx(fa, rel=1e-12)  # the worm's thrust
    assert mesh.tangential == pytest.approx((abs(ft), fa), rel=1e-12)
    assert mesh.radial[0] == pytest.approx(w * math.sin(an), rel=1e-12)
    assert mesh.normal[0] == pytest.approx(w, rel=1e-12)
    # the worm's bearings carry the thrust along its axis and F_r, F_t1 across it
    worm_load = ld.members["worm"]
    assert abs(worm_load.axial_force) == pytest.approx(fa, rel=1e-12)
    assert worm_load.radial_load == pytest.approx(math.hypot(w * math.sin(an), ft), rel=1e-12)
    # the motor pushes the worm round: its torque F_t1 d_1 / 2000 is the power flow's, with
    # the sign of a torque that supplies power to the worm (not one that brakes it)
    assert abs(worm_load.torque) == pytest.approx(abs(ft) * 64 / 2000, rel=1e-9)
    assert worm_load.torque * ld.flow.speeds["worm"] > 0
    # the wheel's bearings: the worm's tangential force along its axis
    assert abs(ld.members["wheel"].axial_force) == pytest.approx(abs(ft), rel=1e-12)
    # the friction mu W lies along the sliding, against the worm's (independent kinematics)
    v = _sliding(ld)
    assert np.dot(mesh.forces["worm"][0], v) / np.linalg.norm(v) == pytest.approx(-MU * w, rel=1e-9)


@pytest.mark.parametrize("hand", ["right", "left"])
@pytest.mark.parametrize("starts, q", [(1, 16), (2, 10)])
@pytest.mark.parametrize("lifting", [True, False])
def test_forces_match_worm_mesh_forces(starts, q, hand, lifting, worm_hoist):
    # the train's force from the power flow's torques against gears.forces.worm_mesh_forces,
    # which builds it from the friction and the driving member (DIN 3996, Ozols (14.15)/(14.18))
    worm = WormPair(starts, 40, 4.0, diameter_quotient=q, hand=hand)
    ends = ("worm", "drum") if lifting else ("drum", "worm")
    ld = loads(worm_hoist(worm), *ends, torque=100.0, friction=MU, mesh_efficiency=SPUR)
    mesh = ld.meshes["worm-wheel"]
    driving = mesh.driver
    assert driving == ("worm" if lifting else "wheel")
    if driving == "wheel" and worm.self_locking(MU):
        return  # worm_mesh_forces refuses it; test_hoist_holds_its_load_backwards checks it
    t1 = abs(ld.members["worm"].torque)
    ref = worm_mesh_forces(t1, worm.worm_diameter, worm.lead_angle, 20.0, MU, driving)
    assert mesh.tangential[0] == pytest.approx(float(ref.tangential), rel=1e-9)
    assert mesh.axial[0] == pytest.approx(float(ref.axial), rel=1e-9)
    assert mesh.tangential[1] == pytest.approx(float(ref.axial), rel=1e-9)  # F_t2 = F_a1
    assert mesh.radial[0] == pytest.approx(float(ref.radial), rel=1e-9)
    assert mesh.normal[0] == pytest.approx(float(ref.normal), rel=1e-9)
    # the worm's axial force is the wheel's tangential force: along the worm's axis it is the
    # force on the wheel across the line of centres in the wheel's plane
    f = mesh.forces["worm"][0]
    worm_axis = ld.members["worm"].axis
    assert abs(np.dot(f, worm_axis)) == pytest.approx(mesh.tangential[1], rel=1e-12)
    v = _sliding(ld)
    assert np.dot(f, v) / np.linalg.norm(v) == pytest.approx(-MU * mesh.normal[0], rel=1e-9)
    bearings = {"worm": (-70.0, 55.0), "wheel": (-30.0, 45.0), "drum": (0.0, 80.0)}
    ld = loads(worm_hoist(worm), *ends, torque=100.0, friction=MU, mesh_efficiency=SPUR,
               axial={"worm-wheel": 12.0}, angles={"worm-wheel": 130.0},
               bearings=bearings)  # fmt: skip
    _assert_balance(ld, bearings)


def test_hands_mirror_and_frictionless_force_is_normal_to_the_sliding():
    # a left-hand pair is the mirror image of the right-hand one: the same magnitudes; with
    # no friction the force is perpendicular to the sliding (it lies along the flank's normal)
    out = []
    for hand in ("right", "left"):
        t = Train()
        t.mesh("worm", "wheel", pair=WormPair(3, 31, 2.5, diameter_quotient=9, hand=hand))
        ld = loads(t, "worm", "wheel", torque=7.0, angles={"worm-wheel": 40.0})
        mesh = ld.meshes["worm-wheel"]
        v = _sliding(ld)
        f = mesh.forces["worm"][0]
        assert abs(np.dot(f, v)) <= 1e-12 * np.linalg.norm(f) * np.linalg.norm(v)
        out.append((mesh.tangential, mesh.radial, mesh.axial, mesh.normal))
    np.testing.assert_allclose(out[0], out[1], rtol=1e-12)


def test_a_motor_coupled_to_the_worm_shares_its_axis(worm_hoist):
    # a member that turns with the worm lies on the worm's axis (across the plane)
    t = worm_hoist(WormPair(2, 40, 4.0, diameter_quotient=10))
    t.couple("motor", "worm")
    ld = loads(t, "motor", "drum", torque=50.0, friction=MU, mesh_efficiency=SPUR)
    motor, worm = ld.members["motor"], ld.members["worm"]
    np.testing.assert_allclose(motor.axis, worm.axis, atol=0)
    np.testing.assert_allclose(motor.position, worm.position, atol=0)
    # across the plane: z x e has no z component (1e-15: one rounding of a unit vector)
    assert abs(np.dot(worm.axis, [0.0, 0.0, 1.0])) <= 1e-15


def test_shifted_wheel_balances_both_members():
    # a shifted wheel (x_2 0.5): the wheel's arm is a - d_m1 / 2 (DIN 3996's d_m2), and each
    # member still balances its power-flow torque
    t = Train()
    t.mesh("worm", "wheel", pair=WormPair(2, 30, 3.0, diameter_quotient=11, profile_shift=0.5))
    bearings = {"worm": (-40.0, 40.0), "wheel": (-20.0, 20.0)}
    for ends in (("worm", "wheel"), ("wheel", "worm")):
        ld = loads(t, *ends, torque=20.0, friction=0.03, bearings=bearings)
        _assert_balance(ld, bearings)


def _cascade() -> Train:
    t = Train()
    t.mesh("w1", "k1", pair=WormPair(1, 30, 2.0))
    t.couple("k1", "w2")
    t.mesh("w2", "k2", pair=WormPair(1, 40, 3.0))
    return t


def test_ambiguous_worm_axes_are_refused():
    # a worm on the axis of another worm's wheel (two worm reducers in series) would turn the
    # second worm's axis out of the plane; a worm shaft that also carries a spur pinion would
    # need its axis both across and in the plane: refused, naming the mesh and the members
    with pytest.raises(TrainError, match=r"worm mesh 'w2-k2'.*'k1'.*ambiguous"):
        loads(_cascade(), "w1", "k2", torque=1.0)
    t = Train()
    t.mesh("worm", "wheel", pair=WormPair(1, 30, 2.0))
    t.couple("worm", "pinion")
    t.mesh("pinion", "gear", gears=(Gear(20, 2), Gear(40, 2)))
    with pytest.raises(TrainError, match=r"worm mesh 'worm-wheel'.*'pinion'.*parallel"):
        loads(t, "pinion", "wheel", torque=1.0)
    # one worm driving two wheels, a worm on its own wheel's axis, a worm on a carrier
    t = Train()
    t.mesh("worm", "k1", pair=WormPair(1, 30, 2.0))
    t.mesh("worm", "k2", pair=WormPair(1, 30, 2.0))
    with pytest.raises(TrainError, match=r"worm mesh 'worm-k2'.*mesh 'worm-k1'.*ambiguous"):
        loads(t, "worm", "k1", torque=1.0)
    t = Train()
    t.mesh("worm", "k1", pair=WormPair(1, 30, 2.0))
    t.coaxial("worm", "k1")
    with pytest.raises(TrainError, match=r"the wheel 'k1' of its own mesh"):
        loads(t, "worm", "k1", torque=1.0)
    t = Train()
    t.mesh("worm", "wheel", pair=WormPair(1, 30, 2.0), carrier="arm")
    t.mesh("sun", "wheel", teeth=(20, 30), carrier="arm")
    with pytest.raises(TrainError, match=r"worm mesh 'worm-wheel' rides on the carrier 'arm'"):
        loads(t, "worm", "sun", fixed=["arm"], torque=1.0, module=2.0)


@settings(max_examples=30, deadline=None)
@given(
    starts=st.integers(1, 6),
    teeth=st.integers(20, 80),
    q=st.floats(6.0, 20.0),
    shift=st.floats(-0.5, 0.5),
    hand=st.sampled_from(["right", "left"]),
    friction=st.one_of(st.none(), st.floats(0.0, 0.2)),
    torque=st.floats(-1e5, 1e5).filter(lambda x: abs(x) > 1e-6),
    angle=st.floats(-360.0, 360.0),
    lifting=st.booleans(),
)
def test_property_worm_loads(
    starts, teeth, q, shift, hand, friction, torque, angle, lifting, worm_hoist
):
    # any worm hoist in either direction: a finite answer or the library's own error, and
    # statics that balance on every shaft
    try:
        worm = WormPair(starts, teeth, 4.0, diameter_quotient=q, profile_shift=shift, hand=hand)
    except GearError:
        return
    ends = ("worm", "drum") if lifting else ("drum", "worm")
    bearings = {"worm": (-50.0, 60.0), "wheel": (-25.0, 35.0)}
    try:
        ld = loads(worm_hoist(worm), *ends, torque=torque, friction=friction, mesh_efficiency=SPUR,
                   angles={"worm-wheel": angle}, axial={"worm-wheel": 8.0},
                   bearings=bearings)  # fmt: skip
    except TrainError:
        return
    for m in ld.members.values():
        assert np.all(np.isfinite(m.force)) and math.isfinite(m.moment)
        assert np.all(np.isfinite(m.reactions)) if m.reactions is not None else True
    _assert_balance(ld, bearings)


@settings(max_examples=30, deadline=None)
@given(
    torque=st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-10, 10)),
    angle=st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.text(max_size=2)),
    axial=st.floats(allow_nan=True, allow_infinity=True),
)
def test_property_bad_options_are_train_errors(torque, angle, axial, worm_hoist):
    # bad numbers for a worm train's options: the library's own error naming the value
    t = worm_hoist(WormPair(2, 40, 4.0))
    try:
        ld = loads(t, "worm", "drum", torque=torque, angles={"worm-wheel": angle},
                   axial={"worm-wheel": axial})  # fmt: skip
    except TrainError as exc:
        assert any(k in str(exc) for k in ("torque", "angles", "axial", "input"))
        return
    assert all(np.all(np.isfinite(m.force)) for m in ld.members.values())


@settings(max_examples=40, deadline=None)
@given(
    theta=st.floats(0.0, 360.0),
    forces=st.lists(
        st.tuples(*[st.floats(-1e6, 1e6)] * 3, *[st.floats(-500.0, 500.0)] * 3),
        min_size=1,
        max_size=4,
    ),
    za=st.floats(-300.0, 300.0),
    zb=st.floats(-300.0, 300.0),
)
def test_property_reactions_of_a_shaft_across_the_plane(theta, forces, za, zb):
    # any shaft axis in the plane (a worm's): the two reactions balance the forces and their
    # moments about the first bearing but for the torque about the axis (independent numpy
    # statics), or the library's own error naming the bearings
    from trains.crossing import axis_reactions, moment_about

    th = math.radians(theta)
    axis = np.array([math.cos(th), math.sin(th), 0.0])
    f = np.array([row[:3] for row in forces], float)
    p = np.array([row[3:] for row in forces], float)
    try:
        r = axis_reactions(f, p, (za, zb), axis)
    except GearError as exc:
        assert "bearings" in str(exc)
        return
    assert np.all(np.isfinite(r))
    scale = max(1.0, float(np.abs(f).max()), float(np.abs(r).max()))  # round-off of the turn
    np.testing.assert_allclose(f.sum(axis=0) + r.sum(axis=0), 0.0, atol=1e-7 * scale)
    a, b = za * axis, zb * axis
    m = sum(np.cross(pi - a, fi) for pi, fi in zip(p, f, strict=True)) + np.cross(b - a, r[1])
    torque = sum(moment_about(pi, fi, axis) for pi, fi in zip(p, f, strict=True))
    reach = max(1.0, float(np.abs(p).max()), abs(za), abs(zb))
    np.testing.assert_allclose(m - torque * axis, 0.0, atol=1e-7 * scale * reach)
    assert abs(np.dot(r[1], axis)) <= 1e-9 * scale  # B floats


def test_a_moment_past_floats_range_names_the_force_and_its_arm():
    # 1e200 N at 1e200 mm: the moment 1e400 N mm is past float's largest (about 1.8e308)
    from trains.crossing import moment_about

    z = np.array([0.0, 0.0, 1.0])
    with pytest.raises(TrainError, match=r"force of 1e\+200 N at 1e\+200 mm.*overflows"):
        moment_about(np.array([1e200, 0.0, 0.0]), np.array([0.0, 1e200, 0.0]), z)
    across = np.array([1.0, 0.0, 0.0])  # a worm's axis: the other branch
    with pytest.raises(TrainError, match=r"force of 1e\+200 N at 1e\+200 mm"):
        moment_about(np.array([0.0, 1e200, 0.0]), np.array([0.0, 0.0, 1e200]), across)
