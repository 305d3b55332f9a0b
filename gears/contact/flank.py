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

from gears.contact.modification import lead_relief, profile_relief

__all__ = [
    "MAX_LEAD_LEVELS",
    "flank_turns",
    "gear_short_relief",
    "modified_outline",
    "rack_short_relief",
    "relieved_outline",
    "solid_lead",
]

#: The most axial levels a lead modification adds to a solid (a crowning of 1 mm held to
#: 1e-6 mm needs 708).
MAX_LEAD_LEVELS = 1024


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


def gear_short_relief(gear) -> float:
    """The short relief (mm of roll) of a gear drawn alone, the default of a relief length left
    None: against its basic rack (:func:`rack_short_relief`); a ring's mirrors it, the rack's
    tip line (at the reference line's addendum, no shift) cutting the line of action beyond
    the pitch point while the ring's tip lies before it."""
    rb, ra = gear.base_diameter / 2, gear.tip_diameter / 2
    if not gear.internal:
        return rack_short_relief(rb, ra, gear.transverse_pressure_angle, gear.rack.addendum,
                                 gear.profile_shift, gear.module, gear.base_pitch)  # fmt: skip
    at = math.radians(gear.transverse_pressure_angle)
    start = rb * math.tan(at) + gear.rack.addendum * gear.module / math.sin(at)
    end = math.sqrt(max(ra**2 - rb**2, 0.0))
    return max(start - end - gear.base_pitch, 0.0)


def relieved_outline(gear, polygon, center=(0.0, 0.0), short: float | None = None):
    """``polygon``, the outline of ``gear`` (a :class:`gears.Gear`) about ``center``, with the
    gear's ``modification`` tip and root relief taken off (:func:`modified_outline`); a
    relief length left None is ``short`` (the pair's short relief, mm of roll), else
    :func:`gear_short_relief`."""
    m = getattr(gear, "modification", None)
    if m is None or not (m.tip_relief or m.root_relief):
        return polygon
    short = gear_short_relief(gear) if short is None else short
    tip_length, root_length, _ = m.lengths(short, gear.face_width or 1.0)
    rb = gear.base_diameter / 2
    form = gear._form / 2 if gear._form > gear.base_diameter else rb
    return modified_outline(polygon, rb, form, gear.tip_diameter / 2, m.tip_relief, tip_length,
                            m.root_relief, root_length, m.kind, center,
                            gear.internal)  # fmt: skip


def _lead_counts(m, tolerance) -> tuple[int, int]:
    """Axial steps a half face takes for the crowning, and an end-relief zone for its relief."""
    n_crown = math.ceil(math.sqrt(m.crowning / (2.0 * tolerance))) if m.crowning else 1
    n_end = math.ceil(math.sqrt(m.end_relief / (4.0 * tolerance))) if m.end_relief else 0
    n_end = min(n_end, 1) if m.kind == "linear" else n_end
    return min(n_crown, MAX_LEAD_LEVELS // 4), min(n_end, MAX_LEAD_LEVELS // 4)


def lead_levels(modification, tolerance: float) -> float:
    """The most axial levels :func:`solid_lead` adds to a solid at ``tolerance`` (0 without
    crowning or end relief): what a solid's size estimate adds before it is drawn."""
    m = modification
    if m is None or not (m.crowning or m.end_relief):
        return 0.0
    n_crown, n_end = _lead_counts(m, tolerance)
    return float(2 * n_crown + 1 + 2 * (n_end + 1))


def solid_lead(gear, face_width: float, tolerance: float):
    """``(lead, extra_twist)`` of ``gear``'s solid of ``face_width`` (mm) at ``tolerance``:
    the ``lead`` argument of :func:`gears.solid.mesh.gear_solid` for its crowning and end
    relief (None without them), and the helix slope f_Hbeta as extra twist in degrees (each
    section turns by f_Hbeta z / (b r_b): a change of the helix angle, the flank facing
    counter-clockwise relieved toward +z, the other filled). The crowning's parabola is held
    to ``tolerance`` by ``ceil(sqrt(C_b / (2 tol)))`` levels a half face (the chord's sag of
    C_b (2 z / b)^2 over a step h is C_b h^2 / (2 b^2)); a parabolic end relief's by
    ``ceil(sqrt(C_I / (4 tol)))`` in its zone; a linear one needs only its kinks."""
    m = getattr(gear, "modification", None)
    if m is None:
        return None, 0.0
    rb = gear.base_diameter / 2
    extra = math.degrees(m.helix_slope / rb)
    if not (m.crowning or m.end_relief):
        return None, extra
    b = face_width
    _, _, end_length = m.lengths(0.0, b)
    half = b / 2.0
    n_crown, n_end = _lead_counts(m, tolerance)
    z = [np.linspace(-half, half, 2 * n_crown + 1)]
    if m.end_relief and end_length > 0:
        zone = np.linspace(half - end_length, half, n_end + 1)
        z += [zone, -zone]
    form = gear._form / 2 if gear._form > gear.base_diameter else rb
    tip = gear.tip_diameter / 2

    def turns_of(rings):
        toothed = range(1, len(rings)) if gear.internal else (0,)
        return np.concatenate([
            flank_turns(r, rb, form, tip, None, (0.0, 0.0), gear.internal) if i in toothed
            else np.zeros(len(r)) for i, r in enumerate(rings)
        ])  # fmt: skip

    def relief_of(zs):
        return lead_relief(zs, b, m.crowning, m.end_relief, end_length, 0.0, m.kind)

    return (turns_of, relief_of, np.concatenate(z)), extra


def flank_turns(ring, base_radius, form_radius, tip_radius, relief_of=None, center=(0.0, 0.0),
                internal=False):  # fmt: skip
    """Turn (radians) of each vertex of ``ring`` (an ``(n, 2)`` closed ring of an oriented
    polygon, closing point dropped: an external gear's counter-clockwise exterior or a ring's
    clockwise toothed hole) that takes a relief off its flanks: ``relief_of(rho)`` mm at the
    roll lengths ``rho`` (None: 1 mm everywhere on the active flank), over the flanks between
    ``form_radius`` and ``tip_radius``; each tip land turns between its two corners."""
    cx, cy = center
    x, y = ring[:, 0] - cx, ring[:, 1] - cy
    r = np.hypot(x, y)
    # along an exterior (counter-clockwise) or a hole (clockwise) the material lies on the
    # left: where the radius grows toward an external tooth's tip (or falls toward a ring
    # tooth's) its centre line lies ahead, so sign(dr) turns toward it in both cases
    dr = np.roll(r, -1) - np.roll(r, 1)
    rho = np.sqrt(np.maximum(r * r - base_radius**2, 0.0))
    relief = np.ones_like(r) if relief_of is None else relief_of(rho)
    steep = np.abs(dr) > 1e-9 * r  # a flank; the tip land and the root arc keep their radius
    low, high = (tip_radius, form_radius) if internal else (form_radius, tip_radius)
    on_flank = (r >= low * (1 - 1e-9)) & (r <= high * (1 + 1e-9)) & steep
    turn = np.where(on_flank, np.sign(dr) * relief / base_radius, 0.0)
    if internal:
        land = ~steep & (r <= tip_radius * (1 + 1e-9))
    else:
        land = ~steep & (r >= tip_radius * (1 - 1e-9))
    _follow_tip_lands(turn, np.arctan2(y, x), land)
    return turn


def _turned(ring, turn, center):
    cx, cy = center
    x, y = ring[:, 0] - cx, ring[:, 1] - cy
    c, s = np.cos(turn), np.sin(turn)
    return np.column_stack([cx + c * x - s * y, cy + s * x + c * y])


def modified_outline(polygon, base_radius, form_radius, tip_radius, tip_relief, tip_length,
                     root_relief, root_length, kind="linear", center=(0.0, 0.0),
                     internal=False):  # fmt: skip
    """``polygon`` (a gear's outline about ``center``) with the profile relief taken off its
    flanks between ``form_radius`` and ``tip_radius`` (mm): each vertex turned toward its
    tooth's centre line by relief / ``base_radius`` (:func:`flank_turns`). An external gear's
    teeth are its exterior; a ring's (``internal``) are its hole, inside the rim."""
    if tip_relief <= 0 and root_relief <= 0:
        return polygon
    oriented = shapely.orient_polygons(polygon)
    rho_tip = math.sqrt(max(tip_radius**2 - base_radius**2, 0.0))
    rho_form = math.sqrt(max(form_radius**2 - base_radius**2, 0.0))

    def relief_of(rho):
        return profile_relief(rho, rho_form, rho_tip, tip_relief, tip_length, root_relief,
                              root_length, kind)  # fmt: skip

    rings = [np.asarray(c.coords)[:-1] for c in (oriented.exterior, *oriented.interiors)]
    toothed = range(1, len(rings)) if internal else (0,)
    for i in toothed:
        turn = flank_turns(rings[i], base_radius, form_radius, tip_radius, relief_of, center,
                           internal)  # fmt: skip
        rings[i] = _turned(rings[i], turn, center)
    return shapely.Polygon(rings[0], rings[1:])


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
