"""Layer 2, sampling: what every outline of the cutting family shares besides its curves: arcs,
circles and involutes sampled to a tolerance (their chords sag at most half of it), chords made
one-sided so that no chord adds material, the backlash, bore and rim checked, and a toothed ring
assembled into the gear's polygon (a disc with its bore, or a ring with its rim).

The sampling rules are those of :mod:`gears.cutting.profile` ("Sampling from a tolerance";
the chord sag of a curve of radius rho over an angle dphi is rho dphi^2 / 8).
"""

from __future__ import annotations

import math

import numpy as np
import shapely

from gears.arguments import check_length, check_real
from gears.budget import BUDGETS
from gears.errors import GearError

__all__ = ["MAX_OUTLINE_VERTICES", "assemble", "check_backlash", "check_blank", "one_sided"]

# Chords are placed at half the tolerance: the deviation then stays below it, and a thickness
# measured across two flanks (2 sag / cos alpha_y) stays within the tolerance too.
_SAFETY = 0.5


def _refuse_protuberance(gear) -> None:
    if gear.rack.protuberance > 0:
        raise GearError(
            f"rack protuberance = {gear.rack.protuberance:g} m: protuberance tools are not "
            "modelled in the outlines; use a rack without protuberance"
        )


def _root(f, lo: float, hi: float, failure: str) -> float:
    """The root of ``f`` in ``[lo, hi]`` (Brent's method to machine precision), or a
    :class:`GearError` saying ``failure`` when the interval does not bracket one (a sampled
    crossing that rounding moved): every root of the envelope is found through here."""
    from scipy.optimize import brentq  # heavy: imported where used

    a, b = float(f(lo)), float(f(hi))
    if a == 0.0:
        return lo
    if b == 0.0:
        return hi
    if not (math.isfinite(a) and math.isfinite(b)) or (a > 0) == (b > 0) or not lo < hi:
        raise GearError(failure)
    return float(brentq(f, lo, hi, xtol=1e-15, rtol=1e-15))


def involute_rolls(rb: float, t0: float, t1: float, sag: float) -> np.ndarray:
    """Roll angles from t0 to t1 on an involute of base radius ``rb`` whose chords sag at most
    ``sag``: the sag of a roll step dt is r_b t dt^2 / 8 (rho = r_b t), so the points are uniform
    in w = t^(3/2) with dw = 1.5 sqrt(8 sag / r_b) (a chord of a curve of radius rho over an
    angle dphi sags rho dphi^2 / 8)."""
    w0, w1 = t0**1.5, t1**1.5
    dw = 1.5 * math.sqrt(8.0 * sag / rb)
    n = max(1, math.ceil(abs(w1 - w0) / dw))
    return np.linspace(w0, w1, n + 1) ** (2.0 / 3.0)


def rim_width(gear, rim: float | None) -> float:
    """Rim width of an internal gear outside its root circle, mm (default 3 m_n), checked
    (:func:`gears.arguments.check_length`, relative to the module)."""
    return default_rim(gear) if rim is None else check_length("rim", rim, gear.module)


#: Largest outline, in vertices (about 160 MB of coordinates with shapely's copy): the
#: ``"outline"`` budget of :data:`gears.budget.BUDGETS`.
MAX_OUTLINE_VERTICES = BUDGETS["outline"]


def check_backlash(gear, backlash) -> float:
    """``backlash`` (the pair's normal backlash, mm) as a float, or a :class:`GearError` naming
    the valid range: 0 <= j < 2 s_t cos(alpha_t), beyond which this gear's half (each flank
    thinned by j/4 along its normal) leaves no tooth on the reference circle."""
    j = check_real("backlash", backlash)
    at = math.radians(gear.transverse_pressure_angle)
    most = 2 * gear.reference_thickness * math.cos(at)
    if not 0.0 <= j < most:  # NaN fails too
        raise GearError(
            f"backlash = {backlash!r} mm; valid is 0 <= backlash < {most:.6g} mm (at that "
            f"backlash z = {gear.teeth} keeps no tooth on its reference circle)"
        )
    return j


def chord_angle(radius: float, tolerance: float) -> float:
    """The largest angle (rad) one chord may span on an arc of ``radius`` with its sagitta
    within ``tolerance``: ``2 acos(1 - tolerance / radius)`` (sagitta ``r (1 - cos(phi / 2))``),
    a whole turn where the tolerance passes the diameter.

    >>> round(chord_angle(10.0, 0.0005), 6)   # 2 sqrt(2 e / r) = 0.02 for a small sagitta
    0.02
    """
    return 2.0 * math.acos(max(1.0 - tolerance / max(radius, 1e-300), -1.0))


def arc_segments(radius: float, angle: float, tolerance: float) -> int:
    """Segments for an arc of ``radius`` over ``angle`` rad with sagitta <= ``tolerance``.

    >>> arc_segments(10.0, math.pi, 0.001)
    158
    """
    if angle <= 0 or radius <= 0:
        return 1
    return max(1, math.ceil(angle / chord_angle(radius, _SAFETY * tolerance)))


#: A vertex next to a chord that would add material moves into the material by this many times
#: the largest sag of the true curve beyond the chord, found at :data:`_BETWEEN` points of it,
#: by curve kind (the margin covers the curve between them). Chords sag at most half the
#: tolerance, so a moved vertex stays within 0.6 tolerances of the curve.
_ONE_SIDED = 1.2
_BETWEEN = {0: np.array([0.5]), 1: np.linspace(0.0, 1.0, 26)[1:-1], 2: np.array([0.25, 0.5, 0.75]),
            3: np.array([0.5])}  # fmt: skip


def one_sided(rho, eta, rho_mid, eta_mid, material_outside: bool = False):
    """A sampled boundary (polar points ``rho, eta``; ``eta`` clockwise from +y, as
    :class:`gears.cutting.profile.ToothProfile` measures it) made one-sided: no chord adds material.

    ``rho_mid, eta_mid`` are points of the true curve between the ends of each chord (an array
    of one row per chord, one fewer than the points; a column per point). Where the curve
    bulges into the material beyond a chord (a concave piece: an
    external gear's fillet, every piece of a ring's toothed hole), the chord would put material
    where the true gear has none, and two gears in mesh at zero backlash would overlap by the
    chords: the vertices at its ends move into the material by :data:`_ONE_SIDED` times the
    sag, so the chord lies on or inside the true material. Convex pieces keep their vertices
    on the curve (their chords lie inside already). The first and last points (on the space
    and tooth centre lines) move radially, so the mirrored tooth stays symmetric.
    ``material_outside``: the material lies outside the boundary (a ring), not inside.
    """
    xy = np.stack([rho * np.sin(eta), rho * np.cos(eta)], axis=-1)
    rho_mid, eta_mid = np.asarray(rho_mid, float), np.asarray(eta_mid, float)
    if rho_mid.ndim == 1:
        rho_mid, eta_mid = rho_mid[:, None], eta_mid[:, None]
    mid = np.stack([rho_mid * np.sin(eta_mid), rho_mid * np.cos(eta_mid)], axis=-1)
    if len(xy) < 2:
        return rho, eta
    d = np.diff(xy, axis=0)
    length = np.hypot(d[:, 0], d[:, 1])
    left = np.stack([-d[:, 1], d[:, 0]], axis=-1) / np.where(length > 0, length, 1.0)[:, None]
    # the region between the boundary and the axis: its orientation says which side of the
    # boundary (walked root -> tip) it lies on; the material is that region, or (ring) not
    closed = np.vstack([[0.0, 0.0], xy])
    area = np.sum(closed[:, 0] * np.roll(closed[:, 1], -1) - np.roll(closed[:, 0], -1)
                  * closed[:, 1])  # fmt: skip
    into = left * (1.0 if (area > 0) != material_outside else -1.0)  # normals into the material
    # how far the curve reaches beyond each chord into the material: > 0, the chord adds some
    sag = np.max(np.einsum("ikj,ij->ik", mid - xy[:-1, None, :], into), axis=1)
    sag = np.where(length > 0, np.maximum(sag, 0.0), 0.0)  # > 0: the chord adds material
    if not np.any(sag > 0):
        return rho, eta
    move = np.zeros(len(xy))
    move[:-1] = np.maximum(move[:-1], sag)
    move[1:] = np.maximum(move[1:], sag)
    way = np.zeros_like(xy)
    way[:-1] += into
    way[1:] += into
    radial = xy / np.maximum(np.hypot(xy[:, 0], xy[:, 1]), 1e-300)[:, None]
    for k in (0, -1):  # on the symmetry lines: radially, towards the material
        way[k] = radial[k] * np.sign(np.dot(radial[k], way[k]) or 1.0)
    way /= np.maximum(np.hypot(way[:, 0], way[:, 1]), 1e-300)[:, None]
    xy = xy + (_ONE_SIDED * move)[:, None] * way
    return np.hypot(xy[:, 0], xy[:, 1]), np.arctan2(xy[:, 0], xy[:, 1])


def _point_segment_distance(q, a, b):
    ab = b - a
    den = np.einsum("ij,ij->i", ab, ab)
    t = np.clip(np.einsum("ij,ij->i", q - a, ab) / np.where(den > 0, den, 1.0), 0.0, 1.0)
    d = a + t[:, None] * ab - q
    return np.hypot(d[:, 0], d[:, 1])


def circle_segments(radius: float, tolerance: float) -> int:
    """Vertices of :func:`circle_points`."""
    return max(8, arc_segments(radius, 2 * math.pi, tolerance))


def circle_points(radius: float, tolerance: float, ccw: bool = True) -> np.ndarray:
    """A full circle sampled so that its sagitta stays below ``tolerance``: inscribed when
    counter-clockwise (an outer boundary: the chords lie inside the material), circumscribed
    when clockwise (a hole, such as a bore: its vertices at r / cos(pi / n), so its edges touch
    the circle and lie in the material; one-sided, as :func:`one_sided`)."""
    n = circle_segments(radius, tolerance)
    a = np.linspace(0.0, 2 * math.pi, n, endpoint=False)
    if not ccw:
        a = -a
        radius = radius / math.cos(math.pi / n)
    return radius * np.stack([np.cos(a), np.sin(a)], axis=-1)


def default_rim(gear) -> float:
    """Default rim width of an internal gear: 3 m_n outside its root circle."""
    return 3.0 * gear.module


def check_bore(bore, root_radius: float) -> float | None:
    """``bore`` (a diameter, mm) as a float within 0 < bore < the root diameter, or None."""
    if bore is None:
        return None
    bd = check_real("bore", bore, 0.0)
    if not 1e-6 * root_radius <= bd < 2 * root_radius:
        raise GearError(
            f"bore = {bore!r} mm; valid is {2e-6 * root_radius:.3g} <= bore < root diameter "
            f"{2 * root_radius:.6g} mm"
        )
    return bd


def check_blank(gear, bore, rim, root_radius: float) -> tuple[float | None, float | None]:
    """``bore`` (a hole in an external gear, :func:`check_bore`) and ``rim`` (a ring's width
    outside its roots, :func:`rim_width`) checked against the gear they are given for: a ring
    has no bore and an external gear no rim, so either given to the other is a
    :class:`GearError` rather than silently ignored. Returns (bore diameter or None, rim width
    or None)."""
    if gear.internal and bore is not None:
        raise GearError(
            f"bore = {bore!r}: a bore is a hole in an external gear; an internal gear (a ring) "
            "has none (its outer edge is set by rim=)"
        )
    if not gear.internal and rim is not None:
        raise GearError(
            f"rim = {rim!r}: a rim is a ring's width outside its tooth roots; an external gear "
            "has none (bore= makes a hole in it)"
        )
    if gear.internal:
        return None, rim_width(gear, rim)
    return check_bore(bore, root_radius), None


def assemble(gear, pts, tol, bore, rim, center, root_radius) -> shapely.Polygon:
    """Build the gear polygon from its toothed boundary ``pts`` (external disc or ring)."""
    cx, cy = center
    pts = pts + np.array([cx, cy])
    if gear.internal:
        outer = circle_points(root_radius + rim_width(gear, rim), tol) + np.array([cx, cy])
        poly = shapely.Polygon(outer, holes=[pts[::-1]])
    else:
        holes = []
        bd = check_bore(bore, root_radius)
        if bd is not None:
            holes.append(circle_points(bd / 2, tol, ccw=False) + np.array([cx, cy]))
        poly = shapely.Polygon(pts, holes=holes)
    if not poly.is_valid:
        raise GearError(
            f"the outline of z = {gear.teeth}, profile_shift = {gear.profile_shift:g} "
            "is not a valid polygon "
            f"({shapely.is_valid_reason(poly)}); the teeth may be cut away by undercut"
        )
    return poly
