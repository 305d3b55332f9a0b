"""A planetary stage in a notebook (Planetary._repr_svg_, issue 21): the stage drawn in mesh with
its planets phased, parsed back with xml.etree; a stage that cannot be drawn says why."""

from __future__ import annotations

import math
import pathlib
import xml.etree.ElementTree as ET

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from gears import GearError
from trains import Planetary, TrainError

NS = "{http://www.w3.org/2000/svg}"


def _polygons(text: str) -> list[shapely.Polygon]:
    root = ET.fromstring(text)
    _, y0, _, h = map(float, root.get("viewBox").split())
    out = []
    for el in root.iter(f"{NS}path"):
        if not el.get("d").endswith("Z"):
            continue  # a line, not an outline
        rings = []
        for part in el.get("d").split("M")[1:]:
            xy = np.array([p.split(",") for p in part.rstrip(" Z").split(" L")], float)
            rings.append(np.column_stack([xy[:, 0], 2 * y0 + h - xy[:, 1]]))
        out.append(shapely.Polygon(rings[0], rings[1:]))
    return out


def test_stage_svg_places_the_planets_at_their_phases():
    # source: Planetary.placement (planet angles 0/120/240 deg, radius a_w = 63 mm for
    # 18/45/108, m = 2: (18 + 45) m / 2); a gear's outline is symmetric about its axis, so its
    # centroid is its centre (to the drawing's two written decimals)
    stage = Planetary(18, 45, 108, n_planets=3, module=2)
    ring, sun, *planets = _polygons(stage._repr_svg_())
    assert len(planets) == 3
    place = stage.placement()
    for planet, angle in zip(planets, place.planet_angles, strict=True):
        c = planet.centroid
        assert math.hypot(c.x, c.y) == pytest.approx(place.planet_radius, abs=0.02)
        off = (math.degrees(math.atan2(c.y, c.x)) - angle + 180) % 360 - 180
        assert off == pytest.approx(0, abs=0.05)
    assert abs(sun.centroid.x) < 0.02 and abs(ring.centroid.y) < 0.02
    assert len(ring.interiors) == 1  # the ring: a rim around its toothed hole
    # in mesh: no gear overlaps another (beyond the display tolerance's chords)
    for p in planets:
        assert p.intersection(ring).area < 0.01 * p.area
        assert p.intersection(sun).area < 0.01 * sun.area


_settings = settings(max_examples=15, deadline=None,
                     suppress_health_check=[HealthCheck.too_slow])  # fmt: skip


@_settings
@given(
    sun=st.integers(6, 60), planet=st.integers(6, 60), ring=st.integers(20, 200),
    n=st.integers(1, 6), m=st.floats(0.3, 8),
)  # fmt: skip
def test_stage_display_never_raises(sun, planet, ring, n, m):
    try:
        stage = Planetary(sun, planet, ring, n_planets=n, module=m)
    except (GearError, TrainError):
        return
    root = ET.fromstring(stage._repr_svg_())
    text = " ".join(t.text or "" for t in root.iter(f"{NS}tspan"))
    if text:
        assert text.startswith("this stage is not drawn: ") and "bug" not in text
    else:
        assert len(list(root.iter(f"{NS}path"))) == 2 + n


def test_notebook_figures_script_writes_the_reprs(tmp_path):
    # docs/make_notebook_figures.py writes the pictures of docs/notebooks.md: each is the
    # object's own _repr_svg_, a drawing (no message in place of one)
    import runpy

    script = pathlib.Path(__file__).resolve().parents[2] / "docs" / "make_notebook_figures.py"
    written = runpy.run_path(str(script))["main"](tmp_path)
    assert sorted(p.name for p in written) == [
        "notebook_bevel.svg", "notebook_differential.svg", "notebook_gear.svg",
        "notebook_pair.svg", "notebook_ring_pair.svg", "notebook_stage.svg",
    ]  # fmt: skip
    for path in written:
        root = ET.fromstring(path.read_text())
        assert not list(root.iter(f"{NS}tspan")) and list(root.iter(f"{NS}path"))


@pytest.mark.parametrize("n_pinions", [2, 3])
def test_differential_svg_shows_the_section_through_the_axle(n_pinions):
    # the side gears on the axle (+-x), the pinions in the section plane at +-y (the second only
    # when it lies opposite the first): each outer tip at (X, d_ae/2) of its blank (two decimals)
    from trains import Differential

    diff = Differential(16, 10, module=3, n_pinions=n_pinions, gleason=True)
    root = ET.fromstring(diff._repr_svg_())
    polygons = _polygons(diff._repr_svg_())
    gears = 4 if n_pinions == 2 else 3
    assert len(list(root.iter(f"{NS}path"))) == 6 * gears  # body, 2 zones, 2 pitch lines, axis
    corners = np.concatenate([np.asarray(p.exterior.coords) for p in polygons])
    side, pinion = diff.pair.g2, diff.pair.g1
    x, r = side.crown_to_apex, side.tip_diameter / 2
    tips = [(x, r), (-x, r), (pinion.tip_diameter / 2, pinion.crown_to_apex)]
    if n_pinions == 2:
        tips.append((pinion.tip_diameter / 2, -pinion.crown_to_apex))
    for tip in tips:
        assert np.min(np.hypot(*(corners - np.array(tip)).T)) < 0.02, tip
