"""Tests of gears.shift (blocking contour, Ozols §21-7 Fig. 21-13).

Reference values come from independent scalar routes: Gear.min_profile_shift (standards.md §1.6),
a brentq root-find on Gear.tip_thickness of the mounted gears (standards.md §1.4) and
GearPair.contact_ratio / GearPair.check (standards.md §1.5), each evaluated one pair at a time.
"""

from __future__ import annotations

import importlib.util
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from gears import Gear, GearError, GearPair
from gears.shift import LIMITS, blocking_contour, plot_blocking_contour

ROOT = Path(__file__).resolve().parents[2]


def _pair(x1, x2, z1=12, z2=28):
    return GearPair(Gear(z1, 1.0, profile_shift=x1), Gear(z2, 1.0, profile_shift=x2))


def _mounted_tip_thickness(x1, x2, which):
    return _pair(x1, x2).mounted[which].tip_thickness


@pytest.fixture(scope="module")
def bc():
    return blocking_contour(12, 28, x1=np.linspace(-0.3, 1.5, 73), x2=np.linspace(-0.3, 1.5, 61))


def test_shapes_names_and_read_only(bc):
    assert tuple(bc.margins) == LIMITS
    for f in (*bc.margins.values(), bc.feasible, bc.contact_ratio, bc.center_distance):
        assert f.shape == (61, 73)
        assert not f.flags.writeable
    with pytest.raises(TypeError):
        bc.margins["new"] = bc.feasible  # MappingProxyType
    assert bc.feasible.any() and not bc.feasible.all()


def test_undercut_zero_lines_are_x_min(bc):
    # x_min from the scalar Gear formula (standards.md §1.6: z = 12 -> 0.2981)
    xmin1 = Gear(12, 1.0).min_profile_shift
    xmin2 = Gear(28, 1.0).min_profile_shift
    assert xmin1 == pytest.approx(0.2981, abs=1e-4)
    shape = bc.feasible.shape
    expect1 = np.broadcast_to(bc.x1[None, :] - xmin1, shape)
    expect2 = np.broadcast_to(bc.x2[:, None] - xmin2, shape)
    np.testing.assert_allclose(bc.margins["undercut_1"], expect1, atol=1e-14)
    np.testing.assert_allclose(bc.margins["undercut_2"], expect2, atol=1e-14)
    # evaluated exactly on the scalar limit the field is zero
    on = blocking_contour(12, 28, x1=[xmin1], x2=[xmin2])
    assert abs(on.margins["undercut_1"][0, 0]) < 1e-14
    assert abs(on.margins["undercut_2"][0, 0]) < 1e-14


@pytest.mark.parametrize("x2", [0.0, 0.2, 0.5])
def test_pointed_tip_zero_line_matches_scalar_root(x2):
    # independent route: root of the mounted gear 1's tip thickness (GearPair applies the tip
    # shortening, Gear.tip_thickness the standards.md §1.4 formula), one pair at a time
    x1_star = brentq(lambda x1: _mounted_tip_thickness(x1, x2, 0), 0.5, 2.0, xtol=1e-13)
    on = blocking_contour(12, 28, x1=[x1_star - 1e-3, x1_star, x1_star + 1e-3], x2=[x2])
    f = on.margins["pointed_tip_1"][0]
    assert abs(f[1]) < 1e-10
    assert f[0] > 0 > f[2]  # thicker below the limit, pointed above it


def test_tip_land_zero_line_matches_scalar_root():
    # tip land 0.2 m (DIN 3960 rule of thumb, standards.md §1.4) for gear 1 at x2 = 0.2
    x1_star = brentq(lambda x1: _mounted_tip_thickness(x1, 0.2, 0) - 0.2, 0.3, 1.5, xtol=1e-13)
    on = blocking_contour(12, 28, x1=[x1_star], x2=[0.2])
    assert abs(on.margins["tip_land_1"][0, 0]) < 1e-10


@pytest.mark.parametrize("x2", [0.0, 0.3])
def test_contact_ratio_one_line_matches_gearpair(x2):
    # epsilon_alpha = 1 from GearPair.contact_ratio (standards.md §1.5) by a scalar root-find
    x1_star = brentq(lambda x1: _pair(x1, x2).contact_ratio - 1.0, 0.5, 1.6, xtol=1e-13)
    on = blocking_contour(12, 28, x1=[x1_star], x2=[x2])
    assert abs(on.margins["contact_ratio"][0, 0]) < 1e-10
    assert on.contact_ratio[0, 0] == pytest.approx(1.0, abs=1e-10)


def test_fields_agree_with_gearpair_check_pointwise(bc):
    # every field against GearPair.check() margins (scalar route), converted to modules
    rng = np.random.default_rng(3)
    for i, j in zip(rng.integers(0, 61, 12), rng.integers(0, 73, 12), strict=True):
        x1, x2 = bc.x1[j], bc.x2[i]
        pair = _pair(x1, x2)
        r = pair.check(min_contact_ratio=1.0, min_tip_land=0.2)
        expect = {
            "undercut_1": r["g1.undercut"].margin,
            "undercut_2": r["g2.undercut"].margin,
            "tip_land_1": r["g1.pointed_tip"].margin,
            "tip_land_2": r["g2.pointed_tip"].margin,
            "contact_ratio": r["contact_ratio"].margin,
            "tip_interference_1": r["tip_interference"].margin,
            "tip_interference_2": r["tip_interference_2"].margin,
        }
        if r["g1.undercut"].margin < 0 or r["g2.undercut"].margin < 0:
            # undercut: Gear.form_diameter finds the trochoid crossing (gears.cutting.profile); the
            # vectorised field uses the base circle there (documented in gears.shift)
            del expect["tip_interference_1"], expect["tip_interference_2"]
        for name, value in expect.items():
            assert bc.margins[name][i, j] == pytest.approx(value, abs=1e-11), (name, x1, x2)
        assert bc.center_distance[i, j] == pytest.approx(pair.center_distance, abs=1e-11)
        assert bc.feasible[i, j] == all(bc.margins[n][i, j] >= 0 for n in LIMITS)


def test_origin_of_12_28_is_undercut_and_a_shifted_pair_is_feasible():
    # Ozols §21-7: z = 12 < z_min = 17 undercuts at x = 0 (x_min = 0.298, standards.md §1.6), and
    # its flank is then reached by the mate's tip (Ozols lines 3-4). Joldasbekov §5.4 row 3,
    # x1 = 0.3, x2 = 0.2 (epsilon = 1.36264), is a usable design.
    bc = blocking_contour(12, 28, x1=[0.0, 0.3], x2=[0.0, 0.2])
    assert bc.failing(0.0, 0.0) == ["undercut_1", "tip_interference_1"]
    assert bc.feasible[1, 1]
    assert bc.contact_ratio[1, 1] == pytest.approx(1.36264, abs=5e-6)


def test_origin_of_a_pair_above_z_min_is_feasible():
    # z1 = 20, z2 = 40 zero-shift: no undercut (z > 17.1, standards.md §1.6), eps ~ 1.64
    bc = blocking_contour(20, 40, x1=[0.0], x2=[0.0])
    assert bc.feasible[0, 0]


def test_center_distance_constant_on_x1_plus_x2_lines():
    # a_w depends on x1 + x2 only (standards.md §1.2)
    x = np.linspace(-0.2, 0.8, 11)
    bc = blocking_contour(12, 28, x1=x, x2=x[::-1])
    a = np.diag(bc.center_distance)  # all points have x1 + x2 = 0.6
    np.testing.assert_allclose(a, a[0], rtol=1e-13)
    assert a[0] == pytest.approx(_pair(0.3, 0.3).center_distance, abs=1e-12)


def test_grid_beyond_existing_working_pressure_angle_raises():
    # x1 + x2 = -2 for 12/28 gives inv(alpha_wt) < 0: no pair exists (standards.md §1.2)
    with pytest.raises(GearError, match="x1 \\+ x2"):
        blocking_contour(12, 28, x1=[-1.0], x2=[-1.0])
    with pytest.raises(GearError, match="z1"):
        blocking_contour(0, 28)


def test_default_grid_stays_valid_for_small_tooth_sums():
    bc = blocking_contour(6, 6, n=11)
    assert all(np.isfinite(f).all() for f in bc.margins.values())


@pytest.mark.skipif(importlib.util.find_spec("matplotlib") is None, reason="needs matplotlib")
def test_plot_draws_every_crossing_limit(bc):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ax = plot_blocking_contour(bc)
    labels = {t.get_text() for t in ax.texts}
    assert "$x_{1,min}$ (undercut 1)" in labels
    assert r"$\varepsilon_\alpha = $ min" in labels
    assert any(t.startswith("a=") for t in labels)  # centre-distance iso-lines
    plt.close(ax.figure)


def test_plot_without_matplotlib_names_the_extra(bc, monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    monkeypatch.setitem(sys.modules, "matplotlib.pyplot", None)
    with pytest.raises(ImportError, match="plot"):
        plot_blocking_contour(bc)


@pytest.mark.skipif(importlib.util.find_spec("matplotlib") is None, reason="needs matplotlib")
def test_figure_script_runs(tmp_path):
    out = subprocess.run(
        [sys.executable, str(ROOT / "docs" / "make_geometry_figures.py"), str(tmp_path)],
        capture_output=True, text=True, cwd=ROOT, check=True,
    )  # fmt: skip
    png = tmp_path / "blocking_contour_12_28.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert str(png) in out.stdout
    assert (ROOT / "docs" / "images" / "blocking_contour_12_28.png").exists()
