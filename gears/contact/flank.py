"""Layer 3, modified flanks: a gear's outline with its profile modifications taken off.

An involute moved along its normal by ``delta`` is the same involute turned by ``delta / r_b``
about the gear's axis (involutes of one base circle are parallel curves, ISO 21771 clause 4),
so a relief of ``delta(r)`` moves each flank point at radius ``r`` through ``delta(r) / r_b``
toward its tooth's centre line: exact at every vertex, with the relief a function of the roll
length ``sqrt(r^2 - r_b^2)`` as in the contact analysis. The tip relief runs from the tip
circle, the root relief from the form circle (the start of the involute); the fillet and the
tip land keep their shape.

Examples
--------
>>> import shapely
>>> square = shapely.Polygon([(9, -1), (11, -1), (11, 1), (9, 1)])
>>> relieved = modified_outline(square, 8.0, 9.0, 11.0, 0.0, 0.0, 0.0, 0.0)
>>> round(relieved.area, 12) == round(square.area, 12)   # nothing to take off
True
"""

from __future__ import annotations

import math

import numpy as np
import shapely

from gears.contact.modification import profile_relief

__all__ = ["modified_outline", "rack_short_relief"]


def rack_short_relief(base_radius, tip_radius, transverse_pressure_angle, addendum, shift,
                      module, base_pitch):  # fmt: skip
    """The short relief (mm of roll) of a gear meshing with its basic rack: from the tip to
    the nearest point of single contact, ``(eps_alpha - 1) p_bt`` with the rack's path of
    contact from its tip line, ``(h_aP - x) m_n / sin alpha_t`` before the pitch point (the
    default relief length of a gear drawn alone). ``transverse_pressure_angle`` in degrees."""
    at = math.radians(transverse_pressure_angle)
    start = base_radius * math.tan(at) - (addendum - shift) * module / math.sin(at)
    end = math.sqrt(max(tip_radius**2 - base_radius**2, 0.0))
    return max(end - start - base_pitch, 0.0)


def modified_outline(polygon, base_radius, form_radius, tip_radius, tip_relief, tip_length,
                     root_relief, root_length, kind="linear", center=(0.0, 0.0)):  # fmt: skip
    """``polygon`` (an external gear's outline about ``center``) with the profile relief taken
    off its flanks between ``form_radius`` and ``tip_radius`` (mm): each vertex turned toward
    its tooth's centre line by relief / ``base_radius``. The flank's side is read from the
    ring's direction (counter-clockwise: the radius grows along a flank whose tooth lies
    ahead, counter-clockwise)."""
    if tip_relief <= 0 and root_relief <= 0:
        return polygon
    ring = np.asarray(shapely.orient_polygons(polygon).exterior.coords)[:-1]
    cx, cy = center
    x, y = ring[:, 0] - cx, ring[:, 1] - cy
    r = np.hypot(x, y)
    dr = np.roll(r, -1) - np.roll(r, 1)  # outward along the ring: tooth ahead (+theta)
    rho = np.sqrt(np.maximum(r * r - base_radius**2, 0.0))
    rho_tip = math.sqrt(max(tip_radius**2 - base_radius**2, 0.0))
    rho_form = math.sqrt(max(form_radius**2 - base_radius**2, 0.0))
    relief = profile_relief(rho, rho_form, rho_tip, tip_relief, tip_length, root_relief,
                            root_length, kind)  # fmt: skip
    steep = np.abs(dr) > 1e-9 * r  # a flank; the tip land and the root arc keep their radius
    on_flank = (r >= form_radius) & (r <= tip_radius * (1 + 1e-9)) & steep
    turn = np.where(on_flank, np.sign(dr) * relief / base_radius, 0.0)
    _follow_tip_lands(turn, np.arctan2(y, x), ~steep & (r >= tip_radius * (1 - 1e-9)))
    c, s = np.cos(turn), np.sin(turn)
    moved = np.column_stack([cx + c * x - s * y, cy + s * x + c * y])
    holes = [np.asarray(h.coords) for h in polygon.interiors]
    return shapely.Polygon(moved, holes)


def _follow_tip_lands(turn, theta, land) -> None:
    """Turn each tip land's vertices between its two corners' turns, in proportion to their
    angle (in place): the land narrows evenly and never folds over its corners."""
    n = land.size
    if land.all() or not land.any():
        return
    first = int(np.argmin(land))  # a vertex off every land: runs do not wrap from there
    order = np.roll(np.arange(n), -first)
    runs = np.flatnonzero(np.diff(np.r_[0, land[order].astype(int), 0]))
    for a, b in zip(runs[::2], runs[1::2], strict=True):  # land[order[a:b]], corners a-1, b
        c0, c1 = order[a - 1], order[b % n]
        span = (theta[c1] - theta[c0]) % (2 * np.pi)
        frac = ((theta[order[a:b]] - theta[c0]) % (2 * np.pi)) / span
        turn[order[a:b]] = turn[c0] + frac * (turn[c1] - turn[c0])
