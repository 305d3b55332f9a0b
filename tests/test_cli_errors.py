"""Every input to the ``geartrain`` CLI gets a clear answer (issue 11, the command-line half).

One class of the issue per section: exit codes; validate first, then print; help; report text;
progress; the internal pair and PNG fill; a hypothesis sweep of random argv. Everything runs
through ``trains.cli.app.main`` (capsys) except the internal-bug case, which needs a real process to
show that the traceback reaches the user with exit status 3.
"""

from __future__ import annotations

import argparse
import ast
import contextlib
import io
import os
import pathlib
import re
import shlex
import subprocess
import sys
import tempfile

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from trains.cli.app import build_parser, main

ROOT = pathlib.Path(__file__).resolve().parent.parent
TRAIN_FILE = str(ROOT / "examples" / "train_simple_planetary.toml")


def _run(capsys, *argv) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def _bad_input(capsys, *argv) -> str:
    """Run ``argv``, assert exit 2 with one line on stderr and nothing on stdout; the line."""
    code, out, err = _run(capsys, *argv)
    assert code == 2, (code, out, err)
    assert out == "", out
    assert err.count("\n") == 1 and err.startswith(f"geartrain {argv[0]}: error: "), err
    assert "Traceback" not in err
    return err


def _subparsers() -> dict[str, argparse.ArgumentParser]:
    parser = build_parser()
    (sub,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    return dict(sub.choices)


# ---------------------------------------------------------------------------------------------
# 1. one exit-code convention: 0 every check passes, 1 a check fails, 2 bad input, 3 a bug


@pytest.mark.parametrize(
    "argv",
    [
        ["pair", "12", "24", "--module", "3", "--shift", "0.6", "0.36"],
        ["planetary", "18", "45", "108", "--planets", "3", "--module", "2"],
        ["synthesize", "--ratio", "7", "--planets", "3"],
        ["train", TRAIN_FILE, "--fixed", "ring", "--input", "sun=1500"],
    ],
)
def test_a_design_that_passes_exits_0(capsys, argv):
    code, out, err = _run(capsys, *argv)
    assert code == 0 and out and err == ""


@pytest.mark.parametrize(
    ("argv", "failed"),
    [
        # zero-shift 20/80 ring: its tip reaches the pinion's fillet (test_cli.py, same pair)
        (["pair", "20", "80", "-m", "2", "--internal"], "tip_interference"),
        # 4 planets in 18/45/108: T = 126 is not a multiple of 4 (lectures §4.3 gcd form), and
        # their tips overlap (the largest count that fits is 3)
        (["planetary", "18", "45", "108", "--planets", "4"], "assembly"),
        # 60 planets in a ratio-3 stage: no set passes the neighbour condition (test_synthesis)
        (["synthesize", "--ratio", "3", "--planets", "60", "--z-max", "120"], "neighbour"),
        # a minimum contact ratio of 5 no spur pair reaches (eps_alpha < 2 for z = 12/24)
        (["pair", "12", "24", "--min-contact-ratio", "5"], "contact_ratio"),
    ],
)
def test_a_design_that_fails_a_check_exits_1_and_names_it(capsys, argv, failed):
    code, out, err = _run(capsys, *argv)
    assert code == 1, (out, err)
    assert failed in out and err == ""
    # the report says which check failed: a FAIL line or the empty-result summary
    assert "FAIL" in out or "no candidate meets the request" in out


@pytest.mark.parametrize(
    ("argv", "named"),
    [
        (["pair", "12", "24", "--module", "0"], "--module 0"),
        (["planetary", "18", "45", "108", "--planets", "0"], "--planets 0"),
        (["synthesize", "--ratio", "1/0"], "--ratio '1/0'"),
        (["train", TRAIN_FILE, "--input", "sun=fast"], "sun=fast"),
        (["profile", "12", "--method", "hob"], "'hob'"),
        (["pair", "12"], "Z2"),  # argparse's own usage error: one line, exit 2
        (["nonsense"], "nonsense"),
    ],
)
def test_bad_input_exits_2_with_one_line_naming_it(capsys, argv, named):
    code, out, err = _run(capsys, *argv)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and named in err, err


@pytest.mark.parametrize(
    "exc", [ZeroDivisionError("division by zero"), KeyError("involute"), ValueError("numpy")]
)
def test_an_internal_bug_shows_its_traceback_and_exits_3(capsys, monkeypatch, exc):
    from trains.cli.gear_commands import pair

    def broken(args):
        print("half a report")
        raise exc

    monkeypatch.setattr(pair, "run", broken)
    code, out, err = _run(capsys, "pair", "12", "24")
    assert code == 3
    assert "Traceback" in err and type(exc).__name__ in err and "internal error" in err
    assert out == ""  # no half report either


def test_an_internal_bug_exits_3_from_the_console_process():
    code = (
        "import sys\n"
        "from trains.cli.gear_commands import pair\n"
        "pair.build_pair = lambda args: 1 / 0\n"
        "from trains.cli.app import main\n"
        "sys.exit(main(['pair', '12', '24']))\n"
    )
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert p.returncode == 3
    assert "Traceback" in p.stderr and "ZeroDivisionError" in p.stderr and p.stdout == ""


def test_a_request_too_large_for_memory_is_bad_input_not_a_bug(capsys, monkeypatch):
    from trains.cli.train_commands import synthesize

    def huge(args):
        raise MemoryError("Unable to allocate 7.28 TiB for an array")

    monkeypatch.setattr(synthesize, "run", huge)
    err = _bad_input(capsys, "synthesize", "--ratio", "7", "--z-max", "1000000")
    assert "7.28 TiB" in err and "less work" in err


def test_a_reader_that_closes_early_is_no_error():
    # `geartrain ... | head -1` with a report larger than the pipe buffer (1 MB here)
    code = (
        "import sys\n"
        "from trains.cli.gear_commands import pair\n"
        "pair.run = lambda args: print('x' * 100 + '\\n') or print('y\\n' * 500_000) or 0\n"
        "from trains.cli.app import main\n"
        "sys.exit(main(['pair', '12', '24']))\n"
    )
    p = subprocess.Popen(
        [sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=ROOT
    )
    p.stdout.readline()
    p.stdout.close()
    err = p.stderr.read().decode()
    assert p.wait() == 0 and "Traceback" not in err and "BrokenPipe" not in err, err


def test_the_convention_is_documented_in_help_and_readme(capsys):
    code, out, _ = _run(capsys, "--help")
    assert code == 0
    for status, words in (("0", "every check passes"), ("1", "fails a check"),
                          ("2", "bad input"), ("3", "internal error")):  # fmt: skip
        assert re.search(rf"^\s+{status}\s+.*{words}", out, flags=re.M), status
    readme = (ROOT / "README.md").read_text()
    assert "exit status" in readme and "internal error" in readme


# ---------------------------------------------------------------------------------------------
# 2. validate first, then print: output paths and numbers are checked before any work


def test_output_in_a_missing_directory_is_refused_before_the_work(capsys, tmp_path):
    target = tmp_path / "missing" / "gear.svg"
    err = _bad_input(capsys, "profile", "12", "-o", target)
    assert "--output" in err and "does not exist" in err and not target.parent.exists()


def test_output_that_is_a_directory_is_refused(capsys, tmp_path):
    err = _bad_input(capsys, "profile", "12", "-o", tmp_path)
    assert "--output" in err and "is a directory" in err


def test_output_with_an_unknown_suffix_is_refused(capsys, tmp_path):
    err = _bad_input(capsys, "profile", "12", "-o", tmp_path / "gear.txt")
    assert "--output" in err and ".txt" in err and ".svg" in err
    assert not (tmp_path / "gear.txt").exists()


@pytest.mark.parametrize(
    ("argv", "named"),
    [
        (["train", TRAIN_FILE, "--fixed", "ring", "--input", "sun=1e400"], "sun=1e400"),
        (["pair", "12", "24", "--min-contact-ratio", "nan"], "--min-contact-ratio nan"),
        (["pair", "12", "24", "--friction", "-1"], "--friction -1"),
        (["pair", "12", "24", "--friction", "1"], "--friction 1"),
        (["pair", "12", "24", "--module", "inf"], "--module inf"),
        (["pair", "12", "24", "--shift", "nan", "0"], "--shift nan"),
        (["pair", "12", "24", "--min-tip-land", "-1"], "--min-tip-land -1"),
        (["profile", "12", "--tolerance", "0"], "--tolerance 0"),
        (["profile", "12", "--bore", "-3"], "--bore -3"),
        (["synthesize", "--ratio", "7", "--tolerance", "nan"], "--tolerance nan"),
        (["synthesize", "--ratio", "7", "--z-max", "many"], "--z-max 'many'"),
        (["synthesize", "--ratio", "7", "--planets", "5-3"], "--planets '5-3'"),
        (["train", TRAIN_FILE, "--efficiency", "1.5"], "--efficiency 1.5"),
        (["planetary", "18", "45", "108", "--clearance", "inf"], "--clearance inf"),
    ],
)
def test_numbers_out_of_range_name_the_option(capsys, argv, named):
    err = _bad_input(capsys, *argv)
    assert named in err, err


@pytest.mark.parametrize(
    ("argv", "named"),
    [
        (["train", str(ROOT / "examples")], "is not a file"),
        (["train", str(ROOT / "no-such-train.toml")], "does not exist"),
        (["train", TRAIN_FILE, "--input", "sun"], "MEMBER=SPEED"),
    ],
)
def test_unreadable_train_files_and_inputs_are_named(capsys, argv, named):
    assert named in _bad_input(capsys, *argv)


@pytest.mark.parametrize(
    ("argv", "words", "api"),
    [
        # the library says split='proportional'; the CLI says --split proportional
        (
            [
                "pair",
                "12",
                "60",
                "--internal",
                "--center-distance",
                "25",
                "--split",
                "proportional",
            ],
            "--split proportional",
            "split=",
        ),
        # the library says x1 + x2; the CLI names the --shift values X1 + X2
        (["pair", "12", "24", "--shift", "-3", "-3"], "X1 + X2", "x1"),
        # the library says helix_angle; the CLI says --helix
        (["pair", "12", "24", "--helix", "70"], "--helix", "helix_angle"),
        # the library says z_min / z_max; the CLI says --z-min / --z-max
        (["synthesize", "--ratio", "7", "--z-min", "30", "--z-max", "20"], "--z-min", "z_min"),
        # an oversized search is refused before any work, naming the options that bound it
        (["synthesize", "--ratio", "7", "--z-max", "100000"], "--max-seconds", "max_seconds"),
    ],
)
def test_errors_speak_the_cli_words_not_the_api(capsys, argv, words, api):
    err = _bad_input(capsys, *argv)
    assert words in err and api not in err, err


def test_an_error_after_the_work_started_prints_no_half_report(capsys, monkeypatch):
    from gears import GearError
    from trains.cli.gear_commands import pair

    real = pair.pair_report

    def fails_midway(*a, **k):
        print(real(*a, **k))  # the whole report printed ...
        raise GearError("late failure")  # ... then an error: none of it may reach stdout

    monkeypatch.setattr(pair, "pair_report", fails_midway)
    assert "late failure" in _bad_input(capsys, "pair", "12", "24")


# ---------------------------------------------------------------------------------------------
# 3. help: user sentences, no RST, examples keep their lines, defaults shown, --version


def test_demo_help_is_a_user_sentence(capsys):
    code, out, _ = _run(capsys, "demo", "--help")
    assert code == 0
    assert "Run the built-in example design" in out
    assert "SECTIONS" not in out and "later stage" not in out  # the old developer docstring


@pytest.mark.parametrize("name", sorted(_subparsers()))
def test_help_has_no_rst_and_examples_keep_their_lines(name):
    text = _subparsers()[name].format_help()
    for markup in ("``", "::", ":class:", ":mod:", ":func:", ":meth:"):
        assert markup not in text, (name, markup)
    examples = [line for line in text.splitlines() if line.lstrip().startswith("geartrain ")]
    assert examples, f"{name} --help shows no example"
    assert all(line.count("geartrain ") == 1 for line in examples)  # one command a line


# 'search' (another helper's command, issue 11 report): 'search gearbox' options lack help yet
@pytest.mark.parametrize("name", sorted(set(_subparsers()) - {"search"}))
def test_every_option_has_help_and_shows_its_default(name):
    parsers = [(name, _subparsers()[name])]
    for where, parser in parsers:
        text = " ".join(parser.format_help().split())
        for action in parser._actions:
            if isinstance(action, argparse._HelpAction):
                continue
            if isinstance(action, argparse._SubParsersAction):  # e.g. search pairs / gearbox
                parsers += [(f"{where} {n}", p) for n, p in action.choices.items()]
                continue
            assert action.help, (where, action.dest)
            shown = action.default not in (None, False, argparse.SUPPRESS)
            if shown and action.option_strings:
                default = re.escape(str(action.default))
                assert re.search(rf"\(default:? {default}", text), (where, action.dest)


def test_version_comes_from_the_distribution(capsys):
    from importlib.metadata import version

    code, out, _ = _run(capsys, "--version")
    assert code == 0 and out.strip() == f"geartrain {version('geartrain')}"


def _help_examples() -> list[tuple[str, str]]:
    found = [("geartrain", build_parser().format_help())]
    found += [(n, p.format_help()) for n, p in sorted(_subparsers().items())]
    return [
        (where, line.strip())
        for where, text in found
        for line in text.splitlines()
        if line.lstrip().startswith("geartrain ")
    ]


@pytest.mark.parametrize(("where", "example"), _help_examples())
def test_every_help_example_runs(capsys, monkeypatch, tmp_path, where, example):
    monkeypatch.chdir(ROOT)  # the examples name files relative to the repository
    argv = shlex.split(example)[1:]
    for i, a in enumerate(argv[:-1]):
        if a in ("-o", "--output", "--scene", "--animate") and "." in argv[i + 1]:
            argv[i + 1] = str(tmp_path / pathlib.Path(argv[i + 1]).name)
    code, out, err = _run(capsys, *argv)
    assert code == 0, f"{where} --help example {example!r} exits {code}: {err}"
    assert out


def test_scheme_help_names_every_scheme():
    # the help text lists the schemes without importing the library; it must not drift
    from trains.planetary.schemes import SCHEMES

    for name in ("planetary", "synthesize"):
        text = " ".join(_subparsers()[name].format_help().split())
        assert all(s in text for s in SCHEMES), name


def test_command_modules_import_the_library_only_inside_run():
    # building the parser (geartrain --help) must not import numpy, scipy or the library: the
    # command modules' top-level imports are the standard library and the CLI's shared modules
    # (trains.cli._common, _text, _types, _rating)
    stdlib = set(sys.stdlib_module_names) | {"__future__"}
    paths = [*(ROOT / "trains" / "cli").rglob("*.py")]
    assert len(paths) >= 9
    for path in paths:
        tree = ast.parse(path.read_text())
        for node in tree.body:
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                names = [node.module or ""]
            else:
                continue
            for n in names:
                ok = n.split(".")[0] in stdlib or n in (
                    "trains", "trains.cli._common", "trains.cli._text", "trains.cli._types",
                    "trains.cli._rating",
                )  # fmt: skip
                assert ok, f"{path.name} imports {n} at module level"


def test_help_loads_neither_numpy_nor_the_library():
    # the end-to-end form of the rule above, through the lazy trains facade (PEP 562): a fresh
    # interpreter builds every parser and has imported no numpy, scipy, shapely or gears
    code = (
        "import sys, trains.cli.app; trains.cli.app.build_parser(); "
        "print(sorted(m for m in ('numpy', 'scipy', 'shapely', 'gears') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


# ---------------------------------------------------------------------------------------------
# 4. report text: wrapped at the terminal width, the synthesis table explained, summary true


@pytest.mark.parametrize("columns", [60, 100])
def test_report_lines_wrap_at_the_terminal_width(capsys, monkeypatch, columns):
    monkeypatch.setenv("COLUMNS", str(columns))
    code, out, _ = _run(capsys, "planetary", "18", "45", "108", "--planets", "4")
    assert code == 1
    lines = out.splitlines()
    # the assembly finding alone was 426 characters; every word of it is still there
    assert max(len(line) for line in lines) <= columns
    assert "nearest assemblable counts: 3 or 6" in " ".join(" ".join(lines).split())


def test_synthesis_table_explains_its_columns(capsys):
    code, out, _ = _run(capsys, "synthesize", "--ratio", "7", "--planets", "3")
    assert code == 0
    header = next(line for line in out.splitlines() if "z2p" in line and "hunt" in line)
    legend = " ".join(out[out.index(header) :].split())
    assert "z2p planet gear on the ring" in legend
    assert "hunt number of meshes whose tooth counts have no common factor" in legend


@pytest.mark.parametrize(
    "argv",
    [
        ["--ratio", "7", "--planets", "3"],
        ["--ratio", "16", "--planets", "3", "--scheme", "stepped", "--z-max", "120"],
        ["--ratio", "3", "--planets", "60", "--z-max", "120"],
    ],
)
def test_synthesis_summary_names_the_condition_that_removed_most(capsys, argv):
    _, out, _ = _run(capsys, "synthesize", *argv)
    text = " ".join(out.split())
    counts = dict(
        (name, int(n))
        for name, n in re.findall(r"([a-z ]+?) (\d+)(?:,|$)", text.split("per condition: ")[1])
    )
    named, n = re.search(r"the '([a-z ]+)' condition removed the most \((\d+)\)", text).groups()
    # brute force over the summary's own counts: the named one removed the most
    assert int(n) == max(counts.values()) == counts[named.strip()]


# ---------------------------------------------------------------------------------------------
# 5. progress: tqdm, on a terminal only, through the API's callback


def test_tqdm_is_a_core_dependency():
    import tomllib

    deps = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["dependencies"]
    assert any(re.match(r"tqdm\b", d) for d in deps)


def test_synthesize_reports_progress_per_block():
    from trains import synthesize

    calls = []
    found = synthesize(
        16, 3, scheme="stepped", z_max=120, progress=lambda d, t: calls.append((d, t))
    )
    assert found
    # z = 17..120 is 104 counts; 10^6 // 104^2 = 92 z1 values a block -> 2 blocks (brute force
    # of the block rule in trains.design.synthesis)
    assert calls == [(1, 2), (2, 2)]


def test_no_progress_bar_when_stderr_is_not_a_terminal(capsys):
    code, _, err = _run(capsys, "synthesize", "--ratio", "16", "--scheme", "stepped",
                        "--z-max", "120")  # fmt: skip
    assert code == 0 and err == ""


def test_progress_bar_on_a_terminal(monkeypatch):
    from trains.cli import _common

    class Tty(io.StringIO):
        def isatty(self):
            return True

    fake = Tty()
    monkeypatch.setattr(sys, "stderr", fake)
    with _common.progress_bar("synthesize", delay=0) as update:
        update(1, 4)
        update(4, 4)
    assert "synthesize" in fake.getvalue() and "4/4" in fake.getvalue()


def test_profile_feeds_the_outline_progress_to_the_bar(capsys, monkeypatch, tmp_path):
    from trains.cli.gear_commands import profile

    calls = []

    @contextlib.contextmanager
    def recorder(desc, total=None, delay=1.0):
        yield lambda done, total: calls.append((desc, done, total))

    monkeypatch.setattr(profile, "progress_bar", recorder)
    code, _, _ = _run(capsys, "profile", "12", "--method", "rack", "--tolerance", "0.01",
                      "--no-check", "-o", tmp_path / "g.svg")  # fmt: skip
    # Gear.outline(progress=) reports the rack simulation chunk by chunk, ending at done = total
    assert code == 0 and calls and calls[-1][1] == calls[-1][2] and calls[0][0] == "rack outline"


# ---------------------------------------------------------------------------------------------
# 6. missing from the CLI: an internal pair drawn; PNG fill respects holes


def test_an_internal_pair_can_be_drawn(capsys, tmp_path):
    import numpy as np

    out_file = tmp_path / "internal.npz"
    # (the zero-shift 20/80 pair fails tip_interference: --no-check, the drawing is the point)
    code, out, _ = _run(capsys, "profile", "80", "-m", "2", "--internal", "--mate", "20",
                        "--tolerance", "0.01", "--no-check", "-o", out_file)  # fmt: skip
    assert code == 0 and "wrote" in out
    with np.load(out_file) as z:
        # pinion: one ring (outline0_ring0); the ring gear: its outer circle and its toothed hole
        assert sorted(z.files) == ["outline0_ring0", "outline1_ring0", "outline1_ring1"]
        # the pinion sits inside the ring: its centre is offset by a_w = m (z2 - z1) / 2 = 60 mm
        pinion, rim = z["outline0_ring0"], z["outline1_ring0"]
        assert np.hypot(*rim.T).max() > np.hypot(*pinion.T).max()


@pytest.mark.parametrize(
    ("argv", "hole"),
    [
        (["profile", "30", "--bore", "10"], (0.0, 0.0)),  # the bore's centre
        (["profile", "80", "-m", "2", "--internal"], (0.0, 0.0)),  # the ring's interior
        (["profile", "80", "-m", "2", "--internal", "--mate", "20", "--no-check"], (-30.0, 0.0)),
    ],
)
def test_png_leaves_bores_and_ring_interiors_unfilled(capsys, tmp_path, argv, hole):
    import matplotlib.image

    png = tmp_path / "gear.png"
    # the figure is drawn by gears.figures.plot.outlines_figure, which save() uses; its data ->
    # pixel
    # transform locates the hole's centre in the written image
    code, _, _ = _run(capsys, *argv, "--tolerance", "0.05", "-o", png)
    assert code == 0
    from gears import Gear, GearPair
    from gears.figures.plot import outlines_figure

    z = int(argv[1])
    gear = Gear(z, 2 if "-m" in argv else 1, internal="--internal" in argv)
    if "--mate" in argv:
        shapes = GearPair(Gear(20, 2), gear).outlines(0.0, 0.05)
    else:
        shapes = [gear.outline(0.05, bore=10 if "--bore" in argv else None)]
    fig = outlines_figure(*shapes)
    fig.canvas.draw()
    x, y = fig.axes[0].transData.transform(hole)
    image = matplotlib.image.imread(png)
    h = image.shape[0]
    scale = image.shape[1] / fig.canvas.get_width_height()[0]
    pixel = image[int(h - y * scale), int(x * scale), :3]
    assert pixel.min() > 0.99, pixel  # white: not filled


# ---------------------------------------------------------------------------------------------
# 7. hypothesis: random argv at every sub-command -> exit 0, 1 or 2, never a traceback

_NUMBERS = ["nan", "inf", "-inf", "1e400", "-1", "0", "0.5", "1", "3", "abc", "", "1/0", "2.5"]
_TEETH = ["0", "-3", "1", "12", "17", "20", "24", "45", "80", "x", "1e3", "7.5"]

_OPTIONS = {
    "pair": {"--module": _NUMBERS, "--shift": _NUMBERS, "--helix": [*_NUMBERS, "70"],
             "--pressure-angle": [*_NUMBERS, "20", "44.9", "90"], "--face-width": _NUMBERS,
             "--center-distance": [*_NUMBERS, "20", "30", "1000"], "--split":
             ["keep", "proportional", "equal_sliding", "x"], "--min-contact-ratio": _NUMBERS,
             "--min-tip-land": _NUMBERS, "--friction": _NUMBERS, "--internal": None},
    "planetary": {"--planets": _TEETH[:6], "--module": _NUMBERS, "--scheme":
                  ["simple", "stepped", "double-planet", "external", "internal", "zz"],
                  "--clearance": _NUMBERS, "--coaxial": None, "--center-distance": _NUMBERS,
                  "--torque": _NUMBERS, "--speed": _NUMBERS, "--face-width": _NUMBERS},
    "rate": {"--module": _NUMBERS, "--shift": _NUMBERS, "--helix": ["0", "15", "nan", "70"],
             "--internal": None, "--face-width": [*_NUMBERS, "20"], "--torque": _NUMBERS,
             "--speed": _NUMBERS, "--material": ["nitrided", "brass", "grey-cast-iron"],
             "--life": _NUMBERS, "--quality": ["0", "5", "12", "13", "x"],
             "--tip-relief": _NUMBERS, "--min-bending": _NUMBERS},
    "synthesize": {"--ratio": [*_NUMBERS, "7", "16", "-3", "22/3"], "--planets":
                   ["3", "3-4", "0", "5-3", "x", "2"], "--scheme": ["simple", "stepped", "qq"],
                   "--tolerance": ["0", "0.01", "nan", "-1", "inf"], "--z-min":
                   ["17", "0", "30", "x"], "--z-max": ["40", "60", "10", "x", "-1"],
                   "--module": _NUMBERS, "--allow-shift": None, "--fixed": ["ring", "sun",
                   "carrier", "moon"], "--limit": ["0", "3", "x"], "--mesh-checks":
                   ["geometry", "textbook", "bad"]},
    "profile": {"--module": _NUMBERS, "--shift": _NUMBERS, "--helix": ["0", "15", "nan"],
                "--pressure-angle": ["20", "14.5", "nan", "0"], "--internal": None,
                "--method": ["analytic", "rack", "x"], "--tolerance": ["0.05", "0.1", "nan",
                "0", "-1"], "--backlash": _NUMBERS, "--bore": _NUMBERS, "--mate": _TEETH,
                "--mate-shift": _NUMBERS, "--cutter-teeth": ["0", "11", "x"],
                "--cutter-shift": _NUMBERS, "--no-check": None},
    "train": {"--fixed": ["ring", "sun", "moon", ""], "--input": ["sun=1500", "sun=1e400",
              "sun=nan", "sun", "ring=1/0", "=3", "arm=-2.5"], "--output": ["arm", "sun", "x"],
              "--efficiency": _NUMBERS, "--torque": _NUMBERS},
    "demo": {"--verbose": None},
    "mesh": {"--module": _NUMBERS, "--shift": _NUMBERS, "--helix": ["0", "20", "-15", "nan"],
             "--face-width": _NUMBERS, "--herringbone": None, "--internal": None,
             "--rim": _NUMBERS, "--method": ["analytic", "rack", "x"], "--bore": _NUMBERS,
             "--backlash": _NUMBERS, "--tolerance": ["0.05", "nan", "0", "-1"],
             "--no-check": None},
    "search": {"--ratio": _NUMBERS, "--ratio-tolerance": ["0", "0.05", "nan"],
               "--center-distance": [*_NUMBERS, "30", "50"], "--split": ["keep", "x"],
               "--helix": ["0", "15", "nan"], "--min-contact-ratio": _NUMBERS,
               "--min-tip-land": _NUMBERS, "--allow-undercut": None,
               "--objective": ["sliding", "-contact_ratio", "bogus"], "--top": ["0", "3", "x"]},
}  # fmt: skip
_POSITIONAL = {
    "pair": st.lists(st.sampled_from(_TEETH), min_size=0, max_size=3),
    "planetary": st.lists(st.sampled_from(_TEETH), min_size=0, max_size=5),
    "rate": st.lists(st.sampled_from(_TEETH), min_size=0, max_size=3),
    "synthesize": st.just([]),
    "profile": st.lists(st.sampled_from(_TEETH[:9]), min_size=0, max_size=2),
    "train": st.sampled_from([[TRAIN_FILE], [str(ROOT)], ["missing.toml"], []]),
    "demo": st.just([]),
    "mesh": st.lists(st.sampled_from(_TEETH[:9]), min_size=0, max_size=2),
    "search": st.sampled_from([["pairs"], ["gearbox"], ["nothing"], []]),
}
_TMP_DIR = tempfile.TemporaryDirectory(prefix="geartrain-cli-")  # removed when the run ends
_TMP = _TMP_DIR.name


@st.composite
def _argv(draw, command: str) -> list[str]:
    argv = [command, *draw(_POSITIONAL[command])]
    options = _OPTIONS[command]
    for name in draw(st.lists(st.sampled_from(sorted(options)), max_size=4, unique=True)):
        values = options[name]
        if values is None:
            argv.append(name)
        elif name == "--shift" and command in ("pair", "rate"):
            argv += [name, draw(st.sampled_from(values)), draw(st.sampled_from(values))]
        else:
            argv += [name, draw(st.sampled_from(values))]
    if command == "profile":
        argv += ["--tolerance", "0.05", "-o", os.path.join(_TMP, "h.npz")]
    if command == "mesh":  # bounded work: a coarse mesh
        argv += ["--tolerance", "0.05", "-o", os.path.join(_TMP, "h.stl")]
    if command == "search" and argv[1:2] == ["pairs"]:  # bounded work: a small grid
        argv += ["--teeth", "12", "24", "--shifts", "0", "0.5", "0.5", "--module", "2"]
    if command == "search" and argv[1:2] == ["gearbox"]:
        argv = [a for a in argv if a not in _OPTIONS["search"]]
        argv += ["--ratio", "7", "--stages", "1", "--z-max", "40"]
    return argv


@pytest.mark.parametrize("command", sorted(_OPTIONS))
@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_random_argv_gets_a_clear_answer(command, data):
    argv = data.draw(_argv(command))
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(argv)
    out, err = out.getvalue(), err.getvalue()
    assert code in (0, 1, 2), (argv, err)
    assert "Traceback" not in err, (argv, err)
    assert not re.search(r"\bnan\b", out, flags=re.I), (argv, out)
    if code == 2:
        assert out == "" and err.count("\n") == 1, (argv, err)


def test_planetary_frames_beyond_the_bound_name_the_option(capsys, tmp_path):
    # Planetary.animate refuses more than gears.solid.animate.MAX_FRAMES frames; the CLI says
    # --frames
    code, out, err = _run(
        capsys, "planetary", "18", "45", "108", "--planets", "3", "--animate",
        str(tmp_path / "a.gif"), "--frames", "100000",
    )  # fmt: skip
    assert code == 2 and out == "" and "--frames = 100000" in err
    assert not (tmp_path / "a.gif").exists()


# ---------------------------------------------------------------------------------------------
# 8. designs (issue 16): mesh and profile run the design's checks (exit 1, the file written,
# the failing findings on stderr; --no-check skips them); options that mean nothing for the
# design are refused with exit 2 and the reason, before anything is written


@pytest.mark.parametrize(
    ("argv", "suffix", "failed"),
    [
        # z = 6, x = 0: x_min = 1 - z sin^2(20 deg) / 2 = 0.649 (ISO 21771 / standards.md §2.1)
        (["mesh", "6", "--face-width", "4", "--tolerance", "0.05"], ".stl", ["undercut"]),
        (["profile", "6", "--tolerance", "0.01"], ".svg", ["undercut"]),
        # the zero-shift 20/80 internal pair: the ring's tip reaches the pinion's fillet (the
        # same pair as test_cli.py's pair test)
        (["profile", "80", "-m", "2", "--internal", "--mate", "20", "--tolerance", "0.05"], ".svg",
         ["tip_interference"]),
    ],
)  # fmt: skip
def test_a_design_that_fails_its_checks_exits_1_and_is_written(capsys, tmp_path, argv, suffix,
                                                               failed):  # fmt: skip
    from gears import Gear, GearPair

    out_file = tmp_path / f"design{suffix}"
    code, out, err = _run(capsys, *argv, "-o", out_file)
    assert code == 1 and out.startswith(f"wrote {out_file}") and out_file.stat().st_size > 0
    words = " ".join(err.split())  # wrapped to the output's width
    assert err.startswith(f"geartrain {argv[0]}: the ") and "--no-check skips them" in words
    named = re.findall(r"\[FAIL\] (\S+)", err)
    assert named == failed and "[ok" not in err  # the failing findings only, every one of them
    # the same findings as the library's own check of that design
    if "--mate" in argv:
        report = GearPair(Gear(20, 2), Gear(80, 2, internal=True)).check()
    else:
        report = Gear(6, 1).check()
    assert report.failed() == failed
    code, out, err = _run(capsys, *argv, "-o", out_file, "--no-check")
    assert code == 0 and out.startswith("wrote") and err == ""


def test_a_design_that_passes_exits_0_with_nothing_on_stderr(capsys, tmp_path):
    for argv in (["mesh", "20", "--face-width", "4", "--tolerance", "0.05", "-o",
                  tmp_path / "g.stl"],
                 ["profile", "12", "-m", "3", "-x", "0.6", "--mate", "24", "--mate-shift",
                  "0.36", "--tolerance", "0.01", "-o", tmp_path / "p.svg"]):  # fmt: skip
        code, out, err = _run(capsys, *argv)
        assert code == 0 and out.startswith("wrote") and err == "", (argv, err)


@pytest.mark.parametrize(
    ("argv", "why"),
    [
        (["mesh", "20", "--rim", "3"], "--rim is the width of a ring outside its tooth roots"),
        (["mesh", "20", "--herringbone"], "a spur gear (--helix 0) has no helix to mirror"),
        (["mesh", "80", "--internal", "--bore", "10"], "a ring (--internal) has none"),
        (["mesh", "20", "--method", "rack", "--cutter-teeth", "20"], "--method rack cuts with"),
        (["profile", "20", "--method", "rack", "--cutter-teeth", "20"], "--method rack cuts"),
        (["profile", "80", "--internal", "--bore", "10"], "a ring (--internal) has none"),
        (["profile", "20", "--mate", "30", "--bore", "10"], "a pair (--mate) is drawn without"),
        (["pair", "12", "24", "--split", "keep"], "it applies with --center-distance only"),
        (["pair", "12", "24", "--tolerance", "0.1"], "it applies with --scene only"),
        (["pair", "12", "24", "--face-width", "10"], "a spur pair (--helix 0) without --scene"),
        (["planetary", "18", "45", "108", "--frames", "10"], "it applies with --animate only"),
        (
            ["planetary", "18", "45", "108", "--face-width", "10"],
            "it applies with --scene or --torque only",
        ),
        (["planetary", "18", "45", "108", "--life", "10"], "applies with --torque and --speed"),
        (["planetary", "18", "45", "108", "--tolerance", "0.1"], "with one of them only"),
        (["search", "pairs", "--ratio", "2", "--split", "keep"], "with --center-distance only"),
        (["synthesize", "--ratio", "37", "--stages", "2", "--fixed", "sun"], "--fixed shape"),
        (["synthesize", "--ratio", "37", "--stages", "2", "--allow-shift"], "no shifted sets"),
    ],
)
def test_options_that_mean_nothing_are_refused(capsys, tmp_path, argv, why):
    if argv[0] in ("mesh", "profile"):
        argv = [*argv, "-o", str(tmp_path / f"x{'.stl' if argv[0] == 'mesh' else '.svg'}")]
    err = _bad_input(capsys, *argv)
    assert why in err
    assert list(tmp_path.iterdir()) == []  # refused before anything is written


def test_the_same_options_are_taken_where_they_mean_something(capsys, tmp_path):
    # the counterparts of the refusals above run (exit 0 or 1, never 2)
    for argv in (
        ["mesh", "80", "-m", "1", "--internal", "--rim", "3", "--face-width", "3",
         "--tolerance", "0.1", "-o", tmp_path / "r.stl"],
        ["mesh", "20", "--helix", "20", "--herringbone", "--face-width", "4", "--tolerance",
         "0.1", "-o", tmp_path / "h.stl"],
        ["pair", "12", "24", "-m", "3", "--center-distance", "56.5", "--split", "keep"],
        ["pair", "12", "24", "--helix", "15", "--face-width", "10"],
        ["planetary", "18", "45", "108", "--scene", tmp_path / "s.glb", "--face-width", "5",
         "--tolerance", "0.2"],
    ):  # fmt: skip
        code, _, err = _run(capsys, *argv)
        assert code in (0, 1), (argv, err)
