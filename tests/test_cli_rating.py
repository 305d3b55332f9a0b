"""``geartrain rate`` and ``geartrain planetary --torque --speed`` (issue 18): the CLI prints what
the API rates, exits 1 when a safety is below its minimum and 2 for bad input."""

from __future__ import annotations

import re

import pytest

from gears import Gear, GearPair
from trains import Planetary
from trains.cli.app import main


@pytest.fixture(autouse=True)
def _wide_output(monkeypatch):
    # these tests read values from the tables: one row per line (tests/test_cli_layout.py holds
    # the layout at the 80 columns of a pipe)
    monkeypatch.setenv("COLUMNS", "200")


def _run(capsys, *argv) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def _row(out: str, label: str) -> list[float]:
    """The numbers of the table row ``label`` (a line of the label and numbers only)."""
    for line in out.splitlines():
        rest = line[len(label) :].split() if line.startswith(label + " ") else []
        if rest and all(re.fullmatch(r"[-+0-9.e]+", v) for v in rest):
            return [float(v) for v in rest]
    raise AssertionError(f"no row {label!r} in:\n{out}")


def test_rate_prints_the_api_safeties_and_exits_by_them(capsys):
    argv = ["rate", "19", "61", "--module", "3", "--face-width", "30", "--torque", "150",
            "--speed", "1450"]  # fmt: skip
    code, out, err = _run(capsys, *argv)
    api = GearPair(Gear(19, 3, face_width=30), Gear(61, 3, face_width=30)).rating(150, 1450)
    # the report prints 4 decimals: the API's values to one unit of the last printed digit
    assert _row(out, "safety pitting S_H") == pytest.approx(api.safety_pitting, abs=1e-4)
    assert _row(out, "safety bending S_F") == pytest.approx(api.safety_bending, abs=1e-4)
    assert code == (0 if api.check().ok else 1), err
    for symbol in ("Z_H", "K_v", "Y_F", "ISO 6336-2 §6.1", "checks:"):
        assert symbol in out
    # a minimum the pair cannot meet: exit 1, the failed finding named
    code, out, _ = _run(capsys, *argv, "--min-pitting", "5")
    assert code == 1 and re.search(r"\[FAIL\] pitting_1", out)


def test_rate_internal_pair_from_the_shaper_cut_root(capsys):
    code, out, _ = _run(capsys, "rate", "20", "80", "-m", "2", "--internal", "--face-width", "20",
                        "--torque", "60", "--speed", "1500", "--material", "nitrided")  # fmt: skip
    assert code in (0, 1)
    assert "gear 2 measured on the exact envelope (shaper-cut)" in out
    api = GearPair(Gear(20, 2, face_width=20), Gear(80, 2, internal=True, face_width=20))
    r = api.rating(60, 1500, "nitrided")
    assert _row(out, "safety bending S_F") == pytest.approx(r.safety_bending, abs=1e-4)


@pytest.mark.parametrize(
    "argv, named",
    [
        (["rate", "20", "40", "--face-width", "10", "--speed", "100"], "--torque"),
        (["rate", "20", "40", "--face-width", "10", "--torque", "0", "--speed", "100"], "--torque"),
        (["rate", "20", "40", "--torque", "10", "--speed", "100"], "--face-width"),
        (["rate", "20", "40", "--face-width", "10", "--torque", "10", "--speed", "100",
          "--material", "brass"], "case-carburized"),
        (["rate", "20", "40", "--face-width", "10", "--torque", "10", "--speed", "100",
          "--quality", "13"], "--quality"),
        (["rate", "20", "40", "--face-width", "10", "--torque", "10", "--speed", "-3"], "--speed"),
        (["planetary", "21", "36", "93", "--torque", "10"], "--speed"),
        (["planetary", "21", "36", "93", "--torque", "10", "--speed", "100"], "--face-width"),
    ],
)  # fmt: skip
def test_bad_rating_input_exits_2_naming_the_option(capsys, argv, named):
    code, out, err = _run(capsys, *argv)
    assert code == 2 and out == "" and err.count("\n") == 1, (code, out, err)
    assert named in err and "Traceback" not in err


def test_planetary_rates_every_mesh(capsys):
    argv = ["planetary", "21", "36", "93", "--planets", "3", "--module", "2", "--face-width", "20",
            "--torque", "120", "--speed", "1500"]  # fmt: skip
    code, out, _ = _run(capsys, *argv)
    api = Planetary(21, 36, 93, n_planets=3, module=2).rating(120, 1500, face_width=20)
    for name, r in api.items():
        row = _row(out, name)
        assert row[3:] == pytest.approx([*r.safety_pitting, *r.safety_bending], abs=1e-3)
    assert "rating checks:" in out and code == 0
    code, out, _ = _run(capsys, *argv, "--min-bending", "3")
    assert code == 1 and "[FAIL] planet-ring.bending_1" in out


def test_rate_against_scuffing(capsys):
    # the oil's FZG stage, temperature and viscosities: S_B and S_intS as the API rates them,
    # exit 1 below --min-scuffing, 2 for an oil option without --fzg-stage or out of range
    from gears.rating.scuffing import Oil

    argv = ["rate", "17", "40", "-m", "4", "--face-width", "40", "--torque", "400", "--speed",
            "3000", "--roughness", "0.6", "--oil-viscosity", "100", "--oil-viscosity-100", "11",
            "--fzg-stage", "9", "--oil-temperature", "80"]  # fmt: skip
    api = GearPair(Gear(17, 4, face_width=40), Gear(40, 4, face_width=40)).rating(
        400, 3000, roughness=0.6, oil_viscosity=100,
        scuffing=Oil(9, 80, 100, 11),
    )  # fmt: skip
    code, out, _ = _run(capsys, *argv)
    assert code == 1 and re.search(r"\[FAIL\] scuffing_flash", out)
    assert _row(out, "scuffing S_B (flash)")[0] == pytest.approx(api.safety_scuffing[0], abs=1e-4)
    code, out, _ = _run(capsys, *argv, "--min-scuffing", "0.9", "1", "--min-pitting", "0.5")
    assert code == 0, out
    for bad, named in ((["--fzg-stage", "13"], "--fzg-stage"),
                       (["--oil-temperature", "300"], "--oil-temperature")):  # fmt: skip
        code, out, err = _run(capsys, *argv, *bad)
        assert code == 2 and out == "" and named in err, err
    code, out, err = _run(capsys, *argv[:-4])
    assert code == 2 and "--fzg-stage" in err, err


def test_planetary_rates_every_mesh_against_scuffing(capsys):
    from gears.rating.scuffing import Oil

    argv = ["planetary", "21", "36", "93", "--planets", "3", "--module", "2", "--face-width", "20",
            "--torque", "120", "--speed", "1500", "--fzg-stage", "10", "--oil-temperature", "70",
            "--oil-viscosity", "150", "--oil-viscosity-100", "15"]  # fmt: skip
    code, out, _ = _run(capsys, *argv)
    oil = Oil(10, 70, 150, 15)
    api = Planetary(21, 36, 93, n_planets=3, module=2).rating(
        120, 1500, face_width=20, scuffing=oil, oil_viscosity=150
    )
    for name, r in api.items():
        row = _row(out, name)
        assert row[-2:] == pytest.approx(r.safety_scuffing, abs=1e-3)
    assert "sun-planet.scuffing_flash" in out
    code, out, err = _run(capsys, "planetary", "21", "36", "93", "--fzg-stage", "10")
    assert code == 2 and "--fzg-stage" in err
