"""Sphinx configuration of the geartrain site: the Markdown guides (myst-parser), the API
reference (autodoc, autosummary, numpydoc) and the gallery of ``examples/`` (sphinx-gallery).

Build: ``python -m sphinx -W -b html docs docs/_build/html`` (the ``docs`` extra), then open
``docs/_build/html/index.html``. ``tests/test_site.py`` runs the same build.
"""

import logging
import os
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))  # the checkout's gears and trains, installed or not

project = "geartrain"
author = "geartrain developers"
copyright = "geartrain developers"

extensions = [
    "myst_parser",
    "numpydoc",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "auto_examples/*.ipynb", "auto_examples/*.py"]
templates_path = ["_templates"]
nitpicky = False

# Markdown guides: "#section" links resolve to headings up to level 3
myst_heading_anchors = 3
# formulas: $...$ inline, $$...$$ displayed, LaTeX environments (amsmath), rendered by MathJax
myst_enable_extensions = ["dollarmath", "amsmath"]

# API reference
autosummary_generate = True
autodoc_default_options = {"members": True, "member-order": "bysource"}
autodoc_typehints = "none"  # the numpydoc Parameters sections say the types
numpydoc_show_class_members = False  # autodoc's :members: documents them
numpydoc_class_members_toctree = False
numpydoc_validation_checks: set[str] = set()

# The gallery: every example runs once; an unchanged example is not run again (md5 cache)
sphinx_gallery_conf = {
    "examples_dirs": str(HERE.parent / "examples"),
    "gallery_dirs": "auto_examples",
    "filename_pattern": r".*",  # execute every example, not only plot_*.py
    "ignore_pattern": r"__init__\.py",
    "download_all_examples": False,
    "image_scrapers": ("matplotlib",),
    "capture_repr": ("_repr_html_", "__repr__"),
    "abort_on_example_error": True,
    "show_memory": False,
    "remove_config_comments": True,
}

html_theme = "pydata_sphinx_theme"
html_title = "geartrain"
html_theme_options = {"navigation_with_keys": False, "show_toc_level": 2}
html_static_path: list[str] = []
html_show_sourcelink = False
os.environ.setdefault("GEARTRAIN_THREADS", "1")


def _elsewhere() -> dict[str, dict[str, str]]:
    """For each module, the names of its ``__all__`` that are documented elsewhere, and where:
    those its package exports (on the package's page, ``gears.Gear``) and those it imports from
    another module (on that module's page, ``gears.arguments.MAX_FRAMES``). The module pages
    leave them out and link to them."""
    import ast
    import importlib

    root = HERE.parent
    out: dict[str, dict[str, str]] = {}
    for package in ("gears", "trains"):
        pkg = importlib.import_module(package)
        for path in sorted((root / package).rglob("*.py")):
            rel = path.relative_to(root).with_suffix("")
            name = ".".join(rel.parts[:-1] if rel.name == "__init__" else rel.parts)
            if name == package or "commands" in rel.parts or name.endswith(".cli"):
                continue
            imported = {}
            for node in ast.parse(path.read_text()).body:
                if isinstance(node, ast.ImportFrom) and (node.module or "").startswith(package):
                    for a in node.names:
                        imported[a.asname or a.name] = f"{node.module}.{a.name}"
            module = importlib.import_module(name)
            for n in getattr(module, "__all__", ()):
                obj = getattr(module, n)
                if n in pkg.__all__ and getattr(pkg, n) is obj:
                    out.setdefault(name, {})[n] = f"{package}.{n}"
                elif n in imported:
                    out.setdefault(name, {})[n] = imported[n]
    for names in out.values():  # a module re-exporting a re-export: link to where it is shown
        for n, where in names.items():
            home, _, attr = where.rpartition(".")
            while attr in out.get(home, {}) and out[home][attr] != where:
                where = out[home][attr]
                home, _, attr = where.rpartition(".")
            names[n] = where
    return out


autosummary_context = {"elsewhere": _elsewhere()}


class _QuietMyst(logging.Filter):
    """myst-parser logs its whole configuration (``myst vX: MdParserConfig(...)``, one long line)
    at the start of every build; drop that line and keep its warnings."""

    def filter(self, record: logging.LogRecord) -> bool:
        return "MdParserConfig(" not in record.getMessage()


def setup(app):
    # installed before "builder-inited", the event at which myst-parser logs the configuration
    logging.getLogger("sphinx.myst_parser.sphinx_ext.main").addFilter(_QuietMyst())
