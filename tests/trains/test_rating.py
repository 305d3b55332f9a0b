"""trains.rating and Planetary.rating: every mesh of a train rated by ISO 6336 (issue 18).

Sources: the statics of the train (power_flow's torques, Ozols §11-2 levers), ISO 6336's
treatment of planets (the load per planet mesh times K_gamma, load cycles per planet pass, idlers
with Y_M), and identities against GearPair.rating of the same mesh.
"""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import Gear, GearPair
from trains import Planetary, Train, TrainError, load_sharing, power_flow, rating


def _stage():
    # sun 21, planet 36, ring 93, three planets, m 2, b 20
    return Planetary(sun=21, planet=36, ring=93, n_planets=3, module=2)


def test_sun_planet_mesh_equals_the_pair_at_its_share_of_the_torque():
    """The sun-planet rating equals its GearPair rated at T_sun / n_planets with K_gamma, the
    sun's speed relative to the carrier, three load cycles per turn on the sun and the planet as
    an idler; and with K_gamma folded into the torque (K_gamma multiplies F_t in every formula
    of ISO 6336) the safeties are the same."""
    stage = _stage()
    t_sun, n_sun = 120.0, 1500.0
    ratings = stage.rating(t_sun, n_sun, face_width=20)
    mesh = ratings["sun-planet"]
    k_gamma = load_sharing(3)
    assert k_gamma == pytest.approx(1.16)
    n_rel = n_sun * (1 - float(1 / stage.ratio()))  # sun relative to the carrier
    pair = stage.meshes["sun-planet"]
    same = pair.rating(t_sun / 3, n_rel, face_width=20, K_gamma=k_gamma, contacts=(3, 1),
                       idler=(False, True))  # fmt: skip
    for name in ("S_H1", "S_H2", "S_F1", "S_F2", "K_v", "K_Hbeta", "Z_NT1", "Y_M2"):
        assert float(getattr(mesh.values, name)) == pytest.approx(
            float(getattr(same.values, name)), rel=1e-12
        ), name
    folded = pair.rating(t_sun / 3 * k_gamma, n_rel, face_width=20, contacts=(3, 1),
                         idler=(False, True))  # fmt: skip
    assert folded.safety_pitting == pytest.approx(mesh.safety_pitting, rel=1e-12)
    assert folded.safety_bending == pytest.approx(mesh.safety_bending, rel=1e-12)
    # the sun counts three load cycles per relative turn (ISO 6336-2 N_L), the planet one
    life_h = 20000.0
    assert mesh.quantities["N_L"][0] == pytest.approx(60 * life_h * n_rel * 3, rel=1e-12)
    assert mesh.quantities["N_L"][1] == pytest.approx(60 * life_h * n_rel * 21 / 36, rel=1e-12)


def test_planet_ring_mesh_loads_and_cycles():
    stage = _stage()
    ratings = stage.rating(120.0, 1500.0, face_width=20)
    mesh = ratings["planet-ring"]
    # the planet's torque per copy: T_sun z_p / (z_s n) (Ozols §11-2 lever: F_t the same)
    assert mesh.settings["torque"] == pytest.approx(120.0 / 3 * 36 / 21, rel=1e-12)
    n_rel = 1500.0 * (1 - float(1 / stage.ratio()))
    assert mesh.settings["speed"] == pytest.approx(n_rel * 21 / 36, rel=1e-12)
    # tangential force on the planet equal in both meshes (no losses)
    f_sun = ratings["sun-planet"].quantities["F_t"]
    assert mesh.quantities["F_t"] == pytest.approx(f_sun, rel=1e-12)
    assert mesh.settings["contacts"] == (1, 3) and mesh.settings["idler"] == (True, False)
    assert mesh.factors["Y_M"] == pytest.approx((0.7, 1.0))
    assert mesh.roots[1] == "measured on the exact envelope (shaper-cut)"


def test_load_sharing_override_and_defaults():
    stage = _stage()
    # with the other load factors pinned, S_F scales as 1 / K_gamma (sigma_F ~ K_gamma F_t)
    pinned = dict(K_v=1.0, K_Hbeta=1.1, K_Fbeta=1.1, K_Halpha=1.0, K_Falpha=1.0)
    given_k = stage.rating(120.0, 1500.0, face_width=20, load_sharing_factor=1.0, **pinned)
    default = stage.rating(120.0, 1500.0, face_width=20, **pinned)
    assert given_k["sun-planet"].factors["K_gamma"] == pytest.approx(1.0)
    assert default["sun-planet"].factors["K_gamma"] == pytest.approx(1.16)
    assert given_k["sun-planet"].safety_bending[0] == pytest.approx(
        default["sun-planet"].safety_bending[0] * 1.16, rel=1e-12
    )
    assert [load_sharing(n) for n in (1, 2, 3, 4, 5, 6)] == pytest.approx(
        [1.0, 1.0, 1.16, 1.25, 1.35, 1.44]
    )
    with pytest.raises(TrainError, match="n_planets"):
        load_sharing(0)


def test_fixed_axis_train_meshes_equal_their_pairs():
    g1, g2, g3 = (Gear(z, 3, face_width=30) for z in (19, 31, 61))
    t = Train()
    t.mesh("in", "idler", gears=(g1, g2))
    t.mesh("idler", "out", gears=(g2, g3))
    r = rating(t, "in", "out", torque=250, speed=1450)
    assert set(r) == {"in-idler", "idler-out"}
    first = GearPair(g1, g2).rating(250, 1450, idler=(False, True))
    assert r["in-idler"].safety_pitting == pytest.approx(first.safety_pitting, rel=1e-12)
    # the idler passes the force on: its mesh with the output has gear 1 = the idler
    second = r["idler-out"]
    assert second.settings["torque"] == pytest.approx(250 * 31 / 19, rel=1e-12)
    assert second.settings["speed"] == pytest.approx(1450 * 19 / 31, rel=1e-12)
    assert second.factors["Y_M"] == pytest.approx((0.7, 1.0))  # the idler, both flanks
    flow = power_flow(t, "in", "out", input_torque=250, input_speed=1450)
    assert flow.relations["idler-out"].torques["out"] == pytest.approx(250 * 61 / 19)


def test_meshes_without_gears_or_load_are_left_out_and_refusals():
    t = Train()
    t.mesh("a", "b", teeth=(20, 40))
    with pytest.raises(TrainError, match="no mesh of real gears"):
        rating(t, "a", "b", torque=10, speed=100)
    t2 = Train()
    t2.mesh("a", "b", gears=(Gear(20, 2, face_width=20), Gear(40, 2, face_width=20)))
    for bad in (0, -1, math.nan, "x"):
        with pytest.raises(TrainError, match="torque"):
            rating(t2, "a", "b", torque=bad, speed=100)
    with pytest.raises(TrainError, match="speed"):
        rating(t2, "a", "b", torque=10, speed=0)
    with pytest.raises(TrainError, match="mesh a-b: face_width"):
        t3 = Train()
        t3.mesh("a", "b", gears=(Gear(20, 2), Gear(40, 2)))
        rating(t3, "a", "b", torque=10, speed=100)


def test_ozols_7_7_hoist_every_mesh_rated():
    """The closed differential of Ozols example 7-7 with real gears (m 4, b 40): every mesh is
    rated, the torques follow the statics and the idler 5 is an idler."""
    m, b = 4, 40

    def g(z, internal=False):
        return Gear(z, m, face_width=b, internal=internal)

    t = Train()
    t.mesh("1", "2", gears=(g(24), g(52)), carrier="4")
    t.mesh("2", "3", gears=(g(21), g(78, True)), carrier="4")
    t.mesh("3", "5", gears=(g(18), g(30)))
    t.mesh("5", "4", gears=(g(30), g(78, True)))
    r = rating(t, "1", "4", torque=50, speed=880, fixed=[])
    assert set(r) == {"1-2", "2-3", "3-5", "5-4"}
    assert r["3-5"].settings["idler"] == (False, True)
    assert r["5-4"].settings["idler"] == (True, False)
    for mesh in r.values():
        assert all(s > 0 and math.isfinite(s) for s in (*mesh.safety_pitting,
                                                       *mesh.safety_bending))  # fmt: skip


@settings(max_examples=15, deadline=None)
@given(
    sun=st.integers(12, 40),
    planet=st.integers(12, 50),
    n=st.integers(1, 6),
    torque=st.floats(1e-3, 1e4),
    speed=st.floats(1e-2, 1e4),
)
def test_random_stages_are_rated_or_refused(sun, planet, n, torque, speed):
    """Random stages and loads: finite safeties for every mesh, or a TrainError naming why."""
    try:
        stage = Planetary(sun=sun, planet=planet, ring=sun + 2 * planet, n_planets=n, module=2)
        ratings = stage.rating(torque, speed, face_width=20, root="standard")
    except TrainError:
        return
    for r in ratings.values():
        for s in (*r.safety_pitting, *r.safety_bending):
            assert math.isfinite(s) and s > 0
