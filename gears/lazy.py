"""Layer 0, package facades: names imported on first use (PEP 562).

A family's ``__init__`` states where each of its public names lives and imports nothing until a
name is asked for, so that importing one module of a family (``gears.rating.materials``) does not
load the whole family above it, and ``import trains.cli`` does not load numpy:

>>> from gears.lazy import attach
>>> __getattr__, __dir__, __all__ = attach("gears.rating", {"MATERIALS": "gears.rating.materials"})
>>> sorted(__all__)
['MATERIALS']
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable

__all__ = ["attach"]


def attach(
    package: str, where: dict[str, str]
) -> tuple[Callable[[str], object], Callable[[], list[str]], list[str]]:
    """``(__getattr__, __dir__, __all__)`` for the facade ``package`` whose public names live
    in the modules ``where`` maps them to; a name is imported on first use and then kept as a
    plain attribute of the package."""

    def __getattr__(name: str) -> object:
        if name in where:
            value = getattr(importlib.import_module(where[name]), name)
            setattr(sys.modules[package], name, value)  # once: later lookups are attributes
            return value
        raise AttributeError(f"module {package!r} has no attribute {name!r}")

    def __dir__() -> list[str]:
        return sorted(set(vars(sys.modules[package])) | set(where))

    return __getattr__, __dir__, sorted(where)
