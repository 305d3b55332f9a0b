"""Simulated rack cutting (gears/generate.py) against the formulas and the analytic outline."""

import itertools
import math

import numpy as np
import pytest
import shapely

from gears import Gear
from gears.cutting.generate import rack_outline, rack_positions
from gears.cutting.measure import thickness_on, undercut_depth
from gears.cutting.profile import ToothProfile, outline


@pytest.mark.parametrize(
    "gear",
    [Gear(20, 1), Gear(12, 3, profile_shift=0.6), Gear(25, 2, profile_shift=-0.4),
     Gear(20, 1, helix_angle=30, profile_shift=0.2)],
    ids=["z20", "z12_x0.6", "z25_x-0.4", "helical"],
)  # fmt: skip
@pytest.mark.parametrize("tol", [1e-2, 1e-3])
def test_rack_thickness_and_agreement(gear, tol, line_hausdorff):
    # source: standards.md §1.4 thickness formula; analytic outline (independent route: closed-
    # form envelope) within 2x the tolerance (issue 5), no undercut in these gears
    assert not gear.undercut
    sim = rack_outline(gear, tol)
    lo, hi = gear.form_diameter, min(gear.tip_diameter, gear.pointed_tip_diameter)
    for d in np.linspace(lo, hi, 7)[1:-1]:
        s = thickness_on(sim, d)
        assert len(s) == gear.teeth
        assert np.abs(s - gear.tooth_thickness(d)).max() <= 2 * tol
    exact = outline(gear, tol / 20)
    # shapely's Hausdorff distance, through an index (tests/conftest.py: 5 s -> 0.2 s at 1 um)
    assert line_hausdorff(sim.exterior, exact.exterior) <= 2 * tol


def test_undercut_is_reproduced(line_hausdorff):
    # source: standards.md §1.6 (z = 8 < 17.1 undercuts at x = 0) and §3.1 (the fillet envelope
    # crosses the involute): the simulated tooth is thinner than the involute formula at the
    # base circle, and the analytic undercut outline agrees with the simulation
    g = Gear(8, 1)
    tol = 1e-3
    sim = rack_outline(g, tol)
    depth = undercut_depth(sim, g)
    assert depth > 0.01  # measurably thinner: ~17 um per flank at m = 1
    assert depth == pytest.approx(undercut_depth(outline(g, 1e-5), g), abs=tol)
    assert line_hausdorff(sim.exterior, outline(g, tol / 20).exterior) <= 2 * tol
    # no undercut at x = 0.6 (x_min = 0.532): depth is zero to the tolerance
    g6 = Gear(8, 1, profile_shift=0.6)
    assert abs(undercut_depth(rack_outline(g6, tol), g6)) < tol


def test_positions_follow_the_error_law():
    # source: standards.md §3.2: flank scallop rho dphi^2/8 -> N ~ tolerance^-1/2; phi = 0 is
    # included (exact root centre); the tip land overlaps (dphi <= 2 u_c / r near phi = 0)
    prof = ToothProfile(Gear(20, 1))
    n = [len(rack_positions(prof, t)) for t in (1e-2, 1e-3, 1e-4)]
    for a, b in itertools.pairwise(n):
        assert 0.6 * math.sqrt(10) < b / a < 1.6 * math.sqrt(10)
    phis = rack_positions(prof, 1e-3)
    assert 0.0 in phis and np.allclose(phis, -phis[::-1])
    central = np.diff(phis[np.abs(phis) <= prof.tool.u_c / prof.tool.r * 2])
    assert central.max() <= 2 * prof.tool.u_c / prof.tool.r


def test_no_root_bump():
    # source: standards.md §3.2 root-bump pitfall: the root circle r - (h_fP - x) m is cut
    # exactly at the space centre (phi = 0 included) and nowhere left above it by > tol
    g, tol = Gear(20, 1), 1e-3
    sim = rack_outline(g, tol)
    assert sim.exterior.distance(shapely.Point(0, 0)) == pytest.approx(
        g.root_diameter / 2, abs=1e-9
    )
    spaces = thickness_on(sim, g.root_diameter + 2 * tol)
    assert len(spaces) == g.teeth  # the root is open all round just above d_f
