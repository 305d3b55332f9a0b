"""Layer 0, display text: SVG drawings and HTML tables, importing no project module.

The one place that writes SVG: :func:`gears.solid.export.to_svg` writes :func:`svg` text to a file
(user unit 1 mm), and the notebook displays (``Gear._repr_svg_``, ``GearPair._repr_svg_``,
``Planetary._repr_svg_``, through :mod:`gears.figures.drawing`) show it at a pixel width. HTML
tables
(:func:`html_table`) are what ``Report``, ``SearchResult`` and ``Rating`` show in a notebook.

Drawings keep the drawings' orientation (y up): a point ``(x, y)`` is written at
``(x, y0 + y1 - y)`` in the view box ``x0 y0 w h`` of the drawing's bounds.

Examples
--------
>>> import shapely
>>> text = svg([(shapely.box(0, 0, 2, 1), {"fill": "none", "stroke": "black"})], margin=0, digits=0)
>>> text.count("<path"), 'viewBox="0 0 2 1"' in text
(1, True)
>>> print(html_table(["name", "margin"], [["undercut", "+0.1"]], failing=[False]))
<table>
<thead><tr><th>name</th><th>margin</th></tr></thead>
<tbody>
<tr><td>undercut</td><td>+0.1</td></tr>
</tbody>
</table>
"""

from __future__ import annotations

import html
import math
import textwrap
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, TypeAlias

import numpy as np
import shapely

__all__ = ["Circle", "bounds", "factor_lines", "factor_text", "html_table", "message_svg", "svg"]

#: Style of a failing row of an HTML table (a red text, readable in light and dark themes).
FAIL_STYLE = "color:#c62828;font-weight:bold"


@dataclass(frozen=True)
class Circle:
    """A circle of centre ``(x, y)`` and radius ``r`` (mm), drawn as one ``<circle>``."""

    x: float
    y: float
    r: float


Shape: TypeAlias = shapely.Geometry | Circle


def bounds(shapes: Sequence[Shape]) -> tuple[float, float, float, float]:
    """``(x0, y0, x1, y1)`` of shapely geometries and :class:`Circle` s together (their finite
    parts; ``(0, 0, 1, 1)`` for nothing).

    >>> bounds([Circle(0, 0, 2), shapely.Point(5, 1)])
    (-2.0, -2.0, 5.0, 2.0)
    """
    geoms = [s for s in shapes if not isinstance(s, Circle)]
    boxes = [shapely.total_bounds(geoms)] if geoms else []
    boxes += [(c.x - c.r, c.y - c.r, c.x + c.r, c.y + c.r) for c in shapes if isinstance(c, Circle)]
    b = np.asarray(boxes, float)
    finite = b[np.all(np.isfinite(b), axis=1)] if b.size else b
    if not finite.size:
        return 0.0, 0.0, 1.0, 1.0
    return (float(finite[:, 0].min()), float(finite[:, 1].min()),
            float(finite[:, 2].max()), float(finite[:, 3].max()))  # fmt: skip


def _rings(geom: shapely.Geometry) -> Iterable[tuple[np.ndarray, bool]]:
    """``(xy, closed)`` of every ring and line of ``geom``."""
    if isinstance(geom, shapely.Polygon):
        for ring in (geom.exterior, *geom.interiors):
            yield np.asarray(ring.coords)[:-1, :2], True
    elif isinstance(geom, shapely.LinearRing):
        yield np.asarray(geom.coords)[:-1, :2], True
    elif isinstance(geom, shapely.LineString):
        yield np.asarray(geom.coords)[:, :2], False
    elif hasattr(geom, "geoms"):  # Multi* and collections
        for part in geom.geoms:
            yield from _rings(part)


def _path_data(geom: shapely.Geometry, flip: float, digits: int) -> str:
    parts = []
    for xy, closed in _rings(geom):
        if len(xy) < 2:
            continue
        xs, ys = xy[:, 0], flip - xy[:, 1]
        coords = " L".join(f"{x:.{digits}f},{y:.{digits}f}" for x, y in zip(xs, ys, strict=True))
        parts.append(f"M{coords}" + (" Z" if closed else ""))
    return " ".join(parts)


def _attributes(style: Mapping[str, Any]) -> str:
    return "".join(f' {k}="{html.escape(str(v))}"' for k, v in style.items())


def svg(
    shapes: Iterable[tuple[Shape, Mapping[str, Any]]], *, margin: float = 1.0,
    width: float | None = None, digits: int = 6, title: str | None = None,
    declaration: bool = False,
) -> str:  # fmt: skip
    """An SVG document of ``shapes``: ``(shape, attributes)`` pairs, each shape a shapely
    geometry (one ``<path>``: polygons closed, with ``fill-rule="evenodd"`` so holes stay open;
    lines open) or a :class:`Circle` (one ``<circle>``), with the SVG presentation attributes
    given (``{"fill": "none", "stroke": "black"}``).

    Parameters
    ----------
    shapes : iterable of (shapely.Geometry or Circle, mapping)
        What to draw, bottom first.
    margin : float
        Space around the shapes' bounds, in drawing units (mm).
    width : float or None
        The picture's width in pixels (height in proportion), for a screen; ``None`` gives
        ``width`` and ``height`` in mm, one user unit per mm, for a file.
    digits : int
        Decimals written per coordinate.
    title : str or None
        A ``<title>`` (shown as a tooltip, read by screen readers).
    declaration : bool
        Start with the ``<?xml ...?>`` declaration (for a file of its own).

    Returns
    -------
    str
    """
    items = list(shapes)
    x0, y0, x1, y1 = bounds([s for s, _ in items])
    x0, y0, x1, y1 = x0 - margin, y0 - margin, x1 + margin, y1 + margin
    w, h = max(x1 - x0, 1e-9), max(y1 - y0, 1e-9)
    flip = y0 + y1
    if width is None:
        size = f'width="{w:.{digits}f}mm" height="{h:.{digits}f}mm"'
    else:
        size = f'width="{width:.0f}" height="{max(width * h / w, 1.0):.0f}"'
    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" {size} '
        f'viewBox="{x0:.{digits}f} {y0:.{digits}f} {w:.{digits}f} {h:.{digits}f}">'
    ]
    if title:
        out.append(f"<title>{html.escape(title)}</title>")
    for shape, style in items:
        if isinstance(shape, Circle):
            if math.isfinite(shape.r) and shape.r > 0:
                out.append(
                    f'<circle cx="{shape.x:.{digits}f}" cy="{flip - shape.y:.{digits}f}" '
                    f'r="{shape.r:.{digits}f}"{_attributes(style)}/>'
                )
            continue
        d = _path_data(shape, flip, digits)
        if d:
            rule = ' fill-rule="evenodd"' if "fill-rule" not in style else ""
            out.append(f'<path d="{d}"{rule}{_attributes(style)}/>')
    out.append("</svg>")
    head = '<?xml version="1.0" encoding="UTF-8"?>\n' if declaration else ""
    return head + "\n".join(out) + "\n"


def message_svg(text: str, width: int = 360, columns: int = 56) -> str:
    """A small SVG that shows ``text`` (wrapped at ``columns`` characters): what a display
    shows instead of a drawing that cannot be made.

    >>> message_svg("cannot draw: z = 3").count("<text")
    1
    """
    lines = textwrap.wrap(str(text), columns) or [""]
    step = 16
    height = step * len(lines) + 12
    body = "".join(
        f'<tspan x="8" y="{step * (i + 1)}">{html.escape(line)}</tspan>'
        for i, line in enumerate(lines)
    )
    return (
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
        f'viewBox="0 0 {width} {height}">\n'
        f'<rect width="{width}" height="{height}" fill="#fff3e0" stroke="#e65100"/>\n'
        f'<text font-family="sans-serif" font-size="12" fill="#bf360c">{body}</text>\n</svg>\n'
    )


def factor_text(value) -> str:
    """A factor or quantity of a rating as text: 5 significant digits, 4 in exponent notation
    beyond 1e5 or below 1e-3; a pair ``(gear 1, gear 2)`` as ``"a / b"``.

    >>> factor_text((1.23456789, 0.0001234)), factor_text(2.5e6)
    ('1.2346 / 0.0001234', '2.5e+06')
    """
    if isinstance(value, tuple):
        return " / ".join(factor_text(v) for v in value)
    if abs(value) >= 1e5 or (value != 0 and abs(value) < 1e-3):
        return f"{value:.4g}"
    return f"{value:.5g}"


def factor_lines(factors: Iterable, quantities: Iterable, source: str, width: int) -> list[str]:
    """The factor and quantity sections of a rating's text: ``factors`` as ``(symbol, value,
    source, what)`` under a ``source`` column ``width`` wide, then ``quantities`` as ``(symbol,
    value, label)``, values by :func:`factor_text`.

    >>> lines = factor_lines([("K_A", 1.25, "ISO 6336-1", "application")],
    ...                      [("m_n", 2.0, "module [mm]")], "clause", 10)
    >>> for line in lines[1:]:
    ...     print(line)
    factor                      value  clause     what
    K_A                          1.25  ISO 6336-1 application
    <BLANKLINE>
    m_n                             2  module [mm]
    """
    lines = ["", f"{'factor':13s} {'value':>19s}  {source:{width}s} what"]
    for symbol, value, where, what in factors:
        lines.append(f"{symbol:13s} {factor_text(value):>19s}  {where:{width}s} {what}")
    lines.append("")
    for symbol, value, label in quantities:
        lines.append(f"{symbol:13s} {factor_text(value):>19s}  {label}")
    return lines


def html_table(
    columns: Sequence[str], rows: Iterable[Sequence[Any]], *,
    failing: Sequence[bool] | None = None, caption: str | None = None,
) -> str:  # fmt: skip
    """An HTML ``<table>`` of ``rows`` under the header ``columns`` (cells are escaped);
    rows whose ``failing`` flag is true are marked (``class="fail"``, red bold text).

    Parameters
    ----------
    columns : sequence of str
        Header cells.
    rows : iterable of sequences
        Body cells, shown with ``str``.
    failing : sequence of bool, optional
        One flag per row.
    caption : str, optional
        A line above the table.

    Returns
    -------
    str
    """
    rows = [list(r) for r in rows]
    flags = list(failing) if failing is not None else [False] * len(rows)
    out = ["<table>"]
    if caption:
        out.append(f"<caption>{html.escape(caption)}</caption>")
    head = "".join(f"<th>{html.escape(str(c))}</th>" for c in columns)
    out += [f"<thead><tr>{head}</tr></thead>", "<tbody>"]
    for row, bad in zip(rows, flags, strict=True):
        cells = "".join(f"<td>{html.escape(str(c))}</td>" for c in row)
        mark = f' class="fail" style="{FAIL_STYLE}"' if bad else ""
        out.append(f"<tr{mark}>{cells}</tr>")
    out += ["</tbody>", "</table>"]
    return "\n".join(out)
