"""gears.rating.iso6336, gears.rating.capacity, gears.rating.root, gears.rating.materials: ISO 6336
method B (issue 18).

Sources: ISO/TR 6336-30:2017 Example 1 as transcribed in rating.md (gfsReboucas/Drivetrain,
``MATISO_6336.example_01``); closed forms of ISO 6336-2; the two routes to Y_F and Y_S (the
standard's equations against the root measured on the exact envelope and on a simulated cut);
identities of the rating's own formulas.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import BasicRack, Gear, GearPair
from gears.errors import GearError
from gears.rating.capacity import load_diameters
from gears.rating.iso6336 import REASONS, rate_pairs
from gears.rating.life import bending_life_factor, pitting_life_factor
from gears.rating.materials import MATERIALS, Material
from gears.rating.pitting import contact_ratio_factor, elasticity_factor, zone_factor
from gears.rating.root import measure_root


# --- ISO/TR 6336-30 Example 1 -------------------------------------------------------------------
def _tr_pair():
    # m_n 8, z 17/103, x 0.14522 (the TR's nominal shift, rating.md) / 0, beta 15.8 deg, b 100,
    # ISO 53 type D; a_w = 500 mm, no tip shortening (the TR's tips)
    rack = BasicRack.iso53("D")
    g1 = Gear(17, 8, helix_angle=15.8, profile_shift=0.14522, face_width=100, rack=rack)
    g2 = Gear(103, 8, helix_angle=-15.8, profile_shift=0.0, face_width=100, rack=rack)
    return GearPair(g1, g2, tip_shortening=False)


def _tr_rating(**extra):
    # T1 9000 N m, n1 360 rpm, life 50 000 h, grade 5, Ra 1.0 um, nu_40 320, C_a 70 um,
    # 16MnCr5 case-carburized (sigma_Hlim 1500, E 206 000, nu 0.3), K_Hbeta = 1.16 as in the TR
    # (the TR works by ISO 6336-1/-2/-3:2006: edition=2006)
    kw = dict(life=50000, quality=5, roughness=1.0, oil_viscosity=320, tip_relief=0.070,
              K_Hbeta=1.16, edition=2006)  # fmt: skip
    kw.update(extra)
    return _tr_pair().rating(9000, 360, "case-carburized", **kw)


def test_tr_6336_30_example_1_geometry():
    p = _tr_pair()
    assert p.center_distance == pytest.approx(500.0, abs=0.01)  # rating.md: a_w 500 mm


def test_tr_6336_30_example_1_factors_to_the_published_digits():
    r = _tr_rating()
    f, q = r.factors, r.quantities
    published = {  # rating.md, "ISO/TR 6336-30:2017, Example 1"
        "Z_H": 2.39533, "Z_E": 189.8117, "Z_eps": 0.803, "Z_beta": 1.01944, "K_v": 1.003,
        "Z_L": 1.04739, "Z_v": 0.96911, "Z_R": 0.96599,
    }  # fmt: skip
    for name, value in published.items():
        assert f[name] == pytest.approx(value, rel=1e-3), name
    assert f["Z_W"] == pytest.approx((1.0, 1.0)) and f["Z_X"] == pytest.approx(1.0)
    assert f["Z_B"] == pytest.approx(1.0) and f["Z_D"] == pytest.approx(1.0)
    assert f["K_Halpha"] == pytest.approx(1.0) and f["K_Falpha"] == pytest.approx(1.0)
    assert f["K_Fbeta"] == pytest.approx(1.12803, rel=1e-3)
    assert f["c'"] == pytest.approx(12.37047, rel=1e-3)
    assert f["c_gamma_alpha"] == pytest.approx(17.46485, rel=1e-3)
    assert f["c_gamma_beta"] == pytest.approx(14.84512, rel=1e-3)
    assert q["F_t"] == pytest.approx(127352, rel=1e-3)
    assert q["v"] == pytest.approx(2.664, rel=1e-3)
    assert q["N_L"] == pytest.approx((1.080e9, 1.783e8), rel=1e-3)
    # Z_NT 0.91 / 0.962 (the TR's y_lim 0.85 at 10^10), to their published digits
    assert f["Z_NT"] == pytest.approx((0.91, 0.962), abs=5e-4)


def test_tr_6336_30_example_1_stresses_and_safeties():
    r = _tr_rating()
    s = r.stresses
    assert s["sigma_H0"] == pytest.approx(1206.58, rel=5e-3)
    assert s["sigma_H"] == pytest.approx((1301.35, 1301.35), rel=5e-3)
    assert s["sigma_HP"] == pytest.approx((1338.48, 1414.53), rel=5e-3)
    assert r.safety_pitting == pytest.approx((1.02853, 1.08696), rel=5e-3)


def test_tr_example_vectorised_route_is_the_class_route():
    r = _tr_rating()
    v = rate_pairs(17, 103, 8, 100, 9000, 360, x1=0.14522, helix_angle=15.8, quality=5,
                   life=50000, oil_viscosity=320, tip_relief=0.070, dedendum=1.4,
                   root_radius=0.39, tip_shortening=False, factors={"K_Hbeta": 1.16},
                   edition=2006)  # fmt: skip
    for name in v._fields:
        assert float(getattr(v, name)) == pytest.approx(float(getattr(r.values, name)), rel=1e-12)


# --- closed forms -------------------------------------------------------------------------------
def test_zone_factor_closed_form():
    # ISO 6336-2 §6.1, spur and zero shift: Z_H = 2 / sqrt(sin 2 alpha) = 2.4946
    assert float(zone_factor(20, 20, 0)) == pytest.approx(2 / math.sqrt(math.sin(math.radians(40))))
    # a shifted helical pair: from its own alpha_t, alpha_wt and beta_b (independent properties)
    p = GearPair(Gear(19, 2, helix_angle=12, profile_shift=0.4, face_width=20),
                 Gear(57, 2, helix_angle=-12, profile_shift=0.1, face_width=20))  # fmt: skip
    at, awt = math.radians(p.g1.transverse_pressure_angle), math.radians(p.working_pressure_angle)
    bb = math.radians(p.g1.base_helix_angle)
    expected = math.sqrt(2 * math.cos(bb) * math.cos(awt) / (math.cos(at) ** 2 * math.sin(awt)))
    assert p.rating(100, 1000).factors["Z_H"] == pytest.approx(expected, rel=1e-12)


def test_elasticity_factor_of_steel():
    # Z_E = sqrt(E / (2 pi (1 - nu^2))) for two steels E 206 000, nu 0.3: 189.81 (ISO 6336-2 §7)
    assert float(elasticity_factor(206000, 0.3, 206000, 0.3)) == pytest.approx(189.81, abs=5e-3)
    r = GearPair(Gear(20, 2, face_width=20), Gear(40, 2, face_width=20)).rating(50, 1000)
    assert r.factors["Z_E"] == pytest.approx(189.8117, rel=1e-6)


def test_contact_ratio_factor_three_ranges():
    # ISO 6336-2 §8: spur sqrt((4 - ea)/3); 0 < eb < 1 the weighted form; eb >= 1 sqrt(1/ea)
    assert float(contact_ratio_factor(1.6, 0.0)) == pytest.approx(math.sqrt(2.4 / 3))
    mixed = math.sqrt((4 - 1.5) / 3 * (1 - 0.4) + 0.4 / 1.5)
    assert float(contact_ratio_factor(1.5, 0.4)) == pytest.approx(mixed)
    assert float(contact_ratio_factor(1.5, 1.0)) == pytest.approx(math.sqrt(1 / 1.5))
    assert float(contact_ratio_factor(1.5, 2.7)) == pytest.approx(math.sqrt(1 / 1.5))
    # continuous where the ranges meet
    assert float(contact_ratio_factor(1.5, 1 - 1e-12)) == pytest.approx(math.sqrt(1 / 1.5))


def test_life_curves_at_their_knots():
    # ISO 6336-2 Table 2 (no pitting permitted) and ISO 6336-3 Table 3 (Eh, IF)
    assert float(pitting_life_factor(1e4, "Eh")) == pytest.approx(1.6)
    assert float(pitting_life_factor(5e7, "Eh")) == pytest.approx(1.0)
    assert float(pitting_life_factor(1e10, "Eh")) == pytest.approx(0.85)
    assert float(pitting_life_factor(2e6, "NT")) == pytest.approx(1.0)
    assert float(bending_life_factor(1e3, "Eh")) == pytest.approx(2.5)
    assert float(bending_life_factor(1e4, "V")) == pytest.approx(2.5)
    assert float(bending_life_factor(3e6, "GG")) == pytest.approx(1.0)


# --- Y_F and Y_S: the standard's equations and the real root ------------------------------------
ROUTE_CASES = [
    (z, x, rack, beta)
    for z, x in ((9, 0.0), (12, 0.3), (17, 0.0), (25, -0.3), (25, 0.5), (60, 0.0), (120, 0.4))
    for rack in ("A", "B", "C", "D")
    for beta in (0.0, 20.0)
]


@pytest.mark.parametrize("z, x, rack, beta", ROUTE_CASES)
def test_y_f_y_s_routes_agree_on_rack_cut_gears(z, x, rack, beta):
    """ISO 6336-3's equations against the root measured on the exact rack envelope of the
    (virtual) gear: within 0.5 % (they agree to about 1e-6)."""
    r = BasicRack.iso53(rack)
    g1 = Gear(z, 2, helix_angle=beta, profile_shift=x, face_width=20, rack=r)
    g2 = Gear(2 * z + 7, 2, helix_angle=-beta, face_width=20, rack=r)
    pair = GearPair(g1, g2)
    standard = pair.rating(100, 1000, root="standard").factors
    measured = pair.rating(100, 1000, root="measured")
    assert measured.roots[0].startswith("measured on the exact envelope")
    for name in ("Y_F", "Y_S"):
        assert measured.factors[name] == pytest.approx(standard[name], rel=5e-3), name


@pytest.mark.parametrize("z, x, rack", [(12, 0.5, "A"), (20, 0.2, "B"), (40, -0.3, "D")])
def test_y_f_y_s_on_the_simulated_cut(z, x, rack):
    """Measured on a simulated rack cut (polygon, m_n / 10000 tolerance): within 0.5 % of the
    standard's equations."""
    g = Gear(z, 2, profile_shift=x, face_width=20, rack=BasicRack.iso53(rack))
    pair = GearPair(g, Gear(47, 2, face_width=20, rack=BasicRack.iso53(rack)))
    standard = pair.rating(100, 1000, root="standard")
    d_en = load_diameters(pair)[0]
    sim = measure_root(pair.mounted[0], d_en, "simulated", tolerance=2e-4)
    yf, ys, _ = sim.factors(2)
    assert yf == pytest.approx(standard.factors["Y_F"][0], rel=5e-3)
    assert ys == pytest.approx(standard.factors["Y_S"][0], rel=5e-3)


@pytest.mark.parametrize("z, x", [(60, 0.0), (80, 0.3), (45, -0.2)])
def test_internal_gear_rated_from_its_shaper_cut_root(z, x):
    """A ring is rated from the root its shaper cutter leaves (measured on the exact envelope);
    its Y_F lies below an external gear's of the same z and x (ISO 6336-3: internal teeth are
    thicker at the root)."""
    pinion = Gear(19, 2, face_width=20)
    # x in KHK's sign for the ring, as these cases were written (the external gear cut by the
    # same rack position): DIN 3960's -x
    ring = Gear(z, 2, internal=True, profile_shift=-x, face_width=20)
    internal = GearPair(pinion, ring).rating(100, 1000)
    assert internal.roots[1] == "measured on the exact envelope (shaper-cut)"
    external = GearPair(pinion, Gear(z, 2, profile_shift=x, face_width=20)).rating(100, 1000)
    assert internal.factors["Y_F"][1] < external.factors["Y_F"][1]
    assert internal.quantities["s_Fn"][1] > external.quantities["s_Fn"][1]
    # the standard's rack approximation is the limit: same side of the external gear
    approx = GearPair(pinion, ring).rating(100, 1000, root="standard")
    assert approx.factors["Y_F"][1] < external.factors["Y_F"][1]


def test_measured_root_of_an_internal_gear_agrees_with_its_simulated_cut():
    ring = Gear(60, 2, internal=True)
    d_en = 122.5
    exact = measure_root(ring, d_en)
    sim = measure_root(ring, d_en, "simulated")
    assert exact.tangent == pytest.approx(60.0)
    assert sim.factors(2)[0] == pytest.approx(exact.factors(2)[0], rel=5e-3)
    assert sim.factors(2)[1] == pytest.approx(exact.factors(2)[1], rel=5e-3)


# --- identities -----------------------------------------------------------------------------------
@pytest.mark.parametrize("internal", [False, True])
def test_stresses_recomputed_from_the_reported_factors(internal):
    g1 = Gear(21, 2.5, helix_angle=14, profile_shift=0.2, face_width=28)
    g2 = Gear(75, 2.5, helix_angle=14 if internal else -14, profile_shift=0.1, face_width=30,
              internal=internal)  # fmt: skip
    r = GearPair(g1, g2).rating(180, 2200, "nitrided", life=8000, K_A=1.25)
    f, q, s = r.factors, r.quantities, r.stresses
    d1, b, m = g1.reference_diameter, 28.0, 2.5
    u = q["u"]
    assert (u < 0) == internal
    sigma_h0 = (
        f["Z_H"]
        * f["Z_E"]
        * f["Z_eps"]
        * f["Z_beta"]
        * math.sqrt(q["F_t"] * (u + 1) / (d1 * b * u))
    )
    assert s["sigma_H0"] == pytest.approx(sigma_h0, rel=1e-12)
    load = math.sqrt(f["K_gamma"] * f["K_A"] * f["K_v"] * f["K_Hbeta"] * f["K_Halpha"])
    assert s["sigma_H"][0] == pytest.approx(f["Z_B"] * sigma_h0 * load, rel=1e-12)
    assert s["sigma_H"][1] == pytest.approx(f["Z_D"] * sigma_h0 * load, rel=1e-12)
    kf = f["K_gamma"] * f["K_A"] * f["K_v"] * f["K_Fbeta"] * f["K_Falpha"]
    for i in (0, 1):
        sigma_f0 = q["F_t"] / (b * m) * f["Y_F"][i] * f["Y_S"][i] * f["Y_beta"] * f["Y_B"][i]
        sigma_f0 *= f["Y_DT"]
        assert s["sigma_F0"][i] == pytest.approx(sigma_f0, rel=1e-12)
        assert s["sigma_F"][i] == pytest.approx(sigma_f0 * kf, rel=1e-12)
        hp = MATERIALS["nitrided"].sigma_Hlim * f["Z_NT"][i] * f["Z_L"] * f["Z_v"] * f["Z_R"]
        hp *= f["Z_W"][i] * f["Z_X"]
        assert s["sigma_HP"][i] == pytest.approx(hp, rel=1e-12)
        fp = MATERIALS["nitrided"].sigma_Flim * f["Y_ST"] * f["Y_NT"][i] * f["Y_deltarelT"][i]
        fp *= f["Y_RrelT"][i] * f["Y_X"][i] * f["Y_M"][i]
        assert s["sigma_FP"][i] == pytest.approx(fp, rel=1e-12)
        assert r.safety_pitting[i] == pytest.approx(hp / s["sigma_H"][i], rel=1e-12)
        assert r.safety_bending[i] == pytest.approx(fp / s["sigma_F"][i], rel=1e-12)


def test_safeties_scale_with_torque_when_the_load_factors_are_pinned():
    """With K_v, K_beta and K_alpha given, S_H ~ 1/sqrt(T) and S_F ~ 1/T (ISO 6336-2/-3: the
    stresses are sqrt(F_t) and F_t times load-independent factors)."""
    pair = GearPair(Gear(18, 3, face_width=30), Gear(55, 3, face_width=30))
    pinned = dict(K_v=1.05, K_Hbeta=1.2, K_Fbeta=1.15, K_Halpha=1.0, K_Falpha=1.0)
    low = pair.rating(100, 1450, **pinned)
    high = pair.rating(400, 1450, **pinned)
    for i in (0, 1):
        assert low.safety_pitting[i] / high.safety_pitting[i] == pytest.approx(2.0, rel=1e-12)
        assert low.safety_bending[i] / high.safety_bending[i] == pytest.approx(4.0, rel=1e-12)


def test_vectorised_rows_equal_single_ratings():
    z1 = np.array([14, 17, 23, 31])
    z2 = np.array([41, 50, 73, 95])
    x1 = np.array([0.3, 0.1, 0.0, -0.1])
    torque = np.array([40.0, 90.0, 300.0, 700.0])
    rows = rate_pairs(z1, z2, 2.5, 25, torque, 1800, x1=x1, helix_angle=10, errors="mask")
    for i in range(4):
        p = GearPair(Gear(int(z1[i]), 2.5, helix_angle=10, profile_shift=float(x1[i])),
                     Gear(int(z2[i]), 2.5, helix_angle=-10))  # fmt: skip
        one = p.rating(float(torque[i]), 1800, face_width=25)
        for name in ("S_H1", "S_H2", "S_F1", "S_F2", "K_v", "Y_F1", "Z_B"):
            assert getattr(rows, name)[i] == pytest.approx(float(getattr(one.values, name)),
                                                          rel=1e-12)  # fmt: skip


def test_blocked_threaded_path_matches_the_plain_one():
    rng = np.random.default_rng(5)
    n = 70000  # > 2 blocks of 32768
    z1 = rng.integers(15, 40, n)
    z2 = z1 + rng.integers(10, 80, n)
    m = rng.uniform(1, 6, n)
    args = (z1, z2, m, 10 * m, 30 * m**2, 1500)
    big = rate_pairs(*args, errors="mask", fields=("S_H1", "S_F2", "K_v"), threads=2)
    idx = rng.integers(0, n, 50)
    small = rate_pairs(z1[idx], z2[idx], m[idx], 10 * m[idx], 30 * m[idx] ** 2, 1500,
                       errors="mask")  # fmt: skip
    for name in ("S_H1", "S_F2", "K_v"):
        assert getattr(big, name)[idx] == pytest.approx(getattr(small, name), rel=1e-14)
    assert big.S_H2 is None and big.valid.all()


# --- planets and idlers -----------------------------------------------------------------------
def test_idler_has_the_reversed_bending_factor():
    pair = GearPair(Gear(20, 2, face_width=20), Gear(31, 2, face_width=20))
    plain = pair.rating(60, 1000)
    idler = pair.rating(60, 1000, idler=(False, True))
    assert idler.factors["Y_M"] == pytest.approx((1.0, 0.7))
    assert idler.safety_bending[1] == pytest.approx(0.7 * plain.safety_bending[1], rel=1e-12)
    assert idler.safety_pitting == pytest.approx(plain.safety_pitting, rel=1e-12)


# --- bad input and validity -------------------------------------------------------------------
@pytest.mark.parametrize(
    "kwargs, word",
    [
        (dict(torque=0), "torque"),
        (dict(torque=-5), "torque"),
        (dict(speed=0), "speed"),
        (dict(speed=math.nan), "speed"),
        (dict(quality=0), "quality"),
        (dict(quality=13), "quality"),
        (dict(quality=6.5), "quality"),
        (dict(life=-1), "life"),
        (dict(roughness=0), "roughness"),
        (dict(oil_viscosity=0), "oil_viscosity"),
        (dict(application_factor=0.5), "application_factor"),
        (dict(tip_relief=-0.01), "tip_relief"),
        (dict(material="unobtainium"), "case-carburized"),
        (dict(K_v=-1), "K_v"),
        (dict(K_foo=1.0), "K_foo"),
        (dict(Y_F=(1, 2, 3)), "Y_F"),
        (dict(root="guess"), "root"),
    ],
)
def test_bad_input_is_refused_naming_it(kwargs, word):
    pair = GearPair(Gear(20, 2, face_width=20), Gear(40, 2, face_width=20))
    args = {"torque": 100, "speed": 1000, **kwargs}
    with pytest.raises(GearError, match=word):
        pair.rating(**args)


def test_missing_face_width_is_refused():
    with pytest.raises(GearError, match="face_width"):
        GearPair(Gear(20, 2), Gear(40, 2)).rating(100, 1000)


def test_pointed_tip_is_outside_method_b():
    # z = 10, x = 0.8: the tooth comes to a point below its tip circle
    pair = GearPair(Gear(10, 2, profile_shift=0.8, face_width=20), Gear(40, 2, face_width=20),
                    tip_shortening=False)  # fmt: skip
    assert pair.mounted[0].tip_thickness < 0
    with pytest.raises(GearError, match="point"):
        pair.rating(50, 1000)
    masked = rate_pairs([10, 20], 40, 2, 20, 50, 1000, x1=[0.8, 0.0], tip_shortening=False,
                        errors="mask")  # fmt: skip
    assert masked.valid.tolist() == [False, True]
    assert REASONS[masked.reason[0]].startswith("a tooth comes to a point")
    assert masked.S_H1[0] == pytest.approx(0.0) and np.isnan(masked.Y_F1[0])
    assert masked.S_H1[1] > 0


def test_materials_table_and_custom_material():
    for name, m in MATERIALS.items():
        assert m.name == name and m.source.startswith("ISO 6336-5")
    custom = Material("18CrNiMo7-6 ME", "Eh", 1650, 525)
    r = GearPair(Gear(20, 2, face_width=20), Gear(40, 2, face_width=20)).rating(50, 1000, custom)
    base = GearPair(Gear(20, 2, face_width=20), Gear(40, 2, face_width=20)).rating(50, 1000)
    assert r.stresses["sigma_HP"][0] > base.stresses["sigma_HP"][0]
    with pytest.raises(GearError, match="kind"):
        Material("x", "brass", 500, 200)
    with pytest.raises(GearError, match="sigma_Hlim"):
        Material("x", "V", -1, 200)


def test_rating_report_and_text():
    r = GearPair(Gear(20, 2, face_width=20), Gear(40, 2, face_width=20)).rating(60, 1000)
    report = r.check(min_pitting=1.0, min_bending=1.4)
    assert list(report) == ["pitting_1", "pitting_2", "bending_1", "bending_2"]
    assert report["pitting_1"].margin == pytest.approx(r.safety_pitting[0] - 1.0)
    strict = r.check(min_pitting=100.0)
    assert not strict.ok and strict.failed() == ["pitting_1", "pitting_2"]
    text = str(r)
    for symbol in ("Z_H", "K_Hbeta", "Y_deltarelT", "ISO 6336-2 §6.1", "sigma_F0"):
        assert symbol in text
    with pytest.raises(GearError, match="min_bending"):
        r.check(min_bending=-1)


# --- property tests -----------------------------------------------------------------------------
@settings(max_examples=40, deadline=None)
@given(
    z1=st.integers(12, 60),
    dz=st.integers(0, 120),
    m=st.floats(0.5, 12),
    x1=st.floats(-0.3, 0.8),
    x2=st.floats(-0.3, 0.8),
    beta=st.sampled_from([0.0, 8.0, 15.0, 25.0]),
    torque=st.floats(1e-3, 1e5),
    speed=st.floats(1e-2, 2e4),
    width=st.floats(3, 30),
    internal=st.booleans(),
)
def test_random_pairs_rate_to_finite_factors_or_refuse(
    z1, dz, m, x1, x2, beta, torque, speed, width, internal
):
    """Random pairs and loads: finite factors within their documented ranges, or a GearError."""
    try:
        g1 = Gear(z1, m, helix_angle=beta, profile_shift=x1, face_width=width * m)
        g2 = Gear(z1 + dz + (5 if internal else 0), m, helix_angle=beta if internal else -beta,
                  profile_shift=x2, face_width=width * m, internal=internal)  # fmt: skip
        pair = GearPair(g1, g2)
        r = pair.rating(torque * m**2, speed, root="standard")
    except GearError:
        return
    f = r.factors
    values = [v for x in f.values() for v in (x if isinstance(x, tuple) else (x,))]
    assert all(math.isfinite(v) and v > 0 for v in values)
    # K_v >= 1 below resonance; above it C_v7 >= 0.75 may take it below 1 (ISO 6336-1 §6.5.6)
    assert f["K_v"] >= (1.0 if r.quantities["N"] <= 0.85 else 0.75)
    assert f["K_Hbeta"] >= 1.0 and 1.0 <= f["K_Fbeta"] <= f["K_Hbeta"]
    assert f["K_Halpha"] >= 1.0 and f["K_Falpha"] >= 1.0
    assert 0 < f["Z_eps"] <= 1.0 and f["Z_B"] >= 1.0 and f["Z_D"] >= 1.0
    assert 0.7 < f["Z_L"] < 1.3 and 0.8 < f["Z_v"] < 1.2
    assert all(0.8 <= z <= 1.6 for z in f["Z_NT"]) and all(0.8 <= y <= 2.5 for y in f["Y_NT"])
    assert all(1.0 <= y < 3.5 for y in f["Y_S"])
    assert all(math.isfinite(s) and s > 0 for s in (*r.safety_pitting, *r.safety_bending))


@settings(max_examples=25, deadline=None)
@given(
    torque=st.one_of(st.floats(allow_nan=True), st.integers(-10, 10), st.text(max_size=3)),
    speed=st.one_of(st.floats(allow_nan=True), st.integers(-10, 10)),
    quality=st.one_of(st.integers(-3, 15), st.floats(0, 14)),
)
def test_random_operating_input_is_rated_or_refused(torque, speed, quality):
    pair = GearPair(Gear(20, 2, face_width=20), Gear(40, 2, face_width=20))
    try:
        r = pair.rating(torque, speed, quality=quality)
    except GearError:
        return
    assert all(math.isfinite(s) and s > 0 for s in (*r.safety_pitting, *r.safety_bending))


@settings(max_examples=20, deadline=None)
@given(
    z=st.integers(6, 150),
    x=st.floats(-0.8, 1.2),
    internal=st.booleans(),
    where=st.floats(0.0, 1.0),
    tangent=st.one_of(st.none(), st.floats(-10, 100)),
)
def test_measure_root_gives_a_root_or_refuses(z, x, internal, where, tangent):
    """measure_root on random gears and load points: a finite root form (s_Fn, rho_F, h_Fe > 0)
    or a GearError saying why method B does not apply."""
    try:
        g = Gear(z + (20 if internal else 0), 2, profile_shift=x, internal=internal)
        d_en = g.base_diameter + where * abs(g.tip_diameter - g.base_diameter) * 1.2
        r = measure_root(g, d_en, tangent=tangent)
    except GearError:
        return
    assert all(math.isfinite(v) and v > 0 for v in (r.s_Fn, r.rho_F, r.h_Fe))
    assert math.isfinite(r.alpha_Fen)


@settings(max_examples=20, deadline=None)
@given(
    n=st.integers(1, 40),
    seed=st.integers(0, 10**6),
    bad=st.sampled_from([None, "nan", "zero", "negative"]),
)
def test_rate_pairs_over_random_arrays(n, seed, bad):
    """rate_pairs over random rows: with errors="mask" every row is rated (finite, positive
    safeties) or marked invalid with a reason and zero safeties; bad input raises naming it."""
    rng = np.random.default_rng(seed)
    z1 = rng.integers(6, 60, n)
    z2 = rng.integers(6, 200, n)
    m = rng.uniform(0.3, 20, n)
    torque = rng.uniform(0.01, 1e4, n) * m * m
    if bad is not None:
        torque[rng.integers(0, n)] = {"nan": np.nan, "zero": 0.0, "negative": -1.0}[bad]
        with pytest.raises(GearError, match="torque"):
            rate_pairs(z1, z2, m, 10 * m, torque, 1000, errors="mask")
        return
    try:
        r = rate_pairs(z1, z2, m, 10 * m, torque, 1000, x1=rng.uniform(-0.5, 1.0, n),
                       x2=rng.uniform(-0.5, 1.0, n), helix_angle=rng.uniform(0, 40, n),
                       errors="mask")  # fmt: skip
    except GearError:  # a row with no working pressure angle is bad input (pair_geometry)
        return
    for s in (r.S_H1, r.S_H2, r.S_F1, r.S_F2):
        assert np.all(np.where(r.valid, np.isfinite(s) & (s > 0), s <= 0.0))  # zero if invalid
    assert np.all((r.reason == 0) == r.valid)


def test_dynamic_factor_ranges_over_arrays_match_one_pair_each():
    # ISO 6336-1 §6.5: over arrays the resonance ranges are computed only where a pair is in
    # them (when few are); independent check: each element alone (plain floats, one expression
    # of all four ranges) to 1e-12, over random inputs reaching every range (N 0 ... 3, w below
    # and above 100 N/mm, eps_gamma both sides of 2: most pairs past N_S), N 0 ... 0.9 (a few
    # past N_S) and N 0 ... 0.6 (none)
    from gears.rating.load_factors import dynamic_factor

    rng = np.random.default_rng(7)
    k = 2000
    args = (rng.uniform(0.0, 3.0, k), rng.uniform(20.0, 2000.0, k), rng.uniform(10.0, 20.0, k),
            rng.uniform(0.0, 20.0, k), rng.uniform(0.0, 20.0, k), rng.uniform(0.0, 50.0, k),
            rng.uniform(1.1, 3.5, k))  # fmt: skip
    for n in (args[0], args[0] * 0.3, args[0] * 0.2):
        got = dynamic_factor(n, *args[1:])
        one = [dynamic_factor(*(float(v[i]) for v in (n, *args[1:]))) for i in range(k)]
        np.testing.assert_allclose(got, one, rtol=1e-12, atol=0)


def test_dynamic_factor_ranges_over_broadcast_arrays_match_one_pair_each():
    # ISO 6336-1 §6.5 over arrays of different shapes (the resonance ratio per row, the rest
    # per column: a spectrum's pairs x bins): the resonance ranges computed only where an
    # element is in them, taken from the broadcast arrays. Independent check: each element
    # alone (plain floats, one expression of all four ranges) to 1e-12; N of 0 ... 0.6 with a
    # few rows up to 3 (a few elements past N_S: the subset route) and of 0 ... 3 (most)
    from gears.rating.load_factors import dynamic_factor

    rng = np.random.default_rng(8)
    rows, cols = 60, 40
    rest = tuple(rng.uniform(lo, hi, cols) for lo, hi in ((20.0, 2000.0), (10.0, 20.0),
                 (0.0, 20.0), (0.0, 20.0), (0.0, 50.0), (1.1, 3.5)))  # fmt: skip
    few = rng.uniform(0.0, 0.6, (rows, 1))
    few[:3, 0] = rng.uniform(1.0, 3.0, 3)
    for n in (few, rng.uniform(0.0, 3.0, (rows, 1))):
        got = dynamic_factor(n, *rest)
        assert got.shape == (rows, cols)
        one = [[dynamic_factor(float(n[i, 0]), *(float(v[j]) for v in rest)) for j in range(cols)]
               for i in range(rows)]  # fmt: skip
        np.testing.assert_allclose(got, one, rtol=1e-12, atol=0)
