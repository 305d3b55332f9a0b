"""Gear trains: the Willis formula per carrier, solved generically (see docs/trains.md).

>>> from trains import Train
>>> t = Train()
>>> t.mesh("sun", "planet", teeth=(20, 30), carrier="arm")
>>> t.mesh("planet", "ring", teeth=(30, 80), carrier="arm", internal=True)
>>> t.ratio("sun", "arm", fixed=["ring"])
Fraction(5, 1)

The names below are imported on first use (PEP 562), so that ``import trains.cli.app`` and
``geartrain --help`` do not load numpy, shapely and the whole library (issue 11 §7).
"""

from __future__ import annotations

import importlib

_WHERE = {
    "Assembly": "trains.planetary.checks",
    "Candidate": "trains.design.synthesis",
    "Candidates": "trains.design.synthesis",
    "Gearbox": "trains.design.gearbox",
    "Gearboxes": "trains.design.gearbox",
    "IllConditionedTrainWarning": "trains.relations",
    "Motion": "trains.relations",
    "Placement": "trains.planetary.placement",
    "Planetary": "trains.planetary.stage",
    "PowerFlow": "trains.power",
    "Relation": "trains.relations",
    "RelationPower": "trains.power",
    "StageContact": "trains.planetary.contact",
    "Structure": "trains.relations",
    "Train": "trains.willis",
    "TrainError": "trains.errors",
    "bevel_differential": "trains.catalog",
    "biplanetary": "trains.catalog",
    "Cycle": "trains.cycle",
    "CycloidalDrive": "trains.cycloidal",
    "Differential": "trains.differential",
    "coaxial_shifts": "trains.coaxial",
    "double_planet": "trains.catalog",
    "ferguson": "trains.catalog",
    "khv": "trains.catalog",
    "load_sharing": "trains.capacity",
    "loads": "trains.loading",
    "MemberLoad": "trains.loading",
    "MeshLoad": "trains.loading",
    "TrainLoads": "trains.loading",
    "noncircular_cycle": "trains.cycle",
    "parallel_efficiency": "trains.power",
    "planetary_efficiency": "trains.power",
    "point_path": "trains.trajectory",
    "power_flow": "trains.power",
    "rating": "trains.capacity",
    "read_train": "trains.toml_format",
    "reduced_inertia": "trains.inertia",
    "self_locking_range": "trains.power",
    "series_efficiency": "trains.power",
    "simple_planetary": "trains.catalog",
    "stepped_planetary": "trains.catalog",
    "strain_wave": "trains.catalog",
    "synthesize": "trains.design.synthesis",
    "synthesize_gearbox": "trains.design.gearbox",
    "wolfrom": "trains.catalog",
}

__all__ = sorted(_WHERE)


def __getattr__(name: str):
    if name == "__version__":  # pyproject.toml's version, as installed (gears.__version__ too)
        from importlib.metadata import PackageNotFoundError, version

        try:
            return version("geartrain")
        except PackageNotFoundError:  # pragma: no cover - a bare source tree, not installed
            return "unknown"
    if name in _WHERE:
        value = getattr(importlib.import_module(_WHERE[name]), name)
        globals()[name] = value  # once: later lookups are plain attributes
        return value
    raise AttributeError(f"module 'trains' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_WHERE))
