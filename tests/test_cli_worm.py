"""geartrain worm: the geometry table, the checks and the efficiency both ways, exit status
0 / 1 / 2.

Reference values: the lecture course §8.15, vector W1 (z1 2, q 10 -> gamma 11.309932 deg,
i 20), printed by the command to its digits; DIN 3975's relations (a = (d_m1 + d_2) / 2 +
x_2 m, d_f1 = d_m1 - 2.4 m) computed by hand in the comments; Ozols (14.18) for the wheel
driving.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from trains.cli.app import main


def _run(capsys, *argv) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


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


def test_scene_and_animation_are_written(capsys, tmp_path):
    glb, gif = tmp_path / "pair.glb", tmp_path / "pair.gif"
    code, out, err = _run(capsys, "worm", 1, 20, "--module", 2, "--flank", "ZA", "--scene", glb,
                          "--animate", gif, "--frames", 2, "--tolerance", 0.3)  # fmt: skip
    assert code == 0, err
    assert glb.stat().st_size > 0 and gif.stat().st_size > 0
    text = " ".join(out.split())  # lines wrapped to the terminal's width
    assert f"wrote {glb}" in text and f"wrote {gif} (2 frames" in text
