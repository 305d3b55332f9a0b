"""Straight bevel gear geometry (issue 19): gears.bevel.cone formulas and the BevelPair/BevelGear
views.

Reference values and their sources:
- KHK Technical Reference (Kohara Gear Industry, "Gear Technical Reference", §4.3 bevel gears):
  Table 4.10, standard straight bevel gears (tapered clearance), and Table 4.11, Gleason straight
  bevel gears (constant clearance), both z = 20/40, m = 3, alpha = 20 deg, Sigma = 90 deg,
  b = 22 mm; printed digits, checked (2026-11-23) against their transcription in the unit tests
  of an independent implementation, bolsover/UtilitiesForAlibre
  UnitTests/BevelGearCalculatorTests.cs (pitch and cone angles, addenda, dedenda, cone distance
  67.08204, crown to apex 58.1955);
- seed-004 digest §2.13 vector B1 (Sigma 90, z 20/40: delta and z_v to 6 decimals) and the Ozols
  digest §2.17 / example list (Sigma 90 and 60 deg, i = 3);
- independent derivations: the sine rule of the pitch cones (z1 / sin delta1 = z2 / sin delta2,
  both cones share a generator), the textbook contact-ratio formula of the Tredgold pair
  written out here, the zero-backlash thickness sum s1 + s2 = pi m_m.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from gears import BevelPair, Gear, GearError, GearPair
from gears.bevel.cone import (
    bevel_geometry,
    face_width_margins,
    gleason_coefficients,
    is_crown,
    pitch_angles,
    virtual_teeth,
)
from gears.bevel.gear import VirtualGear


# ------------------------------------------------------------------------------ cone formulas
def test_seed_vectors_right_angle_and_sixty_degrees():
    # seed-004 B1: Sigma = 90, z 20/40
    d1, d2 = pitch_angles(20, 40, 90.0)
    assert float(d1) == pytest.approx(26.565051, abs=5e-7)
    assert float(d2) == pytest.approx(63.434949, abs=5e-7)
    zv = virtual_teeth([20, 40], [d1, d2])
    np.testing.assert_allclose(zv, [22.360680, 89.442719], atol=5e-7)
    # Ozols digest: Sigma = 90, i = 3 -> 18.4349 / 71.5651, z_v(20) = 21.082
    d1, d2 = pitch_angles(20, 60, 90.0)
    assert (float(d1), float(d2)) == pytest.approx((18.4349, 71.5651), abs=5e-5)
    assert float(virtual_teeth(20, d1)) == pytest.approx(21.082, abs=5e-4)
    # Ozols digest: Sigma = 60, i = 3 -> 13.8979 / 46.1021
    d1, d2 = pitch_angles(20, 60, 60.0)
    assert (float(d1), float(d2)) == pytest.approx((13.8979, 46.1021), abs=5e-5)


@pytest.mark.parametrize("shaft", [30.0, 60.0, 90.0, 120.0, 150.0])
def test_pitch_cones_share_a_generator(shaft):
    # independent: the pitch cones touch along one line, so their base radii at equal cone
    # distance are z m / 2 for both gears: z1 / sin delta1 = z2 / sin delta2, and
    # delta1 + delta2 = Sigma
    p = BevelPair(17, 43, module=2.5, face_width=8, shaft_angle=shaft)
    d1, d2 = (math.radians(d) for d in p.pitch_angles)
    assert math.degrees(d1 + d2) == pytest.approx(shaft, abs=1e-12)
    assert 17 / math.sin(d1) == pytest.approx(43 / math.sin(d2), rel=1e-13)
    # R_e from either gear, and the tangent formula of the standard
    assert p.cone_distance == pytest.approx(2.5 * 43 / (2 * math.sin(d2)), rel=1e-13)
    s = math.radians(shaft)
    assert math.tan(d1) == pytest.approx(math.sin(s) / (43 / 17 + math.cos(s)), rel=1e-12)
    # mean cone distance and module (ISO 23509)
    assert p.mean_cone_distance == pytest.approx(p.cone_distance - 4.0, rel=1e-14)
    assert p.mean_module == pytest.approx(2.5 * p.mean_cone_distance / p.cone_distance)
    # virtual teeth z / cos delta (Tredgold), negative past 90 deg (an internal bevel wheel)
    assert p.virtual_teeth == pytest.approx((17 / math.cos(d1), 43 / math.cos(d2)), rel=1e-12)


# KHK Table 4.10 (standard, tapered clearance) and 4.11 (Gleason, constant clearance): printed
# digits, (pinion, wheel)
KHK_STANDARD = {
    "pitch_angle": ((26.56505, 63.43495), 5e-6),
    "addendum": ((3.0, 3.0), 5e-4),
    "dedendum": ((3.75, 3.75), 5e-4),
    "dedendum_angle": ((3.19960, 3.19960), 5e-6),
    "addendum_angle": ((2.56064, 2.56064), 5e-6),
    "face_angle": ((29.12569, 65.99559), 5e-6),
    "root_angle": ((23.36545, 60.23535), 5e-6),
    "tip_diameter": ((65.36656, 122.68328), 5e-6),
    "crown_to_apex": ((58.6584, 27.3167), 5e-5),
    "axial_face_width": ((19.2374, 8.9587), 5e-5),
    "inner_tip_diameter": ((43.9292, 82.4485), 5e-5),
}
KHK_GLEASON = {
    "pitch_angle": ((26.56505, 63.43495), 5e-6),
    "addendum": ((4.035, 1.965), 5e-4),
    "dedendum": ((2.529, 4.599), 5e-4),
    "dedendum_angle": ((2.15903, 3.92194), 5e-6),
    "addendum_angle": ((3.92194, 2.15903), 5e-6),
    "face_angle": ((30.48699, 65.59398), 5e-6),
    "root_angle": ((24.40602, 59.51301), 5e-6),
    "tip_diameter": ((67.2180, 121.7575), 5e-5),
    "crown_to_apex": ((58.1955, 28.2425), 5e-5),
    "axial_face_width": ((19.0029, 9.0969), 5e-5),
    "inner_tip_diameter": ((44.8425, 81.6609), 5e-5),
}


@pytest.mark.parametrize(
    ("pair", "table"),
    [
        (BevelPair(20, 40, module=3, face_width=22, clearance="tapered"), KHK_STANDARD),
        (BevelPair.gleason(20, 40, module=3, face_width=22), KHK_GLEASON),
    ],
    ids=["KHK-4.10-standard", "KHK-4.11-gleason"],
)
def test_khk_worked_examples_to_their_printed_digits(pair, table):
    assert pair.cone_distance == pytest.approx(67.08204, abs=5e-6)
    # KHK Table 4.10/4.11: d = m z = 60 and 120 mm (computed floats: to rounding)
    assert [pair.g1.reference_diameter, pair.g2.reference_diameter] == pytest.approx(
        [60.0, 120.0], rel=1e-12
    )
    for name, (printed, tol) in table.items():
        got = (getattr(pair.g1, name), getattr(pair.g2, name))
        assert got == pytest.approx(printed, abs=tol), name
    # KHK: the face width "should be less than R/3 or 10 m": 22 < 22.36 and < 30
    assert pair.check()["face_width"].margin == pytest.approx(67.08204 / 3 - 22, abs=1e-5)


def test_gleason_thickness_follows_the_addendum_difference():
    # KHK Table 4.11 (K = 0), outer end: s2 = pi m / 2 - (h_a1 - h_a2) tan(alpha), s1 = pi m - s2
    p = BevelPair.gleason(20, 40, module=3, face_width=22)
    scale = p.cone_distance / p.mean_cone_distance
    s2 = math.pi * 3 / 2 - (4.035 - 1.965) * math.tan(math.radians(20))
    assert p.g2.mean_thickness * scale == pytest.approx(s2, abs=1e-9)
    assert p.g1.mean_thickness * scale == pytest.approx(math.pi * 3 - s2, abs=1e-9)


def test_constant_clearance_keeps_the_mates_cones_parallel():
    p = BevelPair(13, 31, module=4, face_width=15, profile_shift=0.3, clearance="constant")
    g = p.geometry
    # face cone of each gear parallel to the root cone of its mate: theta_a1 = theta_f2
    assert g.addendum_angle[0] == pytest.approx(g.dedendum_angle[1], abs=1e-12)
    assert g.addendum_angle[1] == pytest.approx(g.dedendum_angle[0], abs=1e-12)
    # so the clearance (mate's dedendum minus addendum) is the same at both ends
    c_outer = g.dedendum[1] - g.addendum[0]
    c_inner = (g.mean_dedendum[1] - p.face_width / 2 * math.tan(math.radians(g.dedendum_angle[1]))
               - g.inner_addendum[0])  # fmt: skip
    assert c_outer == pytest.approx(c_inner, abs=1e-12)
    assert c_outer == pytest.approx(0.25 * p.mean_module + p.face_width / 2 * 0.0, rel=0.3)
    # tapered: every cone through the pitch apex, heights proportional to the cone distance
    t = BevelPair(13, 31, module=4, face_width=15, profile_shift=0.3, clearance="tapered")
    r = t.cone_distance / t.mean_cone_distance
    assert t.g1.addendum == pytest.approx(t.geometry.mean_addendum[0] * r, rel=1e-13)


def test_thickness_sum_and_modification():
    # zero backlash: the two arcs on the mean pitch cone fill one circular pitch pi m_m
    p = BevelPair(11, 23, module=2, face_width=6, profile_shift=0.4, thickness_modification=0.05)
    assert p.g1.mean_thickness + p.g2.mean_thickness == pytest.approx(math.pi * p.mean_module)
    tan_a = math.tan(math.radians(20))
    assert p.g1.mean_thickness == pytest.approx(
        p.mean_module * (math.pi / 2 + 2 * 0.4 * tan_a + 0.05), rel=1e-14
    )
    # the virtual gear's own (spur) thickness formula gives the same arc: an independent route
    v1, v2 = p.virtual_pair.g1, p.virtual_pair.g2
    assert v1.reference_thickness == pytest.approx(p.g1.mean_thickness, rel=1e-12)
    assert v2.reference_thickness == pytest.approx(p.g2.mean_thickness, rel=1e-12)
    # and its tip and root are the bevel gear's at the mean cone
    assert v1.tip_diameter == pytest.approx(v1.reference_diameter + 2 * p.geometry.mean_addendum[0])
    assert v2.root_diameter == pytest.approx(
        v2.reference_diameter - 2 * p.geometry.mean_dedendum[1]
    )


def _textbook_contact_ratio(p: BevelPair) -> float:
    """epsilon = (sqrt(ra1^2 - rb1^2) + sqrt(ra2^2 - rb2^2) - a sin(alpha)) / (pi m cos(alpha)),
    on the virtual gears at the mean cone (Ozols (21.12) on Tredgold's gears)."""
    a = math.radians(p.pressure_angle)
    g = p.geometry
    r = [g.virtual_diameter[i] / 2 for i in (0, 1)]
    ra = [r[i] + g.mean_addendum[i] for i in (0, 1)]
    rb = [r[i] * math.cos(a) for i in (0, 1)]
    path = sum(math.sqrt(ra[i] ** 2 - rb[i] ** 2) for i in (0, 1)) - (r[0] + r[1]) * math.sin(a)
    return path / (math.pi * p.mean_module * math.cos(a))


@pytest.mark.parametrize(
    "pair",
    [
        BevelPair(20, 40, module=3, face_width=22, clearance="tapered"),
        BevelPair.gleason(20, 40, module=3, face_width=22),
        BevelPair(15, 27, module=2, face_width=9, shaft_angle=70, profile_shift=0.2),
    ],
)
def test_virtual_pair_and_contact_ratio(pair):
    v = pair.virtual_pair
    assert isinstance(v, GearPair)
    assert all(isinstance(g, VirtualGear) for g in (v.g1, v.g2))
    assert (v.g1.teeth, v.g2.teeth) == pytest.approx(pair.virtual_teeth, rel=1e-14)
    assert v.center_distance == pytest.approx(sum(pair.geometry.virtual_diameter) / 2)
    assert pair.contact_ratio == pytest.approx(_textbook_contact_ratio(pair), rel=1e-12)


def test_crown_and_internal_virtual_pairs():
    # Sigma = 120 deg, z 20/40: tan delta1 = sin 120 / (2 + cos 120) -> delta1 = 30, delta2 = 90
    crown = BevelPair(20, 40, module=3, face_width=10, shaft_angle=120)
    assert crown.pitch_angles == pytest.approx((30.0, 90.0), abs=1e-12)
    assert crown.virtual_pair.is_rack
    # Sigma = 150: delta2 > 90, an internal bevel wheel whose virtual gear is a ring
    ring = BevelPair(20, 40, module=3, face_width=10, shaft_angle=150)
    assert ring.pitch_angles[1] > 90 and ring.g2.internal
    assert ring.virtual_pair.internal and ring.virtual_pair.g2.teeth == pytest.approx(
        -ring.virtual_teeth[1]
    )
    assert ring.contact_ratio > 1.0
    assert ring.check()["contact_ratio"].ok


@settings(max_examples=30, deadline=None)
@given(z1=st.integers(5, 60), extra=st.integers(1, 60))
def test_a_crown_wheel_is_one_decision(z1, extra):
    # issue 26: delta2 = Sigma - delta1 = 90 deg rounded to 89.99999999999999, so the checks
    # took a crown wheel (z_v infinite) while the solid was drawn inside out (volume -493 mm^3).
    # A crown wheel (derivation: equal cone distances z1 / sin delta1 = z2 / sin 90 give
    # sin delta1 = z1 / z2 and Sigma = 90 + delta1): its pitch angle is within the tolerance of
    # 90, the checks see a rack and the solid is refused, never drawn with a negative volume
    z2 = z1 + extra
    shaft = 90.0 + math.degrees(math.asin(z1 / z2))
    d2 = float(pitch_angles(z1, z2, shaft)[1])
    assert abs(d2 - 90.0) <= 1e-9 and is_crown(d2)
    try:
        p = BevelPair(z1, z2, 3, 1.0, shaft)
    except GearError:
        return
    assert math.isinf(p.virtual_teeth[1]) and not p.g2.internal
    assert p.virtual_pair.is_rack
    with pytest.raises(GearError, match="crown"):
        p.g2.mesh(0.05)


def test_the_crown_wheel_of_the_issue_is_refused_by_the_cli(capsys, tmp_path):
    from trains.cli.app import main

    out = tmp_path / "crown.stl"
    argv = ["bevel", "20", "40", "-m", "3", "-b", "10", "--shaft-angle", "120", "--scene", out]
    assert main([str(a) for a in argv]) == 2
    assert "crown" in capsys.readouterr().err and not out.exists()


def test_virtual_gears_have_no_outline_and_gears_keep_whole_teeth():
    v = BevelPair(20, 40, module=3, face_width=20).virtual_pair.g1
    with pytest.raises(GearError, match="virtual gear"):
        v.outline()
    with pytest.raises(GearError, match="virtual gear"):
        v.mesh(10)
    with pytest.raises(GearError, match="whole number"):
        Gear(22.36, 1)  # a real gear keeps an integer tooth count


# ------------------------------------------------------------------------------ checks
def test_face_width_findings_and_limit():
    p = BevelPair(20, 40, module=3, face_width=30)  # R_e / 3 = 22.36
    f = p.check()["face_width"]
    assert not f.ok and f.margin == pytest.approx(67.08204 / 3 - 30, abs=1e-5)
    assert "R_e/3" in f.message
    ok = BevelPair(20, 40, module=3, face_width=20).check()
    assert ok["face_width"].ok and ok["face_width_module"].margin == pytest.approx(10.0)
    assert [float(v) for v in face_width_margins(35.0, 67.08204, 3.0)] == pytest.approx(
        [67.08204 / 3 - 35, -5.0]
    )
    with pytest.raises(GearError, match=r"face_width = 70 mm reaches the pitch apex.*67\.08"):
        BevelPair(20, 40, module=3, face_width=70)


def test_undercut_of_a_small_pinion_is_reported_and_a_shift_cures_it():
    # z = 10 with the 16-tooth side gear of the seeds' differential: z_v = 11.8 < 17
    p = BevelPair(10, 16, module=3, face_width=8)
    f = p.check()["g1.undercut"]
    zv = p.virtual_teeth[0]
    x_min = 1.0 - zv * math.sin(math.radians(20)) ** 2 / 2  # Tredgold, ISO 53 A flank depth 1.0
    assert not f.ok and f.margin == pytest.approx(-x_min, abs=2e-3)
    assert "virtual (Tredgold)" in f.message
    cured = BevelPair(10, 16, module=3, face_width=8, profile_shift=x_min + 0.01)
    assert cured.check()["g1.undercut"].ok
    # a larger pressure angle lowers x_min (z_v sin^2(alpha) / 2 grows): 25 deg needs about 0.02
    steep = BevelPair(10, 16, module=3, face_width=8, pressure_angle=25, profile_shift=0.05)
    assert steep.check()["g1.undercut"].ok


def test_tip_land_at_the_ends_follows_the_face_cone():
    # a large shift sharpens the pinion; with constant clearance its outer end is the sharper one
    p = BevelPair(12, 40, module=3, face_width=12, profile_shift=0.7)
    f = p.check()["g1.tip_land_ends"]
    assert "outer end" in f.message
    # tapered: the relative addendum is the same at both ends, so the land is relatively larger
    t = BevelPair(12, 40, module=3, face_width=12, profile_shift=0.7, clearance="tapered")
    assert f.margin < t.check()["g1.tip_land_ends"].margin
    sharp = BevelPair(12, 40, module=3, face_width=12, profile_shift=1.1)
    assert not sharp.check()["g1.tip_land_ends"].ok


def test_gear_view_and_describe():
    p = BevelPair(20, 40, module=3, face_width=22, clearance="tapered")
    assert p.g1.mate is p.g2 and p.g2.mate is p.g1
    assert (p.g1.teeth, p.g2.teeth) == (20, 40)
    assert p.ratio == pytest.approx(2.0, rel=1e-12)  # u = z2 / z1
    assert p.g2.check()["undercut"].ok and "g2." not in "".join(p.g2.check())
    text = p.describe()
    assert "65.99559" in text and "67.0820" in text and "pinion" in text
    assert p.mesh_efficiency(0.1) == pytest.approx(
        1 - math.pi * 0.1 * p.contact_ratio / 2 * (1 / p.virtual_teeth[0] + 1 / p.virtual_teeth[1])
    )


def test_gleason_coefficients_vectorised():
    k = gleason_coefficients([20, 16], [40, 49], [3.0, 5.08], [22.0, 22.0])
    assert np.shape(k[0]) == (2,)
    g = bevel_geometry([20, 16], [40, 49], [3.0, 5.08], [22.0, 22.0], addendum=k[0],
                       dedendum=k[1], profile_shift=k[2])  # fmt: skip
    # whole depth 2.188 m at the outer end for both pairs (KHK's Gleason system)
    np.testing.assert_allclose(g.addendum + g.dedendum, [[6.564, 11.11504]] * 2, rtol=1e-12)


# ------------------------------------------------------------------------------ bad input
@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"z1": 0}, "z1"),
        ({"z2": 2.5}, "z2"),
        ({"module": -1}, "module"),
        ({"module": 1e300}, "module"),
        ({"face_width": float("nan")}, "face_width"),
        ({"shaft_angle": 180}, "shaft_angle"),
        ({"shaft_angle": 0}, "shaft_angle"),
        ({"shaft_angle": "x"}, "shaft_angle"),
        ({"pressure_angle": 50}, "pressure_angle"),
        ({"clearance": "uniform"}, "clearance"),
        ({"profile": "involute"}, "profile"),
        ({"dedendum": 0.9}, "dedendum"),
        ({"tool_radius": -0.1}, "tool_radius"),
        ({"tool_radius": 0.9}, r"tool_radius = 0.9 .* valid is 0 <= tool_radius <= 0.4"),
        ({"profile_shift": float("inf")}, "profile_shift"),
    ],
)
def test_bad_input_names_the_value(kwargs, match):
    args = {"z1": 20, "z2": 40, "module": 3, "face_width": 10, **kwargs}
    with pytest.raises(GearError, match=match):
        BevelPair(**args)


def test_root_cone_through_the_axis_is_refused():
    with pytest.raises(GearError, match="root cone angle"):
        BevelPair(2, 200, module=1, face_width=5)  # delta1 = 0.57 deg < theta_f1 = 0.72 deg


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    z1=st.integers(1, 200),
    z2=st.integers(1, 200),
    module=st.floats(1e-3, 1e3),
    face=st.floats(0.01, 0.99),
    shaft=st.floats(0.5, 179.5),
    pa=st.floats(5, 35),
    x=st.floats(-1.5, 1.5),
    xs=st.floats(-0.2, 0.2),
    clearance=st.sampled_from(["constant", "tapered"]),
)
def test_property_finite_answer_or_gear_error(z1, z2, module, face, shaft, pa, x, xs, clearance):
    r_e = module * z1 / (2 * math.sin(math.radians(float(pitch_angles(z1, z2, shaft)[0]))))
    try:
        p = BevelPair(z1, z2, module, face * r_e, shaft, pa, x, xs, clearance=clearance)
    except GearError as exc:
        assert str(exc)
        return
    values = [*p.pitch_angles, p.cone_distance, *p.virtual_teeth, *p.tip_diameters]
    assert all(not math.isnan(v) for v in values)
    assert sum(p.pitch_angles) == pytest.approx(shaft)
    rep = p.check()  # never raises, no NaN margin (Finding refuses NaN)
    assert len(rep) >= 6
    try:
        eps = p.contact_ratio
    except GearError as exc:  # e.g. a virtual ring whose tip lies inside its base circle
        assert "base circle" in str(exc)
    else:
        assert math.isfinite(eps) and eps >= 0


@settings(max_examples=40, deadline=None)
@given(
    n=st.integers(1, 50),
    seed=st.integers(0, 2**31 - 1),
    clearance=st.sampled_from(["constant", "tapered"]),
)
def test_property_vectorised_formulas_match_the_pair_view(n, seed, clearance):
    # arrays of valid pairs: every field finite, the pitch cones summing to the shaft angle, and
    # each row equal to the BevelPair built from it (one formula, two views)
    rng = np.random.default_rng(seed)
    z1 = rng.integers(8, 60, n)
    z2 = rng.integers(8, 90, n)
    m = rng.uniform(0.5, 10.0, n)
    shaft = rng.uniform(30.0, 150.0, n)
    x = rng.uniform(-0.3, 0.5, n)
    d1, _ = pitch_angles(z1, z2, shaft)
    r_e = m * z1 / (2 * np.sin(np.radians(d1)))
    b = r_e * rng.uniform(0.05, 0.33, n)
    g = bevel_geometry(z1, z2, m, b, shaft, 20.0, x, 0.0, clearance=clearance)
    for field, value in g._asdict().items():
        if field in ("virtual_teeth", "virtual_diameter"):
            continue  # infinite for a crown wheel (delta = 90 deg), by definition
        assert np.all(np.isfinite(value)), field
    np.testing.assert_allclose(g.pitch_angle.sum(axis=0), shaft, rtol=1e-12)
    i = int(rng.integers(0, n))
    try:
        p = BevelPair(int(z1[i]), int(z2[i]), float(m[i]), float(b[i]), float(shaft[i]),
                      profile_shift=float(x[i]), clearance=clearance)  # fmt: skip
    except GearError:
        return  # a row no blank can carry (e.g. a root cone through the axis)
    assert p.g1.face_angle == pytest.approx(float(g.face_angle[0, i]), rel=1e-12)
    assert p.g2.tip_diameter == pytest.approx(float(g.tip_diameter[1, i]), rel=1e-12)
