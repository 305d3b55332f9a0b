"""geartrain worm: the geometry table, the checks and the efficiency both ways, exit status
0 / 1 / 2.

Reference values: the lecture course §8.15, vector W1 (z1 2, q 10 -> gamma 11.309932 deg,
i 20), printed by the command to its digits; DIN 3975's relations (a = (d_m1 + d_2) / 2 +
x_2 m, d_f1 = d_m1 - 2.4 m) computed by hand in the comments; Ozols (14.18) for the wheel
driving.

--torque: the printed forces are gears.WormPair.forces to the printed digits (that library value
is itself tested against a hand derivation in tests/gears/test_forces.py: F_t1 = F_a1 tan gamma,
F_r = F_a1 tan alpha_n / cos gamma, the wheel's torque over the ideal one the efficiency of
Ozols (14.15) / (14.18)); one force by hand here: the worm's tangential force F_t1 = 2000 T_1 /
d_m1 (DIN 3975 / Niemann-Winter, the worm driving).
"""

from __future__ import annotations

import math
import re

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from trains.cli.app import main


def _run(capsys, *argv) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def _row(out: str, label: str) -> list[float]:
    """The numbers printed on the line that starts with ``label``."""
    line = next(x for x in out.splitlines() if x.startswith(label))
    return [float(v) for v in re.findall(r"-?\d+\.\d+", line[len(label) :])]


W1 = ("worm", 2, 40, "--module", 5, "--q", 10, "--friction", 0.05)


@pytest.mark.parametrize("driving", ["worm", "wheel"])
def test_torque_prints_the_library_forces(capsys, driving):
    from gears import WormPair

    code, out, err = _run(capsys, *W1, "--torque", 12, "--driving", driving)
    assert code == 0 and not err
    assert out.index("efficiency, wheel driving") < out.index("worm mesh, the")  # after it
    assert f"the {driving} driving" in " ".join(out.split())
    f = WormPair(2, 40, 5, diameter_quotient=10).forces(12.0, 0.05, driving)
    named = (("tangential F_t [N]", f.tangential), ("radial F_r [N]", f.radial),
             ("axial F_a [N]", f.axial), ("normal F_n [N]", f.normal))  # fmt: skip
    for label, both in named:  # printed to 3 decimals: within half a unit of the last digit
        assert _row(out, label) == pytest.approx(list(both), abs=5.001e-4), label
    assert _row(out, "torque [N m]") == pytest.approx([12.0, f.torque_2], abs=5.001e-5)


def test_worm_tangential_force_by_hand(capsys):
    # DIN 3975 / Niemann-Winter, the worm driving: F_t1 = 2000 T_1 / d_m1, d_m1 = q m_x = 50 mm,
    # so 2000 * 12 / 50 = 480 N on the worm, and the worm's axial force is the wheel's
    # tangential force F_a1 = F_t2 = F_t1 / tan(gamma + phi') (Ozols (14.15))
    code, out, _ = _run(capsys, *W1, "--torque", 12)
    assert code == 0
    g, phi = math.atan(0.2), math.atan(0.05 / math.cos(math.radians(20)))
    assert _row(out, "tangential F_t [N]") == pytest.approx(
        [2000 * 12 / 50, 480 / math.tan(g + phi)], abs=5.001e-4
    )


def test_wheel_cannot_drive_a_self_locking_worm(capsys):
    # z1 1, q 16: gamma 3.58 deg < phi' 4.87 deg at mu 0.08 (Ozols (14.18)): the library refuses
    code, out, err = _run(capsys, "worm", 1, 40, "-m", 4, "--q", 16, "-f", 0.08, "--torque", 5,
                          "--driving", "wheel")  # fmt: skip
    assert code == 2 and not out and len(err.strip().splitlines()) == 1
    assert "self-locking" in err and "--friction" in err and "--friction angle" not in err


def test_worm_prints_w1(capsys):
    code, out, err = _run(capsys, "worm", 2, 40, "--module", 5, "--q", 10, "--friction", 0.05)
    assert code == 0 and not err
    # gamma = atan(2 / 10) = 11.309932 deg; a = (50 + 200) / 2 = 125; d_f1 = 50 - 2.4 * 5 = 38
    for printed in ("11.309932", "ratio 20,", "125.0000", "38.0000", "210.0000"):
        assert printed in out, printed
    assert "all conditions hold" in out
    # Ozols (14.15) and (14.18) with phi' = atan(0.05 / cos 20 deg)
    g, phi = math.atan(0.2), math.atan(0.05 / math.cos(math.radians(20)))
    assert f"{math.tan(g) / math.tan(g + phi):10.4f}" in out
    assert f"{math.tan(g - phi) / math.tan(g):10.4f}" in out


def test_self_locking_worm_says_so(capsys):
    # z1 1, q 16: gamma 3.58 deg < phi' 4.87 deg at mu 0.08 (Ozols (14.18))
    code, out, _ = _run(capsys, "worm", 1, 40, "-m", 4, "--q", 16, "-f", 0.08, "--speed", 1450)
    assert code == 0 and "self-locking" in out and "sliding speed at 1450 rpm" in out


def test_failing_check_exits_1(capsys):
    # z2 20 with x2 -0.5: z_min = 2 (1 + 0.5) / sin^2(alpha_x) = 25.3 > 20
    code, out, _ = _run(capsys, "worm", 1, 20, "-m", 2, "--q", 8, "--shift", -0.5)
    assert code == 1 and "[FAIL] wheel_undercut" in out


@pytest.mark.parametrize(
    ("argv", "match"),
    [
        (["worm", 2, 40, "--q", 1], "--q = 1"),
        (["worm", 2, 40, "--q", 10, "--worm-diameter", 50], "--worm-diameter"),
        (["worm", 0, 40], "STARTS"),
        (["worm", 2, 40, "--friction", 1], "--friction"),
        (["worm", 2, 40, "--flank", "ZK", "--tool-radius", 0.5], "--tool-radius"),
        (["worm", 2, 40, "--pressure-angle", 60], "--pressure-angle"),
        (["worm", 2, 40, "--tolerance", 0.1], "--tolerance applies with --scene"),
        (["worm", 2, 40, "--frames", 3], "--frames counts the frames of --animate"),
        (["worm", 2, 40, "--torque", 0], "--torque"),
        (["worm", 2, 40, "--torque", -5], "--torque"),
        (["worm", 2, 40, "--torque", "inf"], "--torque"),
        (["worm", 2, 40, "--torque", "nan"], "--torque"),
        (["worm", 2, 40, "--torque", "ten"], "--torque"),
        (["worm", 2, 40, "--driving", "wheel"], "--driving applies with --torque"),
        (["worm", 2, 40, "--torque", 5, "--driving", "rack"], "--driving"),
    ],
)
def test_bad_input_exits_2_naming_the_option(capsys, argv, match):
    code, _, err = _run(capsys, *argv)
    assert code == 2 and match in err and len(err.strip().splitlines()) == 1


@given(
    st.integers(-1, 6),
    st.integers(-1, 120),
    st.floats(-1.0, 12.0),
    st.floats(-2.0, 30.0),
    st.floats(-1.0, 1.0),
    st.sampled_from(["ZA", "ZN", "ZI", "ZK"]),
    st.floats(-0.1, 1.1),
)
@settings(max_examples=25, deadline=None, derandomize=True, database=None,
          suppress_health_check=list(HealthCheck))  # fmt: skip
def test_every_input_gets_exit_0_1_or_2(z1, z2, m, q, x2, flank, mu):
    import contextlib
    import io

    argv = ["worm", str(z1), str(z2), "-m", repr(m), "--q", repr(q), "--shift", repr(x2),
            "--flank", flank, "--friction", repr(mu)]  # fmt: skip
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        code = main(argv)
    assert code in (0, 1, 2)


TORQUES = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.floats(-10.0, 1e4),
                    st.sampled_from(["0", "-0", "1e308", "1e-300", "x"]))  # fmt: skip


@given(TORQUES, st.one_of(st.floats(-0.1, 1.1), st.sampled_from([0.0, 0.3, 0.999999])),
       st.sampled_from(["worm", "wheel"]), st.integers(1, 4), st.floats(5.0, 20.0))  # fmt: skip
@settings(max_examples=40, deadline=None, derandomize=True, database=None,
          suppress_health_check=list(HealthCheck))  # fmt: skip
def test_every_torque_and_friction_gets_exit_0_1_or_2(torque, mu, driving, z1, q):
    # in-process (trains.cli.app.main), as the sweep above: a finite table or one error line
    import contextlib
    import io

    argv = ["worm", str(z1), "40", "-m", "4", "--q", repr(q), "--friction", repr(mu),
            "--torque", torque if isinstance(torque, str) else repr(torque),
            "--driving", driving]  # fmt: skip
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(argv)
    assert code in (0, 1, 2) and "Traceback" not in err.getvalue()
    if code == 2:
        assert len(err.getvalue().strip().splitlines()) == 1 and not out.getvalue()
    else:
        printed = out.getvalue()
        assert "normal F_n [N]" in printed
        assert not re.search(r"\b(nan|inf)\b", printed)


def test_scene_and_animation_are_written(capsys, tmp_path):
    glb, gif = tmp_path / "pair.glb", tmp_path / "pair.gif"
    code, out, err = _run(capsys, "worm", 1, 20, "--module", 2, "--flank", "ZA", "--scene", glb,
                          "--animate", gif, "--frames", 2, "--tolerance", 0.3)  # fmt: skip
    assert code == 0, err
    assert glb.stat().st_size > 0 and gif.stat().st_size > 0
    text = " ".join(out.split())  # lines wrapped to the terminal's width
    assert f"wrote {glb}" in text and f"wrote {gif} (2 frames" in text
