"""The documentation site (docs/conf.py, issue 21) builds with warnings as errors and documents
every public name; every example has its gallery page, with its figures.

The build is the README's command (``sphinx-build -W -b html docs docs/_build/html``) with
``-E`` (every page read again, so a docstring changed since the last build is checked) into
``docs/_build/html``. sphinx-gallery runs each example once and keeps its output: an unchanged
example is not run again (its md5 is cached in ``docs/auto_examples``), which keeps this test
within the suite's time budget; ``tests/test_examples.py`` runs every example on every run.
The build starts in the background when the tests are collected (``start_in_background``, called
by ``tests/conftest.py``) and runs beside the other tests; the test waits for it and checks what
it built.
"""

from __future__ import annotations

import ast
import dataclasses
import html
import importlib
import pathlib
import re
import subprocess
import sys
import tempfile
import time

import pytest

ROOT = pathlib.Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
API = DOCS / "api"
EXAMPLES = sorted((ROOT / "examples").glob("*.py"))
OUT = DOCS / "_build" / "html"


# the README's command with -E: every page read again, so a docstring changed since the last
# build is checked
COMMAND = [sys.executable, "-m", "sphinx", "-E", "-W", "--keep-going", "-b", "html", str(DOCS),
           str(OUT)]  # fmt: skip
TIMEOUT = 900.0  # s


@dataclasses.dataclass
class SiteBuild:
    """A running ``sphinx-build``: its process, the examples folder's listing when it started,
    and the files its output goes to (files, not pipes: nobody reads the output until the build
    ends, and a full pipe would stop it)."""

    process: subprocess.Popen
    examples_before: list[str]
    start: float
    stdout: object
    stderr: object

    @classmethod
    def start_now(cls) -> SiteBuild:
        examples_before = sorted(p.name for p in (ROOT / "examples").iterdir())
        out, err = tempfile.TemporaryFile("w+"), tempfile.TemporaryFile("w+")
        process = subprocess.Popen(COMMAND, stdout=out, stderr=err, text=True, cwd=ROOT)
        return cls(process, examples_before, time.perf_counter(), out, err)

    def wait(self) -> tuple[int, str, str, float]:
        """Return code, stdout, stderr and the build's seconds, once it has finished."""
        try:
            code = self.process.wait(TIMEOUT - (time.perf_counter() - self.start))
        except subprocess.TimeoutExpired:
            self.stop()
            raise
        self.stdout.seek(0)
        self.stderr.seek(0)
        return code, self.stdout.read(), self.stderr.read(), time.perf_counter() - self.start

    def stop(self) -> None:
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()


_BUILD: list[SiteBuild] = []  # the session's build, once started


def start_in_background(session) -> None:
    """Start the build when the site test is among the collected tests (tests/conftest.py)."""
    if not _BUILD and any(
        getattr(item, "function", None) is test_site_builds_with_warnings_as_errors
        for item in session.items
    ):
        _BUILD.append(SiteBuild.start_now())


def stop_in_background() -> None:
    for build in _BUILD:
        build.stop()


@pytest.fixture(scope="session")
def site_build() -> SiteBuild:
    """The session's site build (started now when collection did not start it)."""
    if not _BUILD:
        _BUILD.append(SiteBuild.start_now())
    return _BUILD[0]


def _listed(page: str) -> set[str]:
    """Names in the autosummary directives of ``docs/api/<page>.rst``."""
    text = (API / f"{page}.rst").read_text()
    names = set()
    for block in re.findall(r"^\.\. autosummary::\n((?:[ \t]+.*\n|\n)+)", text, flags=re.M):
        for line in block.splitlines():
            line = line.strip()
            if line and not line.startswith(":"):
                names.add(line)
    return names


def _modules_with_all(package: str) -> list[str]:
    """Every module of ``package`` whose source defines ``__all__`` (the CLI excluded: its
    sub-commands are documented by ``geartrain --help``)."""
    out = []
    for path in sorted((ROOT / package).rglob("*.py")):
        rel = path.relative_to(ROOT).with_suffix("")
        name = ".".join(rel.parts[:-1] if rel.name == "__init__" else rel.parts)
        if name == package or name.startswith("trains.cli"):
            continue
        tree = ast.parse(path.read_text())
        if any(
            isinstance(n, ast.Assign) and any(getattr(t, "id", "") == "__all__" for t in n.targets)
            for n in tree.body
        ):
            out.append(name)
    return out


def _resolve(dotted: str):
    """The object a documented name stands for (None when it is not a module attribute)."""
    module, _, attr = dotted.rpartition(".")
    try:
        return getattr(importlib.import_module(module), attr, None)
    except ImportError:
        return None


PUBLIC = {p: sorted(importlib.import_module(p).__all__) for p in ("gears", "trains")}
MODULES = _modules_with_all("gears") + _modules_with_all("trains")


@pytest.mark.parametrize("package", sorted(PUBLIC))
def test_reference_lists_every_exported_name(package):
    missing = sorted(set(PUBLIC[package]) - _listed(package))
    assert not missing, f"add to docs/api/{package}.rst: {missing}"


def test_reference_lists_every_module_with_public_names():
    missing = sorted(set(MODULES) - _listed("modules"))
    assert not missing, f"add to docs/api/modules.rst: {missing}"


@pytest.mark.parametrize("script", EXAMPLES, ids=[p.name for p in EXAMPLES])
def test_every_example_opens_with_a_title(script):
    # sphinx-gallery makes the docstring's first paragraph the page: without a reST title (a line
    # underlined with "="), the gallery cannot link the page and the -W build fails
    doc = ast.get_docstring(ast.parse(script.read_text()), clean=False) or ""
    lines = doc.splitlines()
    assert len(lines) >= 2 and lines[0].strip() and set(lines[1]) == {"="}, (
        f"{script.name}: open the docstring with a title line underlined with '='"
    )
    assert len(lines[1]) >= len(lines[0]), f"{script.name}: the underline is shorter than the title"


def test_site_builds_with_warnings_as_errors(site_build):
    code, stdout, stderr, seconds = site_build.wait()  # COMMAND, started at collection
    assert code == 0, f"sphinx-build -W failed:\n{stderr[-6000:]}"
    # myst-parser's whole configuration (one line of some 2 000 characters) is not logged
    assert "MdParserConfig(" not in stdout + stderr
    # examples write their files to temporary folders, never beside themselves
    assert sorted(p.name for p in (ROOT / "examples").iterdir()) == site_build.examples_before

    # every public name and every module's __all__ is in the inventory of documented objects
    from sphinx.util.inventory import InventoryFile

    with (OUT / "objects.inv").open("rb") as f:
        inventory = InventoryFile.load(f, "", lambda base, uri: uri)
    entries = getattr(inventory, "data", inventory)  # Sphinx < 9: an _Inventory; 9: a dict
    documented = {name for kind in entries.values() for name in kind}
    missing = [f"{p}.{n}" for p, ns in PUBLIC.items() for n in ns if f"{p}.{n}" not in documented]
    for module in MODULES:
        mod = importlib.import_module(module)
        for n in mod.__all__:
            # documented on this module's page, or as the same object where it is defined or
            # exported (gears.Gear for gears.gear.Gear, gears.arguments.MAX_FRAMES for
            # gears.solid.animate.MAX_FRAMES)
            places = [d for d in documented if d == f"{module}.{n}" or d.endswith(f".{n}")]
            if not any(_resolve(d) is getattr(mod, n) for d in places):
                missing.append(f"{module}.{n}")
    assert not missing, f"not in the API reference: {missing}"

    # every example has its page with a figure (a 3D example a rendered picture), and its own
    # thumbnail in the gallery, not sphinx-gallery's placeholder
    from PIL import Image, ImageChops, ImageStat
    from sphinx_gallery import __file__ as sg

    placeholder = Image.open(pathlib.Path(sg).parent / "_static" / "no_image.png").convert("RGB")
    for script in EXAMPLES:
        page = (OUT / "auto_examples" / f"{script.stem}.html").read_text()
        assert "sphx-glr-single-img" in page or "sphx-glr-multi-img" in page, script.name
        # the thumbnail is the placeholder scaled (mean difference about 1 of 255) or a figure
        thumb = Image.open(OUT / "_images" / f"sphx_glr_{script.stem}_thumb.png").convert("RGB")
        diff = ImageStat.Stat(ImageChops.difference(thumb, placeholder.resize(thumb.size))).mean
        assert max(diff) > 5, f"{script.name}: the gallery shows the placeholder thumbnail"

    # no gallery page prints the build machine's temporary folder (where the examples write),
    # and no page the checkout's folder
    tmp = tempfile.gettempdir() + "/"
    shown = [f"{page.relative_to(OUT)}: {where}" for page in sorted(OUT.rglob("*.html"))
             for where in ((tmp, str(ROOT)) if "auto_examples" in page.parts else (str(ROOT),))
             if where in page.read_text()]  # fmt: skip
    assert not shown, shown

    # every guide of the index's toctrees is in the site under its own title (Sphinx's own
    # search.html replaced a guide called search.md)
    for name, title in _guides():
        page = OUT / f"{name}.html"
        assert page.exists(), name
        head = re.search(r"<title>(.*?)</title>", page.read_text(), flags=re.S)[1]
        assert html.unescape(head).strip().startswith(title), (name, head, title)
        assert title in html.unescape((OUT / "index.html").read_text()), title
    print(f"site built in {seconds:.0f} s")


def _guides() -> list[tuple[str, str]]:
    """(page, title) of every Markdown page in the toctrees of docs/index.md."""
    text = (DOCS / "index.md").read_text()
    out = []
    for block in re.findall(r"^```\{toctree\}\n(.*?)^```", text, flags=re.S | re.M):
        for name in (ln.strip() for ln in block.splitlines()):
            if name and not name.startswith(":") and (DOCS / f"{name}.md").exists():
                first = (DOCS / f"{name}.md").read_text().splitlines()[0]
                out.append((name, first.lstrip("# ").strip()))
    return out


def test_every_guide_is_found_by_the_site_test():
    # the list the site test checks holds every guide (search.md was shadowed, unnoticed)
    names = [n for n, _ in _guides()]
    assert len(names) >= 12 and "design_search" in names and "references" in names
