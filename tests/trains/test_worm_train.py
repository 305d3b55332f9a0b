"""A worm mesh in a Train: its direction-dependent efficiency in power_flow.

Sources: the lecture course §8.15, vector W1 (z1 2, q 10, f' 0.05: eta 0.7920, i 20); Ozols
(14.15) and (14.18) written out by hand; Ozols (14.10) for a series train (the product of the
stages' efficiencies); Ozols §21-12: a self-locking worm holds its load (the wheel cannot drive).
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from gears import Gear, GearError, WormPair
from trains import Train, TrainError, power_flow


def test_w1_in_a_train():
    # W1: mu = f' cos(alpha_n) gives phi' = atan(0.05); i = 20; eta = 0.7920 worm driving
    w = WormPair(2, 40, 5.0, diameter_quotient=10)
    t = Train()
    t.mesh("worm", "wheel", pair=w)
    assert t.ratio("worm", "wheel") == Fraction(-20)
    mu = 0.05 * math.cos(math.radians(20))
    pf = power_flow(t, "worm", "wheel", friction=mu)
    assert round(pf.efficiency, 4) == pytest.approx(0.7920, abs=1e-12)
    g, phi = math.atan(0.2), math.atan(0.05)
    back = power_flow(t, "wheel", "worm", friction=mu)
    assert back.efficiency == pytest.approx(math.tan(g - phi) / math.tan(g), rel=1e-9)  # (14.18)
    assert not back.self_locking and back.relations["worm-wheel"].driver == "wheel"
    # the torques balance and the wheel's is i eta times the worm's (the worm driving)
    assert sum(pf.torques.values()) == pytest.approx(0.0, abs=1e-12)
    assert abs(pf.torques["wheel"]) == pytest.approx(20 * pf.efficiency, rel=1e-9)


def test_self_locking_hoist_holds_its_load(worm_hoist):
    # z1 1, q 16: gamma = 3.576 deg below phi' = atan(0.08 / cos 20) = 4.866 deg
    w = WormPair(1, 40, 4.0, diameter_quotient=16)
    t = worm_hoist(w)
    mu = 0.08
    g = math.atan(1 / 16)
    phi = math.atan(mu / math.cos(math.radians(20)))
    eta_spur = 0.98
    up = power_flow(t, "worm", "drum", friction=mu, mesh_efficiency={"pinion-drum": eta_spur})
    # Ozols (14.10): a series train's efficiency is the product of its stages'
    assert up.efficiency == pytest.approx(math.tan(g) / math.tan(g + phi) * eta_spur, rel=1e-9)
    assert not up.self_locking and up.efficiency < 0.5  # Ozols §21-12: eta < 0.5
    down = power_flow(t, "drum", "worm", friction=mu, mesh_efficiency={"pinion-drum": eta_spur})
    assert down.self_locking and down.efficiency <= 0.0
    assert down.relations["worm-wheel"].efficiency == pytest.approx(
        math.tan(g - phi) / math.tan(g), rel=1e-9
    )
    # a steep worm does not lock: the load drives it backwards
    free = worm_hoist(WormPair(4, 40, 4.0, diameter_quotient=8))
    assert not power_flow(free, "drum", "worm", friction=mu).self_locking


def test_worm_mesh_checks_and_bad_input():
    w = WormPair(1, 20, 2.0, diameter_quotient=8, profile_shift=-0.5)
    t = Train()
    t.mesh("worm", "wheel", pair=w)
    report = t.check()
    assert "worm-wheel.wheel_undercut" in report.failed()
    with pytest.raises(TrainError, match="contradicts"):
        Train().mesh("worm", "wheel", pair=w, teeth=(2, 20))
    with pytest.raises(TrainError, match="external"):
        Train().mesh("worm", "wheel", pair=w, internal=True)
    with pytest.raises(TrainError, match="not both"):
        Train().mesh("worm", "wheel", pair=w, gears=(Gear(20, 2), Gear(20, 2)))


@given(st.integers(1, 4), st.integers(10, 80), st.floats(6.0, 20.0), st.floats(0.0, 0.3))
@settings(max_examples=25, deadline=None, derandomize=True, database=None,
          suppress_health_check=list(HealthCheck))  # fmt: skip
def test_power_flow_of_worm_trains_is_finite_or_refused(z1, z2, q, mu):
    try:
        w = WormPair(z1, z2, 2.0, diameter_quotient=q)
    except GearError:
        return
    t = Train()
    t.mesh("worm", "wheel", pair=w)
    for a, b in (("worm", "wheel"), ("wheel", "worm")):
        pf = power_flow(t, a, b, friction=mu)
        assert math.isfinite(pf.efficiency) and pf.efficiency <= 1.0 + 1e-12  # lstsq rounding
        assert pf.self_locking == (pf.efficiency <= 0.0)
        eta = w.efficiency(mu, "worm" if a == "worm" else "wheel")
        assert pf.efficiency == pytest.approx(eta, rel=1e-9, abs=1e-12)
