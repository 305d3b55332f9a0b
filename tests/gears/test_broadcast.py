"""Arrays that do not broadcast together are bad input: every checked array entry point refuses
them with a GearError naming two of the arguments (gears.arguments.common_shape), before any
work; arrays that do broadcast give each row what it gives alone."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import GearError
from gears.arguments import common_shape
from gears.bevel.cone import bevel_geometry
from gears.checks import pair_margins
from gears.meshing import pair_geometry
from gears.rating import rate_pairs, rate_spectrum
from gears.rating.losses import pair_losses
from gears.rating.scuffing import Oil, rate_scuffing
from gears.rating.sizing import load_case, smallest_width

OIL = Oil(fzg_stage=9, temperature=70, viscosity_40=100, viscosity_100=11)


def _entry_points(a, b):
    """(call, the two names the message must give) with ``a`` and ``b`` arrays of lengths that
    do not broadcast together."""
    z2 = 40 + 0 * a  # tooth counts of length len(a)
    return [
        (lambda: pair_geometry(20, z2, b), ("z2", "module")),
        (lambda: pair_margins(20, z2, b), ("z2", "module")),
        (lambda: rate_pairs(20, z2, 2, b, 100, 1000), ("z2", "face_width")),
        (lambda: rate_pairs(20, 40, 2, 20, 100 + a, 1000 + b), ("torque", "speed")),
        (
            lambda: rate_pairs(20, 40, 2, 20, 100, 1000, roughness=0.5 + 0 * a, x1=0 * b),
            ("roughness", "x1"),
        ),
        (lambda: pair_losses(100 + a, 1000 + b, 20, 40, 2, 20), ("torque", "speed")),
        (lambda: rate_spectrum(20, z2, 2, b, [(100, 1000, 10)]), ("z2", "face_width")),
        (lambda: bevel_geometry(20, z2, b, 10), ("z2", "module")),
        (
            lambda: rate_scuffing(20, 40, 2, 20, 100, 1000 + a, oil=OIL, welding=1 + 0 * b),
            ("speed", "welding"),
        ),
        (lambda: smallest_width(load_case(100, 1000), [10.0, 20.0], 20, z2, b), ("z2", "module")),
    ]


@settings(max_examples=25, deadline=None)
@given(n=st.integers(2, 5), m=st.integers(2, 5))
def test_arrays_that_do_not_broadcast_are_named(n, m):
    if n == m:
        m += 1
    a, b = np.arange(n, dtype=float), 1.0 + np.arange(m, dtype=float)
    for call, names in _entry_points(a, b):
        with pytest.raises(GearError) as e:
            call()
        text = str(e.value)
        assert "do not broadcast" in text and all(k in text for k in names), text


def test_common_shape_names_the_first_two_that_clash():
    # numpy's rule: lengths equal or 1, aligned at the end
    assert common_shape({"a": (2, 1), "b": (3,), "c": ()}) == (2, 3)
    with pytest.raises(GearError, match=r"b has shape \(3,\) and c shape \(4,\)"):
        common_shape({"a": (1,), "b": (3,), "c": (4,)})


def test_scuffing_of_an_array_of_speeds_is_each_speed_alone():
    # failed before: the path's points (the geometry's shape) met the temperatures (the load's
    # shape) in numpy's take_along_axis. Independent reference: each speed rated alone.
    speeds = np.array([1000.0, 2000.0, 3000.0])
    r = rate_scuffing(20, 40, 2, 20, 100, speeds, oil=OIL)
    for i, s in enumerate(speeds):
        one = rate_scuffing(20, 40, 2, 20, 100, s, oil=OIL)
        for k in ("S_B", "S_intS", "gamma_flmax"):
            assert float(np.ravel(getattr(r, k))[i]) == pytest.approx(float(getattr(one, k)),
                                                                      rel=1e-12)  # fmt: skip
    welded = rate_scuffing(20, 40, 2, 20, 100, 1000, oil=OIL, welding=np.array([1.0, 1.1]))
    alone = rate_scuffing(20, 40, 2, 20, 100, 1000, oil=OIL, welding=1.1)
    assert float(welded.S_B[1]) == pytest.approx(float(alone.S_B), rel=1e-12)
