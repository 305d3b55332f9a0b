"""gears.search.engine.pairs: the chunked pair search against brute force and textbook pairs.

Reference values: brute force (``GearPair(...).check()`` on every candidate, an independent
route), Joldasbekov §5.4 (12/28, x 0.3/0.2, m = 1: a_w = 20.46253, eps = 1.36264), KHK's
profile-shifted example (12/24, x 0.6/0.36, m = 3: a_w = 56.4999 mm, alpha_w = 26.0886 deg).
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import Gear, GearError, GearPair
from gears.search.candidates import Limits
from gears.search.engine import pairs
from gears.search.result import SearchResult


def _feasible_by_brute_force(teeth, shifts, module=2.0, limits=None):
    """{(z1, z2, x1, x2): report} of every candidate whose GearPair.check() holds."""
    limits = limits or Limits()
    out = {}
    for z1, z2, x1, x2 in itertools.product(teeth, teeth, shifts, shifts):
        try:
            pair = GearPair(Gear(z1, module, profile_shift=x1), Gear(z2, module, profile_shift=x2))
            report = pair.check(limits.min_contact_ratio, limits.min_tip_land)
        except GearError:  # no working pressure angle, or no real gear: not a candidate
            continue
        if report.ok:
            out[(z1, z2, round(x1, 9), round(x2, 9))] = report
    return out


def _column(name: str) -> str:
    return name.replace(".", "_").replace("contact_ratio", "contact_ratio_margin")


def test_feasible_set_and_margins_equal_brute_force():
    # independent route: GearPair(...).check() on all 7 x 7 x 6 x 6 candidates (1764)
    teeth, shifts = [13, 16, 20, 27, 35, 44, 60], [-0.3, 0.0, 0.2, 0.4, 0.6, 0.9]
    limits = Limits(min_contact_ratio=1.2, min_tip_land=0.25)
    brute = _feasible_by_brute_force(teeth, shifts, limits=limits)
    r = pairs(module=2, teeth=teeth, shifts=shifts, limits=limits, top=None, progress=False)
    assert r.examined == 7 * 7 * 6 * 6
    got = {(int(t["z1"]), int(t["z2"]), round(float(t["x1"]), 9), round(float(t["x2"]), 9)): t
           for t in r.table}  # fmt: skip
    assert set(got) == set(brute) and r.feasible == len(brute) > 100
    for key, report in brute.items():
        row = got[key]
        for name, f in report.items():
            assert row[_column(name)] == pytest.approx(f.margin, abs=1e-9), (key, name)
    # the result's own pair view gives the same margins
    p = r.pair(0)
    assert p.check(1.2, 0.25)["tip_interference"].margin == pytest.approx(
        r["tip_interference"][0], abs=1e-9
    )


def test_joldasbekov_pair_is_found():
    # Joldasbekov §5.4, row 3: z 12/28, x 0.3/0.2, m = 1: a_w = 20.46253, eps = 1.36264
    r = pairs(ratio=28 / 12, module=1, teeth=(10, 30), shifts=(0.0, 0.5, 0.1), top=None,
              progress=False)  # fmt: skip
    t = r.table
    hit = t[(t["z1"] == 12) & (t["z2"] == 28) & np.isclose(t["x1"], 0.3) & np.isclose(t["x2"], 0.2)]
    assert len(hit) == 1
    assert hit["center_distance"][0] == pytest.approx(20.46253, abs=5e-6)
    assert hit["contact_ratio"][0] == pytest.approx(1.36264, abs=5e-6)
    assert hit["working_pressure_angle"][0] == pytest.approx(23.29917, abs=5e-6)


def test_khk_pair_at_its_center_distance():
    # KHK: 12/24, m = 3, x1 = 0.6 at a = 56.4999 mm gives x2 = 0.36, alpha_w = 26.0886 deg
    r = pairs(ratio=2, center_distance=56.4999, module=3, teeth=(10, 30), shifts=(0.0, 1.0, 0.1),
              split="keep", top=None, progress=False)  # fmt: skip
    t = r.table
    hit = t[(t["z1"] == 12) & np.isclose(t["x1"], 0.6)]
    assert len(hit) == 1 and int(hit["z2"][0]) == 24
    assert hit["x2"][0] == pytest.approx(0.36, abs=1e-4)
    assert hit["center_distance"][0] == pytest.approx(56.4999, abs=1e-9)  # solved exactly
    assert hit["working_pressure_angle"][0] == pytest.approx(26.0886, abs=5e-5)
    # every row sits at the requested centre distance
    assert np.allclose(t["center_distance"], 56.4999, atol=1e-9)


def test_proportional_split_matches_at_center_distance():
    # independent route: GearPair.at_center_distance(..., split="proportional") per tooth pair
    r = pairs(ratio=2.5, center_distance=43.0, module=2, teeth=(8, 40), shifts=(-0.5, 1.0, 0.5),
              split="proportional", limits={"allow_undercut": True, "min_contact_ratio": 1.0},
              top=None, progress=False)  # fmt: skip
    assert len(r) > 0
    for row in r.table:
        p = GearPair.at_center_distance(Gear(int(row["z1"]), 2), Gear(int(row["z2"]), 2), 43.0,
                                        split="proportional")  # fmt: skip
        assert row["x1"] == pytest.approx(p.g1.profile_shift, abs=1e-12)
        assert row["x2"] == pytest.approx(p.g2.profile_shift, abs=1e-12)


@pytest.mark.parametrize("internal", [False, True])
def test_equal_sliding_split_matches_at_center_distance(internal):
    # independent route: GearPair.at_center_distance(..., split="equal_sliding") (Brent per
    # pair on the scalar path of contact); the search's rows and margins agree with it
    a, teeth = (43.0, (12, 40)) if not internal else (31.0, (14, 70))
    # a ring's x2 (DIN 3960 sign) lies near -1.3 here: the range reaches it
    shifts = (-1.0, 1.5, 0.5) if not internal else (-1.5, 1.5, 0.5)
    r = pairs(center_distance=a, module=2, teeth=teeth, shifts=shifts,
              split="equal_sliding", internal=internal, top=None, progress=False,
              limits={"allow_undercut": True, "min_contact_ratio": 1.0})  # fmt: skip
    assert len(r) > 3
    for row in r.table[:12]:
        g2 = Gear(int(row["z2"]), 2, internal=internal)
        p = GearPair.at_center_distance(Gear(int(row["z1"]), 2), g2, a, split="equal_sliding")
        assert row["x1"] == pytest.approx(p.g1.profile_shift, abs=1e-9)
        assert row["x2"] == pytest.approx(p.g2.profile_shift, abs=1e-9)
        margins = p.check(1.0)
        assert row["tip_interference"] == pytest.approx(margins["tip_interference"].margin,
                                                        abs=1e-8)  # fmt: skip


def _assert_same_table(a, b):
    """Two result tables hold the same rows: integer fields exactly, float fields to 1e-12
    relative (chunks of other lengths run numpy's SIMD loops over other tails, which may round
    the last bit differently)."""
    assert a.dtype == b.dtype and a.shape == b.shape
    for name in a.dtype.names:
        if np.issubdtype(a.dtype[name], np.floating):
            np.testing.assert_allclose(a[name], b[name], rtol=1e-12, atol=1e-12, err_msg=name)
        else:
            np.testing.assert_array_equal(a[name], b[name], err_msg=name)


def test_chunk_size_and_threads_do_not_change_the_answer():
    kw = dict(ratio=3.2, module=[2, 2.5], teeth=(12, 60), shifts=(-0.4, 1.0, 0.1),
              progress=False)  # fmt: skip
    a = pairs(**kw, top=15, chunk_size=1 << 16, threads=1)
    b = pairs(**kw, top=15, chunk_size=97, threads=2)
    assert a.chunks == 1 and b.chunks > 20
    _assert_same_table(a.table, b.table)
    assert a.feasible == b.feasible
    # a Pareto front of two objectives, too
    c = pairs(**kw, objective=("sliding", "-contact_ratio"), top=None, chunk_size=1 << 16)
    d = pairs(**kw, objective=("sliding", "-contact_ratio"), top=None, chunk_size=131)
    _assert_same_table(c.table, d.table)
    assert len(c) > 3


def test_top_k_is_the_head_of_the_full_ranking():
    # brute force on the result itself: every feasible row, sorted, starts with the top 10
    kw = dict(ratio=3.2, module=2, teeth=(12, 60), shifts=(-0.4, 1.0, 0.1), progress=False)
    every = pairs(**kw, top=None, objective="sliding")
    best = pairs(**kw, top=10, objective="sliding", chunk_size=50)
    _assert_same_table(every.table[:10], best.table)
    assert np.all(np.diff(every["sliding"]) >= 0)


def test_pareto_front_by_brute_force():
    # independent route: the O(n^2) definition on all feasible rows
    kw = dict(ratio=2.0, module=2, teeth=(14, 40), shifts=(-0.2, 0.8, 0.2), progress=False)
    every = pairs(**kw, top=None)
    o = np.stack([every["sliding"], -every["contact_ratio"], every["center_distance"]], axis=1)
    dominated = [bool(np.any(np.all(o <= v, axis=1) & np.any(o < v, axis=1))) for v in o]
    expected = {tuple(r) for r, d in zip(every.table[["z1", "z2", "x1", "x2"]].tolist(),
                                         dominated, strict=True) if not d}  # fmt: skip
    front = pairs(**kw, objective=("sliding", "-contact_ratio", "center_distance"), top=None,
                  chunk_size=200)  # fmt: skip
    assert {tuple(r) for r in front.table[["z1", "z2", "x1", "x2"]].tolist()} == expected


def test_local_and_dask_cluster_agree():
    from distributed import Client, LocalCluster

    kw = dict(ratio=3.2, module=[2, 3], teeth=(12, 50), shifts=(-0.4, 1.0, 0.1),
              progress=False, top=12, chunk_size=200)  # fmt: skip
    local = pairs(**kw, client=False)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                      dashboard_address=None) as cluster, Client(cluster) as client:  # fmt: skip
        remote = pairs(**kw, client=client)
        active = pairs(**kw)  # the active client is picked up
        assert active.chunks == remote.chunks
    assert remote.chunks > 2
    _assert_same_table(local.table, remote.table)
    assert local.feasible == remote.feasible
    _assert_same_table(local.table, active.table)


def test_a_client_that_is_not_the_default_runs_both_searches():
    # a Client(..., set_as_default=False) (one of several, say) raised "No clients found" from
    # dask's wait() before: the results are awaited on the client given
    from distributed import Client, LocalCluster

    from trains import synthesize_gearbox

    kw = dict(ratio=3.2, module=[2, 3], teeth=(12, 40), shifts=(-0.4, 1.0, 0.2), progress=False,
              top=5, chunk_size=200)  # fmt: skip
    box = dict(ratio=12, stages=2, z_max=80, top=3, progress=False)
    with LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                      dashboard_address=None) as cluster, Client(
                          cluster, set_as_default=False) as client:  # fmt: skip
        remote = pairs(**kw, client=client)
        boxes = synthesize_gearbox(**box, client=client)
    _assert_same_table(pairs(**kw, client=False).table, remote.table)
    assert [str(g) for g in boxes] == [str(g) for g in synthesize_gearbox(**box, client=False)]
    assert len(boxes) == 3


def test_progress_callback_and_off(capsys):
    seen = []
    r = pairs(ratio=2, module=2, teeth=(14, 40), chunk_size=500, progress=lambda d, n: seen.append(
        (d, n)))  # fmt: skip
    # one call per chunk, counting candidates
    assert seen[-1] == (r.examined, r.examined) and len(seen) == r.chunks
    assert [d for d, _ in seen] == sorted(d for d, _ in seen)
    pairs(ratio=2, module=2, teeth=(14, 40), progress=False)
    assert capsys.readouterr().err == ""


def test_oversized_local_search_is_refused_before_work():
    # 4 modules x 496^2 tooth pairs x 1501^2 shift pairs = 2,217,097,176,064 candidates
    with pytest.raises(GearError, match=r"has 2,217,097,176,064 candidates.*days.*client="):
        pairs(module=[1, 2, 3, 4], teeth=(5, 500), shifts=(-1.0, 2.0, 0.002))
    # a limit can be raised
    with pytest.raises(GearError, match=r"max_seconds = 0\.001"):
        pairs(ratio=2, module=2, teeth=(14, 400), max_seconds=0.001)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"module": -1}, "module = -1"),
        ({"helix": 70}, "helix = 70"),
        ({"teeth": (0, 10)}, "teeth"),
        ({"objective": "speed"}, "objective 'speed' is not a column"),
        ({"top": 0}, "top = 0"),
        ({"split": "half"}, "split = 'half'"),
        ({"shifts": (1.0, 0.0, 0.1)}, "shifts"),
        ({"chunk_size": 0}, "chunk_size = 0"),
        ({"limits": {"min_contact_ratio": -1}}, "min_contact_ratio"),
        ({"client": 3}, "client must be"),
    ],
)
def test_bad_input_is_refused(kwargs, match):
    with pytest.raises(GearError, match=match):
        pairs(**{"ratio": 2, "progress": False, **kwargs})


def test_exports(tmp_path):
    r = pairs(ratio=2, module=2, teeth=(14, 30), top=5, progress=False)
    assert isinstance(r, SearchResult) and "z1" in r.columns and len(str(r).splitlines()) == 7
    try:
        import pandas  # noqa: F401
    except ImportError:
        with pytest.raises(GearError, match="pip install pandas"):
            r.to_pandas()
    else:
        assert list(r.to_pandas()["z1"]) == list(r["z1"])
    import pyarrow.parquet as pq  # the parquet extra, part of the test extra

    r.to_parquet(tmp_path / "r.parquet")
    assert pq.read_table(tmp_path / "r.parquet").column("z1").to_pylist() == list(r["z1"])


@settings(max_examples=12, deadline=None)
@given(
    teeth=st.lists(st.integers(8, 70), min_size=2, max_size=4, unique=True),
    shifts=st.lists(
        st.sampled_from([-0.5, -0.2, 0.0, 0.1, 0.4, 0.7, 1.0]), min_size=1, max_size=3, unique=True
    ),
    chunk=st.integers(1, 64),
)
def test_random_small_spaces_agree_with_brute_force(teeth, shifts, chunk):
    brute = _feasible_by_brute_force(teeth, shifts)
    r = pairs(module=2, teeth=teeth, shifts=shifts, top=None, chunk_size=chunk, progress=False)
    got = {(int(t["z1"]), int(t["z2"]), round(float(t["x1"]), 9), round(float(t["x2"]), 9))
           for t in r.table}  # fmt: skip
    assert got == set(brute)


def test_command_line(tmp_path, capsys):
    from trains.cli.app import main

    out = tmp_path / "pairs.csv"
    status = main(
        [
            "search",
            "pairs",
            "--ratio",
            "2",
            "--module",
            "2",
            "--teeth",
            "14",
            "40",
            "--objective",
            "sliding,-contact_ratio",
            "--top",
            "4",
            "-o",
            str(out),
        ]
    )
    text = capsys.readouterr().out
    assert status == 0 and "4 pairs of" in text
    rows = out.read_text().splitlines()
    assert rows[0].startswith("module,helix_angle,z1,z2,x1,x2") and len(rows) == 5
    # nothing feasible: exit 1; bad input and an oversized search: exit 2, one line on stderr
    assert (
        main(["search", "pairs", "--ratio", "2", "--teeth", "14", "16", "--min-contact-ratio", "3"])
        == 1
    )
    capsys.readouterr()
    assert main(["search", "pairs", "--teeth", "5", "500", "--shifts", "-1", "2", "0.001"]) == 2
    err = capsys.readouterr().err
    assert "candidates" in err and "--max-seconds" in err and len(err.strip().splitlines()) == 1
