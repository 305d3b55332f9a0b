"""gears.pair: meshing pairs against the seeds' tables, KHK examples and independent routes."""

import math

import numpy as np
import pytest

from gears import Gear, GearPair, Rack, pair_geometry
from gears.errors import GearError
from gears.meshing import center_distance_shift_sum, mesh_efficiency

A20 = math.radians(20.0)
TAN20 = math.tan(A20)


def _pair(z1, z2, x1=0.0, x2=0.0, m=1.0, **kw):
    return GearPair(Gear(z1, m, profile_shift=x1), Gear(z2, m, profile_shift=x2), **kw)


# --- Joldasbekov §5.4: pairs by the book's algorithm (m = 1) ------------------------------------

# z1, z2, xi1, xi2, alpha_w, A, r1', r2', R_i1, R_i2, R_e1, R_e2, eps, s_a1, s_a2
JOLDASBEKOV_5_4 = [
    (20, 20, 0, 0, 20.0, 20.0, 10.0, 10.0, 8.75, 8.75, 11.0, 11.0, 1.55684, 0.69488, 0.69488),
    (17, 17, 0, 0, 20.0, 17.0, 8.5, 8.5, 7.25, 7.25, 9.5, 9.5, 1.51480, 0.67408, 0.67408),
    (12, 28, 0.3, 0.2, 23.29917, 20.46253, 6.13876, 14.32377, 5.05, 12.95, 7.26253, 15.16253,
     1.36264, 0.49459, 0.71346),
    (10, 30, 0.4118, 0, 22.79102, 20.38547, 5.09637, 15.28910, 4.1618, 13.75, 6.38547, 15.97367,
     1.33553, 0.32641, 0.76434),
    (10, 30, 0.4118, -0.4118, 20.0, 20.0, 5.0, 15.0, 4.1618, 13.3382, 6.4118, 15.5882, 1.41569,
     0.27898, 0.81751),
]  # fmt: skip


@pytest.mark.parametrize("row", JOLDASBEKOV_5_4, ids=lambda r: f"{r[0]}-{r[1]}-{r[2]}-{r[3]}")
def test_joldasbekov_5_4_pair_table(row):
    z1, z2, x1, x2, aw, a, rw1, rw2, ri1, ri2, re1, re2, eps, sa1, sa2 = row
    p = _pair(z1, z2, x1, x2)
    g1, g2 = p.mounted
    assert p.working_pressure_angle == pytest.approx(aw, abs=5e-6)
    assert p.center_distance == pytest.approx(a, abs=5e-6)
    assert np.array(p.working_diameters) / 2 == pytest.approx([rw1, rw2], abs=5e-6)
    assert (g1.root_diameter / 2, g2.root_diameter / 2) == pytest.approx((ri1, ri2), abs=5e-6)
    assert np.array(p.tip_diameters) / 2 == pytest.approx([re1, re2], abs=5e-6)
    assert p.contact_ratio == pytest.approx(eps, abs=5e-6)
    assert (g1.tip_thickness, g2.tip_thickness) == pytest.approx((sa1, sa2), abs=5e-6)
    # tip shortening = the book's constant-clearance tips (6.46)-(6.47): R_e1 = A - R_i2 - 0.25 m
    assert g1.tip_diameter / 2 == pytest.approx(p.center_distance - g2.root_diameter / 2 - 0.25)
    assert g2.tip_diameter / 2 == pytest.approx(p.center_distance - g1.root_diameter / 2 - 0.25)
    # pair.mounted carries the shortened tips
    assert (g1.tip_diameter, g2.tip_diameter) == pytest.approx(p.tip_diameters, rel=1e-15)


def test_joldasbekov_5_4_module_independence_and_tip_rule():
    # m = 2 doubles every length, eps unchanged (Joldasbekov §5.4 note)
    p = _pair(12, 28, 0.3, 0.2, m=2)
    assert p.center_distance == pytest.approx(40.92506, abs=1e-5)
    assert np.array(p.tip_diameters) / 2 == pytest.approx([14.52506, 30.32506], abs=1e-5)
    assert p.contact_ratio == pytest.approx(1.36264, abs=5e-6)
    # last row: s_a1 = 0.279 < 0.3 m, so the book's §12 rule (tip land >= 0.3 m) flags it
    g1, g2 = _pair(10, 30, 0.4118, -0.4118).mounted
    assert g1.check(min_tip_land=0.3).failed() == ["undercut", "pointed_tip"]
    assert g2.check(min_tip_land=0.3).ok
    # (x1 = 0.4118 is the book's rounded (17 - z)/17: a 0.003 m undercut by the exact rule)
    # positive shift lowers eps: (12, 28) zero gears 1.52917 vs shifted 1.36264 (§5.4)
    assert _pair(12, 28).contact_ratio == pytest.approx(1.529173, abs=5e-7)


@pytest.mark.parametrize(
    ("z1", "z2", "eps"),
    [
        # Joldasbekov §5.5, zero gears (6.54)
        (20, 20, 1.556838),
        (17, 17, 1.514800),
        (17, 40, 1.614167),
        (12, 28, 1.529173),
        (30, 60, 1.719114),
        (17, 10**5, 1.747730),
    ],
)
def test_joldasbekov_5_5_zero_gear_contact_ratio(z1, z2, eps):
    assert _pair(z1, z2).contact_ratio == pytest.approx(eps, abs=5e-7)


def test_joldasbekov_5_5_pressure_angle_effect():
    # z1 = z2 = 20: 15 deg 1.762879, 20 deg 1.556838, 25 deg 1.410235
    for angle, eps in [(15, 1.762879), (20, 1.556838), (25, 1.410235)]:
        p = GearPair(Gear(20, 1, pressure_angle=angle), Gear(20, 1, pressure_angle=angle))
        assert p.contact_ratio == pytest.approx(eps, abs=5e-7)


def test_joldasbekov_5_6_specific_sliding():
    # zero gears z1 = 20, z2 = 40, m = 1: N1N2 = 10.26060; start K: rho1 = 0.89091,
    # lambda1 = -4.25848, lambda2 = 0.80983; pitch point rho1 = 3.42020 (both 0);
    # end L: rho1 = 5.71820, rho2 = 4.54241, lambda1 = 0.60281, lambda2 = -1.51769
    p = _pair(20, 40)
    path = p.path_of_contact
    assert path.n2 == pytest.approx(10.26060, abs=5e-6)
    assert (path.start, path.pitch_point, path.end) == pytest.approx(
        (0.89091, 3.42020, 5.71820), abs=5e-6
    )
    assert path.n2 - path.end == pytest.approx(4.54241, abs=5e-6)
    _, s1, s2 = p.specific_sliding([path.start, path.pitch_point, path.end])
    assert s1 == pytest.approx([-4.25848, 0, 0.60281], abs=5e-6)
    assert s2 == pytest.approx([0.80983, 0, -1.51769], abs=5e-6)
    assert p.max_specific_sliding == pytest.approx((4.25848, 1.51769), abs=5e-6)
    # lecture digest Q1 (same pair at m = 5): theta1 = -4.2585 at the pinion's lowest point
    _, q1, q2 = _pair(20, 40, m=5).specific_sliding(n=3)
    assert (q1[0], q2[0], q1[-1], q2[-1]) == pytest.approx(
        (-4.2585, 0.8098, 0.6028, -1.5177), abs=5e-5
    )


# --- lecture digest §3.3: G1-G7 ---------------------------------------------------------------

# id, z1, z2, m, x1, x2, alpha_w, a_w, y, dy, da1, da2, df1, df2, sa1/m, sa2/m, eps
LECTURE_G = [
    ("G1", 20, 40, 5, 0, 0, 20, 150, 0, 0, 110, 210, 87.5, 187.5, 0.69488, 0.76066, 1.635186),
    ("G2", 12, 30, 4, 0.3, 0, 22.017593, 85.143823, 0.285956, 0.014044, 58.28765, 127.88765,
     40.4, 110.0, 0.45792, 0.75180, 1.414622),
    ("G3", 12, 30, 4, 0.3, -0.3, 20, 84, 0, 0, 58.4, 125.6, 40.4, 107.6, 0.43574, 0.80052,
     1.479945),
    ("G4", 10, 25, 2, 0.5, 0.3, 25.405524, 36.410343, 0.705171, 0.094829, 25.62069, 54.82069,
     17.0, 46.2, 0.37323, 0.72878, 1.220792),
    ("G5", 17, 17, 1, 0, 0, 20, 17, 0, 0, 19, 19, 14.5, 14.5, 0.67408, 0.67408, 1.514800),
    ("G6", 14, 28, 3, 0.1765, 0.5, 24.080556, 64.843818, 0.614606, 0.061894, 48.68764, 92.62864,
     35.559, 79.5, 0.64089, 0.63709, 1.358693),
]  # fmt: skip


@pytest.mark.parametrize("row", LECTURE_G, ids=lambda r: r[0])
def test_lecture_pairs(row):
    _, z1, z2, m, x1, x2, aw, a, y, dy, da1, da2, df1, df2, sa1, sa2, eps = row
    p = _pair(z1, z2, x1, x2, m=m)
    g1, g2 = p.mounted
    assert p.working_pressure_angle == pytest.approx(aw, abs=1e-6)
    assert p.center_distance == pytest.approx(a, abs=1e-6)
    assert p.center_distance_modification == pytest.approx(y, abs=1e-6)
    assert -p.tip_alteration == pytest.approx(dy, abs=1e-6)
    assert p.tip_diameters == pytest.approx((da1, da2), abs=1e-5)
    assert (g1.root_diameter, g2.root_diameter) == pytest.approx((df1, df2), abs=1e-9)
    assert (g1.tip_thickness / m, g2.tip_thickness / m) == pytest.approx((sa1, sa2), abs=5e-6)
    assert p.contact_ratio == pytest.approx(eps, abs=1e-6)
    # every row keeps the clearance c* m: a_w - (d_a1 + d_f2)/2 = 0.25 m
    assert p.center_distance - (p.tip_diameters[0] + g2.root_diameter) / 2 == pytest.approx(
        0.25 * m
    )
    # second contact-ratio formula (lecture §2.8): [z1 (tan a_a1 - tan a_w) + z2 (...)]/(2 pi)
    tw = math.tan(math.radians(p.working_pressure_angle))
    ta = [math.tan(math.acos(g.base_diameter / g.tip_diameter)) for g in (g1, g2)]
    assert p.contact_ratio == pytest.approx(
        (z1 * (ta[0] - tw) + z2 * (ta[1] - tw)) / (2 * math.pi), rel=1e-12
    )


def test_lecture_g2_extra_and_g7_inverse():
    # G2 extra values: inv alpha_w = 0.020104, d_w = 48.65361 / 121.63403
    p = _pair(12, 30, 0.3, 0, m=4)
    assert p.working_diameters == pytest.approx((48.65361, 121.63403), abs=5e-6)
    # G7: z1 = 12, z2 = 30, m = 4, a_w = 85.143823 -> x1 + x2 = 0.300000
    s = center_distance_shift_sum(12, 30, 4, 85.143823)
    assert float(s) == pytest.approx(0.3, abs=1e-6)
    q = GearPair.at_center_distance(Gear(12, 4), Gear(30, 4), 85.143823, split="keep")
    assert q.working_pressure_angle == pytest.approx(22.017594, abs=1e-6)


# --- KHK examples -----------------------------------------------------------------------------


def test_khk_profile_shifted_example():
    # standards.md §1.2 / §7 (KHK example, bolsover test suite): z 12 / 24, m = 3,
    # x 0.6 / 0.36: alpha_w = 26.0886 deg, a_w = 56.4999 mm (KHK: tips 44.840 / 79.400)
    p = _pair(12, 24, 0.6, 0.36, m=3)
    assert p.working_pressure_angle == pytest.approx(26.0886, abs=5e-5)
    assert p.center_distance == pytest.approx(56.4999, abs=5e-5)
    assert p.tip_diameters == pytest.approx((44.840, 79.400), abs=5e-4)
    # KHK form of the tips: h_a1 = (1 + y - x2) m, h_a2 = (1 + y - x1) m (standards.md §1.3)
    y = p.center_distance_modification
    assert p.tip_diameters[0] == pytest.approx(36 + 2 * 3 * (1 + y - 0.36))
    assert p.tip_diameters[1] == pytest.approx(72 + 2 * 3 * (1 + y - 0.6))
    assert p.ratio == pytest.approx(2.0, rel=1e-15)  # u = z2 / z1 = 24 / 12
    # back: the same centre distance recovers x1 + x2 = 0.96
    assert float(center_distance_shift_sum(12, 24, 3, p.center_distance)) == pytest.approx(0.96)


# --- Ozols §21-5 ---------------------------------------------------------------------------


def _z_min(u):
    """Ozols (21.20): pinion limit against the mate's tip for a ratio u (kappa = 1, 20 deg)."""
    s2 = math.sin(A20) ** 2
    return 2 / (math.sqrt(u * u + (2 * u + 1) * s2) - u)


@pytest.mark.parametrize(
    ("u", "z1", "z2", "z_min", "eps"),
    [
        # Ozols Table 21-1 (book u, z_min, z2, eps) and the digest's z_min(u) by (21.20)
        (1.0, 12, 12, 12.323, 1.42),
        (1.23, 13, 16, 12.921, 1.47),
        (1.85, 14, 26, 13.980, 1.54),
        (3.0, 15, 45, 14.981, 1.61),
        (6.32, 16, 101, 16.000, 1.68),
    ],
)
def test_ozols_table_21_1(u, z1, z2, z_min, eps):
    assert _z_min(u) == pytest.approx(z_min, abs=5e-4)
    assert round(_z_min(u)) == z1
    p = _pair(z1, z2)
    assert p.contact_ratio == pytest.approx(eps, abs=0.005)  # the book prints two decimals
    # independent: (21.20) is the condition "the mate's tip passes through N1", i.e. the path
    # of contact starts at N1 (u = 0 on the line of action) for z1 = z_min(u), z2 = u z1
    zr = _z_min(u)
    g = pair_geometry(zr, u * zr, 1.0)
    rb2 = u * zr * math.cos(A20) / 2
    u_a = float(g.center_distance) * math.sin(A20) - math.sqrt(
        (float(g.tip_diameter_2) / 2) ** 2 - rb2**2
    )
    assert u_a == pytest.approx(0.0, abs=1e-9)


def test_ozols_largest_mate_for_a_pinion():
    # the digest's inverse of (21.20): u_max(z1 = 13) = 1.265, 14: 1.866, 15: 3.033, 16: 6.317;
    # the book's z2 column is the largest wheel whose tip stays above N1
    for z1, z2 in [(13, 16), (14, 26), (15, 45), (16, 101)]:
        assert _pair(z1, z2).path_of_contact.start > 0
        assert _pair(z1, z2 + 1).path_of_contact.start < 0
    # u = 1: 12 teeth are slightly interfering (12 < 12.32), 13 are not
    assert _pair(12, 12).path_of_contact.start < 0 < _pair(13, 13).path_of_contact.start


def test_ozols_rack_limit_and_z_min_17():
    # Table 21-1 last row: pinion-rack, z1 = 17: eps = 1.7478; (21.21) z_min^inf = 17.097
    p = GearPair(Gear(17, 1), Rack(1))
    assert p.contact_ratio == pytest.approx(1.7478, abs=5e-5)
    assert 2 / math.sin(A20) ** 2 == pytest.approx(17.097, abs=5e-4)
    # the rack's tip line is below N1 for 17 teeth (17 < 17.097), above it for 18
    assert p.path_of_contact.start < 0 < GearPair(Gear(18, 1), Rack(1)).path_of_contact.start


def test_ozols_both_limit_gears_21_24():
    # Ozols (21.24)/(21.25): with both gears limit gears eps = N1N2/(t cos a) = (z1+z2) tg a/2pi;
    # eps > 1 needs z1 + z2 >= 18 (2 pi / tg 20 = 17.26), with eps = 1.04
    assert 2 * math.pi / TAN20 == pytest.approx(17.26, abs=5e-3)
    for z1, z2, bound in [(9, 9, 1.04), (8, 10, 1.04)]:
        path = _pair(z1, z2).path_of_contact
        assert path.n2 / path.base_pitch == pytest.approx(bound, abs=5e-3)
        assert path.n2 / path.base_pitch == pytest.approx((z1 + z2) * TAN20 / (2 * math.pi))
    path = _pair(8, 9).path_of_contact
    assert path.n2 / path.base_pitch < 1
    # the standard-tip formula then gives eps = 1.34 > N1N2/p_b: the contact leaves N1N2,
    # which check() must report as tip interference (not as a good contact ratio)
    p = _pair(9, 9)
    assert p.contact_ratio > path.n2 / path.base_pitch
    r = p.check()
    assert not r["tip_interference"].ok and not r["tip_interference_2"].ok


def test_ozols_internal_contact_ratio_21_22_corrected():
    # Ozols digest §2.13: corrected (21.22) lower signs for z1 = 20, z2 = 60 internal: 1.95
    p = GearPair(Gear(20, 1), Gear(60, 1, internal=True))
    assert p.contact_ratio == pytest.approx(1.95, abs=5e-3)
    z1, u, k = 20, 3.0, 1.0
    c = math.cos(A20)
    eps = (z1 / (2 * math.pi)) * (
        math.sqrt((1 + 2 * k / z1) ** 2 / c**2 - 1)
        - math.sqrt((u - 2 * k / z1) ** 2 / c**2 - u**2)
        - (1 - u) * TAN20
    )
    assert p.contact_ratio == pytest.approx(eps, rel=1e-12)
    # lecture digest §3.3: internal 45 / 108 eps = 1.941225; sun-planet 18 / 45: 1.632807
    assert GearPair(Gear(45, 1), Gear(108, 1, internal=True)).contact_ratio == pytest.approx(
        1.941225, abs=5e-7
    )
    assert _pair(18, 45).contact_ratio == pytest.approx(1.632807, abs=5e-7)


def test_mesh_efficiency_ozols_14_25():
    # Ozols digest, derived case (14.25): f = 0.1, eps = 1.6, z 20 / 40: 0.981150 / 0.993717
    assert float(mesh_efficiency(20, 40, 1.6, 0.1)) == pytest.approx(0.981150, abs=5e-7)
    assert float(mesh_efficiency(20, 40, 1.6, 0.1, internal=True)) == pytest.approx(
        0.993717, abs=5e-7
    )
    p = _pair(20, 40)
    assert p.mesh_efficiency(0.1) == pytest.approx(
        1 - math.pi * 0.1 * p.contact_ratio / 2 * (1 / 20 + 1 / 40)
    )
    assert GearPair(Gear(20, 1), Rack(1)).mesh_efficiency(0.1) == pytest.approx(
        1 - math.pi * 0.1 * GearPair(Gear(20, 1), Rack(1)).contact_ratio / 2 / 20
    )


# --- rack branch -------------------------------------------------------------------------------


def test_rack_branch_against_large_wheel():
    # standards.md §1.5 / §6 item 6: z1 = 20 standard with a rack: eps = 1.7688237; the external
    # formula tends to it as O(1/z2)
    p = GearPair(Gear(20, 1), Rack(1))
    assert p.contact_ratio == pytest.approx(1.7688237, abs=5e-8)
    for z2, tol in [(10**3, 1e-2), (10**5, 1e-4), (10**6, 1e-5)]:
        assert _pair(20, z2).contact_ratio == pytest.approx(p.contact_ratio, abs=tol)
    # rack formula (standards.md §1.5) written out, shifted and helical
    for x, beta in [(0.0, 0.0), (0.4, 0.0), (-0.3, 20.0)]:
        g = Gear(20, 2, profile_shift=x, helix_angle=beta)
        q = GearPair(g, Rack(2, helix_angle=-beta))
        at = math.radians(g.transverse_pressure_angle)
        rb, ra, r = g.base_diameter / 2, g.tip_diameter / 2, g.reference_diameter / 2
        eps = (math.sqrt(ra * ra - rb * rb) - r * math.sin(at) + (1 - x) * 2 / math.sin(at)) / (
            math.pi * g.transverse_module * math.cos(at)
        )
        assert q.contact_ratio == pytest.approx(eps, rel=1e-13)
        assert q.working_pressure_angle == pytest.approx(g.transverse_pressure_angle)
        assert q.center_distance == pytest.approx(r + x * 2)
    # rack sliding is the z2 -> inf limit of the gear formula
    u = np.linspace(p.path_of_contact.start, p.path_of_contact.end, 5)
    _, r1, r2 = p.specific_sliding(u)
    _, w1, w2 = _pair(20, 10**7).specific_sliding(u)
    assert r1 == pytest.approx(w1, rel=1e-5) and r2 == pytest.approx(w2, rel=1e-5)


def test_rack_validation():
    with pytest.raises(GearError, match="modules"):
        GearPair(Gear(20, 1), Rack(2))
    with pytest.raises(GearError, match="opposite hand"):
        GearPair(Gear(20, 1, helix_angle=10), Rack(1, helix_angle=10))
    with pytest.raises(GearError, match="module"):
        Rack(0)
    with pytest.raises(GearError, match="centre distance"):
        GearPair.at_center_distance(Gear(20, 1), Rack(1), 10.0)


# --- internal pairs ------------------------------------------------------------------------


def test_internal_pair_formulas():
    # KHK internal pair: inv a_wt = 2 tan a (x2 - x1)/(z2 - z1) + inv a with KHK's ring shift
    # x2 = 0.5 (DIN 3960 sign -0.5: DIN's inv a_wt = 2 tan a (x1 + x2)/(z1 + z2), z2 = -70);
    # a = ((z2 - z1)/2 + y) m; internal pairs keep their tips (no shortening)
    g1, g2 = Gear(20, 2, profile_shift=0.2), Gear(70, 2, internal=True, profile_shift=-0.5)
    p = GearPair(g1, g2)
    from gears.involute import inv, inv_inverse

    aw = float(inv_inverse(2 * TAN20 * (0.5 - 0.2) / 50 + inv(A20)))
    assert math.radians(p.working_pressure_angle) == pytest.approx(aw, rel=1e-13)
    assert p.center_distance == pytest.approx(50 * math.cos(A20) / math.cos(aw), rel=1e-13)
    assert p.tip_alteration == pytest.approx(0.0, abs=1e-12)  # y = x1 + x2: no shortening
    assert p.tip_diameters == pytest.approx((g1.tip_diameter, g2.tip_diameter))
    assert p.reference_center_distance == pytest.approx(50.0)


@pytest.mark.parametrize(
    ("z1", "z2", "x1", "x2"),
    [(20, 60, 0.0, 0.0), (18, 45, 0.3, 0.1), (24, 80, -0.2, 0.4), (30, 41, 0.5, 1.0)],
)
def test_zero_backlash_both_kinds(z1, z2, x1, x2):
    # Joldasbekov (6.40): on the working circles, tooth 1 + tooth 2 = working pitch (external);
    # internal: pinion tooth = ring space. Independent of the alpha_w formula.
    for internal in (False, True):
        g1 = Gear(z1, 2, profile_shift=x1)
        # the ring takes x2 in KHK's sign, as these cases were written: DIN 3960's -x2
        g2 = Gear(z2, 2, profile_shift=-x2 if internal else x2, internal=internal)
        p = GearPair(g1, g2)
        dw1, dw2 = p.working_diameters
        pitch = math.pi * dw1 / z1
        assert math.pi * dw2 / z2 == pytest.approx(pitch, rel=1e-13)
        s1, s2 = g1.tooth_thickness(dw1), g2.tooth_thickness(dw2)
        assert s1 + s2 == pytest.approx(pitch, rel=1e-12)
        sign = -1 if internal else 1
        assert (dw2 + sign * dw1) / 2 == pytest.approx(p.center_distance, rel=1e-13)


def test_internal_limit_of_external_formulas():
    # independent route: the internal contact ratio equals the external formula written with
    # signed radii (a ring is a gear with negative z); checked through the line positions
    g1, g2 = Gear(24, 1, profile_shift=0.2), Gear(90, 1, internal=True, profile_shift=-0.3)
    p = GearPair(g1, g2)
    ra1, ra2 = p.tip_diameters[0] / 2, p.tip_diameters[1] / 2
    rb1, rb2 = g1.base_diameter / 2, g2.base_diameter / 2
    aw = math.radians(p.working_pressure_angle)
    eps = (
        math.sqrt(ra1**2 - rb1**2) - math.sqrt(ra2**2 - rb2**2) + p.center_distance * math.sin(aw)
    ) / g1.base_pitch
    assert p.contact_ratio == pytest.approx(eps, rel=1e-13)


# KHK internal interference scan (standards.md §1.8, x = 0, h_a = 1 m, 20 deg):
# first z2 passing each check; None = never
KHK_SCAN = {
    12: (34, None, 34, 34),
    16: (34, None, 34, 34),
    20: (34, 64, 34, 37),
    24: (34, 40, 34, 41),
    30: (34, 34, 39, 47),
    40: (41, 41, 49, 57),
}
_CHECKS = ("ring_tip_above_base", "involute_interference", "trochoid_interference",
           "radial_interference")  # fmt: skip


def _scan(z1):
    margins = {name: {} for name in _CHECKS}
    for z2 in range(z1 + 1, 120):
        r = GearPair(Gear(z1, 1), Gear(z2, 1, internal=True)).check()
        for name in _CHECKS:
            if name in r:
                margins[name][z2] = r[name].margin
            elif name == "ring_tip_above_base":  # contact impossible: the ring tip check fails
                margins[name][z2] = -1.0
    return margins


@pytest.mark.parametrize("z1", sorted(KHK_SCAN))
def test_khk_internal_interference_scan(z1):
    margins = _scan(z1)
    for name, first in zip(_CHECKS, KHK_SCAN[z1], strict=True):
        passing = sorted(z2 for z2, m in margins[name].items() if m >= 0)
        if first is None:
            assert not passing, name
            continue
        assert passing[0] == first, name
        # and it keeps passing beyond (up to the scan end), so "first" is a real threshold
        assert passing == list(range(first, 120)), name


def test_khk_trochoid_and_radial_fail_when_tip_circles_nest():
    # regression: z1 = 40, z2 = 41 (standards.md §1.8 row 40: trochoid from 49, radial from 57).
    # The ring's tip circle (r = 19.5) lies wholly inside the pinion's (r = 21, a = 0.5): the
    # teeth overlap everywhere, so both checks must fail with a negative margin, not pass.
    r = GearPair(Gear(40, 1), Gear(41, 1, internal=True)).check()
    assert not r["trochoid_interference"].ok
    assert not r["radial_interference"].ok
    # z2 = 42, 43: the pinion's tip circle is larger than the ring's: no radial insertion
    for z2 in (42, 43):
        r = GearPair(Gear(40, 1), Gear(z2, 1, internal=True)).check()
        assert not r["radial_interference"].ok


def test_involute_interference_is_path_start_at_n1():
    # independent route: KHK's involute condition z1/z2 >= 1 - tan a_a2 / tan a_w says the
    # ring's tip stays outside N1, i.e. the path of contact starts at u >= 0
    for z1, z2, x1, x2 in [(20, 50, 0, 0), (20, 70, 0, 0), (24, 38, 0.0, -0.3), (16, 90, 0.5, 0)]:
        p = GearPair(Gear(z1, 1, profile_shift=x1), Gear(z2, 1, internal=True, profile_shift=x2))
        m = p.check()["involute_interference"].margin
        assert (m >= 0) == (p.path_of_contact.start >= 0)


# --- centre distance <-> shifts -------------------------------------------------------------


@pytest.mark.parametrize(
    ("g1", "g2", "a"),
    [
        (Gear(12, 4), Gear(30, 4), 85.143823),
        (Gear(17, 3), Gear(40, 3), 84.0),  # a below a_d: negative shift sum
        (Gear(20, 2), Gear(60, 2, internal=True), 40.5),
        (Gear(20, 2, helix_angle=15), Gear(40, 2, helix_angle=-15), 63.0),
        (Gear(20, 2, helix_angle=15), Gear(70, 2, helix_angle=15, internal=True), 52.3),
    ],
)
@pytest.mark.parametrize("split", ["equal_sliding", "proportional", "keep"])
def test_center_distance_round_trip(g1, g2, a, split):
    if split == "proportional" and g2.internal:
        with pytest.raises(GearError, match="proportional"):
            GearPair.at_center_distance(g1, g2, a, split=split)
        return
    p = GearPair.at_center_distance(g1, g2, a, split=split)
    assert p.center_distance == pytest.approx(a, abs=1e-9)
    # shifts -> centre distance -> shifts
    total = float(
        center_distance_shift_sum(
            g1.teeth, g2.teeth, g1.module, p.center_distance, g1.pressure_angle, g1.helix_angle,
            g2.internal,
        )
    )  # fmt: skip
    # x1 + x2, a ring's x2 in the sign of DIN 3960 too
    assert total == pytest.approx(p.g2.profile_shift + p.g1.profile_shift, abs=1e-9)
    if split == "keep":
        assert p.g1.profile_shift == g1.profile_shift
    if split == "equal_sliding":
        s1, s2 = p.max_specific_sliding
        assert s1 == pytest.approx(s2, rel=1e-8)
    if split == "proportional":
        u = g2.teeth / g1.teeth
        x1 = total / 2 + (0.5 - total / 2) * math.log10(u) / math.log10(g1.teeth * g2.teeth / 100)
        assert p.g1.profile_shift == pytest.approx(x1, abs=1e-12)


def test_equal_sliding_improves_on_keep():
    # the balanced split lowers the worse of the two maxima (Joldasbekov §12 rule 3)
    kept = GearPair.at_center_distance(Gear(12, 4), Gear(30, 4), 85.143823, split="keep")
    even = GearPair.at_center_distance(Gear(12, 4), Gear(30, 4), 85.143823)
    assert max(even.max_specific_sliding) < max(kept.max_specific_sliding)


def test_unreachable_center_distance_and_bad_split():
    with pytest.raises(GearError, match="cannot be reached"):
        GearPair.at_center_distance(Gear(12, 4), Gear(30, 4), 78.0)
    with pytest.raises(GearError, match="split"):
        GearPair.at_center_distance(Gear(12, 4), Gear(30, 4), 85.0, split="magic")


def test_shift_sum_too_negative_names_the_shifts():
    # inv alpha_wt < 0: no working pressure angle exists; the constructor refuses it, naming the
    # shift sum (issue 17: a pair it accepted had check() raise on this)
    with pytest.raises(GearError, match=r"x1 \+ x2 = -2 .* valid is x1 \+ x2 > -0.3"):
        _pair(8, 9, -1.0, -1.0)
    # a ring (DIN 3960 sign): x1 + x2 = 0.6 exceeds 10 inv(20 deg) / (2 tan 20 deg) = 0.2047
    with pytest.raises(GearError, match=r"x1 \+ x2 = 0.6 .* valid is x1 \+ x2 < 0.2047"):
        GearPair(Gear(20, 1, profile_shift=0.5), Gear(30, 1, internal=True, profile_shift=0.1))


# --- helical pairs, validation ------------------------------------------------------------------


def test_helical_pair_hands_and_ratios():
    g1 = Gear(20, 2, helix_angle=15, face_width=20)
    with pytest.raises(GearError, match="opposite hands"):
        GearPair(g1, Gear(40, 2, helix_angle=15))
    with pytest.raises(GearError, match="same hand"):
        GearPair(g1, Gear(80, 2, helix_angle=-15, internal=True))
    with pytest.raises(GearError, match="modules"):
        GearPair(Gear(20, 2), Gear(40, 2.5))
    with pytest.raises(GearError, match="pressure angles"):
        GearPair(Gear(20, 2), Gear(40, 2, pressure_angle=25))
    with pytest.raises(GearError, match="more teeth"):
        GearPair(Gear(40, 2), Gear(40, 2, internal=True))
    with pytest.raises(GearError, match="gear 1 must be external"):
        GearPair(Gear(80, 2, internal=True), Gear(20, 2))
    p = GearPair(g1, Gear(40, 2, helix_angle=-15, face_width=25))
    # lecture digest H1: m_n = 2, beta = 15, b = 20: eps_beta = 0.823847 (smaller face width)
    assert p.overlap_ratio == pytest.approx(0.823847, abs=5e-7)
    assert p.total_contact_ratio == pytest.approx(p.contact_ratio + p.overlap_ratio)
    # the transverse section is a spur pair with m_t, alpha_t (standards.md §1.2)
    at = math.radians(g1.transverse_pressure_angle)
    assert p.center_distance == pytest.approx(30 * 2 / math.cos(math.radians(15)))
    assert math.radians(p.working_pressure_angle) == pytest.approx(at)
    with pytest.raises(GearError, match="face_width"):
        _ = GearPair(Gear(20, 2, helix_angle=15), Gear(40, 2, helix_angle=-15)).overlap_ratio
    # spur: eps_gamma = eps_alpha + eps_beta with eps_beta = 0
    assert _pair(20, 40).total_contact_ratio == pytest.approx(
        _pair(20, 40).contact_ratio, rel=1e-15
    )


# --- path of contact, check() semantics ---------------------------------------------------------


def test_path_of_contact_zones():
    # Joldasbekov E4 / lecture §2.8: double contact share = eps - 1, single zone (2 - eps) p_b
    p = _pair(20, 40)
    path = p.path_of_contact
    lo, hi = path.single_contact
    assert (hi - lo) / path.base_pitch == pytest.approx(2 - p.contact_ratio)
    assert path.length / path.base_pitch == pytest.approx(p.contact_ratio)
    assert path.start < path.pitch_point < path.end < path.n2


def test_pair_check_names_and_configurable_limits():
    p = _pair(12, 24, 0.6, 0.36, m=3)
    r = p.check()
    assert r.ok
    assert {"contact_ratio", "tip_interference", "tip_interference_2"} <= set(r)
    assert {"g1.undercut", "g1.pointed_tip", "g2.undercut", "g2.pointed_tip"} <= set(r)
    assert r["contact_ratio"].margin == pytest.approx(p.contact_ratio - 1.1)
    assert not p.check(min_contact_ratio=1.25).ok
    assert p.check(min_contact_ratio=1.25).failed() == ["contact_ratio"]
    assert p.check(min_tip_land=0.5)["g1.pointed_tip"].margin == pytest.approx(
        p.mounted[0].tip_thickness - 1.5, rel=1e-12
    )
    # the pointed-tip check runs on the shortened tip (pair.mounted), not on the blank
    assert p.mounted[0].tip_diameter < p.g1.tip_diameter
    ri = GearPair(Gear(20, 1), Gear(80, 1, internal=True)).check()
    assert {
        "ring_tip_above_base", "involute_interference", "trochoid_interference",
        "radial_interference", "tip_interference", "tip_interference_2",
    } <= set(ri)  # fmt: skip
    rack = GearPair(Gear(20, 1), Rack(1)).check()
    assert "tip_interference" in rack and "tip_interference_2" not in rack


def test_tip_interference_margin_meaning():
    # margin = distance (mm along the line of action) between the mate's tip point and the
    # start of gear 1's usable involute (its form circle), independent route through radii:
    # contact-start diameter of gear 1 must not be below its form diameter
    for z1, z2, x1 in [(20, 40, 0.0), (14, 60, 0.2), (25, 25, -0.2)]:
        p = _pair(z1, z2, x1)
        g1 = p.mounted[0]
        start_d = 2 * math.hypot(g1.base_diameter / 2, p.path_of_contact.start)
        margin = p.check()["tip_interference"].margin
        assert (margin >= 0) == (start_d >= g1.form_diameter)
    # a pinion undercut by the tool interferes with a rack of the same profile
    r = GearPair(Gear(15, 1), Rack(1)).check()
    assert not r["tip_interference"].ok and not r["g1.undercut"].ok


def test_tip_shortening_switch():
    long = _pair(12, 24, 0.6, 0.36, m=3, tip_shortening=False)
    assert long.tip_diameters == pytest.approx((45.6, 80.16))
    assert long.mounted[0].tip_diameter == pytest.approx(45.6)
    short = _pair(12, 24, 0.6, 0.36, m=3)
    assert short.contact_ratio < long.contact_ratio


def test_pair_geometry_vectorised_matches_pairs():
    z1 = np.array([12, 20, 17, 10])
    z2 = np.array([28, 40, 40, 30])
    x1 = np.array([0.3, 0.0, 0.1, 0.4118])
    x2 = np.array([0.2, 0.0, -0.1, 0.0])
    g = pair_geometry(z1, z2, 2.0, x1, x2)
    for i in range(4):
        p = _pair(int(z1[i]), int(z2[i]), float(x1[i]), float(x2[i]), m=2.0)
        assert g.center_distance[i] == pytest.approx(p.center_distance, rel=1e-14)
        assert g.contact_ratio[i] == pytest.approx(p.contact_ratio, rel=1e-14)


def test_check_marginally_undercut_pinion():
    # Joldasbekov §5.4 last row through the full pair check: only the tip land (0.3 m rule) and
    # the (marginal) undercut may fail; check() must not crash
    r = _pair(10, 30, 0.4118, -0.4118).check(min_tip_land=0.3)
    assert set(r.failed()) <= {"g1.pointed_tip", "g1.undercut", "tip_interference"}
    assert "g1.pointed_tip" in r.failed()


def test_ring_tip_reaching_the_planet_fillet_and_its_remedy():
    # 45/108 internal, m = 2, zero shifts (the 18/45/108 planetary course example): the ring's
    # tip circle cuts the line of action deeper than a rack's tip line would (independent
    # derivation: u_A = u_N2 + sqrt(r_a2^2 - r_b2^2) = 9.054 mm < u_Ff1 = 9.544 mm from N1), so it
    # reaches the planet's fillet. The finding names the ring tip diameter that clears it.
    pair = GearPair(Gear(45, 2), Gear(108, 2, internal=True))
    finding = pair.check()["tip_interference"]
    assert not finding.ok
    assert finding.margin == pytest.approx(-0.4896, abs=1e-4)
    clear = float(finding.message.split("at least ")[1].split(" mm")[0])
    assert clear == pytest.approx(212.2848, abs=1e-4)
    # a ring whose own tip alteration brings d_a2 just above that diameter clears it: the pair
    # honours each gear's own tip alteration
    k = (216.0 - (clear + 0.01)) / (2 * 2) - 1.0  # d_a2 = d2 - 2 m (h_a - x + k)
    ring = Gear(108, 2, internal=True, tip_alteration=k)
    fixed = GearPair(Gear(45, 2), ring)
    assert fixed.tip_diameters[1] == pytest.approx(clear + 0.01)
    assert fixed.check()["tip_interference"].ok
