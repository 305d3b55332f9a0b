"""The generic solver: errors, exactness, stability, identities and random trains."""

import warnings
from fractions import Fraction as F

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from trains import (
    IllConditionedTrainWarning,
    Train,
    TrainError,
    simple_planetary,
    stepped_planetary,
)

# ------------------------------------------------------------------------------- errors


@pytest.mark.parametrize(
    "teeth", [(0, 20), (20, -3), (20.5, 10), (True, 20), ("20", 30), (F(41, 2), 9)]
)
def test_bad_teeth_raise(teeth):
    with pytest.raises(TrainError, match="tooth count must be a positive integer"):
        Train().mesh("a", "b", teeth=teeth)


def test_integer_like_teeth_accepted():
    t = Train()
    t.mesh("a", "b", teeth=(np.int64(20), F(40)))
    assert t.ratio("a", "b") == -2


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda t: t.mesh("a", "a", teeth=(10, 10)), "two different members"),
        (lambda t: t.mesh("a", "b", teeth=(10, 10), carrier="a"), "carrier 'a'"),
        (lambda t: t.mesh("a", "b", teeth=(10,)), "pair"),
        (lambda t: t.link("a", "b", ratio=float("nan")), "finite"),
        (lambda t: t.link("a", "b", ratio="x/3"), "not a number"),
        (lambda t: t.link("a", "b", ratio=None), "must be a number"),
        (lambda t: t.mesh("", "b", teeth=(10, 10)), "non-empty string"),
    ],
)
def test_bad_relations_raise(call, match):
    with pytest.raises(TrainError, match=match):
        call(Train())


def test_duplicate_relation_name_raises_and_default_names_are_unique():
    t = Train()
    t.mesh("a", "b", teeth=(10, 20))
    t.mesh("a", "b", teeth=(10, 20), carrier="c")
    assert [r.name for r in t.relations] == ["a-b", "a-b#2"]
    with pytest.raises(TrainError, match="already exists"):
        t.mesh("a", "c", teeth=(10, 20), name="a-b")


def test_unknown_member_lists_known_names():
    t = simple_planetary(20, 30, 80)
    with pytest.raises(TrainError, match="unknown member 'sunn'; the members are carrier, frame"):
        t.solve(sunn=1, ring=0)
    with pytest.raises(TrainError, match="unknown member 'arm'"):
        t.ratio("sun", "arm", fixed=["ring"])
    with pytest.raises(TrainError, match="unknown member"):
        t.solve(sun=1, ring=0)["moon"]


def test_under_determined_names_free_members_and_count():
    t = simple_planetary(20, 30, 80)
    with pytest.raises(TrainError) as exc:
        t.solve()
    msg = str(exc.value)
    assert "under-determined" in msg and "give 2 more speeds" in msg
    assert "planet" in msg and "mobility 2" in msg
    with pytest.raises(TrainError, match="give 1 more speed"):
        t.solve(sun=3)


def test_three_members_of_a_differential_fixed_is_inconsistent():
    t = simple_planetary(20, 30, 80)
    with pytest.raises(TrainError, match=r"inconsistent.*mobility 2 but 3 speeds"):
        t.solve(sun=1, ring=0, carrier=0)
    with pytest.raises(TrainError, match="cannot turn"):
        t.ratio("sun", "planet", fixed=["ring", "carrier"])
    # consistent redundant speeds are accepted
    assert t.solve(sun=1500, ring=0, carrier=300)["planet"] == -500


def test_locked_closed_loop_names_the_relations():
    # a closed loop whose ratios disagree: a -> b -> c gives c = a, the link says c = 2a
    t = Train()
    t.mesh("a", "b", teeth=(20, 40))
    t.mesh("b", "c", teeth=(40, 20))
    t.link("c", "a", ratio=2, name="loop")
    assert t.mobility == 0
    with pytest.raises(TrainError, match=r"locked.*'a-b'.*'b-c'.*'loop'"):
        t.solve(a=1)
    with pytest.raises(TrainError, match="locked"):
        t.ratio("a", "c")
    assert t.solve(a=0)["c"] == 0  # standing still is the only motion


def test_consistent_closed_loop_is_redundant_not_an_error():
    t = Train()
    t.mesh("a", "b", teeth=(20, 40))
    t.mesh("b", "c", teeth=(40, 20))
    t.link("c", "a", ratio=1)
    assert t.mobility == 1
    assert t.solve(a=3)["c"] == 3
    assert t.solve(a=3.0)["c"] == 3.0


def test_disconnected_member():
    t = simple_planetary(20, 30, 80)
    t.add_member("loose")
    with pytest.raises(TrainError, match="speeds of loose are not fixed"):
        t.solve(sun=1, ring=0)
    assert t.ratio("sun", "carrier", fixed=["ring"]) == 5  # the rest is still determined
    assert t.solve(sun=1, ring=0, loose=7)["loose"] == 7


def test_nan_and_inf_speeds_raise():
    t = simple_planetary(20, 30, 80)
    with pytest.raises(TrainError, match="finite"):
        t.solve(sun=float("nan"), ring=0)
    with pytest.raises(TrainError, match="finite"):
        t.solve(sun=np.array([1.0, np.inf]), ring=0)
    with pytest.raises(TrainError, match="frame"):
        t.solve(sun=1, frame=0)
    with pytest.raises(TrainError, match="number or an array"):
        t.solve(sun="fast", ring=0)


# ------------------------------------------------------------------------------- types


def test_exact_float_and_array_paths_agree():
    t = simple_planetary(20, 30, 80)
    exact = t.solve(sun=1500, ring=7)
    flt = t.solve(sun=1500.0, ring=7.0)
    arr = t.solve(sun=np.array([1500.0, 0.0]), ring=np.array([7.0, 7.0]))
    for m in t.members:
        assert isinstance(exact[m], F)
        assert isinstance(flt[m], float)
        assert flt[m] == pytest.approx(float(exact[m]), rel=1e-15)
        assert arr[m][0] == pytest.approx(float(exact[m]), rel=1e-15)
    assert arr["frame"].shape == (2,)
    # broadcasting a scalar against a 2-d time grid
    grid = t.solve(sun=np.ones((3, 4)), ring=0)
    assert grid["carrier"].shape == (3, 4)
    assert np.all(grid["carrier"] == 0.2)


def test_one_in_ten_thousand_stays_exact():
    # Ozols Ex 7-4 (David): 1/10000 exactly; also through a float input the exact map gives
    # the correctly rounded answer (no cancellation in 1 - 9999/10000).
    t = stepped_planetary(100, 101, 100, 99, meshes=("external", "external"))
    assert t.ratio("1", "H", fixed=["3"]) == F(1, 10000)
    assert t.solve({"H": 3.0, "3": 0.0})["1"] == pytest.approx(3e-4, rel=2.3e-16)


# ------------------------------------------------------------------------------- stability


def test_float_speeds_that_overflow_are_refused():
    # a planetary 20/30/80 turns the carrier at (w_sun + 4 w_ring) / 5: two speeds near the
    # float64 limit (1.8e308) of opposite sign solve to a planet speed past it; that is a
    # TrainError naming the speeds, not an overflow warning and inf (issue 17: no impossible
    # number leaves the library). Exact integers are not bounded.
    t = simple_planetary(20, 30, 80)
    scalars = {"sun": 1.7e308, "ring": -1.7e308}
    arrays = {"sun": np.array([1.0, 1.7e308]), "ring": np.array([0.0, -1.7e308])}
    for speeds in (scalars, arrays):
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            with pytest.raises(TrainError, match=r"\|sun\| up to 1.7e\+308.*overflow float64"):
                t.solve(speeds)
    big = 17 * 10**307
    assert t.solve({"sun": big, "ring": -big})["carrier"] == F(big - 4 * big, 5)
    assert t.solve(sun=1e307, ring=0.0)["carrier"] == pytest.approx(2e306, rel=1e-15)


def test_basic_ratio_near_one_exact_keeps_it():
    # standards.md §6 item 8: i0 -> 1; Fractions keep the exact ratio.
    for n in (10**3, 10**6, 10**12):
        t = Train()
        t.link("1", "3", ratio=F(n - 1, n), carrier="H")
        assert t.ratio("H", "1", fixed=["3"]) == n


def test_basic_ratio_near_one_float_warns():
    t = Train()
    t.link("1", "3", ratio=1 - 1e-12, carrier="H")
    with pytest.warns(IllConditionedTrainWarning, match="ill-conditioned"):
        w1 = t.solve({"H": 1.0, "3": 0.0})["1"]
    assert np.isfinite(w1)
    with pytest.warns(IllConditionedTrainWarning, match="ill-conditioned"):
        assert np.isfinite(t.solve({"1": 1.0, "3": 0.0})["H"])
    # a well-conditioned float train does not warn
    t = Train()
    t.link("1", "3", ratio=-4.0, carrier="H")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert t.solve({"1": 5.0, "3": 0.0})["H"] == pytest.approx(1.0, rel=1e-15)  # 5 / (1 + 4)


def test_float_basic_ratio_exactly_one_gives_clear_error():
    t = Train()
    t.link("1", "3", ratio=1.0, carrier="H")
    with pytest.raises(TrainError, match=r"stands still|cannot turn"):
        t.ratio("H", "1", fixed=["3"])


def test_differential_cancellation_with_float_speeds_warns():
    # i0 = 1 - 1e-10 exact, but two nearly cancelling float inputs: w_H = (w1 - i0 w3)/(1 - i0)
    t = Train()
    t.link("1", "3", ratio=1 - F(1, 10**10), carrier="H")
    assert t.solve({"1": 1, "3": 1})["H"] == 1  # exact: fine
    with pytest.warns(IllConditionedTrainWarning, match="cancel"):
        t.solve({"1": 1.0 + 1e-15, "3": 1.0})


# ------------------------------------------------------------------------------- identities


@given(
    st.lists(st.integers(10, 120), min_size=4, max_size=4),
    st.sampled_from([("external", "internal"), ("external", "external"), ("internal", "internal")]),
)
@settings(max_examples=40, deadline=None)
def test_ratio_chain_identity(z, kinds):
    # independent derivation: i_ab i_bc = i_ac for any three members (same fixed member)
    t = stepped_planetary(*z, meshes=kinds)
    try:
        i_1h = t.ratio("1", "H", fixed=["3"])
        i_h2 = t.ratio("H", "2", fixed=["3"])
        i_12 = t.ratio("1", "2", fixed=["3"])
    except TrainError:
        return  # a member standing still (e.g. z1 z2' = z2 z3): no finite ratio
    assert i_1h * i_h2 == i_12


@given(st.integers(5, 200), st.integers(5, 200), st.lists(st.integers(5, 200), max_size=4))
@settings(max_examples=40, deadline=None)
def test_idlers_do_not_change_magnitude(z_in, z_out, idlers):
    # Ozols (7.4), Joldasbekov (6.61): idlers change the sign only.
    t = Train()
    chain = ["in", *(f"idler{i}" for i in range(len(idlers))), "out"]
    teeth = [z_in, *idlers, z_out]
    for k in range(len(chain) - 1):
        t.mesh(chain[k], chain[k + 1], teeth=(teeth[k], teeth[k + 1]))
    i = t.ratio("in", "out")
    assert abs(i) == F(z_out, z_in)
    assert (i < 0) == (len(chain) - 1) % 2  # (-1)^k, k external meshes


@st.composite
def random_trains(draw):
    n = draw(st.integers(2, 9))
    names = [f"m{i}" for i in range(n)]
    t = Train()
    for i in range(1, n):
        a = names[i]
        b = names[draw(st.integers(0, i - 1))]
        carrier = draw(st.sampled_from([None, *[m for m in names if m not in (a, b)]]))
        kind = draw(st.sampled_from(["mesh", "mesh", "link", "couple"]))
        if kind == "mesh":
            t.mesh(a, b, teeth=(draw(st.integers(1, 150)), draw(st.integers(1, 150))),
                   carrier=carrier, internal=draw(st.booleans()))  # fmt: skip
        elif kind == "link":
            num = draw(st.integers(-50, 50).filter(bool))
            t.link(a, b, ratio=F(num, draw(st.integers(1, 50))), carrier=carrier)
        else:
            t.couple(a, b)
    return t


@given(random_trains(), st.data())
@settings(max_examples=150, deadline=None)
def test_random_trains_every_relation_holds(t, data):
    # Hypothesis over random trains: give speeds to as many members as the mobility asks
    # (the solver's own suggestion), solve, and check every relation.
    free = t._map(()).choices
    speeds = {m: data.draw(st.integers(-10_000, 10_000)) for m in free}
    m = t.solve(speeds)
    fl = t.solve({k: float(v) for k, v in speeds.items()})
    for r in t.relations:
        exact = sum(k * m[name] for name, k in r.coefficients.items())
        assert exact == 0
        scale = sum(abs(float(k) * fl[name]) for name, k in r.coefficients.items())
        resid = sum(float(k) * fl[name] for name, k in r.coefficients.items())
        assert abs(resid) <= 1e-12 * max(scale, 1.0)
    for name in t.members:
        assert np.isfinite(fl[name])
        assert fl[name] == pytest.approx(float(m[name]), rel=1e-12, abs=1e-9)
    assert t.mobility == len(free)


def test_structure_counts_planet_copies():
    # Ozols §21-13: sigma = k - 1 redundant constraints; lectures §2.4 [D]: formal W = -1 for
    # k = 3 on a planetary train (ring fixed), i.e. 0 for the differential counted here.
    for k in (1, 2, 3, 4):
        s = simple_planetary(20, 30, 80, n_planets=k).structure
        assert s.redundant == k - 1
        assert s.mobility == 2
        assert s.chebyshev == 2 - (k - 1)
