"""gears.gear: one gear (external, internal, helical) against the seeds and independent routes."""

import math

import numpy as np
import pytest
from scipy.optimize import brentq, minimize_scalar

from gears import BasicRack, Gear
from gears.errors import GearError
from gears.geometry import (
    base_diameter,
    min_profile_shift,
    reference_diameter,
    tip_diameter,
    tooth_thickness,
)
from gears.involute import inv

A20 = math.radians(20.0)


# --- basic diameters ---------------------------------------------------------------------------


def test_spur_diameters_lecture_g1():
    # lecture digest §3.3 G1: z = 20, 40, m = 5: d_a 110 / 210, d_f 87.5 / 187.5,
    # d_b 93.96926 / 187.93852
    g1, g2 = Gear(20, 5), Gear(40, 5)
    assert (g1.reference_diameter, g1.tip_diameter, g1.root_diameter) == pytest.approx(
        (100, 110, 87.5)
    )
    assert (g2.tip_diameter, g2.root_diameter) == pytest.approx((210, 187.5))
    assert (g1.base_diameter, g2.base_diameter) == pytest.approx((93.96926, 187.93852), abs=5e-6)
    # p_b = 14.760657 (G1 extra values)
    assert g1.base_pitch == pytest.approx(14.760657, abs=5e-7)
    assert g1.normal_base_pitch == pytest.approx(14.760657, abs=5e-7)


def test_blank_diameter_ozols_ex_21_1():
    # Ozols Ex 21-1: z = 30, m = 5, normal gear: d_a = m (z + 2) = 160
    assert Gear(30, 5).tip_diameter == pytest.approx(160.0)


def test_root_above_base_from_42_teeth():
    # Ozols §2.11 (line 9277) "root > base if z > 40"; exact for h_f = 1.25 m: z >= 42 (digest)
    assert Gear(41, 1).root_diameter < Gear(41, 1).base_diameter
    assert Gear(42, 1).root_diameter > Gear(42, 1).base_diameter
    assert 2.5 / (1 - math.cos(A20)) == pytest.approx(41.45, abs=0.005)


def test_vectorised_formulas_broadcast():
    z = np.array([12, 20, 40])
    assert reference_diameter(z, 2.0).tolist() == [24.0, 40.0, 80.0]
    assert base_diameter(z, 2.0).shape == (3,)
    da = tip_diameter(z[:, None], 2.0, np.array([0.0, 0.5]))
    assert da.shape == (3, 2) and da[1, 1] == pytest.approx(46.0)


# --- tooth thickness ---------------------------------------------------------------------------


def test_reference_thickness_joldasbekov_5_3():
    # Joldasbekov §5.3: m = 1, xi = 0.5: s = pi/2 + 2 * 0.5 tan 20 = 1.934767, and (6.37) at r_d
    g = Gear(17, 1, profile_shift=0.5)
    assert g.reference_thickness == pytest.approx(1.934767, abs=5e-7)
    # tip thickness, z = 17, xi = 0, R_e = 9.5: s_a = 0.674079 m
    assert Gear(17, 1).tip_thickness == pytest.approx(0.674079, abs=5e-7)
    # lecture digest §3.3 G1: s_a/m = 0.69488 (z = 20), 0.76066 (z = 40); s = 7.85398 (m = 5)
    assert Gear(20, 5).tip_thickness / 5 == pytest.approx(0.69488, abs=5e-6)
    assert Gear(40, 5).tip_thickness / 5 == pytest.approx(0.76066, abs=5e-6)
    assert Gear(20, 5).reference_thickness == pytest.approx(7.85398, abs=5e-6)


@pytest.mark.parametrize(
    "gear",
    [
        Gear(12, 3, profile_shift=0.6),
        Gear(31, 2.5, profile_shift=-0.4),
        Gear(20, 2, helix_angle=25, profile_shift=0.2),
        Gear(60, 2, internal=True, profile_shift=-0.3),
        Gear(71, 1.5, internal=True, helix_angle=-20, profile_shift=0.25),
    ],
)
def test_thickness_from_base_thickness(gear):
    # independent route: the tooth is bounded by two involutes of the base circle, so its
    # angular half-thickness is s_b/d_b -+ inv alpha_y at any diameter (Joldasbekov 6.33-6.37)
    sign = -1.0 if gear.internal else 1.0
    # up to 1.3 d_b, but not past the pointed tip: no thickness exists there (issue 11)
    top = gear.base_diameter * 1.3
    if not gear.internal:
        top = min(top, gear.pointed_tip_diameter)
    d = np.linspace(gear.base_diameter, top, 7)
    alpha_y = np.arccos(gear.base_diameter / d)
    expected = d * (gear.base_thickness / gear.base_diameter - sign * inv(alpha_y))
    assert gear.tooth_thickness(d) == pytest.approx(expected, rel=1e-12, abs=1e-12)
    # s_b = d_b (s_t/d +- inv alpha_t) (standards.md §1.4); s_t = m_t (pi/2 + 2 x tan alpha_n)
    # for a ring too (DIN 3960: its positive shift thickens the teeth)
    at = math.radians(gear.transverse_pressure_angle)
    s_t = gear.transverse_module * (
        math.pi / 2 + 2 * gear.profile_shift * math.tan(math.radians(gear.pressure_angle))
    )
    assert gear.reference_thickness == pytest.approx(s_t, rel=1e-13)
    assert gear.base_thickness == pytest.approx(
        gear.base_diameter * (s_t / gear.reference_diameter + sign * float(inv(at))), rel=1e-13
    )


def test_thickness_inside_base_circle_raises():
    g = Gear(20, 2)
    with pytest.raises(GearError, match="base circle"):
        g.tooth_thickness(g.base_diameter - 0.01)
    with pytest.raises(GearError, match="base circle"):
        tooth_thickness([39.0, 36.0], 20, 2)


@pytest.mark.parametrize(("z", "x"), [(20, 0.0), (33, 0.25), (60, -0.4), (45, 0.8)])
def test_internal_tooth_is_external_space(z, x):
    # independent route: a ring and the external gear cut by the same rack position are
    # complementary; the ring's tooth is the external gear's space. In the sign of DIN 3960 /
    # ISO 21771 (x > 0 moves the tool towards the axis, thickening ring teeth) the external gear
    # cut by that rack position has the opposite shift -x.
    ring = Gear(z, 2, internal=True, profile_shift=-x)
    ext = Gear(z, 2, profile_shift=x)
    d = np.linspace(ring.base_diameter * 1.001, ring.root_diameter, 9)
    space = math.pi * d / z - ext.tooth_thickness(d)
    assert ring.tooth_thickness(d) == pytest.approx(space, rel=1e-12)
    # diameters (KHK, x_KHK = x here): d_a = d - 2(h_a - x) m, d_f = d + 2(h_f + x) m; with the
    # ring's DIN 3960 shift x_DIN = -x: d_a = d - 2(h_a + x_DIN) m, d_f = d + 2(h_f - x_DIN) m
    assert ring.tip_diameter == pytest.approx(2 * z - 2 * 2 * (1 - x))
    assert ring.root_diameter == pytest.approx(2 * z + 2 * 2 * (1.25 + x))
    assert ring.root_diameter == pytest.approx(2 * z + 2 * 2 * 1.25 + 2 * 2 * x)


# --- pointed tip, tip land, undercut ------------------------------------------------------------


def test_ozols_sharp_tooth_statement():
    # Ozols §2.15 (lines 9577-9583) and digest §6: z = 8, x = 0.529 (= (17 - 8)/17, formula
    # 21.28): s_a = 0.043 m, almost pointed; s_a = 0 at x = 0.566
    assert (17 - 8) / 17 == pytest.approx(0.529, abs=5e-4)
    g = Gear(8, 1, profile_shift=0.529)
    assert g.tip_thickness == pytest.approx(0.043, abs=5e-4)
    x0 = brentq(lambda x: Gear(8, 1, profile_shift=x).tip_thickness, 0.4, 0.7, xtol=1e-12)
    assert x0 == pytest.approx(0.566, abs=5e-4)
    # at that shift the tip circle is the pointed-tip circle
    assert Gear(8, 1, profile_shift=x0).pointed_tip_diameter == pytest.approx(
        Gear(8, 1, profile_shift=x0).tip_diameter, rel=1e-9
    )
    # Ozols digest: for z = 7 the undercut-free shift (0.591) already gives s_a < 0, so z = 8 is
    # the smallest undercut-free, non-pointed pinion
    x7 = float(min_profile_shift(7))
    assert x7 == pytest.approx(0.591, abs=5e-4)
    assert Gear(7, 1, profile_shift=x7).tip_thickness < 0
    assert Gear(8, 1, profile_shift=float(min_profile_shift(8))).tip_thickness > 0


def test_tip_land_boundary_standards_6_4():
    # standards.md §6 item 4: z = 10, x = 0.5, m = 1: s_a = 0.199 mm at d_a = 13, d_amax = 13.206
    g = Gear(10, 1, profile_shift=0.5)
    assert g.tip_diameter == pytest.approx(13.0)
    assert g.tip_thickness == pytest.approx(0.199, abs=5e-4)
    assert g.pointed_tip_diameter == pytest.approx(13.206, abs=5e-4)
    assert g.tooth_thickness(g.pointed_tip_diameter) == pytest.approx(0.0, abs=1e-12)
    # the 0.2 m limit fails by ~1 um; the limit is configurable (Joldasbekov §12 uses 0.3 m)
    report = g.check()
    assert not report["pointed_tip"].ok
    assert report["pointed_tip"].margin == pytest.approx(g.tip_thickness - 0.2, abs=1e-12)
    assert g.check(min_tip_land=0.19)["pointed_tip"].ok
    assert not Gear(10, 1, profile_shift=0.4118).check(min_tip_land=0.3).ok


def test_pointed_tip_internal():
    # a ring tooth thins towards its tip (inside); with a large negative shift (DIN 3960 sign:
    # thinner teeth) it points above the base circle, otherwise the base diameter is returned
    ring = Gear(40, 1, internal=True, profile_shift=-1.5)
    assert ring.pointed_tip_diameter > ring.base_diameter
    assert ring.tooth_thickness(ring.pointed_tip_diameter) == pytest.approx(0.0, abs=1e-12)
    plain = Gear(40, 1, internal=True)
    assert plain.pointed_tip_diameter == pytest.approx(plain.base_diameter, rel=1e-15)


@pytest.mark.parametrize(
    ("z", "x_exact", "x_book"),
    [
        # standards.md §1.6 and Joldasbekov §5.2 (exact 1 - z sin^2(20)/2 and book (17 - z)/17)
        (8, 0.532089, 0.529412),
        (9, 0.473600, 0.470588),
        (10, 0.415111, 0.411765),
        (11, 0.356622, 0.352941),
        (12, 0.298133, 0.294118),
        (13, 0.239644, 0.235294),
        (14, 0.181156, 0.176471),
        (15, 0.122667, 0.117647),
        (16, 0.064178, 0.058824),
        (17, 0.005689, 0.0),
    ],
)
def test_min_profile_shift_table(z, x_exact, x_book):
    assert float(min_profile_shift(z)) == pytest.approx(x_exact, abs=5e-7)
    assert (17 - z) / 17 == pytest.approx(x_book, abs=5e-7)
    # ISO 53 A's straight flank ends at 0.99997 m (rho_fP = 0.38 > 0.3799): within 4e-5
    g = Gear(z, 1)
    assert g.min_profile_shift == pytest.approx(x_exact, abs=4e-5)
    # the book's rounded shift leaves a marginal undercut by the exact criterion (lecture §2.9)
    assert Gear(z, 1, profile_shift=x_book).undercut
    assert not Gear(z, 1, profile_shift=x_exact).undercut
    assert g.check()["undercut"].margin == pytest.approx(-g.min_profile_shift)


def test_min_profile_shift_other_angles_and_stub():
    # standards.md §1.6: z_min = 31.90 at 14.5 deg, 11.20 at 25 deg
    for angle, z0 in [(14.5, 31.90), (25.0, 11.20)]:
        root = brentq(lambda z, a=angle: float(min_profile_shift(z, a)), 2, 60)
        assert root == pytest.approx(z0, abs=0.005)
    # stub kappa = 0.8 (Ozols 21.27 with kappa): x_min = 0.8 - z sin^2(alpha)/2
    stub = Gear(10, 1, rack=BasicRack.stub())
    assert stub.min_profile_shift == pytest.approx(0.8 - 10 * math.sin(A20) ** 2 / 2, abs=1e-12)


# --- form circle ------------------------------------------------------------------------------


def test_form_circle_standards_1_7():
    # standards.md §1.7: m = 2, z = 20, x = 0, ISO 53 A: d_Ff = 37.6401 (d_b = 37.5877);
    # m = 1, z = 20: r_Ff = 9.41003 (reproduced there by rack simulation)
    g = Gear(20, 2)
    assert g.form_diameter == pytest.approx(37.6401, abs=5e-5)
    assert g.base_diameter == pytest.approx(37.5877, abs=5e-5)
    assert Gear(20, 1).form_diameter / 2 == pytest.approx(9.41003, abs=5e-6)


def test_form_circle_reaches_base_at_min_shift():
    # independent: at x = x_min the tool's flank end passes through N, so d_Ff = d_b
    for z in (8, 12, 15, 25):
        x = float(min_profile_shift(z, flank_depth=BasicRack.iso53().straight_flank_depth))
        g = Gear(z, 1, profile_shift=x + 1e-13)
        assert g.form_diameter == pytest.approx(g.base_diameter, rel=1e-6)


def test_form_circle_helical_uses_transverse_section():
    # independent: a helical gear's form circle is that of its transverse section, i.e. of a
    # spur gear with m_t, alpha_t and the tool heights h m_n
    h = Gear(23, 2, helix_angle=20, profile_shift=0.1)
    rb = h.base_diameter / 2
    at = math.radians(h.transverse_pressure_angle)
    # h*_eff of ISO 53 A (0.99997) in module units of m_n = 2
    along = h.reference_diameter / 2 * math.sin(at) - (
        h.rack.straight_flank_depth - 0.1
    ) * 2 / math.sin(at)
    assert h.form_diameter == pytest.approx(2 * math.hypot(rb, along), rel=1e-13)


# --- measurements --------------------------------------------------------------------------------


def test_span_reference_values():
    # standards.md §1.9 / §7: machinecalcs worked example m = 2, z = 20: k = 3, W = 15.321
    k, w = Gear(20, 2).span()
    assert k == 3 and w == pytest.approx(15.321, abs=5e-4)
    # lecture digest §3.3: z = 20, m = 5, n = 3: W = 38.302197; z = 12, m = 4, x = 0.3, n = 2:
    # W = 19.205903
    assert Gear(20, 5).span() == (3, pytest.approx(38.302197, abs=5e-7))
    assert Gear(12, 4, profile_shift=0.3).span(2)[1] == pytest.approx(19.205903, abs=5e-7)
    with pytest.raises(GearError, match="k = 20"):
        Gear(20, 2).span(20)
    with pytest.raises(GearError, match="over_pins"):
        Gear(60, 2, internal=True).span()


@pytest.mark.parametrize(
    "gear",
    [Gear(20, 2), Gear(37, 3, profile_shift=0.45), Gear(25, 2, helix_angle=18, profile_shift=-0.2)],
)
def test_span_equals_base_pitches_plus_base_thickness(gear):
    # independent route: the span is tangent to both outer flanks; unrolled on the base
    # cylinder it is (k - 1) base pitches plus one base tooth thickness (transverse), then
    # projected on the normal plane by cos(beta_b)
    for k in (2, 3, 5):
        _, w = gear.span(k)
        bb = math.radians(gear.base_helix_angle)
        assert w == pytest.approx(((k - 1) * gear.base_pitch + gear.base_thickness) * math.cos(bb))


def test_span_k_rule_spans_flanks_near_reference():
    # the standard k puts the caliper contact near the middle of the flank: between the form
    # and the tip circles (independent check of the k rule)
    for z, x in [(12, 0.3), (20, 0.0), (45, 0.5), (80, -0.3), (150, 1.0)]:
        g = Gear(z, 2, profile_shift=x)
        k, w = g.span()
        # contact diameter: the span tangent touches at roll length W/2 on each side (spur)
        d_contact = 2 * math.hypot(g.base_diameter / 2, w / 2)
        assert g.form_diameter < d_contact < g.tip_diameter, (z, x, k)


def _pin_flank_distance(gear, centre_radius):
    """Smallest distance from a pin centre on the space's symmetry line to a tooth flank."""
    z = gear.teeth
    rb = gear.base_diameter / 2
    hi = (gear.root_diameter if gear.internal else gear.tip_diameter) / 2

    def dist(r):
        half = gear.tooth_thickness(2 * r) / (2 * r)
        return math.hypot(
            r * math.cos(half) - centre_radius * math.cos(math.pi / z),
            r * math.sin(half) - centre_radius * math.sin(math.pi / z),
        )

    res = minimize_scalar(dist, bounds=(rb * (1 + 1e-12), hi), method="bounded")
    return res.fun, 2 * res.x


@pytest.mark.parametrize(
    ("gear", "pin"),
    [
        (Gear(20, 2, profile_shift=0.3), 3.5),
        (Gear(21, 2, profile_shift=-0.2), 3.5),
        (Gear(13, 3, profile_shift=0.5), 5.5),
        (Gear(60, 2, internal=True, profile_shift=-0.3), 3.0),
        (Gear(61, 2, internal=True, profile_shift=0.2), 3.0),
    ],
)
def test_over_pins_pin_touches_both_flanks(gear, pin):
    # independent derivation: with the pin centre where over_pins() puts it, the distance from
    # the centre to the involute flank is the pin radius (odd z: the pins sit half a pitch off
    # the diameter, M = 2 R cos(90 deg / z) +- d_p)
    m = gear.over_pins(pin)
    sign = -1 if gear.internal else 1
    centre = (m - sign * pin) / 2
    if gear.teeth % 2:
        centre /= math.cos(math.pi / (2 * gear.teeth))
    distance, _ = _pin_flank_distance(gear, centre)
    assert distance == pytest.approx(pin / 2, abs=1e-7)


def test_ideal_pin_touches_at_shifted_reference():
    # standards.md §1.9: the ideal pin touches on the circle d + 2 x m
    for g in (Gear(20, 2), Gear(25, 2, profile_shift=0.4), Gear(14, 1, profile_shift=-0.1)):
        pin = g.ideal_pin_diameter()
        centre = (g.over_pins(pin) - pin) / 2
        if g.teeth % 2:
            centre /= math.cos(math.pi / (2 * g.teeth))
        distance, d_contact = _pin_flank_distance(g, centre)
        assert distance == pytest.approx(pin / 2, abs=1e-7)
        assert d_contact == pytest.approx(
            g.reference_diameter + 2 * g.profile_shift * g.module, abs=1e-4
        )
    # odd/even consistency: even z and z + 1 give nearly the same pin (smooth in z)
    assert Gear(40, 1).ideal_pin_diameter() == pytest.approx(
        Gear(41, 1).ideal_pin_diameter(), rel=2e-3
    )
    with pytest.raises(GearError, match="too small"):
        Gear(20, 2).over_pins(0.05)


def test_chordal_thickness():
    # lecture digest §3.3: z = 20, m = 5, x = 0: chordal thickness d sin(s/d) = 7.845910,
    # chordal height 5.154133
    s, h = Gear(20, 5).chordal_thickness()
    assert (s, h) == pytest.approx((7.845910, 5.154133), abs=5e-7)
    # independent derivation (KHK form = chord of the reference arc): shifted and internal
    for g in (Gear(15, 2, profile_shift=0.4), Gear(50, 2, internal=True, profile_shift=-0.2)):
        sign = -1 if g.internal else 1
        half = g.reference_thickness / g.reference_diameter
        s, h = g.chordal_thickness()
        assert s == pytest.approx(g.reference_diameter * math.sin(half), rel=1e-13)
        addendum = sign * (g.tip_diameter - g.reference_diameter) / 2
        height = addendum + sign * g.reference_diameter / 2 * (1 - math.cos(half))
        assert h == pytest.approx(height, rel=1e-13)


# --- helical --------------------------------------------------------------------------------------


def test_helical_transverse_quantities():
    # lecture digest §3.3 H1: m_n = 2, beta = 15, z = 20: alpha_t = 20.646896 deg,
    # m_t = 2.070552, d = 41.411047, z_v = z / cos^3 beta = 22.192113 (also Ozols derived)
    h = Gear(20, 2, helix_angle=15)
    assert h.transverse_pressure_angle == pytest.approx(20.646896, abs=5e-7)
    assert h.transverse_module == pytest.approx(2.070552, abs=5e-7)
    assert h.reference_diameter == pytest.approx(41.411047, abs=5e-7)
    assert 20 / math.cos(math.radians(15)) ** 3 == pytest.approx(22.192113, abs=5e-7)
    # the library gives ISO 21771's exact virtual number z / (cos^2 beta_b cos beta), of which
    # Ozols (21.33) z / cos^3 beta is the approximation (they differ by ~1 % at 15 deg)
    bb = math.radians(h.base_helix_angle)
    assert h.virtual_teeth == pytest.approx(20 / (math.cos(bb) ** 2 * math.cos(math.radians(15))))
    assert h.virtual_teeth == pytest.approx(22.192113, rel=0.01)
    # exact z_min for the helical gear: 2 cos beta / sin^2 alpha_t = 15.5378 (lecture H1)
    z0 = brentq(lambda z: float(min_profile_shift(z, 20.0, 15.0)), 5, 30)
    assert z0 == pytest.approx(15.5378, abs=5e-5)
    assert h.hand == "right" and Gear(20, 2, helix_angle=-15).hand == "left"
    assert Gear(20, 2).hand == "spur"


def test_base_helix_angle_ozols_21_30():
    # Ozols derived case: beta = 15 deg with alpha_t = 20 deg gives beta_b = 14.1327 deg via
    # (21.30) tg beta = tg beta_b / cos alpha_t; alpha_t = 20 needs alpha_n = atan(tan20 cos15)
    an = math.degrees(math.atan(math.tan(A20) * math.cos(math.radians(15))))
    h = Gear(20, 2, pressure_angle=an, helix_angle=15)
    assert h.transverse_pressure_angle == pytest.approx(20.0, abs=1e-12)
    assert h.base_helix_angle == pytest.approx(14.1327, abs=5e-5)


def test_helical_tip_land_is_normal():
    # the pointed_tip finding compares the normal tip land s_at cos(beta_a) with 0.2 m_n
    h = Gear(14, 2, helix_angle=30, profile_shift=0.6)
    ba = math.atan(math.tan(math.radians(30)) * h.tip_diameter / h.reference_diameter)
    margin = h.check()["pointed_tip"].margin
    assert margin == pytest.approx(h.tip_thickness * math.cos(ba) - 0.2 * 2, rel=1e-12)


# --- checks and errors ------------------------------------------------------------------------


def test_gear_check_findings():
    r = Gear(12, 3, profile_shift=0.6).check()
    assert list(r) == ["undercut", "tip_above_base", "pointed_tip", "tooth_height"] and r.ok
    ring = Gear(30, 1, internal=True).check()  # z < 34: ring tip inside its base circle
    assert "undercut" not in ring
    assert not ring["tip_above_base"].ok and not ring["pointed_tip"].ok
    assert Gear(34, 1, internal=True).check()["tip_above_base"].ok
    # standards.md §1.8: standard ring tip above base needs z2 >= 34 (2/(1 - cos 20) = 33.16)
    assert not Gear(33, 1, internal=True).check()["tip_above_base"].ok


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"teeth": 0, "module": 1}, "teeth"),
        ({"teeth": -5, "module": 1}, "teeth"),
        ({"teeth": 12.5, "module": 1}, "teeth"),
        ({"teeth": "12", "module": 1}, "teeth"),
        ({"teeth": True, "module": 1}, "teeth"),
        ({"teeth": float("nan"), "module": 1}, "teeth"),
        ({"teeth": 12, "module": 0}, "module"),
        ({"teeth": 12, "module": -1}, "module"),
        ({"teeth": 12, "module": float("inf")}, "module"),
        ({"teeth": 12, "module": 1, "pressure_angle": 0}, "pressure_angle"),
        ({"teeth": 12, "module": 1, "pressure_angle": 45}, "pressure_angle"),
        ({"teeth": 12, "module": 1, "helix_angle": 60}, "helix_angle"),
        ({"teeth": 12, "module": 1, "helix_angle": -60}, "helix_angle"),
        ({"teeth": 12, "module": 1, "profile_shift": float("nan")}, "profile_shift"),
        ({"teeth": 12, "module": 1, "face_width": 0}, "face_width"),
        ({"teeth": 12, "module": 1, "rack": "A"}, "rack"),
    ],
)
def test_invalid_gear_raises_naming_the_value(kwargs, name):
    with pytest.raises(GearError, match=name):
        Gear(**kwargs)


def test_whole_float_and_numpy_teeth_accepted():
    assert Gear(12.0, 1).teeth == 12 and isinstance(Gear(12.0, 1).teeth, int)
    assert Gear(np.int64(12), 1).teeth == 12
    assert Gear(20, 1, pressure_angle=30, helix_angle=59.9).base_diameter > 0
    # near 45 deg the ISO 53 depth leaves the tool no tip land: a stub-depth rack is needed
    deep = BasicRack(pressure_angle=44.9, addendum=0.5, dedendum=0.6, root_radius=0.0)
    assert Gear(20, 1, rack=deep).base_diameter > 0
    with pytest.raises(GearError, match="dedendum"):
        Gear(20, 1, pressure_angle=44.9)


@pytest.mark.parametrize(("z", "x"), [(17, 0.0), (10, 0.4118), (16, 0.06)])
def test_form_diameter_of_marginally_undercut_gear(z, x):
    # a standard 17-tooth gear is undercut by 0.0057 m (x_min = 0.0057, standards.md §1.6); its
    # form circle lies between the base circle and the rack-formula value at x_min
    g = Gear(z, 1, profile_shift=x)
    assert g.undercut
    assert g.base_diameter <= g.form_diameter < g.reference_diameter


def test_internal_form_circle_stays_inside_the_root_circle():
    # the rack-limit form circle of a small shifted ring (z = 40, x = 0.3, m = 1) would lie at
    # 43.1947 mm, beyond the root circle d_f = d + 2 (h_fP + x) m = 43.1 mm (ISO 53 A; found by
    # the profile tests); a usable involute cannot end outside the root, so it is clamped there
    ring = Gear(40, 1, internal=True, profile_shift=-0.3)
    assert ring.root_diameter == pytest.approx(43.1)
    assert ring.form_diameter == pytest.approx(43.1)
    # a large ring keeps its rack-limit value, independent derivation: 2 sqrt(r_b^2 + L^2),
    # L = r sin(a) + (h_eff + x) m / sin(a), h_eff = 1.25 - 0.38 (1 - sin a) (standards.md §1.1)
    big = Gear(80, 2, internal=True)
    a = math.radians(20)
    h_eff = 1.25 - 0.38 * (1 - math.sin(a))
    along = 80 * math.sin(a) + h_eff * 2 / math.sin(a)
    expected = 2 * math.sqrt((80 * math.cos(a)) ** 2 + along**2)
    assert big.form_diameter == pytest.approx(expected, rel=1e-12)
    assert big.form_diameter < big.root_diameter
