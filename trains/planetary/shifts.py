"""Layer 3, a planetary stage made coaxial by profile shifts (:meth:`Planetary.coaxial
<trains.Planetary.coaxial>`): the sun-planet and the planet-ring pair each take the shift sum x1 +
x2 (the ring's in DIN 3960's sign) of one working centre distance (ISO 21771: cos alpha_w = a_d cos
alpha / a_w), found on a grid around the mean of the two reference centre distances when not given.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from gears import Gear, GearPair
from gears.arguments import check_real
from gears.checks import equal_sliding_split
from gears.errors import GearError
from gears.meshing import center_distance_shift_sum
from trains.errors import TrainError
from trains.planetary.schemes import canonical_scheme

__all__ = ["coaxial_stage"]


def coaxial_stage(stage_class: Any, sun: Any, planet: Any, ring: Any, n_planets: int,
                  module: float | None, center_distance: float | None, split: str,
                  scheme: str, **kwargs: Any) -> Any:  # fmt: skip
    """The stage of :meth:`Planetary.coaxial <trains.Planetary.coaxial>` (its docstring says
    how it is found), built by ``stage_class`` (the ``Planetary`` class or a subclass)."""
    scheme = canonical_scheme(scheme)
    if scheme not in ("simple", "stepped"):
        raise TrainError(f"Planetary.coaxial handles the simple and stepped schemes, not {scheme}")
    base = stage_class(sun, planet, ring, n_planets, module, scheme=scheme, **kwargs)
    g = base._gears_in
    sun_g, p1, p2, ring_g = g["sun"], g["planet"], g["planet'"], g["ring"]
    a1 = base._pairs["sun-planet"].reference_center_distance
    a2 = base._pairs["planet-ring"].reference_center_distance

    def build(a: float, x_sun: float | None = None) -> Any:
        try:
            if x_sun is None:
                sp = GearPair.at_center_distance(sun_g, p1, a, split=split)
            else:  # the split's sun shift, solved for the whole grid at once (below)
                sun_x = sun_g.with_(profile_shift=x_sun)
                sp = GearPair.at_center_distance(sun_x, p1, a, split="keep")
            p2x = sp.g2 if scheme == "simple" else p2
            pr = GearPair.at_center_distance(p2x, ring_g, a, split="keep")
        except GearError as exc:
            raise TrainError(f"centre distance {a:.6g} mm: {exc}") from None
        planet_arg = sp.g2 if scheme == "simple" else (sp.g2, pr.g1)
        return stage_class(
            sp.g1, planet_arg, pr.g2, n_planets, base.module, scheme=scheme, **kwargs
        )

    if center_distance is not None:
        try:
            return build(check_real("center_distance", center_distance, 0.0))
        except GearError as exc:
            raise TrainError(str(exc)) from None
    m = base.module
    mean = (a1 + a2) / 2
    steps = np.arange(-150, 151) * 0.01 * m
    grid = mean + steps[np.argsort(np.abs(steps), kind="stable")]
    x_suns: list = [None] * len(grid)
    if split == "equal_sliding":  # one vectorised solve, not one per centre distance
        x_suns = _equal_sliding_suns(sun_g, p1, grid)
    best, best_key = None, None
    for a, x_sun in zip(grid, x_suns, strict=True):
        try:
            stage = build(float(a), x_sun)
            report = stage.check()
        except (TrainError, GearError):
            continue
        fails = [n for n in report.failed() if n not in ("assembly",)]
        if not fails:
            return stage
        key = (len(fails), abs(a - mean))
        if best_key is None or key < best_key:
            best, best_key = stage, key
    if best is None:
        raise TrainError(
            f"no working centre distance within 1.5 modules of {mean:.4f} mm makes sun "
            f"{sun_g.teeth}, planet {p1.teeth}/{p2.teeth}, ring {ring_g.teeth} coaxial"
        )
    return best


def _equal_sliding_suns(sun: Gear, planet: Gear, grid: np.ndarray) -> list:
    """The sun's shift of the ``"equal_sliding"`` split of the sun-planet pair at each centre
    distance of ``grid`` (what :meth:`gears.GearPair.at_center_distance` solves for one),
    solved for the whole grid at once; None where no shift reaches the distance (that centre
    distance is then refused one by one, as before)."""
    try:
        low, high = GearPair.center_distance_range(sun, planet)
    except GearError:
        return [None] * len(grid)
    inside = (grid >= low * (1 - 1e-9)) & (grid <= high * (1 + 1e-9))
    out: list = [None] * len(grid)
    if not inside.any():
        return out
    a = grid[inside]
    try:
        totals = center_distance_shift_sum(
            sun.teeth, planet.teeth, sun.module, a, sun.pressure_angle, sun.helix_angle, False
        )
        x = equal_sliding_split(sun.teeth, planet.teeth, sun.module, totals, sun.pressure_angle,
                                sun.helix_angle, False, sun.rack.addendum, True)  # fmt: skip
    except GearError:
        return out
    for i, v in zip(np.flatnonzero(inside), np.atleast_1d(x), strict=True):
        out[i] = float(v)
    return out
