"""The text users read (docstrings, messages, the guides, the README, the examples) speaks of
the project alone and cites its sources themselves; the guides' formulas render as math.

Each test reads the files as they are: a citation of a file that is not in the repository, an
issue number in a heading, or a formula left as a code block fails here, with the place.
"""

from __future__ import annotations

import ast
import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
GUIDES = sorted(DOCS.glob("*.md"))
GENERATED = ("_build", "auto_examples", "generated")  # the site's build output, not its sources
CODE = sorted(
    p
    for d in ("gears", "trains", "examples", "docs")
    for p in (ROOT / d).rglob("*.py")
    if not set(GENERATED).intersection(p.relative_to(ROOT).parts)
)
SOURCES = [*CODE, ROOT / "README.md", *GUIDES]


def _hits(pattern: str, files=SOURCES) -> list[str]:
    rx = re.compile(pattern)
    out = []
    for path in files:
        for n, line in enumerate(path.read_text().splitlines(), 1):
            if rx.search(line):
                out.append(f"{path.relative_to(ROOT)}:{n}: {line.strip()}")
    return out


def test_no_citation_of_the_projects_working_notes():
    # standards.md and the seed digests are working notes outside the repository: cite the
    # standard and clause, or the textbook and equation, instead
    # (and the rating's reference card: cite docs/rating.md, the guide, or the standard)
    hits = _hits(
        r"standards\.md|seed-\d{3}|the seeds'|\bseeds'|reference card|(?<!\])\(rating\.md\)"
    )
    assert not hits, "\n".join(hits)


def _headings(path: pathlib.Path) -> list[str]:
    text = re.sub(r"^```.*?^```", "", path.read_text(), flags=re.S | re.M)  # not code blocks
    return [line for line in text.splitlines() if line.startswith("#")]


def test_no_issue_number_in_a_heading_or_an_example_title():
    bad = [f"{p.name}: {h}" for p in [ROOT / "README.md", *GUIDES] for h in _headings(p)
           if re.search(r"\bissues? \d+", h)]  # fmt: skip
    for script in sorted((ROOT / "examples").glob("*.py")):
        doc = ast.get_docstring(ast.parse(script.read_text())) or ""
        lead = doc.split("\n\n")[:2]  # the gallery's title and its first paragraph
        bad += [f"{script.name}: {p}" for p in lead if re.search(r"\bissues? \d+", p)]
    assert not bad, "\n".join(bad)


def test_guide_formulas_are_math_not_code():
    # a fenced block without a language, or an indented block, renders as code: formulas are
    # $...$ / $$...$$ (myst dollarmath + amsmath)
    bad = []
    for page in GUIDES:
        text = page.read_text()
        bad += [
            f"{page.name}:{text[: m.start()].count(chr(10)) + 1}"
            for m in re.finditer(r"^```[ \t]*\n", text, flags=re.M)
            if text[: m.start()].count("\n```") % 2 == 0
        ]  # fmt: skip  (an opening fence)
        prose = re.sub(r"^```.*?^```", "", text, flags=re.S | re.M)
        for m in re.finditer(r"\n\n((?: {4}\S.*\n)+)", prose):
            before = prose[: m.start()].rstrip().splitlines()[-1] if m.start() else ""
            if not re.match(r"\s*([-*]|\d+\.) ", before):  # not a list item's continuation
                bad.append(f"{page.name}: indented block {m[1].strip()[:40]!r}")
    assert not bad, bad
    assert "amsmath" in (DOCS / "conf.py").read_text()


def _toctree() -> list[str]:
    text = (DOCS / "index.md").read_text()
    pages = []
    for block in re.findall(r"^```\{toctree\}\n(.*?)^```", text, flags=re.S | re.M):
        pages += [ln.strip() for ln in block.splitlines() if ln.strip() and ":" not in ln]
    return [p for p in pages if "/" not in p]


def test_no_guide_is_named_as_a_sphinx_page():
    # Sphinx writes search.html and genindex.html itself, over a guide of that name
    clash = sorted({"search", "genindex", "py-modindex"} & set(_toctree()))
    assert not clash and "design_search" in _toctree(), clash


def test_references_page_lists_every_cited_standard():
    # every standard the product cites (ISO 6336-3 -> ISO 6336) is on docs/references.md
    refs = (DOCS / "references.md").read_text()
    assert "references" in _toctree()
    standard = re.compile(r"\b(ISO(?:/TR)? \d+|DIN \d+|AGMA \d+|GOST [\d-]+)")
    cited = {c for path in SOURCES for c in standard.findall(path.read_text())}
    missing = sorted(c for c in cited if c not in refs)
    assert not missing, f"add to docs/references.md: {missing}"
    for book in ("Ozols", "Joldasbekov", "KHK", "Litvin", "Cheng", "Müller", "Roloff"):
        assert book in refs, book


#: drawn only by its benchmark (tests/benchmarks/bench_profile.py, now at 8 in): the next run of
#: the benchmark redraws it at the page width
REDRAWN_BY_A_BENCHMARK = {"profile_speed_accuracy.png"}


def test_guide_figures_are_readable_at_the_page_width():
    # a figure wider than the page is scaled down, and its 8-10 pt text with it: at most 8 in
    # at its own dpi (about 800 px, the width of a guide's column), so text stays its size
    from PIL import Image

    wide = []
    for page in GUIDES:
        if page.name in ("architecture.md", "performance.md"):  # project pages, not guides
            continue
        for name in re.findall(r"\]\(images/([\w.-]+\.png)\)", page.read_text()):
            if name in REDRAWN_BY_A_BENCHMARK:
                continue
            with Image.open(DOCS / "images" / name) as im:
                dpi = float(im.info.get("dpi", (100.0, 100.0))[0])
                inches = im.width / dpi
            if inches > 8.05:
                wide.append(f"{page.name}: {name} is {inches:.1f} in wide")
    assert not wide, wide


def test_no_docstring_holds_a_substitution_reference():
    # ``|x|`` after a space in a docstring is a docutils substitution reference: undefined, it
    # breaks the site build (Sphinx reads every docstring as reST). Write ``abs(x)`` in double
    # backquotes. docutils itself is the reference: its parse marks each one "problematic"
    import docutils.core

    bad = []
    for path in CODE:
        for node in ast.walk(ast.parse(path.read_text())):
            if not isinstance(node, ast.Module | ast.ClassDef | ast.FunctionDef):
                continue
            doc = ast.get_docstring(node)
            if not doc or "|" not in doc:
                continue
            tree = docutils.core.publish_doctree(
                doc,
                settings_overrides={"report_level": 5, "halt_level": 5, "warning_stream": False},
            )
            bad += [
                f"{path.relative_to(ROOT)}:{getattr(node, 'lineno', 1)}: {n.astext()}"
                for n in tree.findall(lambda x: x.tagname == "problematic")
                if n.astext().startswith("|")
            ]
    assert not bad, "\n".join(bad)
