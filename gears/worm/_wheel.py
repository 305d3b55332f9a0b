"""Layer 3, worm solids: the worm wheel's sections on the envelope of the worm's thread (private).

Private to the worm family: :mod:`gears.worm.solid` lofts these sections into the wheel (its
docstring gives the construction). In every plane ``z = zeta`` of the wheel the hob's thread is
a rack rolling on the pitch circle (:mod:`gears.worm.envelope`): :class:`Wheel` gives its flank,
tip corner, trochoid and root in that plane, :func:`planes` samples every plane's section to a
tolerance in one numpy evaluation per round of splits.
"""

from __future__ import annotations

import math

import numpy as np

from gears.cutting.sampling import chord_angle
from gears.errors import GearError
from gears.worm.envelope import plane_rack, rack_conjugate, rolled


def hob_tip(pair) -> float:
    g = pair.geometry
    return float(g.worm_tip_diameter) / 2.0 + pair.clearance * pair.module


# --- the wheel: its flanks as the envelope of the worm's thread (gears.worm.envelope) ----------


class Wheel:
    """The numbers of one pair that the wheel's construction needs (mm, radians)."""

    def __init__(self, pair) -> None:
        g = pair.geometry
        self.m = pair.module
        self.a = float(g.center_distance)
        self.r2 = float(g.wheel_diameter) / 2.0
        self.screw = float(g.lead) / (2.0 * math.pi) * (1.0 if pair.hand == "right" else -1.0)
        self.rt = hob_tip(pair)
        self.rf = float(g.worm_root_diameter) / 2.0
        self.rk = float(g.throat_radius)
        self.re2 = float(g.wheel_outside_diameter) / 2.0
        self.z2 = pair.wheel_teeth
        self.pitch = 2.0 * math.pi / self.z2
        self.half_face = pair.face_width / 2.0
        # the space of tooth 0 lies about this angle (the thread's centre at the pitch line)
        self.ref = math.pi / 2.0 - self.screw * math.pi / self.r2
        # the axial section once, as a cubic spline (its error is below 1e-12 mm at this count;
        # ZI's base cylinder, where the involute starts with h' = 0, stays C1), held with its
        # derivative as the two columns of one piecewise polynomial (one evaluation for both)
        from scipy.interpolate import CubicSpline, PPoly

        pad = 0.01 * self.m
        r = np.linspace(self.rf - pad, self.rt + pad, 8193)
        spline = CubicSpline(r, np.asarray(pair.axial_profile(r), float))
        slope = np.vstack([np.zeros((1, spline.c.shape[1])), spline.derivative().c])
        self._profile = PPoly(np.stack([spline.c, slope], -1), spline.x)
        # the hob's corner runs on its tip cylinder, where h is one number
        self.corner_half = float(spline(self.rt))
        self._limits: dict[tuple, np.ndarray] = {}

    def profile(self, r):
        """The axial half thickness ``h(r)`` and its slope ``dh/dr`` (mm, mm/mm)."""
        both = self._profile(r)
        return both[..., 0], both[..., 1]

    def tip(self, zeta):
        """The wheel's tip radius in the plane ``zeta``: the throat, at most ``d_e2 / 2``."""
        zeta = np.asarray(zeta, float)
        throat = self.a - np.sqrt(np.maximum(self.rk**2 - zeta**2, 0.0))
        return np.where(np.abs(zeta) < self.rk, np.minimum(throat, self.re2), self.re2)

    def root(self, zeta):
        """The root radius in the plane ``zeta``: the hob's tip line."""
        return self.a - np.sqrt(self.rt**2 - np.asarray(zeta, float) ** 2)

    def flank(self, zeta, depth, side):
        """The wheel's flank conjugate to the hob's at ``depth`` (the worm's own ``X``):
        ``(x, y, u)`` (:func:`gears.worm.envelope.rack_conjugate`)."""
        x, y, nx, ny = plane_rack(zeta, depth, side, *self.profile(np.hypot(depth, zeta)),
                                  self.a, self.screw)  # fmt: skip
        return rack_conjugate(x, y, nx, ny, self.r2)

    def corner_depth(self, zeta):
        return -np.sqrt(self.rt**2 - np.asarray(zeta, float) ** 2)

    def corner(self, zeta, side):
        d = self.corner_depth(zeta)
        x, y, _, _ = plane_rack(zeta, d, side, self.corner_half, 0.0, self.a, self.screw)
        return x, y

    def trochoid(self, zeta, t, side):
        """The root fillet drawn by the hob's tip corner, from the root circle (``t = 0``)."""
        cx, cy = self.corner(zeta, side)
        return rolled(cx, cy, -cx + side * np.asarray(t, float), self.r2)

    def fillet_reach(self, zeta, rho):
        """The fillet's ``|t|`` at the radius ``rho``: its point is the corner moved to
        ``(side t, r_root)`` and turned (:func:`gears.worm.envelope.rolled`), so its radius is
        ``hypot(t, r_root)``, one point at each radius from the root up."""
        rho = np.asarray(rho, float)
        return np.sqrt(np.maximum(rho * rho - self.root(zeta) ** 2, 0.0))

    def upper(self, zeta, side, rows, g):
        """The upper piece of a side of the tooth space, at the normalised parameters ``g``:
        over ``rows[..., 1:3]``, the flank's depths (``rows[..., 3] == 0``) or, where the flank
        stays above the tip and the hob's corner alone cuts that side, the fillet's ``t``
        continued (``== 1``). ``rows`` broadcasts against ``zeta`` (one row a plane)."""
        rows = np.asarray(rows, float)
        b0, b1, kind = rows[..., 1:2], rows[..., 2:3], rows[..., 3:4] > 0.5
        par = b0 + (b1 - b0) * np.asarray(g, float)
        fx, fy, _ = self.flank(zeta, np.where(kind, self.corner_depth(zeta), par), side)
        tx, ty = self.trochoid(zeta, np.where(kind, par, 0.0), side)
        return np.where(kind, tx, fx), np.where(kind, ty, fy)

    def limits(self, zetas, land: float) -> np.ndarray:
        """The rows of :func:`_limits_batch` of both sides in each plane ``zetas``,
        ``(planes, 2, 4)``, with the tip lowered to a land of ``land`` where the tooth would be
        pointed (:func:`_tip_land`); cached by plane."""
        zetas = np.asarray(zetas, float)
        new = np.array([z for z in np.unique(zetas) if (float(z), land) not in self._limits])
        if len(new):
            lim = _limits_batch(self, new)
            _tip_land(self, new, lim, land)
            for z, row in zip(new, lim, strict=True):
                self._limits[(float(z), land)] = row
        return np.array([self._limits[(float(z), land)] for z in zetas])

    def angle(self, x, y):
        """Polar angles about the space of tooth 0, continuous over it."""
        c, s = math.cos(self.ref), math.sin(self.ref)
        return self.ref + np.arctan2(c * y - s * x, c * x + s * y)


def _exits(radius_of, lo, hi, target, iterations: int = 40):
    """Parameters in ``[lo, hi]`` (arrays) at which ``radius_of(params)`` crosses ``target``
    (below at ``lo``, above at ``hi``), by the Illinois false position: the end kept twice in a
    row has its value halved (superlinear on a smooth function; the bracket always holds).
    Written here, vectorised, because scipy's ``optimize.elementwise.find_root`` spends more on
    its bookkeeping (about 0.7 ms an iteration) than these functions cost."""
    lo, hi = np.array(lo, float), np.array(hi, float)
    f_lo, f_hi = radius_of(lo) - target, radius_of(hi) - target
    tol = 1e-12 * (1.0 + np.abs(target))
    kept = np.zeros(lo.shape)  # +1: hi moved last (lo kept), -1: lo moved last
    x = lo
    for _ in range(iterations):
        den = f_hi - f_lo
        x = np.where(np.abs(den) > 0.0, lo - f_lo * (hi - lo) / np.where(den == 0, 1.0, den),
                     0.5 * (lo + hi))  # fmt: skip
        x = np.clip(x, np.minimum(lo, hi), np.maximum(lo, hi))
        f = radius_of(x) - target
        up = f > 0.0
        f_lo = np.where(up & (kept > 0), 0.5 * f_lo, f_lo)
        f_hi = np.where(~up & (kept < 0), 0.5 * f_hi, f_hi)
        hi, f_hi = np.where(up, x, hi), np.where(up, f, f_hi)
        lo, f_lo = np.where(up, lo, x), np.where(up, f_lo, f)
        kept = np.where(up, 1.0, -1.0)
        if np.all((np.abs(f) < tol) | (np.abs(hi - lo) < 1e-13 * (1.0 + np.abs(x)))):
            break
    return x


def _turn(ax, ay, bx, by):
    """The angle from the direction ``(a_x, a_y)`` to ``(b_x, b_y)``, in ``(-pi, pi]``."""
    return np.arctan2(ax * by - ay * bx, ax * bx + ay * by)


#: The two sides of a tooth space (the flanks ``+h`` and ``-h``), over ``(..., side, sample)``.
_SIDES = np.array([[1.0], [-1.0]])
_GRID = 201


def _limits_batch(w: Wheel, zetas: np.ndarray) -> np.ndarray:
    """The limits of both sides of the tooth space in each plane ``zetas``, ``(planes, 2, 4)``
    (side 0 the flank ``+h``, 1 the flank ``-h``): ``(t_star, X_star, X_exit, 0)``, the root
    fillet from ``t = 0`` to ``t_star`` and the flank from the hob's depth ``X_star`` (its
    corner's, or where the fillet cuts the flank: undercut) to ``X_exit`` (the tip); or
    ``(t_x, t_x, t_exit, 1)`` where the flank's contact lies above the tip and the hob's corner
    alone cuts that side, up to the tip at ``t_exit`` (off the mid-plane, near the faces).
    Every plane and side at once, a row each: the flank sampled at 401 depths between the
    hob's corner and the worm's root, then its crossings refined."""
    planes = np.asarray(zetas, float)
    z = np.concatenate([planes, planes])
    side = np.repeat([1.0, -1.0], len(planes))
    rho_tip = w.tip(z)
    x_t = w.corner_depth(z)
    # up to the worm's root cylinder; past the axis's line, over the far side of the worm
    x_hi = np.where(np.abs(z) < w.rf, -np.sqrt(np.maximum(w.rf**2 - z**2, 0.0)), -x_t)
    g = np.linspace(0.0, 1.0, _GRID)
    xs = x_t[:, None] + (x_hi - x_t)[:, None] * g
    ex, ey, _ = w.flank(z[:, None], xs, side[:, None])
    rho = np.hypot(ex, ey)
    above = rho > rho_tip[:, None]
    short = ~np.any(above, axis=1)
    if np.any(short):
        raise GearError(
            f"the worm's flank does not reach the wheel's tip in the plane z = "
            f"{z[np.argmax(short)]:.6g} mm (a narrower face)"
        )
    first = np.argmax(above, axis=1)
    cx, cy = w.corner(z, side)
    _, _, u_c = w.flank(z, x_t, side)
    t_c = side * (u_c + cx)  # the corner's own contact
    # the fillet's way from the root: towards the flank while the hob's tip line runs inside
    # the pitch circle; where the root torus rises above it (near the faces) the corner moves
    # backwards relative to the wheel
    way = np.where(cy < w.r2, 1.0, -1.0)
    idx = np.arange(len(g))
    k = np.argmin(np.where(idx < first[:, None], rho, np.inf), axis=1)
    out = np.zeros((len(z), 4))
    # the flank touches above the tip: the corner alone cuts this side, up to the tip; the
    # upper piece shrinks as t_c -> t_exit (continuous with the planes of a flank)
    alone = first == 0
    s_exit = w.fillet_reach(z, rho_tip)
    s_x = np.minimum(np.maximum(2.0 * s_exit - way * t_c, 0.5 * s_exit), s_exit)
    out[alone] = np.column_stack([way * s_x, way * s_x, way * s_exit, np.ones(len(z))])[alone]
    c = np.flatnonzero(~alone)
    fc = first[c]

    def radius(d):
        x, y, _ = w.flank(z[c], d, side[c])
        return np.hypot(x, y)

    x_exit = _exits(radius, xs[c, fc - 1], xs[c, fc], rho_tip[c])
    # no undercut: the corner's contact joins fillet and flank
    out[c] = np.column_stack([t_c[c], x_t[c], x_exit, np.zeros(len(c))])
    cut = (k[c] > 0) | (way[c] * t_c[c] < 0.0)
    if np.any(cut):
        u = c[cut]
        out[u, 1], out[u, 0] = _undercut(w, z[u], side[u], xs[u], ex[u], ey[u], rho[u], k[u],
                                          first[u], way[u], x_exit[cut])  # fmt: skip
    return out.reshape(2, len(planes), 4).transpose(1, 0, 2)


def _undercut(w: Wheel, z, side, xs, ex, ey, rho, k, first, way, x_exit):
    """Where the fillet cuts the flank (undercut, or the corner's contact beyond the root's
    lowest point off the mid-plane): the flank's depth and the fillet's ``t`` at the crossing
    highest on the flank's upper branch (beyond its cusp at ``xs[k]``, up to the tip at
    ``xs[first]``). The fillet has one point at each radius (:meth:`Wheel.fillet_reach`), so a
    crossing is where the flank's point turns from one side of the fillet's point at its
    radius to the other: bracketed on the samples, then found by false position."""
    zc = z[:, None]
    t = way[:, None] * w.fillet_reach(zc, rho)
    tx, ty = w.trochoid(zc, t, side[:, None])
    turn = _turn(tx, ty, ex, ey)
    idx = np.arange(xs.shape[1])
    # from one sample below the cusp's (the crossing may lie between them), but never from the
    # corner's own sample past a cusp (there the fillet meets the lower branch, not a crossing)
    lo = np.maximum(np.minimum(k, first - 1), 0)
    lo = np.where(lo > 1, lo - 1, lo)
    ok = (idx >= lo[:, None]) & (idx <= first[:, None]) & (rho >= w.root(zc))
    ok &= np.abs(turn) < 1.0  # away from the wrap of the angle at pi
    change = ok[:, :-1] & ok[:, 1:] & ((turn[:, :-1] <= 0.0) != (turn[:, 1:] <= 0.0))
    rows = np.arange(len(z))
    j = np.where(np.any(change, axis=1), change.shape[1] - 1 - np.argmax(change[:, ::-1], 1), -1)
    d = xs[rows, np.maximum(k, 0)]  # no crossing: the cusp
    has = j >= 0
    if np.any(has):
        h, jh = rows[has], j[has]
        sign = np.where(turn[h, jh] <= 0.0, 1.0, -1.0)

        def gap(dd):
            fx, fy, _ = w.flank(z[h], dd, side[h])
            ft = way[h] * w.fillet_reach(z[h], np.hypot(fx, fy))
            return sign * _turn(*w.trochoid(z[h], ft, side[h]), fx, fy)

        d[h] = _exits(gap, xs[h, jh], xs[h, jh + 1], 0.0)
    d = np.minimum(np.maximum(d, xs[:, 0]), x_exit)
    fx, fy, _ = w.flank(z, d, side)
    return d, way * w.fillet_reach(z, np.hypot(fx, fy))


def _tip_land(w: Wheel, zetas: np.ndarray, lim: np.ndarray, land: float) -> None:
    """Where the tooth between space 0's left side and space 1's right side would be thinner
    than ``land`` at the tip (a pointed tooth, off the mid-plane of a wheel of few teeth), lower
    the tip of that plane to the radius of a land ``land`` wide: the ends of both sides' upper
    pieces move there (``lim``, ``(planes, 2, 4)``, in place)."""
    z = np.asarray(zetas, float)[:, None]
    # the tooth's width at the tip from the ends of both sides: most planes are not pointed
    ends = w.angle(*w.upper(z[:, :, None], _SIDES, lim, np.ones(1)))[..., 0]
    tips = w.tip(z[:, 0])
    thin = (ends[:, 0] + w.pitch - ends[:, 1]) * tips < land
    if not np.any(thin):
        return
    c = np.flatnonzero(thin)
    g = np.linspace(0.0, 1.0, 401)
    x, y = w.upper(z[c][:, :, None], _SIDES, lim[c], g)
    rho, ang = np.hypot(x, y), w.angle(x, y)
    (rho_r, rho_l), (a_r, a_l) = rho.transpose(1, 0, 2), ang.transpose(1, 0, 2)
    at = np.full(len(z), np.nan)
    bracket = np.zeros((len(z), 2, 2))  # the samples of each side about the land's radius
    for n, i in enumerate(c):
        lo = max(rho_r[n, 0], rho_l[n, 0])
        rho = np.linspace(lo, tips[i], 401)
        # the upper branch (beyond a cusp) is where the radius grows: interpolate on it
        kr, kl = int(np.argmin(rho_r[n])), int(np.argmin(rho_l[n]))
        thick = (np.interp(rho, rho_r[n, kr:], a_r[n, kr:]) + w.pitch
                 - np.interp(rho, rho_l[n, kl:], a_l[n, kl:])) * rho  # fmt: skip
        if thick[-1] >= land:
            continue
        if thick[0] < land:
            raise GearError(
                f"the wheel's teeth are pointed down to their root in the plane z = "
                f"{z[i, 0]:.6g} mm (see check(): fewer teeth need a larger profile shift or a "
                "narrower face)"
            )
        j = int(np.flatnonzero(thick < land)[0])
        frac = (thick[j - 1] - land) / (thick[j - 1] - thick[j])
        at[i] = rho[j - 1] + (rho[j] - rho[j - 1]) * frac
        for s, (rs, k) in enumerate(((rho_r[n], kr), (rho_l[n], kl))):
            up = max(k + int(np.argmax(rs[k:] >= at[i])), 1)
            bracket[i, s] = g[up - 1], g[up]
    pointed = np.flatnonzero(np.isfinite(at))
    if len(pointed) == 0:
        return
    zp, rows = z[pointed][:, :, None], lim[pointed]

    def radius(b):
        r = rows.copy()
        r[..., 2] = b
        return np.hypot(*w.upper(zp, _SIDES, r, np.ones(1)))[..., 0]

    b0, span = rows[..., 1], rows[..., 2] - rows[..., 1]
    lo, hi = (b0 + span * bracket[pointed, :, k] for k in (0, 1))
    lim[pointed, :, 2] = _exits(radius, lo, hi, at[pointed][:, None])


class _Plan:
    """The limits of the tooth space in each plane (``(planes, side, row)``, side 0 the right
    side of space 0, 1 the left) and the sampling shared by every plane: normalised parameters
    of the fillet and of the upper piece, and the counts of the root and tip arcs' inner
    vertices."""

    def __init__(self, w: Wheel, zetas, land: float, fillet=(0.0, 1.0), flank=(0.0, 1.0),
                 root_n: int = 1, tip_n: int = 1) -> None:  # fmt: skip
        self.w, self.zetas, self.land = w, np.asarray(zetas, float), land
        self.limits = w.limits(self.zetas, land)
        self.fillet, self.flank = np.asarray(fillet, float), np.asarray(flank, float)
        self.root_n, self.tip_n = root_n, tip_n

    def at(self, zetas) -> _Plan:
        """The same sampling in other planes."""
        return _Plan(self.w, zetas, self.land, self.fillet, self.flank, self.root_n, self.tip_n)

    def fillets(self, g=None):
        """The root fillets, ``(planes, side, samples, 2)``, from the root."""
        g = self.fillet if g is None else g
        z = self.zetas[:, None, None]
        return np.stack(self.w.trochoid(z, self.limits[..., :1] * g, _SIDES), -1)

    def flanks(self, g=None):
        """The upper pieces (flanks), ``(planes, side, samples, 2)``, up to the tip."""
        g = self.flank if g is None else g
        return np.stack(self.w.upper(self.zetas[:, None, None], _SIDES, self.limits, g), -1)

    def arcs(self):
        """The root and tip arcs in each plane: ``((start, end), (start, end))`` angles and
        the tip's radius (the throat's, or a pointed tooth's land)."""
        fil, fla = self.fillets(np.array([0.0])), self.flanks(np.array([1.0]))
        w = self.w
        root = w.angle(fil[:, 0, 0, 0], fil[:, 0, 0, 1]), w.angle(fil[:, 1, 0, 0], fil[:, 1, 0, 1])
        tip = (w.angle(fla[:, 1, 0, 0], fla[:, 1, 0, 1]),
               w.angle(fla[:, 0, 0, 0], fla[:, 0, 0, 1]) + w.pitch)  # fmt: skip
        return root, tip, np.hypot(fla[:, 0, 0, 0], fla[:, 0, 0, 1])

    def rings(self, spaces: int | None = None) -> np.ndarray:
        """Every plane's section, ``(planes, N, 2)``, counter-clockwise: tooth space 0 (the
        right side down, the root, the left side up), the tip, turned ``z_2`` times (or only
        ``spaces`` times: the first spaces of the section, for the checks)."""
        w = self.w
        fil, fla = self.fillets(), self.flanks()
        (r0, r1), (t0, t1), rho_tip = self.arcs()

        def arc(a0, a1, rho, n):
            ang = a0[:, None] + (a1 - a0)[:, None] * np.linspace(0.0, 1.0, n + 2)[1:-1]
            return np.stack([rho[:, None] * np.cos(ang), rho[:, None] * np.sin(ang)], -1)

        root = arc(r0, r1, w.root(self.zetas), self.root_n)
        tip = arc(t0, t1, rho_tip, self.tip_n)
        space = np.concatenate([
            fla[:, 0, ::-1], fil[:, 0, -2::-1], root, fil[:, 1, :-1], fla[:, 1], tip,
        ], axis=1)  # fmt: skip
        turns = np.arange(w.z2 if spaces is None else spaces) * w.pitch
        c, s = np.cos(turns)[:, None], np.sin(turns)[:, None]
        x = c * space[:, None, :, 0] - s * space[:, None, :, 1]
        y = s * space[:, None, :, 0] + c * space[:, None, :, 1]
        return np.stack([x, y], -1).reshape(len(self.zetas), -1, 2)


def _chord_sag(pts, mid) -> np.ndarray:
    """Distances of the midpoints ``mid`` (..., K-1, 2) from the chords of ``pts`` (..., K, 2)."""
    a, b = pts[..., :-1, :], pts[..., 1:, :]
    d = b - a
    length = np.maximum(np.hypot(d[..., 0], d[..., 1]), 1e-300)
    e = mid - a
    return np.abs(d[..., 0] * e[..., 1] - d[..., 1] * e[..., 0]) / length


def _refine(curve, tolerance: float, g=None) -> np.ndarray:
    """Normalised parameters from 0 to 1 (starting from ``g``), halved where a chord of
    ``curve(g)`` (``(..., samples, 2)``) misses the curve at its middle by more than
    ``tolerance`` in any plane."""
    g = np.linspace(0.0, 1.0, 5) if g is None else np.asarray(g, float)
    for _ in range(30):
        mid = (g[:-1] + g[1:]) / 2.0
        pts = curve(np.concatenate([g, mid]))
        sag = _chord_sag(pts[..., : len(g), :], pts[..., len(g) :, :])
        bad = sag.reshape(-1, len(mid)).max(axis=0) > tolerance
        if not np.any(bad):
            break
        g = np.sort(np.concatenate([g, mid[bad]]))
    return g


def _arc_count(span: float, radius: float, tolerance: float) -> int:
    return max(math.ceil(span / max(chord_angle(radius, tolerance), 1e-12)) - 1, 1)


def _sample(plan: _Plan, tolerance: float) -> _Plan:
    """``plan`` with the sampling that keeps every chord of its sections within
    ``tolerance`` in each of its planes (starting from its own)."""
    fillet = _refine(plan.fillets, tolerance, plan.fillet)
    flank = _refine(plan.flanks, tolerance, plan.flank)
    (r0, r1), (t0, t1), rho_tip = plan.arcs()
    w = plan.w
    root_n = _arc_count(float(np.max(r1 - r0)), float(np.min(w.root(plan.zetas))), tolerance)
    tip_n = _arc_count(float(np.max(t1 - t0)), float(np.max(rho_tip)), tolerance)
    return _Plan(w, plan.zetas, plan.land, fillet, flank, max(root_n, plan.root_n),
                 max(tip_n, plan.tip_n))  # fmt: skip


def _ring_gap(mid, lower, upper, spaces: int = 1) -> np.ndarray:
    """Per plane, the largest distance of a vertex of the mid-planes' sections ``mid``
    ``(planes, N, 2)`` from the sections interpolated linearly between their neighbours (the
    quads' deviation): each vertex against the interpolated ring's segments near it. With
    ``spaces = 3`` the rings hold three tooth spaces of the sections (every space is the same
    turned) and the middle one's vertices are measured, its neighbours' segments at hand."""
    ring = (lower + upper) / 2.0
    a = ring
    b = np.roll(ring, -1, axis=1)
    best = np.full(mid.shape[:2], np.inf)
    for shift in (-2, -1, 0, 1):
        pa, pb = np.roll(a, -shift, axis=1), np.roll(b, -shift, axis=1)
        d = pb - pa
        t = np.einsum("...i,...i->...", mid - pa, d) / np.maximum(
            np.einsum("...i,...i->...", d, d), 1e-300
        )
        foot = pa + np.clip(t, 0.0, 1.0)[..., None] * d
        best = np.minimum(best, np.hypot(*(mid - foot).transpose(2, 0, 1)))
    if spaces == 3:
        n = best.shape[1] // 3
        best = best[:, n : 2 * n]
    return best.max(axis=1)


def planes(w: Wheel, tolerance: float, progress=None) -> _Plan:
    """Planes ``z = zeta`` from face to face, split where the sections interpolated between
    two planes miss the mid-plane's by more than ``tolerance``, with their sampling. The miss
    of a linear interpolation falls with the square of the spacing, so an interval missing by
    ``e`` is split at once into the power of two nearest above ``sqrt(e / tolerance)`` (at most
    8) parts, unless it is itself part of a split whose miss did not fall so (an edge or a jump
    of the section between two planes: halved); the new planes and the next mid-planes are
    evaluated together."""
    b = w.half_face
    zs = list(np.linspace(-b, b, 5))
    # where the throat meets the outside cylinder (the tip radius a - sqrt(r_k^2 - z^2) reaches
    # d_e2 / 2) the tip has an edge
    z_e = math.sqrt(max(w.rk**2 - (w.a - w.re2) ** 2, 0.0))
    if z_e < b:
        zs += [-z_e, z_e]
    zs = np.unique(np.round(zs, 12))
    # the quarters of the first intervals with them, in one evaluation: the first checks and
    # splits find them there
    quarters = zs[:-1, None] + np.diff(zs)[:, None] * np.array([0.25, 0.5, 0.75])
    w.limits(np.concatenate([zs, quarters.ravel()]), tolerance)
    plan = _sample(_Plan(w, zs, tolerance), tolerance)
    done = 0
    spaces = min(w.z2, 3)  # the check's share of each section: the others are the same turned
    expect: dict[float, float] = {}  # an interval's lower plane: the miss its split foretold
    for _ in range(4):
        rings = dict(zip(plan.zetas.tolist(), plan.rings(spaces), strict=True))
        pending = np.empty(0)
        for _ in range(14):
            zs = np.unique(np.concatenate([list(rings), pending]))
            mids = (zs[:-1] + zs[1:]) / 2.0
            batch = plan.at(np.concatenate([pending, mids])).rings(spaces)
            rings.update(zip(pending.tolist(), batch[: len(pending)], strict=True))
            mid_rings = batch[len(pending) :]
            low = np.array([rings[z] for z in zs[:-1]])
            up = np.array([rings[z] for z in zs[1:]])
            gap = _ring_gap(mid_rings, low, up, spaces)
            bad = gap > tolerance
            done += 1
            if progress is not None:
                progress(min(done, 15), 16)
            if not np.any(bad):
                break
            rings.update(zip(mids[bad].tolist(), mid_rings[bad], strict=True))
            i_bad = np.flatnonzero(bad)
            smooth = gap[bad] <= 4.0 * np.array([expect.get(z, np.inf) for z in zs[i_bad]])
            parts = np.where(smooth, 2 ** np.clip(np.ceil(np.log2(np.sqrt(gap[bad] / tolerance))),
                                                  1, 3), 2).astype(int)  # fmt: skip
            new = [zs[i] + (zs[i + 1] - zs[i]) * np.arange(n) / n
                   for i, n in zip(i_bad, parts, strict=True)]  # fmt: skip
            for starts, e in zip(new, gap[bad] / parts**2, strict=True):
                expect.update(dict.fromkeys(starts.tolist(), float(e)))
            pending = np.concatenate([starts[1:] for starts in new])
            pending = pending[~np.isin(pending, mids[bad])]
        fine = _sample(plan.at(zs), tolerance)
        same = (len(fine.fillet) == len(plan.fillet) and len(fine.flank) == len(plan.flank)
                and fine.root_n == plan.root_n and fine.tip_n == plan.tip_n)  # fmt: skip
        plan = fine
        if same:
            break
    return plan
