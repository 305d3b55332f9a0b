"""geartrain noncircular: the pair's table, the checks and the drawing, exit status 0 / 1 / 2.

Reference values: Litvin's elliptical pair (centre distance 2 A, ratio (1 - e)/(1 + e) ...
(1 + e)/(1 - e)), computed by hand in the comments.
"""

from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from trains.cli.app import main


def _run(capsys, *argv) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def test_elliptical_pair_table_and_drawing(capsys, tmp_path):
    # A = 20, e = 0.2: a = 40 mm, ratio 0.8/1.2 = 0.666667 ... 1.2/0.8 = 1.5; the ellipse's
    # length 4 A E(e) = 124.4 mm holds 124.4 / (2 pi) = 19.8 -> 20 teeth of module 2
    svg = tmp_path / "pair.svg"
    code, out, err = _run(capsys, "noncircular", "elliptical", "-a", 20, "-e", 0.2, "-m", 2,
                          "-o", svg, "--tolerance", 0.05)  # fmt: skip
    assert code == 0, err
    assert "centre distance    40 mm" in out
    assert "ratio w1/w2        0.666667 ... 1.5" in out
    assert "teeth              20 / 20" in out
    assert svg.stat().st_size > 1000


def test_a_failing_check_exits_1(capsys):
    # a 3-lobed oval of e = 0.4 is concave between its lobes: no rack can cut it
    code, out, _ = _run(capsys, "noncircular", "lobed", "-a", 40, "-e", 0.4, "--lobes", 3, 3)
    assert code == 1 and "gear1.convexity" in out and "FAIL" in out


def test_bad_input_exits_2_naming_the_option(capsys):
    code, _, err = _run(capsys, "noncircular", "elliptical", "-e", 1.5)
    assert code == 2 and "--eccentricity" in err
    code, _, err = _run(capsys, "noncircular", "elliptical", "-o", "x.svg")
    assert code == 2 and "--module" in err
    code, _, err = _run(capsys, "noncircular", "eccentric", "--lobes", 2, 2)
    assert code == 2 and "--lobes" in err


@settings(max_examples=20, deadline=None, derandomize=True, database=None,
          suppress_health_check=list(HealthCheck))  # fmt: skip
@given(
    kind=st.sampled_from(["elliptical", "lobed", "eccentric", "oval"]),
    a=st.sampled_from(["40", "-1", "nan", "1e300"]),
    e=st.sampled_from(["0.2", "0", "0.99", "-0.5", "x", "5"]),
    lobes=st.sampled_from([[], ["1", "2"], ["2", "3"], ["0", "1"]]),
)  # fmt: skip
def test_cli_sweep(capsys, kind, a, e, lobes):
    argv = ["noncircular", kind, "-a", a, "-e", e] + (["--lobes", *lobes] if lobes else [])
    code = main(argv)
    _, err = capsys.readouterr()
    assert code in (0, 1, 2), err
    assert "Traceback" not in err
