"""power_flow and Planetary.efficiency with the mesh efficiencies of their gears at the operating
point (mesh_efficiency="gears" or a callable; issue 30).

Sources: for a fixed-axis train, the product of the mesh efficiencies (Ozols (14.10)) with each
mesh's efficiency computed here from its own torque; for a planetary stage (ring fixed, sun
driving) Kreines' formula eta_1H = (1 + |i0| eta0) / (1 + |i0|) (Müller; Ozols (14.26)) with the
basic efficiency eta0 the product of the two meshes', each at the torque a planet copy carries.
"""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import Gear, GearPair
from trains import Planetary, Train, power_flow
from trains.errors import TrainError


def test_fixed_axis_train_is_the_product_of_its_meshes():
    a, b = Gear(19, 3, face_width=30), Gear(61, 3, face_width=30)
    c, d = Gear(17, 4, face_width=40), Gear(53, 4, face_width=40)
    t = Train()
    t.mesh("in", "mid", gears=(a, b))
    t.mesh("mid", "out", gears=(c, d))
    torque, speed = 250.0, 1450.0
    pf = power_flow(t, "in", "out", mesh_efficiency="gears", input_torque=torque, input_speed=speed)
    # by hand: the first mesh at the input torque; the second at the torque mesh 1 delivers
    e1 = GearPair(a, b).efficiency(torque, speed).efficiency
    t2, n2 = torque * 61 / 19 * e1, speed * 19 / 61
    e2 = GearPair(c, d).efficiency(t2, n2).efficiency
    assert pf.efficiency == pytest.approx(e1 * e2, rel=1e-9)
    assert pf.relations["in-mid"].efficiency == pytest.approx(e1, rel=1e-9)


def _stage():
    return Planetary(
        Gear(20, 2, face_width=20),
        Gear(31, 2, face_width=20),
        Gear(82, 2, internal=True, face_width=20),
        n_planets=3,
    )


def test_planetary_from_its_gears_against_kreines():
    p = _stage()
    torque, speed = 60.0, 1500.0
    eta = p.efficiency(mesh_efficiency="gears", torque=torque, speed=speed)
    # by hand: ring fixed, sun in; the carrier turns at n / (1 + 82/20), the sun at n - n_H
    # relative to it; each of 3 planet copies takes T/3 at the sun mesh and passes
    # T/3 (31/20) eta_sp to the ring mesh (the planet idles in the carrier frame)
    i0 = 82 / 20
    n_h = speed / (1 + i0)
    sun_planet = GearPair(p.sun, p.planet)
    e_sp = sun_planet.efficiency(torque / 3, speed - n_h).efficiency
    planet_ring = GearPair(p.planet, p.ring)
    e_pr = planet_ring.efficiency(torque / 3 * 31 / 20 * e_sp, (speed - n_h) * 20 / 31).efficiency
    kreines = (1 + i0 * e_sp * e_pr) / (1 + i0)
    assert eta == pytest.approx(kreines, rel=1e-9)
    # the same through a callable with the defaults
    same = p.efficiency(mesh_efficiency=lambda pr, t, n: pr.efficiency(t, n).efficiency,
                        torque=torque, speed=speed)  # fmt: skip
    assert same == pytest.approx(eta, rel=1e-12)


def test_callable_constant_is_the_constant_efficiency():
    p = _stage()
    const = p.efficiency(mesh_efficiency=0.985)
    via = p.efficiency(mesh_efficiency=lambda pr, t, n: 0.985, torque=10.0, speed=100.0)
    assert via == pytest.approx(const, rel=1e-12)


@pytest.mark.parametrize(
    "kw, match",
    [
        ({"mesh_efficiency": "teeth", "torque": 1.0, "speed": 1.0}, "mesh_efficiency"),
        ({"mesh_efficiency": "gears"}, "torque"),
        ({"mesh_efficiency": "gears", "torque": -1.0, "speed": 1.0}, "torque"),
        ({"mesh_efficiency": lambda p, t, n: 1.5, "torque": 1.0, "speed": 1.0}, "valid is"),
        ({"mesh_efficiency": lambda p, t, n: "x", "torque": 1.0, "speed": 1.0}, "valid is"),
    ],
)
def test_bad_operating_efficiency(kw, match):
    with pytest.raises(TrainError, match=match):
        _stage().efficiency(**kw)


@settings(max_examples=20, deadline=None)
@given(st.floats(1e-3, 1e5), st.floats(1e-2, 1e5), st.sampled_from(["ring", "sun", "carrier"]))
def test_planetary_gears_efficiency_property(torque, speed, fixed):
    try:
        eta = _stage().efficiency(fixed=fixed, mesh_efficiency="gears", torque=torque, speed=speed)
    except TrainError:
        return
    assert math.isfinite(eta) and eta <= 1.0


def test_gears_model_leaves_worm_meshes_to_their_own_efficiency():
    # "gears" rates spur and helical meshes only; a worm mesh keeps its friction estimate
    from gears import WormPair

    a, b = Gear(19, 3, face_width=30), Gear(61, 3, face_width=30)
    t = Train()
    t.mesh("in", "mid", gears=(a, b))
    t.mesh("mid", "out", pair=WormPair(2, 40, 4, diameter_quotient=10))
    kw = dict(input_torque=50.0, input_speed=1450.0, friction=0.05)
    pf = power_flow(t, "in", "out", mesh_efficiency="gears", **kw)
    plain = power_flow(t, "in", "out", **kw)
    first = GearPair(a, b).efficiency(50.0, 1450.0).efficiency
    assert pf.relations["in-mid"].efficiency == pytest.approx(first, rel=1e-9)
    worm = plain.relations["mid-out"].efficiency
    assert pf.relations["mid-out"].efficiency == pytest.approx(worm, rel=1e-12)
