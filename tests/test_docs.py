"""Every code block of README.md and docs/*.md runs, so the documentation cannot rot (issue 16).

- A ``python`` block runs in a fresh process (forked from a server that has only imported the
  libraries, so no block sees another block's names or state), in its own temporary directory.
  Where an expression statement (a ``print(...)``, or a bare expression as a notebook shows it)
  carries a comment that starts with a value (``# 56.4999 26.0886``,
  ``# True``, ``# ['tip_interference']``, ``# 5, exact``), the printed values must equal the
  comment's: numbers to one unit in the comment's last digit (the docs print rounded values, and
  the last bits of a computation differ between machines), everything else exactly. A comment
  that starts with a word is prose and is not compared; ``...`` after the values compares only
  those that precede it.
- A ``bash`` block's ``geartrain`` lines run through the CLI in a temporary directory that can
  see ``examples/``: each must finish with exit status 0 or 1 (0 all checks pass, 1 a check
  fails, as documented), or the status its trailing ``# exit N`` comment names.
- A ``toml`` block is a train file: it is read by ``read_train``.
- A block preceded by ``<!-- no-test: reason -->`` is not run; there are at most two.

The blocks start running as soon as the tests are collected (``start_in_background``, called by
``tests/conftest.py``), as many at a time as there are cores, beside the rest of the suite; each
block's test waits for them and checks its own.
"""

from __future__ import annotations

import ast
import dataclasses
import io
import multiprocessing
import os
import pathlib
import re
import runpy
import tempfile
import threading
import tokenize
from fractions import Fraction

import pytest

ROOT = pathlib.Path(__file__).resolve().parent.parent
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
FENCE = re.compile(
    r"(?:<!--\s*no-test:(?P<why>[^>]*)-->\s*\n)?"  # an optional reason not to run it
    r"^```(?P<lang>[a-z]+)\n(?P<code>.*?)^```",
    re.S | re.M,
)
RUNNER = pathlib.Path(__file__).with_name("docs_runner.py")  # what each block's process runs
PRELOAD = ["numpy", "scipy.optimize", "shapely", "trimesh", "manifold3d", "gears", "trains"]
MAX_UNTESTED = 2
TIMEOUT = 180.0  # s for one block on a shared 2-core machine


@dataclasses.dataclass
class Block:
    id: str
    lang: str
    code: str
    line: int = 1  # the first code line in its page
    why: str = ""  # why it is not run (empty: it runs)

    @classmethod
    def found(cls, page: pathlib.Path, match: re.Match) -> Block:
        line = page.read_text()[: match.start("code")].count("\n") + 1
        return cls(f"{page.name}:{line}", match["lang"], match["code"], line,
                   (match["why"] or "").strip())  # fmt: skip


BLOCKS = [
    Block.found(page, m)
    for page in PAGES
    for m in FENCE.finditer(page.read_text())
    if m["lang"] in ("python", "bash", "toml")
]


def _is_install(block: Block) -> bool:
    """The README's first block: the two set-up commands (pip), held by test_readme.py."""
    return all(line.startswith("pip install") for line in block.code.strip().splitlines())


RUN = [b for b in BLOCKS if not b.why and not (b.lang == "bash" and _is_install(b))]

# ---------------------------------------------------------------------------------- values

_TOKEN = re.compile(
    r"""\s*(?:
        (?P<fraction>Fraction\(\s*[-+]?\d+\s*,\s*\d+\s*\))
      | (?P<frac>[-+]?\d+/\d+(?![\w.]))
      | (?P<num>[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?(?![\w]))
      | (?P<word>True|False|None|inf|nan)(?!\w)
      | (?P<str>'[^']*'|"[^"]*")
      | (?P<punct>[\[\](){},:;])
      | (?P<more>\.\.\.)
    )""",
    re.X,
)


def expected_values(comment: str) -> tuple[list, bool] | None:
    """The values a comment starts with, and whether it ends in ``...``; None for prose."""
    values, pos, more = [], 0, False
    while pos < len(comment):
        m = _TOKEN.match(comment, pos)
        if not m or m.end() == pos:
            break
        pos = m.end()
        if m["more"]:
            more = True
            break
        if m["punct"] is None:
            values.append(m)
    if not values:
        return None
    return values, more


def printed_values(text: str) -> list:
    """Every value token in printed text (numbers not inside names, True/False/None, strings)."""
    found = []
    for m in re.finditer(
        r"(?P<fraction>Fraction\(\s*[-+]?\d+\s*,\s*\d+\s*\))"
        r"|(?P<frac>(?<![\w.])[-+]?\d+/\d+(?![\w.]))"
        r"|(?P<num>(?<![\w.])[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?(?!\w))"
        r"|(?P<word>(?<!\w)(?:True|False|None|inf|nan)(?!\w))"
        r"|(?P<str>'[^']*'|\"[^\"]*\")",
        text,
    ):
        found.append(m)
    return found


def _unit(number: str) -> float:
    """One unit in the last digit of a number as written (``56.4999`` -> 1e-4, ``7`` -> 0)."""
    mantissa, _, exponent = number.lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    if "." not in mantissa and not exponent:
        return 0.0  # an integer is exact
    return 10.0 ** (-decimals + (int(exponent) if exponent else 0))


def _kind(m: re.Match) -> str:
    return "frac" if m.lastgroup == "fraction" else m.lastgroup


def _text(m: re.Match) -> str:
    """A token as written; ``Fraction(-12, 35)`` reads as ``-12/35``."""
    if m.lastgroup == "fraction":
        return "/".join(re.findall(r"[-+]?\d+", m["fraction"]))
    return m[m.lastgroup].strip()


def compare(comment: str, text: str) -> str | None:
    """None when ``text`` (what a print call printed) shows the values ``comment`` starts with,
    else a sentence saying what differs."""
    parsed = expected_values(comment)
    if parsed is None:
        return None
    want, more = parsed
    got = printed_values(text)
    if len(got) < len(want) or (not more and len(got) != len(want)):
        return f"printed {len(got)} values {text.strip()!r}, the comment gives {len(want)}"
    for w, g in zip(want, got, strict=False):
        kind, ws, gs = _kind(w), _text(w), _text(g)
        if "frac" in (kind, _kind(g)):
            ok = Fraction(ws) == Fraction(gs)
        elif kind == "num" and _kind(g) == "num":
            ok = abs(float(gs) - float(ws)) <= _unit(ws) * (1 + 1e-9) + 1e-12 * abs(float(ws))
        else:
            ok = ws.strip("'\"") == gs.strip("'\"") and (kind == "str") == (_kind(g) == "str")
        if not ok:
            return f"printed {gs} where the comment says {ws} (in {text.strip()!r})"
    return None


def test_the_value_comparison_itself():
    # the rule can fail: wrong digit, wrong count, wrong word; prose is not compared
    assert compare("56.4999 26.0886", "56.4999 26.0886\n") is None
    assert compare("56.4999 26.0886", "56.4998 26.0886\n") is None  # one unit in the last digit
    assert compare("56.4999 26.0886", "56.4997 26.0886\n") is not None
    assert compare("5, exact", "5\n") is None
    assert compare("5, exact", "6\n") is not None
    assert compare("7", "7 8\n") is not None  # a value the comment does not give
    assert compare("7 ...", "7 8\n") is None
    assert compare("['tip_interference']", "['tip_interference']\n") is None
    assert compare("['tip_interference']", "['undercut']\n") is not None
    assert compare("True 12", "(True, 12)\n") is None
    assert compare("True 12", "(False, 12)\n") is not None
    assert compare("2767/63", "2767/63\n") is None and compare("2767/63", "2767/64\n")
    assert compare("(300, -800): the planet", "(Fraction(300, 1), Fraction(-800, 1))") is None
    assert compare("Fraction(7, 1): ring fixed", "7") is None
    assert compare("{'planet': Fraction(-12, 35)}", "{'planet': Fraction(-12, 36)}") is not None
    assert compare("every finding with its margin", "anything at all 1 2 3") is None
    assert compare("0.97702", "0.977\n") is not None  # 2e-5 off at a 1e-5 unit


# ------------------------------------------------------------------------------- running


def _value_comments(code: str) -> dict[int, str]:
    """Last line of each expression statement (a print call, a bare expression) -> the comment
    on that line, where there is one."""
    comments = {
        t.start[0]: t.string.lstrip("#").strip()
        for t in tokenize.generate_tokens(io.StringIO(code).readline)
        if t.type == tokenize.COMMENT
    }
    ends = {n.end_lineno for n in ast.walk(ast.parse(code)) if isinstance(n, ast.Expr)}
    return {line: comments[line] for line in sorted(ends & comments.keys())}


def run_blocks(blocks: list[Block], basetemp: pathlib.Path) -> dict[str, dict]:
    """Run ``blocks``, a fresh process each, as many at a time as there are cores."""
    ctx = multiprocessing.get_context("forkserver")
    ctx.set_forkserver_preload(PRELOAD)
    pending, running, done = list(blocks), [], {}
    slots = max(1, len(os.sched_getaffinity(0)))
    while pending or running:
        while pending and len(running) < slots:
            block = pending.pop(0)
            receive, send = ctx.Pipe(duplex=False)
            data = {"id": block.id, "lang": block.lang, "code": block.code, "root": str(ROOT)}
            job = {"BLOCK": data, "WORKDIR": tempfile.mkdtemp(dir=basetemp), "CONN": send}
            proc = ctx.Process(target=runpy.run_path, args=(str(RUNNER), job, "__docs_block__"))
            proc.start()
            send.close()
            running.append((block, proc, receive))
        block, proc, receive = running.pop(0)
        if receive.poll(TIMEOUT):
            done[block.id] = receive.recv()
        else:
            done[block.id] = {"error": f"no answer in {TIMEOUT:.0f} s", "prints": {}, "status": []}
        proc.join(10)
        if proc.is_alive():
            proc.kill()
    return done


def problems(block: Block, got: dict) -> list[str]:
    """What is wrong with a block's run: its error, a CLI status, a value a comment gives."""
    if got["error"] is not None:
        return [f"raised:\n{got['error']}"]
    out = [
        f"{line!r} exited {status}"
        for line, status, want in got["status"]
        if (status != want if want is not None else status not in (0, 1))
    ]
    comments = _value_comments(block.code) if block.lang == "python" else {}
    for lineno, comment in comments.items():
        if expected_values(comment) is None:
            continue
        where = f"line {block.line + lineno - 1}"
        if lineno not in got["prints"]:
            out.append(f"{where}: never ran")
        elif why := compare(comment, got["prints"][lineno]):
            out.append(f"{where}: {why}")
    return out


class _Background:
    """``run_blocks`` in a thread of this process (it mostly waits on its block processes):
    started when the tests are collected, so the other tests run meanwhile."""

    def __init__(self, blocks: list[Block], basetemp: pathlib.Path):
        self.done: dict[str, dict] | None = None
        self.error: BaseException | None = None
        self.thread = threading.Thread(target=self._run, args=(blocks, basetemp), daemon=True)
        self.thread.start()

    def _run(self, blocks, basetemp):
        try:
            self.done = run_blocks(blocks, basetemp)
        except BaseException as exc:  # raised again in the test that waits for it
            self.error = exc

    def result(self) -> dict[str, dict]:
        self.thread.join()
        if self.error is not None:
            raise self.error
        return self.done


_STARTED: list[_Background] = []


def start_in_background(session) -> None:
    """Run the blocks from the end of collection (tests/conftest.py) when a test that checks
    them is among the collected tests."""
    if not _STARTED and any(
        "outcomes" in getattr(item, "fixturenames", ()) for item in session.items
    ):
        basetemp = session.config._tmp_path_factory.getbasetemp()  # outcomes' own folder
        _STARTED.append(_Background(RUN, basetemp))


@pytest.fixture(scope="session")
def outcomes(tmp_path_factory):
    if not _STARTED:
        _STARTED.append(_Background(RUN, tmp_path_factory.getbasetemp()))
    return _STARTED[0].result()


def test_the_runner_catches_what_is_wrong(tmp_path):
    # the mechanism can fail: a wrong value, a missing import, a wrong CLI call, a bad TOML;
    # and it passes a right block (a multi-line call, a bare expression, a loop's first pass)
    right = (
        "from fractions import Fraction\nprint(\n    1 / 4,\n)  # 0.25\n"
        "Fraction(6, 4)  # 3/2\nfor i in range(3):\n    print(i)  # 0\n"
    )
    blocks = [
        Block(
            "value", "python", "x = 2\nprint(x / 3)  # 0.6667\nprint(round(x / 3, 4))  # 0.6669\n"
        ),
        Block("import", "python", "t = Train()\n"),
        Block("status", "bash", "geartrain pair 12 24 --module 0\n"),
        Block("toml", "toml", "[[mesh]]\ngears = ['a']\n"),
        Block("right", "python", right),
    ]
    got = run_blocks(blocks, tmp_path)
    found = {b.id: problems(b, got[b.id]) for b in blocks}
    assert found["value"] == ["line 3: printed 0.6667 where the comment says 0.6669 (in '0.6667')"]
    assert "NameError" in found["import"][0]
    assert "exited 2" in found["status"][0]
    assert "TrainError" in found["toml"][0]
    assert found["right"] == []


@pytest.mark.parametrize("block", RUN, ids=[b.id for b in RUN])
def test_block_runs_and_prints_what_it_says(block, outcomes):
    found = problems(block, outcomes[block.id])
    assert not found, f"{block.id}:\n" + "\n".join(found)
