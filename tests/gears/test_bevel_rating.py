"""gears.bevel.rating, BevelPair.rating, Differential.rating: bevel gears through their virtual
cylindrical gears, after ISO 10300 method B1 (issue 30).

Sources: the limit of a very long cone distance (a shaft angle of 0.5 deg: the pitch angles go to
0, z_v to z and the bevel pair to a spur pair of the mean module), rated independently as a
cylindrical GearPair by ISO 6336 with ISO 10300's K_Hbeta = 1.5 K_Hbeta-be and Z_K = 0.85; the
force at the mean cone F_mt = 2000 T / d_m (ISO 10300-1) carried by the virtual pinion; the
statics of a differential (the case torque split equally, Ozols §13).
"""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import BevelPair, Gear, GearPair
from gears.bevel.rating import BEVEL_FACTOR, MOUNTING_FACTORS
from gears.errors import GearError
from trains import Differential
from trains.errors import TrainError


@pytest.mark.parametrize("mounting", ["both-straddle", "neither-straddle"])
def test_long_cone_distance_rates_like_its_cylindrical_pair(mounting):
    bevel = BevelPair(20, 40, module=3, face_width=15, shaft_angle=0.5)
    vp = bevel.virtual_pair
    r = bevel.rating(50.0, 1500.0, mounting=mounting, life=10000.0)
    # the cylindrical pair of the mean module with integer teeth, as cut by the same rack
    mm = bevel.mean_module
    spur = GearPair(Gear(20, mm, rack=vp.g1.rack, face_width=15),
                    Gear(40, mm, rack=vp.g2.rack, face_width=15), tip_shortening=False)  # fmt: skip
    k = 1.5 * MOUNTING_FACTORS[mounting]
    c = spur.rating(50.0, 1500.0, life=10000.0, K_Hbeta=k, K_Fbeta=k)
    for a, b in zip(r.safety_pitting, c.safety_pitting, strict=True):
        assert a == pytest.approx(b / BEVEL_FACTOR, rel=1e-4)
    for a, b in zip(r.safety_bending, c.safety_bending, strict=True):
        assert a == pytest.approx(b, rel=1e-4)


def test_virtual_pinion_carries_the_mean_cone_force():
    bevel = BevelPair(18, 45, module=4, face_width=25)
    r = bevel.rating(120.0, 900.0)
    d_m1 = bevel.geometry.mean_diameter[0]
    # F_mt = 2000 T / d_m1 (ISO 10300-1); the real pinion's load cycles 60 n L
    assert r.quantities["F_t"] == pytest.approx(2000 * 120.0 / d_m1, rel=1e-9)
    assert r.quantities["N_L"][0] == pytest.approx(60 * 900.0 * 20000.0, rel=1e-12)
    assert r.quantities["N_L"][1] == pytest.approx(60 * 900.0 * 20000.0 * 18 / 45, rel=1e-12)
    assert r.settings["torque"] == pytest.approx(120.0, rel=1e-15)
    assert "ISO 10300" in r.settings["bevel"]


def test_differential_rating_is_its_pair_under_the_split_torque():
    d = Differential(side=16, pinion=10, n_pinions=2, module=3, gleason=True)
    r = d.rating(torque=150, left=90, right=110)
    spin = abs(float(d.solve(left=90, right=110).relative("pinion", "case")))
    # statics: 150 N m on the case, 75 on each side gear, shared by 2 pinions; on the pinion
    # the side gear's torque times z_p / z_s
    direct = d.pair.rating(150 / 2 / 2 * 10 / 16, spin, contacts=(1, 2), idler=(True, False))
    assert list(r) == ["pinion-right", "pinion-left"]
    assert r["pinion-left"].safety_pitting[0] == pytest.approx(direct.safety_pitting[0], rel=1e-12)
    assert r["pinion-right"].safety_bending[1] == pytest.approx(direct.safety_bending[1], rel=1e-12)
    with pytest.raises(TrainError, match="do not turn"):
        d.rating(torque=150, left=100, right=100)


@pytest.mark.parametrize(
    "args, kw, match",
    [
        ((0.0, 1000.0), {}, "torque"),
        ((10.0, math.inf), {}, "speed"),
        ((10.0, 1000.0), {"mounting": "bolted"}, "mounting"),
        ((10.0, 1000.0), {"Z_NT": 1.0}, "Z_NT"),
    ],
)
def test_bevel_rating_bad_input(args, kw, match):
    with pytest.raises(GearError, match=match):
        BevelPair(20, 40, module=3, face_width=20).rating(*args, **kw)


@settings(max_examples=15, deadline=None)
@given(
    st.integers(8, 40), st.integers(8, 80), st.floats(30.0, 150.0), st.floats(1e-2, 1e4),
    st.floats(1e-1, 1e5),
)  # fmt: skip
def test_bevel_rating_property(z1, z2, shaft, torque, speed):
    try:
        bevel = BevelPair(z1, z2, module=3, face_width=12, shaft_angle=shaft)
        r = bevel.rating(torque, speed)
    except GearError:
        return
    assert all(math.isfinite(s) and s > 0 for s in (*r.safety_pitting, *r.safety_bending))


@settings(max_examples=10, deadline=None)
@given(st.floats(-1e4, 1e4), st.floats(-1e3, 1e3), st.floats(-1e3, 1e3))
def test_differential_rating_property(torque, left, right):
    d = Differential(side=16, pinion=10, module=3, gleason=True)
    try:
        r = d.rating(torque=torque, left=left, right=right)
    except TrainError:
        return
    for v in r.values():
        assert all(math.isfinite(s) and s > 0 for s in (*v.safety_pitting, *v.safety_bending))
