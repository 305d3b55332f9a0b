"""The ``geartrain`` CLI: ``pair`` and ``demo`` (issue 2), called through trains.cli.app.main.

Bad input, exit codes, help and progress (issue 11) are in test_cli_errors.py."""

from __future__ import annotations

import re

import pytest

from trains.cli.app import main


def _row(out: str, label: str) -> str:
    """The value column(s) of the report row starting with ``label``."""
    for line in out.splitlines():
        if line.startswith(label):
            return re.sub(r"^\[[^\]]*\]", "", line[len(label) :].strip()).strip()
    raise AssertionError(f"no row {label!r} in:\n{out}")


def _values(out: str, label: str) -> list[float]:
    """The numbers of the report row ``label``: the report prints 4 decimals, so a row is
    compared to its reference within one unit of that last digit (1e-4), not as text."""
    return [float(v) for v in re.findall(r"[-+]?\d+\.\d+(?:e[-+]?\d+)?", _row(out, label))]


def _run(capsys, *argv) -> str:
    assert main(list(argv)) == 0
    return capsys.readouterr().out


def test_pair_12_24_profile_shifted(capsys):
    out = _run(capsys, "pair", "12", "24", "--module", "3", "--shift", "0.6", "0.36")
    # peers.md (pygears, verified): 12/24, m 3, x 0.6/0.36 -> a_w = 56.49987 mm, alpha_w = 26.088
    assert _values(out, "centre distance a_w") == pytest.approx([56.4999], abs=1e-4)
    assert _values(out, "working pressure angle alpha_wt")[0] == pytest.approx(26.088, abs=1e-3)
    # y = (a_w - a_d)/m = (56.49987 - 54)/3 = 0.8333; k = y - (x1 + x2) = -0.1267 (standards §1.3)
    assert _values(out, "centre distance modification y") == pytest.approx([0.8333], abs=1e-4)
    assert _values(out, "tip alteration k") == pytest.approx([-0.1267, -0.1267], abs=1e-4)
    # KHK form d_a1 = d1 + 2 m (1 + y - x2) = 36 + 6 (1.8333 - 0.36) = 44.8397,
    # d_a2 = 72 + 6 (1.8333 - 0.6) = 79.3997 (standards.md §1.3); d_f = d - 2 m (1.25 - x)
    assert _values(out, "tip diameter d_a [mm]") == pytest.approx([44.8397, 79.3997], abs=1e-4)
    assert _values(out, "root diameter d_f [mm]") == pytest.approx([32.1, 66.66], abs=1e-4)
    # s_t = m (pi/2 + 2 x tan 20) = 3 (1.570796 + 0.436764) = 6.0227 (standards.md §1.4)
    assert _values(out, "thickness at d, s_t [mm]")[0] == pytest.approx(6.0227, abs=1e-4)
    assert _values(out, "ratio u = z2/z1") == pytest.approx([2.0], abs=1e-4)
    assert "contact ratio eps_alpha" in out and "mesh efficiency" in out
    assert "max specific sliding" in out
    for name in ("g1.undercut", "g2.pointed_tip", "contact_ratio", "tip_interference_2"):
        assert re.search(rf"\[ok  \] {re.escape(name)}\s+margin [+]", out), name
    assert "all conditions hold" in out


def test_pair_contact_ratio_matches_gearpair(capsys):
    from gears import Gear, GearPair

    out = _run(capsys, "pair", "12", "28", "--shift", "0.3", "0.2")
    # Joldasbekov §5.4 row 3: 12/28, x 0.3/0.2 -> epsilon_alpha = 1.36264 (pair_geometry doctest)
    assert _values(out, "contact ratio eps_alpha") == pytest.approx([1.3626], abs=1e-4)
    ref = GearPair(Gear(12, 1, profile_shift=0.3), Gear(28, 1, profile_shift=0.2))
    assert _values(out, "mesh efficiency (f = 0.1)") == pytest.approx(
        [ref.mesh_efficiency(0.1)], abs=1e-4
    )


def test_pair_internal_helical_with_face_width(capsys):
    argv = ["pair", "20", "80", "-m", "2", "--internal", "--helix", "15", "--face-width", "20"]
    # a zero-shift 20/80 ring's tip reaches the pinion's fillet: the report names the failed
    # check and the exit status is 1 (the CLI's convention: 1 = the design fails a check)
    assert main(argv) == 1
    out = capsys.readouterr().out
    assert re.search(r"\[FAIL\] tip_interference\s+margin -", out)
    # eps_beta = b sin(beta) / (pi m_n) = 20 sin 15 / (2 pi) = 0.8238 (Ozols 21.31)
    assert _values(out, "overlap ratio eps_beta") == pytest.approx([0.8238], abs=1e-4)
    # a_d = m_n (z2 - z1) / (2 cos beta) = 2 * 60 / (2 cos 15) = 62.1166 (standards.md §1.2)
    assert _values(out, "centre distance a_w") == pytest.approx([62.1166], abs=1e-4)
    assert "internal, right" in out
    for name in ("involute_interference", "trochoid_interference", "radial_interference"):
        assert name in out


def test_pair_from_center_distance_round_trip(capsys):
    out = _run(capsys, "pair", "12", "24", "-m", "3", "--center-distance", "56.5")
    assert _values(out, "centre distance a_w") == pytest.approx([56.5], abs=1e-4)
    out = _run(
        capsys, "pair", "12", "24", "-m", "3", "--shift", "0.6", "0", "--center-distance",
        "56.49987", "--split", "keep",
    )  # fmt: skip
    # keeping x1 = 0.6 the rest is x2 = 0.36 (peers.md pygears example, inverted)
    assert _values(out, "profile shift x") == pytest.approx([0.6, 0.36], abs=1e-4)


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["pair", "12", "24", "--module", "0"], "--module 0 is out of range"),
        (["pair", "0", "24"], "Z1 0 is out of range"),
        (["pair", "30", "20", "--internal"], "Z2 = 20 <= Z1 = 30"),
        (["pair", "12", "24", "--center-distance", "10"], "10.0 mm cannot be reached"),
        (["pair", "12", "24", "--pressure-angle", "50"], "--pressure-angle"),
    ],
)
def test_pair_errors_exit_2_with_the_gear_error(capsys, argv, message):
    assert main(argv) == 2
    out, err = capsys.readouterr()
    assert err.startswith("geartrain pair: error: ")
    assert message in err
    assert out == "" and err.count("\n") == 1  # one line, nothing on stdout


def test_demo_runs_the_default_pair(capsys):
    out = _run(capsys, "demo")
    assert "Profile-shifted spur pair 12/24" in out
    assert _values(out, "centre distance a_w") == pytest.approx(
        [56.4999], abs=1e-4
    )  # peers.md, pygears: 56.49987
    assert "all conditions hold" in out


def test_demo_writes_its_stage_as_a_scene(capsys, tmp_path):
    # issue 10: the README's demo also writes a small scene; the GLB holds one planet geometry
    # for three planet nodes (instancing), checked by loading the file
    import trimesh  # the mesh extra is part of the test extra

    path = tmp_path / "stage.glb"
    assert main(["demo", "--scene", str(path)]) == 0
    assert f"wrote {path}" in capsys.readouterr().out
    loaded = trimesh.load(path)
    assert len(loaded.graph.nodes_geometry) == 5 and len(loaded.geometry) == 3


def test_demo_sections_are_extensible():
    from trains.cli import demo

    assert all(callable(f) and isinstance(t, str) for t, f in demo.SECTIONS)


def test_synthesize_stages_prints_the_ranked_gearboxes(capsys):
    # issue 13: geartrain synthesize --ratio 37 --stages 2 prints what synthesize_gearbox ranks
    # (that function is checked against a brute-force product of single-stage synthesize results
    # in tests/trains/test_gearbox.py)
    from trains import synthesize_gearbox

    assert main(["synthesize", "--ratio", "37", "--stages", "2", "--limit", "3"]) == 0
    out = capsys.readouterr().out
    want = synthesize_gearbox(37, 2, 3, "simple", z_max=200, top=3, progress=False).table()
    assert out.split() == want.split()  # the same words; the CLI wraps at the terminal width
