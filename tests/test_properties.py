"""Every public entry point, swept by hypothesis (issue 17): good, edge and bad arguments.

Properties, for each call: a finite answer or the library's own error (GearError / TrainError)
whose message names the argument that was bad; no NaN in any answer; no foreign exception
(TypeError, a GEOS or scipy error, MemoryError ...); meshes watertight, consistently wound and of
positive volume; each call within SECONDS and the process within 2 GB; a check never raises for
what its constructor accepts; the vectorised margins equal check()'s findings to 1e-9 relative;
search.pairs and synthesize_gearbox equal brute force on small spaces (independent routes:
GearPair(...).check() on every candidate; products of single stages).

The default run is small (deterministic, about 40 s on a loaded machine); a larger run scales
every count by GEARTRAIN_PROPERTY_SCALE (and draws new examples): tests/run_properties.py.
"""

from __future__ import annotations

import itertools
import math
import os
import resource
import time
from fractions import Fraction

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, assume, event, given, settings
from hypothesis import strategies as st

from gears import BasicRack, Gear, GearError, GearPair, Rack, gear_margins, pair_margins
from gears.report import Report
from trains import Planetary, Train, TrainError, power_flow, synthesize, synthesize_gearbox

trimesh = pytest.importorskip("trimesh")

from gears.solid.export import save  # noqa: E402
from gears.solid.mesh import gear_solid  # noqa: E402

SCALE = float(os.environ.get("GEARTRAIN_PROPERTY_SCALE", "1"))
SECONDS = 30.0  # a bound, not a benchmark: the machine is shared (the reproducers: 5 s)
BYTES = 2 * 2**30
ERRORS = (GearError, TrainError)


def sweep(n: int):
    """Settings for ``n`` examples in the default run (times GEARTRAIN_PROPERTY_SCALE)."""
    return settings(
        max_examples=max(1, round(n * SCALE)),
        deadline=None,
        derandomize=SCALE == 1,
        database=None,
        suppress_health_check=list(HealthCheck),
    )


def answer(call, *names):
    """``call()`` within the bounds: its result, or the library's own error it raised (whose
    message then names one of ``names``, when given). Anything else propagates and fails."""
    t0 = time.perf_counter()
    try:
        out = call()
    except ERRORS as exc:
        text = str(exc)
        assert text, "an error says what is wrong"
        if names:
            assert any(n in text for n in names), (names, text)
        out = exc
    assert time.perf_counter() - t0 < SECONDS
    assert resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024 < BYTES
    event("refused" if isinstance(out, ERRORS) else "answered")  # --hypothesis-show-statistics
    return out


def no_nan(report: Report) -> None:
    for name, f in report.items():
        assert not math.isnan(f.margin), name
        assert f.message


def finite(*values) -> None:
    for v in values:
        assert np.all(np.isfinite(np.asarray(v, float))), values


def watertight(mesh) -> None:
    assert np.all(np.isfinite(mesh.vertices))
    assert mesh.is_watertight and mesh.is_winding_consistent
    assert mesh.volume > 0


# --- strategies ----------------------------------------------------------------------------------
BAD = st.sampled_from(
    [None, True, False, "1", "abc", math.nan, math.inf, -math.inf, 5e-324, 1e300, -1.0, 0, [1]]
)
#: Words of the errors a real design may meet with good arguments (they name z, x, the tip ...)
DESIGN = (
    "z =",
    "z1",
    "tip",
    "root",
    "tooth",
    "teeth",
    "undercut",
    "budget",
    "cutter",
    "pointed",
    "fillet",
    "base circle",
    "involute",
    "x1 + x2",
    "ring",
)


@st.composite
def arguments(draw, **good):
    """``(kwargs, bad)``: every argument good, or (one draw in three) one of them, ``bad``,
    replaced by a bad value: None, a bool, a string, NaN, an infinity, a denormal ..."""
    values = {k: draw(v) for k, v in good.items()}
    bad = None
    if draw(st.integers(0, 2)) == 0:
        bad = draw(st.sampled_from(sorted(good)))
        values[bad] = draw(BAD)
    return values, bad


def named(bad, *more) -> tuple[str, ...]:
    """What an error may name: the bad argument, or (a good call) the design's own values and
    ``more`` (an argument whose good values include refused ones: a tolerance of 1e-7 mm)."""
    return DESIGN + more + ((bad,) if bad else ())


RACKS = st.sampled_from(["A", "B", "C", "D"]).map(BasicRack.iso53)
teeth = st.one_of(st.integers(8, 80), st.integers(3, 400))
modules = st.sampled_from([0.0024, 0.05, 0.5, 1.0, 2.5, 8.0])
pressure = st.one_of(st.just(20.0), st.sampled_from([14.5, 25.0, 30.0]), st.floats(5, 40))
helix = st.one_of(st.just(0.0), st.floats(-45, 45))
shift = st.one_of(st.floats(-0.5, 1.0), st.floats(-1.5, 2.0))
GEAR = {
    "teeth": teeth,
    "module": modules,
    "pressure_angle": pressure,
    "helix_angle": helix,
    "profile_shift": shift,
    "face_width": st.one_of(st.none(), st.floats(0.1, 50.0)),
    "internal": st.booleans(),
    "rack": RACKS,
}


@st.composite
def pairs_of_gears(draw):
    """Two gears of one module and angle, the hands right (mostly), rack-cut."""
    m, pa, beta, rack = draw(modules), draw(pressure), draw(helix), draw(RACKS)
    internal = draw(st.booleans())
    z1 = draw(st.integers(3, 80))
    z2 = draw(st.integers(z1 + 1, z1 + 120)) if internal else draw(st.integers(3, 150))
    beta2 = beta if internal else -beta
    if draw(st.integers(0, 9)) == 0:
        beta2 = -beta2  # wrong hands: refused when helical
    x1, x2, shortening = draw(shift), draw(shift), draw(st.booleans())
    try:  # a gear no blank can carry is refused at once (tested in test_gear)
        g1 = Gear(z1, m, pa, beta, x1, rack=rack)
        g2 = Gear(z2, m, pa, beta2, x2, internal=internal, rack=rack)
    except GearError:
        return None
    return g1, g2, shortening


@st.composite
def drawable_gears(draw):
    """A gear that has an outline (most do), of at most 60 teeth."""
    kw = {k: draw(v) for k, v in GEAR.items()}
    kw["teeth"] = min(kw["teeth"], 60)
    kw["helix_angle"] /= 2
    g = made(kw)
    assume(g is not None)
    try:
        g.outline(0.5)
    except GearError:
        assume(False)
    return g


def made(kwargs) -> Gear | None:
    try:
        return Gear(**kwargs)
    except GearError:
        return None


# --- gears and pairs -----------------------------------------------------------------------------
@sweep(150)
@given(args=arguments(**GEAR))
def test_gear(args):
    kw, bad = args
    g = answer(lambda: Gear(**kw), *named(bad))
    if isinstance(g, GearError):
        return
    finite(g.reference_diameter, g.base_diameter, g.tip_diameter, g.root_diameter)
    no_nan(answer(g.check))  # a check never raises for a gear the constructor accepts
    for call in (
        lambda: g.tooth_thickness(g.reference_diameter),
        g.span,
        lambda: g.form_diameter,
        lambda: g.over_pins(1.7 * g.module),
        g.chordal_thickness,
    ):
        out = answer(call)
        if not isinstance(out, GearError):
            finite(out)


@sweep(150)
@given(gears=pairs_of_gears(), split=st.sampled_from(["equal_sliding", "proportional", "keep"]))
def test_pair_check_and_centre_distance(gears, split):
    assume(gears is not None)
    g1, g2, shortening = gears
    pair = answer(lambda: GearPair(g1, g2, shortening))
    if isinstance(pair, GearError):
        return
    report = answer(pair.check)
    assert isinstance(report, Report), report  # never raises for a pair the constructor accepts
    no_nan(report)
    out = answer(lambda: (pair.contact_ratio, pair.center_distance, pair.tip_diameters))
    if not isinstance(out, GearError):
        finite(*out)
    # the pair's own centre distance is reached again (issue 17: it was refused)
    again = answer(
        lambda: GearPair.at_center_distance(g1, g2, pair.center_distance, "keep", shortening)
    )
    assert not isinstance(again, GearError), again
    assert again.center_distance == pytest.approx(pair.center_distance, rel=1e-9)
    other = answer(
        lambda: GearPair.at_center_distance(g1, g2, pair.center_distance * 1.03, split, shortening),
        "center_distance",
        "split",
        *DESIGN,
    )
    if not isinstance(other, GearError):
        no_nan(answer(other.check))


@sweep(60)
@given(
    args=arguments(
        pressure_angle=st.sampled_from([20.0, 25.0]),
        face_width=st.floats(1, 40),
        addendum=st.sampled_from([0.8, 1.0, 1.25]),
    ),
    z=st.integers(3, 80),
    x=shift,
    beta=helix,
)
def test_pinion_and_rack(args, z, x, beta):
    kw, bad = args
    rack = answer(lambda: Rack(1.5, helix_angle=-beta, **kw), *named(bad))
    if isinstance(rack, GearError):
        return
    pinion = made(
        {
            "teeth": z,
            "module": 1.5,
            "pressure_angle": rack.pressure_angle,
            "helix_angle": beta,
            "profile_shift": x,
        }
    )
    assume(pinion is not None)
    pair = answer(lambda: GearPair(pinion, rack))
    if isinstance(pair, GearError):
        return
    no_nan(answer(pair.check))


@sweep(120)
@given(
    gears=pairs_of_gears(),
    land=st.sampled_from([0.0, 0.2, 0.4]),
    eps=st.sampled_from([1.0, 1.1, 1.3]),
)
def test_margins_equal_check(gears, land, eps):
    # independent route: the class path GearPair(...).check() (scalar, one gear at a time)
    assume(gears is not None)
    g1, g2, shortening = gears
    try:
        pair = GearPair(g1, g2, shortening)
    except GearError:
        return
    report = pair.check(eps, land)
    m = pair_margins(
        g1.teeth,
        g2.teeth,
        g1.module,
        g1.profile_shift,
        g2.profile_shift,
        g1.pressure_angle,
        g1.helix_angle,
        g2.internal,
        g1.rack,
        shortening,
        eps,
        land,
    ).findings()
    for name, f in report.items():
        assert float(m[name]) == pytest.approx(f.margin, rel=1e-9, abs=1e-12), name
    for g in (g1, g2):
        gm = gear_margins(
            g.teeth,
            g.module,
            g.profile_shift,
            g.pressure_angle,
            g.helix_angle,
            g.internal,
            g.rack,
            0.0,
            land,
        )
        for name, f in g.check(land).items():
            assert float(getattr(gm, name)) == pytest.approx(f.margin, rel=1e-9, abs=1e-12)


@sweep(30)
@given(
    z1=st.integers(5, 60),
    z2=st.lists(st.integers(5, 90), min_size=1, max_size=40),
    pa=st.lists(st.sampled_from([14.5, 20.0, 25.0]), min_size=1, max_size=3),
)
def test_margins_over_arrays_give_one_shape(z1, z2, pa):
    # scalars and arrays broadcast; every margin has the broadcast shape (one stayed 0-d)
    z2 = np.array(z2)
    p = answer(lambda: pair_margins(z1, z2[:, None], 1.0, pressure_angle=np.array(pa)))
    if isinstance(p, GearError):
        return
    for name, v in p.findings().items():
        assert np.shape(v) == (len(z2), len(pa)), name
    assert p.ok().shape == (len(z2), len(pa))


# --- outlines, solids, scenes, animations, files -------------------------------------------------
TOLERANCES = st.sampled_from([0.2, 0.05, 0.01, 0.003, 1e-7])
METHODS = st.sampled_from(["analytic"] * 6 + ["rack", "shaper", "laser"])


@sweep(40)
@given(
    g=drawable_gears(),
    args=arguments(
        tolerance=TOLERANCES,
        method=METHODS,
        backlash=st.sampled_from([0.0, 0.02]),
        bore=st.one_of(st.none(), st.floats(0.5, 20.0)),
        angle=st.floats(-720, 720),
    ),
)
def test_outline(g, args):
    kw, bad = args
    if g.internal:
        kw["bore"] = None
    p = answer(lambda: g.outline(**kw), *named(bad, "tolerance", "method"))
    if isinstance(p, GearError):
        return
    assert isinstance(p, shapely.Polygon) and p.is_valid and p.area > 0
    finite(shapely.get_coordinates(p))


@sweep(12)
@given(
    g=drawable_gears(),
    args=arguments(
        face_width=st.floats(0.01, 60.0), tolerance=TOLERANCES, herringbone=st.booleans()
    ),
)
def test_gear_mesh(g, args):
    kw, bad = args
    m = answer(lambda: g.mesh(**kw), *named(bad, "tolerance"))
    if not isinstance(m, GearError):
        watertight(m)


@st.composite
def outlines(draw):
    kind = draw(st.sampled_from(["box", "ngon", "ring", "gear"]))
    s = draw(st.sampled_from([1e-3, 1.0, 40.0]))
    if kind == "box":
        return shapely.box(-s, -s / 2, s, s)
    if kind == "ngon":
        n = draw(st.integers(3, 40))
        a = np.linspace(0, 2 * np.pi, n, endpoint=False)
        return shapely.Polygon(np.stack([s * np.cos(a), s * np.sin(a)], -1))
    if kind == "ring":
        return shapely.Point(0, 0).buffer(s).difference(shapely.Point(0, 0).buffer(s / 2))
    try:
        return Gear(draw(st.integers(6, 40)), s / 10, internal=draw(st.booleans())).outline(s / 20)
    except GearError:  # a ring of too few teeth: tested in test_outline
        return shapely.box(-s, -s, s, s)


@sweep(25)
@given(
    o=outlines(),
    args=arguments(
        face_width=st.floats(1e-3, 100.0),
        twist=st.one_of(st.just(0.0), st.floats(-720, 720)),
        tolerance=st.sampled_from([0.5, 0.05, 0.01]),
        herringbone=st.booleans(),
    ),
)
def test_gear_solid(o, args):
    kw, bad = args
    m = answer(lambda: gear_solid(o, **kw), *named(bad))
    if not isinstance(m, GearError):
        watertight(m)


SCENE_PAIRS = [
    GearPair(Gear(12, 2), Gear(30, 2)),
    GearPair(Gear(17, 1, helix_angle=15), Gear(29, 1, helix_angle=-15)),
    GearPair(Gear(20, 2, profile_shift=0.5), Gear(80, 2, internal=True, profile_shift=-0.5)),
]


@sweep(8)
@given(
    pair=st.sampled_from(SCENE_PAIRS),
    args=arguments(
        angle=st.floats(-1e4, 1e4),
        face_width=st.one_of(st.none(), st.floats(0.5, 30.0)),
        tolerance=st.sampled_from([0.2, 0.05, 0.01, 1e-7]),
        herringbone=st.booleans(),
    ),
)
def test_pair_scene(pair, args):
    kw, bad = args
    sc = answer(lambda: pair.scene(**kw), *named(bad, "tolerance"))
    if isinstance(sc, GearError):
        return
    for mesh in sc.geometry.values():
        watertight(mesh)


@sweep(6)
@given(
    pair=st.sampled_from(SCENE_PAIRS),
    args=arguments(
        frames=st.integers(1, 3),
        fps=st.floats(0.5, 60.0),
        turn=st.one_of(st.none(), st.floats(-720, 720)),
        tolerance=st.sampled_from([0.2, 0.05, 1e-7]),
    ),
)
def test_pair_animation(tmp_path_factory, pair, args):
    kw, bad = args
    path = tmp_path_factory.mktemp("anim") / "p.gif"
    out = answer(lambda: pair.animate(path, **kw), *named(bad, "tolerance"))
    if not isinstance(out, GearError):
        assert path.read_bytes()[:6] == b"GIF89a"


STAGES = [
    Planetary(18, 45, 108, n_planets=3, module=1),
    Planetary(19, 29, 77, n_planets=3, module=0.5, helix_angle=15),
    Planetary(26, (70, 21), 117, n_planets=3, scheme="stepped"),
]


@sweep(6)
@given(
    stage=st.sampled_from(STAGES),
    args=arguments(
        angle=st.floats(-1e4, 1e4),
        face_width=st.one_of(st.none(), st.floats(0.5, 30.0)),
        tolerance=st.sampled_from([0.2, 0.2, 0.05, 1e-7]),
        fixed=st.sampled_from(["ring", "ring", "sun", "carrier", "planet"]),
    ),
)
def test_stage_scene(stage, args):
    kw, bad = args
    sc = answer(lambda: stage.scene(**kw), *named(bad, "tolerance"), "fixed")
    if isinstance(sc, TrainError):
        return
    for mesh in sc.geometry.values():
        watertight(mesh)


@sweep(5)
@given(
    stage=st.sampled_from(STAGES),
    args=arguments(
        frames=st.integers(1, 2),
        fps=st.floats(0.5, 60.0),
        turn=st.one_of(st.none(), st.floats(-720, 720)),
        tolerance=st.sampled_from([0.3, 1e-7]),
    ),
)
def test_stage_animation(tmp_path_factory, stage, args):
    kw, bad = args
    path = tmp_path_factory.mktemp("anim") / "s.gif"
    out = answer(lambda: stage.animate(path, **kw), *named(bad, "tolerance"))
    if not isinstance(out, TrainError):
        assert path.read_bytes()[:6] == b"GIF89a"


OUTLINE = Gear(12, 1).outline(0.05)
MESH = gear_solid(shapely.box(0, 0, 1, 1), 1.0)


@sweep(25)
@given(
    name=st.sampled_from(
        [
            "g.svg",
            "g.dxf",
            "g.npz",
            "g.stl",
            "g.glb",
            "g.ply",
            "g.obj",
            "g.3mf",
            "g.txt",
            "g",
            "",
            "missing/g.svg",
            None,
            3,
            "dir",
        ]
    ),
    obj=st.sampled_from(["outline", "mesh", "scene", "none", "number"]),
)
def test_save(tmp_path_factory, name, obj):
    folder = tmp_path_factory.mktemp("out")
    (folder / "dir").mkdir()
    path = folder / name if isinstance(name, str) and name else name
    thing = {
        "outline": OUTLINE,
        "mesh": MESH,
        "scene": SCENE_PAIRS[0].scene(tolerance=0.2),
        "none": None,
        "number": 3.0,
    }[obj]
    out = answer(lambda: save(path, thing))
    if not isinstance(out, GearError):
        assert out.exists() and out.stat().st_size > 0


# --- searches against brute force ----------------------------------------------------------------
def _brute_pairs(teeth, shifts, module=2.0):
    out = set()
    for z1, z2, x1, x2 in itertools.product(teeth, teeth, shifts, shifts):
        try:
            pair = GearPair(Gear(z1, module, profile_shift=x1), Gear(z2, module, profile_shift=x2))
        except GearError:
            continue
        if pair.check().ok:
            out.add((z1, z2, round(x1, 9), round(x2, 9)))
    return out


@sweep(4)
@given(
    teeth=st.lists(st.integers(6, 80), min_size=2, max_size=4, unique=True),
    shifts=st.lists(
        st.sampled_from([-0.6, -0.2, 0.0, 0.3, 0.7, 1.1]), min_size=1, max_size=3, unique=True
    ),
)
def test_search_pairs_equal_brute_force(teeth, shifts):
    from gears.search.engine import pairs

    r = answer(lambda: pairs(module=2, teeth=teeth, shifts=shifts, top=None, progress=False))
    got = {
        (int(t["z1"]), int(t["z2"]), round(float(t["x1"]), 9), round(float(t["x2"]), 9))
        for t in r.table
    }
    assert got == _brute_pairs(teeth, shifts)


def _simple_ratios(z_max: int):
    return {Fraction(z1 + z3, z1) for z1 in range(17, z_max + 1) for z3 in range(z1 + 1, z_max + 1)}


@sweep(2)
@given(data=st.data())
def test_gearbox_equals_the_product_of_single_stages(data):
    # independent route: every product of two single stages, each from synthesize() with its
    # own exact target; the gearbox's feasible set is that product's checked pairs
    z_max = 60
    ratios = sorted(_simple_ratios(z_max))
    r1, r2 = data.draw(st.sampled_from(ratios)), data.draw(st.sampled_from(ratios))
    target = r1 * r2
    got = answer(
        lambda: synthesize_gearbox(target, stages=2, z_max=z_max, top=1000, progress=False)
    )
    expected = set()
    for a in ratios:
        b = target / a
        if b < a or b not in ratios:
            continue
        for s1, s2 in itertools.product(
            synthesize(a, 3, z_max=z_max, limit=10**6), synthesize(b, 3, z_max=z_max, limit=10**6)
        ):
            if s1.stage.check().ok and s2.stage.check().ok:
                expected.add(tuple(sorted((s1.teeth, s2.teeth))))
    assert {tuple(sorted(c.teeth for c in g.stages)) for g in got} == expected


# --- trains --------------------------------------------------------------------------------------
@sweep(40)
@given(
    z=st.lists(st.integers(8, 120), min_size=2, max_size=4),
    internal=st.booleans(),
    real=st.booleans(),
    args=arguments(
        friction=st.one_of(st.none(), st.floats(0, 0.3)),
        mesh_efficiency=st.one_of(st.none(), st.floats(0.5, 1.0)),
    ),
    speed=st.one_of(st.floats(-1e4, 1e4), BAD, st.sampled_from([["x"], [[1, 2], [3]], [1, 2]])),
)
def test_train_and_power_flow(z, internal, real, args, speed):
    kw, bad = args
    t = Train()
    names = [f"g{i}" for i in range(len(z))]
    for i, (a, b) in enumerate(itertools.pairwise(names)):
        extra = {"carrier": "h"} if i == 0 else {}
        ring = internal and i == 0
        if real:
            g1 = Gear(z[i], 1)
            g2 = Gear(max(z[i + 1], z[i] + 8), 1, internal=True) if ring else Gear(z[i + 1], 1)
            made_ = answer(
                lambda a=a, b=b, g1=g1, g2=g2, e=extra: t.mesh(a, b, gears=(g1, g2), **e)
            )
        else:
            made_ = answer(
                lambda a=a, b=b, i=i, r=ring, e=extra: t.mesh(
                    a, b, teeth=(z[i], z[i + 1]), internal=r, **e
                )
            )
        if isinstance(made_, ERRORS):
            return
    fixed = [names[-1]]
    m = answer(lambda: t.solve({names[0]: speed, fixed[0]: 0}), names[0], "speed", "float")
    if not isinstance(m, ERRORS):
        finite(*m.values())
    flow = answer(
        lambda: power_flow(t, names[0], "h", fixed=fixed, **kw),
        *named(bad),
        "relation",
        "self-locking",
        "fixed",
    )
    assert not isinstance(flow, GearError), flow  # the train's own error (issue 17)
    if not isinstance(flow, TrainError):
        finite(flow.efficiency)


@sweep(12)
@given(
    args=arguments(
        ratio=st.one_of(st.floats(1.05, 30), st.sampled_from([1e9, 7, "7/2", -3])),
        n_planets=st.integers(1, 8),
        scheme=st.sampled_from(["simple", "stepped", "double-planet", "A"]),
        tolerance=st.sampled_from([0.0, 0.01, 0.05]),
    ),
)
def test_synthesize(args):
    kw, bad = args
    found = answer(
        lambda: synthesize(**kw, z_max=80, limit=5, max_seconds=10), *named(bad), "ratio", "stage"
    )
    if isinstance(found, TrainError):
        return
    if not found:
        assert found.reason
    for cand in found:
        report = cand.stage.check()
        no_nan(report)
        assert report["neighbour"].ok and report["assembly"].ok  # its own filters hold


@sweep(40)
@given(
    args=arguments(
        sun=st.integers(6, 60),
        planet=st.integers(6, 60),
        ring=st.integers(20, 200),
        n_planets=st.integers(1, 6),
        module=st.sampled_from([0.5, 1.0, 3.0]),
        helix_angle=st.one_of(st.just(0.0), st.floats(-30, 30)),
        clearance=st.sampled_from([0.0, 0.5, 2.0]),
    ),
    scheme=st.sampled_from(["simple", "simple", "stepped", "double-planet"]),
    second=st.integers(6, 60),
)
def test_stage_check(args, scheme, second):
    # Planetary(...) is a stage or a TrainError; its check() never raises, has no NaN
    kw, bad = args
    if scheme != "simple" and bad != "planet":
        kw["planet"] = (kw["planet"], second)
    stage = answer(lambda: Planetary(**kw, scheme=scheme), *named(bad), "mesh", "scheme")
    if isinstance(stage, TrainError):
        return
    no_nan(answer(stage.check))
    no_nan(answer(stage.train.check))
    out = answer(lambda: (float(stage.ratio()), stage.efficiency()))
    if not isinstance(out, ERRORS):
        finite(*out)


@sweep(20)
@given(
    args=arguments(
        mesh_efficiency=st.one_of(st.none(), st.floats(0.5, 1.0)), friction=st.floats(0.0, 0.3)
    ),
    stage=st.sampled_from(STAGES[:2]),
    a=st.one_of(st.floats(40.0, 90.0), BAD),
    split=st.sampled_from(["equal_sliding", "proportional", "keep", "none"]),
)
def test_stage_efficiency_and_coaxial(args, stage, a, split):
    kw, bad = args
    eta = answer(lambda: stage.efficiency(**kw), *named(bad), "relation")
    if not isinstance(eta, ERRORS):
        finite(eta)
    made_ = answer(
        lambda: Planetary.coaxial(21, 43, 108, 3, module=1, center_distance=a, split=split),
        "center_distance",
        "split",
        *DESIGN,
    )
    if not isinstance(made_, ERRORS):
        no_nan(made_.check())
