"""The import structure holds to the layer and family map of docs/architecture.md.

Every import of a project module is read from the source (function-level "lazy" imports and
``TYPE_CHECKING`` blocks included), and each must point to a strictly lower layer of the same
package, or from ``trains`` into ``gears``. The ``__init__`` files are facades: the packages' on
top may import their own package's modules, the families' import nothing but ``gears.lazy``; no
module imports a facade of its own package, nor a private (``_name``) module of another family.
The order below is the one docs/architecture.md states; a test checks the two agree.
"""

from __future__ import annotations

import ast
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parent.parent

# bottom to top; a module may import only modules of a lower layer (of its own package, or
# trains -> gears). A dotted name is a module of a family subpackage: "cutting.cutter" is
# gears/cutting/cutter.py, of the family "cutting"; an undotted name belongs to the core.
LAYERS = {
    "gears": [
        ["errors", "display", "lazy", "namespace"],
        [
            "involute",
            "report",
            "files",
            "arguments",
            "budget",
            "rating.materials",
            "rating._arrays",
        ],
        [
            "geometry",
            "meshing",
            "cutting.sampling",
            "rating.load_factors",
            "rating.pitting",
            "rating.bending",
            "rating.life",
            "rating._one",
            "search.tables",
            "forces",
            "contact.compliance",
            "contact.modification",
            "worm.crossed",
            "worm.envelope",
            "noncircular.centrode",
            "noncircular.cycloid",
        ],
        [
            "rack",
            "mating",
            "cutting.cutter",
            "bevel.cone",
            "rating._block",
            "rating.losses",
            "rating.miner",
            "bevel.iso10300",
            "search.cluster",
            "contact.analysis",
            "contact.flank",
            "worm.geometry",
            "worm._wheel",
            "figures.forces",
            "noncircular.conjugate",
        ],
        [
            "checks",
            "cutting.profile",
            "cutting.measure",
            "rating.iso6336",
            "bevel.spherical",
            "bevel.rating",
            "worm.flank",
        ],
        [
            "interference",
            "cutting.generate",
            "bevel.crown",
            "rating.sizing",
            "rating.scuffing",
            "worm.checks",
            "noncircular.checks",
        ],
        [
            "cutting.outline",
            "rating.root",
            "rating.spectrum",
            "search.candidates",
            "noncircular.teeth",
        ],
        [
            "solid.mesh",
            "solid.animate",
            "figures.drawing",
            "bevel.solid",
            "search.reduction",
            "contact.plot",
        ],
        [
            "gear",
            "pair_drawing",
            "rating.capacity",
            "solid.render",
            "bevel.drawing",
            "search.checks",
            "contact.result",
            "noncircular.pair",
            "worm.solid",
        ],
        ["pair", "bevel.gear", "search.scheduling"],
        ["shift", "figures.plot", "bevel.pair", "search.result", "worm.pair"],
        ["solid.export", "search.engine"],
    ],
    "trains": [
        ["errors", "cli._text", "cli._types"],
        ["inertia", "trajectory", "conditions", "relations", "cli._rating"],
        ["willis", "planetary.schemes"],
        [
            "power",
            "coaxial",
            "planetary.checks",
            "planetary.placement",
            "planetary.scene",
            "planetary.shifts",
            "layout",
            "cycle",
            "crossing",
        ],
        ["capacity", "loading", "planetary.contact"],
        ["catalog", "differential", "planetary.stage"],
        [
            "toml_format",
            "cycloidal",
            "design.synthesis",
            "design.sizing",
            "design.plan",
            "design.ratios",
            "design.scheduling",
            "design.combine",
        ],
        ["design.gearbox"],
        ["cli._common"],
        ["cli.gear_commands.*", "cli.train_commands.*"],
        ["cli.demo"],
        ["cli.app"],
    ],
}

# the family subpackages of each package (docs/architecture.md, "Families"); the rest is the core
FAMILIES = {
    "gears": [
        "cutting",
        "rating",
        "solid",
        "figures",
        "bevel",
        "search",
        "contact",
        "worm",
        "noncircular",
    ],
    "trains": ["planetary", "design", "cli"],
}


def _family(package: str, module: str) -> str:
    head = module.split(".", 1)[0]
    return head if head in FAMILIES[package] else "core"


def _is_facade(package: str, module: str) -> bool:
    """The package itself ("") or one of its subpackages (an ``__init__.py``)."""
    path = MODULES[package].get(module)
    return path is not None and path.name == "__init__.py"


def _layer(package: str, module: str) -> int | None:
    for i, names in enumerate(LAYERS[package]):
        if module in names:
            return i
    for i, names in enumerate(LAYERS[package]):
        if any(n.endswith(".*") and module.startswith(n[:-1]) for n in names):
            return i
    return None


def _modules(package: str) -> dict[str, pathlib.Path]:
    base = ROOT / package
    out = {}
    for path in sorted(base.rglob("*.py")):
        rel = path.relative_to(base).with_suffix("")
        parts = rel.parts
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = path  # "" is the package facade
    return out


MODULES = {p: _modules(p) for p in LAYERS}


def _imports(path: pathlib.Path, package: str, module: str) -> list[tuple[str, str, int]]:
    """(package, module, line) of every project import in ``path`` ("" = the facade)."""
    tree = ast.parse(path.read_text(), str(path))
    here = [package, *module.split(".")] if module else [package]
    is_pkg = path.name == "__init__.py"
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = here[: len(here) - node.level + (1 if is_pkg else 0)]
                prefix = ".".join(base + ([node.module] if node.module else []))
            else:
                prefix = node.module or ""
            # "from gears import geometry" names a submodule; "from gears import Gear" the facade
            names = []
            for a in node.names:
                candidate = f"{prefix}.{a.name}"
                top, _, rest = candidate.partition(".")
                names.append(candidate if top in MODULES and rest in MODULES[top] else prefix)
        else:
            continue
        for name in names:
            top, _, rest = name.partition(".")
            if top in MODULES and (top, rest, node.lineno) not in found:
                found.append((top, rest, node.lineno))
    return found


def _edges():
    for package, modules in MODULES.items():
        for module, path in modules.items():
            for target_pkg, target, line in _imports(path, package, module):
                yield package, module, path, target_pkg, target, line


def test_every_module_has_a_layer():
    missing = [
        f"{p}.{m}"
        for p, mods in MODULES.items()
        for m in mods
        if not _is_facade(p, m) and _layer(p, m) is None
    ]
    assert not missing, f"modules without a layer in docs/architecture.md: {missing}"


def test_every_family_is_a_subpackage_and_every_subpackage_a_family():
    for package, families in FAMILIES.items():
        found = sorted(d.name for d in (ROOT / package).iterdir() if (d / "__init__.py").is_file())
        assert found == sorted(families), package


def _private(module: str) -> bool:
    return any(part.startswith("_") for part in module.split("."))


def _wrong(package, module, path, target_pkg, target, line) -> str | None:
    where = f"{path.relative_to(ROOT)}:{line} imports {target_pkg}.{target or '(facade)'}"
    if target_pkg != package:
        if not (package == "trains" and target_pkg == "gears"):
            return f"{where}: gears never imports trains"
        if _private(target):
            return f"{where}: a private module of gears"
        return None
    if _is_facade(package, module):  # a facade gathers its own subpackage, nothing else
        inside = not module or target == module or target.startswith(module + ".")
        return None if inside or target == "lazy" else f"{where}: a facade outside its own family"
    if _is_facade(package, target):
        return f"{where}: a module never imports a facade of its own package"
    if _private(target) and _family(package, target) != _family(package, module):
        return f"{where}: a private module of the family {_family(package, target)!r}"
    lo, hi = _layer(package, target), _layer(package, module)
    if lo is None or hi is None or not lo < hi:
        return f"{where}: layer {hi} may import only layers below it (this is {lo})"
    return None


def test_imports_point_down():
    wrong = [w for edge in _edges() if (w := _wrong(*edge))]
    assert not wrong, "\n".join(wrong)


def test_family_facades_load_nothing():
    # importing one module of a family runs the family's __init__: it must not load the rest
    # (imports inside its functions run only when they are called)
    loud = []
    for package, families in FAMILIES.items():
        for family in families:
            path = MODULES[package][family]
            eager = {n.lineno for n in ast.parse(path.read_text()).body}
            for target_pkg, target, line in _imports(path, package, family):
                if line in eager and (target_pkg, target) != ("gears", "lazy"):
                    loud.append(f"{path.relative_to(ROOT)}:{line} imports {target_pkg}.{target}")
    assert not loud, loud


def test_no_import_circles():
    graph: dict[str, set[str]] = {}
    for package, module, _, target_pkg, target, _ in _edges():
        graph.setdefault(f"{package}.{module}", set()).add(f"{target_pkg}.{target}")
    state: dict[str, int] = {}
    cycle: list[str] = []

    def visit(node: str, stack: list[str]) -> bool:
        state[node] = 1
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                cycle.extend([*stack[stack.index(nxt) :], nxt])
                return True
            if state.get(nxt) is None and visit(nxt, [*stack, nxt]):
                return True
        state[node] = 2
        return False

    for start in sorted(graph):
        if state.get(start) is None and visit(start, [start]):
            break
    assert not cycle, " -> ".join(cycle)


def test_architecture_doc_states_the_same_order():
    text = (ROOT / "docs" / "architecture.md").read_text()
    for package, layers in LAYERS.items():
        section = text.split(f"## `{package}`", 1)[1].split("\n## ", 1)[0]
        rows = re.findall(r"^\|\s*(\d+)\s*\|([^|]*)\|", section, flags=re.M)
        stated = [sorted(re.findall(r"`([\w.*]+)`", names)) for _, names in rows]
        assert stated == [sorted(names) for names in layers], package
        families = re.findall(r"^\|\s*`(\w+)/`\s*\|", section, flags=re.M)
        assert sorted(families) == sorted(FAMILIES[package]), package


@pytest.mark.parametrize("package", sorted(MODULES))
def test_every_module_opens_with_its_layer(package):
    missing = []
    for module, path in MODULES[package].items():
        if _is_facade(package, module) or module.startswith(
            ("cli.gear_", "cli.train_", "cli.demo")
        ):
            continue  # a command's docstring is its --help text
        doc = ast.get_docstring(ast.parse(path.read_text())) or ""
        found = re.match(r"Layer (\d+)", doc)
        if not found or int(found.group(1)) != _layer(package, module):
            missing.append(f"{path.relative_to(ROOT)} (layer {_layer(package, module)})")
    assert not missing, f"first docstring line must name its layer ('Layer N, ...'): {missing}"


def test_the_checker_sees_a_wrong_way_import(tmp_path):
    # the rule itself can fail: a formula module reaching up to the Gear class is caught
    bad = tmp_path / "geometry.py"
    bad.write_text("def f():\n    from gears.gear import Gear\n    return Gear\n")
    ((pkg, target, _),) = _imports(bad, "gears", "geometry")
    assert (pkg, target) == ("gears", "gear")
    assert not _layer("gears", target) < _layer("gears", "geometry")


def test_the_checker_sees_a_reach_into_another_family(tmp_path):
    # a private module of the rating family is not for the cutting family
    bad = tmp_path / "outline.py"
    bad.write_text("from gears.rating._factors import x\n")
    edge = ("gears", "cutting.outline", ROOT / "gears" / "cutting" / "outline.py")
    ((pkg, target, line),) = _imports(bad, "gears", "cutting.outline")
    assert "private module of the family 'rating'" in _wrong(*edge, pkg, target, line)
    assert _wrong(*edge, "gears", "rating", 1).endswith("a facade of its own package")


def test_architecture_figure_is_drawn_from_the_tables(tmp_path):
    # docs/make_architecture_figure.py reads the same tables this test holds the code to
    pytest.importorskip("matplotlib")
    import runpy

    mod = runpy.run_path(str(ROOT / "docs" / "make_architecture_figure.py"))
    tables = mod["layer_tables"]((ROOT / "docs" / "architecture.md").read_text())
    assert {p: [sorted(layer) for layer in layers] for p, layers in tables.items()} == {
        p: [sorted(layer) for layer in layers] for p, layers in LAYERS.items()
    }
    (path,) = mod["main"](tmp_path)
    assert path.name == "architecture.png" and path.stat().st_size > 10_000


def test_version_is_the_distribution_version():
    # gears.__version__ and trains.__version__ come from the installed metadata, which
    # pyproject.toml's [project] version sets (source: the packaging metadata itself)
    import importlib.metadata
    import tomllib

    import gears
    import trains

    stated = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["version"]
    installed = importlib.metadata.version("geartrain")
    assert gears.__version__ == trains.__version__ == installed
    if installed != stated:
        pytest.fail(f"installed {installed}, pyproject.toml {stated}: reinstall (pip install -e .)")
