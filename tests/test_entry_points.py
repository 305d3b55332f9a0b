"""Every entry point holds (issue 17): each reproducer of the issue, as a test.

A reproducer ends in a finite answer or in the library's own error (GearError / TrainError,
ValueError subclasses) naming the value, within 5 s and 2 GB of this process (the issue's
bound; refusals come before the work). The hypothesis sweeps of every entry point are in
tests/test_properties.py. Sources: the issue's reproducers; the valid ranges and budgets are
those of gears.arguments and gears.budget.
"""

from __future__ import annotations

import math
import resource
import time

import numpy as np
import pytest
import shapely

from gears import BasicRack, Gear, GearError, GearPair, ShaperCutter, gear_margins, pair_margins
from gears.arguments import check_tolerance, min_tolerance
from gears.budget import BUDGETS, check_budget, fitting_tolerance
from trains import Planetary, TrainError

trimesh = pytest.importorskip("trimesh")

from gears.solid.mesh import gear_solid  # noqa: E402

SECONDS, BYTES = 5.0, 2 * 2**30


def bounded(fn):
    """fn() within the issue's bounds: its result, or the library error it raised."""
    t0 = time.perf_counter()
    try:
        out = fn()
    except (GearError, TrainError) as exc:
        out = exc
    assert time.perf_counter() - t0 < SECONDS
    assert resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024 < BYTES
    return out


def refused(fn, *words, exc=GearError):
    out = bounded(fn)
    assert isinstance(out, exc), out
    for w in words:
        assert w in str(out), (w, str(out))
    return str(out)


# --- 1. checks never raise for a pair the constructor accepts ------------------------------------
def test_check_of_a_marginally_undercut_pinion_reports_instead_of_raising():
    # issue: x = x_min - 1e-9 on a B rack made _form_lengths raise "undercut fillet does not
    # meet the involute". A hair inside the limit the fillet touches the involute at the base
    # circle (independent: at x = x_min the closed form gives d_Ff = d_b), so the form circle is
    # d_b, continuous with x_min, and every finding has a finite margin.
    B = BasicRack.iso53("B")
    g1 = Gear(7, 1, helix_angle=-13.248786, profile_shift=0.6115320105763605, rack=B)
    g2 = Gear(226, 1, helix_angle=13.248786, profile_shift=-0.5, rack=B)
    report = bounded(lambda: GearPair(g1, g2).check())
    assert all(math.isfinite(f.margin) for f in report.values())
    assert g1.form_diameter == pytest.approx(g1.base_diameter, rel=1e-9)
    assert report["g1.undercut"].margin == pytest.approx(-1e-9, abs=1e-12)


def test_shift_sums_that_leave_no_tooth_are_refused_by_the_constructor():
    # a large negative sum: DIN 3960's k = y - (x1 + x2) < 0 on both sides of zero; where it
    # would take the whole tooth the pair is refused at once, naming the limit (it used to be
    # accepted and raise in check()). Independent limit: the low end of center_distance_range.
    g1, g2 = Gear(200, 1, profile_shift=-4.5), Gear(300, 1, profile_shift=-4.5)
    low, _ = GearPair.center_distance_range(g1, g2)
    text = refused(lambda: GearPair(g1, g2), "x1 + x2 = -9", "too small", "valid is x1 + x2 >")
    least = float(text.rsplit("> ", 1)[1])
    ok = GearPair.at_center_distance(g1, g2, low * (1 + 1e-6), split="keep")
    assert ok.g1.profile_shift + ok.g2.profile_shift == pytest.approx(least, abs=2e-4)
    assert GearPair(g1, g2, tip_shortening=False).check() is not None
    refused(lambda: GearPair(Gear(8, 1, profile_shift=-1), Gear(9, 1, profile_shift=-1)),
            "no working pressure angle")  # fmt: skip


@pytest.mark.parametrize("shift", [-0.7, 0.0, 3.0, 6.4])
def test_at_center_distance_accepts_a_pairs_own_centre_distance(shift):
    # the range ends are roots found to 1e-12; a pair's own a_w near an end is still reached
    g1, g2 = Gear(12, 3, profile_shift=shift / 2), Gear(24, 3, profile_shift=shift / 2)
    p = GearPair(g1, g2)
    q = GearPair.at_center_distance(g1, g2, p.center_distance, split="keep")
    assert q.center_distance == pytest.approx(p.center_distance, rel=1e-12)


# --- 2. the vectorised margins equal check()'s findings -------------------------------------------
def test_gear_margins_re_angle_the_rack_like_gear():
    # issue: the undercut margin of z = 30 at 30 deg was 2.750 (the 20-deg rack's tip round)
    # against Gear's 2.555 (the round capped to fit the 30-deg tool: BasicRack.with_pressure_angle)
    g = Gear(30, 1, 30.0)
    m = gear_margins(30, 1, 0, 30.0, 0, False, BasicRack.iso53("A"))
    assert float(m.undercut) == pytest.approx(g.check()["undercut"].margin, rel=1e-12)
    assert float(m.undercut) == pytest.approx(2.555174761587831, rel=1e-12)


def test_margins_of_a_gear_a_hair_inside_the_undercut_limit_are_finite():
    # issue: Gear(77, 1, 29.471921, x = x_min - 1e-9): tip_interference NaN in pair_margins
    # against -2.25 in check(); now one vectorised form circle for both (d_Ff = d_b here)
    x = Gear(77, 1, 29.471921).min_profile_shift - 1e-9
    m = gear_margins(77, 1, x, 29.471921)
    g = Gear(77, 1, 29.471921, profile_shift=x)
    for name, f in g.check().items():
        assert float(getattr(m, name)) == pytest.approx(f.margin, rel=1e-9, abs=1e-12), name


def test_pair_margins_take_array_pressure_angles_and_scalars_give_arrays():
    p = pair_margins(17, 30, 1, pressure_angle=np.array([20.0, 25.0]))
    for name, v in p.findings().items():
        assert np.shape(v) == (2,), name
    for i, pa in enumerate((20.0, 25.0)):
        ref = GearPair(Gear(17, 1, pa), Gear(30, 1, pa)).check()
        for name, f in ref.items():
            assert float(p.findings()[name][i]) == pytest.approx(f.margin, rel=1e-9), name
    ok = pair_margins(17, np.arange(20, 80), 1).ok()  # raised: one margin stayed 0-d
    assert ok.shape == (60,)


# --- 3. foreign exceptions from the 3D, scene and animation calls -----------------------------
BOX = shapely.box(-1.0, -1.0, 1.0, 1.0)
PAIR = GearPair(Gear(12, 2), Gear(30, 2))
STAGE = Planetary(18, 45, 108, n_planets=3, module=2)
RING = Gear(60, 1, internal=True)


@pytest.mark.parametrize(
    ("call", "words"),
    [
        (lambda: gear_solid(BOX, 1, twist="abc"), ["twist", "'abc'"]),
        (lambda: gear_solid(BOX, 1, twist=1e300), ["twist", "budget"]),
        (lambda: gear_solid(BOX, 1, twist=math.nan), ["twist"]),
        (lambda: Gear(20, 1, helix_angle=20).mesh(face_width=1e300), ["face_width", "1e+300"]),
        (lambda: Gear(20, 1, helix_angle=20).mesh(face_width=1e20), ["face_width"]),
        (lambda: Gear(20, 1).mesh(10, bore="abc"), ["bore", "'abc'"]),
        (lambda: Gear(20, 1).mesh(face_width=5e-324), ["face_width", "5e-324"]),
        (lambda: Gear(20, 1).mesh(face_width="3"), ["face_width", "'3'"]),
        (lambda: Gear(20, 1).mesh(face_width=True), ["face_width", "True"]),
        (lambda: Gear(20, 1).mesh(10, tolerance="0.1"), ["tolerance", "'0.1'"]),
        (lambda: Gear(20, 1).mesh(10, tolerance=False), ["tolerance", "False"]),
        (lambda: Gear(20, 1).mesh(10, herringbone="no"), ["herringbone", "'no'"]),
        (lambda: gear_solid(BOX, 5e-324), ["face_width"]),
        (lambda: PAIR.scene(angle=None), ["angle", "None"]),
        (lambda: PAIR.scene(face_width="x"), ["face_width"]),
        (lambda: PAIR.scene(tolerance=math.inf), ["tolerance"]),
        (lambda: PAIR.scene(method="laser"), ["method", "'laser'"]),
        (  # a ring shift of 1.130071 in KHK's sign: DIN 3960's -1.130071
            lambda: Gear(
                6, 50, 14.5, 0, -1.130071, internal=True, rack=BasicRack.iso53("B")
            ).outline(0.05),
            ["z = 6"],
        ),
        # a bore on a ring and a rim on an external gear were silently ignored (the CLI refused)
        (lambda: RING.outline(0.05, bore=10), ["bore = 10", "external"]),
        (lambda: RING.mesh(5, tolerance=0.05, bore=10), ["bore = 10", "external"]),
        (lambda: Gear(20, 1).outline(0.05, rim=3), ["rim = 3", "external"]),
        (lambda: Gear(20, 1).outline(0.05, "rack", rim=3), ["rim = 3", "external"]),
        (lambda: Gear(20, 1).mesh(5, tolerance=0.05, rim=3), ["rim = 3", "external"]),
    ],
)
def test_3d_and_outline_calls_refuse_bad_input(call, words):
    refused(call, *words)


@pytest.mark.parametrize(
    ("call", "words"),
    [
        (lambda p: STAGE.scene(angle="x"), ["angle", "'x'"]),
        (lambda p: STAGE.scene(face_width=-1), ["face_width"]),
        (lambda p: STAGE.scene(herringbone=1), ["herringbone"]),
        (lambda p: STAGE.animate(p / "s.gif", turn=math.nan), ["turn", "nan"]),
        (lambda p: STAGE.animate(p / "s.gif", fps="x"), ["fps", "'x'"]),
        (lambda p: STAGE.animate(p / "s.gif", fps=1e300), ["fps"]),
        (lambda p: STAGE.animate(p / "missing" / "s.gif"), ["does not exist"]),
        (lambda p: STAGE.outlines(tolerance=None), ["tolerance"]),
    ],
)
def test_stage_scene_and_animation_refuse_bad_input(tmp_path, call, words):
    refused(lambda: call(tmp_path), *words, exc=TrainError)


@pytest.mark.parametrize(
    ("kwargs", "words"),
    [
        ({"turn": math.nan}, ["turn", "nan"]),
        ({"fps": "x"}, ["fps", "'x'"]),
        ({"fps": 0}, ["fps"]),
        ({"frames": 2.5}, ["frames"]),
        ({"tolerance": -1}, ["tolerance"]),
    ],
)
def test_pair_animation_refuses_bad_input_before_drawing(tmp_path, kwargs, words):
    refused(lambda: PAIR.animate(tmp_path / "p.gif", **kwargs), *words)
    assert not (tmp_path / "p.gif").exists()


def test_denormal_and_tiny_face_widths_give_a_solid_or_a_clear_error():
    # the smallest face width accepted (1e-6 of the outline's radius) is a real solid: finite
    # vertices, watertight, positive volume = area x width (independent: the prism formula)
    g = Gear(20, 1)
    r = g.tip_diameter / 2
    m = g.mesh(face_width=1.001e-6 * r, tolerance=0.05)
    assert np.all(np.isfinite(m.vertices)) and m.is_watertight
    assert m.volume == pytest.approx(g.outline(0.05).area * 1.001e-6 * r, rel=1e-9)
    for b in (5e-324, 1e-300, 0.99e-6 * r):
        refused(lambda b=b: g.mesh(face_width=b), "face_width")


# --- 5. accepted work is bounded -----------------------------------------------------------------
def test_a_fine_helical_mesh_is_refused_with_the_tolerance_that_fits():
    # issue: 35 s and 2.5 GB before; now refused at once with a tolerance inside the budget
    text = refused(lambda: Gear(20, 1, helix_angle=30).mesh(10, tolerance=1e-5), "mesh budget")
    fits = float(text.rsplit(">= ", 1)[1].split()[0])
    g = Gear(20, 1, helix_angle=30)
    twist = 2 * 10 * math.tan(math.radians(30)) / g.reference_diameter * 180 / math.pi
    assert g.solid_vertices(fits, twist) <= BUDGETS["mesh"] < g.solid_vertices(fits * 0.9, twist)


def test_a_sharp_five_tooth_shaper_simulation_is_refused_before_the_work():
    # issue: a 5-tooth cutter at 5e-5 mm passed 60 s and 5.9 GB (z = 30: 28 s, 1.4 GB here)
    cutter = ShaperCutter(5, addendum=1.0, tip_radius=0)
    for z in (30, 60):
        refused(
            lambda z=z: Gear(z, 1).outline(5e-5, method="shaper", cutter=cutter),
            "simulation budget",
            "use tolerance >=",
        )


def test_rack_outlines_at_tiny_modules_cost_what_they_cost_at_module_1():
    # issue: Gear(290, 0.0024, ...) rack outlines took over 75 s. A rack C tool whose tip
    # round's centre rolls on the pitch line (x = h_fP - rho = 1.0) stamps its fillet at one
    # position: the old rule asked for endless positions at any module. Scale invariance
    # (independent: the geometry is similar): the same outline at m = 0.0024 and m = 1 with
    # the tolerance scaled by the module.
    rack = BasicRack.iso53("C")
    small = bounded(lambda: Gear(290, 0.0024, profile_shift=1.0, rack=rack).outline(
        0.001, method="rack"))  # fmt: skip
    large = bounded(lambda: Gear(290, 1, profile_shift=1.0, rack=rack).outline(
        0.001 / 0.0024, method="rack"))  # fmt: skip
    assert isinstance(small, shapely.Polygon) and small.is_valid
    assert len(small.exterior.coords) == len(large.exterior.coords)
    assert small.area / 0.0024**2 == pytest.approx(large.area, rel=1e-9)


def test_a_fine_planetary_animation_is_refused_before_drawing(tmp_path):
    # issue: Planetary.animate at tolerance 1e-6 took 36 s
    refused(
        lambda: STAGE.animate(tmp_path / "s.gif", tolerance=1e-6),
        "animation budget",
        "tolerance >=",
        exc=TrainError,
    )
    assert not (tmp_path / "s.gif").exists()


def test_a_scene_is_budgeted_as_a_whole(tmp_path):
    # each solid alone may fit while the scene does not: the budget counts the distinct solids
    pair = GearPair(Gear(40, 1, helix_angle=30), Gear(80, 1, helix_angle=-30))
    each = [g.solid_vertices(2e-4, 60.0) for g in pair.mounted]
    assert all(n < BUDGETS["mesh"] for n in each) and sum(each) > BUDGETS["mesh"]
    twist = math.degrees(2 * 10 * math.tan(math.radians(30)) / pair.g1.reference_diameter)
    assert twist > 0
    refused(lambda: pair.scene(face_width=10, tolerance=2e-5), "scene", "mesh budget")


def test_the_budget_names_a_tolerance_that_fits():
    # fitting_tolerance is the smallest two-digit tolerance whose estimate fits (independent:
    # the inverse of n = c / t is c / budget; of n = c / sqrt(t), (c / budget)^2)
    assert fitting_tolerance(lambda t: 1e5 * 0.01 / t, 1e-5, 2e6) == pytest.approx(5e-4)
    assert fitting_tolerance(lambda t: 1e3 / math.sqrt(t), 1e-9, 1e6) == pytest.approx(1e-6)
    # a part no tolerance reduces: no tolerance fits, and the message says what else to reduce
    with pytest.raises(GearError, match="no tolerance brings it within the budget: fewer"):
        check_budget("animation", "x", lambda t: 5e6 + 1.0 / t, 1.0, hint="fewer frames")


def test_the_tolerance_floor_follows_the_module():
    # 1e-6 mm for modules of 1 mm and more, 1e-6 modules below (a watch gear may be drawn as
    # finely, relative to its teeth, as a gear of module 1)
    assert min_tolerance(2.0) == 1e-6 and min_tolerance(0.01) == pytest.approx(1e-8)
    assert check_tolerance(2e-8, module=0.01) == 2e-8
    refused(lambda: check_tolerance(2e-8, module=1.0), "tolerance", "1e-06")
    p = bounded(lambda: Gear(20, 0.01).outline(1e-7))
    assert isinstance(p, shapely.Polygon) and p.is_valid


# --- 7. small slips ------------------------------------------------------------------------------
def test_synthesize_candidates_pass_their_own_neighbour_check():
    # issue: a candidate failed its own neighbour check by -1.4e-14. Six planets at clearance 0
    # touch exactly (2 a sin 30 deg = a = the tip diameter, in exact arithmetic); the search and
    # the stage decide with the one stated tolerance (trains.planetary.checks.NEIGHBOUR_TOLERANCE)
    from trains import synthesize

    found = synthesize(3, 6, scheme="stepped", clearance=0.0, module=0.3, z_min=17, z_max=100,
                       tolerance=0.02, limit=50)  # fmt: skip
    assert found
    for cand in found:
        assert cand.stage.check()["neighbour"].ok, cand


def test_pareto_keeps_module_twins_whose_objectives_tie():
    # issue: the front dropped a module twin whose objectives differ by 1.4e-15. Sliding and
    # contact ratio do not depend on the module (independent: similar geometry), so every
    # front row appears once per module
    import collections

    from gears.search import engine as search

    r = search.pairs(ratio=2.5, module=(1, 2, 3), teeth=(12, 40), shifts=(-0.5, 1.0, 0.1),
                     objective=("sliding", "-contact_ratio"), top=None)  # fmt: skip
    rows = zip(r["z1"], r["z2"], np.round(r["x1"], 9), np.round(r["x2"], 9), strict=True)
    twins = collections.Counter(rows)
    assert set(twins.values()) == {3}


def test_power_flow_friction_errors_are_train_errors():
    # issue: a mesh whose ring tip lies inside its base circle made power_flow(friction=...)
    # raise GearError; the train's own error names the relation
    from trains import Train, power_flow

    t = Train()
    t.mesh("a", "b", gears=(Gear(20, 1), Gear(24, 1, internal=True)), carrier="h")
    text = refused(lambda: power_flow(t, "a", "h", fixed=["b"], friction=0.1), "a-b",
                   exc=TrainError)  # fmt: skip
    assert "base circle" in text


def test_an_unreachable_ratio_says_what_one_stage_reaches():
    # issue: synthesize(1e9, 3) said only which filters removed the sets. Independent bound: a
    # simple stage, ring fixed, reaches 1 + z3 / z1 <= 1 + 200 / 17 = 12.8 within z 17 ... 200
    from trains import synthesize

    found = bounded(lambda: synthesize(1e9, 3))
    assert not found
    assert "reach" in found.reason and "at most about 1:" in found.reason
    most = float(found.reason.split("at most about 1:")[1].split()[0].rstrip(";,:"))
    assert 9 < most <= 1 + 200 / 17


# --- 8. one-sided tessellation: zero-backlash scenes never interpenetrate ------------------------
@pytest.mark.parametrize(
    "gear",
    [
        Gear(20, 1),  # convex flanks, concave fillets
        Gear(8, 1),  # undercut
        Gear(12, 3, profile_shift=0.6, helix_angle=20),
        Gear(77, 1, internal=True),  # every piece of a ring's toothed hole is concave
        Gear(60, 2, internal=True, rack=BasicRack.iso53("C"), profile_shift=0.3),
    ],
)
@pytest.mark.parametrize("tol", [0.1, 0.01])
def test_outlines_never_add_material(gear, tol):
    # independent reference: the same exact curves sampled 200 times finer; what the coarse
    # outline has beyond it is at most the fine outline's own (one-sided) deviation, a strip of
    # tol / 200 along the boundary, never a chord's sag (up to tol / 2)
    bore = 0.3 * gear.root_diameter if not gear.internal else None
    coarse, fine = gear.outline(tol, bore=bore), gear.outline(tol / 200, bore=bore)
    extra = coarse.difference(fine).area
    assert extra <= 0.625 * tol / 200 * fine.length
    # and the achieved deviation stays within the tolerance
    assert shapely.hausdorff_distance(coarse.exterior, fine.exterior) <= tol
    inner = [shapely.hausdorff_distance(a, b) for a, b in zip(coarse.interiors, fine.interiors,
                                                              strict=True)]  # fmt: skip
    assert max(inner, default=0.0) <= tol


@pytest.mark.parametrize("helix", [0.0, 15.0])
@pytest.mark.parametrize("tol", [0.2, 0.05, 0.01, 0.002])
def test_a_zero_backlash_stage_never_interpenetrates(helix, tol):
    # issue: at tolerance 0.01 the 19/29/77 stage's planets overlapped the ring by 6.6e-3 mm^3
    # (the ring's chords cut into the tooth spaces). Exact booleans (manifold3d, float64): no
    # volume in common, yet every mesh engaged (the gap within the tolerance), and a 0.5-degree
    # turn of the sun or ring makes them collide (so the test can fail)
    from gears.solid.mesh import to_manifold, transform

    p = Planetary(19, 29, 77, n_planets=3, module=1, helix_angle=helix)
    assert p.check().ok
    b = 4.0
    sc = bounded(lambda: p.scene(face_width=b, tolerance=tol))

    def node(name, turn=0.0):
        matrix, geom = sc.graph[name]
        return to_manifold(sc.geometry[geom], transform(turn) @ matrix)

    sun, ring = node("sun"), node("ring")
    for k in (1, 2, 3):
        planet = node(f"planet{k}")
        for mate in (sun, ring):
            assert (mate ^ planet).volume() <= 1e-9
            assert mate.min_gap(planet, 1.0) <= tol
    planet = node("planet1")
    assert (node("sun", 0.5) ^ planet).volume() > 1e-3
    assert (node("ring", 0.5) ^ planet).volume() > 1e-3


def test_zero_backlash_outlines_of_a_stage_never_overlap():
    for tol in (0.3, 0.05, 0.01, 0.001):
        o = Planetary(19, 29, 77, n_planets=3, module=1).outlines(tolerance=tol)
        # one-sided outlines only touch: any common area is GEOS's overlay rounding of
        # coordinates near 40 mm (about 1e-14 mm each), far below 1e-12 mm^2
        for k in (1, 2, 3):
            assert o["ring"].intersection(o[f"planet{k}"]).area <= 1e-12
            assert o["sun"].intersection(o[f"planet{k}"]).area <= 1e-12


def test_long_work_reports_progress():
    # a scene reports each distinct solid; a mesh or scene of a simulated outline follows the
    # simulation (the long part), ending at its total
    calls = []
    STAGE.scene(tolerance=0.2, progress=lambda done, total: calls.append((done, total)))
    assert calls == [(1, 3), (2, 3), (3, 3)]
    calls.clear()
    Gear(20, 1).mesh(5, tolerance=0.05, method="rack", progress=lambda d, t: calls.append((d, t)))
    assert calls and calls[-1][0] == calls[-1][1]
    calls.clear()
    PAIR.scene(tolerance=0.05, method="rack", progress=lambda d, t: calls.append((d, t)))
    assert calls[-1] == (1000, 1000)
    refused(lambda: PAIR.scene(progress="yes"), "progress")
