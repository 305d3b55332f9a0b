"""Layer 3, planetary: a stage drawn and built: outlines in mesh, the 3D scene, animation, SVG.

Every gear placed at its real centre distance and turned to its phase
(:meth:`~trains.planetary.stage.Planetary.placement`), the members turned by the Willis speeds of
the stage's train; the outlines and solids come from :mod:`gears.cutting.outline` and
:mod:`gears.solid.mesh`, the frames from :mod:`gears.solid.animate`. The functions take a
:class:`~trains.planetary.stage.Planetary` (``stage``) and are the bodies of its ``outlines``,
``scene``, ``animate``, ``mesh_cycle`` and ``_repr_svg_``.
"""

from __future__ import annotations

import math
import os
import pathlib
from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

from gears.arguments import (
    check_angle,
    check_callback,
    check_flag,
    check_fps,
    check_frames,
    check_length,
    check_positive,
    check_tolerance,
)
from gears.budget import check_budget
from gears.contact.flank import solid_lead
from gears.cutting.outline import outline_vertices
from gears.errors import GearError
from gears.figures.drawing import display_tolerance, outlines_svg
from gears.files import check_output
from gears.solid.animate import FORMATS, write_animation
from gears.solid.mesh import COLOURS, gear_solid, helix_twist, transform
from gears.solid.mesh import scene as solid_scene
from trains.conditions import refuse_failing
from trains.errors import TrainError

if TYPE_CHECKING:
    import trimesh


def gear_layout(stage, angle: float = 0.0, fixed: str = "ring") -> list[tuple]:
    """``(name, key, gear, centre, rotation, z)`` of every gear with the carrier turned by
    ``angle`` degrees (the sun when the carrier is ``fixed``): phases from
    ``stage.placement()``, rotations from the Willis solution of ``stage.train``. ``z`` is the
    mid-plane in face widths (the ring side of a stepped planet sits above the sun side)."""
    fixed = stage._member(fixed)
    if fixed not in ("sun", "ring", "carrier"):
        raise TrainError(f"fixed = {fixed!r}; valid are 'sun', 'ring', 'carrier'")
    try:
        a = check_angle("angle", angle)
    except GearError as exc:
        raise TrainError(str(exc)) from None
    name = {"sun": "sun", "ring": "ring", "carrier": stage.carrier}
    drive = "sun" if fixed == "carrier" else "carrier"
    motion = stage.train.solve({name[drive]: 1, name[fixed]: 0})

    def turned(member: str) -> float:
        return float(motion[member]) * a

    pl = stage.placement()
    stepped = stage.scheme in ("stepped", "external", "internal")
    lo, hi = (-0.5, 0.5) if stepped else (0.0, 0.0)
    c = turned(stage.carrier)
    origin = (0.0, 0.0)
    out = [("ring", "ring", stage.ring, origin, pl.ring_rotation + turned("ring"), hi),
           ("sun", "sun", stage.sun, origin, pl.sun_rotation + turned("sun"), lo)]  # fmt: skip
    steps = stage.planet_gears
    for i, (phi, rot) in enumerate(zip(pl.planet_angles, pl.planet_rotations, strict=True)):
        t = math.radians(phi + c)
        centre = (pl.planet_radius * math.cos(t), pl.planet_radius * math.sin(t))
        r = rot + turned("planet")
        out.append((f"planet{i + 1}", "planet", steps[0], centre, r, lo))
        if stepped:
            out.append((f"planet{i + 1}'", "planet'", steps[1], centre, r, hi))
    for i, (phi, rot) in enumerate(zip(pl.planet2_angles, pl.planet2_rotations, strict=True)):
        t = math.radians(phi + c)
        centre = (pl.planet2_radius * math.cos(t), pl.planet2_radius * math.sin(t))
        out.append((f"outer{i + 1}", "planet2", steps[1], centre,
                    rot + turned("planet2"), 0.0))  # fmt: skip
    return out


def placed_outlines(stage, angle: float, tolerance: float, fixed: str, cache: dict) -> list[tuple]:
    """``(name, key, outline)`` of every gear placed by :func:`gear_layout`; ``cache`` keeps
    one outline per distinct gear across calls."""
    from shapely import affinity

    out = []
    for name, key, gear, centre, rot, _ in gear_layout(stage, angle, fixed):
        if key not in cache:
            try:
                cache[key] = gear.outline(tolerance)
            except GearError as exc:
                raise TrainError(f"{key}: {exc}") from None
        shape = affinity.rotate(cache[key], rot, origin=(0.0, 0.0))
        out.append((name, key, affinity.translate(shape, *centre)))
    return out


def outlines(stage, angle: float = 0.0, tolerance: float = 0.01, fixed: str = "ring") -> dict:
    """Every gear's 2D outline placed in mesh (:meth:`Planetary.outlines`)."""
    try:
        tolerance = check_tolerance(tolerance, module=stage.module)
    except GearError as exc:
        raise TrainError(str(exc)) from None
    return {name: p for name, _, p in placed_outlines(stage, angle, tolerance, fixed, {})}


def scene(stage, angle: float = 0.0, face_width: float | None = None,
          tolerance: float = 0.01, fixed: str = "ring", herringbone: bool = False,
          progress: Callable[[int, int], object] | None = None,
          check: bool = True) -> trimesh.Scene:  # fmt: skip
    """The stage as a ``trimesh.Scene`` (:meth:`Planetary.scene`)."""
    try:
        tol = check_tolerance(tolerance, module=stage.module)
        herringbone = check_flag("herringbone", herringbone)
        check_callback("progress", progress)
        b = face_width
        if b is None:
            b = stage.sun.face_width or 10.0 * stage.module
        b = check_positive("face_width", b)
    except GearError as exc:
        raise TrainError(str(exc)) from None
    refuse_failing(stage, check, "scene")
    layout = gear_layout(stage, angle, fixed)
    distinct = {key: gear for _, key, gear, *_ in reversed(layout)}
    twists = {}
    try:
        for key, gear in distinct.items():
            check_length("face_width", b, gear.solid_radius(), f"the {key}'s radius")
            twists[key] = helix_twist(b, gear.helix_angle, gear.reference_diameter)
        check_budget(
            "mesh", f"the scene of {stage!r}",
            lambda t: sum(g.solid_vertices(t, twists[k], herringbone=herringbone)
                          for k, g in distinct.items()), tol,
        )  # fmt: skip
    except GearError as exc:
        raise TrainError(str(exc)) from None
    solids = {}
    parts = []
    for name, key, gear, centre, rot, z in layout:
        if key not in solids:
            try:
                lead, extra = solid_lead(gear, b, tol)  # the gear's lead modification
                solids[key] = gear_solid(gear.outline(tol), b, twists[key] + extra, tol,
                                         herringbone=herringbone, lead=lead)  # fmt: skip
            except GearError as exc:
                raise TrainError(f"{key}: {exc}") from None
            solids[key].metadata["name"] = key
            if progress is not None:
                progress(len(solids), len(distinct))
        colour = COLOURS.get(key.rstrip("'"), COLOURS["planet"])
        parts.append((name, solids[key], transform(rot, centre, z * b), colour))
    return solid_scene(parts)


def animate(stage, path: str | os.PathLike[str], frames: int = 48, fps: float = 20.0,
            turn: float | None = None, tolerance: float = 0.02, fixed: str = "ring",
            progress: Callable[[int, int], object] | None = None,
            check: bool = True) -> pathlib.Path:  # fmt: skip
    """Write the stage's animation (:meth:`Planetary.animate`)."""
    try:
        path = check_output(path, FORMATS)
        n = check_frames(frames)
        check_fps(fps)
        tol = check_tolerance(tolerance, module=stage.module)
        check_callback("progress", progress)
        if turn is not None:
            turn = check_angle("turn", turn)
    except GearError as exc:
        raise TrainError(str(exc)) from None
    refuse_failing(stage, check, "animation")
    if turn is None:
        turn = mesh_cycle(stage, fixed)
    layout = gear_layout(stage, 0.0, fixed)
    try:
        check_budget(
            "animation", f"{n} frames of {stage!r}",
            lambda t: n * sum(outline_vertices(g, t) for _, _, g, *_ in layout), tol,
            hint="fewer frames",
        )  # fmt: skip
    except GearError as exc:
        raise TrainError(str(exc)) from None
    step = turn / n
    cache: dict = {}

    def frame(i: int) -> list:
        placed = placed_outlines(stage, i * step, tol, fixed, cache)
        return [(p, np.asarray(COLOURS[key.rstrip("'")]) / 255.0) for _, key, p in placed]

    try:
        return write_animation(path, frame, fps=fps, n_frames=n, progress=progress,
                               title=repr(stage))  # fmt: skip
    except GearError as exc:
        raise TrainError(str(exc)) from None


def mesh_cycle(stage, fixed: str = "ring") -> float:
    """Carrier rotation of one mesh cycle, degrees (:meth:`Planetary.mesh_cycle`)."""
    fixed = stage._member(fixed)
    name = {"sun": "sun", "ring": "ring", "carrier": stage.carrier}
    drive = "sun" if fixed == "carrier" else "carrier"
    motion = stage.train.solve({name.get(drive, drive): 1, name.get(fixed, fixed): 0})
    rel = abs(float(motion["sun"]) - float(motion[stage.carrier]))
    return 360.0 / (stage.sun.teeth * rel)


def svg(stage) -> str:
    """The stage in mesh as an SVG picture (:meth:`Planetary._repr_svg_`)."""

    def parts() -> list:
        tolerance = display_tolerance(max(stage.ring.root_diameter, stage.ring.tip_diameter))
        placed = placed_outlines(stage, 0.0, tolerance, "ring", {})
        return [(p, COLOURS[key.rstrip("'")]) for _, key, p in placed]

    return outlines_svg(parts, "this stage", title=repr(stage))
