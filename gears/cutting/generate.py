"""Layer 5, simulated cutting.

The cutter rolled over the blank, each position subtracted with shapely.

Two tools (Ozols §21-6: Maag and Fellows methods; Joldasbekov §2.8):

* :func:`rack_outline` - the rack cutter (the basic rack's mirror image: straight flanks, tip
  land, tip rounds) rolled on the reference circle of an external gear;
* :func:`shaper_outline` - a pinion-type (Fellows) cutter of ``cutter_teeth`` teeth, for internal
  gears and for external gears cut by a shaper.

One cutter tooth cuts one tooth space (the rolling is symmetric about the centred position, which
is always included so the root centre is exact); the space is the union of the tool positions,
patterned z times and subtracted from the blank (tip circle; for a ring, the annulus).

Accuracy comes from ``tolerance`` (mm), split over the three error sources measured
here (docs/performance.md):

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

from gears.arguments import check_angle, check_callback, check_point, check_tolerance
from gears.budget import BUDGETS, check_budget
from gears.cutting.measure import thickness_on
from gears.cutting.profile import ShaperProfile, ToothProfile
from gears.cutting.sampling import (
    _refuse_protuberance,
    arc_segments,
    assemble,
    check_blank,
    circle_points,
    involute_rolls,
)
from gears.errors import GearError

__all__ = [
    "rack_outline",
    "rack_positions",
    "rack_tool_polygon",
    "shaper_outline",
    "shaper_positions",
    "shaper_tool_polygon",
]


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


def _rack_need(prof: ToothProfile, tolerance: float) -> tuple[np.ndarray, np.ndarray]:
    """The largest roll step allowed on a grid of roll angles ``0 ... phi_max`` (inf where
    nothing constrains it): the scallop rules of :func:`rack_positions`."""
    t = prof.tool
    e = 0.35 * tolerance
    rb = prof.rb
    # analytic contact points of the right tool half: fillet (round) and flank up to the tip
    tau = np.linspace(0.0, 1.0, 200)
    samples_phi, samples_dphi = [], []
    phi_f, speed = _fillet_speed(prof, tau)
    rho_tool = 0.0 if t.a == 0 else (t.b * t.b / t.a if t.a >= t.b else t.a * t.a / t.b)
    step = _fillet_step(e, rho_tool) / np.maximum(speed, 1e-300)
    if t.a > 0:  # where the round is nearly stamped, its centre's travel sets the scallop
        tt = -math.pi / 2 + tau * (t.t_f + math.pi / 2)
        u, v, nu, nv = t.round_points(tt)
        lam = -(v + t.xm) * np.hypot(nu, nv) / np.where(nv != 0, nv, np.inf)  # to I
        centre = np.abs(lam + rho_tool)  # the curvature centre's travel per radian of roll
        stamped = speed > _STAMPED**2 * centre
        relaxed = _fillet_step(e, rho_tool) / np.sqrt(np.maximum(speed * centre, 1e-300))
        step = np.where(stamped, relaxed / _STAMPED, step)
    samples_phi.append(phi_f)
    samples_dphi.append(step)
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
    return grid, need


def rack_positions(prof: ToothProfile, tolerance: float) -> np.ndarray:
    """Roll angles (rad) of the tool positions: symmetric, including 0, spaced locally so that
    every scallop stays below ``0.35 tolerance`` (see the module docstring).

    On the tip round the scallop between two positions is ``d_C d_E / (8 rho_t)``: ``d_C`` the
    travel of the round's curvature centre (``|lambda + rho_t|`` per radian, lambda the
    distance from the contact point to the pitch point along the normal), ``d_E`` that of the
    generated point, ``rho_t`` the round's curvature radius. The rule used is the stricter
    ``d_E^2 / (8 rho_t)``, except where the round is nearly stamped (``d_E > 16 d_C``: its
    centre rolls on the pitch line, and the whole fillet is cut at almost one position), where
    ``d_E`` alone would ask for endless positions: there ``d_C d_E`` with a factor 4 of
    safety.
    """
    grid, need = _rack_need(prof, tolerance)
    half, step = _spread(grid, need)
    # one step past the last contact sample so the tip corner is cut completely
    half = np.append(half, grid[-1] + step)
    return np.concatenate([-half[:0:-1], half])


#: How much faster than its round's curvature centre the generated fillet point may run before
#: the round counts as stamped (see :func:`rack_positions`).
_STAMPED = 4.0


def _fillet_speed(prof, tau):
    """Roll angles of the fillet points at ``tau`` and the speed ds/dphi of the generated point
    (finite differences; 0 where the roll angle stands still)."""
    rho, eta, phi = prof.fillet(tau)
    xy = np.stack([rho * np.sin(eta), rho * np.cos(eta)], axis=-1)
    ds = np.hypot(*np.gradient(xy, axis=0).T)
    dphi = np.abs(np.gradient(phi))
    return phi, ds / np.where(dphi > 0, dphi, np.inf)


def _fillet_step(e: float, rho: float) -> float:
    """Largest travel of the generated fillet point between two tool positions for a scallop
    <= e: sqrt(8 e rho) for a tip round of radius rho; a sharp tool corner leaves a notch of up
    to half its travel (two edges meeting at <= 90 deg beside the chord), so 2 e - the notch
    error falls only as 1/N there."""
    return max(math.sqrt(8.0 * e * rho), 2.0 * e)


def _need_on_grid(grid: np.ndarray, need: np.ndarray) -> np.ndarray:
    """The requirement between grid points (the smaller neighbour), interpolated over gaps."""
    finite = np.isfinite(need)
    need = np.interp(grid, grid[finite], need[finite])
    return np.minimum(need, np.concatenate([need[1:], need[-1:]]))


def _count(grid: np.ndarray, need: np.ndarray) -> float:
    """About how many angles :func:`_spread` places: the integral of 1 / need, before the
    positions are placed (for the budget)."""
    if not np.isfinite(need).any():
        return 2.0
    n = _need_on_grid(grid, need)
    return float(np.sum(np.diff(grid) / n[:-1])) + 2.0


def _spread(grid: np.ndarray, need: np.ndarray) -> tuple[np.ndarray, float]:
    """Angles from 0 to ``grid[-1]`` whose spacing stays below ``need`` (given on ``grid``; inf
    where nothing constrains it) everywhere within each step, and the spacing needed at the end.

    Greedy: from each angle take the largest step that does not exceed the requirement anywhere
    inside it (a requirement that dips within a step shortens it).
    """
    if not np.isfinite(need).any():
        return np.array([0.0, grid[-1]]), float(grid[-1])
    need = _need_on_grid(grid, need)
    end = float(grid[-1])
    out = [0.0]
    phi = 0.0
    while phi < end:
        i = min(int(np.searchsorted(grid, phi, side="right")) - 1, len(grid) - 1)
        step = float(need[i])
        for _ in range(50):
            j = int(np.searchsorted(grid, phi + step, side="right"))
            m = float(need[i : max(j, i + 1)].min())
            if m >= step * (1 - 1e-12):
                break
            step = m
        phi = min(phi + step, end)
        if end - phi < 1e-3 * step:
            phi = end
        out.append(phi)
    return np.array(out), float(need[-1])


#: Largest simulation, in vertex operations (:func:`simulation_work`): the ``"simulation"``
#: budget of :data:`gears.budget.BUDGETS` (docs/profiles.md, "Bounded work").
MAX_PLACED_VERTICES = BUDGETS["simulation"]
_UNION_CHUNKS = 32


def _union_positions(tool, phis, place, progress=None) -> shapely.Polygon:
    """Union of the tool polygon ``tool`` placed at the angles ``phis`` (``place(tool, phis)``),
    in chunks of positions so memory stays bounded; ``progress(done, total)`` after each chunk."""
    chunks = np.array_split(np.asarray(phis), min(_UNION_CHUNKS, len(phis)))
    parts = []
    for i, chunk in enumerate(chunks):
        parts.append(shapely.union_all(shapely.polygons(place(tool, chunk))))
        if progress is not None:
            progress(i + 1, len(chunks))
    return shapely.union_all(parts)


def _space(prof: ToothProfile, tolerance: float, progress=None) -> shapely.Polygon:
    """Union of all rack-tool positions: one tooth space, centred on +y; refused over the
    simulation budget before any position is placed."""
    what = f"the rack simulation of z = {prof.z}"
    check_budget("simulation", what, lambda t: _rack_work(prof, t), tolerance)
    tool = rack_tool_polygon(prof, tolerance)
    phis = rack_positions(prof, tolerance)
    return _union_positions(tool, phis, prof.tool.place, progress)


def _pattern(space, z: int, angle: float):
    """Rotate a space (centred on +y) so it lies between tooth 0 (at ``angle``) and tooth 1,
    then repeat it around the gear."""
    step = 2 * math.pi / z
    first = angle + step / 2 - math.pi / 2
    out = []
    for part in shapely.get_parts(space):  # a shaper's tooth may also cut beside its space
        coords = shapely.get_coordinates(part.exterior)
        rings = []
        for k in range(z):
            a = first + k * step
            c, s = math.cos(a), math.sin(a)
            x = c * coords[:, 0] - s * coords[:, 1]
            rings.append(np.stack([x, s * coords[:, 0] + c * coords[:, 1]], -1))
        out.append(shapely.polygons(rings))
    return np.concatenate(out)


def rack_outline(
    gear, tolerance: float = 0.001, backlash: float = 0.0, bore: float | None = None,
    angle: float = 0.0, center=(0.0, 0.0), progress=None,
) -> shapely.Polygon:  # fmt: skip
    """Outline of an external ``gear`` cut by its rack cutter (simulated generation).

    Parameters are those of :func:`gears.cutting.profile.outline`, plus ``progress``, a callable
    ``progress(done, total)`` called as the tool positions are united (the long part). The
    result reproduces the undercut and pointed tips exactly as the tool leaves them; it agrees
    with the analytic outline within the tolerance (tests/gears/test_generate.py).

    Raises
    ------
    GearError
        Also when the work (tool vertices placed) would exceed :data:`MAX_PLACED_VERTICES`; the
        message names the coarsest tolerance that fits.
        For an internal gear (a rack cannot cut a ring).

    Examples
    --------
    >>> from gears import Gear
    >>> p = rack_outline(Gear(20, 1), tolerance=0.01)
    >>> p.is_valid, round(p.area / (math.pi * 10**2), 2)
    (True, 0.98)
    """
    tol = check_tolerance(tolerance, module=gear.module)
    angle, center = check_angle("angle", angle), check_point("center", center)
    check_callback("progress", progress)
    _refuse_protuberance(gear)
    if gear.internal:
        raise GearError(
            "a rack cutter cannot generate an internal gear; use method='analytic' (the "
            "rack-limit outline of a shaper-cut ring)"
        )
    prof = ToothProfile(gear, backlash)
    check_blank(gear, bore, None, prof.rf)
    space = _space(prof, tol, progress)
    if space.geom_type != "Polygon":
        raise GearError(f"z = {gear.teeth}: the simulated tooth space is not one piece")
    blank = shapely.Polygon(circle_points(prof.ra, tol / 2))
    # keep only the part of the space inside a slightly larger tip disc: cheaper unions
    space = space.intersection(shapely.Polygon(circle_points(prof.ra + 0.1 * gear.module, tol)))
    spaces = _pattern(space, gear.teeth, math.radians(angle))
    cut = blank.difference(shapely.union_all(spaces))
    if cut.geom_type != "Polygon":
        raise GearError(
            f"z = {gear.teeth}, profile_shift = {gear.profile_shift:g}: the cut gear falls apart "
            f"({cut.geom_type}); the teeth are cut away"
        )
    pts = np.asarray(cut.exterior.coords)[:-1]
    if not shapely.LinearRing(pts).is_ccw:
        pts = pts[::-1]
    return assemble(gear, pts, tol, bore, None, center, prof.rf)


# --- shaper (pinion-type) cutter ---------------------------------------------------------------
_MAX_EXTRA_POSITIONS = 20000


def shaper_tool_polygon(prof, tolerance: float) -> np.ndarray:
    """One shaper-cutter tooth in the cutter frame (cutter centre at the origin, the tooth
    pointing at the work), closed counter-clockwise without the repeated point.

    Tip land and rounds are sampled with chord sag <= ``tolerance / 4``, the involute flanks
    likewise; the flanks run down to a radius that never enters the work blank (or radially
    below the cutter's base circle), where the tooth is closed by a chord.
    """
    t = prof.tool
    e = tolerance / 4
    g = prof.gear
    # cutter points inside this radius stay outside the work blank in every position
    if t.s > 0:
        r_low = t.a0 - prof.ra - 0.05 * g.module
    else:
        r_low = prof.ra - t.a0 - 0.05 * g.module
    r_low = min(max(r_low, 0.05 * t.r0), t.ra0 - t.rho - 1e-3 * g.module)
    parts = []
    n = arc_segments(t.ra0, t.gamma_tip, e)
    ang = np.linspace(0.0, t.gamma_tip, n + 1)
    parts.append(np.stack([t.ra0 * np.sin(ang), t.ra0 * np.cos(ang)], -1))
    if t.rho > 0:
        n = arc_segments(t.rho, abs(t.gamma_flank - t.gamma_tip), e)
        gam = np.linspace(t.gamma_tip, t.gamma_flank, n + 1)[1:]
        parts.append(t.center_up + t.rho * np.stack([np.sin(gam), np.cos(gam)], -1))
    t_low = math.sqrt(max(r_low * r_low - t.rb0 * t.rb0, 0.0)) / t.rb0
    rolls = involute_rolls(t.rb0, t.t_f, t_low, e)[1:]
    parts.append(t._flank_xy(rolls))
    if r_low < t.rb0:
        parts.append(np.array([[r_low * math.sin(t.psi_b), r_low * math.cos(t.psi_b)]]))
    right = np.concatenate(parts)  # up frame, tip centre -> flank bottom (clockwise side)
    left = right[::-1] * np.array([-1.0, 1.0])
    tooth = np.concatenate([left[:-1], right])  # from the left bottom over the tip to the right
    tooth = t._frame(tooth)
    if not shapely.LinearRing(tooth).is_ccw:
        tooth = tooth[::-1]
    return tooth


def shaper_positions(prof, tolerance: float) -> np.ndarray:
    """Work rotations (rad) of the cutter positions: symmetric, including 0, spaced locally.

    Requirements (chord sag rho dphi^2 / 8, generalised to a cutter of finite teeth): on the flank
    the scallop between two positions is dphi^2 rho_w L / (8 rho_t) (rho_w, rho_t the work and
    cutter involute curvature radii at contact, L = N1 N2; the rack limit rho_t -> inf gives
    rho_w dphi^2 / 8); on the fillet d^2 / (8 rho_a0) with d the generated fillet point's travel
    (it bounds the round's scallop d_C^2 (1/rho_a0 + 1/R_c) / 8, R_c the curvature radius of the
    round centre's trochoid; near a cusp of the envelope, where the fillet point stops, the
    centre's own travel ``|C - I| omega_rel dphi`` is used); on the root the tip land must overlap
    (cutter turn <= its land) and the tip circle's scallop a0^2 dphi^2 (1/r_a0 + s/r_f) / 8
    stays small. The steps are chosen greedily so no requirement inside a step is broken. Each
    is held at ``0.35 tolerance``. Past the last contact the cutter keeps turning until its
    tooth has left the blank, so secondary cutting (trimming of a ring's tips) is reproduced.
    """
    grid, need = _shaper_need(prof, tolerance)
    half, step = _spread(grid, need)
    t = prof.tool
    tooth = shaper_tool_polygon(prof, tolerance)
    count = _extra_count(prof, step)
    extra = grid[-1] + step * np.arange(1, count + 1)
    out = None
    for k in range(0, count, 512):  # in chunks: positions x tooth vertices stay small
        r = np.hypot(*np.moveaxis(t.place(tooth, extra[k : k + 512]), -1, 0))
        inside = (r.min(axis=1) < prof.ra) if t.s > 0 else (r.max(axis=1) > prof.ra)
        if not inside.all():
            out = k + int(np.argmin(inside))
            break
    if out is None:
        raise GearError(
            f"cutter z0 = {t.z0} for z = {t.z}: the cutter tooth never leaves the blank; use a "
            "cutter with fewer teeth"
        )
    half = np.concatenate([half, extra[: out + 1]])
    return np.concatenate([-half[:0:-1], half])


def _extra_count(prof, step: float) -> int:
    """Positions of half a relative cutter turn past the last contact (the most the tooth
    needs to leave the blank), refused when the cutter lingers."""
    t = prof.tool
    count = math.ceil(math.pi / t.omega_rel / step)
    if count > _MAX_EXTRA_POSITIONS:
        raise GearError(
            f"cutter z0 = {t.z0} for z = {t.z}: the cutter turns so slowly against the work "
            f"(relative speed {t.omega_rel:.3g}) that its teeth linger in the blank; use a "
            "cutter with fewer teeth"
        )
    return count


def _shaper_need(prof, tolerance: float) -> tuple[np.ndarray, np.ndarray]:
    """The largest work rotation step allowed on a grid of rotations ``0 ... phi_max`` (the
    requirements of :func:`shaper_positions`)."""
    t = prof.tool
    g = prof.gear
    m = g.module
    e = 0.35 * tolerance
    phis, dphis = [], []
    # involute flank (right flank of the space), from the form circle to the tip circle
    rho_a = math.sqrt(max(prof.ra**2 - prof.rb**2, 0.0))
    if t.s > 0:
        lo, hi = max(t.length - t.rho_t_flank, 0.0), rho_a
    else:
        lo, hi = rho_a, t.length + t.rho_t_flank
    rho_w = np.linspace(lo, hi, 400)
    phi_f, rho_t = prof.flank_contact(rho_w)
    rho_t = np.maximum(rho_t, 0.01 * m)
    phis.append(phi_f)
    dphis.append(np.sqrt(8 * e * rho_t / (np.maximum(rho_w, 0.01 * m) * t.length)))
    # tip round (and, when undercut, the cutter flank beyond N1)
    # the speed of the generated fillet point bounds the round's scallop: with the round's
    # centre path of curvature radius R_c, h = d_C^2 (1/rho + 1/R_c) / 8 <= d_E^2 / (8 rho)
    tau = np.linspace(0.0, 2.0 if prof.undercut else 1.0, 300)
    phi_r, speed = _fillet_speed(prof, tau)
    # near a cusp of the envelope (undercut) the fillet point stops while the centre moves on
    gam = t.gamma_tip + np.clip(tau, 0.0, 1.0) * (t.gamma_flank - t.gamma_tip)
    p, n = t.round_points(gam)
    speed_c = np.abs(t.contact_lambda(p, n) + t.rho) * t.omega_rel
    speed = np.maximum(np.maximum(speed, np.where(tau <= 1.0, speed_c, 0.0)), 1e-9 * m)
    phis.append(phi_r)
    dphis.append(_fillet_step(e, t.rho) / speed)
    phi_all = np.abs(np.concatenate(phis))
    dphi_all = np.concatenate(dphis)
    dphi_all = np.minimum(dphi_all, math.pi / (4 * prof.z))
    phi_max = float(phi_all.max())
    grid = np.linspace(0.0, phi_max, 1025)
    need = np.full(grid.shape, np.inf)
    idx = np.clip(np.searchsorted(grid, phi_all), 0, len(grid) - 1)
    np.minimum.at(need, idx, dphi_all)
    # root: land overlap and tip-circle scallop while the land is on the line of centres
    land_phi = t.land_half_angle * t.ratio
    root_sag = math.sqrt(8 * e / (1 / t.ra0 + t.s / prof.rf)) / t.a0
    land = min(2 * land_phi, root_sag) if land_phi > 0 else root_sag
    need = np.where(grid <= 2 * land_phi + land, np.minimum(need, land), need)
    return grid, need


#: Vertices of a simulated outline per tool vertex and position, per tooth (measured 1.4 ...
#: 4.9 for racks, shapers and sharp-cornered shapers at 0.01 ... 1e-4 mm), and the union work
#: of one outline vertex against one tool vertex placed (5 us against 0.4 us, measured).
_OUTLINE_PER_POSITION = 5.0
_OUTLINE_WORK = 10.0


def simulation_work(z: int, tool_vertices: float, positions: float) -> float:
    """Work of a simulated outline in vertex operations: the tool vertices placed plus
    :data:`_OUTLINE_WORK` per vertex of the patterned outline (about ``5 z (P + T)``), the
    unit of the ``"simulation"`` budget (:data:`gears.budget.BUDGETS`)."""
    out = _OUTLINE_PER_POSITION * z * (positions + tool_vertices)
    return tool_vertices * positions + _OUTLINE_WORK * out


def _rack_work(prof, tolerance: float) -> float:
    grid, need = _rack_need(prof, tolerance)
    return simulation_work(prof.z, len(rack_tool_polygon(prof, tolerance)),
                           2 * _count(grid, need) + 3)  # fmt: skip


def _shaper_work(prof, tolerance: float) -> float:
    grid, need = _shaper_need(prof, tolerance)
    # past the last contact: about as many positions as a step at its end takes to turn the
    # tooth out of the blank (bounded by half a relative turn)
    step = float(_need_on_grid(grid, need)[-1]) if np.isfinite(need).any() else grid[-1]
    extra = min(_extra_count(prof, step), _exit_turn(prof) / step + 1)
    return simulation_work(prof.z, len(shaper_tool_polygon(prof, tolerance)),
                           2 * (_count(grid, need) + extra) + 1)  # fmt: skip


def _exit_turn(prof) -> float:
    """Work rotation past the last contact after which the cutter tooth has left the blank,
    found on a coarse tooth (the exit is a matter of shape, not of tolerance)."""
    cache = prof.__dict__.setdefault("_exit", {})
    if "turn" not in cache:
        t = prof.tool
        coarse = shaper_tool_polygon(prof, 0.05 * prof.gear.module)
        grid, _ = _shaper_need(prof, 0.05 * prof.gear.module)
        turns = np.linspace(0.0, math.pi / t.omega_rel, 2001)[1:]
        r = np.hypot(*np.moveaxis(t.place(coarse, grid[-1] + turns), -1, 0))
        inside = (r.min(axis=1) < prof.ra) if t.s > 0 else (r.max(axis=1) > prof.ra)
        cache["turn"] = float(turns[int(np.argmin(inside))]) if not inside.all() else turns[-1]
    return cache["turn"]


def _shaper_space(prof, tolerance: float, progress=None) -> shapely.Polygon:
    """Union of all shaper-cutter positions: one tooth space, centred on +y; refused over the
    simulation budget before any position is placed."""
    what = f"the shaper simulation of z = {prof.z} (cutter z0 = {prof.tool.z0})"
    check_budget("simulation", what, lambda t: _shaper_work(prof, t), tolerance)
    tooth = shaper_tool_polygon(prof, tolerance)
    phis = shaper_positions(prof, tolerance)
    return _union_positions(tooth, phis, prof.tool.place, progress)


def shaper_outline(
    gear, tolerance: float = 0.001, backlash: float = 0.0, bore: float | None = None,
    rim: float | None = None, angle: float = 0.0, center=(0.0, 0.0), cutter=None, progress=None,
) -> shapely.Polygon:  # fmt: skip
    """Outline of ``gear`` cut by a shaper (pinion-type) cutter, simulated (``progress`` as in
    :func:`rack_outline`; the work is bounded the same way).

    The cutter (:class:`gears.cutting.cutter.ShaperCutter`; default
    :meth:`~gears.cutting.cutter.ShaperCutter.default_for`) turns with the work at the cutting
    centre
    distance; one cutter tooth's positions (:func:`shaper_positions`) are united into one tooth
    space, patterned ``z`` times and subtracted from the blank (tip disc, or for an internal
    gear the ring between its tip circle and ``rim`` outside the root circle). The result
    reproduces the shaper's own root circle and fillet, undercut, pointed tips and any trimming
    of a ring's tips by the cutter on its way out; it agrees with the analytic shaper outline
    (:class:`gears.cutting.profile.ShaperProfile`) within the tolerance
    (tests/gears/test_shaper.py).

    Raises
    ------
    GearError
        When the cutter does not fit the gear or the cut falls apart.

    Examples
    --------
    >>> from gears import Gear
    >>> p = shaper_outline(Gear(60, 1, internal=True), tolerance=0.01)
    >>> p.is_valid, len(p.interiors)
    (True, 1)
    """
    tol = check_tolerance(tolerance, module=gear.module)
    angle, center = check_angle("angle", angle), check_point("center", center)
    check_callback("progress", progress)
    _refuse_protuberance(gear)
    prof = ShaperProfile(gear, cutter, backlash)
    _, width = check_blank(gear, bore, rim, prof.rf)  # width: a ring's rim, checked
    t = prof.tool
    m = gear.module
    space = _shaper_space(prof, tol, progress)
    if t.s > 0:
        blank = shapely.Polygon(circle_points(prof.ra, tol / 2))
        space = space.intersection(shapely.Polygon(circle_points(prof.ra + 0.1 * m, tol)))
    else:
        outer = circle_points(prof.rf + width, tol / 2)
        blank = shapely.Polygon(outer, holes=[circle_points(prof.ra, tol / 2, ccw=False)])
        clip = shapely.Polygon(
            circle_points(prof.rf + 0.5 * width, tol),
            holes=[circle_points(max(prof.ra - 0.1 * m, 1e-3 * m), tol, ccw=False)],
        )
        space = space.intersection(clip)
    spaces = _pattern(space, gear.teeth, math.radians(angle))
    cut = blank.difference(shapely.union_all(spaces))
    holes = 0 if t.s > 0 else 1
    if cut.geom_type != "Polygon" or len(cut.interiors) != holes:
        raise GearError(
            f"z = {gear.teeth}, profile_shift = {gear.profile_shift:g}: the cut gear falls apart "
            f"({cut.geom_type}); the teeth are cut away"
        )
    if len(thickness_on(cut, gear.reference_diameter)) != gear.teeth:
        raise GearError(
            f"z = {gear.teeth}, cutter z0 = {t.z0}: the cutter cuts the teeth away (see "
            "ShaperCutter.check for trimming)"
        )
    ring = cut.exterior if t.s > 0 else cut.interiors[0]
    pts = np.asarray(ring.coords)[:-1]
    if not shapely.LinearRing(pts).is_ccw:
        pts = pts[::-1]
    return assemble(gear, pts, tol, bore, rim, center, prof.rf)
