"""TOML train files and the `geartrain train` command."""

from fractions import Fraction as F
from pathlib import Path

import pytest

from trains import TrainError, read_train
from trains.cli.app import main

EXAMPLES = Path(__file__).parents[2] / "examples"


def test_toml_simple_planetary_matches_design_example():
    # DESIGN.md: sun 20 / planet 30 / ring 80 on carrier "arm": ratio 5 with the ring fixed.
    t = read_train(EXAMPLES / "train_simple_planetary.toml")
    assert t.ratio("sun", "arm", fixed=["ring"]) == F(5)
    assert t.structure.redundant == 2  # [planets] planet = 3: sigma = k - 1 (Ozols §21-13)
    assert t.run_defaults["output"] == "arm"


def test_toml_links_with_string_fractions(tmp_path):
    p = tmp_path / "t.toml"
    p.write_text(
        '[[link]]\nmembers = ["a", "b"]\nratio = "-13/3"\n[[couple]]\nmembers = ["b", "c"]\n'
    )
    t = read_train(p)
    assert t.ratio("a", "c") == F(-13, 3)


@pytest.mark.parametrize(
    ("text", "match"),
    [
        (
            '[[mesh]]\ngears = ["a", "b"]\nteeth = [20, 0]\n',
            r"line 3: mesh #1, 'teeth': second tooth count",
        ),
        ('[[mesh]]\ngears = ["a"]\nteeth = [20, 10]\n', "list of two member names"),
        ('[[mesh]]\ngears = ["a", "b"]\nteeth = [20, 10]\ncolour = 1\n', "unknown keys"),
        ('[[link]]\nmembers = ["a", "b"]\n', "'ratio' is required"),
        ("gears = 3\n", "unknown top-level keys"),
        ("[[mesh]\n", "not valid TOML"),
    ],
)
def test_toml_errors_name_the_entry(tmp_path, text, match):
    p = tmp_path / "bad.toml"
    p.write_text(text)
    with pytest.raises(TrainError, match=match):
        read_train(p)


def test_toml_missing_file():
    with pytest.raises(TrainError, match="no such train file"):
        read_train("/nonexistent/train.toml")


def test_cli_prints_speeds_ratios_torques_efficiency(capsys):
    f = str(EXAMPLES / "train_simple_planetary.toml")
    assert main(["train", f, "--fixed", "ring", "--input", "sun=1500", "--output", "arm"]) == 0
    out = capsys.readouterr().out
    assert "arm     300" in out  # speed of the arm: 1500 / 5
    assert "sun/arm     5" in out  # ratio
    assert "planet on arm: -800" in out  # planet bearing speed
    assert "efficiency 0.96832" in out  # 0.98 meshes from the file: (1 + 4*0.98^2)/5
    assert "torque" in out


def test_cli_closed_differential_uses_file_defaults(capsys):
    assert main(["train", str(EXAMPLES / "train_closed_differential.toml")]) == 0
    out = capsys.readouterr().out
    assert "2767/63" in out  # Ozols ex. 7-7 exact ratio
    assert "efficiency" in out


def test_cli_two_inputs_negative_speed(capsys, tmp_path):
    f = str(EXAMPLES / "train_bevel_differential.toml")
    args = ["train", f, "--input", "left=-90", "--input", "right=-110", "--output", "carrier"]
    assert main(args) == 0
    out = capsys.readouterr().out
    assert "carrier  -100" in out and "efficiency 1" in out


def test_cli_errors_exit_2(capsys):
    f = str(EXAMPLES / "train_simple_planetary.toml")
    assert main(["train", f, "--fixed", "ring", "--input", "moon=1"]) == 2
    assert "unknown member 'moon'" in capsys.readouterr().err
    assert main(["train", f, "--fixed", "", "--input", "sun=1"]) == 2
    assert "under-determined" in capsys.readouterr().err
    assert main(["train", f, "--input", "sun=fast"]) == 2


def test_reverted_reducer_toml_matches_coaxial_shifts(capsys):
    # examples/train_reverted_reducer.toml holds the shifts coaxial_shifts finds for 17/40 +
    # 20/38 at m = 2 (the example script's design): both stages at a_w = 58 mm, all checks hold
    from gears import Gear
    from trains import coaxial_shifts

    p12, _ = coaxial_shifts([(Gear(17, 2), Gear(40, 2)), (Gear(20, 2), Gear(38, 2))])
    f = EXAMPLES / "train_reverted_reducer.toml"
    t = read_train(f)
    pair = t.pairs["in-lay"]
    # the stored shifts are a computed result: another machine's numpy/scipy build finds them a
    # few ulps away (2e-15 seen), so compare within 1e-12, far below a shift anyone can grind
    assert (pair.g1.profile_shift, pair.g2.profile_shift) == pytest.approx(
        (p12.g1.profile_shift, p12.g2.profile_shift), abs=1e-12
    )
    assert abs(pair.center_distance - t.pairs["lay-out"].center_distance) < 1e-9
    assert main(["train", str(f)]) == 0  # prints the check report; every check holds
    out = capsys.readouterr().out
    assert "all conditions hold" in out and "coaxiality(in, out)" in out
