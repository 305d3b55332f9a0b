"""Trains of real gears (issue 12): meshes from Gear objects, Train.check, coaxial_shifts,
efficiency from the mesh geometry, TOML gear fields and the reader's robustness (issue 11).

Sources: Ozols = seed-001-ozols.md, Joldasbekov = seed-000-joldasbekov.md, lectures =
seed-004-lectures.md, standards = standards.md; "derivation" marks an independent computation
written in the test.
"""

import math
from fractions import Fraction as F
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from gears import Gear, GearPair, Rack
from trains import (
    Planetary,
    Train,
    TrainError,
    coaxial_shifts,
    planetary_efficiency,
    power_flow,
    read_train,
    self_locking_range,
    stepped_planetary,
)
from trains.conditions import assembly_number, closure_margin, neighbour_gap
from trains.toml_format import train_from_dict

ROOT = Path(__file__).parents[2]


def _inv(a):
    return math.tan(a) - a


# --------------------------------------------------------------- the seeds' trains, real gears


def _ozols_7_7(real: bool) -> Train:
    # Ozols Ex 7-7 (Fig 7-13), the electric hoist: differential 1-2/2'-3 on the drum 4, closed
    # by 3' - idler 5 - drum 4 (tooth counts as in test_worked_examples). Modules 1.5 / 2 / 2
    # (ISO 54 series 1) make 1, 3 and 4 coaxial at zero shift: 38 x 1.5 = 28.5 x 2 = 57 mm and
    # 24 x 2 = 24 x 2 = 48 mm (derivation).
    t = Train()
    spec = [
        ("1", "2", (24, 52), 1.5, "4", False),
        ("2", "3", (21, 78), 2.0, "4", True),
        ("3", "5", (18, 30), 2.0, None, False),
        ("5", "4", (30, 78), 2.0, None, True),
    ]
    for a, b, z, m, c, internal in spec:
        if real:
            t.mesh(a, b, gears=(Gear(z[0], m), Gear(z[1], m, internal=internal)), carrier=c)
        else:
            t.mesh(a, b, teeth=z, carrier=c, internal=internal)
    return t


def _joldasbekov_e6(real: bool) -> Train:
    # Joldasbekov E6 (Fig 191), signs as in test_worked_examples (digest recommendation); the
    # ring 5' of mesh 5-6 is member 5 (50 teeth), so with gears the ring is gears[0].
    t = Train()
    spec = [
        ("1", "2", (15, 30), None, None),
        ("2", "3", (20, 25), None, None),
        ("3", "H", (25, 50), None, 1),
        ("9", "8", (15, 10), None, None),
        ("8", "5", (20, 25), None, None),
        ("5", "6", (50, 10), "H", 0),
        ("6", "7", (15, 25), "H", None),
    ]
    for a, b, z, c, ring in spec:
        if real:
            gears = (Gear(z[0], 2, internal=ring == 0), Gear(z[1], 2, internal=ring == 1))
            t.mesh(a, b, gears=gears, carrier=c)
        else:
            t.mesh(a, b, teeth=z, carrier=c, internal=ring is not None)
    return t


def _hand_pairs(t: Train) -> dict:
    # each mesh's GearPair built by hand from the relation's gears (external gear first)
    out = {}
    for r in t.relations:
        ga, gb = r.gears
        out[r.name] = GearPair(gb, ga) if ga.internal else GearPair(ga, gb)
    return out


@pytest.mark.parametrize(
    ("build", "given_speeds"),
    [(_ozols_7_7, {"1": 880}), (_joldasbekov_e6, {"1": 1500, "9": -1000})],
)
def test_seed_trains_on_real_gears_same_speeds_and_findings(build, given_speeds):
    real, counts = build(True), build(False)
    # same exact speeds as the tooth-count trains (Ozols 7-7: i_14 = 2767/63; Joldasbekov E6:
    # n_H = 300, n5 = -1200, n7 = 4800, test_worked_examples)
    m_real, m_counts = real.solve(given_speeds), counts.solve(given_speeds)
    assert dict(m_real) == dict(m_counts)
    assert all(isinstance(v, F) for v in m_real.values())
    # the train's findings are exactly the hand-built pairs' findings, prefixed by mesh name
    report = real.check()
    hand = _hand_pairs(real)
    for name, pair in hand.items():
        for fname, f in pair.check().items():
            g = report[f"{name}.{fname}"]
            assert (g.ok, g.message) == (f.ok, f.message)
            assert g.margin == pytest.approx(f.margin, rel=1e-12)  # the same formula, same gears
    expected_failed = [f"{n}.{x}" for n, p in hand.items() for x in p.check().failed()]
    assert report.failed() == expected_failed


def test_joldasbekov_e6_names_the_undercut_of_its_small_gears():
    # Joldasbekov E6 at zero shift: z = 10 and 15 are below z_min = 2/sin^2(20 deg) = 17.1
    # (Ozols 21.27 / standards §1.6), so every such gear is undercut; z >= 20 is not.
    report = _joldasbekov_e6(True).check()
    z_min = 2 / math.sin(math.radians(20)) ** 2
    for r in _joldasbekov_e6(True).relations:
        for which, gear in zip(("g1", "g2"), _hand_pairs_gears(r), strict=True):
            if gear.internal:
                continue
            assert report[f"{r.name}.{which}.undercut"].ok == (gear.teeth >= z_min)


def _hand_pairs_gears(r):
    ga, gb = r.gears
    return (gb, ga) if ga.internal else (ga, gb)


def test_ozols_7_7_coaxial_at_zero_shift_and_planet_conditions():
    t = _ozols_7_7(True)
    t.coaxial("1", "3", "4")
    f = t.check()["coaxiality(1, 3, 4)"]
    # derivation: a_12 = 38 x 1.5 = 57 = a_23 = (78 - 21) / 2 x 2; a_35 = a_54 = 48 mm
    assert f.ok and f.margin == pytest.approx(0.01, abs=1e-12)
    assert "57.0000 / 57.0000" in f.message and "48.0000 / 48.0000" in f.message
    # three identical stepped planets 2: T = (78 x 52 + 24 x 21) / gcd(52, 21) = 4560
    # (lectures §4.3 gcd form), a multiple of 3
    t.set_planets("2", 3)
    r = t.check()
    assert r["2.assembly"].ok and "T = 4560" in r["2.assembly"].message
    # neighbour: 2 a_w sin(60 deg) - d_a2 - 0.5 m (Ozols §21-13); the planet's largest gear is
    # its 52-tooth gear: d_a = (52 + 2) x 1.5 = 81 mm (no tip shortening at zero shift)
    gap = 2 * 57 * math.sin(math.pi / 3) - 81.0 - 0.5 * 2.0
    assert r["2.neighbour"].margin == pytest.approx(gap, abs=1e-9)


# --------------------------------------------------------------------------- reverted train


def test_reverted_train_coaxial_shifts_against_independent_inv():
    # 17/40 + 20/38 at m = 2: a = 57 and 58 mm; the smaller tooth sum (57) must be shifted.
    m, alpha = 2.0, math.radians(20)
    p12, p34 = coaxial_shifts([(Gear(17, m), Gear(40, m)), (Gear(20, m), Gear(38, m))])
    assert (p34.g1.profile_shift, p34.g2.profile_shift) == (0.0, 0.0)
    s12 = p12.g1.profile_shift + p12.g2.profile_shift
    assert s12 > 0
    assert abs(p12.center_distance - p34.center_distance) < 1e-9
    # independent route 1 (derivation, ISO 21771 §5): cos a_w = a cos alpha / a_w,
    # x1 + x2 = (z1 + z2)(inv a_w - inv alpha) / (2 tan alpha)
    aw = 58.0
    alpha_w = math.acos(57.0 * math.cos(alpha) / aw)
    assert s12 == pytest.approx(57 * (_inv(alpha_w) - _inv(alpha)) / (2 * math.tan(alpha)),
                                abs=1e-12)  # fmt: skip
    # independent route 2: from the shift sum back to a_w by a root of inv(a_w) (brentq)
    target = 2 * math.tan(alpha) * s12 / 57 + _inv(alpha)
    alpha_w2 = brentq(lambda a: _inv(a) - target, 1e-6, 1.5, xtol=1e-15)
    assert 57.0 * math.cos(alpha) / math.cos(alpha_w2) == pytest.approx(58.0, abs=1e-9)
    # each pair's contact ratio and checks are those GearPair computes for the same gears
    t = Train()
    t.mesh("in", "lay", pair=p12)
    t.mesh("lay", "out", pair=p34)
    t.coaxial("in", "out")
    r = t.check()
    for name, pair in (("in-lay", p12), ("lay-out", p34)):
        hand = GearPair(pair.g1, pair.g2)
        # the same formulas on the same gears: equal to rounding (1e-12 relative)
        assert t.pairs[name].contact_ratio == pytest.approx(hand.contact_ratio, rel=1e-12)
        mine = {
            k.removeprefix(name + "."): v.margin for k, v in r.items() if k.startswith(name + ".")
        }
        assert mine == pytest.approx({k: v.margin for k, v in hand.check().items()}, rel=1e-12)
    assert r.ok
    assert r["coaxiality(in, out)"].margin == pytest.approx(0.01, abs=1e-9)
    assert t.ratio("in", "out") == F(40 * 38, 17 * 20)  # derivation: (-40/17)(-38/20)


def test_reverted_train_unshifted_fails_coaxiality_by_one_millimetre():
    # the same train at zero shift: a_w 57 vs 58 mm, margin 0.01 - 1 (derivation)
    t = Train()
    t.mesh("in", "lay", gears=(Gear(17, 2), Gear(40, 2)))
    t.mesh("lay", "out", gears=(Gear(20, 2), Gear(38, 2)))
    t.coaxial("in", "out")
    f = t.check()["coaxiality(in, out)"]
    assert not f.ok and f.margin == pytest.approx(-0.99, abs=1e-12)


def test_coaxial_shifts_given_distance_internal_and_errors():
    # an internal mesh in the group: 20/60 ring (a = 20 mm) and 15/25 (a = 20 mm) at m = 1,
    # both moved to 20.5 mm; the internal pair's x1 + x2 (the ring's in the sign of DIN 3960)
    # follows (z1 - z2) (ISO 21771 §5)
    pairs = coaxial_shifts([(Gear(20, 1), Gear(60, 1, internal=True)), (Gear(15, 1), Gear(25, 1))],
                           center_distance=20.5, split="keep")  # fmt: skip
    alpha = math.radians(20)
    alpha_w = math.acos(20.0 * math.cos(alpha) / 20.5)
    want = -40 * (_inv(alpha_w) - _inv(alpha)) / (2 * math.tan(alpha))  # derivation
    ring = pairs[0]
    assert ring.internal and ring.g2.profile_shift + ring.g1.profile_shift == pytest.approx(want)
    assert all(abs(p.center_distance - 20.5) < 1e-9 for p in pairs)
    # a ring given first in a tuple becomes the pair's g2
    assert coaxial_shifts([(Gear(60, 1, internal=True), Gear(20, 1)), (Gear(15, 1), Gear(25, 1))],
                          center_distance=20.5)[0].g2.teeth == 60  # fmt: skip
    with pytest.raises(TrainError, match="two or more meshes"):
        coaxial_shifts([(Gear(17, 2), Gear(40, 2))])
    with pytest.raises(TrainError, match="mesh #2 must be"):
        coaxial_shifts([(Gear(17, 2), Gear(40, 2)), (Gear(17, 2),)])
    with pytest.raises(TrainError, match=r"mesh #1 \(17/40\): .*\b50(\.0)? mm"):
        coaxial_shifts([(Gear(17, 2), Gear(40, 2)), (Gear(20, 2), Gear(38, 2))],
                       center_distance=50)  # fmt: skip
    for bad in (0, -1.0, math.nan, "x", True):
        with pytest.raises(TrainError, match="center_distance"):
            coaxial_shifts([(Gear(17, 2), Gear(40, 2)), (Gear(20, 2), Gear(38, 2))],
                           center_distance=bad)  # fmt: skip


# ------------------------------------------------------------------------------ efficiency


def test_single_mesh_efficiency_from_geometry():
    # Ozols (14.25): eta = 1 - (pi f eps / 2)(1/z1 + 1/z2), written here independently
    pair = GearPair(Gear(20, 2), Gear(40, 2))
    t = Train()
    t.mesh("a", "b", pair=pair)
    pf = power_flow(t, "a", "b", friction=0.06)
    want = 1 - math.pi * 0.06 * pair.contact_ratio / 2 * (1 / 20 + 1 / 40)
    assert pf.efficiency == pytest.approx(want, rel=1e-13)
    assert pf.efficiency == pytest.approx(pair.mesh_efficiency(0.06), rel=1e-13)
    assert pf.relations["a-b"].efficiency == pytest.approx(pair.mesh_efficiency(0.06), rel=1e-13)
    # a user's value for the mesh wins over the estimate; friction 0 is lossless
    assert power_flow(t, "a", "b", friction=0.06, mesh_efficiency={"a-b": 0.9}).efficiency == (
        pytest.approx(0.9, rel=1e-13)
    )
    assert power_flow(t, "a", "b", friction=0.0).efficiency == pytest.approx(1.0, rel=1e-15)
    for bad in (-0.1, 1.0, math.nan, "0.1", True):
        with pytest.raises(TrainError, match="friction"):
            power_flow(t, "a", "b", friction=bad)


def test_mixed_user_and_geometric_efficiencies():
    # a real-gear mesh (geometry) in series with a chain (a link with the user's 0.95):
    # fixed-axis series efficiency is the product (Ozols (14.10))
    pair = GearPair(Gear(18, 3), Gear(45, 3))
    t = Train()
    t.mesh("a", "b", pair=pair)
    t.link("b", "c", ratio=F(-1, 2))
    pf = power_flow(t, "a", "c", friction=0.08, mesh_efficiency=0.95)
    assert pf.efficiency == pytest.approx(pair.mesh_efficiency(0.08) * 0.95, rel=1e-13)
    # a mapping names some relations; the rest: the estimate for meshes of gears, 1 for links
    pf = power_flow(t, "a", "c", friction=0.08, mesh_efficiency={"b-c": 0.9})
    assert pf.efficiency == pytest.approx(pair.mesh_efficiency(0.08) * 0.9, rel=1e-13)
    pf = power_flow(t, "a", "c", friction=0.08, mesh_efficiency={"a-b": 0.97})
    assert pf.efficiency == pytest.approx(0.97, rel=1e-13)


@pytest.mark.parametrize("fixed", ["ring", "sun"])
def test_planetary_efficiency_both_ways(fixed):
    # the same stage as a Train of real gears and as a Planetary: equal efficiency (Kreines,
    # standards §4) with each mesh's (14.25) estimate; ring_tip_relief off so both hold the
    # same gears
    p = Planetary(20, 30, 80, n_planets=2, module=2, ring_tip_relief=False)
    t = Train()
    t.mesh("sun", "planet", gears=(Gear(20, 2), Gear(30, 2)), carrier="arm")
    t.mesh("planet", "ring", gears=(Gear(30, 2), Gear(80, 2, internal=True)), carrier="arm")
    t.set_planets("planet", 2)
    inp = "sun" if fixed == "ring" else "ring"
    eta = power_flow(t, inp, "arm", fixed=[fixed], friction=0.06).efficiency
    assert eta == pytest.approx(p.efficiency(fixed=fixed, friction=0.06), rel=1e-13)
    # and the whole-train checks agree with the stage's (coaxiality, assembly, neighbour)
    r, rp = t.check(), p.check()
    assert r["coaxiality(sun, ring)"].ok == rp["coaxiality"].ok
    assert r["planet.assembly"].ok == rp["assembly"].ok  # 20 + 80 = 100: 2 planets fit
    assert r["planet.neighbour"].margin == pytest.approx(rp["neighbour"].margin, abs=1e-12)
    for name in ("sun-planet", "planet-ring"):
        for k, f in p.meshes[name].check().items():
            assert r[f"{name}.{k}"].margin == pytest.approx(f.margin, rel=1e-12)  # same formula


def test_planet_assembly_fails_like_planetary():
    # Ozols §21-13 derived case: 20/30/80 assembles with 2 and 4 planets, not 3
    for k in (2, 3, 4):
        t = Train()
        t.mesh("sun", "planet", gears=(Gear(20, 2), Gear(30, 2)), carrier="arm")
        t.mesh("planet", "ring", gears=(Gear(30, 2), Gear(80, 2, internal=True)), carrier="arm")
        t.set_planets("planet", k)
        a = t.check()["planet.assembly"]
        assert a.ok == Planetary(20, 30, 80, n_planets=k, module=2).check()["assembly"].ok
        assert a.ok == (k != 3)


def test_david_mechanism_self_locking_from_friction():
    # Ozols Ex 14-3 (David mechanism, Ex 7-4: 100/101, 100/99, i_1H = 1/10000) with eta_H from
    # the meshes' geometry: eta_H = eta_12 eta_2'3 (Ozols §14-5, the inverted train in series),
    # then (14.26) with the corrected exponent and the self-locking range (14.27)
    m = 1.0
    t = Train()
    t.mesh("1", "2", gears=(Gear(100, m), Gear(101, m)), carrier="H")
    t.mesh("2", "3", gears=(Gear(100, m), Gear(99, m)), carrier="H")
    f = 0.05
    eta_h = t.pairs["1-2"].mesh_efficiency(f) * t.pairs["2-3"].mesh_efficiency(f)
    i_1h = t.ratio("1", "H", fixed=["3"])
    assert i_1h == F(1, 10000)
    lo, hi = self_locking_range(eta_h)
    assert lo < i_1h < hi
    fwd = power_flow(t, "1", "H", fixed=["3"], friction=f)
    assert fwd.self_locking
    assert fwd.efficiency == pytest.approx(planetary_efficiency(i_1h, eta_h), rel=1e-9)
    back = power_flow(t, "H", "1", fixed=["3"], friction=f)
    assert back.efficiency == pytest.approx(planetary_efficiency(i_1h, eta_h, "carrier"), rel=1e-9)
    # the same train as a Planetary (external scheme) gives the same numbers both ways
    p = Planetary(100, (101, 100), 99, n_planets=1, module=m, scheme="external", carrier="H")
    assert p.efficiency(fixed="ring", input="sun", output="carrier", friction=f) == (
        pytest.approx(fwd.efficiency, rel=1e-12)
    )


# -------------------------------------------------------------------------- Train.mesh input


def test_mesh_from_gears_input_errors():
    t = Train()
    with pytest.raises(TrainError, match="not both"):
        t.mesh("a", "b", gears=(Gear(20, 2), Gear(40, 2)), pair=GearPair(Gear(20, 2), Gear(40, 2)))
    with pytest.raises(TrainError, match="two internal gears"):
        t.mesh("a", "b", gears=(Gear(20, 2, internal=True), Gear(40, 2, internal=True)))
    with pytest.raises(TrainError, match=r"mesh a-b: the gears of a pair need equal modules"):
        t.mesh("a", "b", gears=(Gear(20, 2), Gear(40, 3)))
    with pytest.raises(TrainError, match="contradicts the gears' tooth counts"):
        t.mesh("a", "b", teeth=(20, 41), gears=(Gear(20, 2), Gear(40, 2)))
    with pytest.raises(TrainError, match="internal = True contradicts"):
        t.mesh("a", "b", internal=True, gears=(Gear(20, 2), Gear(40, 2)))
    with pytest.raises(TrainError, match=r"two gears\.Gear"):
        t.mesh("a", "b", gears=(20, 40))
    with pytest.raises(TrainError, match="no second axis"):
        t.mesh("a", "b", pair=GearPair(Gear(20, 2), Rack(2)))
    with pytest.raises(TrainError, match="give teeth"):
        t.mesh("a", "b")
    # gears whose shifts leave no working pressure angle are impossible input (raise now)
    with pytest.raises(TrainError, match=r"mesh a-b: x1 \+ x2 = -16 is too negative"):
        t.mesh("a", "b", gears=(Gear(20, 2, profile_shift=-8), Gear(40, 2, profile_shift=-8)))
    assert t.relations == ()  # nothing half-added
    # agreeing teeth and a ring on member a are fine
    t.mesh("ring", "p", teeth=(60, 20), gears=(Gear(60, 2, internal=True), Gear(20, 2)),
           carrier="c")  # fmt: skip
    r = t.relation("ring-p")
    assert r.internal and t.pairs["ring-p"].g2.teeth == 60
    assert r.gear_of("ring")[0].internal and r.gear_of("p")[0].teeth == 20
    # the mounted tip diameters: ring d_a = d - 2 m = 116, pinion d_a = d + 2 m = 44 (ISO 21771)
    assert r.gear_of("ring")[1] == pytest.approx(116.0) and r.gear_of("p")[1] == pytest.approx(44)


def test_same_gear_in_two_meshes_must_agree():
    # one 30-tooth module-2 planet described with two different shifts: one gear cannot be both
    t = Train()
    t.mesh("sun", "planet", gears=(Gear(20, 2), Gear(30, 2, profile_shift=0.2)), carrier="c")
    t.mesh("planet", "ring", gears=(Gear(30, 2), Gear(80, 2, internal=True)), carrier="c")
    f = t.check()["planet.same_gear"]
    assert not f.ok and f.margin == pytest.approx(-0.2) and "profile_shift 0.2 vs 0" in f.message
    assert f.unit == "module"
    # a stepped planet (another tooth count on the same member) is two gears: no finding
    t = Train()
    t.mesh("sun", "planet", gears=(Gear(20, 2), Gear(30, 2, profile_shift=0.2)), carrier="c")
    t.mesh("planet", "ring", gears=(Gear(25, 2), Gear(75, 2, internal=True)), carrier="c")
    assert "planet.same_gear" not in t.check()


def test_check_arguments_and_coaxial_declarations():
    t = Train()
    t.mesh("a", "b", gears=(Gear(20, 2), Gear(40, 2)))
    with pytest.raises(TrainError, match="tolerance"):
        t.check(tolerance=-1)
    with pytest.raises(TrainError, match="clearance"):
        t.check(clearance=math.nan)
    with pytest.raises(TrainError, match="two or more different members"):
        t.coaxial("a")
    with pytest.raises(TrainError, match="unknown member"):
        t.coaxial("a", "zz")
    # two coaxial members meshing directly cannot share an axis: margin tolerance - a_w
    t.coaxial("a", "b")
    assert t.check()["coaxiality(a, b)"].margin == pytest.approx(0.01 - 60.0)
    # a group joined only through kinematic meshes gets an informative note
    k = Train()
    k.mesh("a", "b", teeth=(20, 40))
    k.mesh("b", "c", teeth=(20, 40))
    k.coaxial("a", "c")
    note = k.check()["coaxiality(a, c)"]
    assert note.ok and "not checked" in note.message


def test_pure_conditions():
    # lectures §4.3: T = z_s + z_r for a simple planet (18/45/108 -> 126); the stepped example
    # (26, 70/21, 117) -> (117 x 70 + 26 x 21) / 7 = 1248 (as Planetary.assembly)
    assert assembly_number(18, 45, 45, 108, internal_b=True) == 126
    assert assembly_number(26, 70, 21, 117, internal_b=True) == 1248
    # David (both external): |99 x 101 - 100 x 100| / 1 = 1 (derivation)
    assert assembly_number(100, 101, 100, 99) == 1
    # neighbour: one planet has no neighbour; two planets: 2 a - d_a (sin 90 deg = 1)
    assert math.isinf(neighbour_gap(50.0, 30.0, 1))
    assert neighbour_gap(50.0, 30.0, 2) == pytest.approx(70.0)
    # polygon closure (triangle inequality): 3-4-5 closes with 2 mm to spare, 1-1-3 does not
    assert closure_margin([3.0, 4.0, 5.0]) == pytest.approx(2.0)
    assert closure_margin([1.0, 1.0, 3.0]) == pytest.approx(-1.0)


# ---------------------------------------------------------------------------------- TOML

_REVERTED_TOML = """\
name = "reverted reducer 17/40 + 20/38, m = 2"
coaxial = [["in", "out"]]

[[mesh]]
gears = ["in", "lay"]
teeth = [17, 40]
module = 2
shift = [{x1}, {x2}]
face_width = 20

[[mesh]]
gears = ["lay", "out"]
teeth = [20, 38]
module = 2
face_width = [22, 20]

[run]
input = {{ in = 1450 }}
output = "out"
friction = 0.06
"""


def _reverted_file(tmp_path, x1=None, x2=None):
    if x1 is None:
        p12, _ = coaxial_shifts([(Gear(17, 2), Gear(40, 2)), (Gear(20, 2), Gear(38, 2))])
        x1, x2 = p12.g1.profile_shift, p12.g2.profile_shift
    f = tmp_path / "reverted.toml"
    f.write_text(_REVERTED_TOML.format(x1=repr(x1), x2=repr(x2)))
    return f


def test_toml_with_gears_round_trips(tmp_path):
    p12, p34 = coaxial_shifts([(Gear(17, 2), Gear(40, 2)), (Gear(20, 2), Gear(38, 2))])
    t = read_train(_reverted_file(tmp_path))
    a, b = t.pairs["in-lay"], t.pairs["lay-out"]
    # repr() of a float round-trips exactly through TOML (IEEE 754 shortest repr)
    assert (a.g1.profile_shift, a.g2.profile_shift) == (p12.g1.profile_shift, p12.g2.profile_shift)
    # the centre distances are recomputed from those shifts: equal to rounding
    assert a.center_distance == pytest.approx(p12.center_distance, rel=1e-13)
    assert b.center_distance == pytest.approx(p34.center_distance, rel=1e-13)
    assert (a.g1.face_width, b.g1.face_width, b.g2.face_width) == (20.0, 22.0, 20.0)
    assert t.coaxial_groups == (("in", "out"),) and t.check().ok
    assert t.run_defaults["friction"] == 0.06
    # helix and internal: the gear with more teeth is the ring, hands follow the mesh kind
    text = ('[[mesh]]\ngears = ["r", "p"]\nteeth = [60, 20]\nmodule = 1\nhelix = 15\n'
            'internal = true\ncarrier = "c"\n')  # fmt: skip
    (tmp_path / "h.toml").write_text(text)
    pair = read_train(tmp_path / "h.toml").pairs["r-p"]
    assert pair.internal and pair.g2.teeth == 60
    assert pair.g1.helix_angle == pair.g2.helix_angle == 15.0  # internal: same hand (ISO 21771)


def test_cli_prints_checks_and_exits_1_when_one_fails(tmp_path, capsys):
    from trains.cli.app import main

    good = _reverted_file(tmp_path)
    assert main(["train", str(good)]) == 0
    out = capsys.readouterr().out
    assert out.index("efficiency") < out.index("checks") < out.index("coaxiality(in, out)")
    assert "friction 0.06" in out
    bad = _reverted_file(tmp_path, 0.0, 0.0)  # unshifted: 57 vs 58 mm
    assert main(["train", str(bad)]) == 1
    # at zero shift the 17-tooth pinion is also just undercut (GearPair's own finding,
    # x_min = 0.0057 with the ISO 53 A tool), so both names head the report
    head = next(x for x in capsys.readouterr().out.splitlines() if x.startswith("FAILED:"))
    assert "coaxiality(in, out)" in head and "in-lay.g1.undercut" in head


@pytest.mark.parametrize(
    ("text", "match"),
    [
        ('[[mesh]]\ngears = ["a", "b"]\nteeth = [20, 40]\nmodule = 0\n',
         r"line 4: mesh #1, 'module': must be a number > 0"),
        ('[[mesh]]\ngears = ["a", "b"]\nteeth = [20, 40]\nmodule = 2\nshift = "x"\n',
         r"line 5: mesh #1, 'shift': must be a number or a list"),
        ('[[mesh]]\ngears = ["a", "b"]\nteeth = [20, 40]\nmodule = 2\nhelix = 75\n',
         r"line 5: mesh #1, 'helix': .*helix_angle"),
        ('[[mesh]]\ngears = ["a", "b"]\nteeth = [20, 40]\nshift = 0.5\n',
         r"line 4: mesh #1, 'shift': gear fields \['shift'\] need 'module'"),
        ('[[mesh]]\ngears = ["a", "b"]\nteeth = [20, 40]\nmodule = 2\nface_width = [1, 2, 3]\n',
         r"'face_width': must be a number or a list of two"),
        ('[[mesh]]\ngears = ["a", "b"]\nteeth = [20, 20]\nmodule = 2\ninternal = true\n',
         r"'teeth': an internal mesh needs a ring with more teeth"),
        ('[[mesh]]\ngears = ["a", "b"]\nteeth = [20, 40]\nmodule = 2\nshift = -8\n',
         r"line 5: mesh #1, 'shift': mesh a-b: x1 \+ x2 = -16"),
        ('[[mesh]]\ngears = ["a", "b"]\nteeth = [20, 40]\ninternal = "yes"\n',
         r"line 4: mesh #1, 'internal': must be true or false"),
        ('[[mesh]]\ngears = ["a", "b"]\nteeth = [20, 40]\ncarrier = 3\n',
         r"line 4: mesh #1, 'carrier': must be a non-empty string"),
        ('[[link]]\nmembers = ["a", "b"]\nratio = "1/0"\n',
         r"line 3: link #1, 'ratio': ratio '1/0' divides by zero"),
        ('[[mesh]]\ngears = ["a", "b"]\nteeth = [20, 40]\n[planets]\nb = "three"\n',
         r"line 5: \[planets\], 'b': must be a whole number >= 1"),
        ('planets = 3\n', r"line 1: 'planets': \[planets\] must be a table"),
        ('[[mesh]]\ngears = ["a", "b"]\nteeth = [20, 40]\n[planets]\nzz = 2\n',
         r"\[planets\], 'zz': unknown member 'zz'"),
        ('run = [1, 2]\n', r"line 1: 'run': \[run\] must be a table"),
        ('[run]\nfixed = 3\n', r"line 2: \[run\], 'fixed': must be a member name"),
        ('[run]\nspeed = 3\n', r"line 1: \[run\]: unknown keys \['speed'\]"),
        ('[run]\nfriction = 1.5\n', r"'friction': must be a number 0 <= f < 1"),
        ('[run]\ninput = 5\n', r"'input': must be a table"),
        ('coaxial = [["a"]]\n[[mesh]]\ngears = ["a", "b"]\nteeth = [20, 40]\n',
         r"line 1: 'coaxial': coaxial needs two or more different members"),
        ('coaxial = "ab"\n', r"'coaxial': must be a list of member lists"),
        ('[[mesh]]\ngears = ["a", "b"]\nteeth = [20, 40]\nmodul = 2\n',
         r"line 4: mesh #1, 'modul': unknown keys \['modul'\]"),
        ('name = 5\n', r"line 1: 'name': must be a string"),
        ('members = "ab"\n', r"'members': must be a list of member names"),
        ('mesh = 3\n', r"line 1: 'mesh': must be an array of tables"),
    ],
)  # fmt: skip
def test_toml_bad_fields_name_file_line_and_field(tmp_path, text, match):
    p = tmp_path / "bad.toml"
    p.write_text(text)
    with pytest.raises(TrainError, match=match) as err:
        read_train(p)
    assert str(err.value).startswith(str(p))


def test_toml_unreadable_files(tmp_path):
    with pytest.raises(TrainError, match="is a directory"):
        read_train(tmp_path)
    p = tmp_path / "latin1.toml"
    p.write_bytes(b'name = "ok"\n# Zahnr\xe4der\n')
    with pytest.raises(TrainError, match=r"line 2: not UTF-8 text \(byte 19: 0xe4\)"):
        read_train(p)
    with pytest.raises(TrainError, match=r"not valid TOML.*line 1"):
        p.write_text("a = [" * 5)
        read_train(p)
    with pytest.raises(TrainError, match="a TOML table"):
        train_from_dict([1, 2])


@settings(
    max_examples=100, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(st.binary(max_size=300))
def test_read_train_arbitrary_bytes(tmp_path, data):
    # stability (DESIGN quality bars): any bytes give a Train or a TrainError, nothing else
    p = tmp_path / "fuzz.toml"
    p.write_bytes(data)
    try:
        assert isinstance(read_train(p), Train)
    except TrainError:
        pass


_VALUES = st.sampled_from([
    "1", "0", "-3", "2.5", "1e400", "nan", "true", '"x"', '"1/0"', '"-13/3"', "[]", "[1]",
    "[20, 40]", "[20, 0]", '["a", "b"]', '["a"]', '["a", "a"]', "{}", "{ a = 1 }", '{ "a" = "x" }',
    "[[1, 2]]", '[["a", "b"]]', "1979-05-27", "[0.1, 0.2]", "-8", "[60, 20]",
])  # fmt: skip
_KEYS = st.sampled_from([
    "gears", "teeth", "module", "shift", "helix", "face_width", "pressure_angle", "internal",
    "carrier", "name", "members", "ratio", "a", "b", "fixed", "input", "output",
    "mesh_efficiency", "friction", "coaxial", "planets", "run", "mesh",
])  # fmt: skip
_HEADERS = st.sampled_from(["[[mesh]]", "[[link]]", "[[couple]]", "[run]", "[planets]", ""])


@settings(
    max_examples=120, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(st.lists(st.tuples(_HEADERS, st.lists(st.tuples(_KEYS, _VALUES), max_size=5)), max_size=4))
def test_read_train_structured_fuzz(tmp_path, tables):
    # near-valid train files: a Train or a TrainError, never another exception (stability)
    lines = []
    for header, items in tables:
        lines.append(header)
        seen = set()
        for k, v in items:
            if k not in seen:
                seen.add(k)
                lines.append(f"{k} = {v}")
    p = tmp_path / "fuzz.toml"
    p.write_text("\n".join(lines) + "\n")
    try:
        t = read_train(p)
    except TrainError:
        return
    assert isinstance(t, Train)
    report = t.check()  # checking a train that was read never raises either
    assert all(math.isfinite(f.margin) or f.margin == math.inf for f in report.values())


def test_geometric_example_train_exact_ratio():
    # stepped_planetary with real gears through Train.mesh reproduces the catalog's ratio
    # (Ozols Ex 7-4: 1/10000), i.e. the gears only add geometry
    t = Train()
    t.mesh("1", "2", gears=(Gear(100, 1), Gear(101, 1)), carrier="H")
    t.mesh("2", "3", gears=(Gear(100, 1), Gear(99, 1)), carrier="H")
    cat = stepped_planetary(100, 101, 100, 99, meshes=("external", "external"))
    assert t.ratio("1", "H", fixed=["3"]) == cat.ratio("1", "H", fixed=["3"]) == F(1, 10000)


def test_figure_script_runs(tmp_path):
    # docs/make_train_figures.py draws the docs figure (examples/train_reverted_reducer.py is
    # run by tests/test_examples.py)
    pytest.importorskip("matplotlib")
    import runpy

    mod = runpy.run_path(str(ROOT / "docs" / "make_train_figures.py"))
    (path,) = mod["main"](tmp_path)
    assert path.name == "train_reverted_reducer.png" and path.stat().st_size > 10_000


@pytest.mark.parametrize(
    ("scheme", "sun", "planet", "ring"),
    [
        ("simple", 18, 45, 108),  # lectures §4.3 course example
        ("stepped", 26, (70, 21), 117),  # lectures §4.3, scheme B
        ("external", 100, (101, 100), 99),  # Ozols Ex 7-4 (David)
        ("internal", 100, (30, 28), 98),  # scheme D, z3 = z1 - z2 + z2' (lectures §4.2)
    ],
)
def test_planetary_builds_its_train_from_its_gears(scheme, sun, planet, ring):
    # Planetary.train goes through Train.mesh(gears=/pair=): the same GearPairs, so the general
    # Train.check reports each mesh exactly as Planetary.check does, and the same assembly verdict
    p = Planetary(sun, planet, ring, n_planets=2, module=1, scheme=scheme)
    t = p.train
    assert t.pairs == p.meshes
    r, rp = t.check(), p.check()
    for name in p.meshes:
        mine = {k: f.margin for k, f in r.items() if k.startswith(name + ".")}
        theirs = {k: f.margin for k, f in rp.items() if k.startswith(name + ".")}
        assert mine == pytest.approx(theirs, rel=1e-12)  # the same GearPair formulas
    assert r["planet.assembly"].ok == rp["assembly"].ok
    assert r["coaxiality(sun, ring)"].ok == rp["coaxiality"].ok


@settings(max_examples=60, deadline=None)
@given(
    z=st.lists(st.integers(6, 120), min_size=4, max_size=4),
    m=st.sampled_from([0.5, 1.0, 2.0, 5.0]),
    split=st.sampled_from(["keep", "proportional"]),
    extra=st.floats(-3.0, 3.0),
)
def test_coaxial_shifts_property(z, m, split, extra):
    # stability (DESIGN quality bars): any two external meshes and a target distance near the
    # larger reference distance give pairs at that distance to 1e-9 mm or a TrainError; no NaN
    meshes = [(Gear(z[0], m), Gear(z[1], m)), (Gear(z[2], m), Gear(z[3], m))]
    target = max(z[0] + z[1], z[2] + z[3]) * m / 2 + extra * m
    try:
        pairs = coaxial_shifts(meshes, center_distance=target, split=split)
    except TrainError:
        return
    for p in pairs:
        assert abs(p.center_distance - target) < 1e-9
        assert all(math.isfinite(g.profile_shift) for g in p.mounted)


def test_closed_differential_friction_equals_per_mesh_mapping():
    # Ozols Ex 7-7 on real gears: friction= is the same Kreines power flow as giving each mesh
    # its GearPair.mesh_efficiency by name (Ozols (14.25)); derivation: same etas, same solver
    f = 0.08
    real, counts = _ozols_7_7(True), _ozols_7_7(False)
    etas = {n: p.mesh_efficiency(f) for n, p in real.pairs.items()}
    a = power_flow(real, "1", "4", friction=f)
    b = power_flow(counts, "1", "4", mesh_efficiency=etas)
    assert a.efficiency == pytest.approx(b.efficiency, rel=1e-14)
    assert a.torques == pytest.approx(b.torques, rel=1e-13)
    # every mesh loses, so the hoist is less efficient than its best mesh (sanity bound)
    assert a.efficiency < min(etas.values())


def test_coaxiality_through_a_coupled_layshaft():
    # the reverted train with its layshaft as two coupled members (w_lay1 = w_lay2: one shaft,
    # one axis): the same chain in - lay - out, a_w 57 vs 58 mm at zero shift (derivation)
    t = Train()
    t.mesh("in", "lay1", gears=(Gear(17, 2), Gear(40, 2)))
    t.couple("lay1", "lay2")
    t.mesh("lay2", "out", gears=(Gear(20, 2), Gear(38, 2)))
    t.coaxial("in", "out")
    assert t.check()["coaxiality(in, out)"].margin == pytest.approx(-0.99, abs=1e-12)
