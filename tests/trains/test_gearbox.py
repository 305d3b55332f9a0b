"""trains.synthesize_gearbox: multi-stage planetary gearboxes against brute force.

Reference values: brute force (an independent route): every product of single-stage
``synthesize`` results, each called with its own exact target ratio, ranked by the documented
objective and checked with ``Planetary.check()``; hand arithmetic stated at each test.
"""

from __future__ import annotations

import itertools
import math
from fractions import Fraction

import pytest

from trains import TrainError, synthesize, synthesize_gearbox


def _teeth_total(c):
    z1, z2, z2p, z3 = c.teeth
    return z1 + z2 + z3 if c.scheme == "simple" else z1 + z2 + z2p + z3


def _brute_two_stage(target, z_max, top):
    """Every (r1, r2) with r1 <= r2, r1 r2 = target, both single simple stages, ranked by the
    smallest largest ring, then the fewest teeth, then the stages; only fully checked stages."""
    # the stage ratios a simple stage can have here: 1 + z3/z1 (ring fixed) for z <= z_max
    ratios = {
        Fraction(z1 + z3, z1) for z1 in range(17, z_max + 1) for z3 in range(z1 + 1, z_max + 1)
    }
    found = []
    for r1 in sorted(ratios):
        r2 = target / r1
        if r2 < r1 or r2 not in ratios:
            continue
        s1 = synthesize(r1, 3, z_max=z_max, limit=10**6)  # exact-target mode, its own call
        s2 = synthesize(r2, 3, z_max=z_max, limit=10**6)
        for a, b in itertools.product(s1, s2):
            ring = max(a.teeth[3], b.teeth[3]) * 1.0
            ident = ((a.scheme, a.teeth, a.n_planets), (b.scheme, b.teeth, b.n_planets))
            key = (ring, _teeth_total(a) + _teeth_total(b), ident)
            found.append((key, a, b))
    found.sort(key=lambda t: t[0])
    out = []
    for key, a, b in found:
        if a.stage.check().ok and b.stage.check().ok:
            out.append((key[0], key[1], a.teeth, b.teeth))
        if len(out) == top:
            break
    return out


def test_two_stages_equal_the_brute_force_product():
    # independent route: products of separately synthesised single stages (see _brute_two_stage)
    got = synthesize_gearbox(12, stages=2, z_max=100, top=6, progress=False)
    expected = _brute_two_stage(Fraction(12), 100, 6)
    assert len(got) == 6
    assert [(g.ring, g.teeth, g.stages[0].teeth, g.stages[1].teeth) for g in got] == expected
    for g in got:
        assert g.ratio == 12 and g.ratio_error == 0.0
        assert math.prod(c.ratio for c in g.stages) == 12


def test_first_gearbox_by_hand():
    # hand arithmetic: 3 x 4 = 12 with 40/20/80 (1 + 80/40 = 3) and 21/21/63 (1 + 63/21 = 4),
    # both assembling with 3 planets ((40 + 80)/3 = 40, (21 + 63)/3 = 28), ring 80 m
    got = synthesize_gearbox(12, stages=2, z_max=100, top=20, progress=False)
    teeth = [tuple(c.teeth for c in g.stages) for g in got]
    assert ((40, 20, 20, 80), (21, 21, 21, 63)) in teeth
    rings = [g.ring for g in got]
    assert rings == sorted(rings)


def test_three_stages_and_stepped():
    # 37 is prime: no exact simple pair below z = 150 reaches it (brute force in the stage
    # sets), but stepped stages do; three stages multiply to the target exactly
    two = synthesize_gearbox(37, stages=2, z_max=150, progress=False, top=3)
    assert len(two) == 0 and two.ratio_tuples == 0
    mixed = synthesize_gearbox(37, stages=2, schemes=("simple", "stepped"), z_max=120, top=3,
                               progress=False)  # fmt: skip
    assert len(mixed) == 3 and all(g.ratio == 37 for g in mixed)
    assert all(c.stage.check().ok for g in mixed for c in g.stages)
    # 4 x 4 x 4 = 64: the same stage may serve three times, so the smallest ring is at most
    # that of the best single ratio-4 stage (synthesize's own ranking: smallest ring first)
    three = synthesize_gearbox(64, stages=3, z_max=100, top=3, progress=False)
    assert three and all(g.ratio == 64 and len(g.stages) == 3 for g in three)
    assert three[0].ring <= synthesize(4, 3, z_max=100)[0].teeth[3]


def test_tolerance_and_objectives():
    exact = synthesize_gearbox(37, stages=2, z_max=120, tolerance=0.002, top=5, progress=False)
    assert exact and all(abs(float(g.ratio) / 37 - 1) <= 0.002 for g in exact)
    fewest = synthesize_gearbox(12, stages=2, z_max=100, objective="teeth", top=5, progress=False)
    assert [g.teeth for g in fewest] == sorted(g.teeth for g in fewest)
    best_eta = synthesize_gearbox(12, stages=2, z_max=90, objective="efficiency", top=3,
                                  progress=False)  # fmt: skip
    etas = [g.efficiency for g in best_eta]
    assert etas == sorted(etas, reverse=True) and 0.9 < etas[0] < 1


def test_local_and_dask_cluster_agree():
    from distributed import Client, LocalCluster

    kw = dict(ratio=12, stages=2, schemes=("simple", "stepped"), z_max=80, top=5, progress=False)
    local = synthesize_gearbox(**kw, client=False)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                      dashboard_address=None) as cluster, Client(cluster) as client:  # fmt: skip
        remote = synthesize_gearbox(**kw, client=client)
    assert [str(g) for g in local] == [str(g) for g in remote] and len(local) == 5


def test_progress_and_table():
    seen = []
    got = synthesize_gearbox(12, 2, z_max=100, top=3, progress=lambda d, n: seen.append((d, n)))
    assert seen[-1][0] == seen[-1][1] and "ratio 12" in got.table()
    arr = got.to_array()
    assert list(arr["rank"]) == [1, 2, 3] and arr["1_z1"][0] == got[0].stages[0].teeth[0]


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"ratio": 0.5}, "ratio > 1"),
        ({"stages": 4}, "stages = 4"),
        ({"objective": "cost"}, "objective = 'cost'"),
        ({"top": 0}, "top = 0"),
        ({"tolerance": -1}, "tolerance"),
        ({"schemes": "warp"}, "warp"),
        ({"z_max": 0}, "z_max"),
    ],
)
def test_bad_input(kwargs, match):
    with pytest.raises(TrainError, match=match):
        synthesize_gearbox(**{"ratio": 12, "progress": False, **kwargs})


def test_command_line(capsys):
    from trains.cli.app import main

    assert main(["search", "gearbox", "--ratio", "12", "--z-max", "100", "--top", "3"]) == 0
    out = capsys.readouterr().out
    assert out.count("ratio 12 ") == 3
    assert main(["search", "gearbox", "--ratio", "37", "--z-max", "100"]) == 1  # none: exit 1
    capsys.readouterr()
    assert main(["search", "gearbox", "--ratio", "1/2"]) == 2
    assert "ratio > 1" in capsys.readouterr().err
