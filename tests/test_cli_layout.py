"""What the ``geartrain`` commands print fits the output: 80 columns when piped (no terminal),
wide tables cut into blocks of whole columns, prose columns wrapped under themselves; and the
commands share their defaults (``--module`` 1 mm everywhere).
"""

from __future__ import annotations

import argparse
import re

import pytest

from trains.cli._text import PIPE_WIDTH, wrap
from trains.cli.app import build_parser, main

RATE = ["rate", "19", "61", "-m", "3", "--face-width", "30", "--torque", "150", "--speed", "1450"]
SEARCH = ["search", "pairs", "--ratio", "3.2", "--center-distance", "100", "--module", "2", "2.5",
          "3", "--teeth", "12", "120"]  # fmt: skip


@pytest.mark.parametrize("argv", [RATE, SEARCH, ["pair", "12", "24", "-m", "3"]],
                         ids=["rate", "search", "pair"])  # fmt: skip
def test_piped_output_fits_80_columns(capsys, monkeypatch, argv):
    # capsys is not a terminal, like a pipe: the issue found rows of 95-98 columns there
    monkeypatch.delenv("COLUMNS", raising=False)
    assert main(argv) in (0, 1)
    out = capsys.readouterr().out
    long = [line for line in out.splitlines() if len(line) > PIPE_WIDTH]
    assert not long, long


def test_a_wide_table_is_cut_into_blocks_of_whole_columns(capsys, monkeypatch):
    # every row's cells, read across the blocks (the first column repeated), are the wide row's
    monkeypatch.delenv("COLUMNS", raising=False)
    assert main(SEARCH) == 0
    narrow = capsys.readouterr().out
    monkeypatch.setenv("COLUMNS", "400")
    assert main(SEARCH) == 0
    wide = capsys.readouterr().out
    row = re.compile(r"^(#|\d+)  ")  # the table's header and rows, not the line above it
    rows = [ln.split() for ln in wide.splitlines() if row.match(ln)]
    blocks, block = [], []
    for ln in narrow.splitlines():
        if row.match(ln):
            block.append(ln.split())
        elif block:
            blocks.append(block)
            block = []
    blocks += [block] if block else []
    assert len(blocks) >= 2 and all(len(b) == len(rows) for b in blocks)
    joined = [blocks[0][r] + [c for b in blocks[1:] for c in b[r][1:]] for r in range(len(rows))]
    assert joined == rows


def test_a_prose_column_wraps_under_itself():
    # a factor table: the last cell (what the factor is) continues under itself, so the
    # value and clause columns stay clear
    line = "K_Hbeta                    1.4119  ISO 6336-1 §7.6  face load factor, contact, method C"
    first, second = wrap(line, width=78).splitlines()
    start = line.index("face")
    assert first.startswith(line[:start]) and second[:start].strip() == ""
    assert second.strip() == "method C" and max(len(first), len(second)) <= 78


def test_every_command_defaults_to_module_1(capsys):
    # `differential` defaulted to 3 mm while every other command took 1 mm
    parser = build_parser()
    (sub,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    defaults = {}
    for name, p in sub.choices.items():
        for act in p._actions:
            if "--module" in act.option_strings and act.default is not None:
                defaults[name] = act.default
    assert "differential" in defaults and set(defaults.values()) == {1.0}, defaults
    assert main(["differential"]) in (0, 1)  # 16/10 without --gleason: undercut pinions
    assert re.search(r"module 1 mm", capsys.readouterr().out)


def test_a_bevel_export_loads_only_what_it_needs(tmp_path):
    # `geartrain bevel ... --scene x.stl` spent most of its ~0.9 s in imports: the rating family
    # (ISO 6336), the cutting simulations, the notebook drawings and the package metadata were
    # loaded by the package facade and by module-level imports; a fresh process shows what is
    # loaded now (tests/benchmarks/bench_process.py times it against OpenSCAD)
    import json
    import subprocess
    import sys

    code = (
        "import sys, json\n"
        "from trains.cli.app import main\n"
        f"main(['bevel', '20', '40', '-m', '3', '-b', '20', '--scene', {str(tmp_path / 'x.stl')!r}"
        "])\n"
        "sys.stdout.flush()\n"
        "print(json.dumps(sorted(sys.modules)), file=sys.stderr)\n"
    )
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=300)  # fmt: skip
    assert run.returncode == 0, run.stderr[-2000:]
    loaded = set(json.loads(run.stderr.strip().splitlines()[-1]))
    assert (tmp_path / "x.stl").stat().st_size > 10_000
    unneeded = {"gears.rating.iso6336", "gears.rating.capacity", "gears.cutting.generate",
                "gears.figures.drawing", "gears.figures.plot", "gears.search.engine",
                "matplotlib"} & loaded  # fmt: skip
    assert not unneeded, sorted(unneeded)
