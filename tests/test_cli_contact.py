"""``geartrain contact``: the loaded contact analysis on the command line.

Sources: the printed figures equal the library's (GearPair.contact, the same pair and load);
exit status 0 / 1 (--max-te) / 2 (bad input, one line naming the option); hypothesis sweeps the
options (never an internal error, exit 3).
"""

from __future__ import annotations

import re

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from gears import Gear, GearPair
from gears.contact.modification import Modification
from trains.cli.app import main


def _run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_contact_prints_the_librarys_figures(capsys, tmp_path):
    figure = str(tmp_path / "te.png")
    code, out, _ = _run(capsys, "contact", "20", "50", "-m", "3", "--face-width", "30",
                        "--torque", "300", "--tip-relief", "0.015", "-o", figure)  # fmt: skip
    assert code == 0
    m = Modification(tip_relief=0.015)
    c = GearPair(Gear(20, 3, face_width=30, modification=m),
                 Gear(50, 3, face_width=30, modification=m)).contact(300)  # fmt: skip
    p2p = float(re.search(r"peak to peak\s+([\d.]+) um", out)[1])
    mean = float(re.search(r"mean ([\d.]+)", out)[1])
    assert p2p == pytest.approx(c.peak_to_peak, abs=1e-3)
    assert mean == pytest.approx(c.mean_mesh_stiffness, abs=1e-3)
    assert (tmp_path / "te.png").stat().st_size > 10_000


def test_contact_exit_status(capsys, tmp_path):
    base = ["contact", "20", "50", "-m", "3", "--face-width", "30", "--torque", "300"]
    assert _run(capsys, *base, "--max-te", "1")[0] == 1  # peak to peak 12.7 um > 1 um
    assert _run(capsys, *base, "--max-te", "100")[0] == 0
    code, out, err = _run(capsys, *base[:-4], "--torque", "300")  # no face width
    assert code == 2 and "--face-width" in err and not out
    code, out, err = _run(capsys, *base, "--misalignment", "5")
    assert code == 2 and "--misalignment" in err and not out
    code, _, err = _run(capsys, *base, "--figure", "harris", "-o", str(tmp_path / "h.svg"))
    assert code == 0 and (tmp_path / "h.svg").stat().st_size > 10_000


@given(
    st.integers(6, 80),
    st.integers(6, 200),
    st.sampled_from(["0.5", "2", "8"]),
    st.sampled_from(["0", "12", "30"]),
    st.sampled_from(["1e-3", "50", "5000", "-1", "nan"]),
    st.sampled_from(["0", "0.01", "0.2", "-0.1"]),
    st.sampled_from(["4", "16", "3", "x"]),
    st.sampled_from([[], ["--internal"], ["--f-ma", "0.01", "--f-sh", "-0.3"], ["--best"]]),
)
@settings(max_examples=15, deadline=None, derandomize=True, database=None,
          suppress_health_check=list(HealthCheck))  # fmt: skip
def test_contact_options_never_fail_inside(z1, z2, m, helix, torque, relief, positions, extra):
    import io
    from contextlib import redirect_stderr, redirect_stdout

    argv = ["contact", str(z1), str(z2), "-m", m, "--helix", helix, "--face-width", "20",
            "--torque", torque, "--tip-relief", relief, "--positions", positions,
            "--slices", "4", *extra]  # fmt: skip
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        code = main(argv)
    assert code in (0, 2), (argv, err.getvalue())
    if code == 2:
        assert len(err.getvalue().strip().splitlines()) == 1 and not out.getvalue()


def test_contact_of_a_ring_pair_with_f_ma_f_sh_and_the_best_modification(capsys):
    # the printed figures equal the library's: an internal pair, f_ma and f_sh adding to the
    # tilt, and --best's search (GearPair.best_modification at the same torque and tilt)
    code, out, _ = _run(capsys, "contact", "29", "77", "-m", "2", "--internal", "--face-width",
                        "20", "--torque", "60", "--f-ma", "0.006", "--f-sh", "0.004",
                        "--positions", "16", "--slices", "6", "--best")  # fmt: skip
    assert code == 0
    pair = GearPair(Gear(29, 2, face_width=20), Gear(77, 2, internal=True, face_width=20))
    c = pair.contact(60, misalignment=0.01, positions=16, slices=6)
    p2p = float(re.search(r"peak to peak\s+([\d.]+) um", out)[1])
    assert p2p == pytest.approx(c.peak_to_peak, abs=1e-3)
    s = pair.best_modification(60, f_ma=0.006, f_sh=0.004)
    best = re.search(r"best tip relief\s+([\d.]+) um, crowning ([\d.]+) um", out)
    assert float(best[1]) == pytest.approx(s.tip_relief * 1000, abs=0.01)
    assert float(best[2]) == pytest.approx(s.crowning * 1000, abs=0.01)
    code, out, err = _run(capsys, "contact", "20", "50", "-m", "3", "--face-width", "30",
                          "--torque", "300", "--f-sh", "nan")  # fmt: skip
    assert code == 2 and "--f-sh" in err and not out
