"""Loads of a planetary stage (trains.loading.planetary_loads, Planetary.loads).

Sources: Ozols, *Mehanismu un masinu teorija* (1974) section 11-2 (11.11): three planets,
R = M1 / (3 r1 cos alpha), the planet's centrifugal force J2 = AO omega_H^2 m2, the pin
reaction sqrt(J2^2 + (2 R cos alpha)^2), M_H = M1 (1 + r3 / r1); the mass by hand: the
density times the volume of the planet's triangulated solid (Gear.mesh, an independent route
from the outline's area); statics (the sum of the turned planet forces).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import MATERIALS, Gear
from trains import Planetary, TrainError
from trains.loading import planetary_loads, solid_mass

COS20 = math.cos(math.radians(20))
STEEL = MATERIALS["case-carburized"].density  # kg/mm^3


def test_centrifugal_force_by_hand_from_the_solid():
    # sun 21, planets 36 (three, equally spaced: (21 + 93) / 3 = 38), ring 93, m = 2, b = 20 mm;
    # 1500 rpm at the sun, ring fixed: n_H = 1500 / (1 + 93/21) rpm; rho = a_w = 57 mm;
    # m2 = density x volume of the planet's triangulated solid
    pytest.importorskip("trimesh")
    p = Planetary(21, 36, 93, n_planets=3, module=2)
    assert p.placement().planet_angles == pytest.approx((0.0, 120.0, 240.0), abs=1e-12)
    ld = planetary_loads(p, "sun", "arm", "ring", 100.0, 1500.0, 1.0, face_width=20)
    volume = Gear(36, 2).mesh(face_width=20, tolerance=0.02).volume  # mm^3, triangulated
    mass = volume * STEEL
    assert ld.notes["planet mass [kg]"] == pytest.approx(mass, rel=1e-6)
    omega = 2 * math.pi * 1500 / (1 + 93 / 21) / 60
    j = mass * omega**2 * 0.057  # N: kg (rad/s)^2 m
    assert ld.notes["centrifugal force [N]"] == pytest.approx(j, rel=1e-6)
    # Ozols (11.11): the pin carries sqrt(J^2 + (2 R cos alpha)^2), the carrier M1 (1 + r3/r1)
    r = 100.0 / (3 * 0.021 * COS20)
    assert ld.members["planet"].radial_load == pytest.approx(math.hypot(j, 2 * r * COS20), rel=1e-6)
    assert ld.notes["carrier torque [N m]"] == pytest.approx(-100 * (1 + 93 / 21), rel=1e-12)
    assert ld.notes["output torque (balancing moment) [N m]"] == pytest.approx(
        -100 * (1 + 93 / 21), rel=1e-12
    )
    # symmetric planets: no net radial force on the sun or the carrier
    assert ld.notes["net radial force on sun [N]"] == pytest.approx(0.0, abs=1e-9 * r)
    assert ld.notes["net radial force on arm [N]"] == pytest.approx(0.0, abs=1e-9 * r)
    # the most loaded planet with K_gamma = 1.3: its mesh forces and its pin's mesh part scale
    k = planetary_loads(p, "sun", "arm", "ring", 100.0, 1500.0, 1.3, face_width=20).notes
    assert k["most loaded planet: sun-planet F_n [N]"] == pytest.approx(1.3 * r, rel=1e-12)
    pin = math.hypot(j, 1.3 * 2 * r * COS20)
    assert k["most loaded planet: pin load [N]"] == pytest.approx(pin, rel=1e-6)


def test_given_mass_and_one_planet():
    # one planet: the sun carries R (Ozols (11.8)) and the carrier the pin with J outwards
    p = Planetary(20, 30, 80, n_planets=1, module=2)
    ld = planetary_loads(p, "sun", "arm", "ring", 100.0, 1500.0, 1.0, planet_mass=2.0)
    r = 100.0 / (0.020 * COS20)
    j = 2.0 * (2 * math.pi * 300 / 60) ** 2 * 0.050
    assert ld.notes["net radial force on sun [N]"] == pytest.approx(r, rel=1e-9)
    pin = ld.members["planet"].bearing
    # the pin pushes the planet inwards against J and the two mesh forces (2 R cos alpha, y)
    assert -pin[0] == pytest.approx(j, rel=1e-9)
    assert abs(pin[1]) == pytest.approx(2 * r * COS20, rel=1e-9)
    assert ld.notes["net radial force on arm [N]"] == pytest.approx(
        math.hypot(j, 2 * r * COS20), rel=1e-9
    )


def test_unequal_spacing_and_load_sharing():
    # 20/31/82 with four planets does not assemble evenly: the placement's angles; independent:
    # the sun carries |sum_k s_k exp(i theta_k)| times the whole mesh force
    p = Planetary(20, 31, 82, n_planets=4, module=2)
    angles = p.placement().planet_angles
    assert max(abs(a - 90 * k) for k, a in enumerate(angles)) > 0.1
    for k_gamma in (1.0, 1.25):
        ld = planetary_loads(
            p, "sun", "arm", "ring", 100.0, 1000.0, k_gamma, planet_mass=0.3, unequal_sharing=True
        )
        shares = [k_gamma / 4] + [(4 - k_gamma) / 12] * 3
        whole = 100.0 / (0.020 * COS20)
        turn = abs(
            sum(s * np.exp(1j * math.radians(a)) for s, a in zip(shares, angles, strict=True))
        )
        assert ld.notes["net radial force on sun [N]"] == pytest.approx(whole * turn, rel=1e-9)
        assert ld.meshes["sun-planet"].normal[0] == pytest.approx(whole * shares[0], rel=1e-12)


def test_double_planet_balances():
    p = Planetary(20, (18, 16), 52, n_planets=3, module=2, scheme="double-planet")
    ld = planetary_loads(p, "sun", "ring", "arm", 50.0, 1000.0, 1.0, planet_mass=0.2)
    for m in ld.members.values():
        assert m.moment + m.torque == pytest.approx(0.0, abs=1e-9)
    assert "planet mass [kg] (planet2)" in ld.notes


def test_solid_mass_is_outline_area_times_width():
    # a disc check: a gear's outline lies between its root and tip circles
    g = Gear(40, 1.5)
    m = solid_mass(g, 10.0, 1.0)
    assert math.pi / 4 * g.root_diameter**2 * 10 < m < math.pi / 4 * g.tip_diameter**2 * 10


@pytest.mark.parametrize(
    "kwargs, name",
    [
        ({"speed": float("nan")}, "speed"),
        ({"planet_mass": -1.0}, "planet_mass"),
        ({"planet_mass": {"moon": 1.0}}, "planet_mass"),
        ({"torque": 0.0}, "torque"),
    ],
)
def test_bad_input(kwargs, name):
    p = Planetary(20, 30, 80, n_planets=3, module=2)
    args = {"torque": 10.0, "speed": 100.0, "planet_mass": 1.0} | kwargs
    with pytest.raises(TrainError, match=name):
        planetary_loads(
            p, "sun", "arm", "ring", args.pop("torque"), args.pop("speed"), 1.16, **args
        )


@settings(max_examples=15, deadline=None)
@given(
    sun=st.integers(12, 40),
    planet=st.integers(12, 40),
    n=st.integers(1, 4),
    torque=st.floats(-1e4, 1e4),
    speed=st.floats(-1e4, 1e4),
    k=st.floats(1.0, 1.6),
)
def test_property_finite_or_train_error(sun, planet, n, torque, speed, k):
    try:
        p = Planetary(sun, planet, sun + 2 * planet, n_planets=n, module=2)
        ld = planetary_loads(p, "sun", "arm", "ring", torque, speed, min(k, n), planet_mass=0.5)
    except TrainError:
        return
    assert all(math.isfinite(v) for v in ld.notes.values())
    for m in ld.members.values():
        assert np.all(np.isfinite(m.force))


def test_planetary_loads_method_and_roles():
    # Planetary.loads is planetary_loads with the stage's roles, K_gamma and material density
    p = Planetary(21, 36, 93, n_planets=3, module=2)
    a = p.loads(100.0, 1500.0, planet_mass=0.6)
    b = planetary_loads(p, "sun", "arm", "ring", 100.0, 1500.0, 1.16, planet_mass=0.6)
    assert a.members["sun"].radial_load == pytest.approx(0.0, abs=1e-9)  # equal statics
    u = p.loads(100.0, 1500.0, planet_mass=0.6, unequal_sharing=True)
    assert u.members["sun"].radial_load > 1.0  # K_gamma in the statics loads the sun
    with pytest.raises(TrainError, match="unequal_sharing"):
        p.loads(100.0, 1500.0, planet_mass=0.6, unequal_sharing="yes")
    assert a.notes == pytest.approx(b.notes, rel=1e-15)
    # carrier fixed: sun in, ring out; the carrier stands, so no centrifugal force
    c = p.loads(100.0, 1500.0, fixed="carrier", planet_mass=0.6)
    assert c.notes["centrifugal force [N]"] == 0.0
    assert c.notes["output torque (balancing moment) [N m]"] == pytest.approx(100 * 93 / 21)
    with pytest.raises(TrainError, match="material"):
        p.loads(100.0, 1500.0, material="cheese")
    assert "<table>" in a._repr_html_() and "centrifugal force" in str(a)
