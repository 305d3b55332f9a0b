"""The public API is type-hinted (issue 21): every function the packages export (``gears`` and
``trains``, their ``__all__``) and every public method and property of the classes they export
annotates each parameter and its return; both packages ship ``py.typed`` (PEP 561), so type
checkers read these hints.
"""

from __future__ import annotations

import importlib
import inspect
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parent.parent


def _callables(package: str):
    mod = importlib.import_module(package)
    seen: set[int] = set()
    for name in mod.__all__:
        obj = getattr(mod, name)
        if id(obj) in seen:
            continue
        seen.add(id(obj))
        if inspect.isfunction(obj):
            yield f"{package}.{name}", obj
        elif inspect.isclass(obj) and not issubclass(obj, BaseException):
            for attr, value in vars(obj).items():
                if attr.startswith("_") and attr not in ("__init__", "__call__"):
                    continue
                if isinstance(value, property):
                    value = value.fget
                elif hasattr(value, "func") and hasattr(value, "attrname"):  # cached_property
                    value = value.func
                elif isinstance(value, staticmethod | classmethod):
                    value = value.__func__
                if inspect.isfunction(value):
                    yield f"{package}.{name}.{attr}", value


def _unannotated(fn) -> list[str]:
    sig = inspect.signature(fn)
    bad = [
        p.name for p in sig.parameters.values()
        if p.annotation is inspect.Parameter.empty and p.name not in ("self", "cls")
        and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)
    ]  # fmt: skip
    if sig.return_annotation is inspect.Signature.empty:
        bad.append("return")
    return bad


@pytest.mark.parametrize("package", ["gears", "trains"])
def test_the_public_api_is_annotated(package):
    missing = {name: bad for name, fn in _callables(package) if (bad := _unannotated(fn))}
    assert not missing, f"add type hints: {missing}"


def test_the_checker_sees_a_missing_hint():
    def half(x: float, y):  # y and the return are not annotated
        return x / 2

    assert _unannotated(half) == ["y", "return"]


@pytest.mark.parametrize("package", ["gears", "trains"])
def test_packages_ship_py_typed(package):
    assert (ROOT / package / "py.typed").is_file()
    text = (ROOT / "pyproject.toml").read_text()
    assert f'{package} = ["py.typed"]' in text
