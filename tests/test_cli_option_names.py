"""Every option error of the ``geartrain`` CLI names the option the user gave.

A value the library refuses (a shift that closes a bevel tooth space, a shift sum with no working
pressure angle, a cutter of too few teeth) reaches the user through the command's ``NAMES`` map
(trains/cli/_common.py ``translate``): the message must name the option, not the library's
parameter (``x``, ``cutter teeth``) or another option the user did not give. The sweep gives each
numeric option of the geometry commands a negative, a moderate and a huge value.
"""

from __future__ import annotations

import argparse

import pytest

from trains.cli.app import build_parser, main

BASE = {
    "bevel": ["bevel", "20", "40"],
    "differential": ["differential"],
    "pair": ["pair", "12", "24"],
    "profile": ["profile", "12"],
    "mesh": ["mesh", "20"],
    "worm": ["worm", "2", "40"],
}
#: options that name a file or a resource, not a number of the design
NOT_DESIGN = {"--scene", "--animate", "--output", "--threads", "--frames"}


def _numeric_options(command: str) -> list[tuple[str, tuple[str, ...], int]]:
    parser = build_parser()
    (sub,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    out = []
    for act in sub.choices[command]._actions:
        if not act.option_strings or act.nargs == 0 or act.choices or act.type is None:
            continue
        name = max(act.option_strings, key=len)
        if name not in NOT_DESIGN:
            out.append(
                (name, tuple(act.option_strings), act.nargs if isinstance(act.nargs, int) else 1)
            )
    return out


CASES = [(cmd, *opt) for cmd in BASE for opt in _numeric_options(cmd)]


@pytest.mark.parametrize(("command", "option", "aliases", "n"), CASES,
                         ids=[f"{c[0]} {c[1]}" for c in CASES])  # fmt: skip
def test_an_option_error_names_its_option(
    capsys, tmp_path, monkeypatch, command, option, aliases, n
):
    monkeypatch.chdir(tmp_path)
    # a huge module is a valid (and slow to draw) gear: its refusal is tested elsewhere
    for value in ("-1", "5") if option == "--module" else ("-1", "5", "1e6"):
        code = main([*BASE[command], option, *[value] * n])
        err = capsys.readouterr().err
        if code == 2:
            # a size the work budget refuses names the option that makes it fit instead
            budget = "budget" in err and "--tolerance" in err
            assert budget or any(a in err for a in aliases), f"{command} {option} {value}: {err}"


def test_bevel_shift_that_closes_the_tooth_space(capsys):
    # the case: --shift 5 closed the pinion's tooth space and the message said only
    # "the crown tooth has no thickness"; 2 x 5 tan 20 deg = 3.64 > pi/2 (ISO 23509 mean-cone
    # thickness s_m = m_m (pi/2 + 2 x_hm tan alpha + x_sm) of both gears must stay positive)
    assert main(["bevel", "20", "40", "-m", "3", "-b", "20", "--shift", "5"]) == 2
    err = capsys.readouterr().err
    assert "--shift = 5" in err and "pi/2" in err and "3.64" in err, err
    # a shift that leaves the virtual pinion's tip inside its base circle is a report, not a
    # crash of describe()
    assert main(["bevel", "20", "40", "-m", "3", "-b", "20", "--shift", "-1.9"]) in (0, 1)


def test_rate_names_the_shift_that_spoils_the_contact_ratio(capsys):
    # 19/61 with x = 3 / 3: the contact ratio falls below 1 and ISO 6336 does not apply
    code = main(["rate", "19", "61", "-m", "3", "--face-width", "30", "--torque", "150",
                 "--speed", "1450", "--shift", "3", "3"])  # fmt: skip
    err = capsys.readouterr().err
    assert code == 2 and "--shift 3 3" in err, err


@pytest.mark.parametrize(
    ("path", "why"),
    [
        ("/proc/pair.glb", "does not accept new files"),  # permission bits say yes to root
        ("/tmp/" + "a" * 300 + ".stl", "longer than the file system allows"),
    ],
)
def test_an_output_that_cannot_be_created_is_refused_before_any_work(capsys, path, why):
    # the issue's case: the scene was computed first, then the write failed with "No such file
    # or directory"; the file is now opened (and removed) when the option is read, so nothing is
    # printed before the one-line refusal that names the option and the reason
    code = main(["bevel", "20", "40", "-m", "3", "-b", "20", "--scene", path])
    out, err = capsys.readouterr()
    assert code == 2 and out == "" and "--scene" in err and why in err, err
    assert err.count("\n") == 1


def test_checking_an_output_leaves_no_file(tmp_path):
    # the check creates the file to see that it can, and removes it: a refused or failed run
    # leaves nothing behind, and an existing file is opened to append, not truncated
    from gears.files import check_output

    assert check_output(tmp_path / "new.stl", (".stl",)).name == "new.stl"
    assert list(tmp_path.iterdir()) == []
    old = tmp_path / "old.stl"
    old.write_text("kept")
    check_output(old, (".stl",))
    assert old.read_text() == "kept"
