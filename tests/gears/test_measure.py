"""Measurements on outlines (gears/measure.py) against shapes with known answers."""

import math

import numpy as np
import pytest
import shapely

from gears import Gear
from gears.cutting.measure import form_diameter_on, thickness_on, undercut_depth
from gears.cutting.profile import outline


def test_thickness_on_known_shapes():
    # source: geometry: a square of side 2 about the origin is cut by the circle r = 1.2 in four
    # arcs of angle 2 * (pi/4 - acos(1/1.2)) each; a full disc gives one arc pi d
    sq = shapely.box(-1, -1, 1, 1)
    s = thickness_on(sq, 2.4)
    assert len(s) == 4
    assert s == pytest.approx(1.2 * 2 * (math.pi / 4 - math.acos(1 / 1.2)) * np.ones(4), rel=1e-12)
    disc = shapely.Point(0, 0).buffer(5, 64)
    assert thickness_on(disc, 2) == pytest.approx([2 * math.pi])
    assert thickness_on(disc, 20).size == 0
    # off-centre measuring circle
    assert thickness_on(shapely.box(9, -1, 11, 1), 2.4, center=(10, 0)) == pytest.approx(s)


def test_undercut_depth_and_form_diameter_measured():
    # source: standards.md §1.6/§1.7: z = 8 undercuts at x = 0 (depth > 0, form above base);
    # z = 20 is not undercut and its measured form diameter is the closed-form 18.8201 (m = 1);
    # the fillet leaves the involute tangentially, so a 2-tolerance criterion finds it ~0.01 lower
    g8 = Gear(8, 1)
    assert undercut_depth(outline(g8, 1e-5), g8) > 0.01
    g20 = Gear(20, 1)
    assert form_diameter_on(outline(g20, 1e-4), g20, 1e-4) == pytest.approx(
        g20.form_diameter, abs=0.02
    )
    assert form_diameter_on(outline(g8, 1e-4), g8, 1e-4) == pytest.approx(
        g8.form_diameter, abs=0.01
    )
