"""Gearbox stages' efficiency from their meshes at the load (issue 30): stage_efficiency and
synthesize_gearbox(objective="mesh_efficiency").

Reference values: ``Planetary.efficiency`` with each mesh's efficiency from
``GearPair.efficiency`` (ISO/TR 14179-2) at the mesh's torque and speed as ``Planetary.rating``
finds them (the power flow of the stage's train, an independent route from the vectorised
``trains.design.sizing``); the closed form of Ozols (14.26) by hand; and a brute force over
products of single stages from ``synthesize`` (each with its own exact target), both orders.
"""

from __future__ import annotations

import functools
import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears.rating.sizing import load_case
from trains import Planetary, TrainError, synthesize_gearbox
from trains.design.sizing import stage_efficiency
from trains.planetary.schemes import stage_ratio
from trains.power import planetary_efficiency, power_flow

STAGES = [
    ("simple", (21, 24, 24, 69), 3),
    ("simple", (17, 40, 40, 97), 4),
    ("stepped", (18, 24, 21, 63), 3),
    ("stepped", (20, 30, 30, 80), 3),
    ("external", (30, 20, 21, 29), 3),
    ("internal", (80, 20, 23, 83), 3),
    ("double-planet", (20, 17, 18, 74), 3),
]
BOX = dict(torque=50, speed=1500, face_width=[10, 15, 20, 25, 30], progress=False)


def _planetary(scheme, teeth, k, module):
    z1, z2, z2p, z3 = teeth
    return Planetary(z1, z2 if scheme == "simple" else (z2, z2p), z3, k, module, scheme=scheme)


def _reference(p: Planetary, torque, speed, b):
    """Planetary.efficiency's power flow (ring fixed, sun in) with every mesh's
    GearPair.efficiency at the mesh's torque (on its gear 1, per planet) and speed relative to
    the carrier, as Planetary.rating finds them."""
    rating = p.rating(torque, speed, face_width=b, root="standard")
    etas = {name: float(p.meshes[name].efficiency(r.settings["torque"], r.settings["speed"],
                                                  face_width=b).efficiency)
            for name, r in rating.items()}  # fmt: skip
    flow = power_flow(p.train, "sun", p.carrier, fixed=["ring"], mesh_efficiency=etas)
    return flow.efficiency


@pytest.mark.parametrize(("scheme", "teeth", "k"), STAGES)
def test_stage_efficiency_is_planetary_efficiency_of_its_meshes(scheme, teeth, k):
    # independent route: Planetary.rating's mesh loads, GearPair.efficiency per mesh, and
    # power_flow of the stage's train (as Planetary.efficiency solves it) with those meshes
    load = load_case(80, 1200)
    num, den = stage_ratio(scheme, *teeth)
    got = stage_efficiency(load, scheme, *teeth, k, num, den, 80.0, 1200.0, 2.0, 20.0)
    want = _reference(_planetary(scheme, teeth, k, 2.0), 80, 1200, 20.0)
    assert 0 < float(got) <= 1
    assert float(got) == pytest.approx(want, rel=1e-9)


def test_stage_efficiency_vectorised_and_near_the_loaded_flow():
    # rows of one call equal the calls one by one (torques and speeds per row); and the
    # lossless mesh loads differ from Planetary.efficiency(mesh_efficiency="gears") (the
    # loaded flow, fixed-point) only by the loss on the mesh torque, which enters as F^0.2
    load = load_case(60, 1500)
    torque, speed = np.array([20.0, 60.0, 300.0]), np.array([3000.0, 1500.0, 200.0])
    rows = stage_efficiency(load, "simple", 20, 31, 31, 82, 3, 102, 20, torque, speed, 2.0, 20.0)
    p = _planetary("simple", (20, 31, 31, 82), 3, 2.0)
    for i in range(3):
        one = stage_efficiency(load, "simple", 20, 31, 31, 82, 3, 102, 20, torque[i], speed[i],
                               2.0, 20.0)  # fmt: skip
        assert float(rows[i]) == pytest.approx(float(one), rel=1e-12)
        loaded = p.efficiency(
            mesh_efficiency=lambda pair, t, n: pair.efficiency(t, n, face_width=20.0).efficiency,
            torque=float(torque[i]),
            speed=float(speed[i]),
        )
        assert float(rows[i]) == pytest.approx(loaded, abs=1e-4)
    # mu_mz ~ (F_bt / v)^0.2 (ISO/TR 14179-2): a heavier, slower load loses more
    assert rows[0] > rows[1] > rows[2]


def test_ozols_1426_by_hand():
    # Ozols (14.26), sun driving, i_1H = 1 + z3/z1 > 1: eta = (1 + (i - 1) eta0) / i;
    # Mueller's example i0 = -4, eta0 = 0.97: 0.976
    got = planetary_efficiency(np.array([5.0, 4.0]), np.array([0.97, 0.98]))
    assert got == pytest.approx([0.976, (1 + 3 * 0.98) / 4], rel=1e-12)
    assert isinstance(planetary_efficiency(5, 0.97), float)
    with pytest.raises(TrainError, match="non-zero"):
        planetary_efficiency(np.array([5.0, 0.0]), 0.98)


def test_search_stage_efficiencies_are_planetary_efficiency():
    boxes = synthesize_gearbox(12, 2, schemes=("simple", "stepped"), z_max=80, top=2,
                               objective="mesh_efficiency", **BOX)  # fmt: skip
    assert len(boxes) == 2
    for box in boxes:
        assert box.mesh_efficiency == pytest.approx(math.prod(box.stage_efficiencies), rel=1e-12)
        for c, t, n, b, eta in zip(box.stages, box.torques, box.speeds, box.face_widths,
                                   box.stage_efficiencies, strict=True):  # fmt: skip
            assert eta == pytest.approx(_reference(c.stage, t, n, b), rel=1e-9)
    assert boxes[0].mesh_efficiency >= boxes[1].mesh_efficiency
    arr = boxes.to_array()
    assert arr["mesh_efficiency"][0] == pytest.approx(boxes[0].mesh_efficiency, rel=1e-12)
    assert arr["2_efficiency"][0] == pytest.approx(boxes[0].stage_efficiencies[1], rel=1e-12)


@functools.cache
def _check_ok(teeth, module):
    return _planetary("simple", teeth, 3, module).check().ok


def _brute_force(products, target, z_max, modules, widths):
    """Every product of two single simple stages (synthesize, each with its exact target), in
    both orders, each stage sized at its place (tests/conftest.py ``stage_products``);
    (-efficiency, volume, teeth 1, teeth 2) of the best that passes Planetary.check()."""
    found = []
    for a, i, d1, b, j, d2 in products(target, z_max, modules, widths, 50.0, 1500.0):
        if not (_check_ok(a.teeth, d1["module"][i]) and _check_ok(b.teeth, d2["module"][j])):
            continue
        eta = d1["efficiency"][i] * d2["efficiency"][j]
        found.append((-eta, d1["volume"][i] + d2["volume"][j], a.teeth, b.teeth))
    return min(found)


def test_best_by_mesh_efficiency_equals_the_brute_force_product(gearbox_stage_products):
    modules, widths = [1.0, 1.25, 1.5, 2.0, 2.5, 3.0], [10.0, 15.0, 20.0, 25.0]
    best = _brute_force(gearbox_stage_products, Fraction(12), 70, modules, widths)
    got = synthesize_gearbox(12, 2, z_max=70, module=modules, objective="mesh_efficiency", top=1,
                             **dict(BOX, face_width=widths))[0]  # fmt: skip
    assert got.mesh_efficiency == pytest.approx(-best[0], rel=1e-12)
    assert got.volume == pytest.approx(best[1], rel=1e-12)
    assert (got.stages[0].teeth, got.stages[1].teeth) == best[2:]


def test_mesh_efficiency_needs_a_load():
    with pytest.raises(TrainError, match="objective = 'mesh_efficiency'"):
        synthesize_gearbox(12, 2, z_max=60, objective="mesh_efficiency", progress=False)


@settings(max_examples=6, deadline=None)
@given(
    ratio=st.sampled_from([6, 9, 12, 16]),
    torque=st.floats(1.0, 2000.0),
    speed=st.floats(10.0, 6000.0),
)
def test_property_mesh_efficiency_in_unit_interval(ratio, torque, speed):
    boxes = synthesize_gearbox(ratio, 2, z_max=50, top=2, objective="mesh_efficiency",
                               torque=torque, speed=speed, face_width=[10, 20, 40, 80],
                               progress=False)  # fmt: skip
    for box in boxes:
        assert math.isfinite(box.mesh_efficiency) and 0 < box.mesh_efficiency <= 1
        assert all(0 < e <= 1 for e in box.stage_efficiencies)


@settings(max_examples=25, deadline=None)
@given(
    scheme_stage=st.sampled_from(STAGES),
    torque=st.floats(1e-3, 1e5),
    speed=st.floats(1e-3, 1e5),
    module=st.floats(0.3, 20.0),
    width=st.floats(1.0, 500.0),
)
def test_property_stage_efficiency_finite(scheme_stage, torque, speed, module, width):
    scheme, teeth, k = scheme_stage
    num, den = stage_ratio(scheme, *teeth)
    eta = float(stage_efficiency(load_case(60, 1500), scheme, *teeth, k, num, den, torque, speed,
                                 module, width))  # fmt: skip
    assert math.isfinite(eta) and eta <= 1
    if num / den > 1:  # a reduction, as the gearbox search's: it cannot lock, Ozols (14.26)
        assert eta >= 0  # 0: the friction equation does not apply


@settings(max_examples=5, deadline=None)
@given(
    st.text(min_size=1, max_size=12).filter(
        lambda s: s not in ("volume", "mass", "ring", "teeth", "efficiency", "mesh_efficiency")
    )
)
def test_property_bad_objective_named(name):
    with pytest.raises(TrainError, match="objective = "):
        synthesize_gearbox(12, 2, z_max=40, objective=name, **BOX)


def test_cli_objective_mesh_efficiency(capsys):
    # the CLI prints what synthesize_gearbox ranks with the same options
    from trains.cli.app import main

    argv = ["search", "gearbox", "--ratio", "12", "--stages", "2", "--z-max", "80", "--torque",
            "50", "--speed", "1500", "--face-width", "10:30:10", "--objective",
            "mesh_efficiency", "--top", "2"]  # fmt: skip
    assert main(argv) == 0
    out = capsys.readouterr().out
    want = synthesize_gearbox(12, 2, z_max=80, torque=50, speed=1500, face_width=[10, 20, 30],
                              objective="mesh_efficiency", top=2, progress=False)  # fmt: skip
    flat = " ".join(out.split())  # the CLI wraps its lines
    assert " ".join(want.table().split()) in flat and "mesh efficiency" in flat
