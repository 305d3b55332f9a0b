"""search.pairs(spectrum=...): a design found for a load spectrum (ISO 6336-6, issue 30).

Sources: each row re-rated alone by ``GearPair.rating(spectrum=...)`` (the one-mesh route,
which shares no code with the search's array path but the formulas); a one-bin spectrum is the
single load for its hours, so its search equals the search at that torque, speed and life.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import search
from gears.errors import GearError
from gears.rating.sizing import load_case, rate

BINS = [(40.0, 1500.0, 2000.0), (80.0, 1500.0, 200.0), (120.0, 1000.0, 20.0)]
GRID = dict(ratio=3, module=2, teeth=(14, 80), shifts=(0.0, 0.6, 0.2), face_width=(10, 40, 5))
MIN = {"pitting": 1.1, "bending": 1.5}


def test_rows_rated_alone_meet_the_spectrum():
    r = search.pairs(spectrum=BINS, min_safety=MIN, top=4, **GRID)
    assert len(r) == 4
    for i in range(len(r)):
        row = r.table[i]
        spec = r.rating(i)  # GearPair.rating(spectrum=...) of the row's pair and face width
        assert min(spec.safety_pitting) >= 1.1 and min(spec.safety_bending) >= 1.5
        assert float(row["S_H"]) == pytest.approx(min(spec.safety_pitting), rel=1e-9)
        assert float(row["S_F"]) == pytest.approx(min(spec.safety_bending), rel=1e-9)


def test_one_bin_is_the_search_at_that_load():
    # a one-bin spectrum is its load for its hours (ISO 6336-6): the same rows and safeties
    one = search.pairs(spectrum=[(80.0, 1500.0, 3000.0)], min_safety=MIN, top=5, **GRID)
    load = search.pairs(torque=80.0, speed=1500.0, life=3000.0, min_safety=MIN, top=5, **GRID)
    assert len(one) == len(load) == 5
    for column in ("z1", "z2", "x1", "x2", "face_width"):
        assert np.array_equal(one[column], load[column])
    np.testing.assert_allclose(one["S_H"], load["S_H"], rtol=1e-9)
    np.testing.assert_allclose(one["S_F"], load["S_F"], rtol=1e-9)


def test_rate_under_a_spectrum_masks_pairs_without_rating():
    load = load_case(None, None, spectrum=BINS)
    assert load.torque == pytest.approx(120.0, rel=1e-15) and load.life == pytest.approx(2220.0)
    r = rate(load, np.array([20, 8]), 50, 2.0, 20.0, x1=np.array([0.0, -0.5]))
    assert r.valid.tolist() == [True, False]
    assert r.S_H1[1] == pytest.approx(0.0, abs=1e-300) and r.S_H1[0] > 0.0  # masked: zero


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(spectrum=BINS, torque=10.0, speed=100.0), "not both"),
        (dict(spectrum=BINS, life=100.0), "life"),
        (dict(spectrum=[(1.0, -2.0, 1.0)]), "speed"),
    ],
)
def test_bad_spectrum_search(kwargs, match):
    with pytest.raises(GearError, match=match):
        search.pairs(**{**GRID, **kwargs})


@settings(max_examples=8, deadline=None)
@given(
    st.lists(
        st.tuples(st.floats(1e-2, 1e4), st.floats(1.0, 1e5), st.floats(1e-2, 1e6)),
        min_size=1,
        max_size=4,
    )
)
def test_search_spectrum_property(bins):
    # any spectrum: rows with finite positive safeties, or our own error
    try:
        r = search.pairs(ratio=2, module=2, teeth=(16, 40), shifts=(0.0, 0.4, 0.2),
                         face_width=(10, 20, 10), spectrum=bins, top=3)  # fmt: skip
    except GearError:
        return
    for name in ("S_H", "S_F"):
        values = np.asarray(r[name], float)
        assert all(math.isfinite(v) and v > 0 for v in values)


def test_mesh_efficiency_column_is_the_pairs_efficiency():
    # the column is GearPair.efficiency at the load (ISO/TR 14179-2, the one-pair route), and
    # "-mesh_efficiency" ranks by it: the first row is the best of every feasible row
    kw = dict(torque=60.0, speed=1500.0, min_safety=MIN, **GRID)
    every = search.pairs(top=None, **kw)
    best = search.pairs(top=3, objective="-mesh_efficiency", **kw)
    assert float(best["mesh_efficiency"][0]) == pytest.approx(
        float(np.max(every["mesh_efficiency"])), rel=1e-12
    )
    assert np.all(np.diff(best["mesh_efficiency"]) <= 0.0)
    for i in range(len(best)):
        b = float(best["face_width"][i])
        eta = best.pair(i).efficiency(60.0, 1500.0, face_width=b).efficiency
        assert float(best["mesh_efficiency"][i]) == pytest.approx(eta, rel=1e-12)


def test_mesh_efficiency_of_a_spectrum_is_the_energys():
    # under a spectrum: one less the energy lost over the energy transmitted, by hand from
    # GearPair.efficiency at each bin (P_i = T_i n_i pi / 30, hours h_i)
    r = search.pairs(spectrum=BINS, min_safety=MIN, top=2, **GRID)
    for i in range(len(r)):
        b = float(r["face_width"][i])
        pair = r.pair(i)
        lost = sum(t * n * h * (1.0 - pair.efficiency(t, n, face_width=b).efficiency)
                   for t, n, h in BINS)  # fmt: skip
        total = sum(t * n * h for t, n, h in BINS)
        assert float(r["mesh_efficiency"][i]) == pytest.approx(1.0 - lost / total, rel=1e-12)


def test_pair_losses_masked_where_the_friction_equation_fails():
    from gears.rating.losses import pair_losses

    with pytest.raises(GearError, match="efficiency"):
        pair_losses(100.0, [1500.0, 1e-12], 20, 50, 3.0, 30.0)
    r = pair_losses(100.0, [1500.0, 1e-12], 20, 50, 3.0, 30.0, errors="mask")
    assert r.efficiency[0] > 0.98 and r.efficiency[1] == pytest.approx(0.0, abs=1e-300)
    assert r.power_loss[1] == pytest.approx(100.0 * 1e-12 * math.pi / 30.0, rel=1e-12)
    with pytest.raises(GearError, match="errors"):
        pair_losses(100.0, 1500.0, 20, 50, 3.0, 30.0, errors="ignore")


@settings(max_examples=25, deadline=None)
@given(
    st.lists(st.integers(5, 80), min_size=1, max_size=4),
    st.floats(-0.6, 1.2),
    st.lists(
        st.tuples(st.floats(1e-3, 1e5), st.floats(1e-2, 1e5), st.floats(1e-3, 1e7)),
        min_size=1,
        max_size=4,
    ),
)
def test_masked_spectrum_and_losses_property(z1, x1, bins):
    # rate_spectrum(errors="mask") and pair_losses(errors="mask") over any pairs and loads:
    # every row finite with its flag, never an exception but our own for bad input
    from gears.rating.losses import pair_losses
    from gears.rating.spectrum import rate_spectrum

    z1 = np.array(z1)
    try:
        r = rate_spectrum(z1, 60, 2.0, 20.0, bins, x1=x1, errors="mask")
    except GearError:
        return
    valid = np.asarray(r.valid, bool)
    for name in ("S_H1", "S_H2", "S_F1", "S_F2", "L_H1", "L_F2"):
        v = np.asarray(getattr(r, name))
        assert np.all(np.isfinite(v) & (v >= 0.0)) and np.all(np.abs(v[~valid]) < 1e-300), name
    torques = np.array([t for t, _, _ in bins])
    speeds = np.array([n for _, n, _ in bins])
    try:
        eff = pair_losses(torques, speeds, z1[:, None], 60, 2.0, 20.0, x1, errors="mask")
    except GearError:
        return
    assert np.all((eff.efficiency >= 0.0) & (eff.efficiency < 1.0))
    assert np.all(np.isfinite(eff.power_loss) & (eff.power_loss >= 0.0))
