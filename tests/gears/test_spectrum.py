"""gears.rating.spectrum, GearPair.rating(spectrum=...): load spectra by ISO 6336-6 (issue 30).

Sources: the single-load rating (a one-bin spectrum is that load for its hours); Miner's
elementary rule computed here from the bins' own stresses and the S-N curves of ISO 6336-2
Table 2 and ISO 6336-3 Table 3 (the knots written out below, read backwards in log-log).
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import Gear, GearPair
from gears.errors import GearError
from gears.rating.spectrum import LIFE_CAP, rate_spectrum

# case-carburized (Eh): ISO 6336-2 Table 2 (pitting) and ISO 6336-3 Table 3 (bending) knots
EH_PITTING = ((1e5, 1.6), (5e7, 1.0), (1e10, 0.85))
EH_BENDING = ((1e3, 2.5), (3e6, 1.0), (1e10, 0.85))


def _cycles_to_failure(ratio, knots):
    """N_f at sigma / sigma_inf, by hand: the log-log line through the knots read backwards."""
    (n0, y0), (n1, y1), (n2, y2) = knots
    if ratio > y0:
        return 1.0
    if ratio <= y2:
        return math.inf
    (na, ya), (nb, yb) = ((n0, y0), (n1, y1)) if ratio > y1 else ((n1, y1), (n2, y2))
    return math.exp(math.log(na) + (math.log(ratio) - math.log(ya))
                    * (math.log(nb) - math.log(na)) / (math.log(yb) - math.log(ya)))  # fmt: skip


def _miner(ratings, gear, mode, scale=1.0):
    """Miner's sum of one gear and mode from the bins' single-load ratings."""
    s, p, f, knots = {
        "pitting": ("sigma_H", "sigma_HP", "Z_NT", EH_PITTING),
        "bending": ("sigma_F", "sigma_FP", "Y_NT", EH_BENDING),
    }[mode]
    total = 0.0
    for r in ratings:
        stress = r.stresses[s][gear] * scale
        strength = r.stresses[p][gear] / r.factors[f][gear]
        cycles = r.quantities["N_L"][gear]
        total += cycles / _cycles_to_failure(stress / strength, knots)
    return total


def _pair():
    return GearPair(Gear(20, 3, face_width=30), Gear(50, 3, face_width=30))


@pytest.mark.parametrize("hours", [0.5, 20000.0, 3e6])
def test_one_bin_is_the_single_load_rating(hours):
    # a one-bin spectrum is that load for its hours; the three lives reach the three segments
    # of the curves (static, sloped, endurance)
    pair = _pair()
    single = pair.rating(250.0, 1500.0, life=hours)
    spec = pair.rating(spectrum=[(250.0, 1500.0, hours)])
    for a, b in zip((*single.safety_pitting, *single.safety_bending),
                    (*spec.safety_pitting, *spec.safety_bending), strict=True):  # fmt: skip
        assert b == pytest.approx(a, rel=1e-9)
    arr = rate_spectrum(20, 50, 3, 30, [(250.0, 1500.0, hours)])
    assert float(arr.S_H1) == pytest.approx(single.safety_pitting[0], rel=1e-9)
    assert float(arr.S_F2) == pytest.approx(single.safety_bending[1], rel=1e-9)


def test_two_bins_miner_by_hand():
    pair = _pair()
    bins = [(420.0, 1500.0, 3000.0), (180.0, 900.0, 40000.0)]
    ratings = [pair.rating(t, n, life=h) for t, n, h in bins]
    spec = pair.rating(spectrum=bins)
    for mode in ("pitting", "bending"):
        for gear in (0, 1):
            expected = _miner(ratings, gear, mode)
            assert spec.damage[mode][gear] == pytest.approx(expected, rel=1e-9, abs=1e-300)
            life = spec.life[mode][gear]
            if expected > 0:
                assert life == pytest.approx(min(43000.0 / expected, LIFE_CAP), rel=1e-9)
    # the pinion's pitting damage is positive here and the equivalent safety is where the
    # sum by hand crosses 1 when every stress grows by S
    s = spec.safety_pitting[0]
    assert spec.damage["pitting"][0] > 0
    assert (
        _miner(ratings, 0, "pitting", s * (1 - 1e-7))
        < 1.0
        <= _miner(ratings, 0, "pitting", s * (1 + 1e-7))
    )
    sf = spec.safety_bending[1]
    assert (
        _miner(ratings, 1, "bending", sf * (1 - 1e-7))
        < 1.0
        <= _miner(ratings, 1, "bending", sf * (1 + 1e-7))
    )


def test_arrays_match_the_pair():
    bins = [(420.0, 1500.0, 3000.0), (180.0, 900.0, 40000.0)]
    spec = _pair().rating(spectrum=bins)
    arr = rate_spectrum([20, 20], [50, 50], 3, [30, 30], bins)
    assert arr.S_H1.shape == (2,)
    assert float(arr.S_H1[1]) == pytest.approx(spec.safety_pitting[0], rel=1e-9)
    assert float(arr.D_H2[0]) == pytest.approx(spec.damage["pitting"][1], rel=1e-9)
    assert float(arr.L_F1[0]) == pytest.approx(spec.life["bending"][0], rel=1e-9)


def test_blocks_and_a_grid_match_each_pair(monkeypatch):
    # the array path in many blocks of a 2-D grid of pairs, on two threads (each block's bins
    # reduced by Miner's rule as it is rated), against each pair rated alone (GearPair)
    from gears.rating import sizing

    monkeypatch.setattr(sizing, "_SPECTRUM_CHUNK", 8)  # one row of 4 pairs x 2 bins a block
    bins = [(420.0, 1500.0, 3000.0), (180.0, 900.0, 40000.0)]
    z1, z2 = np.array([18, 20, 23])[:, None], np.array([45, 50, 61, 70])[None, :]
    arr = rate_spectrum(z1, z2, 3, 30, bins, threads=2)
    assert arr.S_H1.shape == (3, 4)
    for i, j in ((0, 0), (1, 2), (2, 3)):
        pair = GearPair(Gear(int(z1[i, 0]), 3, face_width=30), Gear(int(z2[0, j]), 3,
                                                                     face_width=30))  # fmt: skip
        spec = pair.rating(spectrum=bins)
        assert float(arr.S_H1[i, j]) == pytest.approx(spec.safety_pitting[0], rel=1e-9)
        assert float(arr.S_F2[i, j]) == pytest.approx(spec.safety_bending[1], rel=1e-9)
        assert float(arr.D_H1[i, j]) == pytest.approx(spec.damage["pitting"][0], rel=1e-9)
        assert float(arr.L_F1[i, j]) == pytest.approx(spec.life["bending"][0], rel=1e-9)


def test_spectrum_report_and_display():
    spec = _pair().rating(spectrum=[(420.0, 1500.0, 3000.0), (180.0, 900.0, 40000.0)])
    report = spec.check(min_pitting=1.0, min_bending=1.4)
    assert list(report) == ["pitting_1", "pitting_2", "bending_1", "bending_2"]
    assert report["pitting_1"].margin == pytest.approx(spec.safety_pitting[0] - 1.0, rel=1e-12)
    assert "Miner" in str(spec) and "<table" in spec._repr_html_()


@pytest.mark.parametrize(
    "spectrum, match",
    [
        ([], "bins"),
        ([(100.0, 1000.0)], "bins"),
        ([(100.0, 1000.0, -1.0)], r"spectrum bin 0: hours = -1\.0; valid"),  # a plain number
        ([(100.0, math.nan, 1.0)], "speed"),
        ("abc", "spectrum"),
    ],
)
def test_bad_spectrum(spectrum, match):
    with pytest.raises(GearError, match=match):
        _pair().rating(spectrum=spectrum)


def test_spectrum_with_torque_refused():
    with pytest.raises(GearError, match="not both"):
        _pair().rating(100.0, 1000.0, spectrum=[(100.0, 1000.0, 1.0)])
    with pytest.raises(GearError, match="spectrum"):
        rate_spectrum(20, 50, 3, 30, [(1.0, 1.0, 1.0)], life=3.0)


bins_strategy = st.lists(
    st.tuples(st.floats(1e-3, 1e5), st.floats(1e-2, 1e5), st.floats(1e-3, 1e7)),
    min_size=1,
    max_size=5,
)


@settings(max_examples=20, deadline=None)
@given(bins_strategy, st.integers(8, 60), st.integers(8, 120))
def test_rate_spectrum_property(bins, z1, z2):
    try:
        r = rate_spectrum(z1, z2, 2.0, 20.0, bins)
    except GearError:
        return
    for v in r:
        assert np.all(np.isfinite(v)) and np.all(np.asarray(v) >= 0)


@settings(max_examples=20, deadline=None)
@given(
    st.lists(st.integers(6, 60), min_size=1, max_size=7),
    st.lists(st.floats(1.0, 5000.0), min_size=1, max_size=5),
    st.integers(1, 40),
    st.integers(1, 2),
)
def test_rate_reduced_property(z1, torques, chunk, threads):
    # every block handed to the reducer (any block size, in pieces on threads) holds what
    # rate_pairs gives for its rows: the same ratings stored whole (an independent path)
    from gears.rating.iso6336 import rate_pairs, rate_reduced

    pairs, loads = np.array(z1, float)[:, None], np.array(torques)
    kw = dict(z1=pairs, z2=61, module=3, face_width=30, torque=loads, speed=1450.0,
              errors="mask", fields=("S_H1", "S_F2"))  # fmt: skip
    seen = np.full((len(z1), len(torques)), np.nan)

    def reduce(q, i0, i1):
        seen[i0:i1] = q["S_H1"]

    r = rate_reduced(reduce, chunk, threads=threads, **kw)
    whole = rate_pairs(**kw, threads=1)
    assert np.array_equal(np.broadcast_to(r.valid, seen.shape), whole.valid)
    assert np.allclose(seen, whole.S_H1, rtol=1e-12, atol=0.0)
    assert np.all(np.isfinite(seen))


@pytest.mark.parametrize(
    ("reduce", "chunk", "extra", "named"),
    [
        (None, 10, {}, r"reduce = None; valid is a callable"),
        ("sum", 10, {}, r"reduce = 'sum'; valid is a callable"),
        (print, 0, {}, r"chunk = 0; valid is an integer >= 1"),
        (print, 1.5, {}, r"chunk = 1.5; valid is an integer >= 1"),
        (print, "x", {}, r"chunk = 'x'; valid is an integer >= 1"),
        (print, True, {}, r"chunk = True; valid is an integer >= 1"),
        (print, 10, {"torqe": 100.0}, r"torqe is not an argument; valid are the arguments of "
                                      r"rate_pairs by name: z1, z2"),
        (print, 10, {"speed": None}, r"speed is missing; valid are the arguments of rate_pairs"),
    ],
)  # fmt: skip
def test_rate_reduced_names_what_it_cannot_take(reduce, chunk, extra, named):
    # a reducer that is not callable, a block size that is not a whole number of ratings, an
    # argument rate_pairs does not have or a required one left out: our own error, naming it
    from gears.rating.iso6336 import rate_reduced

    kw = dict(z1=20, z2=61, module=3, face_width=30, torque=100.0, speed=1450.0) | extra
    kw = {k: v for k, v in kw.items() if v is not None}
    with pytest.raises(GearError, match=named):
        rate_reduced(reduce, chunk, **kw)


@settings(max_examples=10, deadline=None)
@given(bins_strategy)
def test_pair_spectrum_property(bins):
    try:
        spec = _pair().rating(spectrum=bins)
    except GearError:
        return
    assert all(math.isfinite(s) and s > 0 for s in (*spec.safety_pitting, *spec.safety_bending))


@settings(max_examples=40, deadline=None)
@given(
    st.lists(st.tuples(st.floats(0.2, 5.0), st.floats(1.0, 1e12)), min_size=1, max_size=6),
    st.sampled_from(["pitting", "bending"]),
    st.integers(0, 7),
)
def test_equivalent_safety_property(bins, mode, code):
    # stresses relative to a unit strength: S finite and positive, Miner's sum at S times the
    # stresses at least 1 and just below it under 1 (the definition), for every material group
    from gears.rating.spectrum import equivalent_safety, miner_damage

    ratio = np.array([b[0] for b in bins])
    cycles = np.array([b[1] for b in bins])
    s = float(equivalent_safety(ratio, 1.0, cycles, code, mode))
    assert math.isfinite(s) and s > 0
    if 1e-4 * 1.01 < s < 1e4 / 1.01:
        assert float(miner_damage(ratio * s * (1 + 1e-9), 1.0, cycles, code, mode)) >= 1.0 - 1e-9
        assert float(miner_damage(ratio * s * (1 - 1e-6), 1.0, cycles, code, mode)) < 1.0
    # the solver's own Miner sum (each bin's S-N line written through its knee, in kept
    # buffers) is miner_damage's (the S-N curve by its knots): the same formula two ways, to
    # 1e-11 relative (ln N_f of up to a few hundred, rounded in a different order)
    from gears.rating.miner import _damage_and_safety

    for k in (0.5, 1.0, 2.0):
        d, _ = _damage_and_safety(ratio * k, 1.0, cycles, code, mode)
        want = float(miner_damage(ratio * k, 1.0, cycles, code, mode))
        assert float(d) == pytest.approx(want, rel=1e-11, abs=1e-300), (k, float(d), want)


@settings(max_examples=30, deadline=None)
@given(st.text(alphabet="0123456789.,; #\nabce-", max_size=60))
def test_read_spectrum_property(tmp_path_factory, text):
    from gears.rating.spectrum import read_spectrum

    f = tmp_path_factory.mktemp("s") / "duty.csv"
    f.write_text(text)
    try:
        bins = read_spectrum(f)
    except GearError as exc:
        assert "spectrum" in str(exc)
        return
    assert bins and all(len(b) == 3 and min(b) > 0 and math.isfinite(sum(b)) for b in bins)


@settings(max_examples=40, deadline=None)
@given(
    st.integers(1, 12),
    st.integers(1, 300),
    st.sampled_from(["pitting", "bending"]),
    st.one_of(st.integers(0, 7), st.just(-1)),
    st.integers(0, 2**32 - 1),
)
def test_fast_path_equals_the_bisection(bins, rows, mode, code, seed):
    # brute force by another method: the rounds of _solve (each stretch's D = 1 solved, kept
    # where the bins' states at the root are the stretch's) against the bisection over every
    # row's sorted knots (_bisect), on random blocks: stresses over 1e-3 ... 20 of the
    # strength, cycles from under one to 1e11, a few rows where D jumps over 1 at a knot (a
    # bin's endurance knot with N_L of 1e10 and more), NaN rows, absurd cycles, a material
    # group per row
    from gears.rating.life import _BENDING_TABLE, _PITTING_TABLE
    from gears.rating.miner import _bisect, _knots, _solve

    rng = np.random.default_rng(seed)
    z = rng.uniform(-7.0, 3.0, (bins, rows))
    lc = rng.uniform(-2.0, 25.3, (bins, rows))
    jump = rng.random(rows) < 0.1
    lc[0, jump] = rng.uniform(23.0, 26.0, jump.sum())  # N_L of 1e10 ... 2e11 on one bin
    z[:, rng.random(rows) < 0.02] = np.nan
    lc[-1, rng.random(rows) < 0.02] = 120.0  # N_L of 1e52: past what the lines' factors hold
    codes = rng.integers(0, 8, rows) if code < 0 else code
    knots = _knots(codes, _PITTING_TABLE if mode == "pitting" else _BENDING_TABLE)
    if np.ndim(codes):
        knots = tuple(k[..., 0] for k in knots)
    d_fast, s_fast = _solve(z.copy(), np.exp(lc), knots)
    d_bis, s_bis = _bisect(z.copy(), lc.copy(), knots)
    # the same Miner's sum written two ways (the lines' factors at S = 1 against each bin's
    # ln damage at S = 1): to 1e-12 relative; the safeties to 1e-12 (both solve the same
    # stretch's equation to ~1e-16)
    np.testing.assert_allclose(d_fast, d_bis, rtol=1e-12, atol=0)
    np.testing.assert_allclose(s_fast, s_bis, rtol=1e-12, atol=0)


def test_a_static_bin_far_past_its_knot_is_not_lost():
    # regression: group 7's bending curve (Y_NT 2.5 ... 1 over 10^3 ... 3 x 10^6 cycles: its
    # upper line falls 84 in ln N_f per unit of ln sigma) with one bin 8.4 times its strength
    # (static at S = 1: D(1) = its 4.4 cycles) and one far below: the bisection's line of the
    # static bin at the next knot overflowed (e^726, times a False mask: NaN) and S came out
    # 1e4. By the definition, D jumps over 1 where that bin turns static: S is the static
    # knot's stress ratio over the bin's, e^y0 / 8.3963 (y0 = ln Y_NT there), within 1e-9;
    # and brute force with miner_damage (the S-N curve by its knots) on either side of it
    from gears.rating.spectrum import equivalent_safety, miner_damage

    stress = np.exp([2.12755577, -6.8400827])
    cycles = np.exp([1.47810215, 7.00615623])
    s = float(equivalent_safety(stress, 1.0, cycles, 7, "bending"))
    from gears.rating.life import _BENDING_TABLE

    y0 = float(_BENDING_TABLE[1][7][0])
    assert s == pytest.approx(math.exp(y0) / stress[0], rel=1e-9)
    assert float(miner_damage(stress * s * (1 - 1e-9), 1.0, cycles, 7, "bending")) < 1.0
    assert float(miner_damage(stress * s * (1 + 1e-9), 1.0, cycles, 7, "bending")) >= 1.0


_KINDS = ("any", "ties", "one row of bins", "below endurance", "static", "under one cycle",
          "near the endurance knot", "far out")  # fmt: skip


@settings(max_examples=150, deadline=None)
@given(
    st.sampled_from([1, 2, 3, 7, 50, 200]),
    st.integers(1, 24),
    st.sampled_from(["pitting", "bending"]),
    st.booleans(),
    st.sampled_from(_KINDS),
    st.sampled_from([1, 2, 6]),
    st.integers(0, 2**32 - 1),
)
def test_fast_path_by_the_definition(bins, rows, mode, per_row, kind, rounds, seed):
    # the rounds of _solve (cut short after 1, 2 or its 6 rounds: the rows left go to the
    # knot between the last x below and above, or the bisection) against (a) the bisection
    # over the sorted knots (_bisect) to 1e-9 and (b) brute force by the definition with
    # miner_damage (the S-N curve by its knots, another formula): D < 1 just below S (unless
    # S is the bound 1e-4) and D >= 1 at S (1 + 1e-7) (unless S is the bound 1e4); S within
    # 1e-7 of a crossing is 4 x 10^-7 of D at least on the curves' slopes (b >= 6.2), far over
    # the two formulas' 1e-12 apart. On ties (equal stresses and cycles), zero cycles, cycles
    # under one, 1 ... 200 bins, every bin below its endurance knot or static at S = 1, S far
    # out (up to 1e4), a material group per row, NaN rows (both give S = 1e4 and a NaN sum)
    from gears.rating import miner
    from gears.rating.life import _BENDING_TABLE, _PITTING_TABLE
    from gears.rating.miner import _bisect, _knots, _solve, miner_damage

    rng = np.random.default_rng(seed)
    z = rng.uniform(-3.0, 2.5, (bins, rows))  # ln(sigma / sigma_inf)
    lc = rng.uniform(-3.0, 25.0, (bins, rows))  # ln N_L
    if kind == "ties":
        z, lc = np.round(z * 2.0) / 2.0, np.round(lc / 4.0) * 4.0
    elif kind == "one row of bins":
        z[:], lc[:] = z[0], lc[0]
    elif kind == "below endurance":
        z = rng.uniform(-3.0, -0.17, (bins, rows))  # ln 0.85 = -0.163: the lowest y2
    elif kind == "static":
        z = rng.uniform(0.5, 3.0, (bins, rows))  # ln 1.6 = 0.47: past every y0 but 2.5's
    elif kind == "under one cycle":
        lc = rng.uniform(-10.0, 0.0, (bins, rows))
    elif kind == "near the endurance knot":
        z, lc = rng.uniform(-0.5, 0.3, (bins, rows)), rng.uniform(18.0, 24.0, (bins, rows))
    elif kind == "far out":  # stresses 1e-4 ... 2.5e-3 of the strength: S up to 1e4
        z, lc = rng.uniform(-9.2, -6.0, (bins, rows)), rng.uniform(-3.0, 40.0, (bins, rows))
    cycles = np.exp(lc)
    cycles[rng.random((bins, rows)) < 0.1] = 0.0  # ln N_L = -inf
    nan = rng.random(rows) < 0.05
    z[:, nan] = np.nan
    codes = rng.integers(0, 8, rows) if per_row else int(rng.integers(0, 8))
    knots = _knots(codes, _PITTING_TABLE if mode == "pitting" else _BENDING_TABLE)
    if per_row:
        knots = tuple(k[..., 0] for k in knots)
    saved = miner._ROUNDS
    miner._ROUNDS = rounds
    try:
        d_fast, s_fast = _solve(z.copy(), cycles.copy(), knots)
    finally:
        miner._ROUNDS = saved
    with np.errstate(divide="ignore"):
        d_bis, s_bis = _bisect(z.copy(), np.log(cycles), knots)
    np.testing.assert_allclose(s_fast, s_bis, rtol=1e-9, atol=0)
    np.testing.assert_allclose(d_fast, d_bis, rtol=1e-11, atol=1e-300)
    assert np.all(np.isnan(d_fast) == nan) and np.all(s_fast[nan] > 1e4 * (1 - 1e-12))
    ratio, n_l, s = np.exp(z[:, ~nan]).T, cycles[:, ~nan].T, s_fast[~nan]
    code = codes[~nan] if per_row else codes
    below = miner_damage(ratio * (s * (1 - 1e-7))[:, None], 1.0, n_l, code, mode)
    above = miner_damage(ratio * (s * (1 + 1e-7))[:, None], 1.0, n_l, code, mode)
    assert np.all((below < 1.0) | (s < 1e-4 * (1 + 1e-12))), (s, below)
    assert np.all((above >= 1.0) | (s > 1e4 * (1 - 1e-12))), (s, above)


def test_bins_under_one_cycle_never_fail():
    # regression: bending, group 2, three bins of 0.094, 8 x 10^-5 and 0 cycles: each bin's
    # damage is at most its cycles (N_f >= 1), so D <= 0.094 at any S and S is the bound 1e4
    # (within 1e-12); the rounds gave 15.09, the second bin's static knot, taking the one knot
    # past the last x below 1 for a jump with no x at or above 1 seen
    from gears.rating.spectrum import equivalent_safety, miner_damage

    stress = np.exp([0.33266419, -1.22401813, -1.79795485])
    cycles = np.array([9.35366884e-02, 7.98290784e-05, 0.0])
    s = float(equivalent_safety(stress, 1.0, cycles, 2, "bending"))
    assert s == pytest.approx(1e4, rel=1e-12)
    assert float(miner_damage(stress * 1e4, 1.0, cycles, 2, "bending")) < 1.0


def test_given_life_factors_cancel_and_factor_arrays_are_per_pair():
    # Miner's rule reads the S-N curve itself: the strength is sigma_HP / Z_NT (sigma_FP / Y_NT)
    # and sigma_HP is Z_NT times the rest (ISO 6336-2 eq. (2), ISO 6336-3 eq. (4)), so a given
    # life factor cancels (derivation): rate_spectrum (bins rated with Z_NT = Y_NT = 1) with
    # and without them to 1e-12, and GearPair.rating (each bin with its life factors) to 1e-9
    bins = [(420.0, 1500.0, 3000.0), (180.0, 900.0, 40000.0), (900.0, 300.0, 2.0)]
    plain = rate_spectrum([18, 20, 25], 50, 3, 30, bins)
    given = rate_spectrum([18, 20, 25], 50, 3, 30, bins, factors={"Z_NT": 0.8, "Y_NT": (0.9, 1.1)})
    for f in plain._fields[:-1]:
        np.testing.assert_allclose(getattr(given, f), getattr(plain, f), rtol=1e-12, atol=0)
    spec = _pair().rating(spectrum=bins, Z_NT=0.8, Y_NT=(0.9, 1.1))
    assert float(given.S_H1[1]) == pytest.approx(spec.safety_pitting[0], rel=1e-9)
    assert float(given.S_F2[1]) == pytest.approx(spec.safety_bending[1], rel=1e-9)
    # a factor's array runs over the pairs, not the bins (3 of each here: it used to run over
    # the bins), each of a per-gear pair's too: against each pair rated alone, to 1e-12
    k_a, y_x = np.array([1.0, 1.25, 1.5]), np.array([1.0, 0.95, 0.9])
    arr = rate_spectrum([18, 20, 25], 50, 3, 30, bins, factors={"K_A": k_a, "Y_X": (y_x, 1.0)})
    for i, z in enumerate((18, 20, 25)):
        one = rate_spectrum(z, 50, 3, 30, bins, factors={"K_A": k_a[i], "Y_X": (y_x[i], 1.0)})
        assert float(arr.S_H1[i]) == pytest.approx(float(one.S_H1), rel=1e-12)
        assert float(arr.S_F1[i]) == pytest.approx(float(one.S_F1), rel=1e-12)


@pytest.mark.parametrize("factors", [[], 0, "K_A", np.array([1.0, 2.0]), {"K_A": [[1.0], 2]},
                                     {"Z_NT": ([1.0, [2.0]], 1.0)}])  # fmt: skip
def test_bad_factors_are_named(factors):
    # factors that are not a dict of factors (or a ragged array in one): our own error naming
    # them, in rate_spectrum as in rate_pairs (were: AttributeError, ValueError, or taken as
    # no factors)
    from gears.rating.iso6336 import rate_pairs

    bins = [(420.0, 1500.0, 3000.0), (180.0, 900.0, 40000.0)]
    for rate in (lambda: rate_spectrum(20, 50, 3, 30, bins, factors=factors),
                 lambda: rate_pairs(20, 50, 3, 30, 420.0, 1500.0, factors=factors)):  # fmt: skip
        with pytest.raises(GearError, match=r"factors = |K_A = |Z_NT = "):
            rate()


@pytest.mark.parametrize(
    ("args", "kw", "named"),
    [
        (("a", 1.0, 1.0, 4), {}, r"stress = 'a'; valid is a number"),
        ((-1.0, 1.0, [1.0], 4), {}, r"stress = -1; valid is 0 < stress"),
        (([1.0, np.nan], 1.0, 1.0, 4), {}, r"stress = nan at row 1"),
        (([1.0], 0.0, [1.0], 4), {}, r"strength = 0; valid is 0 < strength"),
        (([1.0], 1.0, [np.inf], 4), {}, r"cycles = inf at row 0; valid is 0 <= cycles"),
        (([9.0, 9.0], 1.0, [1e308, 1e308], 4), {}, r"cycles = 1e\+308 at row 0; valid is 0 <= "
                                                    r"cycles <= 1e\+30"),  # the sum was inf
        (([1.0], 1.0, [1.0], 8), {}, r"code = 8; valid is an integer 0 <= code <= 7"),
        (([1.0], 1.0, [1.0], 2.5), {}, r"code = 2.5; valid is an integer"),
        (([[1.0, 2.0]], 1.0, 1.0, [1, 2, 3]), {}, r"code has shape \(3,\); valid is the result's"),
        (([1.0, 2.0], 1.0, [1.0, 2.0, 3.0], 4), {}, r"stress has shape \(2,\) and cycles"),
        (([], 1.0, 1.0, 4), {}, r"no bins"),
        ((1.0, 1.0, 1.0, 4), {}, r"axis = -1: the bins' arrays are numbers"),
        (([1.0], 1.0, [1.0], 4), {"axis": 1}, r"axis = 1; valid is an axis .* from -1 to 0"),
        (([1.0], 1.0, [1.0], 4), {"axis": True}, r"axis = True"),
        (([1.0], 1.0, [1.0], 4), {"mode": "wear"}, r"mode = 'wear'; valid are pitting, bending"),
    ],
)  # fmt: skip
def test_miner_functions_name_bad_bins(args, kw, named):
    # the public Miner's rule functions check their bins before any work (were: numpy's
    # AxisError, ValueError, IndexError, or a NaN or 1e4 out)
    from gears.rating.spectrum import equivalent_safety, miner_damage

    for f in (equivalent_safety, miner_damage):
        with pytest.raises(GearError, match=named):
            f(*args, **kw)


@settings(max_examples=60, deadline=None)
@given(
    st.lists(st.tuples(st.floats(allow_nan=True, allow_infinity=True),
                       st.floats(-1.0, 1e308, allow_nan=False)), min_size=0, max_size=4),
    st.one_of(st.integers(-2, 9), st.floats(-1.0, 9.0)),
    st.sampled_from(["pitting", "bending", "x"]),
)  # fmt: skip
def test_miner_functions_property(bins, code, mode):
    # any numbers: a finite answer (S in [1e-4, 1e4], D and N_f >= 0) or our own error
    from gears.rating.spectrum import cycles_to_failure, equivalent_safety, miner_damage

    ratio = [b[0] for b in bins]
    cycles = [b[1] for b in bins]
    for call in (lambda: equivalent_safety(ratio, 1.0, cycles, code, mode),
                 lambda: miner_damage(ratio, 1.0, cycles, code, mode),
                 lambda: cycles_to_failure(ratio, code, mode)):  # fmt: skip
        try:
            v = np.asarray(call(), float)
        except GearError:
            continue
        assert np.all(np.isfinite(v)) and np.all(v >= 0.0)


def test_a_far_out_bin_turning_static_is_not_lost():
    # regression: group 7 bending, one bin at 2.1e-4 of its strength for 1.07 cycles: D jumps
    # from 0.001 to its 1.07 cycles where the bin turns static, at S = e^y0 / the stress ratio
    # (y0 = ln Y_NT at the static knot), within 1e-9 (derivation). The rounds' lines cannot
    # hold a bin this far out and the bisection took D at the last stretch's start as
    # 0 * e^719 = NaN: S came out 1e4. Brute force with miner_damage on either side
    from gears.rating.life import _BENDING_TABLE
    from gears.rating.spectrum import equivalent_safety, miner_damage

    stress, cycles = np.exp([-8.47130678]), np.array([1.07296993])
    s = float(equivalent_safety(stress, 1.0, cycles, 7, "bending"))
    y0 = float(_BENDING_TABLE[1][7][0])
    assert s == pytest.approx(math.exp(y0) / stress[0], rel=1e-9)
    assert float(miner_damage(stress * s * (1 - 1e-9), 1.0, cycles, 7, "bending")) < 1.0
    assert float(miner_damage(stress * s * (1 + 1e-9), 1.0, cycles, 7, "bending")) >= 1.0


def test_rounds_come_down_from_a_start_above_the_answer():
    # group 7's bending curve is steeper above its knee than below (a_1 = -84 < a_2 = -49.9,
    # ISO 6336-3 Table 3's Y_NT): a bin's damage is the larger of its two lines, so the start
    # (where one line summed over the bins reaches 1) lies above the answer in most rows; the
    # rounds still reach it: against the bisection over the sorted knots (_bisect, brute force
    # by another method) to 1e-12, and by the definition with miner_damage (D < 1 just below
    # S, >= 1 just above)
    from gears.rating.life import _BENDING_TABLE
    from gears.rating.miner import _bisect, _knots, _Lines, _slopes, _solve, miner_damage

    knots = _knots(7, _BENDING_TABLE)
    a1, a2 = _slopes(knots)
    assert a1 < a2
    rng = np.random.default_rng(3)
    z, cycles = rng.uniform(-0.5, 0.5, (5, 400)), np.exp(rng.uniform(10.0, 20.0, (5, 400)))
    start, _ = _Lines(z, cycles, knots).start()
    _, s = _solve(z.copy(), cycles.copy(), knots)
    assert np.count_nonzero(start > np.log(s) + 1e-9) > 200  # most rows start above
    _, s_bis = _bisect(z.copy(), np.log(cycles), knots)
    np.testing.assert_allclose(s, s_bis, rtol=1e-12, atol=0)
    ratio = np.exp(z).T
    assert np.all(miner_damage(ratio * (s * (1 - 1e-7))[:, None], 1.0, cycles.T, 7, "bending") < 1)
    assert np.all(miner_damage(ratio * (s * (1 + 1e-7))[:, None], 1.0, cycles.T, 7, "bending") >= 1)


@pytest.mark.parametrize("mode", ["pitting", "bending"])
def test_the_solvers_line_is_the_life_curve(mode):
    # both Miner's solvers take a bin's ln N_f at S = 1 from one line (_line_at_one): on the
    # S-N curve's sloped segments it is the curve of ISO 6336-2 Table 2 / ISO 6336-3 Table 3
    # (log-log linear between the knots), read by cycles_to_failure (another formula: the
    # hinge through the knee), to 1e-12 relative, above the knee on the upper line and below
    # it on the lower, for every material group
    from gears.rating.life import _BENDING_TABLE, _PITTING_TABLE
    from gears.rating.miner import _knots, _line_at_one, _slopes, cycles_to_failure

    for code in range(8):
        knots = _knots(code, _PITTING_TABLE if mode == "pitting" else _BENDING_TABLE)
        y0, y1, y2 = knots[3:]
        for lo, hi, a in ((y1, y0, _slopes(knots)[0]), (y2, y1, _slopes(knots)[1])):
            z = np.linspace(lo, hi, 7)[1:-1]
            want = np.log(cycles_to_failure(np.exp(z), code, mode))
            np.testing.assert_allclose(_line_at_one(y1 - z, a, knots[1]), want, rtol=1e-12)


@settings(max_examples=25, deadline=None)
@given(
    st.integers(1, 4),
    st.integers(1, 4),
    st.sampled_from(["K_A", "Y_X", "Z_NT", "K_v", "Z_L"]),
    st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.floats(0.5, 2.0)),
    st.sampled_from(["number", "per pair", "other length", "per gear", "per gear arrays"]),
)
def test_rate_spectrum_factors_property(pairs, bins, name, value, form):
    # rate_spectrum's factors= (a number, an array over the pairs, one of another length, a
    # per-gear pair of numbers or arrays), any value: finite safeties and lives >= 0, or our
    # own error
    z1 = list(range(18, 18 + pairs))
    spectrum = [(300.0 + 100 * i, 1000.0, 500.0 * (i + 1)) for i in range(bins)]
    arr = np.full(pairs, value)
    given = {"number": value, "per pair": arr, "other length": np.full(pairs + 1, value),
             "per gear": (value, 1.0), "per gear arrays": (arr, arr)}[form]  # fmt: skip
    try:
        r = rate_spectrum(z1, 50, 3, 30, spectrum, factors={name: given})
    except GearError:
        return
    for v in r:
        assert np.all(np.isfinite(v)) and np.all(np.asarray(v) >= 0)


@pytest.mark.parametrize(("factors", "named"), [
    ({"K_A": np.ones(4)}, r'factors\["K_A"\] has shape \(4,?'),
    ({"Y_X": (1.0, np.ones(4))}, r'factors\["Y_X"\]\[1\] has shape \(4,?'),
    ({"c'": np.full(4, 14.0)}, r'factors\["c\'"\] has shape \(4,?'),
])  # fmt: skip
def test_a_factor_array_of_another_length_is_named_as_given(factors, named):
    # three pairs, a factor's array of four: the message names the factor as the caller gave it
    # (it named the internal o_K_A, o_Y_X2, o_c_prime), in rate_pairs and rate_spectrum
    from gears.rating.iso6336 import rate_pairs

    for rate in (lambda: rate_pairs([18, 19, 20], 50, 3, 30, 300.0, 1000.0, factors=factors),
                 lambda: rate_spectrum([18, 19, 20], 50, 3, 30, [(300.0, 1000.0, 5.0)],
                                       factors=factors)):  # fmt: skip
        with pytest.raises(GearError, match=named):
            rate()


def test_one_term_root_is_the_root():
    # _term_root (the rounds' start and _regime_root's one-term roots) by its definition:
    # C + A exp(b x) = 1 at x, to 1e-12, over C in [0, 0.99), A over 1e-30 ... 1e30, b 6 ... 84
    # (the S-N lines' slopes negated)
    from gears.rating.miner import _term_root

    rng = np.random.default_rng(11)
    c, a, b = rng.uniform(0, 0.99, 500), 10.0 ** rng.uniform(-30, 30, 500), rng.uniform(6, 84, 500)
    x = _term_root(np.log1p(-c), a, b)
    np.testing.assert_allclose(c + a * np.exp(b * x), 1.0, rtol=1e-12)
