"""The import structure holds to the layer map of docs/architecture.md (issue 9).

Every import of a project module is read from the source (function-level "lazy" imports and
``TYPE_CHECKING`` blocks included), and each must point to a strictly lower layer of the same
package, or from ``trains`` into ``gears``. The package ``__init__`` files are the facades on top
and may import their own package's modules; no module imports its own package's facade.
The order below is the one docs/architecture.md states; a test checks the two agree.
"""

from __future__ import annotations

import ast
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parent.parent

# bottom to top; a module may import only modules of a lower layer of its own package
LAYERS = {
    "gears": [
        ["errors", "display"],
        ["involute", "report", "files", "materials", "arguments", "budget"],
        ["geometry", "meshing"],
        ["rack", "cutter", "bevel"],
        ["profile", "measure", "checks", "rating", "spherical"],
        ["generate", "crown", "sizing"],
        ["outline", "root"],
        ["mesh", "animate", "drawing", "bevel_mesh"],
        ["gear", "capacity", "render"],
        ["pair"],
        ["shift", "plot", "bevel_pair"],
        ["export", "search"],
    ],
    "trains": [
        ["errors"],
        ["inertia", "trajectory", "conditions"],
        ["willis"],
        ["power", "coaxial"],
        ["capacity"],
        ["planetary", "catalog", "differential"],
        ["synthesis", "toml_format", "sizing"],
        ["gearbox"],
        ["commands", "commands._common"],
        ["commands.*"],
        ["commands.demo"],
        ["cli"],
    ],
}


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
        f"{p}.{m}" for p, mods in MODULES.items() for m in mods if m and _layer(p, m) is None
    ]
    assert not missing, f"modules without a layer in docs/architecture.md: {missing}"


def test_imports_point_down():
    wrong = []
    for package, module, path, target_pkg, target, line in _edges():
        where = f"{path.relative_to(ROOT)}:{line} imports {target_pkg}.{target or '(facade)'}"
        if target_pkg != package:
            if not (package == "trains" and target_pkg == "gears"):
                wrong.append(f"{where}: gears never imports trains")
            continue
        if module == "":  # the facade may gather its package
            continue
        if target == "":
            wrong.append(f"{where}: a module never imports its own package's facade")
            continue
        lo, hi = _layer(package, target), _layer(package, module)
        if lo is None or hi is None or not lo < hi:
            wrong.append(f"{where}: layer {hi} may import only layers below it (this is {lo})")
    assert not wrong, "\n".join(wrong)


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


@pytest.mark.parametrize("package", sorted(MODULES))
def test_every_module_opens_with_its_layer(package):
    missing = []
    for module, path in MODULES[package].items():
        if not module or module.startswith("commands."):
            continue  # a command's docstring is its --help text; commands/__init__ names the layer
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
