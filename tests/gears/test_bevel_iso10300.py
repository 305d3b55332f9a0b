"""gears.bevel.iso10300: the factors of ISO 10300 method B1 (issue 30).

Source: ISO/TR 10300-30:2024, Annex A, sample 1 (a spiral bevel pair without offset, z 14/39,
m_mn 3.213 mm, beta_m 35 deg, b 25.4 mm, b_eff 0.85 b, T1 300 N m), its printed inputs and
results as transcribed in an open ISO 10300 calculator's self-test: the virtual gears (d_v, d_va,
d_vb, z_v, z_vn, d_van, d_vbn, p_vet, g_va, eps_va, eps_vb, beta_vb), then Z_M-B 0.916, l_bm
22.442 mm, Z_LS 0.935, rho_t 13.173 mm, rho_rel 12.459 mm, K_Hbeta 1.650, Y_LS 0.873, Y_eps
0.625, Y_BS 1.054, the pinion's root s_Fn 7.423 mm, rho_F 1.023 mm, h_Fa 6.405 mm, alpha_Fan
31.534 deg, Y_Fa 2.033, Y_Sa 2.022, q_s 3.630, the wheel's Y_Fa 2.480, Y_Sa 1.706, q_s 2.166,
sigma_H0 1168.5 MPa (F_n 14193.3 N, Z_E 191.646) and sigma_HP1 1617.8 MPa (Z_L 0.992, Z_v 0.974,
Z_R 0.930, Z_NT 1). The report prints three or four digits and its inputs to three decimals: the
tolerance is 3e-3 relative (3.5e-3 where its chain of rounded inputs is longest).
Straight teeth: independent derivations written here from the equations (the inner point of
single contact, the ellipse of the contact pattern, Hertz's radius of the virtual pair).
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears.bevel.iso10300 import (
    BEVEL_FACTOR,
    MOUNTING_FACTORS,
    bevel_spiral_angle_factor,
    contact_line_length,
    contact_line_positions,
    contact_ratio_factor_root,
    face_load_factors,
    load_sharing_factor,
    mid_zone_factor,
    mounting_factor,
    relative_curvature,
    tip_form_factors,
    zone_of_action,
)
from gears.errors import GearError

# ISO/TR 10300-30:2024 sample 1, virtual cylindrical gears (ISO 10300-1 Annex A)
S1 = dict(
    alpha_vet=23.957, d_v1=58.350, d_v2=452.804, d_va1=68.023, d_va2=455.984, d_vb1=53.323,
    d_vb2=413.796, z_v1=14.875, z_v2=115.431, p_vet=11.262, g_va=13.120, eps_va=1.165,
    eps_vb=1.227, beta_v=35.0, beta_vb=32.615, b_veff=21.590, b_v=25.400, m_mn=3.213,
    z_vn1=25.594, z_vn2=198.613, d_van1=91.915, d_vbn1=77.281, h_m1=4.837 + 2.393,
    h_m2=1.590 + 5.640,
)  # fmt: skip
RTOL = 3e-3


def _sample1_lines(exponent=3.0):
    s = S1
    f_max, l_b0 = zone_of_action(s["g_va"], s["b_veff"], s["beta_vb"])
    f = contact_line_positions(s["p_vet"], s["eps_va"], s["eps_vb"], s["beta_vb"])
    l_b = [contact_line_length(fi, f_max, l_b0, s["b_veff"], s["b_v"]) for fi in f]
    return f, f_max, l_b, load_sharing_factor(f, f_max, l_b, exponent)


def test_sample1_pitting_factors():
    s = S1
    z_mb = mid_zone_factor(s["alpha_vet"], s["d_va1"], s["d_vb1"], s["z_v1"], s["d_va2"],
                           s["d_vb2"], s["z_v2"], s["eps_va"], s["eps_vb"])  # fmt: skip
    assert float(z_mb) == pytest.approx(0.916, rel=RTOL)
    # the middle line of sample 1 (eps_vb >= 1) crosses the zone's centre; its length and the
    # load sharing over tip, middle and root lines (low profile crowning: e_LS = 3)
    f, _, l_b, z_ls = _sample1_lines()
    assert float(f[1]) == pytest.approx(0.0, abs=1e-12)
    assert float(l_b[1]) == pytest.approx(22.442, rel=RTOL)
    assert float(z_ls) == pytest.approx(0.935, rel=RTOL)
    assert float(z_ls) ** 2 == pytest.approx(0.873, rel=RTOL)  # Y_LS = Z_LS^2 (ISO 10300-3)
    rho = relative_curvature(s["d_v1"], s["d_v2"], 20.0, s["beta_v"])
    assert float(rho) == pytest.approx(12.459, rel=RTOL)
    # sigma_H0 = sqrt(F_n / (l_bm rho_rel)) Z_M-B Z_LS Z_E with the report's F_n and Z_E
    s_h0 = math.sqrt(14193.3 / (l_b[1] * rho)) * z_mb * z_ls * 191.646
    assert float(s_h0) == pytest.approx(1168.5, rel=3.5e-3)
    # sigma_HP1 = sigma_Hlim Z_NT Z_X Z_L Z_v Z_R Z_W Z_K: the report's 1617.8 MPa needs Z_K 1.2
    assert 1500.0 * 0.992 * 0.974 * 0.930 * BEVEL_FACTOR == pytest.approx(1617.8, rel=RTOL)
    # K_Hbeta-C = 1.5 K_Hbeta-be: one member cantilever, pattern checked under a light test load
    kh, kf = face_load_factors(mounting_factor("one-straddle", "light-load"))
    assert float(kh) == pytest.approx(1.650, rel=1e-12)
    assert float(kf) == pytest.approx(1.650, rel=1e-12)


def test_sample1_bending_factors():
    s = S1
    y = tip_form_factors(s["z_vn1"], s["m_mn"], 0.505, 0.036, 20.0, s["d_van1"], s["d_vbn1"],
                         1.25, 0.8 / s["m_mn"])  # fmt: skip
    y_fa, y_sa, s_fn, rho_f, h_fa, a_fan, q_s = (float(v) for v in y)
    assert s_fn == pytest.approx(7.423, rel=RTOL)
    assert rho_f == pytest.approx(1.023, rel=RTOL)
    assert h_fa == pytest.approx(6.405, rel=RTOL)
    assert math.degrees(a_fan) == pytest.approx(31.534, rel=RTOL)
    assert y_fa == pytest.approx(2.033, rel=RTOL)
    assert y_sa == pytest.approx(2.022, rel=RTOL)
    assert q_s == pytest.approx(3.630, rel=RTOL)
    # the wheel: x_hm2 = -0.505, x_sm2 = -0.055, tool tip radius 1.2 mm; its normal-section
    # virtual gear d_vn = z_vn m_mn, d_van = d_vn + 2 h_am2, d_vbn = d_vn cos alpha_n
    d_vn2 = s["z_vn2"] * s["m_mn"]
    y = tip_form_factors(s["z_vn2"], s["m_mn"], -0.505, -0.055, 20.0, d_vn2 + 2 * 1.590,
                         d_vn2 * math.cos(math.radians(20.0)), 1.25, 1.2 / s["m_mn"])  # fmt: skip
    assert float(y[0]) == pytest.approx(2.480, rel=RTOL)
    assert float(y[1]) == pytest.approx(1.706, rel=RTOL)
    assert float(y[6]) == pytest.approx(2.166, rel=RTOL)
    assert float(contact_ratio_factor_root(s["eps_va"], s["eps_vb"])) == pytest.approx(0.625)
    _, _, l_b, _ = _sample1_lines()
    y_bs = bevel_spiral_angle_factor(s["beta_v"], s["beta_vb"], l_b[1], s["b_v"], s["h_m1"],
                                     s["h_m2"])  # fmt: skip
    assert float(y_bs) == pytest.approx(1.054, rel=RTOL)


def test_mounting_factor_table():
    # ISO 10300-1 (2014), the mounting factor K_Hbeta-be as printed in the FVA-Workbench
    # documentation (attribute 233): rows by how the pattern was checked, columns by mounting
    table = {"full-load": (1.0, 1.0, 1.0), "light-load": (1.05, 1.10, 1.25),
             "estimated": (1.20, 1.32, 1.50)}  # fmt: skip
    for pattern, row in table.items():
        got = [mounting_factor(m, pattern) for m in ("both-straddle", "one-straddle",
                                                     "neither-straddle")]  # fmt: skip
        assert got == pytest.approx(list(row), abs=1e-12)
    assert set(MOUNTING_FACTORS) == set(table)
    with pytest.raises(GearError, match="mounting"):
        mounting_factor("bolted")
    with pytest.raises(GearError, match="pattern"):
        mounting_factor("both-straddle", "guessed")


@pytest.mark.parametrize("eps", [1.05, 1.3, 1.6, 1.95])
def test_straight_teeth_independently(eps):
    """Straight teeth (beta = 0): the middle line is the inner point of single contact of the
    pinion, g/2 - p from the zone's centre; the tip line ends the zone, the root line lies
    beyond it, so Z_LS = 1 for eps_va < 2; the contact pattern's ellipse shortens the middle
    line to b_eff (1 - sqrt(r^2 + k^2 (1 - r^2))), r = 1 - 2 / eps_va."""
    p, b, w = 8.0, 20.0, 0.85
    g = eps * p
    f_max, l_b0 = zone_of_action(g, w * b)
    assert float(f_max) == pytest.approx(g / 2, rel=1e-12)
    assert float(l_b0) == pytest.approx(w * b, rel=1e-12)
    f = contact_line_positions(p, eps, 0.0)
    assert [float(x) for x in f] == pytest.approx([g / 2, g / 2 - p, g / 2 - 2 * p], abs=1e-12)
    l_b = [contact_line_length(x, f_max, l_b0, w * b, b) for x in f]
    r, k = 1.0 - 2.0 / eps, 1.0 - math.sqrt(w)
    assert float(l_b[1]) == pytest.approx(w * b * (1 - math.sqrt(r * r + k * k * (1 - r * r))))
    assert float(l_b[0]) == pytest.approx(0.0, abs=1e-12)
    for e_ls in (1.5, 3.0):
        assert float(load_sharing_factor(f, f_max, l_b, e_ls)) == pytest.approx(1.0, abs=1e-12)
    # Y_eps = 0.25 + 0.75 / eps_va for eps_vb = 0
    assert float(contact_ratio_factor_root(eps, 0.0)) == pytest.approx(0.25 + 0.75 / eps)


def test_straight_mid_zone_factor_is_iso6336_single_pair_factor():
    # eps_vb = 0: F1 = 2, F2 = 2 (eps - 1): ISO 6336-2's Z_B, written here from its equation
    z1, z2, m, a = 18.0, 41.0, 2.5, math.radians(20.0)
    d1, d2 = z1 * m, z2 * m
    da1, da2 = d1 + 2 * m, d2 + 2 * m
    db1, db2 = d1 * math.cos(a), d2 * math.cos(a)
    g = (math.sqrt(da1**2 - db1**2) + math.sqrt(da2**2 - db2**2)) / 2 - (d1 + d2) / 2 * math.sin(a)
    eps = g / (math.pi * m * math.cos(a))
    m1 = math.sqrt(da1**2 / db1**2 - 1) - 2 * math.pi / z1
    m2 = math.sqrt(da2**2 / db2**2 - 1) - (eps - 1) * 2 * math.pi / z2
    z_b = math.tan(a) / math.sqrt(m1 * m2)
    got = mid_zone_factor(20.0, da1, db1, z1, da2, db2, z2, eps, 0.0)
    assert float(got) == pytest.approx(z_b, rel=1e-12)
    # and Hertz's relative radius at the pitch point for straight teeth
    rho = relative_curvature(d1, d2, 20.0)
    assert float(rho) == pytest.approx(math.sin(a) * d1 * d2 / 2 / (d1 + d2), rel=1e-12)


@settings(max_examples=40, deadline=None)
@given(st.floats(8.0, 200.0), st.floats(8.0, 400.0), st.floats(1.0, 1.99), st.floats(0.0, 3.0),
       st.floats(0.3, 1.0), st.floats(0.0, 40.0))  # fmt: skip
def test_factors_property(z1, z2, eps, eps_b, w, beta):
    """Finite factors in range over the method's scope; the arrays broadcast."""
    a = 20.0
    d1, d2 = z1 * 3.0, z2 * 3.0
    z_mb = mid_zone_factor(a, d1 + 6, d1 * math.cos(math.radians(a)), z1, d2 + 6,
                           d2 * math.cos(math.radians(a)), z2, eps, eps_b)  # fmt: skip
    assert np.isnan(z_mb) or 0.0 < z_mb < 10.0
    p = 3.0 * math.pi * math.cos(math.radians(a))
    f_max, l_b0 = zone_of_action(eps * p, w * 20.0, beta)
    f = contact_line_positions(p, eps, eps_b, beta)
    l_b = [contact_line_length(x, f_max, l_b0, w * 20.0, 20.0) for x in f]
    assert all(0.0 <= float(x) <= float(l_b0) + 1e-9 for x in l_b)
    if float(l_b[1]) > 0:
        z_ls = float(load_sharing_factor(f, f_max, l_b))
        assert 0.0 < z_ls <= 1.0
    assert 0.625 <= float(contact_ratio_factor_root(eps, eps_b)) <= 1.0
    arr = contact_ratio_factor_root(np.array([1.2, eps]), np.array([[0.0], [eps_b]]))
    assert arr.shape == (2, 2)
