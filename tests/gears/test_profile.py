"""Analytic tooth outlines (gears/profile.py): thickness, tolerance, meshing, stability."""

import math

import numpy as np
import pytest
import shapely

from gears import BasicRack, Gear, GearError, GearPair, ShaperCutter
from gears.cutting.measure import thickness_on
from gears.cutting.profile import ToothProfile, outline, undercut_form_diameter

GEARS = {
    "z20": Gear(20, 1),
    "z12_x0.6_m3": Gear(12, 3, profile_shift=0.6),
    "z17_x-0.3": Gear(17, 2, profile_shift=-0.3),  # undercut
    "helical_z20_b30": Gear(20, 1, helix_angle=30, profile_shift=0.2),
    "ring_z80": Gear(80, 2, internal=True),
    "ring_z40_x-0.3": Gear(40, 1, internal=True, profile_shift=-0.3),
}


def _flank_diameters(g, n=6):
    tip = g.tip_diameter if g.internal else min(g.tip_diameter, g.pointed_tip_diameter)
    lo, hi = sorted([g.form_diameter, tip])
    return np.linspace(lo, hi, n + 2)[1:-1]


@pytest.mark.parametrize("name", GEARS)
@pytest.mark.parametrize("tol", [1e-2, 1e-3, 1e-4])
def test_thickness_on_outline_matches_formula(name, tol):
    # source: standards.md §1.4 (s_y = d_y (s_t/d + inv a_t - inv a_yt)) via Gear.tooth_thickness
    g = GEARS[name]
    p = outline(g, tol)
    for d in _flank_diameters(g):
        s = thickness_on(p, d)
        assert len(s) == g.teeth
        assert np.abs(s - g.tooth_thickness(d)).max() <= 2 * tol, d


def test_form_diameter_closed_form():
    # source: standards.md §1.7 worked values: m = 2, z = 20 -> 37.6401; m = 1, z = 20 -> r 9.41003
    assert undercut_form_diameter(Gear(20, 2)) == pytest.approx(37.6401, abs=5e-5)
    assert undercut_form_diameter(Gear(20, 1)) / 2 == pytest.approx(9.41003, abs=5e-6)


def test_undercut_form_diameter_hook_in_gear():
    # source: derivation: the fillet cuts the involute above the base circle when undercut
    g = Gear(8, 1)
    assert g.undercut
    assert g.base_diameter < g.form_diameter == pytest.approx(undercut_form_diameter(g))
    # and the fillet lies on the involute there (the crossing is exact, not sampled)
    prof = ToothProfile(g)
    rho, eta, _ = prof.fillet(prof.tau_form)
    assert float(eta) == pytest.approx(float(prof.eta_involute(rho)), abs=1e-14)


def test_root_minimum_is_exact():
    # source: standards.md §3.1: min |E| = r - (h_fP - x) m = 8.75 for m = 1, z = 20. The
    # space centre lies on the root circle exactly; the one-sided sampling moves the vertex where
    # the (concave) fillet leaves the root circle inwards by at most 0.625 tolerances
    tol = 1e-4
    rho, eta, _ = ToothProfile(Gear(20, 1)).half_space(tol)
    assert eta[0] == 0.0 and rho[0] == pytest.approx(8.75, abs=1e-12)
    p = outline(Gear(20, 1), tol)
    r = np.hypot(*np.asarray(p.exterior.coords).T)
    assert 8.75 - 0.625 * tol <= r.min() <= 8.75 + 1e-12


def _deviations(g, tol):
    """Deviation of vertices and edge midpoints from the exact curves, per curve kind."""
    prof = ToothProfile(g)
    rho, eta, kind = prof.half_space(tol)
    xy = np.stack([rho * np.sin(eta), rho * np.cos(eta)], -1)
    mid = 0.5 * (xy[1:] + xy[:-1])
    mk = kind[:-1]
    rm, em = np.hypot(mid[:, 0], mid[:, 1]), np.arctan2(mid[:, 0], mid[:, 1])
    dev = np.zeros(len(mid))
    arc = (mk == 0) | (mk == 3)
    dev[arc] = np.abs(rm[arc] - np.where(mk[arc] == 0, prof.rf, prof.ra))
    inv_ = mk == 2
    # distance from the involute ~ (eta - eta_inv(r)) r cos(alpha_y) (normal to the flank)
    cos_a = prof.rb / rm[inv_]
    dev[inv_] = np.abs(em[inv_] - prof.eta_involute(rm[inv_])) * rm[inv_] * cos_a
    fil = mk == 1
    if fil.any():  # reference: the same exact fillet at 1e-3 of the tolerance
        t = prof._fillet_samples(0.0, prof.tau_form, tol * 1e-3)
        r_, e_, _ = prof.fillet(t)
        ref = shapely.LineString(np.stack([r_ * np.sin(e_), r_ * np.cos(e_)], -1))
        dev[fil] = shapely.distance(ref, shapely.points(mid[fil]))
    vert_inv = kind == 2
    v_dev = np.abs(eta[vert_inv] - prof.eta_involute(rho[vert_inv])) * rho[vert_inv]
    return dev, v_dev, len(rho)


# the one-sided sampling (gears.cutting.sampling.one_sided) moves a vertex next to a concave chord
# into
# the material by 1.25 times that chord's sag, and chords sag about half the tolerance at most;
# v_dev measures the involute vertices by angle x radius, which overstates the normal distance
# by 1/cos(alpha_y): within 0.75 tolerances (stated), inside the tolerance itself
VERTEX = 0.75


@pytest.mark.parametrize("name", ["z20", "z17_x-0.3", "z12_x0.6_m3", "helical_z20_b30"])
def test_requested_tolerance_is_achieved(name):
    # source: the definition of the tolerance (chordal deviation), measured against the exact
    # curves; the vertex count grows as tolerance^-1/2 (standards.md §3.2 sag law r_b t dt^2/8)
    g = GEARS[name]
    counts = []
    for tol in [1e-1, 1e-2, 1e-3, 1e-4]:
        dev, v_dev, n = _deviations(g, tol)
        assert dev.max() < tol
        assert dev.max() > 0.2 * tol or tol == 1e-1  # not wastefully fine
        assert v_dev.max() <= VERTEX * tol
        counts.append(n)
    ratios = np.array(counts[2:]) / np.array(counts[1:-1])
    assert np.all((ratios > 0.6 * math.sqrt(10)) & (ratios < 1.6 * math.sqrt(10))), counts


def test_ring_tolerance_down_to_the_fold():
    # source: as above; the rack-limit fillet of a ring folds back by ~1e-4 m_n before the
    # involute (gears/profile.py ToothProfile._tau_tangent), so 1e-3 mm is the floor at m = 2
    for tol in [1e-1, 1e-2, 1e-3]:
        dev, v_dev, _ = _deviations(GEARS["ring_z80"], tol)
        assert dev.max() < tol and v_dev.max() <= VERTEX * tol


def _mesh_check(pair, method, tol=1e-4):
    for angle in (0.0, 4.0, 11.0):
        p1, p2 = pair.outlines(angle, tol, method)
        assert p1.intersection(p2).area < 1e-4
        assert p1.distance(p2) < 2 * tol  # touching
        q1, _ = pair.outlines(angle + 0.5, tol, method)
        assert q1.intersection(p2).area > 1e-2  # source: 0.5 deg is far beyond the tolerance
        q1, _ = pair.outlines(angle - 0.5, tol, method)
        assert q1.intersection(p2).area > 1e-2


@pytest.mark.parametrize("method", ["analytic", "rack"])
def test_external_pair_meshes_without_overlap(method):
    # source: KHK example pair (standards.md §1.2): z 12/24, x 0.6/0.36, m 3, a_w 56.4999
    _mesh_check(GearPair(Gear(12, 3, profile_shift=0.6), Gear(24, 3, profile_shift=0.36)), method)


def test_internal_pair_meshes_without_overlap():
    # source: an internal pair clear of interference (standards.md §1.8 table: z1 = 20 needs
    # z2 >= 64 at x = 0; shifts 0.5/-0.5, the ring's -0.5 in DIN 3960's sign (KHK's 0.5), keep
    # the ring tip above the pinion's form circle)
    pair = GearPair(Gear(20, 2, profile_shift=0.5), Gear(80, 2, internal=True, profile_shift=-0.5))
    _mesh_check(pair, "analytic")


def test_interfering_internal_pair_overlaps():
    # source: standards.md §1.8/§1.6: z1 = 20, z2 = 80 at x = 0: the ring tip reaches the pinion
    # fillet (tip interference); the outlines show it as overlap at zero backlash
    pair = GearPair(Gear(20, 2), Gear(80, 2, internal=True))
    p1, p2 = pair.outlines(0.0, 1e-4)
    assert p1.intersection(p2).area > 1e-4


def test_backlash_thins_teeth():
    # source: derivation: each flank moves j/4 along its normal, so s_y shrinks by j/(2 cos a_y)
    g, j = Gear(20, 2), 0.2
    p = outline(g, 1e-5, backlash=j)
    for d in _flank_diameters(g, 3):
        cos_a = g.base_diameter / d
        assert thickness_on(p, d).mean() == pytest.approx(
            g.tooth_thickness(d) - j / (2 * cos_a), abs=2e-5
        )
    pair = GearPair(Gear(12, 3, profile_shift=0.6), Gear(24, 3, profile_shift=0.36))
    p1, p2 = pair.outlines(0.0, 1e-4, backlash=j)
    assert p1.distance(p2) > 0.2 * j  # free play on both flanks


@pytest.mark.parametrize(
    "gear",
    [
        Gear(8, 1, profile_shift=0.6),  # pointed
        Gear(8, 1),  # undercut
        Gear(5, 1),
        Gear(5, 1, profile_shift=0.5),
        Gear(400, 1),
        Gear(12, 0.1),
        Gear(12, 50, profile_shift=0.3),
        Gear(30, 1, internal=True),  # tip inside base circle: clear error
        Gear(40, 1, internal=True, profile_shift=-0.8),
        Gear(3, 1, profile_shift=-0.2),  # root just above the centre (x > -0.25)
        Gear(200, 1, internal=True),
        # a 38-tooth shaper on a 40-tooth ring trims its tips (ShaperCutter.check)
        Gear(40, 1, internal=True, profile_shift=-0.3, cutter=ShaperCutter(38)),
    ],
    ids=lambda g: (
        f"z{g.teeth}_m{g.module}_x{g.profile_shift}_{'int' if g.internal else 'ext'}"
        + ("_cutter" if g.cutter else "")
    ),
)
@pytest.mark.parametrize("method", ["analytic", "rack", "shaper"])
def test_stability_valid_or_clear_error(gear, method):
    # source: standards.md §6 items 2-4, 7: a valid polygon or a GearError, never NaN
    try:
        p = gear.outline(tolerance=1e-3, method=method)
    except GearError as exc:
        assert str(exc)
        return
    assert p.is_valid and p.area > 0
    assert np.isfinite(shapely.get_coordinates(p)).all()


def test_pointed_tooth_ends_at_pointed_diameter():
    # source: standards.md §1.4 pointed-tip formula (Gear.pointed_tip_diameter)
    g = Gear(8, 1, profile_shift=0.6)
    assert g.pointed_tip_diameter < g.tip_diameter
    r = np.hypot(*np.asarray(outline(g, 1e-5).exterior.coords).T)
    assert r.max() == pytest.approx(g.pointed_tip_diameter / 2, abs=1e-9)


def test_protuberance_is_refused_not_ignored():
    # source: the BasicRack docstring: a protuberance tool is not modelled; drawing it without
    # its protuberance would be silently wrong
    g = Gear(20, 1, rack=BasicRack(20, 1.0, 1.25, 0.3, protuberance=0.02))
    for method in ("analytic", "rack", "shaper"):
        with pytest.raises(GearError, match="protuberance"):
            g.outline(tolerance=0.01, method=method)


def test_bad_arguments():
    g = Gear(20, 1)
    with pytest.raises(GearError, match="tolerance"):
        g.outline(tolerance=0)
    with pytest.raises(GearError, match="method"):
        g.outline(method="hob")
    with pytest.raises(GearError, match="bore"):
        g.outline(bore=100)
    with pytest.raises(GearError, match="rack cutter cannot"):
        Gear(80, 1, internal=True).outline(method="rack")
    p = g.outline(bore=5)
    assert len(p.interiors) == 1
    ring = Gear(80, 1, internal=True).outline(rim=4)
    assert ring.exterior.distance(shapely.Point(0, 0)) == pytest.approx(41.25 + 4, abs=1e-3)
