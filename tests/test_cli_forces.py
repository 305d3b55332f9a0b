"""The CLI prints the forces where a torque is given: pair, bevel, planetary, train.

Sources: Ozols section 11-2 (11.8) R = M1 / (r1 cos alpha) = 2128.36 N for M1 = 100 N m,
r1 = 50 mm; ISO 10300-1 F_t = 2000 T / d_m; statics (symmetric planets leave the sun unloaded).
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import BevelPair
from trains.cli.app import main

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def _row(out: str, label: str) -> list[float]:
    line = next(x for x in out.splitlines() if x.startswith(label))
    return [float(v) for v in re.findall(r"-?\d+\.\d+", line[len(label) :])]


def test_pair_torque_prints_the_mesh_forces(capsys):
    assert main(["pair", "20", "40", "--module", "5", "--torque", "100"]) == 0
    out = capsys.readouterr().out
    assert _row(out, "normal F_n [N]") == pytest.approx([2128.356, 2128.356], abs=5e-4)
    assert _row(out, "torque [N m]") == pytest.approx([100.0, 200.0], abs=1e-4)


def test_bevel_torque_prints_the_mean_cone_forces(capsys):
    assert main(["bevel", "20", "40", "--module", "3", "--face-width", "22", "--torque", "50"]) == 0
    out = capsys.readouterr().out
    d_m = BevelPair(20, 40, 3, 22).g1.mean_diameter
    assert _row(out, "tangential F_t [N]")[0] == pytest.approx(2000 * 50 / d_m, abs=5e-4)


def test_planetary_torque_and_speed_print_the_loads(capsys):
    argv = ["planetary", "21", "36", "93", "--planets", "3", "--module", "2", "--face-width",
            "20", "--torque", "120", "--speed", "1500"]  # fmt: skip
    main(argv)
    out = capsys.readouterr().out
    assert "centrifugal force [N]" in out and "net radial force on sun [N]" in out
    carrier = float(re.search(r"carrier torque \[N m\]: (\S+)", out).group(1))
    assert carrier == pytest.approx(-120 * (1 + 93 / 21), rel=1e-5)  # Ozols (11.11)


def test_train_prints_forces_with_a_module(capsys):
    toml = str(EXAMPLES / "train_simple_planetary.toml")
    main(["train", toml, "--torque", "100", "--module", "2"])
    out = capsys.readouterr().out
    assert "forces at 100 N m on sun" in out
    assert _row(out, "   sun")[1] == pytest.approx(0.0, abs=1e-6)  # symmetric planets
    main(["train", toml, "--torque", "100"])
    assert "give --module" in capsys.readouterr().out


def test_bad_torque_is_exit_2_naming_the_option(capsys):
    assert main(["pair", "20", "40", "--module", "5", "--torque", "0"]) == 2
    assert "--torque" in capsys.readouterr().err


@settings(max_examples=20, deadline=None)
@given(torque=st.floats(allow_nan=True, allow_infinity=True), z=st.sampled_from([9, 20, 57]))
def test_property_pair_torque(torque, z):
    # a CLI answer or a one-line refusal: exit 0, 1 (a check fails) or 2 (bad input)
    code = main(["pair", str(z), "40", "--module", "2", "--torque", repr(torque)])
    assert code in (0, 1, 2)
    if not math.isfinite(torque) or torque == 0:
        assert code == 2
