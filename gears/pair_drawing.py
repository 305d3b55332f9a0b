"""Layer 8, drawings of a pair: :class:`gears.GearPair`'s 3D scene and its animation in mesh.

The pair's outlines come from :mod:`gears.cutting.outline`, its solids from
:mod:`gears.solid.mesh`, its frames from :mod:`gears.solid.animate`; :class:`gears.GearPair`
calls :func:`pair_scene` and :func:`pair_animation` from its ``scene`` and ``animate``.
"""

from __future__ import annotations

import os
import pathlib
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import numpy as np
import shapely

from gears.arguments import (
    check_angle,
    check_callback,
    check_choice,
    check_flag,
    check_fps,
    check_frames,
    check_length,
    check_positive,
    check_tolerance,
)
from gears.budget import check_budget
from gears.errors import GearError
from gears.files import check_output
from gears.solid.animate import FORMATS, write_animation
from gears.solid.mesh import COLOURS, gear_solid, helix_twist, scene, solid_levels, transform

if TYPE_CHECKING:
    import trimesh

    from gears.cutting.cutter import ShaperCutter

__all__ = ["pair_animation", "pair_scene"]


def _unplaced(pair, tolerance: float, method: str, backlash: float, cutter,
              progress=None) -> tuple:  # fmt: skip
    """Both outlines centred on their own axes, unturned (from :meth:`outlines` at 0)."""
    from shapely import affinity

    p1, p2 = pair.outlines(0.0, tolerance, method, backlash, cutter, progress)
    angle2, (x2, y2) = _placement(pair, 0.0)
    p2 = affinity.rotate(affinity.translate(p2, -x2, -y2), -angle2, origin=(0.0, 0.0))
    return p1, p2


def _placement(pair, angle: float) -> tuple[float, tuple[float, float]]:
    if pair.is_rack:
        raise GearError("a pinion-and-rack pair has no scene; mesh the gear alone")
    from gears.cutting.outline import pair_placement

    g1, g2 = pair.mounted
    return pair_placement(g1.teeth, g2.teeth, pair.center_distance, pair.internal, angle)


def _drawn(pair, method: str, cutter) -> list[tuple]:
    """``(gear, method, cutter)`` of both mounted gears as :meth:`outlines` draws them (a
    rack cannot cut a ring: its default shaper does)."""
    c1, c2 = cutter if isinstance(cutter, tuple | list) else (cutter, cutter)
    g1, g2 = pair.mounted
    m2 = "shaper" if (g2.internal and method == "rack") else method
    return [(g1, method, c1), (g2, m2, c2)]


def _check_drawing(pair, tolerance, method, backlash, cutter, progress) -> tuple:
    """The arguments every drawing of the pair shares, checked before any work."""
    if pair.is_rack:
        raise GearError("a pinion-and-rack pair has no scene; mesh the gear alone")
    from gears.cutting.outline import METHODS

    tol = check_tolerance(tolerance, module=pair.g1.module)
    method = check_choice("method", method, METHODS)
    check_callback("progress", progress)
    if isinstance(cutter, tuple | list) and len(cutter) != 2:
        raise GearError(f"cutter = {cutter!r}; valid is one ShaperCutter or a pair of them")
    return tol, method


def pair_scene(
    pair: Any, angle: float = 0.0, face_width: float | None = None, tolerance: float = 0.01,
    method: str = "analytic", backlash: float = 0.0, herringbone: bool = False,
    cutter: ShaperCutter | tuple | None = None,
    progress: Callable[[int, int], object] | None = None,
) -> trimesh.Scene:  # fmt: skip
    """:meth:`gears.GearPair.scene` of ``pair`` (its docstring says what it draws)."""
    angle = check_angle("angle", angle)
    tol, method = _check_drawing(pair, tolerance, method, backlash, cutter, progress)
    herringbone = check_flag("herringbone", herringbone)
    if face_width is not None:
        check_positive("face_width", face_width)
    drawn = _drawn(pair, method, cutter)
    widths, twists = [], []
    for gear, _, _ in drawn:
        b = face_width if face_width is not None else gear.face_width
        b = b if b is not None else 10.0 * gear.module
        widths.append(check_length("face_width", b, gear.solid_radius(), "the gear's radius"))
        twists.append(helix_twist(widths[-1], gear.helix_angle, gear.reference_diameter))
    check_budget(
        "mesh", f"the scene of z = {drawn[0][0].teeth}/{drawn[1][0].teeth}",
        lambda t: sum(g.solid_vertices(t, w, m, backlash, None, None, c, herringbone)
                      for (g, m, c), w in zip(drawn, twists, strict=True)), tol,
    )  # fmt: skip
    angle2, centre2 = _placement(pair, angle)
    outlines = _unplaced(pair, tol, method, backlash, cutter, progress)
    radii = [g.solid_radius() for g, _, _ in drawn]
    check_budget(  # the outlines as drawn (a simulation's may exceed the estimate)
        "mesh", f"the scene of z = {drawn[0][0].teeth}/{drawn[1][0].teeth}",
        lambda t: sum(shapely.get_num_coordinates(o) * solid_levels(w, r, t, herringbone)
                      for o, w, r in zip(outlines, twists, radii, strict=True)), tol,
    )  # fmt: skip
    from gears.contact.flank import solid_lead

    parts = []
    for i, (shape, b, twist) in enumerate(zip(outlines, widths, twists, strict=True)):
        lead, extra = solid_lead(drawn[i][0], b, tol)  # crowning, end relief, helix slope
        solid = gear_solid(shape, b, twist + extra, tol, herringbone=herringbone, lead=lead)
        place = transform(angle) if i == 0 else transform(angle2, centre2)
        parts.append((f"gear{i + 1}", solid, place, COLOURS[f"gear{i + 1}"]))
    return scene(parts)


def pair_animation(
    pair: Any, path: str | os.PathLike[str], frames: int = 48, fps: float = 20.0,
    turn: float | None = None, tolerance: float = 0.02, method: str = "analytic",
    backlash: float = 0.0, cutter: ShaperCutter | tuple | None = None,
    progress: Callable[[int, int], object] | None = None,
) -> pathlib.Path:  # fmt: skip
    """:meth:`gears.GearPair.animate` of ``pair`` (its docstring says what it draws)."""
    from shapely import affinity

    from gears.cutting.outline import outline_vertices

    path = check_output(path, FORMATS)
    n = check_frames(frames)
    check_fps(fps)
    turn = 360.0 / pair.g1.teeth if turn is None else check_angle("turn", turn)
    tol, method = _check_drawing(pair, tolerance, method, backlash, cutter, progress)
    drawn = _drawn(pair, method, cutter)
    check_budget(
        "animation", f"{n} frames of z = {drawn[0][0].teeth}/{drawn[1][0].teeth}",
        lambda t: n * sum(outline_vertices(g, t, m, backlash, None, None, c)
                          for g, m, c in drawn), tol, hint="fewer frames",
    )  # fmt: skip
    p1, p2 = _unplaced(pair, tol, method, backlash, cutter)
    check_budget(
        "animation", f"{n} frames of z = {drawn[0][0].teeth}/{drawn[1][0].teeth}",
        lambda t: n * sum(shapely.get_num_coordinates(o) for o in (p1, p2)), tol,
        hint="fewer frames",
    )  # fmt: skip
    c1, c2 = (np.asarray(COLOURS[k]) / 255.0 for k in ("gear1", "gear2"))

    def frame(i: int) -> list:
        a = i * turn / n
        a2, (x2, y2) = _placement(pair, a)
        q2 = affinity.translate(affinity.rotate(p2, a2, origin=(0.0, 0.0)), x2, y2)
        return [(affinity.rotate(p1, a, origin=(0.0, 0.0)), c1), (q2, c2)]

    return write_animation(path, frame, fps=fps, n_frames=n, progress=progress)
