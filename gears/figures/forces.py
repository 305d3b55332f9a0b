"""Layer 3, figures: force vectors drawn on the outlines of a pair or a stage (matplotlib).

:func:`forces_figure` draws outlines (shapely polygons, in mm) and arrows (a force in N at a
point in mm), the arrows scaled so that the largest spans a third of the drawing;
:func:`pair_forces_figure` draws the mesh force on each gear of a pair at the pitch point and
each bearing's reaction at its gear's axis (:class:`gears.forces.PairForces`).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import Any

import numpy as np

from gears.errors import GearError
from gears.files import pyplot
from gears.forces import PairForces

__all__ = ["forces_figure", "pair_forces_figure"]

#: Arrow colours: a mesh force, a bearing's reaction, a planet's pin.
COLOURS = {"mesh": "#c62828", "bearing": "#1565c0", "pin": "#2e7d32"}


def forces_figure(
    outlines: Iterable[Any],
    arrows: Sequence[tuple[float, float, float, float, str, str]],
    ax: Any = None,
    title: str | None = None,
):
    """A figure of ``outlines`` with ``arrows`` ``(x, y, fx, fy, label, kind)``: a force
    ``(fx, fy)`` in N at ``(x, y)`` in mm, drawn in the colour of ``kind`` (``"mesh"``,
    ``"bearing"`` or ``"pin"``) and labelled with ``label``. Returns the matplotlib Figure.

    Examples
    --------
    >>> import shapely
    >>> fig = forces_figure([shapely.Point(0, 0).buffer(10)], [(10, 0, 0, -100, "F", "mesh")])
    >>> len(fig.axes[0].texts)   # the arrow and its label
    2
    """
    plt = pyplot()
    if ax is None:
        fig, ax = plt.subplots(figsize=(6, 6))
    else:
        fig = ax.figure
    xs, ys = [], []
    for poly in outlines:
        for part in getattr(poly, "geoms", [poly]):
            for ring in (part.exterior, *part.interiors):
                x, y = ring.xy
                ax.plot(x, y, color="0.35", linewidth=0.6)
                xs += list(x)
                ys += list(y)
    pts = np.array([(a[0], a[1]) for a in arrows], float).reshape(-1, 2)
    vec = np.array([(a[2], a[3]) for a in arrows], float).reshape(-1, 2)
    if not (np.all(np.isfinite(pts)) and np.all(np.isfinite(vec))):
        raise GearError("forces_figure: every arrow needs finite coordinates and components")
    xs += list(pts[:, 0])
    ys += list(pts[:, 1])
    size = max(np.ptp(xs) if xs else 1.0, np.ptp(ys) if ys else 1.0, 1e-9)
    longest = float(np.max(np.hypot(vec[:, 0], vec[:, 1]))) if len(vec) else 0.0
    scale = size / 3 / longest if longest > 0 else 0.0
    for x, y, fx, fy, label, kind in arrows:
        if fx == 0 and fy == 0:
            continue
        ax.annotate(
            "",
            xy=(x + fx * scale, y + fy * scale),
            xytext=(x, y),
            arrowprops={"arrowstyle": "-|>", "color": COLOURS.get(kind, "k"), "lw": 1.6},
        )
        ax.text(
            x + fx * scale, y + fy * scale, f" {label}", fontsize=7, color=COLOURS.get(kind, "k")
        )
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    if title:
        ax.set_title(title, fontsize=9)
    if xs:
        pad = 0.1 * size
        ax.set_xlim(min(xs) - pad, max(xs) + pad)
        ax.set_ylim(min(ys) - pad, max(ys) + pad)
    ax.autoscale_view()
    return fig


def pair_forces_figure(forces: PairForces, outlines: Iterable[Any] = (), ax: Any = None):
    """The mesh force on each gear of a pair at the pitch point and each bearing's reaction
    at its axis (in the plane of the pair's frame), on the pair's ``outlines``.

    Examples
    --------
    >>> from gears import Gear, GearPair
    >>> from gears.forces import pair_forces
    >>> f = pair_forces(GearPair(Gear(20, 5), Gear(40, 5)), 100.0)
    >>> fig = pair_forces_figure(f)
    >>> len(fig.axes[0].texts)   # two mesh forces, two bearings: arrows and labels
    8
    """
    p = forces.point
    arrows = []
    for i, name in enumerate(("gear 1", "gear 2")):
        v = forces.vectors[i]
        arrows.append((p[0], p[1], v[0], v[1], f"on {name}: {np.hypot(v[0], v[1]):.0f} N", "mesh"))
        c = forces.centres[i]
        if np.all(np.isfinite(c)):
            arrows.append((c[0], c[1], -v[0], -v[1], f"bearing {i + 1}", "bearing"))
    title = (
        f"{forces.kind} mesh, T1 = {forces.torque:g} N m: F_t {forces.tangential[0]:.0f} N, "
        f"F_r {forces.radial[0]:.0f} N, F_a {forces.axial[0]:.0f} N"
    )
    return forces_figure(outlines, arrows, ax, title)
