"""Slow work that waits for nothing the tests do starts in the background as soon as the tests
are collected, and runs beside the rest of the suite.

A test module that defines ``start_in_background(session)`` has it called once when collection
ends (with the collected items in ``session.items``: it starts only what its selected tests
need), and ``stop_in_background()`` when the session ends (a run stopped early, by ``-x`` or
Ctrl-C, leaves nothing behind). Two modules do: ``tests/test_site.py`` (the site build, a third of
the suite's time, in a process of its own) and ``tests/test_docs.py`` (every documentation block,
each in a process of its own). Their tests then wait for the result and check it as before; the
work and every check are the same, only the suite's other tests no longer wait for it.

``line_hausdorff``: shapely's Hausdorff distance of two lines, found through an index (the same
value, for the outlines compared at fine tolerances).
"""

from __future__ import annotations

import numpy as np
import pytest
import shapely


def _modules(session):
    seen = {}
    for item in session.items:
        module = getattr(item, "module", None)
        if module is not None:
            seen.setdefault(id(module), module)
    return list(seen.values())


def pytest_collection_finish(session):
    if session.config.option.collectonly:
        return
    for module in _modules(session):
        start = getattr(module, "start_in_background", None)
        if start is not None:
            start(session)


def pytest_sessionfinish(session):
    for module in _modules(session):
        stop = getattr(module, "stop_in_background", None)
        if stop is not None:
            stop()


def hausdorff(a, b) -> float:
    """shapely's Hausdorff distance of two lines (GEOS's discrete one: the largest distance from
    a vertex of either line to the other line), each vertex's nearest segment found through an
    STRtree: O(n log n), where GEOS compares every vertex with every segment (10^8 pairs for two
    tooth outlines at 1 um, 5 s; equal to shapely's value within 1e-15 mm on the tests' gears)."""

    def one_way(p, q):
        xy = shapely.get_coordinates(q)
        tree = shapely.STRtree(shapely.linestrings(np.stack([xy[:-1], xy[1:]], axis=1)))
        points = shapely.points(shapely.get_coordinates(p))
        _, d = tree.query_nearest(points, return_distance=True, all_matches=False)
        return float(d.max())

    for g in (a, b):
        if shapely.get_type_id(g) not in (1, 2):  # LineString, LinearRing: one chain of segments
            raise TypeError(f"hausdorff() takes lines, got {g.geom_type}")
    return max(one_way(a, b), one_way(b, a))


@pytest.fixture
def line_hausdorff():
    """:func:`hausdorff`, for the tests that compare two outlines' exteriors."""
    return hausdorff


def stage_products(target, z_max, modules, widths, torque, speed):
    """The brute force behind the gearbox searches' tests: every product of two single simple
    stages (``trains.synthesize``, each with its exact target ratio, 3 planets, suns from 17
    teeth), in both orders, each stage sized at its place for ``torque`` (N m) and ``speed``
    (rpm) on ``modules`` x ``widths``. Yields ``(a, i, d1, b, j, d2)``: the candidates, their
    rows and the sizing tables of stage 1 and 2, for every pair both of whose stages found a
    module; the tests apply their own checks and objectives."""
    import itertools
    from fractions import Fraction

    from gears.rating.sizing import load_case
    from trains import synthesize
    from trains.design.sizing import size_stages

    modules, widths = list(modules), list(widths)
    ratios = {Fraction(z1 + z3, z1) for z1 in range(17, z_max + 1)
              for z3 in range(z1 + 1, z_max + 1)}  # fmt: skip
    load = load_case(torque, speed)
    for r1 in sorted(ratios):
        r2 = target / r1
        if r2 not in ratios:
            continue
        s1 = synthesize(r1, 3, z_max=z_max, limit=10**6)
        s2 = synthesize(r2, 3, z_max=z_max, limit=10**6)
        if not (s1 and s2):
            continue
        sized = []
        for place, stages in ((1, s1), (r1, s2)):
            z = np.array([c.teeth for c in stages])
            num = np.array([c.ratio.numerator for c in stages])
            den = np.array([c.ratio.denominator for c in stages])
            sized.append(size_stages(load, "simple", *z.T, 3, num, den, torque * float(place),
                                     speed / float(place), modules, widths))  # fmt: skip
        d1, d2 = sized
        for (i, a), (j, b) in itertools.product(enumerate(s1), enumerate(s2)):
            if d1["module_index"][i] >= 0 and d2["module_index"][j] >= 0:
                yield a, i, d1, b, j, d2


@pytest.fixture
def gearbox_stage_products():
    """:func:`stage_products`, for the brute forces of the gearbox searches."""
    return stage_products


def worm_hoist_train(worm):
    """The hoist of examples/train_worm_hoist.py: motor -> ``worm`` (a ``gears.WormPair``) ->
    its wheel coupled to a 17/68 m 3 spur pinion -> the drum."""
    from gears import Gear
    from trains import Train

    t = Train()
    t.mesh("worm", "wheel", pair=worm)
    t.couple("wheel", "pinion")
    t.mesh("pinion", "drum", gears=(Gear(17, 3), Gear(68, 3)))
    return t


@pytest.fixture(scope="session")
def worm_hoist():
    """:func:`worm_hoist_train`, for the worm trains' tests (session-wide: hypothesis tests take
    it too)."""
    return worm_hoist_train
