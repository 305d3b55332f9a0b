"""Simulated generation: the cutter rolled over the blank, each position subtracted with shapely.

Two tools (standards.md §3.2; Ozols §21-6: Maag and Fellows methods; Joldasbekov §2.8):

* :func:`rack_outline` - the rack cutter (the basic rack's mirror image: straight flanks, tip
  land, tip rounds; optional protuberance) rolled on the reference circle of an external gear;
* :func:`shaper_outline` - a pinion-type (Fellows) cutter of ``cutter_teeth`` teeth, for internal
  gears and for external gears cut by a shaper.

One cutter tooth cuts one tooth space (the rolling is symmetric about the centred position, which
is always included so the root centre is exact); the space is the union of the tool positions,
patterned z times and subtracted from the blank (tip circle; for a ring, the annulus).

Accuracy comes from ``tolerance`` (mm), split over the three error sources measured in
standards.md §3.2:

* the flank scallop between two tool positions, h = rho_y dphi^2 / 8 (rho_y the involute's
  curvature radius where that position cuts) - so dphi is chosen *locally* from the contact
  point of each position (:func:`rack_positions`), O(1/N^2) overall;
* on the fillet, the scallop between two positions of the tip round, h = ds^2 / (8 rho_aP0);
* the root bump: consecutive positions of the tip land must overlap (dphi <= 2 u_c / r);
* the tool's own polygon: its tip rounds are sampled so the chord sag is <= tolerance / 4;
* the blank's tip circle is sampled as an arc (sagitta <= tolerance / 2), never as a chord
  across the tooth tip.
"""

from __future__ import annotations

import math

import numpy as np
import shapely

from gears.errors import GearError
from gears.profile import (
    ToothProfile,
    _check_tolerance,
    arc_segments,
    assemble,
    circle_points,
)

__all__ = ["rack_outline", "rack_positions", "rack_tool_polygon", "shaper_outline"]


def rack_tool_polygon(prof: ToothProfile, tolerance: float) -> np.ndarray:
    """One rack-cutter tooth in tool coordinates (u, v), closed counter-clockwise.

    The tip rounds are sampled so that their chord sag stays below ``tolerance / 4``; the
    flanks reach past the gear's tip circle.
    """
    t = prof.tool
    g = prof.gear
    rho_max = max(t.a, t.b)
    v_top = t.s * (abs(prof.ra - (t.r + t.xm)) + 0.5 * g.module) if t.s > 0 else None
    if t.s < 0:
        v_top = -(t.r + t.xm - prof.ra) - 0.5 * g.module
    right = []
    if rho_max > 0:
        span = t.t_f + math.pi / 2
        n = arc_segments(rho_max, span, tolerance / 4)
        tt = np.linspace(-math.pi / 2, t.t_f, n + 1)
        u, v, _, _ = t.round_points(tt)
        right.append(np.stack([u, v], axis=-1))
    else:
        right.append(np.array([[t.c - t.h * t.tan_a, -t.s * t.h]]))
    u_top = t.c + t.s * v_top * t.tan_a
    right.append(np.array([[u_top, v_top]]))
    r = np.concatenate(right)
    if t.u_c > 0:
        r = np.concatenate([[[0.0, -t.s * t.h]], r])
    left = r[::-1] * np.array([-1.0, 1.0])
    ring = np.concatenate([left[:-1], r]) if t.u_c <= 0 else np.concatenate([left[:-1], r[1:]])
    if t.s < 0:
        ring = ring[::-1]
    return ring


def rack_positions(prof: ToothProfile, tolerance: float) -> np.ndarray:
    """Roll angles (rad) of the tool positions: symmetric, including 0, spaced locally so that
    every scallop stays below ``0.35 tolerance`` (see the module docstring)."""
    t = prof.tool
    e = 0.35 * tolerance
    rb = prof.rb
    # analytic contact points of the right tool half: fillet (round) and flank up to the tip
    tau = np.linspace(0.0, 1.0, 200)
    samples_phi, samples_dphi = [], []
    if t.a > 0:
        rho_f, eta_f, phi_f = prof.fillet(tau)
        xy = np.stack([rho_f * np.sin(eta_f), rho_f * np.cos(eta_f)], axis=-1)
        ds = np.hypot(*np.gradient(xy, axis=0).T)
        dphi = np.abs(np.gradient(phi_f))
        speed = np.maximum(ds / np.where(dphi > 0, dphi, np.inf), 1e-300)
        rho_tool = t.b * t.b / t.a if t.a >= t.b else t.a * t.a / t.b
        samples_phi.append(phi_f)
        samples_dphi.append(np.sqrt(8.0 * e * rho_tool) / speed)
    v_lo = min(t.v_f, prof.v_limit) if t.s > 0 else t.v_f
    # flank heights up to the tip (the flank maps monotonically to the involute)
    v_hi = t.s * 3.0 * prof.gear.module
    v = np.linspace(v_lo, v_hi, 400)
    u, vv, nu, nv = t.flank_points(v)
    rho_i, _, phi_i = t.envelope(u, vv, nu, nv)
    keep = (rho_i <= prof.ra) if t.s > 0 else (rho_i >= prof.ra)
    keep[0] = True
    rho_i, phi_i = rho_i[keep], phi_i[keep]
    curv = np.sqrt(np.maximum(rho_i * rho_i - rb * rb, 0.0))  # involute curvature radius
    samples_phi.append(phi_i)
    samples_dphi.append(np.sqrt(8.0 * e / np.maximum(curv, 1e-3 * prof.gear.module)))
    phis = np.concatenate(samples_phi)
    dphis = np.concatenate(samples_dphi)
    # one step past the last contact sample so the tip corner is cut completely
    dphis = np.minimum(dphis, math.pi / (4 * prof.z))
    phi_max = float(np.max(np.abs(phis)))
    # the left flank is the mirror image: requirement at phi is the min over +-phi
    grid = np.linspace(0.0, phi_max, 513)
    need = np.full(grid.shape, np.inf)
    idx = np.clip(np.searchsorted(grid, np.abs(phis)), 0, len(grid) - 1)
    np.minimum.at(need, idx, dphis)
    land = 2.0 * t.u_c / t.r
    if land > 0:
        need = np.where(grid <= 2.0 * land + t.u_c / t.r, np.minimum(need, land), need)
    finite = np.isfinite(need)
    need = np.interp(grid, grid[finite], need[finite])
    # a requirement holds over the step around it: take the running min over one step
    need = np.minimum(need, np.concatenate([need[1:], need[-1:]]))
    density = 1.0 / need
    cum = np.concatenate([[0.0], np.cumsum(0.5 * (density[1:] + density[:-1]) * np.diff(grid))])
    n = max(1, math.ceil(cum[-1]))
    half = np.interp(np.linspace(0.0, cum[-1], n + 1), cum, grid)
    # one step past the last contact sample so the tip corner is cut completely
    half = np.append(half, phi_max + need[-1])
    return np.concatenate([-half[:0:-1], half])


def _space(prof: ToothProfile, tolerance: float) -> shapely.Polygon:
    """Union of all rack-tool positions: one tooth space, centred on +y."""
    t = prof.tool
    tool = rack_tool_polygon(prof, tolerance)
    phis = rack_positions(prof, tolerance)
    c, s = np.cos(phis)[:, None], np.sin(phis)[:, None]
    x0 = tool[None, :, 0] + t.r * phis[:, None]
    y0 = t.r + t.xm + tool[None, :, 1]
    rings = np.stack([c * x0 - s * y0, s * x0 + c * y0], axis=-1)
    return shapely.union_all(shapely.polygons(rings))


def _pattern(space, z: int, angle: float):
    """Rotate a space (centred on +y) so it lies between tooth 0 (at ``angle``) and tooth 1,
    then repeat it around the gear."""
    step = 2 * math.pi / z
    first = angle + step / 2 - math.pi / 2
    coords = shapely.get_coordinates(space.exterior)
    rings = []
    for k in range(z):
        a = first + k * step
        c, s = math.cos(a), math.sin(a)
        x = c * coords[:, 0] - s * coords[:, 1]
        rings.append(np.stack([x, s * coords[:, 0] + c * coords[:, 1]], -1))
    return shapely.polygons(rings)


def rack_outline(
    gear, tolerance: float = 0.001, backlash: float = 0.0, bore: float | None = None,
    angle: float = 0.0, center=(0.0, 0.0),
) -> shapely.Polygon:  # fmt: skip
    """Outline of an external ``gear`` cut by its rack cutter (simulated generation).

    Parameters are those of :func:`gears.profile.outline`. The result reproduces the undercut
    and pointed tips exactly as the tool leaves them; it agrees with the analytic outline within
    the tolerance (tests/gears/test_generate.py).

    Raises
    ------
    GearError
        For an internal gear (a rack cannot cut a ring).

    Examples
    --------
    >>> from gears import Gear
    >>> p = rack_outline(Gear(20, 1), tolerance=0.01)
    >>> p.is_valid, round(p.area / (math.pi * 10**2), 2)
    (True, 0.98)
    """
    tol = _check_tolerance(tolerance)
    if gear.internal:
        raise GearError(
            "a rack cutter cannot generate an internal gear; use method='analytic' (the "
            "rack-limit outline of a shaper-cut ring)"
        )
    prof = ToothProfile(gear, backlash)
    space = _space(prof, tol)
    if space.geom_type != "Polygon":
        raise GearError(f"z = {gear.teeth}: the simulated tooth space is not one piece")
    blank = shapely.Polygon(circle_points(prof.ra, tol / 2))
    # keep only the part of the space inside a slightly larger tip disc: cheaper unions
    space = space.intersection(shapely.Polygon(circle_points(prof.ra + 0.1 * gear.module, tol)))
    spaces = _pattern(space, gear.teeth, math.radians(angle))
    cut = blank.difference(shapely.union_all(spaces))
    if cut.geom_type != "Polygon":
        raise GearError(
            f"z = {gear.teeth}, x = {gear.profile_shift:g}: the cut gear falls apart "
            f"({cut.geom_type}); the teeth are cut away"
        )
    pts = np.asarray(cut.exterior.coords)[:-1]
    if not shapely.LinearRing(pts).is_ccw:
        pts = pts[::-1]
    return assemble(gear, pts, tol, bore, None, center, prof.rf)


def shaper_outline(gear, tolerance: float = 0.001, backlash: float = 0.0, **kwargs):
    """Pinion-type (Fellows) cutter simulation - not available in this version.

    Raises
    ------
    GearError
        Always; use ``method='analytic'`` (internal gears: the rack-limit outline of
        :mod:`gears.profile`) or ``method='rack'`` for external gears.
    """
    raise GearError(
        "shaper-cutter simulation is not implemented yet; use method='analytic' (internal "
        "gears: the rack-limit outline) or method='rack' (external gears)"
    )
