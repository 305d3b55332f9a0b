"""Layer 4, envelopes and measurement.

Measurements on a tooth outline (any shapely Polygon), as a machinist would take them.

* :func:`thickness_on` - arc width of each tooth where a circle of diameter d cuts the outline
  (the exact intersection of every boundary edge with the circle, no sampling);
* :func:`undercut_depth` - how far each flank is cut in below the involute at the base circle;
* :func:`form_diameter_on` - the smallest diameter above which the measured thickness follows
  the involute formula within a tolerance.
"""

from __future__ import annotations

import math

import numpy as np
import shapely

from gears.errors import GearError

__all__ = ["form_diameter_on", "thickness_on", "undercut_depth"]


def _edges(polygon) -> np.ndarray:
    rings = [polygon.exterior, *polygon.interiors]
    out = []
    for ring in rings:
        c = np.asarray(ring.coords)
        out.append(np.stack([c[:-1], c[1:]], axis=1))
    return np.concatenate(out)


def thickness_on(outline, diameter: float, center=(0.0, 0.0)) -> np.ndarray:
    """Arc widths (mm, along the circle) of the material where the circle of ``diameter``
    about ``center`` crosses ``outline``, one per tooth, counter-clockwise from +x.

    Parameters
    ----------
    outline : shapely.Polygon
        A gear outline (external disc or internal ring).
    diameter : float
        Measuring circle, mm.
    center : (float, float)
        The gear axis.

    Returns
    -------
    ndarray
        Arc lengths of the material arcs (an uncut full circle gives one arc of length pi d).

    Examples
    --------
    >>> from gears import Gear
    >>> from gears.cutting.profile import outline
    >>> g = Gear(20, 1)
    >>> s = thickness_on(outline(g, 1e-4), g.reference_diameter)
    >>> len(s), round(float(s.mean()), 4), round(float(g.reference_thickness), 4)
    (20, 1.5707, 1.5708)
    """
    r = float(diameter) / 2
    if not (math.isfinite(r) and r > 0):
        raise GearError(f"diameter = {diameter!r}; valid is a finite number > 0")
    e = _edges(outline) - np.asarray(center, float)
    a, b = e[:, 0], e[:, 1]
    d = b - a
    qa = np.einsum("ij,ij->i", d, d)
    qb = 2 * np.einsum("ij,ij->i", a, d)
    qc = np.einsum("ij,ij->i", a, a) - r * r
    disc = qb * qb - 4 * qa * qc
    ok = (disc >= 0) & (qa > 0)
    sq = np.sqrt(np.where(ok, disc, 0.0))
    angles = []
    for sign in (-1.0, 1.0):
        t = (-qb + sign * sq) / np.where(ok, 2 * qa, 1.0)
        hit = ok & (t >= 0) & (t < 1)
        p = a[hit] + t[hit, None] * d[hit]
        angles.append(np.arctan2(p[:, 1], p[:, 0]))
    ang = np.unique(np.mod(np.concatenate(angles), 2 * math.pi))
    if ang.size < 2:
        inside = outline.contains(shapely.Point(center[0] + r, center[1]))
        return np.array([2 * math.pi * r]) if inside else np.array([])
    nxt = np.concatenate([ang[1:], ang[:1] + 2 * math.pi])
    mid = 0.5 * (ang + nxt)
    pts = shapely.points(center[0] + r * np.cos(mid), center[1] + r * np.sin(mid))
    shapely.prepare(outline)  # many points against one large polygon: index it once
    inside = shapely.contains(outline, pts)
    widths = (nxt - ang)[inside] * r
    return widths[np.argsort(np.mod(mid[inside], 2 * math.pi))]


def undercut_depth(outline, gear, center=(0.0, 0.0)) -> float:
    """Largest depth (mm, along the base circle, per flank) by which the outline's teeth are cut
    in below the involute at the base circle: (s_b,formula - s_b,measured) / 2; 0 or less when
    the base circle is not undercut."""
    db = gear.base_diameter
    s = thickness_on(outline, db * (1 + 1e-12), center)
    if s.size == 0:
        raise GearError("the outline has no material on the base circle")
    return float((gear.tooth_thickness(db * (1 + 1e-12)) - s.min()) / 2)


def form_diameter_on(outline, gear, tolerance: float, center=(0.0, 0.0), steps: int = 400):
    """Smallest diameter (mm) above which the thickness measured on ``outline`` matches the
    involute thickness within ``2 tolerance`` up to the tip (scanned at ``steps`` diameters
    from the base or root circle to the tip)."""
    lo = max(gear.base_diameter, gear.root_diameter) * (1 + 1e-9)
    hi = gear.tip_diameter
    if gear.internal:
        lo, hi = gear.tip_diameter, gear.root_diameter
    ds = np.linspace(lo, hi, steps)
    good = []
    for d in ds:
        s = thickness_on(outline, d, center)
        good.append(
            s.size == gear.teeth and abs(s.mean() - gear.tooth_thickness(d)) <= 2 * tolerance
        )
    good = np.array(good)
    if gear.internal:
        bad = np.flatnonzero(~good)
        return float(ds[bad[0] - 1]) if bad.size else float(hi)
    bad = np.flatnonzero(~good[:-1])
    return float(ds[bad[-1] + 1]) if bad.size else float(lo)
