"""A train with a non-circular pair over one cycle of its law (trains.noncircular_cycle),
against the elliptical pair's closed form and the pair's own law."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from gears import NonCircularPair
from trains import Train, TrainError, noncircular_cycle


def test_elliptical_pair_then_a_fixed_stage():
    # input -> elliptical pair (A = 50, e = 0.3) -> a 20/40 external stage -> output.
    # Closed form (Litvin): psi = 2 atan((1 + e)/(1 - e) tan(phi/2)); the stage halves it and
    # turns it back: output = +psi / 2 (two external meshes), speed = psi'(phi) / 2
    e = 0.3
    pair = NonCircularPair.elliptical(50.0, e)
    t = Train()
    t.mesh("driven", "output", teeth=(20, 40))
    c = noncircular_cycle(t, pair, "input", "driven", "input", "output", samples=241)
    phi = np.radians(c.pair_angle)
    psi = 2 * np.unwrap(np.arctan((1 + e) / (1 - e) * np.tan(phi / 2)) * 2) / 2
    assert np.allclose(c.input_angle, c.pair_angle, atol=1e-9)
    assert np.allclose(c.output_angle, np.degrees(psi) / 2, atol=1e-5)
    q = (1 - e * e) / (1 - 2 * e * np.cos(phi) + e * e)
    assert np.allclose(c.output_speed, q / 2, rtol=1e-8)
    dq = -2 * e * np.sin(phi) * (1 - e * e) / (1 - 2 * e * np.cos(phi) + e * e) ** 2
    assert np.allclose(c.output_acceleration, dq / 2, atol=2e-3)  # 2nd-order differences
    lo, hi = c.speed_range
    assert lo == pytest.approx((1 - e) / (1 + e) / 2, rel=1e-9)
    assert hi == pytest.approx((1 + e) / (1 - e) / 2, rel=1e-6)


def test_stage_before_the_pair():
    # input -> 30/10 stage (the driver turns 3x faster, opposite) -> pair: one cycle of the pair
    # takes a third of a turn of the input; the output follows the pair's own law, turned (an
    # external pair)
    pair = NonCircularPair.lobed(40.0, 0.2, (2, 2))
    t = Train()
    t.mesh("input", "driver", teeth=(30, 10))
    c = noncircular_cycle(t, pair, "driver", "out", "input", "out", samples=201)
    assert c.input_angle[-1] == pytest.approx(-180.0 / 3, rel=1e-9)
    assert np.allclose(c.output_angle, -pair.output_angle(c.pair_angle), atol=1e-6)


def test_refusals():
    pair = NonCircularPair.elliptical(50.0, 0.3)
    t = Train()
    t.mesh("x", "y", teeth=(20, 40))
    with pytest.raises(TrainError):
        noncircular_cycle(t, pair, "a", "b", "x", "b")  # x does not drive the pair
    with pytest.raises(TrainError, match="train"):
        noncircular_cycle("train", pair, "a", "b", "a", "b")


@settings(max_examples=15, deadline=None, derandomize=True, database=None,
          suppress_health_check=list(HealthCheck))  # fmt: skip
@given(e=st.floats(0.0, 0.9), z=st.integers(1, 200), samples=st.integers(-5, 60))
def test_cycle_sweep(e, z, samples):
    pair = NonCircularPair.elliptical(20.0, e)
    t = Train()
    t.mesh("b", "out", teeth=(z, 2 * z))
    try:
        c = noncircular_cycle(t, pair, "a", "b", "a", "out", samples=samples)
    except Exception as exc:  # our errors only (GearError and TrainError are ValueErrors)
        assert isinstance(exc, ValueError), exc
        return
    for v in (c.input_angle, c.output_angle, c.output_speed, c.output_acceleration):
        assert np.all(np.isfinite(v))
    assert math.isfinite(c.speed_range[0])
