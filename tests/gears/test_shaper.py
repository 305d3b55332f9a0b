"""Shaper-cutter (Fellows) generation: gears/cutter.py (exact envelope) and gears/generate.py
(simulation) against the formulas, against each other and against the rack limit."""

import itertools
import math

import numpy as np
import pytest
import shapely
from scipy.optimize import brentq

from gears import BasicRack, Gear, GearError, GearPair
from gears.cutting.cutter import ShaperCutter
from gears.cutting.generate import rack_outline, shaper_outline, shaper_positions
from gears.cutting.measure import thickness_on, undercut_depth
from gears.cutting.outline import gear_outline
from gears.cutting.profile import ShaperProfile, outline


def _inv(a):
    return math.tan(a) - a


def _ring(p):
    return p.interiors[0] if len(p.interiors) else p.exterior


def _hausdorff(p, q, z):
    """Hausdorff distance of two outlines' toothed boundaries over three pitches around +x
    (every tooth is the same pattern; thickness_on checks all of them). Hausdorff is O(n m), so
    whole rings of fine outlines would cost seconds."""
    a = np.linspace(-3 * math.pi / z, 3 * math.pi / z, 64)
    big = 1e6
    wedge = shapely.Polygon(np.concatenate([[[0, 0]], big * np.stack([np.cos(a), np.sin(a)], -1)]))
    return _ring(p).intersection(wedge).hausdorff_distance(_ring(q).intersection(wedge))


def _cutting_center_distance(z, z0, x, x0, m, alpha=20.0, internal=False):
    """Independent: standards.md §1.2 with the cutter as the mating gear (own inverse
    involute by Brent's method); a ring as DIN 3960 writes it, with z < 0 and its own x."""
    a = math.radians(alpha)
    if internal:
        y = 2 * math.tan(a) * (x + x0) / (z0 - z) + _inv(a)
        zz = z - z0
    else:
        y = 2 * math.tan(a) * (x + x0) / (z + z0) + _inv(a)
        zz = z + z0
    aw = brentq(lambda t: _inv(t) - y, 1e-6, 1.5, xtol=1e-15)
    return m * zz / 2 * math.cos(a) / math.cos(aw), aw


@pytest.mark.parametrize(
    "z, x, z0, x0, internal",
    [(20, 0.0, 25, 0.0, False), (20, 0.5, 20, 0.0, False), (12, 0.6, 30, 0.2, False),
     (80, 0.0, 38, 0.0, True), (60, -0.5, 25, 0.1, True), (40, 0.2, 19, 0.0, True)],
)  # fmt: skip
def test_cutting_center_distance_and_root(z, x, z0, x0, internal):
    # source: standards.md §1.2 (working centre distance of the cutter-work mesh at zero
    # backlash) and the root it leaves, d_f = 2 (a0 -+ r_a0) with r_a0 = r0 + (1.25 + x0) m
    m = 2.0
    g = Gear(z, m, profile_shift=x, internal=internal)
    c = ShaperCutter(z0, shift=x0)
    a0, _ = _cutting_center_distance(z, z0, x, x0, m, internal=internal)
    assert c.center_distance(g) == pytest.approx(a0, abs=1e-9)
    ra0 = m * z0 / 2 + (1.25 + x0) * m
    df = 2 * (a0 + ra0) if internal else 2 * (a0 - ra0)
    assert c.root_diameter(g) == pytest.approx(df, abs=1e-9)
    if x == x0 == 0:  # the shaper then leaves the rack's root circle (standards.md §1.3)
        assert c.root_diameter(g) == pytest.approx(g.root_diameter, abs=1e-9)


def test_form_diameter_on_the_line_of_action():
    # source: independent derivation: the cutter's involute ends where its tip round (radius
    # rho, tangent to the tip circle) meets it, at roll t_f with r_b0 t_f = rho +
    # sqrt((r_a0 - rho)^2 - r_b0^2); the conjugate work point lies on the line of action
    # rho_w = a0 sin(alpha_w0) -+ r_b0 t_f, r_Ff = sqrt(r_b^2 + rho_w^2)
    m = 1.0
    for g, z0 in [(Gear(20, m), 30), (Gear(80, m, internal=True, profile_shift=-0.4), 40)]:
        a0, aw = _cutting_center_distance(g.teeth, z0, g.profile_shift, 0.0, m, internal=g.internal)
        rb0, ra0, rho = z0 * m / 2 * math.cos(math.radians(20)), z0 * m / 2 + 1.25 * m, 0.38 * m
        end = rho + math.sqrt((ra0 - rho) ** 2 - rb0**2)
        rho_w = a0 * math.sin(aw) + (end if g.internal else -end)
        d_ff = 2 * math.hypot(g.base_diameter / 2, rho_w)
        c = ShaperCutter(z0)
        assert ShaperProfile(g, c).tool.rho == rho  # the ISO 53 A round fits this cutter
        assert c.form_diameter(g) == pytest.approx(d_ff, abs=1e-9)
        assert 2 * ShaperProfile(g, c).form_radius == pytest.approx(d_ff, abs=1e-9)
    # rack limit: standards.md §1.7 example d_Ff = 37.6401 (m = 2, z = 20, ISO 53 A)
    assert ShaperCutter(10**6).form_diameter(Gear(20, 2)) == pytest.approx(37.6401, abs=1e-4)


def test_rack_limit_falls_as_one_over_z0():
    # source: derivation: a cutter of z0 teeth tends to the rack cutter as z0 -> inf (Ozols
    # §21-6; Joldasbekov §2.8); its fillet differs from the rack's by O(1/z0)
    g = Gear(20, 1, profile_shift=0.3)
    rack = outline(g, 1e-5)
    d = [_hausdorff(outline(g, 1e-5, cutter=ShaperCutter(z0)), rack, g.teeth)
         for z0 in (250, 500, 1000)]  # fmt: skip
    for a, b in itertools.pairwise(d):
        assert 1.8 < a / b < 2.2
    assert d[-1] < 2e-3


CASES = {
    "z20": Gear(20, 1),
    "z12_x0.6_m3": Gear(12, 3, profile_shift=0.6),
    "z25_x-0.4_m2": Gear(25, 2, profile_shift=-0.4),
    "helical_z20_b20": Gear(20, 1, helix_angle=20, profile_shift=0.2),
    "ring_z80_m2": Gear(80, 2, internal=True),
    "ring_z60_x-0.5": Gear(60, 1, internal=True, profile_shift=-0.5),
    "ring_z40_x-0.3_c20": Gear(40, 1, internal=True, profile_shift=-0.3, cutter=ShaperCutter(20)),
}


@pytest.mark.parametrize("name", list(CASES))
@pytest.mark.parametrize("tol", [1e-2, 1e-3])
def test_shaper_thickness_and_agreement(name, tol):
    # source: standards.md §1.4 thickness formula (a shaper at zero backlash on the cutting
    # centre distance generates the work's own involute: Joldasbekov §2.8), and the exact
    # envelope of gears/cutter.py as the independent route: Hausdorff <= 2 tolerance (issue 5)
    g = CASES[name]
    prof = ShaperProfile(g)
    assert not prof.undercut
    sim = shaper_outline(g, tol)
    tip = g.tip_diameter if g.internal else min(g.tip_diameter, g.pointed_tip_diameter)
    lo, hi = sorted([2 * prof.form_radius, tip])
    for d in np.linspace(lo, hi, 7)[1:-1]:
        s = thickness_on(sim, d)
        assert len(s) == g.teeth
        assert np.abs(s - g.tooth_thickness(d)).max() <= 2 * tol
    exact = outline(g, tol / 20, cutter=prof.cutter)
    assert _hausdorff(sim, exact, g.teeth) <= 2 * tol
    # the shaper's own root circle, exact at the centred position (phi = 0 is included)
    r = np.hypot(*shapely.get_coordinates(_ring(sim)).T)
    root = r.max() if g.internal else r.min()
    assert root == pytest.approx(prof.cutter.root_diameter(g) / 2, abs=1e-9)


def test_shaper_undercut_is_reproduced():
    # source: standards.md §1.6 (z = 8 undercuts at x = 0) and the lectures digest §2.9: "for a
    # shaper cutter the undercut limit depends on z0": the 76-tooth cutter's involute ends past
    # N1 (ShaperCutter.check), the simulated tooth is thinner at the base circle, and the exact
    # envelope with its undercut crossing agrees with the simulation
    g, c, tol = Gear(8, 1), ShaperCutter(76), 1e-3
    assert not c.check(g).ok and g.with_(cutter=c).undercut
    sim = shaper_outline(g, tol, cutter=c)
    depth = undercut_depth(sim, g)
    assert depth > 0.005
    assert depth == pytest.approx(undercut_depth(outline(g, 1e-5, cutter=c), g), abs=tol)
    assert sim.exterior.hausdorff_distance(outline(g, tol / 20, cutter=c).exterior) <= 2 * tol
    # a 76-tooth cutter undercuts z = 8 less than the rack (its tip path is curved away)
    assert depth < undercut_depth(rack_outline(g, tol), g)


def test_positions_follow_the_error_law():
    # source: standards.md §3.2 (flank scallop ~ dphi^2 -> N ~ tolerance^-1/2), phi = 0 included
    # (exact root centre), symmetric, the tip land overlaps near phi = 0
    prof = ShaperProfile(Gear(20, 1), ShaperCutter(30))
    n = [len(shaper_positions(prof, t)) for t in (1e-2, 1e-3, 1e-4)]
    assert 0.6 * math.sqrt(10) < n[2] / n[1] < 1.6 * math.sqrt(10)
    phis = shaper_positions(prof, 1e-3)
    assert 0.0 in phis and np.allclose(phis, -phis[::-1])
    land = prof.tool.land_half_angle * prof.tool.ratio
    central = np.diff(phis[np.abs(phis) <= 2 * land])
    assert central.max() <= 2 * land


def test_ring_tip_past_the_cutters_n1_is_reported():
    # source: KHK involute-interference condition (standards.md §1.8) with the cutter as the
    # pinion: a standard ring z = 40 (x = 0) passes the default 20-tooth cutter's N1, x = 0.3
    # keeps its tip before it
    c = ShaperCutter(20)
    assert c.check(Gear(40, 1, internal=True)).failed() == ["tip_past_n1"]
    assert c.check(Gear(40, 1, internal=True, profile_shift=-0.3)).ok


def test_trimming_of_ring_tips():
    # source: KHK trochoid-interference condition (standards.md §1.8) with the cutter as the
    # pinion: a 37-tooth cutter on a 40-tooth ring fails it, a 20-tooth cutter passes; the
    # simulation, which follows the cutter tooth until it leaves the blank, cuts the ring's tips
    # off in the first case only
    ring = Gear(40, 1, internal=True, profile_shift=-0.3)
    d = ring.tip_diameter + 0.05
    for z0, trimmed in [(20, False), (37, True)]:
        c = ShaperCutter(z0)
        assert c.check(ring)["trimming"].ok is not trimmed
        loss = ring.tooth_thickness(d) - thickness_on(shaper_outline(ring, 1e-3, cutter=c), d)
        assert (loss.min() > 0.05) if trimmed else (np.abs(loss).max() < 2e-3)
        # the exact envelope models generation only: no trimming there
        exact = thickness_on(outline(ring, 1e-4, cutter=c), d)
        assert np.abs(ring.tooth_thickness(d) - exact).max() < 2e-4


def test_gear_with_cutter_drives_checks():
    # source: pair check against the form circle (DIN 3960 d_Nf >= d_Ff): the shaper-cut
    # pinion's form circle lies higher (the cutter's tip path is curved), so a ring tip that
    # clears the rack-cut pinion reaches the shaper-cut one's fillet - and the outlines overlap
    c = ShaperCutter(38)
    rack_pair = GearPair(
        Gear(20, 2, profile_shift=0.3), Gear(80, 2, internal=True, profile_shift=-0.6)
    )
    assert rack_pair.check().ok
    g1 = Gear(20, 2, profile_shift=0.3, cutter=c)
    g2 = Gear(80, 2, internal=True, profile_shift=-0.6, cutter=c)
    assert g1.form_diameter == pytest.approx(c.form_diameter(g1))
    assert g1.form_diameter > rack_pair.mounted[0].form_diameter + 0.1
    assert g1.root_diameter == pytest.approx(c.root_diameter(g1))
    pair = GearPair(g1, g2)
    assert pair.check().failed() == ["tip_interference"]
    p1, p2 = pair.outlines(0.0, 1e-4)  # analytic: each gear's own shaper envelope
    assert p1.intersection(p2).area > 3e-4
    # relieve the ring tip to the limit the finding names (+0.2 mm): check and outlines agree
    limit = pair.tip_diameter_limits[1]
    g2r = g2.with_(tip_alteration=(g2.tip_diameter - (limit + 0.2)) / (2 * g2.module))
    pair = GearPair(g1, g2r)
    assert pair.check().ok
    _mesh_check(pair, "shaper")


def _mesh_check(pair, method, tol=1e-4):
    # source: issue 5: no overlap (< 1e-4 mm^2), touching flanks at zero backlash; 0.5 deg more
    # turn of gear 1 either way overlaps (far beyond the tolerance). Overlaps can only occur near
    # the pitch point, so both outlines are clipped to a box there first (fast intersections).
    g1 = pair.mounted[0]
    m, rw1 = g1.module, pair.working_diameters[0] / 2
    zone = shapely.box(rw1 - 4 * m, -4 * m, rw1 + 4 * m, 4 * m)
    for angle in (0.0, 4.0, 11.0):
        p1, p2 = pair.outlines(angle, tol, method)
        p2 = p2.intersection(zone)
        assert p1.intersection(zone).intersection(p2).area < 1e-4
        assert p1.distance(p2) < 2 * tol
        for turn in (0.5, -0.5):
            q1 = gear_outline(g1, tol, method, angle=angle + turn).intersection(zone)
            assert q1.intersection(p2).area > 1e-2


def test_external_shaper_pair_meshes():
    # source: KHK example pair (standards.md §1.2): z 12/24, x 0.6/0.36, m 3
    _mesh_check(GearPair(Gear(12, 3, profile_shift=0.6), Gear(24, 3, profile_shift=0.36)), "shaper")


def test_default_cutter_rule():
    # source: the documented default (a 76 mm Fellows disc cutter, 12..100 teeth, rings <= z/2)
    assert ShaperCutter.default_for(Gear(20, 1)).teeth == 76
    assert ShaperCutter.default_for(Gear(20, 3)).teeth == 25
    assert ShaperCutter.default_for(Gear(20, 0.1)).teeth == 100
    assert ShaperCutter.default_for(Gear(20, 20)).teeth == 12
    assert ShaperCutter.default_for(Gear(50, 1, internal=True)).teeth == 25
    with pytest.raises(GearError, match="no default shaper"):
        ShaperCutter.default_for(Gear(9, 1, internal=True, profile_shift=3.0))


def test_small_cutter_gets_a_fitting_tip_round():
    # source: derivation: a 12-tooth cutter with h_a0 = 1.25 m has too narrow a tip for the
    # rack's 0.38 m round; the default round is reduced so a tip land remains, an explicit one
    # that does not fit is refused
    prof = ShaperProfile(Gear(30, 1), ShaperCutter(12))
    assert 0 < prof.tool.rho < 0.38 and prof.tool.land_half_angle > 0
    with pytest.raises(GearError, match="pointed"):
        ShaperProfile(Gear(30, 1), ShaperCutter(12, tip_radius=0.38))


def test_sharp_cornered_tools_converge():
    # source: standards.md §3.2: a sharp tool corner leaves notches that fall as 1/N (not
    # 1/N^2); the spacing rule accounts for it, so rack and shaper simulations of a sharp tool
    # still meet their exact envelopes (the trochoid of the corner) within 2 tolerances
    g, tol = Gear(12, 1, rack=BasicRack(20, 1.0, 1.25, 0.0)), 1e-2
    assert rack_outline(g, tol).exterior.hausdorff_distance(outline(g, tol / 20).exterior) <= (
        2 * tol
    )
    c = ShaperCutter(30, tip_radius=0.0)
    sim = shaper_outline(g, tol, cutter=c)
    assert sim.exterior.hausdorff_distance(outline(g, tol / 20, cutter=c).exterior) <= 2 * tol


def test_bad_cutters():
    g = Gear(40, 1, internal=True)
    for bad, match in [(4, "teeth"), (True, "teeth"), (12.5, "teeth")]:
        with pytest.raises(GearError, match=match):
            ShaperCutter(bad)
    with pytest.raises(GearError, match="shift"):
        ShaperCutter(20, shift=float("nan"))
    with pytest.raises(GearError, match="addendum"):
        ShaperCutter(20, addendum=0)
    with pytest.raises(GearError, match="tip_radius"):
        ShaperCutter(20, tip_radius=-0.1)
    with pytest.raises(GearError, match="z0 < z"):
        ShaperCutter(40).center_distance(g)
    with pytest.raises(GearError, match="ShaperCutter"):
        Gear(20, 1, cutter=20)
    with pytest.raises(GearError, match="rack"):
        Gear(20, 1).outline(method="rack", cutter=ShaperCutter(20))
    with pytest.raises(GearError, match="rack"):
        Gear(20, 1, cutter=ShaperCutter(20)).outline(method="rack")
