"""Layer 6, design: what a gearbox search is asked to do, checked and planned.

The objective, the modules to choose from and, with a torque, the load case every stage is sized
for (:func:`gears.rating.sizing.load_case`) and the face widths
(:func:`trains.design.gearbox.synthesize_gearbox`'s ``objective``, ``module``, ``torque``, ...):
each refused with the value and the valid range before any work.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass
from typing import Any

import numpy as np

from gears.rating.sizing import ISO54, load_case
from trains.errors import TrainError

_OBJECTIVES = ("ring", "teeth", "efficiency")
_RATED_OBJECTIVES = ("volume", "mass", "ring", "teeth", "efficiency", "mesh_efficiency")


def _positive_list(name: str, value, what: str) -> np.ndarray:
    items = [value] if isinstance(value, numbers.Real) else value
    try:
        items = list(items)
    except TypeError:
        raise TrainError(f"{name} = {value!r}; valid is {what}") from None
    if not items:
        raise TrainError(f"{name} is empty; valid is {what}")
    for v in items:
        if (
            isinstance(v, bool)
            or not isinstance(v, numbers.Real)
            or not (math.isfinite(float(v)) and 0 < float(v) <= 1e5)
        ):
            raise TrainError(f"{name} = {v!r}; valid is {what}")
    return np.unique(np.asarray(items, float))


@dataclass(frozen=True)
class _Plan:
    """What the search does: the objective, the module(s), and with a load its case."""

    objective: str
    modules: np.ndarray
    load: Any = None
    widths: np.ndarray | None = None
    load_sharing: float | None = None

    @property
    def rated(self) -> bool:
        return self.load is not None


def _plan(objective, module, torque, speed, material, face_width, life, min_safety,
          options) -> _Plan:  # fmt: skip
    if "spectrum" in options:  # a load spectrum per stage is not modelled in this search
        raise TrainError("spectrum= is not an option of the gearbox search: size for the "
                         "spectrum's peak torque and speed, then rate a found stage with "
                         "Planetary.rating(spectrum=...)")  # fmt: skip
    if torque is None:
        extra = [k for k, v in (("speed", speed), ("face_width", face_width),
                                ("min_safety", min_safety)) if v is not None]  # fmt: skip
        extra += list(options)
        if extra:
            raise TrainError(f"{', '.join(extra)} size the stages for a load: give torque= "
                             "(N m on the input) and speed= (rpm) too")  # fmt: skip
        objective = "ring" if objective is None else objective
        if objective not in _OBJECTIVES:
            raise TrainError(f"objective = {objective!r}; valid are {list(_OBJECTIVES)} (with "
                             f"a torque also 'volume', 'mass' and 'mesh_efficiency')")  # fmt: skip
        m = 1.0 if module is None else module
        if (
            isinstance(m, bool)
            or not isinstance(m, numbers.Real)
            or not (math.isfinite(float(m)) and float(m) > 0)
        ):
            raise TrainError(f"module = {module!r}; valid is a number > 0 (mm); a list of "
                             "modules to choose from needs torque=")  # fmt: skip
        return _Plan(objective, np.array([float(m)]))
    objective = "volume" if objective is None else objective
    if objective not in _RATED_OBJECTIVES:
        raise TrainError(f"objective = {objective!r}; valid are {list(_RATED_OBJECTIVES)}")
    if speed is None:
        raise TrainError("torque= needs speed= (rpm of the input) to size the stages")
    if face_width is None:
        raise TrainError("torque= needs face_width=: a width in mm or a set of them; each "
                         "stage takes the smallest that carries its load")  # fmt: skip
    widths = _positive_list("face_width", face_width, "a width 0 < b <= 1e5 mm or a list")
    what = "a module 0 < m <= 1e5 mm or a list (default ISO 54 series I)"
    modules = _positive_list("module", ISO54 if module is None else module, what)
    mats = material if isinstance(material, tuple | list) else (material,)
    if len(mats) != 1 and len(set(map(str, mats))) != 1:
        raise TrainError(f"material = {material!r}; a gearbox takes one material for every gear")
    options = dict(options)
    sharing = options.pop("load_sharing_factor", None)
    for key in ("contacts", "idler"):
        if key in options:
            raise TrainError(f"{key} is set by each stage's planets; it is no option here")
    if sharing is not None and (
        isinstance(sharing, bool)
        or not isinstance(sharing, numbers.Real)
        or not (math.isfinite(float(sharing)) and 1 <= float(sharing) <= 10)
    ):
        raise TrainError(f"load_sharing_factor = {sharing!r}; valid is 1 <= K_gamma <= 10")
    load = load_case(torque, speed, mats[0], life, min_safety, error=TrainError, **options)
    return _Plan(objective, modules, load, widths, None if sharing is None else float(sharing))
