"""Vectorised margins (gears.checks) against the per-object checks, and the tooth_height finding.

Reference values: the per-object ``Gear.check()`` / ``GearPair.check()`` (an independent route:
scalar code, Brent's method for the undercut form circle), standards.md §1.7 (form circle of
z = 20, m = 2: 37.6401 mm) and hand derivations stated at each test.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import Gear, GearError, GearPair
from gears.checks import (
    gear_margins,
    has_working_angle,
    pair_margins,
    tooth_height_margin,
    undercut_form_diameter,
)
from gears.cutting.profile import undercut_form_diameter as brent_form_diameter


def _brute(z1s, z2s, xs, module=2.0, helix=0.0, internal=False):
    rows = np.array(list(itertools.product(z1s, z2s, xs, xs)), float)
    if internal:
        rows = rows[rows[:, 1] > rows[:, 0]]
    rows = rows[has_working_angle(rows[:, 0], rows[:, 1], rows[:, 2], rows[:, 3], 20.0, helix,
                                  internal)]  # fmt: skip
    return rows


@pytest.mark.parametrize(
    ("z1s", "z2s", "xs", "helix", "internal"),
    [
        ([7, 10, 13, 18], [12, 25, 41], [-0.4, 0.0, 0.5, 0.9], 0.0, False),  # undercut too
        ([11, 16, 23], [15, 30], [-0.3, 0.2, 0.7], 20.0, False),  # helical
        ([12, 17, 25], [40, 61, 90], [-0.4, 0.0, 0.5], 0.0, True),  # internal
    ],
)
def test_margins_equal_the_pair_check(z1s, z2s, xs, helix, internal):
    # independent route: every finding of GearPair.check() (scalar code) for each pair
    rows = _brute(z1s, z2s, xs, helix=helix, internal=internal)
    pm = pair_margins(rows[:, 0], rows[:, 1], 2.0, rows[:, 2], rows[:, 3], 20.0, helix,
                      internal)  # fmt: skip
    found, ok = pm.findings(), pm.ok()
    checked = 0
    for i, (z1, z2, x1, x2) in enumerate(rows):
        h2 = helix if internal else -helix
        try:
            pair = GearPair(Gear(int(z1), 2, profile_shift=x1, helix_angle=helix),
                            Gear(int(z2), 2, profile_shift=x2, helix_angle=h2,
                                 internal=internal))  # fmt: skip
        except GearError:  # no real gear (the lead's refusals): the search rejects it too
            assert not ok[i]
            continue
        report = pair.check()
        assert bool(ok[i]) == report.ok, (z1, z2, x1, x2, report.failed())
        for name, f in report.items():
            assert found[name][i] == pytest.approx(f.margin, abs=1e-9), (z1, z2, x1, x2, name)
        checked += 1
    assert checked > 0.8 * len(rows)


def test_undercut_form_diameter_equals_brent():
    # independent route: gears.cutting.profile.undercut_form_diameter (Brent per gear)
    cases = [(z, x) for z in (5, 7, 9, 12, 14) for x in (-0.3, 0.0, 0.2)]
    cases = [(z, x) for z, x in cases if Gear(z, 1.5, profile_shift=x).undercut]
    z = np.array([c[0] for c in cases])
    x = np.array([c[1] for c in cases])
    d = undercut_form_diameter(z, 1.5, x)
    for zi, xi, di in zip(z, x, d, strict=True):
        try:
            ref = brent_form_diameter(Gear(int(zi), 1.5, profile_shift=float(xi)))
        except GearError:
            assert math.isnan(di)  # the fillet cuts the whole involute away in both
            continue
        assert di == pytest.approx(ref, abs=1e-9)
    # standards.md §1.7: not undercut, the closed form 37.6401 mm
    assert float(undercut_form_diameter(20, 2, 0.0)) == pytest.approx(37.6401, abs=5e-5)


def test_helical_undercut_form_diameter_equals_brent():
    # independent route as above, helical gears (the tool's round is an ellipse)
    g = Gear(8, 2, helix_angle=25, profile_shift=-0.1)
    assert g.undercut
    d = undercut_form_diameter(8, 2, -0.1, 20.0, 25.0)
    assert float(d) == pytest.approx(brent_form_diameter(g), abs=1e-9)


def test_tooth_height_fails_below_the_form_circle():
    # derivation: z = 20, m = 2, k = -1: d_a = 40 + 2*2*(1 - 1) = 40 mm, d_f = 35 mm,
    # d_Ff = 37.6401 (standards.md §1.7): the tip is 1.18 mm (radius) above the form circle;
    # k = -1.7: d_a = 37.2 mm lies 0.22 mm below it (radius), so the flank has no involute left
    ok = Gear(20, 2, tip_alteration=-1.0).check()["tooth_height"]
    assert ok.ok and ok.margin == pytest.approx((40.0 - 37.6401) / 2, abs=5e-5)
    bad = Gear(20, 2, tip_alteration=-1.7).check()["tooth_height"]
    assert not bad.ok and bad.margin == pytest.approx((37.2 - 37.6401) / 2, abs=5e-5)
    # the vectorised margin is the same number
    m = gear_margins(20, 2, 0.0, tip_alteration=np.array([-1.0, -1.7])).tooth_height
    assert m == pytest.approx([ok.margin, bad.margin], abs=1e-12)


def test_tooth_height_of_a_ring_mirrors():
    # a ring's tip lies inside its root and form circles: min(d_f, d_Ff) - d_a (radius)
    assert float(tooth_height_margin(78.0, 85.0, 83.0, internal=True)) == pytest.approx(2.5)
    assert float(tooth_height_margin(84.0, 85.0, 83.0, internal=True)) == pytest.approx(-0.5)
    # and an external gear's: d_a - max(d_f, d_Ff)
    assert float(tooth_height_margin(44.0, 35.0, 37.0)) == pytest.approx(3.5)


def test_pointed_tip_is_a_negative_land_not_an_error():
    # z = 9, x = 0.8: the flanks cross below the tip (pointed_tip_diameter < d_a): the check
    # reports a negative land instead of raising
    g = Gear(9, 2, profile_shift=0.8)
    assert g.pointed_tip_diameter < g.tip_diameter
    f = g.check()["pointed_tip"]
    assert not f.ok and f.margin < -0.2 * 2
    assert float(gear_margins(9, 2, 0.8).pointed_tip) == pytest.approx(f.margin, abs=1e-12)


@settings(max_examples=30, deadline=None)
@given(
    z1=st.integers(6, 60), z2=st.integers(6, 120), x1=st.floats(-0.8, 1.2),
    x2=st.floats(-0.8, 1.2), helix=st.sampled_from([0.0, 12.0, 30.0]),
)  # fmt: skip
def test_margins_are_finite_or_marked(z1, z2, x1, x2, helix):
    # stability: a margin is a finite number, or +inf for a finding not reported; never NaN
    if not has_working_angle(z1, z2, x1, x2, 20.0, helix):
        with pytest.raises(GearError):
            pair_margins(z1, z2, 1.0, x1, x2, 20.0, helix)
        return
    pm = pair_margins(z1, z2, 1.0, x1, x2, 20.0, helix)
    for name, v in pm.findings().items():
        assert not np.isnan(v), name


def test_scalar_and_array_inputs_broadcast_in_ok():
    # docs/design_search.md: one pinion against 60 wheels; a scalar input left some margins 0-d and
    # ok() raised (issue 16). Independent route: each pair's own ok() from scalar inputs.
    z2 = np.arange(20, 80)
    ok = pair_margins(17, z2, 2.0, 0.3, 0.0).ok()
    assert ok.shape == (60,)
    assert ok.tolist() == [bool(pair_margins(17, int(z), 2.0, 0.3, 0.0).ok()) for z in z2]
