"""Layer 7, drawings: what a gear, a pair in mesh and a stage show in a notebook.

``Gear._repr_svg_``, ``GearPair._repr_svg_``, ``BevelPair._repr_svg_``,
``trains.Planetary._repr_svg_`` and ``trains.Differential._repr_svg_`` call these functions;
the SVG itself is written by :func:`gears.display.svg` (the same text
:func:`gears.solid.export.to_svg` writes to a file). The
outlines are the analytic ones of :func:`gears.cutting.outline.gear_outline` and
:func:`gears.cutting.outline.pair_outlines`, sampled at a display tolerance
(:func:`display_tolerance`:
1/1500 of the picture's size, a fraction of a pixel at :data:`WIDTH` pixels), so a drawing stays
small and quick.

A drawing never raises: what cannot be drawn (a rack pair, a tip below the base circle, a
request past the outline's vertex budget) shows as a short text that says why
(:func:`gears.display.message_svg`), and a failure that is not the library's own error says
that it is a bug.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import shapely

from gears.arguments import MIN_TOLERANCE
from gears.cutting.outline import gear_outline, pair_outlines
from gears.display import Circle, bounds, message_svg, svg
from gears.meshing import line_of_action_points

__all__ = [
    "LINE",
    "WIDTH",
    "display_tolerance",
    "filled",
    "gear_svg",
    "outlines_svg",
    "pair_svg",
    "picture",
    "shown",
]

#: Width of a notebook drawing in pixels.
WIDTH = 360
#: Display tolerance as a fraction of the picture's size (0.24 px at 360 px).
SAMPLING = 1 / 1500

Colour = Sequence[float]  # RGB(A), 0-255, as gears.solid.mesh.COLOURS
#: gear 1 and gear 2 (the RGB of gears.solid.mesh.COLOURS, which the classes pass in)
_PAIR_COLOURS = ((70, 130, 180), (222, 140, 60))
#: the style of a drawn line (no fill); stroke widths and dashes are given in pixels (see picture)
LINE = {"fill": "none"}


def display_tolerance(size: float) -> float:
    """The outline tolerance (mm) of a drawing ``size`` mm across: ``size / 1500``.

    >>> display_tolerance(60.0)
    0.04
    """
    return max(float(size) * SAMPLING, MIN_TOLERANCE)


def shown(what: str, draw: Callable[[], str]) -> str:
    """``draw()``, or a text in its place when it fails: the library's own message for a
    :class:`GearError` / ``TrainError`` (both ``ValueError``), a bug report for anything else.

    >>> def fails():
    ...     raise ValueError("no involute")
    >>> "this gear is not drawn: no involute" in shown("this gear", fails)
    True
    """
    try:
        return draw()
    except ValueError as exc:
        return message_svg(f"{what} is not drawn: {exc}")
    except Exception as exc:  # a repr must never raise; say it is a bug
        return message_svg(f"{what} is not drawn ({type(exc).__name__}: {exc}): this is a bug")


def _css(colour: Colour) -> str:
    r, g, b = (int(c) for c in colour[:3])
    return f"rgb({r},{g},{b})"


def filled(colour: Colour) -> dict[str, Any]:
    """The SVG style of a filled shape of ``colour`` (RGB 0-255): the fill at 45 % and its
    outline."""
    return {"fill": _css(colour), "fill-opacity": 0.45, "stroke": _css(colour),
            "stroke-width": 1}  # fmt: skip


def _digits(size: float) -> int:
    """Decimals that resolve 1/10000 of ``size`` (a small fraction of a pixel)."""
    return max(0, min(6, -int(f"{size / 1e4:e}".split("e")[1])))


def picture(shapes: list, size: float, title: str) -> str:
    """The SVG of ``shapes`` at :data:`WIDTH` pixels, their stroke widths and dashes (given in
    pixels) turned into drawing units, so every renderer draws the same lines (SVG's
    ``vector-effect`` is not supported everywhere)."""
    margin = 0.02 * size
    x0, _, x1, _ = bounds([s for s, _ in shapes])
    px = (x1 - x0 + 2 * margin) / WIDTH  # drawing units per pixel
    scaled = []
    for shape, style in shapes:
        style = dict(style)
        if "stroke-width" in style:
            style["stroke-width"] = f"{float(style['stroke-width']) * px:.3g}"
        if "stroke-dasharray" in style:
            dashes = str(style["stroke-dasharray"]).split()
            style["stroke-dasharray"] = " ".join(f"{float(d) * px:.3g}" for d in dashes)
        scaled.append((shape, style))
    return svg(scaled, margin=margin, width=WIDTH, digits=_digits(size), title=title)


def gear_svg(gear: Any, colour: Colour = (70, 130, 180)) -> str:
    """The gear's outline (analytic, every tooth) with its reference circle dashed.

    >>> from gears import Gear
    >>> gear_svg(Gear(12, 3)).count("<path")
    1
    """

    def draw() -> str:
        size = max(gear.tip_diameter, gear.root_diameter)
        shape = gear_outline(gear, display_tolerance(size))
        reference = Circle(0.0, 0.0, gear.reference_diameter / 2)
        dashed = {**LINE, "stroke": "gray", "stroke-width": 0.8, "stroke-dasharray": "4 3"}
        return picture([(shape, filled(colour)), (reference, dashed)], size, repr(gear))

    return shown("this gear", draw)


def pair_svg(pair: Any, colours: tuple[Colour, Colour] = _PAIR_COLOURS) -> str:
    """Both gears in mesh as :meth:`GearPair.outlines` places them (as mounted), their working
    circles dashed, the line of action from N1 (to N2) and the path of contact A-E in red.

    >>> from gears import Gear, GearPair
    >>> pair_svg(GearPair(Gear(12, 3), Gear(24, 3))).count("<path")
    4
    """

    def draw() -> str:
        tips = pair.tip_diameters
        size = pair.center_distance + max(tips)
        p1, p2 = pair_outlines(pair, 0.0, display_tolerance(size))
        shapes: list = [(p1, filled(colours[0])), (p2, filled(colours[1]))]
        dashed = {**LINE, "stroke": "gray", "stroke-width": 0.8, "stroke-dasharray": "4 3"}
        x2 = -pair.center_distance if pair.internal else pair.center_distance
        w1, w2 = pair.working_diameters
        shapes += [(Circle(0.0, 0.0, w1 / 2), dashed), (Circle(x2, 0.0, w2 / 2), dashed)]
        path = pair.path_of_contact
        rb1 = pair.mounted[0].base_diameter / 2

        def line(*u: float) -> shapely.LineString:
            x, y = line_of_action_points(rb1, pair.working_pressure_angle, u, pair.internal)
            return shapely.LineString(list(zip(x, y, strict=True)))

        # N1 to N2 (a ring's N2 lies beyond N1), through the path of contact
        ends = (min(0.0, path.n2, path.start), max(path.n2, path.end))
        shapes.append((line(*ends), {**LINE, "stroke": "black", "stroke-width": 1}))
        shapes.append((line(path.start, path.end), {**LINE, "stroke": "#c62828",
                                                    "stroke-width": 3}))  # fmt: skip
        title = (f"{pair!r}: contact ratio {pair.contact_ratio:.3f}, line of action N1-N2, "
                 "path of contact A-E")  # fmt: skip
        return picture(shapes, size, title)

    return shown("this pair", draw)


def outlines_svg(parts: Callable[[], list[tuple[shapely.Geometry, Colour]]], what: str,
                 title: str = "") -> str:  # fmt: skip
    """Placed outlines, each filled in its colour: ``parts()`` gives ``(outline, colour)``
    pairs (called here, so that a failure to make them shows as a text too).

    >>> import shapely
    >>> outlines_svg(lambda: [(shapely.box(0, 0, 1, 1), (200, 0, 0))], "a box").count("<path")
    1
    """

    def draw() -> str:
        shapes = [(p, filled(c)) for p, c in parts()]
        x0, y0, x1, y1 = shapely.total_bounds([p for p, _ in shapes])
        return picture(shapes, max(x1 - x0, y1 - y0), title)

    return shown(what, draw)
