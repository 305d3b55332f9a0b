"""The worm's helicoid solid and the wheel built on the envelope of its thread.

References: the exact conjugate of a ZA worm in its mid-plane is the involute of the wheel's
base circle r_2 cos(alpha_x) with the thickness s_2 = m (pi/2 + 2 x_2 tan alpha_x) (the worm's
axial section is a straight rack; DIN 3975, and the core's tooth_thickness as an independent
formula); the volumes of solids of revolution bound the wheel's (its blank, its root cylinder).
tests/gears/test_worm_wheel.py holds the wheel to the exact conjugate surface off the mid-plane.
"""

from __future__ import annotations

import math
import time

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from gears import GearError, WormPair
from gears.cutting.measure import thickness_on
from gears.geometry import tooth_thickness

trimesh = pytest.importorskip("trimesh")

from gears.solid.mesh import to_manifold  # noqa: E402
from gears.worm.solid import wheel_blank, worm_section  # noqa: E402

TOL = 0.15  # mm: coarse, so the tests stay quick


@pytest.fixture(scope="module")
def pair():
    w = WormPair(1, 10, 2.0, diameter_quotient=10, flank="ZA", profile_shift=0.3, face_width=10)
    return w, w.worm_mesh(TOL), w.wheel_mesh(TOL)


def test_worm_and_wheel_are_watertight_and_of_plausible_volume(pair):
    w, worm, wheel = pair
    for m in (worm, wheel):
        assert m.is_watertight and m.is_winding_consistent and m.volume > 0
    # the worm lies between its root and tip cylinders (volume of revolution, independent)
    rf, ra = w.worm_root_diameter / 2, w.worm_tip_diameter / 2
    assert math.pi * rf**2 * w.worm_length < worm.volume < math.pi * ra**2 * w.worm_length
    # the wheel lies within its blank and outside its root cylinder over the face width
    blank = wheel_blank(w, TOL).volume()
    root = math.pi * (w.wheel_root_diameter / 2) ** 2 * w.face_width
    assert root < wheel.volume < blank


def test_mid_plane_is_the_involute_within_the_tolerance(pair):
    # ZA: the mid-plane is a rack-and-gear mesh; the exact conjugate tooth has the involute
    # thickness at every diameter. The flanks' vertices lie on it and their chords inside the
    # convex tooth (thinner), each flank within the tolerance, so the thickness within twice
    # of it below and nothing above (1e-6 mm of rounding).
    w, _, wheel = pair
    rings = to_manifold(wheel).slice(0.0).to_polygons()
    polys = [shapely.Polygon(r) for r in rings]
    section = max(polys, key=lambda p: p.area)
    base = w.wheel_diameter * math.cos(math.radians(w.axial_pressure_angle))
    for d in np.linspace(max(w.wheel_root_diameter, base) + 0.5, w.wheel_tip_diameter - 0.5, 4):
        s = thickness_on(section, d)
        exact = float(tooth_thickness(d, 10, 2.0, 0.3, w.axial_pressure_angle))
        assert len(s) == 10
        assert np.all(s - exact > -2 * TOL) and np.all(s - exact < 1e-6), (d, s - exact)


def test_section_refuses_crossing_threads():
    # a worm section whose threads cross is refused, not drawn
    w = WormPair(2, 40, 2.0, diameter_quotient=10)
    assert worm_section(w, 0.05).is_valid
    with pytest.raises(GearError, match="tolerance"):
        w.worm_mesh(float("nan"))


def test_scene_places_worm_and_wheel(pair):
    w = pair[0]
    sc = w.scene(tolerance=TOL)
    assert sorted(sc.graph.nodes_geometry) == ["wheel", "worm"]
    worm_at, _ = w.placements(0.0)
    # the worm's axis runs along x at the centre distance
    axis = worm_at[:3, :3] @ np.array([0.0, 0.0, 1.0])
    assert np.allclose(axis, [1.0, 0.0, 0.0], atol=1e-12)
    assert worm_at[1, 3] == pytest.approx(w.center_distance, rel=1e-14)


BAD = st.sampled_from([float("nan"), float("inf"), -1.0, 0.0, "0.1", None])


@given(st.one_of(st.floats(max_value=1e-7, allow_nan=False), BAD))
@settings(max_examples=25, deadline=None, derandomize=True, database=None,
          suppress_health_check=list(HealthCheck))  # fmt: skip
def test_bad_tolerances_are_refused_before_any_work(tol):
    w = WormPair(2, 40, 2.0)
    t0 = time.perf_counter()
    for make in (w.worm_mesh, w.wheel_mesh, lambda t: w.scene(tolerance=t)):
        with pytest.raises(GearError, match="tolerance"):
            make(tol)
    assert time.perf_counter() - t0 < 5.0


def test_too_large_a_wheel_is_refused_with_the_tolerance_that_fits():
    # the budget (gears.budget): the estimate grows with the teeth and the planes
    t0 = time.perf_counter()
    with pytest.raises(GearError, match=r"mesh budget .* use tolerance >="):
        WormPair(1, 400, 2.0).wheel_mesh(1e-4)
    assert time.perf_counter() - t0 < 10.0
