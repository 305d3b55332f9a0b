"""Layer 3, conjugate: the geometric transmission error of any two outlines, the profile
conjugate to a given one (the envelope by inversion), and the meshing-theorem check.

* :func:`transmission_error`: two outlines turned about fixed centres; for each input angle the
  angle gear 2 can lag behind its nominal position before one of its flanks meets gear 1's (the
  driving flank pair), measured along circles about gear 2's centre, vertex against edge both
  ways: zero, to the outlines' tolerance, for a conjugate pair at zero backlash.
* :func:`conjugate`: the profile on gear 2 enveloped by a profile on gear 1 as the centrodes
  roll (Ozols section 19-2, the inversion method: gear 2 held still, gear 1 turned about it); a
  point of the profile is in contact where its normal passes through the pole (the Willis
  theorem, Ozols 19-2; Joldasbekov section 5).
* :func:`normal_miss`: how far the common normal at a contact point misses the pole (the
  meshing theorem's residual, mm) for any two profiles.

Angles in degrees at the interface; lengths mm.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import NamedTuple

import numpy as np
import shapely
from numpy.typing import ArrayLike
from shapely import affinity

from gears.arguments import check_choice, check_integer, check_point, check_real
from gears.errors import GearError

__all__ = ["MAX_TE_WORK", "Conjugate", "conjugate", "normal_miss", "transmission_error"]

#: The most vertex-edge tests one transmission-error call makes (angles x vertices x edges in
#: the mesh zone), about 10 s on one core.
MAX_TE_WORK = 2_000_000_000


def _rings(poly) -> list[np.ndarray]:
    """The rings of a polygon, exterior counter-clockwise and holes clockwise, as (n, 2)."""
    poly = shapely.orient_polygons(poly) if hasattr(shapely, "orient_polygons") else (
        shapely.geometry.polygon.orient(poly, 1.0))  # fmt: skip
    return [np.asarray(poly.exterior.coords)] + [np.asarray(h.coords) for h in poly.interiors]


def _segments(poly) -> tuple[np.ndarray, np.ndarray]:
    starts, ends = [], []
    for ring in _rings(poly):
        starts.append(ring[:-1])
        ends.append(ring[1:])
    return np.concatenate(starts), np.concatenate(ends)


def _rotate(points: np.ndarray, angle: float, center: np.ndarray) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    d = points - center
    return center + np.stack([c * d[:, 0] - s * d[:, 1], s * d[:, 0] + c * d[:, 1]], axis=-1)


def _gaps(q, a, b, center, sense):
    """For each point q (M, 2): the angle (rad) it may travel about ``center`` in the sense
    ``sense`` (+1 counter-clockwise) before it enters the polygon whose edges are a -> b
    (counter-clockwise exterior), measured along its circle; negative (the way back to the
    entry) for a point already inside; inf where its circle meets no edge. Inside or outside
    is read from the same crossings (the nearest one ahead is an exit for a point inside), so a
    point on the boundary is decided consistently; a point inside nearer the exit ahead than
    the entry behind has come in through the other flank and counts by the next entry."""
    rel_q = q - center
    rho2 = np.sum(rel_q**2, axis=1)[:, None]
    theta_q = np.arctan2(rel_q[:, 1], rel_q[:, 0])[:, None]
    p0 = a - center
    d = b - a
    qa = np.sum(d * d, axis=1)[None, :]
    qb = 2.0 * np.sum(p0 * d, axis=1)[None, :]
    qc = np.sum(p0 * p0, axis=1)[None, :] - rho2
    disc = qb * qb - 4.0 * qa * qc
    ok = (disc >= 0) & (qa > 0)
    root = np.sqrt(np.where(ok, disc, 0.0))
    gaps, entries = [], []
    for sign in (-1.0, 1.0):
        t = (-qb + sign * root) / (2.0 * np.where(qa > 0, qa, 1.0))
        hit = ok & (t >= 0.0) & (t < 1.0)
        theta = np.arctan2(p0[None, :, 1] + t * d[None, :, 1], p0[None, :, 0] + t * d[None, :, 0])
        # moving along the circle in the given sense enters the polygon where the tangent
        # points to the left of the edge (the interior side of a counter-clockwise ring)
        tau_x, tau_y = -np.sin(theta) * sense, np.cos(theta) * sense
        entries.append((d[None, :, 0] * tau_y - d[None, :, 1] * tau_x) > 0)
        gap = np.mod(sense * (theta - theta_q) + math.pi, 2.0 * math.pi) - math.pi
        gaps.append(np.where(hit, gap, np.nan))
    gap = np.concatenate(gaps, axis=1)
    enters = np.concatenate(entries, axis=1)
    ahead = np.where(gap > 0, gap, np.inf)
    first = np.argmin(ahead, axis=1)
    rows = np.arange(q.shape[0])
    has_ahead = np.isfinite(ahead[rows, first])
    inside = has_ahead & ~enters[rows, first]
    best_pos = np.min(np.where(enters & (gap > 0), gap, np.inf), axis=1)
    best_neg = np.max(np.where(gap <= 0, gap, -np.inf), axis=1)
    # a point inside that is nearer the exit ahead than the entry behind has crossed the other
    # flank (the coast side, at zero backlash): travelling on frees it, so the next entry counts
    coast = inside & (ahead[rows, first] < -best_neg)
    return np.where(inside & ~coast, best_neg, best_pos)


def _least_gap(q, other, a, b, center, sense, first: int = 48) -> float:
    """The least of :func:`_gaps` over the points q, evaluated on the few nearest ``other`` (its
    edges a -> b) first: a point at distance d from it travels at least d / rho (rad) on its
    circle of radius rho before it can touch, so the rest need no test once that bound exceeds
    the least found. The distance is bounded below by the nearest edge end's less half the
    longest edge; points inside ``other`` are always tested."""
    from scipy.spatial import cKDTree  # heavy: imported where used

    if q.shape[0] == 0 or a.shape[0] == 0:
        return math.inf
    shapely.prepare(other)
    inside = shapely.contains_xy(other, q[:, 0], q[:, 1])
    half = 0.5 * float(np.max(np.hypot(*(b - a).T)))
    dist = np.maximum(cKDTree(a).query(q)[0] - half, 0.0)
    dist[inside] = 0.0
    order = np.argsort(dist)
    best = float(np.min(_gaps(q[order[:first]], a, b, center, sense)))
    rest = order[first:]
    rho = np.hypot(*(q[rest] - center).T)
    bound = max(best, 0.0) if math.isfinite(best) else math.inf
    cand = rest[dist[rest] <= bound * rho * (1.0 + 1e-9) + 1e-12]
    for chunk in np.array_split(cand, max(1, cand.size // 4096 + 1)):
        if chunk.size:
            best = min(best, float(np.min(_gaps(q[chunk], a, b, center, sense))))
    return best


def transmission_error(
    outline1: shapely.Polygon, outline2: shapely.Polygon,
    centers: tuple[tuple[float, float], tuple[float, float]], angles: ArrayLike,
    output: float | Callable, *, kind: str = "external",
) -> np.ndarray:  # fmt: skip
    """The geometric transmission error of two outlines turned about fixed centres, degrees of
    gear 2 (its actual angle minus the nominal, in its sense of rotation: negative lags).

    Parameters
    ----------
    outline1, outline2 : shapely.Polygon
        The gears as placed at input angle 0 (in the fixed frame).
    centers : ((x1, y1), (x2, y2))
        Their centres, mm.
    angles : array_like
        Gear 1's angles, degrees (counter-clockwise).
    output : float or callable
        Gear 2's nominal angle at each input angle, degrees in its own sense of rotation: a
        callable psi(phi), or a number, the constant ratio omega1/omega2 (psi = phi / ratio).
    kind : "external" or "internal"
        Gear 2 turns against gear 1 (external) or with it (internal).

    The driven gear sits where the driver's flanks push it: at each angle, gear 2 is turned
    back (against its rotation) until a flank of it meets one of gear 1's; a conjugate pair at
    zero backlash gives zero, to the outlines' tolerance.

    Raises
    ------
    GearError
        For outlines that are not polygons, an angle where they do not mesh, or work over
        :data:`MAX_TE_WORK`.
    """
    kind = check_choice("kind", kind, ("external", "internal"))
    for name, poly in (("outline1", outline1), ("outline2", outline2)):
        if not isinstance(poly, shapely.Polygon) or poly.is_empty or not poly.is_valid:
            raise GearError(f"{name} = {type(poly).__name__}; valid is a non-empty, valid "
                            "shapely Polygon")  # fmt: skip
    if not (isinstance(centers, tuple | list) and len(centers) == 2):
        raise GearError(f"centers = {centers!r}; valid is ((x1, y1), (x2, y2)) in mm")
    c1 = np.array(check_point("centers[0]", centers[0]))
    c2 = np.array(check_point("centers[1]", centers[1]))
    phi = _array("angles", angles)
    if phi.ndim != 1 or phi.size == 0 or phi.size > 100_000 or not np.all(np.isfinite(phi)):
        raise GearError("angles must be 1 ... 100000 finite angles in degrees (a 1-D array)")
    psi = _array("output", _output_law(output)(phi)) * np.ones_like(phi)
    if psi.shape != phi.shape or not np.all(np.isfinite(psi)):
        raise GearError("output gave an angle that is not finite; valid are finite degrees")
    sense = -1.0 if kind == "external" else 1.0
    a1, b1 = _segments(outline1)
    a2, b2 = _segments(outline2)
    v1, v2 = a1, a2
    reach2 = float(np.max(np.hypot(*(v2 - c2).T)))
    reach1 = float(np.max(np.hypot(*(v1 - c1).T)))
    out = np.empty(phi.size)
    for k, (f, p) in enumerate(zip(np.radians(phi), np.radians(psi), strict=True)):
        q1 = _rotate(v1, f, c1)
        q2 = _rotate(v2, sense * p, c2)
        # only vertices within reach of the other gear can touch it
        near1 = np.hypot(*(q1 - c2).T) <= reach2
        near2 = np.hypot(*(q2 - c1).T) <= reach1
        if k == 0:
            work = phi.size * 2 * int(near1.sum()) * int(near2.sum())
            if work > MAX_TE_WORK:
                raise GearError(
                    f"the transmission error over {phi.size} angles would take {work:.3g} "
                    f"vertex-edge tests, over the budget of {MAX_TE_WORK:.3g}: use fewer angles "
                    "or coarser outlines"
                )
        # the edges within reach of the other gear (either end) are the only ones it can meet
        e1a, e1b = q1, _rotate(b1, f, c1)
        e2a, e2b = q2, _rotate(b2, sense * p, c2)
        keep1 = near1 | (np.hypot(*(e1b - c2).T) <= reach2)
        keep2 = near2 | (np.hypot(*(e2b - c1).T) <= reach1)
        e1a, e1b, e2a, e2b = e1a[keep1], e1b[keep1], e2a[keep2], e2b[keep2]
        placed1 = affinity.rotate(outline1, f, origin=tuple(c1), use_radians=True)
        placed2 = affinity.rotate(outline2, sense * p, origin=tuple(c2), use_radians=True)
        g1 = _least_gap(q1[near1], placed2, e2a, e2b, c2, sense)
        # gear 2's vertices travel backwards (against its sense) into gear 1
        g2 = _least_gap(q2[near2], placed1, e1a, e1b, c2, -sense)
        gap = min(g1, g2)
        if not math.isfinite(gap):
            raise GearError(f"the outlines do not mesh at the input angle {math.degrees(f):g} deg")
        out[k] = -math.degrees(gap)
    return out


class Conjugate(NamedTuple):
    """What :func:`conjugate` finds: the conjugate points (n, 2) in gear 2's frame, the input
    angle of each contact (degrees), the meshing theorem's residual there (mm), and the index of
    each in the given profile."""

    points: np.ndarray
    angles: np.ndarray
    miss: np.ndarray
    index: np.ndarray


def _array(name: str, value) -> np.ndarray:
    """``value`` as a float array, or a GearError naming it."""
    try:
        return np.atleast_1d(np.asarray(value, dtype=float))
    except (TypeError, ValueError):
        raise GearError(f"{name} = {value!r}; valid are finite numbers (an array)") from None


def normal_miss(points, normals, pole):
    """The distance (mm) by which the normal line through each contact point misses the pole
    (arrays (..., 2), broadcast): zero where the meshing theorem (Willis, Ozols 19-2) holds.
    A zero normal is refused."""
    x, n, p = (_array("points", points), _array("normals", normals), _array("pole", pole))
    length = np.hypot(n[..., 0], n[..., 1])
    if not np.all(length > 0) or not (np.all(np.isfinite(x)) and np.all(np.isfinite(p))):
        raise GearError("normal_miss needs finite points and pole and non-zero normals")
    unit = n / length[..., None]
    d = p - x
    return np.abs(unit[..., 0] * d[..., 1] - unit[..., 1] * d[..., 0])


def _output_law(output) -> Callable:
    """psi(phi) in degrees from a callable (its errors reported as ours) or a constant ratio."""
    if callable(output):

        def law(phi):
            try:
                return np.asarray(output(phi), dtype=float)
            except GearError:
                raise
            except Exception as exc:
                raise GearError(f"output = {output!r} failed at the input angles: {exc}") from None

        return law
    ratio = check_real("output", output, 0.0)
    return lambda phi: np.asarray(phi, dtype=float) / ratio


def conjugate(
    profile: ArrayLike, center_distance: float, output: float | Callable, *, kind: str = "external",
    window: tuple[float, float] = (-120.0, 120.0), steps: int = 2400,
) -> Conjugate:  # fmt: skip
    """The profile on gear 2 conjugate to ``profile`` on gear 1 (Ozols 19-2: the envelope by
    inversion; contact where the profile's normal passes through the pole).

    Parameters
    ----------
    profile : (n, 2) array
        Points of gear 1's profile in order along it, mm, as placed at input angle 0 (O1 at the
        origin, O2 at (center_distance, 0)).
    center_distance : float
        mm.
    output : float or callable
        Gear 2's angle psi(phi) in degrees (its own sense of rotation), or the constant ratio
        omega1/omega2. The pole at each angle follows from its derivative (Ozols (19.2)).
    kind : "external" or "internal"
    window, steps
        The input angles searched for each point's contact (degrees) and the grid's size.

    Returns
    -------
    Conjugate
        ``points``: the conjugate points in gear 2's frame as placed at input angle 0, for the
        profile's points that pass the pole within ``window`` (``index``: which ones);
        ``angles``: the input angle of each contact (degrees); ``miss``: how far the normal
        misses the pole there (mm: the meshing theorem's residual, zero but for the root
        finding).
    """
    kind = check_choice("kind", kind, ("external", "internal"))
    a = check_real("center_distance", center_distance, 0.0)
    pts = _array("profile", profile)
    if pts.ndim != 2 or pts.shape[1] != 2 or not 3 <= pts.shape[0] <= 1_000_000:
        raise GearError("profile must be an (n, 2) array of 3 ... 1000000 points (mm)")
    if not np.all(np.isfinite(pts)):
        raise GearError("profile has a point that is not finite")
    if not (isinstance(window, tuple | list) and len(window) == 2):
        raise GearError(f"window = {window!r}; valid is (low, high) in degrees")
    lo = check_real("window[0]", window[0], -3600.0, 3600.0)
    hi = check_real("window[1]", window[1], lo, 3600.0)
    n = check_integer("steps", steps, 3, 1_000_000)
    if n * pts.shape[0] > 50_000_000:
        raise GearError(
            f"steps x points = {n * pts.shape[0]:.3g}, over the budget of 5e7 residuals: use "
            "fewer steps or points"
        )
    law = _output_law(output)
    sense = -1.0 if kind == "external" else 1.0
    normals = np.gradient(pts, axis=0) @ np.array([[0.0, -1.0], [1.0, 0.0]])  # tangent turned
    if not np.all(np.hypot(normals[:, 0], normals[:, 1]) > 0.0):
        raise GearError("profile has repeated points: its normal is undefined there")
    with np.errstate(all="ignore"):  # a law with psi' = 0 puts the pole at infinity: no root
        return _envelope(pts, normals, a, law, kind, sense, lo, hi, n)


def _envelope(pts, normals, a, law, kind, sense, lo, hi, n):
    """The conjugate's points (:func:`conjugate`, its arguments checked)."""

    def pole(phi_deg):
        """The pole's x (on O1O2) at the input angles (Ozols (19.2), the ratio from psi')."""
        h = 1e-4
        dpsi = (np.asarray(law(phi_deg + h)) - np.asarray(law(phi_deg - h))) / (2.0 * h)
        ratio = 1.0 / dpsi  # omega1/omega2
        if kind == "external":
            return a / (1.0 + ratio)
        r1 = a / np.abs(1.0 - ratio)
        return np.where(ratio > 1.0, -r1, r1)  # inside a ring gear 2, or beyond O2

    def residual(phi_deg, p, nrm):  # broadcast: angles against points
        t = np.radians(phi_deg)
        c, s = np.cos(t), np.sin(t)
        x = c * p[..., 0] - s * p[..., 1]
        y = s * p[..., 0] + c * p[..., 1]
        nx = c * nrm[..., 0] - s * nrm[..., 1]
        ny = s * nrm[..., 0] + c * nrm[..., 1]
        return nx * (0.0 - y) - ny * (pole(phi_deg) - x)

    grid = np.linspace(lo, hi, n)
    f = residual(grid[:, None], pts[None], normals[None])
    change = np.sign(f[:-1]) * np.sign(f[1:]) <= 0
    # the crossing nearest the input angle 0 for each point
    idx = np.where(change, np.abs(grid[:-1, None]), np.inf)
    k = np.argmin(idx, axis=0)
    found = np.isfinite(idx[k, np.arange(pts.shape[0])])
    x0, x1 = grid[k], grid[k + 1]
    cols = np.arange(pts.shape[0])
    f0, f1 = f[k, cols], f[k + 1, cols]
    for _ in range(40):  # bracketed secant (Illinois) on each point's own residual
        xm = np.where(f1 != f0, x1 - f1 * (x1 - x0) / np.where(f1 != f0, f1 - f0, 1.0), x0)
        fm = residual(xm, pts, normals)
        left = np.sign(fm) == np.sign(f0)
        x0, f0, x1, f1 = (np.where(left, xm, x0), np.where(left, fm, f0 * 0.5),
                          np.where(left, x1, xm), np.where(left, f1 * 0.5, fm))  # fmt: skip
        x0, x1 = np.minimum(x0, x1), np.maximum(x0, x1)
        if np.all(np.abs(x1 - x0) < 1e-11):
            break
    found &= np.isfinite(xm) & np.isfinite(f0) & np.isfinite(f1)
    phi = np.where(found, xm, np.nan)
    t = np.radians(np.where(found, phi, 0.0))
    c, s = np.cos(t), np.sin(t)
    x = np.stack([c * pts[:, 0] - s * pts[:, 1], s * pts[:, 0] + c * pts[:, 1]], axis=-1)
    nrm = np.stack([c * normals[:, 0] - s * normals[:, 1], s * normals[:, 0] + c * normals[:, 1]],
                   axis=-1)  # fmt: skip
    p = np.stack([pole(np.where(found, phi, 0.0)), np.zeros(pts.shape[0])], axis=-1)
    unit = nrm / np.hypot(nrm[:, 0], nrm[:, 1])[:, None]
    miss = np.abs(unit[:, 0] * (p - x)[:, 1] - unit[:, 1] * (p - x)[:, 0])
    psi = np.radians(np.asarray(law(np.where(found, phi, 0.0)), dtype=float))
    back = -sense * psi  # gear 2 turned back to its placement at input angle 0
    cb, sb = np.cos(back), np.sin(back)
    dx, dy = x[:, 0] - a, x[:, 1]
    out = np.stack([a + cb * dx - sb * dy, sb * dx + cb * dy], axis=-1)
    found &= np.all(np.isfinite(out), axis=1) & np.isfinite(miss)
    return Conjugate(out[found], phi[found], miss[found], np.flatnonzero(found))
