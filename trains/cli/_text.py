"""Layer 0, the CLI's text layout: what the commands print, fitted to the output's width.

A terminal gives its width; a pipe or a file has none, and gets 80 columns (the width of a
pager or a mail, and of the terminals the output is most often read in); ``COLUMNS`` overrides
both. Three kinds of lines are fitted differently:

- a table of single-word cells (a search result, a table of numbers) wider than the width is
  cut into blocks of whole columns, one under the other, each repeating the first column (the
  row's number or name), the way pandas prints a wide frame: every value stays under its header;
- a line of columns whose last cell is prose (a factor and what it is) wraps that cell under
  itself, so the columns on its left stay clear;
- any other line (a finding, a sentence) wraps under its own text, past ``[FAIL] `` for a
  finding.
"""

from __future__ import annotations

import itertools
import os
import re
import shutil
import sys
import textwrap

__all__ = ["output_width", "wrap"]

#: the width of output that does not go to a terminal
PIPE_WIDTH = 80
_GAP = re.compile(r"\S+(?: \S+)*")  # a cell: words joined by single spaces


def output_width() -> int:
    """Columns of the output: ``COLUMNS`` when set, else the terminal's, else :data:`PIPE_WIDTH`
    (a pipe or a file)."""
    columns = os.environ.get("COLUMNS", "")
    if columns.isdigit() and int(columns) > 0:
        return int(columns)
    try:
        if sys.stdout.isatty():
            return shutil.get_terminal_size((PIPE_WIDTH, 24)).columns
    except (AttributeError, ValueError, OSError):  # a closed or replaced stdout
        pass
    return PIPE_WIDTH


def _cells(line: str) -> list[tuple[int, str]]:
    """(start, text) of the cells of ``line``: runs of words separated by two or more spaces."""
    return [(m.start(), m.group()) for m in _GAP.finditer(line)]


def _is_table_row(line: str) -> bool:
    cells = _cells(line)
    return len(cells) >= 3 and all(" " not in text for _, text in cells)


def _split_table(rows: list[str], width: int) -> list[str]:
    """``rows`` (a table of one-word cells) cut into blocks of whole columns no wider than
    ``width``, each block repeating the first column; a blank line between blocks."""
    n = max(len(r) for r in rows)
    padded = [r.ljust(n) for r in rows]
    space = [all(p[i] == " " for p in padded) for i in range(n)]
    # a column ends where every row has a space after a non-space (right-aligned numbers and
    # left-aligned words alike); its span runs to the next column's end
    ends = [i + 1 for i in range(n - 1) if not space[i] and space[i + 1]] + [n]
    bounds = [0, *ends]
    spans = list(itertools.pairwise(bounds))
    first, rest = spans[0], spans[1:]
    blocks: list[list[tuple[int, int]]] = [[first]]
    used = first[1] - first[0]
    for lo, hi in rest:
        if used + hi - lo > width and len(blocks[-1]) > 1:
            blocks.append([first])
            used = first[1] - first[0]
        blocks[-1].append((lo, hi))
        used += hi - lo
    out: list[str] = []
    for k, block in enumerate(blocks):
        if k:
            out.append("")
        out += ["".join(p[lo:hi] for lo, hi in block).rstrip() for p in padded]
    return out


def _wrap_line(line: str, width: int) -> list[str]:
    lead = line[: len(line) - len(line.lstrip())]
    body = line.lstrip()
    cells = _cells(line)
    last = cells[-1][0] if len(cells) >= 2 else -1
    if not body.startswith("[") and 0 < last <= width - 24:  # prose in the last column
        rest = textwrap.wrap(line[last:], width - last, break_long_words=False,
                             break_on_hyphens=False)  # fmt: skip
        return [line[:last] + rest[0], *(" " * last + r for r in rest[1:])]
    hang = lead + (" " * (body.index("]") + 2) if body.startswith("[") else "    ")
    return textwrap.wrap(body, width, initial_indent=lead, subsequent_indent=hang,
                         break_long_words=False, break_on_hyphens=False)  # fmt: skip


def wrap(text: str, width: int | None = None) -> str:
    """``text`` fitted to ``width`` columns (default :func:`output_width`, at least 40): wide
    tables cut into blocks of columns, long lines wrapped under their own text.

    >>> print(wrap("[FAIL] a_long_finding margin -1: " + "word " * 8, width=40))
    [FAIL] a_long_finding margin -1: word
           word word word word word word
           word
    >>> print(wrap("#  name  value  other\\n1  aaaa  1.2345  6.7890\\n2  bbbb  2.3456  7.8901",
    ...            width=40))
    #  name  value  other
    1  aaaa  1.2345  6.7890
    2  bbbb  2.3456  7.8901
    """
    width = max(width or output_width(), 40)
    lines = text.splitlines()
    out: list[str] = []
    i = 0
    while i < len(lines):
        j = i
        while j < len(lines) and _is_table_row(lines[j]):
            j += 1
        if j - i >= 2 and max(len(r) for r in lines[i:j]) > width:
            out += _split_table(lines[i:j], width)
            i = j
            continue
        for line in lines[i : max(j, i + 1)]:
            out += [line] if len(line) <= width else _wrap_line(line, width)
        i = max(j, i + 1)
    return "\n".join(out)
