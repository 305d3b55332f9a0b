"""gears.bevel.rating, BevelPair.rating, Differential.rating: ISO 10300 method B1 (issue 30).

Sources: the limit of a very long cone distance (a shaft angle of 0.5 deg: the pitch angles go to
0, z_v to z and the bevel pair to a spur pair of the mean module), rated here independently: the
ISO 10300-2/-3 method B1 stresses written in this test from the standard's equations on the spur
pair's own geometry (d, d_a, d_b, eps_alpha of a cylindrical GearPair), with the factors ISO
10300 shares with ISO 6336 taken from that spur pair's ISO 6336 rating; the force at the mean cone
F_mt = 2000 T / d_m (ISO 10300-1); the statics of a differential (the case torque split equally,
Ozols §13). The factors themselves are checked against ISO/TR 10300-30 in
tests/gears/test_bevel_iso10300.py.
"""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import BevelPair, BevelRating, Gear, GearPair
from gears.bevel.iso10300 import BEVEL_FACTOR, MOUNTING_FACTORS
from gears.bevel.rating import BEVEL_FACTORS, BEVEL_QUANTITIES
from gears.errors import GearError
from trains import Differential
from trains.errors import TrainError


def _iso10300_on(spur: GearPair, torque, speed, k_be, w=0.85, life=10000.0):
    """ISO 10300 method B1 on a cylindrical spur pair, written from the standard's equations
    (ISO 10300-1 Annex A, ISO 10300-2 and -3 method B1) independently of gears.bevel."""
    g1, g2 = spur.g1, spur.g2
    m, a = g1.module, math.radians(g1.pressure_angle)
    b = g1.face_width
    kh = 1.5 * k_be
    c = spur.rating(torque, speed, life=life, K_Hbeta=kh, K_Fbeta=kh)  # the shared factors
    f = c.factors
    eps = spur.contact_ratio
    p = math.pi * m * math.cos(a)
    # the middle line: the inner point of single contact, g/2 - p from the zone's centre; the
    # contact pattern's ellipse over b_eff = w b shortens it
    r = (eps * p / 2 - p) / (eps * p / 2)
    k = 1 - math.sqrt(w)
    l_bm = w * b * (1 - math.sqrt(r * r + k * k * (1 - r * r)))
    d1, d2 = g1.reference_diameter, g2.reference_diameter
    rho = math.sin(a) * d1 * d2 / (2 * (d1 + d2))
    da1, da2, db1, db2 = g1.tip_diameter, g2.tip_diameter, g1.base_diameter, g2.base_diameter
    z_mb = math.tan(a) / math.sqrt(
        (math.sqrt((da1 / db1) ** 2 - 1) - 2 * math.pi / g1.teeth)
        * (math.sqrt((da2 / db2) ** 2 - 1) - 2 * (eps - 1) * math.pi / g2.teeth)
    )
    f_mt = 2000 * torque / d1
    s_h = (math.sqrt(f_mt / math.cos(a) / (l_bm * rho)) * z_mb * f["Z_E"]
           * math.sqrt(f["K_A"] * f["K_v"] * kh * f["K_Halpha"]))  # fmt: skip
    s_hp = [s * BEVEL_FACTOR for s in c.stresses["sigma_HP"]]
    # root: the load at the tip (tan of the tip pressure angle, ISO 6336-3's h_Fe at d_a)
    y_eps = 0.25 + 0.75 / eps
    out = {"S_H": [hp / s_h for hp in s_hp], "S_F": [], "c": c, "l_bm": l_bm, "Z_M-B": z_mb}
    for i, g in enumerate((g1, g2)):
        x, hf, rh = g.profile_shift, g.rack.dedendum, g.rack.root_radius
        e = math.pi / 4 - hf * math.tan(a) - (1 - math.sin(a)) * rh / math.cos(a)
        gg = rh - hf + x
        h = 2 / g.teeth * (math.pi / 2 - e) - math.pi / 3
        th = math.pi / 6
        for _ in range(60):  # the standard's fixed point, iterated to convergence
            th = 2 * gg / g.teeth * math.tan(th) - h
        s_fn = m * (g.teeth * math.sin(math.pi / 3 - th) + math.sqrt(3) * (gg / math.cos(th) - rh))
        rho_f = m * (rh + 2 * gg * gg / (math.cos(th) * (g.teeth * math.cos(th) ** 2 - 2 * gg)))
        a_an = math.acos(g.base_diameter / g.tip_diameter)
        inv = lambda t: math.tan(t) - t  # noqa: E731
        gam = (math.pi / 2 + 2 * x * math.tan(a)) / g.teeth + inv(a) - inv(a_an)
        a_fan = a_an - gam
        arm = (math.cos(gam) - math.sin(gam) * math.tan(a_fan)) * g.tip_diameter / m
        h_fa = m / 2 * (arm - g.teeth * math.cos(math.pi / 3 - th) - gg / math.cos(th) + rh)
        y_fa = 6 * h_fa / m * math.cos(a_fan) / ((s_fn / m) ** 2 * math.cos(a))
        la, qs = s_fn / h_fa, s_fn / (2 * rho_f)
        y_sa = (1.2 + 0.13 * la) * qs ** (1 / (1.21 + 2.3 / la))
        s_f = f_mt / (b * m) * y_fa * y_sa * y_eps * f["K_A"] * f["K_v"] * kh * f["K_Falpha"]
        out["S_F"].append(c.stresses["sigma_FP"][i] / s_f)
    return out


@pytest.mark.parametrize("mounting", ["both-straddle", "neither-straddle"])
def test_long_cone_distance_rates_like_its_cylindrical_pair(mounting):
    bevel = BevelPair(20, 40, module=3, face_width=15, shaft_angle=0.5)
    vp = bevel.virtual_pair
    r = bevel.rating(50.0, 1500.0, mounting=mounting, life=10000.0)
    assert isinstance(r, BevelRating)
    # the cylindrical pair of the mean module with integer teeth, as cut by the same rack
    mm = bevel.mean_module
    spur = GearPair(Gear(20, mm, rack=vp.g1.rack, face_width=15),
                    Gear(40, mm, rack=vp.g2.rack, face_width=15), tip_shortening=False)  # fmt: skip
    k_be = MOUNTING_FACTORS["light-load"][mounting]
    ref = _iso10300_on(spur, 50.0, 1500.0, k_be)
    # z_v = z / cos delta with delta1 = 0.167 deg: 4e-6 apart; the rest is the same formula
    for a, b in zip(r.safety_pitting, ref["S_H"], strict=True):
        assert a == pytest.approx(b, rel=1e-4)
    for a, b in zip(r.safety_bending, ref["S_F"], strict=True):
        assert a == pytest.approx(b, rel=1e-4)
    assert r.quantities["l_bm"] == pytest.approx(ref["l_bm"], rel=1e-4)
    assert r.factors["Z_M-B"] == pytest.approx(ref["Z_M-B"], rel=1e-4)
    # what ISO 10300 shares with ISO 6336 is the cylindrical pair's, and its Z_M-B is Z_B there
    c = ref["c"]
    for s in ("K_v", "K_Halpha", "Z_E", "Z_L", "Z_v", "Z_R", "Y_deltarelT", "Y_X"):
        for u, v in zip(*(x if isinstance(x, tuple) else (x,) for x in
                          (r.factors[s], c.factors[s])), strict=True):  # fmt: skip
            assert u == pytest.approx(v, rel=1e-4)
    assert r.factors["Z_M-B"] == pytest.approx(c.factors["Z_B"], rel=1e-4)
    # against ISO 6336's own root stress (the load at the outer point of single contact with
    # Y_epsilon = 1): the tip load with Y_epsilon of ISO 10300-3 comes within 12 %
    for a, b in zip(r.safety_bending, c.safety_bending, strict=True):
        assert a == pytest.approx(b, rel=0.12)


def test_virtual_pinion_carries_the_mean_cone_force():
    bevel = BevelPair(18, 45, module=4, face_width=25)
    r = bevel.rating(120.0, 900.0)
    d_m1 = bevel.geometry.mean_diameter[0]
    # F_mt = 2000 T / d_m1 (ISO 10300-1); the real pinion's load cycles 60 n L
    q = r.quantities
    assert q["F_mt"] == pytest.approx(2000 * 120.0 / d_m1, rel=1e-9)
    assert r.virtual.quantities["F_t"] == pytest.approx(q["F_mt"], rel=1e-9)
    assert q["F_n"] == pytest.approx(q["F_mt"] / math.cos(math.radians(20.0)), rel=1e-12)
    assert q["N_L"][0] == pytest.approx(60 * 900.0 * 20000.0, rel=1e-12)
    assert q["N_L"][1] == pytest.approx(60 * 900.0 * 20000.0 * 18 / 45, rel=1e-12)
    assert r.settings["torque"] == pytest.approx(120.0, rel=1e-15)
    # S = sigma_P / sigma with sigma_HP = sigma_HP(ISO 6336) Z_K
    s = r.stresses
    for i in (0, 1):
        assert r.safety_pitting[i] == pytest.approx(s["sigma_HP"][i] / s["sigma_H"], rel=1e-12)
        assert s["sigma_HP"][i] == pytest.approx(
            r.virtual.stresses["sigma_HP"][i] * BEVEL_FACTOR, rel=1e-12
        )
        assert r.safety_bending[i] == pytest.approx(s["sigma_FP"][i] / s["sigma_F"][i], rel=1e-12)
    assert set(r.factors) == {f[0] for f in BEVEL_FACTORS}
    assert set(r.quantities) == {q[0] for q in BEVEL_QUANTITIES}
    text = str(r)
    assert "ISO 10300 method B1" in text and "Z_M-B" in text and "Y_Fa" in text
    assert "<table>" in r._repr_html_()
    assert repr(r).startswith("BevelRating(S_H = ")


def test_mounting_and_pattern_scale_the_stresses():
    bevel = BevelPair(20, 40, module=3, face_width=20)
    a = bevel.rating(50, 1500, mounting="both-straddle", pattern="full-load")
    b = bevel.rating(50, 1500, mounting="neither-straddle", pattern="estimated")
    # sigma_H ~ sqrt(K_Hbeta K_Halpha), sigma_F ~ K_Fbeta K_Falpha (K_Halpha depends on K_Hbeta)
    kh = (1.5 * 1.5 * b.factors["K_Halpha"]) / (1.5 * 1.0 * a.factors["K_Halpha"])
    assert b.stresses["sigma_H"] / a.stresses["sigma_H"] == pytest.approx(math.sqrt(kh))
    assert b.factors["K_Hbeta"] == pytest.approx(2.25, rel=1e-12)
    assert a.factors["K_Hbeta-be"] == pytest.approx(1.0, rel=1e-12)


def test_differential_rating_is_its_pair_under_the_split_torque():
    d = Differential(side=16, pinion=10, n_pinions=2, module=3, gleason=True)
    r = d.rating(torque=150, left=90, right=110)
    spin = abs(float(d.solve(left=90, right=110).relative("pinion", "case")))
    # statics: 150 N m on the case, 75 on each side gear, shared by 2 pinions; on the pinion
    # the side gear's torque times z_p / z_s
    direct = d.pair.rating(150 / 2 / 2 * 10 / 16, spin, contacts=(1, 2), idler=(True, False))
    assert list(r) == ["pinion-right", "pinion-left"]
    assert isinstance(r["pinion-left"], BevelRating)
    assert r["pinion-left"].safety_pitting[0] == pytest.approx(direct.safety_pitting[0], rel=1e-12)
    assert r["pinion-right"].safety_bending[1] == pytest.approx(direct.safety_bending[1], rel=1e-12)
    # the pinion is an idler (both flanks loaded): Y_M = 0.7 of ISO 6336-5 on its root
    assert r["pinion-left"].factors["Y_M"][0] == pytest.approx(0.7, rel=1e-12)
    with pytest.raises(TrainError, match="do not turn"):
        d.rating(torque=150, left=100, right=100)


@pytest.mark.parametrize(
    "args, kw, match",
    [
        ((0.0, 1000.0), {}, "torque"),
        ((10.0, math.inf), {}, "speed"),
        ((10.0, 1000.0), {"life": -1.0}, "life"),
        ((10.0, 1000.0), {"mounting": "bolted"}, "mounting"),
        ((10.0, 1000.0), {"pattern": "guessed"}, "pattern"),
        ((10.0, 1000.0), {"effective_width": 1.5}, "effective_width"),
        ((10.0, 1000.0), {"effective_width": "all"}, "effective_width"),
        ((10.0, 1000.0), {"Z_NT": 1.0}, "Z_NT"),
        ((10.0, 1000.0), {"material": ("case-carburized",) * 3}, "material"),
    ],
)
def test_bevel_rating_bad_input(args, kw, match):
    with pytest.raises(GearError, match=match):
        BevelPair(20, 40, module=3, face_width=20).rating(*args, **kw)


def test_outside_the_method_scope_is_refused():
    # ISO 10300 rates virtual gears with eps_valpha < 2 (its scope, ISO 10300-1 clause 1)
    deep = BevelPair(40, 80, module=2, face_width=15, pressure_angle=14.5, addendum=1.2,
                     dedendum=1.45)  # fmt: skip
    assert deep.contact_ratio > 2.0
    with pytest.raises(GearError, match=r"eps_valpha = 2\.66"):
        deep.rating(10.0, 100.0)


def test_check_findings():
    r = BevelPair(20, 40, module=3, face_width=20).rating(50, 1500)
    rep = r.check(min_pitting=1.0, min_bending=1.4)
    assert list(rep) == ["pitting_1", "pitting_2", "bending_1", "bending_2"]
    assert rep["pitting_1"].margin == pytest.approx(r.safety_pitting[0] - 1.0, rel=1e-12)
    assert not r.check(min_pitting=10.0).ok
    with pytest.raises(GearError, match="min_bending"):
        r.check(min_bending=-1.0)


@settings(max_examples=15, deadline=None)
@given(
    st.integers(8, 40), st.integers(8, 80), st.floats(30.0, 150.0), st.floats(1e-2, 1e4),
    st.floats(1e-1, 1e5), st.sampled_from(["both-straddle", "one-straddle", "neither-straddle"]),
    st.floats(0.3, 1.0),
)  # fmt: skip
def test_bevel_rating_property(z1, z2, shaft, torque, speed, mounting, w):
    try:
        bevel = BevelPair(z1, z2, module=3, face_width=12, shaft_angle=shaft)
        r = bevel.rating(torque, speed, mounting=mounting, effective_width=w)
    except GearError:
        return
    assert all(math.isfinite(s) and s > 0 for s in (*r.safety_pitting, *r.safety_bending))
    assert all(math.isfinite(v) for v in r.values.values())
    r.check()  # never raises


@settings(max_examples=10, deadline=None)
@given(st.floats(-1e4, 1e4), st.floats(-1e3, 1e3), st.floats(-1e3, 1e3))
def test_differential_rating_property(torque, left, right):
    d = Differential(side=16, pinion=10, module=3, gleason=True)
    try:
        r = d.rating(torque=torque, left=left, right=right)
    except TrainError:
        return
    for v in r.values():
        assert all(math.isfinite(s) and s > 0 for s in (*v.safety_pitting, *v.safety_bending))


def test_method_b1_over_arrays_is_each_pair():
    """gears.bevel.iso10300.method_b1 over arrays of torques and face widths: the element of
    the rated pair is its BevelRating; with the load factors held, sigma_H goes with sqrt(T / b)
    (Hertz: l_bm scales with b) and sigma_F with T / b (the root stress)."""
    import numpy as np

    from gears.bevel.iso10300 import method_b1

    bevel = BevelPair(20, 40, module=3, face_width=20)
    r = bevel.rating(50.0, 1500.0)
    vp, f6, s6 = bevel.virtual_pair, r.virtual.factors, r.virtual.stresses
    gears = (vp.g1, vp.g2)
    t = np.array([[10.0], [50.0], [200.0]])
    b = np.array([10.0, 20.0])
    out = method_b1(
        t, bevel.geometry.mean_diameter[0], b, bevel.mean_module, 20.0,
        [g.reference_diameter for g in gears], [g.tip_diameter for g in gears],
        [g.base_diameter for g in gears], vp.contact_ratio, (0.0, 0.0), (0.0, 0.0), 1.25,
        [g.rack.root_radius for g in gears], (0.0, 0.0),
        [f6[k] for k in ("K_A", "K_v", "K_Hbeta", "K_Fbeta", "K_Halpha", "K_Falpha")],
        f6["Z_E"], s6["sigma_HP"], s6["sigma_FP"],
    )  # fmt: skip
    assert out["S_H1"].shape == (3, 2)
    assert out["S_H1"][1, 1] == pytest.approx(r.safety_pitting[0], rel=1e-12)
    assert out["S_F2"][1, 1] == pytest.approx(r.safety_bending[1], rel=1e-12)
    sh = out["sigma_H"]
    assert sh / sh[1, 1] == pytest.approx(np.sqrt(t / 50.0 * 20.0 / b), rel=1e-12)
    sf = out["sigma_F1"]
    assert sf / sf[1, 1] == pytest.approx(t / 50.0 * 20.0 / b, rel=1e-12)


def test_train_rating_rates_bevel_meshes_from_the_power_flow():
    """trains.rating on the differential's train: the statics of the power flow (the case
    torque into the left wheel, the right held) against the Differential's own split (Ozols
    §13: half the case torque on each side gear, shared by the pinions)."""
    import trains

    d = Differential(side=16, pinion=10, n_pinions=2, module=3, gleason=True)
    r = trains.rating(d.train, "case", "left", fixed=["right"], torque=150, speed=100,
                      mounting="one-straddle")  # fmt: skip
    left = float(d.solve(case=100, right=0)["left"])
    direct = d.rating(150, left, 0.0, mounting="one-straddle")
    assert set(r) == {"pinion-right", "pinion-left"}
    for name in r:
        assert isinstance(r[name], BevelRating)
        for a, b in zip((*r[name].safety_pitting, *r[name].safety_bending),
                        (*direct[name].safety_pitting, *direct[name].safety_bending),
                        strict=True):  # fmt: skip
            assert a == pytest.approx(b, rel=1e-9)
        assert r[name].factors["K_Hbeta-be"] == pytest.approx(1.10, rel=1e-12)
    with pytest.raises(TrainError, match="face width is its own"):
        trains.rating(d.train, "case", "left", fixed=["right"], torque=150, speed=100,
                      face_width={"pinion-left": 10.0})  # fmt: skip
    # a spectrum rates cylindrical meshes only: here there are none
    with pytest.raises(TrainError, match="no mesh of real gears"):
        trains.rating(d.train, "case", "left", fixed=["right"],
                      spectrum=[(150, 100, 10), (50, 100, 100)])  # fmt: skip
    with pytest.raises(TrainError, match="mounting= rates bevel meshes"):
        trains.rating(d.train, "case", "left", fixed=["right"], mounting="one-straddle",
                      spectrum=[(150, 100, 10)])  # fmt: skip
