"""Loads in a train (trains/loading.py): Ozols section 11-2 and statics in every example train.

Sources: Ozols, *Mehanismu un masinu teorija* (1974) section 11-2: (11.8) the mesh reaction
R = M1 / (r1 cos alpha), (11.9) the idler's bearing 2 R cos alpha, (11.10) the two-stage train
R23 = R12 r2 / r2', (11.11) three planets R = M1 / (3 r1 cos alpha), the pin
sqrt(J^2 + (2 R cos alpha)^2) and M_H = M1 (1 + r3 / r1). Statics (independent of the code's
route): every member's forces and torques balance, Newton's third law per mesh, and the frame's
bearings carry no net force (every mesh force and pin force is internal to the train);
Joldasbekov Ch. VIII section 12: the stepped planet's two reactions balance about its axis.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import Gear, GearPair
from trains import (
    Train,
    TrainError,
    coaxial_shifts,
    double_planet,
    khv,
    loads,
    read_train,
    simple_planetary,
    stepped_planetary,
    strain_wave,
    wolfrom,
)
from trains.catalog import bevel_differential, biplanetary

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
COS20 = math.cos(math.radians(20))


def _idler() -> Train:
    t = Train()
    t.mesh("1", "2", teeth=(20, 30))
    t.mesh("2", "3", teeth=(30, 40))
    return t


def test_ozols_11_9_idler_bearing():
    # M1 = 100 N m, r1 = 50 mm (z = 20, m = 5), alpha = 20 deg, centres on one line:
    # R = 2128.36 N, idler bearing R42 = 2 R cos alpha = 4000 N; M3 = M1 i13 = 200 N m
    ld = loads(_idler(), "1", "3", torque=100, module=5)
    for mesh in ld.meshes.values():
        assert mesh.normal[0] == pytest.approx(2128.36, abs=0.005)
    r = 100 / (0.05 * COS20)
    assert ld.members["2"].radial_load == pytest.approx(2 * r * COS20, rel=1e-12)
    assert ld.members["2"].radial_load == pytest.approx(4000.0, rel=1e-12)
    assert ld.members["3"].torque == pytest.approx(-200.0, rel=1e-12)
    # the idler's two mesh forces are equal and parallel: their radial parts cancel (11.9)
    f = ld.meshes["1-2"].forces["2"][0] + ld.meshes["2-3"].forces["2"][0]
    assert f[0] == pytest.approx(0.0, abs=1e-9) and abs(f[1]) == pytest.approx(4000.0, rel=1e-12)


def test_idler_at_an_angle_carries_the_vector_sum():
    # independent: the two forces of magnitude R along lines of action turned by 90 deg
    # (an idler reached at right angles) add as vectors
    ld = loads(_idler(), "1", "3", torque=100, module=5, angles={"2-3": 90.0})
    a = ld.meshes["1-2"].forces["2"][0]
    b = ld.meshes["2-3"].forces["2"][0]
    assert np.linalg.norm(a) == pytest.approx(np.linalg.norm(b), rel=1e-12)
    assert ld.members["2"].radial_load == pytest.approx(np.linalg.norm(a + b), rel=1e-12)
    assert ld.members["3"].position[:2] == pytest.approx([125.0, 175.0], abs=1e-9)


def test_ozols_11_10_two_stage_shaft():
    # Ozols (11.10): R23 = R12 r2 / r2' = M1 r2 / (r1 r2' cos alpha), M3 = M1 r2 r3 / (r1 r2')
    t = Train()
    t.mesh("1", "2", teeth=(20, 40))
    t.mesh("2", "3", teeth=(15, 45))  # member 2 is the stepped shaft: gears 2 and 2'
    ld = loads(t, "1", "3", torque=100, module=4)
    r1, r2, r2p, r3 = 40.0, 80.0, 30.0, 90.0
    r12 = 100 / (r1 / 1000 * COS20)
    assert ld.meshes["1-2"].normal[0] == pytest.approx(r12, rel=1e-12)
    assert ld.meshes["2-3"].normal[0] == pytest.approx(r12 * r2 / r2p, rel=1e-12)
    assert ld.members["3"].torque == pytest.approx(-100 * r2 * r3 / (r1 * r2p), rel=1e-12)


def test_ozols_11_11_three_planets_and_centrifugal_pin():
    # Ozols (11.11): sun 1, planets 2 (three), fixed ring 3: R = M1 / (3 r1 cos alpha), the pin
    # carries 2 R cos alpha (and with the centrifugal force J, sqrt(J^2 + (2 R cos alpha)^2)),
    # M_H = M1 (1 + r3 / r1); symmetric planets leave the sun and carrier bearings unloaded
    t = simple_planetary(20, 30, 80, n_planets=3)
    m1, r1, r3 = 100.0, 50.0, 200.0
    ld = loads(t, "sun", "carrier", fixed=["ring"], torque=m1, module=5)
    r = m1 / (3 * r1 / 1000 * COS20)
    assert ld.meshes["sun-planet"].normal[0] == pytest.approx(r, rel=1e-12)
    assert ld.meshes["planet-ring"].normal[0] == pytest.approx(r, rel=1e-12)
    assert ld.members["planet"].radial_load == pytest.approx(2 * r * COS20, rel=1e-12)
    assert ld.members["carrier"].torque == pytest.approx(-m1 * (1 + r3 / r1), rel=1e-12)
    for member in ("sun", "carrier", "ring"):
        assert ld.members[member].radial_load == pytest.approx(0.0, abs=1e-9 * r)
    j = 350.0
    ld = loads(t, "sun", "carrier", fixed=["ring"], torque=m1, module=5, centrifugal={"planet": j})
    pin = math.hypot(j, 2 * r * COS20)
    assert ld.members["planet"].radial_load == pytest.approx(pin, rel=1e-12)
    assert ld.members["carrier"].radial_load == pytest.approx(0.0, abs=1e-9 * r)


def test_one_planet_loads_sun_and_carrier():
    # one planet: nothing cancels; the sun's bearing carries the sun mesh force (R) and the
    # carrier's the planet's pin (2 R cos alpha), Ozols (11.8)
    ld = loads(
        simple_planetary(20, 30, 80, n_planets=1),
        "sun",
        "carrier",
        fixed=["ring"],
        torque=100,
        module=5,
    )
    r = 100 / (0.05 * COS20)
    assert ld.members["sun"].radial_load == pytest.approx(r, rel=1e-12)
    assert ld.members["carrier"].radial_load == pytest.approx(2 * r * COS20, rel=1e-12)


# every train of examples/ (kinematic meshes get a module; stepped planets a module per mesh
# so that their two meshes close at one centre distance)
TRAINS = {
    "simple planetary": (
        simple_planetary(20, 30, 80, n_planets=3),
        "sun",
        "carrier",
        ["ring"],
        2.0,
    ),
    "double planet": (double_planet(20, 15, 17, 70, n_planets=3), "carrier", "ring", ["sun"], 2.0),
    "wolfrom": (
        wolfrom(20, 30, 80, 29, 77, n_planets=3),
        "sun",
        "ring2",
        ["ring1"],
        {"sun-planet": 2.0, "planet-ring1": 2.0, "planet-ring2": 50 / 24},
    ),
    "khv": (khv(49, 50), "carrier", "output", ["ring"], 2.0),
    "strain wave": (strain_wave(200, 202), "generator", "flexspline", ["rigid"], 0.5),
    "david": (
        stepped_planetary(100, 101, 100, 99, meshes=("external", "external")),
        "H",
        "1",
        ["3"],
        {"1-2": 2.0, "2-3": 2 * 201 / 199},
    ),
    "stepped": (
        stepped_planetary(20, 40, 30, 90, n_planets=3),
        "1",
        "H",
        ["3"],
        {"1-2": 2.0, "2-3": 2.0},
    ),
    "closed differential": (
        read_train(EXAMPLES / "train_closed_differential.toml"),
        "1",
        "4",
        [],
        {"1-2": 2.0, "2-3": 2 * 76 / 57, "3-5": 2.0, "5-4": 2.0},
    ),
    "bevel differential": (bevel_differential(), "carrier", "left", ["right"], None),
}


def _reverted() -> Train:
    p12, p34 = coaxial_shifts(
        [
            (Gear(17, 2, face_width=20), Gear(40, 2, face_width=20)),
            (Gear(20, 2, face_width=22), Gear(38, 2, face_width=20)),
        ]
    )
    t = Train()
    t.mesh("in", "lay", pair=p12)
    t.mesh("lay", "out", pair=p34)
    t.coaxial("in", "out")
    return t


TRAINS["reverted reducer (real gears)"] = (_reverted(), "in", "out", [], None)
TRAINS["helical pair (real gears)"] = (None, "a", "b", [], None)


def _train(name):
    t, i, o, fx, mod = TRAINS[name]
    if t is None:
        t = Train()
        t.mesh("a", "b", pair=GearPair(Gear(19, 3, helix_angle=15), Gear(53, 3, helix_angle=-15)))
    return t, i, o, fx, mod


def _assert_statics(ld, torque):
    scale = max(1.0, max(np.abs(m.force).max() for m in ld.members.values()))
    for m in ld.members.values():
        # torques balance about every member's axis (N m; forces in N at lever arms in mm)
        assert m.moment + m.torque == pytest.approx(0.0, abs=1e-10 * scale * 1e3), m.name
        np.testing.assert_allclose(m.force + m.bearing, 0.0, atol=1e-12 * scale)
    for mesh in ld.meshes.values():
        if mesh.forces:  # Newton's third law, copy by copy
            a, b = mesh.forces.values()
            np.testing.assert_allclose(a, -b, atol=1e-12 * scale)
    held = [m.bearing for m in ld.members.values() if m.carried_by == "frame"]
    np.testing.assert_allclose(np.sum(held, axis=0), 0.0, atol=1e-9 * scale)


@pytest.mark.parametrize("efficiency", [None, 0.97])
@pytest.mark.parametrize("name", sorted(TRAINS))
def test_statics_balance_in_every_example_train(name, efficiency):
    t, i, o, fx, mod = _train(name)
    ld = loads(t, i, o, fixed=fx, torque=25.0, module=mod, mesh_efficiency=efficiency)
    _assert_statics(ld, 25.0)


def test_bearing_reactions_of_a_helical_shaft():
    # independent hand calculation: a helical pinion at mid-span (bearings at 0 and 100 mm,
    # the gear at 50 mm): the axial force F_a at the pitch radius r_w adds a moment F_a r_w,
    # so the radial reactions are F_r / 2 -+ F_a r_w / L and the tangential ones F_t / 2
    pair = GearPair(Gear(19, 3, helix_angle=15), Gear(53, 3, helix_angle=-15))
    t = Train()
    t.mesh("a", "b", pair=pair)
    ld = loads(t, "a", "b", torque=40.0, axial={"a-b": 50.0}, bearings={"a": (0.0, 100.0)})
    f = ld.meshes["a-b"]
    ft, fr, fa = f.tangential[0], f.radial[0], f.axial[0]
    rw = pair.working_diameters[0] / 2
    ra, rb = ld.members["a"].reactions
    assert sorted([ra[0], rb[0]]) == pytest.approx(
        sorted([fr / 2 - fa * rw / 100, fr / 2 + fa * rw / 100]), rel=1e-12
    )
    assert ra[1] == pytest.approx(ft / 2, rel=1e-12) and rb[1] == pytest.approx(ft / 2, rel=1e-12)
    assert abs(ra[2]) == pytest.approx(fa, rel=1e-12) and rb[2] == 0.0


def test_table_and_html():
    ld = loads(_idler(), "1", "3", torque=100, module=5)
    text = str(ld)
    assert "4000.00" in text and "F_t [N]" in text
    assert ld._repr_html_().count("<table>") == 2


@pytest.mark.parametrize(
    "kwargs, name",
    [
        ({}, "module"),
        ({"module": -1.0}, "module"),
        ({"module": 5, "angles": {"nope": 1.0}}, "angles"),
        ({"module": 5, "angles": {"1-2": float("nan")}}, "angles"),
        ({"module": 5, "bearings": {"2": (1.0, 1.0)}}, "bearings"),
        ({"module": 5, "torque": "1"}, "torque"),
        ({"module": 5, "pressure_angle": 95}, "pressure_angle"),
        ({"module": {"1-2": 5}}, "2-3"),
    ],
)
def test_bad_input_is_a_train_error_naming_it(kwargs, name):
    with pytest.raises(TrainError, match=name):
        loads(_idler(), "1", "3", **kwargs)


def test_a_train_that_does_not_close_is_refused():
    # a stepped planet 20/40 + 30/80 at one module: a_w 60 and 50 mm cannot both hold
    with pytest.raises(TrainError, match="does not close"):
        loads(stepped_planetary(20, 40, 30, 80), "1", "H", fixed=["3"], module=2)


def test_carriers_on_carriers_are_refused():
    with pytest.raises(TrainError, match="biplanetary"):
        loads(biplanetary(60, 20, 10, 5), "1", "H", fixed=["3"], module=2)


@settings(max_examples=25, deadline=None)
@given(
    sun=st.integers(12, 40),
    planet=st.integers(12, 40),
    n=st.integers(1, 5),
    torque=st.floats(-1e4, 1e4).filter(lambda x: abs(x) > 1e-6),
    eta=st.one_of(st.none(), st.floats(0.5, 1.0)),
    module=st.floats(0.2, 20),
    inp=st.sampled_from(
        [
            ("sun", "carrier", "ring"),
            ("carrier", "sun", "ring"),
            ("sun", "ring", "carrier"),
            ("ring", "carrier", "sun"),
        ]
    ),
)
def test_property_planetary_statics(sun, planet, n, torque, eta, module, inp):
    # a finite answer or the library's own error, and statics that balance
    t = simple_planetary(sun, planet, sun + 2 * planet, n_planets=n)
    i, o, f = inp
    try:
        ld = loads(t, i, o, fixed=[f], torque=torque, module=module, mesh_efficiency=eta)
    except TrainError:
        return
    for m in ld.members.values():
        assert np.all(np.isfinite(m.force)) and math.isfinite(m.moment)
    _assert_statics(ld, torque)


@pytest.mark.parametrize(
    "angles, sharing",
    [
        ((0.0, 120.0, 240.0), None),
        ((0.0, 110.0, 240.0), None),
        ((0.0, 120.0, 240.0), 1.16),
        ((0.0, 100.0, 230.0), 1.3),
    ],
)
def test_unequal_spacing_and_sharing_load_sun_and_carrier(angles, sharing):
    # independent: every planet presses on the sun with the same in-plane force turned by its
    # angle and scaled by its share s_k, so the sun's bearing carries
    # |sum_k s_k exp(i theta_k)| times the whole mesh force (zero for equal spacing and shares)
    t = simple_planetary(20, 30, 80, n_planets=3)
    kw = {"planet_angles": {"planet": angles}}
    if sharing:
        kw["load_sharing"] = {"planet": sharing}
    ld = loads(t, "sun", "carrier", fixed=["ring"], torque=100, module=5, **kw)
    _assert_statics(ld, 100)
    shares = [1 / 3] * 3 if not sharing else [sharing / 3] + [(3 - sharing) / 6] * 2
    whole = 100 / (0.05 * COS20)  # Ozols (11.8) for the whole sun torque
    turn = abs(sum(s * np.exp(1j * np.radians(a)) for s, a in zip(shares, angles, strict=True)))
    assert ld.members["sun"].radial_load == pytest.approx(whole * turn, rel=1e-9, abs=1e-9)
    assert ld.meshes["sun-planet"].normal[0] == pytest.approx(whole * shares[0], rel=1e-12)


@pytest.mark.parametrize(
    "kwargs, name",
    [
        ({"planet_angles": {"planet": (0.0, 1.0)}}, "planet_angles"),
        ({"load_sharing": {"planet": 4.0}}, "load_sharing"),
        ({"load_sharing": {"sun": 1.0}}, "load_sharing"),
        ({"centrifugal": {"planet": float("inf")}}, "centrifugal"),
    ],
)
def test_bad_planet_options(kwargs, name):
    with pytest.raises(TrainError, match=name):
        loads(
            simple_planetary(20, 30, 80, n_planets=3),
            "sun",
            "carrier",
            fixed=["ring"],
            module=5,
            **kwargs,
        )


def test_figure_draws_every_mesh_force_and_bearing():
    pytest.importorskip("matplotlib")
    import matplotlib.pyplot as plt

    ld = loads(
        simple_planetary(20, 30, 80, n_planets=3),
        "sun",
        "carrier",
        fixed=["ring"],
        torque=100,
        module=5,
    )
    fig = ld.figure()
    # 6 mesh forces (2 meshes x 3 planets) and the planet's pin: arrow and label each
    assert len(fig.axes[0].texts) == 2 * 7
    plt.close(fig)


def test_joldasbekov_planet_block_balance():
    # Joldasbekov Ch. VIII section 12 (Fig. 255): the stepped planet's two mesh reactions
    # balance about its axis, R12 r2 cos a = R32' r2' cos a', and wheel 3 gives
    # R2'3 = M3 / (r3 cos a'); here sun 1 (20) drives planet 2 (40), 2' (30) rolls in ring 3 (90)
    t = stepped_planetary(20, 40, 30, 90, n_planets=3)
    ld = loads(t, "1", "H", fixed=["3"], torque=60.0, module=2.0)
    r2, r2p = 40.0, 30.0
    f12, f23 = ld.meshes["1-2"].tangential[0], ld.meshes["2-3"].tangential[0]
    assert f12 * r2 == pytest.approx(f23 * r2p, rel=1e-12)
    m3 = ld.members["3"].torque / 3  # the ring's holding torque per planet
    assert ld.meshes["2-3"].normal[0] == pytest.approx(abs(m3) / (0.090 * COS20), rel=1e-12)


def test_too_many_planets_is_refused_before_the_work():
    with pytest.raises(TrainError, match="at most 1000"):
        loads(
            simple_planetary(20, 30, 80, n_planets=10**7),
            "sun",
            "carrier",
            fixed=["ring"],
            module=2,
        )
