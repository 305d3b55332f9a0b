"""gears.search.engine.pairs under a load (issue 20): rated candidates against brute force.

Reference values: brute force, an independent route: ``GearPair(...).check()`` and
``GearPair(...).rating(...)`` (the one-pair path of ISO 6336 method B) on every candidate of a
small space; the O(n^2) definition of a Pareto front; ``gears.rating.sizing.pair_volume`` against
the
pitch cylinders by hand.
"""

from __future__ import annotations

import functools
import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import Gear, GearError, GearPair
from gears.search.engine import estimate, pairs

TEETH = [14, 17, 21, 26, 33, 41]
SHIFTS = [-0.2, 0.1, 0.4, 0.7]
WIDTHS = [8.0, 14.0, 24.0]
LOAD = dict(torque=60.0, speed=1500.0, life=20000.0, quality=7)
MIN = {"pitting": 1.1, "bending": 1.5}
SPACE = dict(module=2, teeth=TEETH, shifts=SHIFTS, face_width=WIDTHS, min_safety=MIN,
             progress=False, **LOAD)  # fmt: skip


@functools.cache
def _brute_force():
    """{(z1, z2, x1, x2, b): (S_H1, S_H2, S_F1, S_F2)} of every candidate whose GearPair.check()
    holds and whose GearPair.rating() meets the minimum safeties: 6 x 6 x 4 x 4 x 3 = 1728."""
    out = {}
    for z1, z2, x1, x2 in itertools.product(TEETH, TEETH, SHIFTS, SHIFTS):
        try:
            pair = GearPair(Gear(z1, 2, profile_shift=x1), Gear(z2, 2, profile_shift=x2))
            ok = pair.check(1.1, 0.2).ok
        except GearError:  # no working pressure angle: not a candidate
            continue
        if not ok:
            continue
        for b in WIDTHS:
            try:
                r = pair.rating(60.0, 1500.0, face_width=b, life=20000.0, quality=7)
            except GearError:  # no rating exists (e.g. q_s outside method B's range)
                continue
            s = (*r.safety_pitting, *r.safety_bending)
            if min(s[:2]) >= MIN["pitting"] and min(s[2:]) >= MIN["bending"]:
                out[(z1, z2, round(x1, 9), round(x2, 9), b)] = s
    return out


def _key(row):
    return (int(row["z1"]), int(row["z2"]), round(float(row["x1"]), 9),
            round(float(row["x2"]), 9), float(row["face_width"]))  # fmt: skip


def test_feasible_set_and_safeties_equal_brute_force():
    brute = _brute_force()
    r = pairs(**SPACE, smallest_width=False, top=None)
    assert r.examined == 6 * 6 * 4 * 4 * 3
    got = {_key(t): t for t in r.table}
    assert set(got) == set(brute) and r.feasible == len(brute) > 100
    for key, safeties in brute.items():
        row = got[key]
        for name, want in zip(("S_H1", "S_H2", "S_F1", "S_F2"), safeties, strict=True):
            assert row[name] == pytest.approx(want, rel=1e-9, abs=1e-9), (key, name)
        assert row["S_H"] == pytest.approx(min(safeties[:2]), rel=1e-12)
    # the search's rejects: some geometry-feasible candidates fail the load, so it filtered
    assert len(pairs(module=2, teeth=TEETH, shifts=SHIFTS, top=None, progress=False)) * 3 > len(
        brute
    )


def test_smallest_width_is_the_brute_force_minimum():
    brute = _brute_force()
    smallest = {}
    for z1, z2, x1, x2, b in brute:
        smallest[(z1, z2, x1, x2)] = min(b, smallest.get((z1, z2, x1, x2), math.inf))
    r = pairs(**SPACE, top=None)
    got = {_key(t)[:4]: float(t["face_width"]) for t in r.table}
    assert got == smallest
    assert r.feasible == len(smallest)


def test_every_row_rated_on_its_own_meets_the_minimums():
    r = pairs(ratio=2.5, module=[2, 2.5], teeth=(15, 60), shifts=(0.0, 0.6, 0.3),
              face_width=(10, 30, 5), min_safety=MIN, objective=("volume", "-S_H"), top=None,
              progress=False, **LOAD)  # fmt: skip
    assert len(r) > 3
    for i in range(len(r)):
        rating = r.rating(i)  # pair(i).rating(...) at the row's face width
        assert min(rating.safety_pitting) >= MIN["pitting"]
        assert min(rating.safety_bending) >= MIN["bending"]
        assert rating.safety_pitting[0] == pytest.approx(r["S_H1"][i], rel=1e-9)
        assert rating.safety_bending[1] == pytest.approx(r["S_F2"][i], rel=1e-9)
        assert r.pair(i).g1.face_width == r["face_width"][i]


def test_internal_pairs_rated_by_the_standard_route():
    # the ring's root by ISO 6336-3's rack approximation, as GearPair.rating(root="standard")
    r = pairs(teeth=(18, 80), ratio=3.5, ratio_tolerance=0.05, module=1.5, internal=True,
              shifts=(0.0, 0.5, 0.25), torque=20, speed=1000, face_width=[10, 20], top=6,
              progress=False)  # fmt: skip
    assert len(r) == 6
    for i in range(len(r)):
        p = r.pair(i)
        assert p.internal
        rating = p.rating(20, 1000, root="standard")
        assert rating.safety_pitting == pytest.approx((r["S_H1"][i], r["S_H2"][i]), rel=1e-9)
        assert rating.safety_bending == pytest.approx((r["S_F1"][i], r["S_F2"][i]), rel=1e-9)


def test_volume_and_mass_columns():
    # pitch cylinders by hand: pi/4 b (d1^2 + d2^2), d = z m; steel 7.83e-6 kg/mm^3
    r = pairs(ratio=2, module=2, teeth=(20, 40), shifts=0.0, face_width=[12.0], top=None,
              progress=False)  # fmt: skip
    row = r.table[r.table["z1"] == 20][0]
    v = math.pi / 4 * 12 * (40.0**2 + 80.0**2)
    assert row["volume"] == pytest.approx(v, rel=1e-12)
    assert row["mass"] == pytest.approx(7.83e-6 * v, rel=1e-12)
    assert np.all(np.diff(r["volume"]) >= 0)  # objective "volume" by default with a width


def test_rated_objectives_rank_and_front_by_brute_force():
    every = pairs(**SPACE, smallest_width=False, top=None, objective="mass")
    assert np.all(np.diff(every["mass"]) >= 0)
    best = pairs(**SPACE, smallest_width=False, top=7, objective="-S_F", chunk_size=50)
    order = np.lexsort((-every["S_F"],))
    np.testing.assert_allclose(best["S_F"], every["S_F"][order][:7], rtol=1e-12)
    o = np.stack([every["volume"], -every["S_H"]], axis=1)
    dominated = [bool(np.any(np.all(o <= v, axis=1) & np.any(o < v, axis=1))) for v in o]
    expected = {_key(t) for t, d in zip(every.table, dominated, strict=True) if not d}
    front = pairs(**SPACE, smallest_width=False, top=None, objective=("volume", "-S_H"),
                  chunk_size=97)  # fmt: skip
    assert {_key(t) for t in front.table} == expected and len(expected) > 2


def test_chunks_threads_and_dask_give_the_same_rated_table():
    from distributed import Client, LocalCluster

    from tests.gears.test_search import _assert_same_table

    kw = dict(SPACE, teeth=(14, 45), shifts=(-0.2, 0.8, 0.25), top=10)
    a = pairs(**kw, threads=1, chunk_size=1 << 16)
    b = pairs(**kw, threads=2, chunk_size=997)
    _assert_same_table(a.table, b.table)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                      dashboard_address=None) as cluster, Client(cluster) as client:  # fmt: skip
        c = pairs(**kw, client=client, chunk_size=997)
    _assert_same_table(a.table, c.table)
    assert a.feasible == b.feasible == c.feasible and c.chunks > 2


def test_dataset_written_by_the_chunks(tmp_path):
    import pyarrow.parquet as pq
    from distributed import Client, LocalCluster

    kw = dict(SPACE, top=None, chunk_size=100)
    whole = pairs(**kw)
    local = pairs(**kw, dataset=tmp_path / "local")
    assert len(local) == 0 and local.feasible == whole.feasible and local.dataset
    assert "written to" in str(local)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                      dashboard_address=None) as cluster, Client(cluster) as client:  # fmt: skip
        remote = pairs(**kw, client=client, dataset=tmp_path / "remote")
    for folder in ("local", "remote"):
        table = pq.read_table(tmp_path / folder)
        assert table.num_rows == whole.feasible
        got = sorted(zip(*(table.column(c).to_pylist() for c in ("z1", "z2", "x1", "x2")),
                         strict=True))  # fmt: skip
        want = sorted(zip(*(whole[c].tolist() for c in ("z1", "z2", "x1", "x2")), strict=True))
        assert got == want
    assert remote.feasible == whole.feasible
    with pytest.raises(GearError, match="already holds part files"):
        pairs(**kw, dataset=tmp_path / "local")
    with pytest.raises(GearError, match="needs top=None"):
        pairs(**dict(kw, top=5), dataset=tmp_path / "other")
    with pytest.raises(GearError, match="names a file"):
        pairs(**kw, dataset=tmp_path / "rows.parquet")


def test_estimate_counts_the_candidates():
    kw = dict(SPACE, teeth=(14, 45), chunk_size=500)
    e = estimate(**kw)
    r = pairs(**kw)
    assert e.candidates == r.examined and e.chunks == r.chunks
    assert e.rate > 0 and e.sampled > 0 and e.local_seconds > 0
    assert e.worker_seconds >= e.local_seconds
    assert "candidates" in str(e) and "Dask" in str(e)
    with pytest.raises(GearError, match="torque = -5"):
        estimate(**dict(kw, torque=-5))


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"torque": -1}, "torque = -1"),
        ({"torque": float("nan")}, "torque = nan"),
        ({"speed": 0}, "speed = 0"),
        ({"speed": None}, "needs speed="),
        ({"face_width": None}, "needs face_width="),
        ({"face_width": [10, -2]}, "face_width = -2"),
        ({"face_width": (10, 5, 1)}, "face_width"),
        ({"min_safety": {"pitting": -1}}, r"min_safety\['pitting'\] = -1"),
        ({"min_safety": {"wear": 1}}, "'wear'"),
        ({"min_safety": 1.4}, "min_safety = 1.4"),
        ({"life": 0}, "life = 0"),
        ({"quality": 13}, "quality"),
        ({"K_v": -1}, "K_v"),
        ({"flux": 3}, "unknown rating option 'flux'"),
        ({"root": "measured"}, "root = 'measured'"),
        ({"material": "brass"}, "brass"),
        ({"objective": "-S_X"}, "'-S_X' is not a column"),
        ({"smallest_width": "yes"}, "smallest_width"),
        # GearPair.rating takes these as one number each; a pair of them broadcast against the
        # candidates and raised numpy's ValueError before (found by the gearbox-loss work)
        ({"roughness": (0.8, 1.2)}, r"roughness = \(0.8, 1.2\); valid is one number"),
        ({"tip_relief": [0.01, 0.02]}, r"tip_relief = \[0.01, 0.02\]; valid is one number"),
        ({"root_roughness": (1, 2)}, r"root_roughness = \(1, 2\); valid is one number"),
    ],
)
def test_bad_load_input_is_refused(kwargs, match):
    with pytest.raises(GearError, match=match):
        pairs(**{**SPACE, "teeth": (14, 20), **kwargs})


def test_load_options_need_a_torque():
    with pytest.raises(GearError, match="give torque="):
        pairs(ratio=2, module=2, speed=1500, progress=False)
    with pytest.raises(GearError, match="give torque="):
        pairs(ratio=2, module=2, quality=6, progress=False)
    with pytest.raises(GearError, match="needs torque="):
        pairs(ratio=2, module=2, face_width=10, objective="-S_H", progress=False)
    with pytest.raises(GearError, match="needs face_width="):
        pairs(ratio=2, module=2, objective="volume", progress=False)


@settings(max_examples=15, deadline=None)
@given(
    torque=st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-5, 500)),
    speed=st.one_of(st.floats(-10, 1e5), st.integers(-5, 5000)),
    pitting=st.floats(-1, 3),
    width=st.one_of(st.floats(-5, 60), st.lists(st.floats(0.5, 60), min_size=1, max_size=3)),
)
def test_any_load_gives_finite_rows_or_a_named_error(torque, speed, pitting, width):
    try:
        r = pairs(ratio=2, module=2, teeth=(16, 40), shifts=(0.0, 0.5, 0.5), torque=torque,
                  speed=speed, face_width=width, min_safety={"pitting": pitting}, top=5,
                  progress=False)  # fmt: skip
    except GearError as exc:
        text = str(exc)
        assert any(name in text for name in ("torque", "speed", "face_width", "min_safety"))
        return
    for name in ("S_H1", "S_H2", "S_F1", "S_F2", "volume", "mass", "face_width"):
        assert np.all(np.isfinite(r[name]))
    assert np.all(r["S_H"] >= pitting)


def test_command_line_rated_search_estimate_and_dataset(tmp_path, capsys):
    from trains.cli.app import main

    args = ["search", "pairs", "--ratio", "3", "--module", "2", "--teeth", "14", "60",
            "--shifts", "0", "0.6", "0.2", "--torque", "60", "--speed", "1500",
            "--face-width", "10:30:5", "--min-pitting", "1.1", "--min-bending", "1.5"]  # fmt: skip
    out = tmp_path / "rows.csv"
    assert main([*args, "--top", "3", "-o", str(out)]) == 0
    text = capsys.readouterr().out
    want = pairs(ratio=3, module=2, teeth=(14, 60), shifts=(0.0, 0.6, 0.2), torque=60,
                 speed=1500, face_width=[10, 15, 20, 25, 30], min_safety=MIN, top=3,
                 progress=False)  # fmt: skip
    assert "S_H" in text and f"of {want.feasible} feasible" in text
    rows = out.read_text().splitlines()
    head = rows[0].split(",")
    assert len(rows) == 4 and "S_H1" in head and "face_width" in head
    first = dict(zip(head, rows[1].split(","), strict=True))
    assert float(first["S_H1"]) == pytest.approx(want["S_H1"][0], rel=1e-12)
    assert main([*args, "--estimate"]) == 0
    assert f"{want.examined:,} candidates" in capsys.readouterr().out
    folder = tmp_path / "every"
    assert main([*args, "--all", "-o", f"{folder}/"]) == 0
    assert f"{want.feasible} feasible pairs" in capsys.readouterr().out
    assert any(folder.glob("part-*.parquet"))
    # a rating option without --torque, --torque without --face-width: exit 2, named
    assert main(["search", "pairs", "--ratio", "3", "--quality", "5"]) == 2
    assert "--quality" in capsys.readouterr().err
    assert main(["search", "pairs", "--ratio", "3", "--torque", "5", "--speed", "9"]) == 2
    assert "--face-width" in capsys.readouterr().err


def test_figure_script_runs(tmp_path):
    # docs/make_search_figures.py draws the docs figure (safety against volume, its fronts)
    pytest.importorskip("matplotlib")
    import pathlib
    import runpy

    root = pathlib.Path(__file__).resolve().parents[2]
    from matplotlib.figure import Figure

    titles = []
    save = Figure.savefig

    def savefig(fig, *args, **kwargs):  # what the saved figure says it shows
        titles.append(fig._suptitle.get_text() if fig._suptitle else "")
        return save(fig, *args, **kwargs)

    mod = runpy.run_path(str(root / "docs" / "make_search_figures.py"))
    Figure.savefig = savefig
    try:
        (path,) = mod["main"](tmp_path)
    finally:
        Figure.savefig = save
    assert path.name == "search_load_front.png" and path.stat().st_size > 10_000
    # the axes are safety (y) against volume (x): the title says so (it said "material")
    assert titles and titles[0].endswith("safety against volume"), titles
