"""A planetary stage's loaded tooth contact per mesh and its net transmission error with the
planets' mesh phasing (trains/planetary/contact.py).

Sources: statics of a simple stage (the planet is an idler: the same force along the line of
action at its sun and ring meshes, Ozols (11.11)); Parker and Lin (2004), J. Mech. Des. 126,
mesh phasing: the sun meshes of equally spaced planets are in phase when z_sun / n is an
integer, and the net mesh-order harmonic h cancels when h z / n is not an integer and is n
times one mesh's when it is; a shift by whole samples is np.roll (exact, an independent route
to the Fourier shift).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from trains import Planetary, TrainError
from trains.planetary.contact import mesh_phases, phased_sum


def _stage_contact(z, n=3, **kw):
    kw.setdefault("positions", 48)
    kw.setdefault("slices", 1)
    return Planetary(*z, n_planets=n, module=2).contact(40.0, face_width=20, **kw)


def test_mesh_torques_follow_the_statics_of_the_stage():
    # ring fixed, sun in: each planet's sun mesh carries T / n (times K_gamma); the planet is
    # an idler, so its ring mesh carries the same force along the line of action: torque on
    # the planet = T_sun-mesh r_b,planet / r_b,sun (to 1e-9)
    st_ = Planetary(19, 29, 77, n_planets=3, module=2)
    c = st_.contact(40.0, face_width=20, load_sharing_factor=1.16, positions=16, slices=1)
    assert c.torques["sun-planet"] == pytest.approx(40.0 / 3 * 1.16, rel=1e-9)
    assert c.torques["planet-ring"] == pytest.approx(c.torques["sun-planet"] * 29 / 19, rel=1e-9)
    assert c.meshes["sun-planet"].load == pytest.approx(c.meshes["planet-ring"].load, rel=1e-9)
    assert c.meshes["planet-ring"].pair.internal


@pytest.mark.parametrize(
    ("z", "sequential"),
    [((19, 29, 77), True), ((18, 45, 108), False)],  # 19/3 and 77/3 not integers; 18/3, 108/3
)
def test_net_transmission_error_harmonics_follow_the_mesh_phasing(z, sequential):
    # Parker and Lin (2004): with n equally spaced planets, the net harmonic h of a central
    # gear's meshes is n times one mesh's when h z / n is an integer (in phase) and 0
    # otherwise (sequential phasing cancels it); to 1e-9 of one mesh's amplitude
    c = _stage_contact(z)
    for mesh, teeth in (("sun-planet", z[0]), ("planet-ring", z[2])):
        orders = (1, 2, 3, 6)
        h = c.harmonics(mesh, orders)
        for k, order in enumerate(orders):
            single, net = h["single"][k], h["net"][k]
            assert single > 1e-4  # um: the harmonic exists to cancel
            if (order * teeth) % 3 == 0:
                assert net == pytest.approx(3 * single, rel=1e-9), (mesh, order)
            else:
                assert net == pytest.approx(0.0, abs=1e-9 * single), (mesh, order)
        assert c.in_phase(mesh) is not sequential


def test_phased_sum_equals_whole_sample_shifts():
    # a delay by k of P samples is np.roll by k (exact): the Fourier shift agrees to 1e-12
    rng = np.random.default_rng(7)
    te = rng.normal(size=24)
    phases = np.array([0, 5, 13]) / 24
    expected = sum(np.roll(te, k) for k in (0, 5, 13))
    np.testing.assert_allclose(phased_sum(te, phases), expected, atol=1e-12)
    assert mesh_phases(77, 120.0, ring=True) == pytest.approx((-77 / 3) % 1.0)


def test_unequal_spacing_gives_the_phases_of_its_angles():
    # planets at given angles: the sun mesh of planet i runs z psi_i / 360 cycles after
    # planet 0's (Parker and Lin 2004, eq. 9), here for a spacing the assembly allows
    st_ = Planetary(19, 29, 77, n_planets=3, module=2)
    angles = (0.0, 123.75, 236.25)  # 96 ticks of 3.75 deg: 33 and 63 ticks
    c = st_.contact(40.0, face_width=20, angles=angles, positions=16, slices=1)
    expected = [(19 * a / 360) % 1.0 for a in angles]
    np.testing.assert_allclose(c.phases["sun-planet"], expected, atol=1e-9)
    assert not c.in_phase("sun-planet")


def test_bad_input_is_refused_naming_it():
    st_ = Planetary(19, 29, 77, n_planets=3, module=2)
    with pytest.raises(TrainError, match="torque"):
        st_.contact(-1.0, face_width=20)
    with pytest.raises(TrainError, match="load_sharing_factor"):
        st_.contact(10.0, face_width=20, load_sharing_factor=0.5)
    with pytest.raises(TrainError, match="face_width"):
        st_.contact(10.0)  # the gears have no face width
    c = st_.contact(10.0, face_width=20, positions=8, slices=1)
    with pytest.raises(TrainError, match="mesh"):
        c.harmonics("planet-sun")
    with pytest.raises(TrainError, match="orders"):
        c.harmonics("sun-planet", (5,))


@given(
    st.integers(12, 30),
    st.integers(14, 40),
    st.integers(2, 5),
    st.floats(1e-2, 1e4) | st.sampled_from([0.0, math.inf, -1.0]),
    st.sampled_from(["simple", "stepped", "double-planet"]),
)
@settings(max_examples=15, deadline=None, derandomize=True, database=None,
          suppress_health_check=list(HealthCheck))  # fmt: skip
def test_stage_contact_is_finite_or_refused(z_sun, z_planet, n, torque, scheme):
    try:
        if scheme == "simple":
            st_ = Planetary(z_sun, z_planet, z_sun + 2 * z_planet, n_planets=n, module=2)
        elif scheme == "stepped":
            st_ = Planetary(z_sun, (z_planet, z_planet - 2), z_sun + 2 * z_planet - 2,
                            n_planets=n, module=2, scheme="stepped")  # fmt: skip
        else:
            st_ = Planetary(z_sun, (z_planet, z_planet), z_sun + 4 * z_planet, n_planets=n,
                            module=2, scheme="double-planet")  # fmt: skip
        c = st_.contact(torque, face_width=15, positions=8, slices=1)
    except TrainError:
        return
    for name, m in c.meshes.items():
        assert np.all(np.isfinite(m.transmission_error))
        if c.phases[name] is not None:
            assert np.all(np.isfinite(c.net_transmission_error(name)))
