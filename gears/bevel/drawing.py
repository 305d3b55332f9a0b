"""Layer 8, bevel drawings: what a bevel pair and the differential show in a notebook.

Bevel gears on a common pitch apex in the axial section of their axes, drawn with the notebook
drawing's own picture (:func:`gears.figures.drawing.picture`): the tooth zone of each gear from
its cone formulas (:func:`gears.bevel.cone.axial_section`), its pitch cone and axis.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import shapely

from gears.bevel.cone import axial_section
from gears.figures.drawing import LINE, Colour, filled, picture, shown

__all__ = ["bevel_pair_svg", "bevel_svg"]


def bevel_svg(parts: Callable[[], list[tuple[Any, float, Colour]]], what: str,
              title: str = "") -> str:  # fmt: skip
    """Bevel gears on a common pitch apex (the origin) in the axial section of their axes: each
    gear's tooth zone (:func:`gears.bevel.cone.axial_section`, on both sides of its axis, over a
    lighter body down to the axis), its pitch cone dashed and its axis dash-dotted. ``parts()``
    gives ``(bevel gear, axis angle in degrees in the drawing, colour)`` triples (a
    :class:`gears.BevelGear` or anything with its cone attributes).

    >>> from gears import BevelPair
    >>> p = BevelPair(20, 40, module=3, face_width=20)
    >>> bevel_svg(lambda: [(p.g1, 0.0, (70, 130, 180))], "a gear").count("<path")
    6
    """

    def draw() -> str:
        size = 0.0
        shapes: list = []
        dashed = {**LINE, "stroke": "gray", "stroke-width": 0.8, "stroke-dasharray": "4 3"}
        axis = {**LINE, "stroke": "black", "stroke-width": 0.6, "stroke-dasharray": "8 3 2 3"}
        for gear, angle, colour in parts():
            a = np.array([np.cos(np.radians(angle)), np.sin(np.radians(angle))])
            p = np.array([-a[1], a[0]])  # both sides of the axis are drawn
            corners = axial_section(gear.pitch_angle, gear.face_angle, gear.root_angle,
                                    gear.cone_distance, gear.face_width, gear.addendum,
                                    gear.dedendum)  # fmt: skip
            (r_o, z_o), (r_i, z_i) = corners[1], corners[2]  # the root line, back to front
            body = [z_o * a + r_o * p, z_i * a + r_i * p, z_i * a - r_i * p, z_o * a - r_o * p]
            shapes.append((shapely.Polygon(body), {**filled(colour), "fill-opacity": 0.15}))
            delta = np.radians(gear.pitch_angle)
            pitch = gear.cone_distance * np.array([np.sin(delta), np.cos(delta)])
            for side in (1.0, -1.0):
                xy = [z * a + side * rho * p for rho, z in corners]
                shapes.append((shapely.Polygon(xy), filled(colour)))
                end = pitch[1] * a + side * pitch[0] * p
                shapes.append((shapely.LineString([(0.0, 0.0), end]), dashed))
            reach = float(np.max(corners[:, 1])) * 1.1
            shapes.append((shapely.LineString([(0.0, 0.0), reach * a]), axis))
            size = max(size, float(np.max(np.abs(corners))))
        return picture(shapes, 2 * size, title)

    return shown(what, draw)


def bevel_pair_svg(
    pair: Any, colours: tuple[Colour, Colour] = ((70, 130, 180), (222, 140, 60))
) -> str:
    """A bevel pair in axial section (:func:`bevel_svg`), the drawing of its blanks: gear 1's
    axis along +x, gear 2's at the shaft angle, their pitch cones touching along one generator.

    >>> from gears import BevelPair
    >>> bevel_pair_svg(BevelPair(20, 40, module=3, face_width=20)).count("<path")
    12
    """

    def parts() -> list:
        return [(pair.g1, 0.0, colours[0]), (pair.g2, float(pair.shaft_angle), colours[1])]

    return bevel_svg(parts, "this bevel pair", f"{pair!r}: axial section, pitch cones dashed")
