"""Layer 3, statics and design by shift.

Coaxial stages by profile shift: several meshes brought to one working centre distance.

A reverted (coaxial) two-stage reducer has its input and output shafts on one axis, so its two
meshes share the centre distance: ``a_w12 = a_w34`` (Ozols §21-13 for the planetary case;
lectures §4.2). With one module and different tooth sums the reference centre distances differ,
and the mesh with the smaller sum is shifted (positive shift sum) to reach the larger one:
``cos alpha_w = a cos alpha / a_w`` and ``x_1 + x_2 = (z_1 + z_2)(inv alpha_w - inv alpha) /
(2 tan alpha)`` (ISO 21771, the inverse problem). Each mesh's sum is split
between its gears by the rule of :meth:`gears.GearPair.at_center_distance`.

This is the general form of what :meth:`trains.Planetary.coaxial` does for a planetary stage
(where the planet is shared by both meshes); here each mesh has its own two gears.

Examples
--------
>>> from gears import Gear
>>> p12, p34 = coaxial_shifts([(Gear(17, 2), Gear(40, 2)), (Gear(20, 2), Gear(38, 2))])
>>> round(p12.center_distance, 9), round(p34.center_distance, 9)
(58.0, 58.0)
>>> round(p12.g1.profile_shift + p12.g2.profile_shift, 4), p34.g1.profile_shift
(0.5313, 0.0)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from gears import Gear, GearError, GearPair
from trains.errors import TrainError

__all__ = ["coaxial_shifts"]


def _mesh(entry: Any, i: int) -> tuple[Gear, Gear]:
    if isinstance(entry, GearPair):
        if entry.is_rack:
            raise TrainError(f"mesh #{i}: a pinion and rack has no centre distance")
        return entry.g1, entry.g2
    if (
        isinstance(entry, tuple | list)
        and len(entry) == 2
        and all(isinstance(g, Gear) for g in entry)
    ):
        g1, g2 = entry
        return (g2, g1) if g1.internal else (g1, g2)
    raise TrainError(f"mesh #{i} must be a GearPair or two gears.Gear objects, got {entry!r}")


def coaxial_shifts(
    meshes: Sequence[Any],
    center_distance: float | None = None,
    split: str = "equal_sliding",
    tip_shortening: bool = True,
) -> list[GearPair]:
    """Pairs whose profile shifts put every mesh at one working centre distance.

    Parameters
    ----------
    meshes : sequence of GearPair or (Gear, Gear)
        Two or more meshes (a ring may be either gear of a tuple; it becomes the pair's g2).
        Their gears are independent (a reverted train); for a planet shared by two meshes use
        :meth:`trains.Planetary.coaxial`.
    center_distance : float, optional
        The common working centre distance a_w in mm. Default: the largest centre distance the
        meshes have with their given shifts, so the mesh that already has it keeps its gears
        and the others get larger centre distances: positive shift sums on external meshes,
        negative ones on internal meshes (a ring's shift in DIN 3960's sign, where
        ``x_1 + x_2 = (z_1 - z_2)(inv alpha_w - inv alpha) / (2 tan alpha)``).
    split : str
        How each shift sum is shared between the two gears: ``"equal_sliding"`` (default),
        ``"proportional"`` or ``"keep"`` (gear 1 keeps its shift), as in
        :meth:`gears.GearPair.at_center_distance`.
    tip_shortening : bool
        DIN 3960 tip shortening on the external pairs.

    Returns
    -------
    list of GearPair
        In the order given; a mesh already at ``center_distance`` (within 1e-12 mm) is returned
        with its gears unchanged.

    Raises
    ------
    TrainError
        Fewer than two meshes, a mesh that is not two gears, or a centre distance that no shift
        reaches (the message of :class:`gears.GearError`, with the mesh number).
    """
    if isinstance(meshes, GearPair) or not isinstance(meshes, Sequence) or len(meshes) < 2:
        raise TrainError(f"coaxial_shifts needs a sequence of two or more meshes, got {meshes!r}")
    gears = [_mesh(m, i) for i, m in enumerate(meshes, start=1)]
    pairs = []
    for i, (g1, g2) in enumerate(gears, start=1):
        try:
            pairs.append(GearPair(g1, g2, tip_shortening))
        except GearError as exc:
            raise TrainError(f"mesh #{i}: {exc}") from None
    if center_distance is None:
        target = max(p.center_distance for p in pairs)
    else:
        if isinstance(center_distance, bool):
            raise TrainError(f"center_distance = {center_distance!r}; valid is a number > 0 mm")
        try:
            target = float(center_distance)
        except (TypeError, ValueError):
            raise TrainError(
                f"center_distance = {center_distance!r}; valid is a number > 0 mm"
            ) from None
        if not (math.isfinite(target) and target > 0):
            raise TrainError(f"center_distance = {center_distance!r}; valid is a number > 0 mm")
    out = []
    for i, (pair, (g1, g2)) in enumerate(zip(pairs, gears, strict=True), start=1):
        if abs(pair.center_distance - target) <= 1e-12:
            out.append(pair)
            continue
        try:
            out.append(GearPair.at_center_distance(g1, g2, target, split, tip_shortening))
        except GearError as exc:
            raise TrainError(f"mesh #{i} ({g1.teeth}/{g2.teeth}): {exc}") from None
    return out
