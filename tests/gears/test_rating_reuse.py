"""The rating's shared parts (issues 26 and 30): a pair's load-independent part computed once
for many loads (``Rating.at``, a spectrum's bins) gives the numbers of a fresh rating, and
Miner's equivalent safety is where Miner's sum crosses 1.

Sources: the fresh rating itself (``rate_pairs`` on each pair and load alone, the route that
shares nothing), and Miner's elementary rule evaluated by ``miner_damage`` on both sides of the
answer (the definition of the equivalent safety, ISO 6336-6).
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import Gear, GearPair
from gears.errors import GearError
from gears.rating.iso6336 import rate_pairs
from gears.rating.spectrum import equivalent_safety, miner_damage, rate_spectrum


def test_pairs_by_bins_equal_each_rating_alone():
    # 6600 pairs x 10 loads (over two blocks, so the blocked path runs): each pair's gears'
    # part computed once per pair equals the same pair and load rated as a row of its own
    rng = np.random.default_rng(7)
    n, bins = 6600, 10
    z1 = rng.integers(14, 41, n)[:, None]
    z2 = rng.integers(40, 121, n)[:, None]
    m = rng.choice([1.0, 2.0, 3.0, 5.0], n)[:, None]
    x1 = rng.uniform(0.0, 0.5, n)[:, None]
    torque = np.geomspace(5.0, 500.0, bins)
    speed = np.linspace(300.0, 3000.0, bins)
    fields = ("S_H1", "S_H2", "S_F1", "S_F2", "K_v", "K_Hbeta", "Z_NT1", "Y_NT2", "sigma_H1")
    shared = rate_pairs(z1, z2, m, 10 * m, torque * m**2, speed, x1=x1, helix_angle=12.0,
                        life=2000.0, fields=fields, errors="mask", threads=2)  # fmt: skip
    flat = [np.broadcast_to(v, (n, bins)).ravel() for v in (z1, z2, m, x1, torque * m**2, speed)]
    z1f, z2f, mf, x1f, tf, nf = flat
    alone = rate_pairs(z1f, z2f, mf, 10 * mf, tf, nf, x1=x1f, helix_angle=12.0, life=2000.0,
                       fields=fields, errors="mask", threads=1)  # fmt: skip
    assert shared.valid.shape == (n, bins) and shared.valid.mean() > 0.99
    assert np.array_equal(shared.valid.ravel(), alone.valid)
    for f in fields:
        a, b = getattr(shared, f).ravel(), getattr(alone, f)
        np.testing.assert_allclose(a, b, rtol=1e-12, atol=0.0, err_msg=f)


def test_one_bin_spectrum_is_the_single_load_over_arrays():
    # a one-bin spectrum of many pairs (ISO 6336-6: one load for its hours) equals the
    # single-load safeties of rate_pairs at that load and life, pair by pair
    rng = np.random.default_rng(3)
    n = 400
    z1, z2 = rng.integers(14, 41, n), rng.integers(40, 121, n)
    m = rng.choice([1.0, 2.0, 3.0], n)
    spec = rate_spectrum(z1, z2, m, 10 * m, [(40.0, 1500.0, 3000.0)], x1=0.2, helix_angle=10.0)
    single = rate_pairs(z1, z2, m, 10 * m, 40.0, 1500.0, x1=0.2, helix_angle=10.0, life=3000.0)
    for f in ("S_H1", "S_H2", "S_F1", "S_F2"):
        np.testing.assert_allclose(getattr(spec, f), getattr(single, f), rtol=1e-11, err_msg=f)


@pytest.mark.parametrize("mode, code", [("pitting", 1), ("bending", 4), ("pitting", 7)])
def test_equivalent_safety_past_an_endurance_jump(mode, code):
    # the first bin's damage jumps at its endurance knot to half of Miner's limit (N_L = 5e9
    # against 1e10 cycles at the knot): the sum crosses 1 later, on the sloped curve, not at
    # the jump (found by brute force: Miner's sum on both sides of the answer)
    ratio = np.array([2.2, 1.0])
    cycles = np.array([5.01795425e9, 64.1086452])
    s = float(equivalent_safety(ratio, 1.0, cycles, code, mode))
    assert float(miner_damage(ratio * s * (1 - 1e-9), 1.0, cycles, code, mode)) < 1.0
    assert float(miner_damage(ratio * s * (1 + 1e-9), 1.0, cycles, code, mode)) >= 1.0 - 1e-9


def test_equivalent_safety_over_random_spectra():
    # 3000 random spectra of 1 ... 11 bins for each material group and mode: Miner's sum is
    # below 1 just under the answer and at least 1 just over it (the definition)
    rng = np.random.default_rng(11)
    for mode in ("pitting", "bending"):
        bins = int(rng.integers(1, 12))
        ratio = np.exp(rng.uniform(-1.5, 1.5, (3000, bins)))
        ratio[::3] = np.round(ratio[::3], 1)  # ties between the bins' knots
        cycles = np.exp(rng.uniform(0.0, 30.0, (3000, bins)))
        code = rng.integers(0, 8, 3000)
        s = equivalent_safety(ratio, 1.0, cycles, code, mode)
        inside = (s > 1.01e-4) & (s < 1e4 / 1.01)
        below = miner_damage(ratio * (s * (1 - 1e-9))[:, None], 1.0, cycles, code, mode)
        above = miner_damage(ratio * (s * (1 + 1e-9))[:, None], 1.0, cycles, code, mode)
        assert np.all((below < 1.0)[inside]) and np.all((above >= 1.0 - 1e-9)[inside])


def _same(a, b, rel=1e-12):
    """Every field of two one-pair PairRatings equal within ``rel`` (NaN where both are)."""
    for name, x, y in zip(a._fields, a, b, strict=True):
        x, y = float(x), float(y)
        if math.isnan(y):
            assert math.isnan(x), name
        else:
            assert x == pytest.approx(y, rel=rel, abs=1e-300), name


_PAIRS = {
    "spur": lambda: GearPair(Gear(19, 3, face_width=30), Gear(61, 3, face_width=30)),
    "helical": lambda: GearPair(
        Gear(17, 8, profile_shift=0.145, helix_angle=15.8, face_width=100),
        Gear(103, 8, helix_angle=-15.8, face_width=100),
    ),
    "ring": lambda: GearPair(Gear(20, 2, face_width=20), Gear(80, 2, internal=True, face_width=20)),
}


@pytest.mark.parametrize("kind", sorted(_PAIRS))
def test_rating_at_equals_a_fresh_rating(kind):
    # Rating.at keeps the gears' part and reruns the load's: every number equals a fresh
    # GearPair.rating at that load (with the kept parts cleared), to rounding
    from gears.rating import iso6336

    pair = _PAIRS[kind]()
    options = dict(material=("case-carburized", "through-hardened"), quality=5, roughness=0.6,
                   K_Hbeta=1.2, root_roughness=2.0)  # fmt: skip
    first = pair.rating(150.0, 1450.0, **options)
    for torque, speed, life, k_a in ((40.0, 300.0, 2e5, 1.0), (900.0, 6000.0, 50.0, 1.5)):
        again = first.at(torque, speed, life=life, application_factor=k_a)
        for kept in (iso6336._GEARS, iso6336._ARGUMENTS, iso6336._GEOMETRY):
            kept.clear()
        fresh = pair.rating(torque, speed, life=life, application_factor=k_a, **options)
        _same(again.values, fresh.values)
        assert again.settings["torque"] == pytest.approx(torque, rel=1e-15)
        assert again.roots == fresh.roots
    # not given: this rating's own load
    _same(first.at().values, first.values)
    _same(first.at(speed=700.0).values, pair.rating(150.0, 700.0, **options).values)


@pytest.mark.parametrize(
    "args, match",
    [((np.array([1.0, 2.0]),), "torque"), ((100.0, -5.0), "speed"), ((100.0, "fast"), "speed")],
)
def test_rating_at_refuses_bad_loads(args, match):
    first = _PAIRS["spur"]().rating(150.0, 1450.0)
    with pytest.raises(GearError, match=match):
        first.at(*args)


@settings(max_examples=40, deadline=None)
@given(st.floats(1e-6, 1e7), st.floats(1e-3, 1e6), st.floats(1e-3, 1e8), st.floats(1.0, 5.0))
def test_rating_at_property(torque, speed, life, k_a):
    # any load: the fresh rating's numbers, or the same GearError; never NaN
    pair = _PAIRS["helical"]()
    first = pair.rating(5000.0, 360.0)
    try:
        fresh = pair.rating(torque, speed, life=life, application_factor=k_a)
    except GearError as exc:
        with pytest.raises(GearError) as again:
            first.at(torque, speed, life=life, application_factor=k_a)
        assert str(again.value) == str(exc)
        return
    again = first.at(torque, speed, life=life, application_factor=k_a)
    _same(again.values, fresh.values)
    assert all(math.isfinite(s) and s > 0 for s in (*again.safety_pitting,
                                                     *again.safety_bending))  # fmt: skip
