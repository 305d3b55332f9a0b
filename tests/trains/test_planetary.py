"""Planetary stage: ratios, coaxiality, assembly, neighbour, placement (trains/planetary.py)."""

import math
from fractions import Fraction
from itertools import product
from math import gcd

import numpy as np
import pytest

from gears import Gear, GearError, GearPair
from trains import Planetary, TrainError
from trains.planetary.schemes import assembly_ticks, phasing_class, textbook_assembly


def brute_force_assembles(za, zb, zc, zd, k, sa, sb):
    """Exact phase search, independent of the gcd formula (lectures §7's method).

    Planet j sits at j/k turn. Rolling the planet by v turns in the carrier frame shifts the
    sun's tooth phase by -sa*zc*v... in teeth; a planet fits when some v makes both central
    gears' phases integers: z_a j/k - sa' z_c v and z_b j/k - sb' z_d v in Z. v is searched
    over the only candidates the sun condition allows, v = (z_a j/k - n)/z_c, n in 0..z_c k.
    """
    sign_a = 1 if sa == -1 else -1  # external sun: the sun turns against the planet
    sign_b = -1 if sb == +1 else 1  # internal ring: the ring turns with the planet
    for j in range(1, k):
        phi = Fraction(j, k)
        found = False
        for n in range(zc * k + 1):
            v = (za * phi - n) / (sign_a * zc)
            ring_phase = zb * phi - sign_b * zd * v
            if ring_phase.denominator == 1:
                found = True
                break
        if not found:
            return False
    return True


# --------------------------------------------------------------------------- ratios


def test_ozols_derived_ratios_and_train_agree():
    # Ozols derived case (7.7): 20/30/80, ring fixed: i_13^H = -4, i_1H = 5
    p = Planetary(20, 30, 80, n_planets=2, module=2)
    assert p.basic_ratio == -4
    assert p.ratio() == 5 and isinstance(p.ratio(), Fraction)
    # sun fixed: 1 - 1/i0 = 5/4; carrier fixed: i0 = -4 (standards.md §4)
    assert p.ratio(fixed="sun") == Fraction(5, 4)
    assert p.ratio(fixed="carrier") == -4
    assert p.ratio(fixed="ring", input="carrier", output="sun") == Fraction(1, 5)
    # lectures §2.3 [P] 683 (vector K1): w2 - wH = (w1 - wH)(-z1/z2) = (1 - 1/5)(-2/3)
    assert p.planet_speed() == {"planet": Fraction(-8, 15)}


def test_stepped_ratio_standards_example():
    # standards.md §4: compound planet 20/40/20/80, ring fixed: 1 + 80*40/(20*20) = 9
    p = Planetary(20, (40, 20), 80, n_planets=3, scheme="stepped")
    assert p.ratio() == 9


def test_david_ratio_exact():
    # Ozols Ex 7-4 (lectures §4.2 scheme C): z = 100, 101, 100, 99 gives i_1H = 1/10000 exactly
    p = Planetary(100, (101, 100), 99, n_planets=1, scheme="external")
    assert p.ratio() == Fraction(1, 10000)
    assert p.ratio(input="carrier", output="sun") == 10000


def test_efficiency_matches_kreines_formula():
    # standards.md §4 table: i0 = -4, eta0 = 0.97 gives eta_1H = 0.97600 and eta_H1 = 0.97586
    p = Planetary(20, 30, 80, n_planets=2)
    eta = math.sqrt(0.97)  # two meshes in series give eta0 = 0.97
    assert p.efficiency(mesh_efficiency=eta) == pytest.approx(0.976, abs=5e-6)
    assert p.efficiency(input="carrier", output="sun", mesh_efficiency=eta) == pytest.approx(
        0.97586, abs=5e-6
    )


def test_efficiency_self_locking_plus_gear():
    # Ozols Ex 14-3 / derived (14.26): the David stage driven from the sun is self-locking
    p = Planetary(100, (101, 100), 99, n_planets=1, scheme="external")
    eta = math.sqrt(0.98)  # eta_H = 0.98 over two meshes
    assert p.efficiency(mesh_efficiency=eta) < 0
    assert p.efficiency(input="carrier", output="sun", mesh_efficiency=eta) == pytest.approx(
        0.0049756, rel=1e-3
    )


# --------------------------------------------------------------------------- assembly


@pytest.mark.parametrize("k,ok", [(2, True), (3, False), (4, True), (5, True)])
def test_ozols_assembly_20_30_80(k, ok):
    # Ozols §21-13 derived case: (20 + 80)/k: k = 2, 4, 5 integer, k = 3 not
    p = Planetary(20, 30, 80, n_planets=k)
    assert p.assembly().exact is ok
    assert p.check()["assembly"].ok is ok


def test_ozols_neighbour_20_30_80_gives_k_2_and_4():
    # Ozols §21-13 derived case: sin(pi/k) > 32/50 holds for k = 2, 3, 4 only; with assembly
    # only k in {2, 4} pass both (zero clearance, the book's form)
    both = []
    for k in range(2, 8):
        r = Planetary(20, 30, 80, n_planets=k, clearance=0).check()
        if r["assembly"].ok and r["neighbour"].ok:
            both.append(k)
    assert both == [2, 4]
    assert Planetary(20, 30, 80, n_planets=2, clearance=0).max_planets == 4


def test_compound_planet_exact_accepts_textbook_rejects():
    # lectures §4.3 [D] counter-example: scheme B 26/70/21/117, k = 3: exact 8736/21 = 416,
    # textbook (26*16/3)(1 + 3p) never an integer
    p = Planetary(26, (70, 21), 117, n_planets=3, scheme="stepped")
    asm = p.assembly()
    assert asm.exact and not asm.textbook
    assert (26 * 21 + 117 * 70) % (3 * gcd(70, 21)) == 0  # the lecture's number, 416 * 21
    assert brute_force_assembles(26, 117, 70, 21, 3, -1, +1)
    report = p.check()
    assert report["assembly"].ok and report["assembly_textbook"].ok
    assert "rejects" in report["assembly_textbook"].message
    # and the placement finds a phase for every planet (independent: the float search)
    assert p.placement().residual < 1e-9


def test_gcd_form_equals_brute_force_random():
    # lectures §7: the gcd form against an exact phase search (here 300 random cases per sign)
    rng = np.random.default_rng(4)
    for _ in range(300):
        za, zb, zc, zd = (int(x) for x in rng.integers(10, 60, 4))
        k = int(rng.integers(2, 7))
        for scheme, sa, sb in (("stepped", -1, +1), ("external", -1, -1)):
            t = int(assembly_ticks(scheme, za, zc, zd, zb))
            assert (t % k == 0) == brute_force_assembles(za, zb, zc, zd, k, sa, sb), (
                scheme, za, zc, zd, zb, k,
            )  # fmt: skip


def test_textbook_form_never_accepts_what_exact_rejects():
    # lectures §7: the textbook form is sufficient only
    for za, zc, zd, k in product(range(17, 30), (30, 35, 42), (18, 21), (2, 3, 4)):
        zb = za + zc + zd
        p = Planetary(za, (zc, zd), zb, n_planets=k, scheme="stepped")
        a = p.assembly()
        assert not (a.textbook and not a.exact)


def test_assembly_integer_not_float():
    # standards.md §6 item 9: (19 + 80)/4 = 24.75 must fail cleanly, by integers
    p = Planetary(19, 30, 80, n_planets=4, scheme="simple")
    a = p.assembly()
    assert a.ticks == 99 and not a.exact
    assert a.nearest_counts == (3, 9)  # divisors of 99 around 4
    # the unequal spacing lies on the tick 360/99 and near equal spacing
    ticks = np.array(a.spacing) / (360 / 99)
    assert np.allclose(ticks, np.round(ticks))
    assert a.max_deviation <= 360 / 99 / 2 + 1e-12
    f = p.check()["assembly"]
    assert not f.ok and "3.6364 deg" in f.message and "3 or 9" in f.message
    assert not textbook_assembly(19, Fraction(99, 19), 4)


def test_phasing_classes():
    # standards.md §4 (drivetrainhub): z mod N = 0 in-phase, 1 or N-1 sequential, else counter
    assert phasing_class(108, 3) == "in-phase"
    assert phasing_class(80, 3) == "sequential"
    assert phasing_class(82, 5) == "counter-phase"
    assert Planetary(18, 45, 108, 3).phasing == {
        "sun-planet": "in-phase",
        "planet-ring": "in-phase",
    }


# --------------------------------------------------------------------------- neighbour


def test_course_example_18_45_108():
    # lectures §4.3 third-party course example: u = 7, k <= 3.73 so k = 3, assembly 126/3 = 42
    p = Planetary(18, 45, 108, n_planets=3, module=2, clearance=0)
    assert p.ratio() == 7
    assert p.assembly().ticks // 3 == 42
    bound = math.pi / math.asin((45 + 2) / (18 + 45))
    assert bound == pytest.approx(3.7307, abs=1e-4)  # lectures §4.3 [D]
    assert p.max_planets == 3
    assert Planetary(18, 45, 108, n_planets=4, clearance=0).check()["neighbour"].ok is False


def test_neighbour_margin_equals_direct_tip_circle_distance():
    # independent route: place the planets and measure the distance between tip circles
    sun = Gear(19, 3, profile_shift=0.3)
    planet = Gear(31, 3, profile_shift=0.1)
    # any ring; only a_w matters (KHK's x = 0.5, DIN 3960's -0.5)
    ring = Gear(81, 3, profile_shift=-(0.3 + 0.1 + 0.1), internal=True)
    p = Planetary(sun, planet, ring, n_planets=4, module=3)
    pair = GearPair(sun, planet)
    a = pair.center_distance
    tip = pair.tip_diameters[1]  # the planet's tip after tip shortening
    c1 = np.array([a, 0.0])
    c2 = a * np.array([math.cos(2 * math.pi / 4), math.sin(2 * math.pi / 4)])
    direct = np.linalg.norm(c1 - c2) - tip
    assert p.check()["neighbour"].margin == pytest.approx(direct - 0.5 * 3, abs=1e-9)
    assert pair.tip_alteration < 0  # the shortened tip is the one used


def test_stepped_neighbour_uses_larger_step():
    # lectures §4.3 item 4: max(d_a2, d_a2') for a double-row planet
    p = Planetary(18, (54, 18), 90, n_planets=3, scheme="stepped", clearance=0)
    a = (18 + 54) / 2
    assert p.check()["neighbour"].margin == pytest.approx(
        2 * a * math.sin(math.pi / 3) - (54 + 2), abs=1e-9
    )


# --------------------------------------------------------------------------- coaxiality


def test_coaxiality_zero_shift_is_tooth_count_condition():
    # Ozols §21-13: z1 + 2 z2 = z3; one tooth off is 0.5 module off
    assert Planetary(20, 30, 80, 2).check()["coaxiality"].ok
    f = Planetary(20, 30, 81, 2, module=2).check()["coaxiality"]
    assert not f.ok and f.margin == pytest.approx(0.01 - 1.0)


def test_coaxial_21_43_108_round_trip_through_gearpair():
    # lectures §4.3 / issue: planet 43 between sun 21 and ring 108 (21 + 86 = 107) made coaxial
    p = Planetary.coaxial(21, 43, 108, n_planets=3, module=2, center_distance=65.3)
    sp, pr = p.meshes["sun-planet"], p.meshes["planet-ring"]
    # round trip: rebuild each pair from its shifts alone; a_w must come back
    g = [Gear(21, 2, profile_shift=sp.g1.profile_shift),
         Gear(43, 2, profile_shift=sp.g2.profile_shift),
         Gear(43, 2, profile_shift=pr.g1.profile_shift),
         Gear(108, 2, profile_shift=pr.g2.profile_shift, internal=True)]  # fmt: skip
    a1 = GearPair(g[0], g[1]).center_distance
    a2 = GearPair(g[2], g[3]).center_distance
    assert a1 == pytest.approx(65.3, abs=1e-9) and a2 == pytest.approx(65.3, abs=1e-9)
    assert sp.g2.profile_shift == pr.g1.profile_shift  # one planet, one shift
    assert p.check()["coaxiality"].ok
    # zero shifts: not coaxial (0.5 module off)
    assert not Planetary(21, 43, 108, 3, module=2).check()["coaxiality"].ok


def test_coaxial_chooses_distance_that_passes():
    p = Planetary.coaxial(21, 43, 108, n_planets=3, module=1)
    r = p.check()
    assert r.ok, r.failed()
    assert r["assembly"].ok  # (21 + 108)/3 = 43


# --------------------------------------------------------------------------- placement


@pytest.mark.parametrize(
    "args,kw",
    [
        ((18, 45, 108, 3), {}),
        ((20, 30, 80, 4), {}),
        ((26, (70, 21), 117, 3), {"scheme": "stepped"}),
        ((100, (101, 100), 99, 1), {"scheme": "external"}),
        ((21, (20, 22), 83, 2), {"scheme": "internal"}),
    ],
)
def test_placement_meshes_in_phase(args, kw):
    # independent check of the placement: at each line of centres a tooth faces a space,
    # evaluated from the returned angles with the tooth-phase definition of Placement
    p = Planetary(*args, **kw)
    pl = p.placement()
    z1, zc, zd, z3 = p.teeth
    sun_int = p.scheme == "internal"
    ring_int = p.scheme != "external"
    for th, rot in zip(pl.planet_angles, pl.planet_rotations, strict=True):
        t, phi = th / 360, rot / 360
        p_sun = z1 * (t - pl.sun_rotation / 360)
        if sun_int:
            s = p_sun - zc * (t - phi)
        else:
            s = p_sun + zc * (t + 0.5 - phi)
        assert abs(s - 0.5 - round(s - 0.5)) < 1e-9
        p_ring = z3 * (t - pl.ring_rotation / 360)
        r = p_ring - zd * (t - phi) if ring_int else p_ring + zd * (t + 0.5 - phi)
        assert abs(r - 0.5 - round(r - 0.5)) < 1e-9


def test_placement_unequal_when_equal_fails():
    # Ozols §21-13 "avoided if satellite positions are adjustable": 20/30/80 with 3 planets
    pl = Planetary(20, 30, 80, 3).placement()
    assert pl.residual < 1e-9
    assert pl.planet_angles[1] == pytest.approx(118.8)  # 33 ticks of 3.6 deg


def test_double_planet_stage():
    # double-planet: i0 = +z3/z1, i_1H = 1 - z3/z1; assembly (z3 - z1)/k
    p = Planetary(18, (19, 21), 72, n_planets=3, scheme="double-planet")
    assert p.ratio() == -3
    r = p.check()
    assert r["coaxiality"].ok and r["assembly"].ok and r["neighbour"].ok
    assert p.placement().residual < 1e-9
    assert set(p.planet_speed()) == {"planet", "planet2"}


# --------------------------------------------------------------------------- report, errors


def test_report_contains_every_mesh_and_note():
    r = Planetary(18, 45, 108, 3, module=2).check()
    for name in ("coaxiality", "assembly", "assembly_textbook", "neighbour",
                 "redundant_constraints", "sun-planet.contact_ratio",
                 "planet-ring.involute_interference"):  # fmt: skip
        assert name in r
    assert r["redundant_constraints"].margin == 2  # q = k - 1 (Ozols §21-13)


@pytest.mark.parametrize(
    "kw,match",
    [
        ({"n_planets": 0}, "n_planets"),
        ({"scheme": "wolfrom"}, "scheme"),
        ({"sun": 18.5}, "whole number"),
        ({"planet": (40, 20)}, "stepped"),
        ({"ring": Gear(108, 1)}, "internal"),
        ({"module": -1}, "module"),
    ],
)
def test_errors_name_the_value(kw, match):
    args = {"sun": 18, "planet": 45, "ring": 108, "n_planets": 3} | kw
    with pytest.raises(TrainError, match=match):
        Planetary(**args)


def test_large_planet_count_is_finite():
    # stability: a very large planet count; neighbour fails with a finite margin
    p = Planetary(200, 20, 240, n_planets=440)
    r = p.check()
    assert r["assembly"].ok and not r["neighbour"].ok
    assert math.isfinite(r["neighbour"].margin)
    assert p.max_planets < 440


def test_figure_script_runs(tmp_path):
    # docs/make_planetary_figures.py makes the docs figure of the three conditions
    pytest.importorskip("matplotlib")
    import runpy

    mod = runpy.run_path(str(__import__("pathlib").Path(__file__).parents[2] / "docs"
                             / "make_planetary_figures.py"))  # fmt: skip
    (path,) = mod["main"](tmp_path)
    assert path.stat().st_size > 10_000


def test_planet_count_search_and_assembly_agree_with_brute_force():
    # issue 26: a stage of 10^7 planets never finished check() (a search over range(v) in the
    # assembly test, a scan over every count with an n x n distance matrix for the largest
    # count that fits). Brute force (the former linear scans) against the closed forms:
    # k p = -1 (mod v) has a solution exactly when gcd(k, v) = 1; the largest count is the
    # last n before the first that fails the neighbour gap
    from fractions import Fraction

    from trains.planetary.checks import NEIGHBOUR_TOLERANCE, max_planets, neighbour_gap
    from trains.planetary.schemes import textbook_assembly

    for z_a in (12, 17, 20, 31):
        for num, den in ((1, 3), (7, 2), (-11, 5), (9, 4)):
            for k in range(1, 13):
                v = (Fraction(z_a) * abs(Fraction(num, den)) / k).denominator
                brute = any((1 + k * p) % v == 0 for p in range(v))
                assert textbook_assembly(z_a, Fraction(num, den), k) == brute
    stages = [Planetary(20, 30, 80, n_planets=3), Planetary(12, 60, 132, n_planets=3),
              Planetary(40, 10, 60, n_planets=5), Planetary(30, 5, 40, n_planets=2),
              Planetary(18, 20, 60, n_planets=3, scheme="double-planet")]  # fmt: skip
    for stage in stages:
        need = (stage.clearance - NEIGHBOUR_TOLERANCE) * stage.module
        n = 1
        while neighbour_gap(stage, n + 1) >= need:
            n += 1
        assert max_planets(stage) == n, stage


def test_ten_million_planets_are_refused_at_once():
    import time

    t0 = time.perf_counter()
    with pytest.raises(
        TrainError, match=r"n_planets = 10000000; valid is an integer 1 \.\.\. 10000"
    ):
        Planetary(20, 30, 80, n_planets=10**7)
    with pytest.raises(TrainError, match=r"module = 1\.000e\+400"):
        Planetary(20, 30, 80, n_planets=3, module=10**400)
    assert time.perf_counter() - t0 < 1.0  # s


def test_coaxial_solves_the_split_for_the_whole_grid_as_one_pair_would():
    # issue 26: Planetary.coaxial(96, 5, 103, 1, 0.1) took 11-25 s, one equal-sliding solve and
    # one reachable-range search per candidate centre distance. The grid is now solved at once;
    # each sun shift must be the one GearPair.at_center_distance finds alone (the scalar route)
    import numpy as np

    from trains.planetary.shifts import _equal_sliding_suns

    sun, planet = Gear(96, 0.1), Gear(5, 0.1)
    grid = np.array([4.9, 4.96, 5.0, 5.04, 5.1, 7.0])  # mm; 7.0 is beyond the reachable range
    x = _equal_sliding_suns(sun, planet, grid)
    for a, xs in zip(grid, x, strict=True):
        try:
            alone = GearPair.at_center_distance(sun, planet, float(a)).g1.profile_shift
        except GearError:
            assert xs is None or not math.isfinite(xs)
            continue
        assert xs == pytest.approx(alone, abs=1e-12)


def test_a_failing_stage_is_drawn_only_when_asked(tmp_path):
    # issue 26 (as for the differential): 5 planets of 30 teeth around a 20-tooth sun collide
    # (spacing 2 a sin 36 deg = 58.8 mm < their tip diameter 64 mm, a = 50 mm); the scene drew
    # them without a word. Measured: the planets' outlines overlap (shapely area)
    stage = Planetary(20, 30, 80, n_planets=5)
    assert stage.check().failed() == ["neighbour"]
    with pytest.raises(TrainError, match=r"fails its checks \(neighbour.*check=False"):
        stage.scene(tolerance=0.1)
    with pytest.raises(TrainError, match=r"neighbour.*check=False"):
        stage.animate(tmp_path / "s.gif", frames=2, tolerance=0.1)
    o = stage.outlines(tolerance=0.05)
    assert o["planet1"].intersection(o["planet2"]).area > 1.0  # mm^2
    sc = stage.scene(tolerance=0.1, check=False)
    assert len(sc.graph.nodes_geometry) == 7
