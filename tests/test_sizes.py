"""Rooms a reader can hold (issue 25): no module over about 800 lines and no function over about
120 lines of code, unless its reason is stated here.

A function's length is counted without its docstring: a numpydoc docstring with examples is
reading matter, not code to hold in mind (``gears.search.pairs`` documents 30 arguments in 108
lines and runs in 15). Source: the limits the issue states, measured on the source with ``ast``.
"""

from __future__ import annotations

import ast
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parent.parent
MAX_MODULE = 800
MAX_FUNCTION = 120

# module or "module:function" -> why it may be longer (none today)
REASONS: dict[str, str] = {}


def _sources():
    for package in ("gears", "trains"):
        yield from sorted((ROOT / package).rglob("*.py"))


def _code_lines(node: ast.AST) -> int:
    lines = node.end_lineno - node.lineno + 1
    body = getattr(node, "body", [])
    if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
        if isinstance(body[0].value.value, str):
            lines -= body[0].end_lineno - body[0].lineno + 1
    return lines


@pytest.mark.parametrize("path", list(_sources()), ids=lambda p: str(p.relative_to(ROOT)))
def test_rooms_a_reader_can_hold(path):
    rel = str(path.relative_to(ROOT))
    text = path.read_text()
    too_long = []
    if len(text.splitlines()) > MAX_MODULE and rel not in REASONS:
        too_long.append(f"{rel}: {len(text.splitlines())} lines > {MAX_MODULE}")
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
            n = _code_lines(node)
            if n > MAX_FUNCTION and f"{rel}:{node.name}" not in REASONS:
                too_long.append(f"{rel}:{node.name}: {n} lines of code > {MAX_FUNCTION}")
    assert not too_long, too_long


def test_the_count_leaves_out_the_docstring_only():
    # a function of a 3-line docstring and 2 lines of code counts its def line and 2 lines
    (f,) = ast.parse('def f():\n    """a\n    b\n    """\n    x = 1\n    return x\n').body
    assert _code_lines(f) == 3
