"""Layer 4, envelopes: the exact tooth profile a rack or shaper cutter generates, sampled to a
tolerance, and the analytic outline built from it (involute flanks, generated root fillet,
undercut, tip and root arcs).

The outline is what the generating tool leaves (Litvin & Fuentes; Joldasbekov §2.7-2.8, Ozols
§21-6). The tool is the basic rack's mirror image (:class:`gears.rack.BasicRack`): straight flanks
at the pressure angle, a tip land and tip rounds of radius rho_aP0. In the transverse section of a
helical gear the rounds are ellipses (semi-axes rho/cos(beta) along the pitch line, rho across).

**Envelope in closed form.** A tool point T = (u, v) (v measured from the tool reference line,
positive away from the gear axis) with profile normal N is in contact at the roll angle where its
normal passes through the pitch point I = (-r phi, -x m_n) (the meshing equation n . v12 = 0):

    phi = ((v + x m_n) N_u / N_v - u) / r,    P = Rot(phi) (u + r phi, r + x m_n + v)

(rack kinematics: the normal passes through the pitch point). Applied to the straight flank it gives
the involute; to the flat tip land, the root circle; to a circular tip round it gives the offset of
the primary trochoid traced by the round's centre C(phi): the contact point lies on the line IC, so
``E = C + rho (C - I)/|C - I|`` with C' perpendicular to C - I, i.e. the offset curve
``E = C +- rho J C'/|C'|`` (Litvin & Fuentes). No sampling or iteration is involved.

**Undercut.** When the tool's straight flank reaches below the line-of-action limit point N1
(x < x_min), the fillet curve cuts the involute; the generated boundary is the outermost of the
two (for each radius the larger space angle). The crossing is found by Brent's method on
eta_fillet(t) - eta_involute(r(t)) (:func:`undercut_form_diameter`).

**Internal gears** are modelled with the rack limit of the shaper cutter (a pinion-type cutter
with infinitely many teeth): the flanks are exact involutes of the ring's base circle, as with
any cutter; the root fillet is the envelope of the rack tool's tip round rolled on the ring's
reference circle from the inside. A real shaper of z0 teeth leaves a slightly different fillet;
:func:`gears.cutting.generate.shaper_outline` simulates it.

**Sampling from a tolerance** (chordal deviation in mm): arcs by their sagitta,
n = ceil(angle / (2 acos(1 - e/R))); the involute by its curvature radius rho = r_b t
(t = tan alpha_y, the roll angle), chord sag r_b t dt^2 / 8 <= e, i.e. points uniform in
w = t^(3/2) (the chord sag of a curve of radius rho: rho dphi^2 / 8); the fillet by its measured
curvature (point density sqrt(kappa / 8e) per unit length), then refined by bisection until every
chord midpoint is within ``e`` of the curve.

**Backlash** is a thickness allowance: ``backlash`` j is the pair's normal (line-of-action)
backlash; each gear takes half, so every flank is moved j/4 along its normal (the tool is widened
by j/(4 cos alpha_t)). The transverse arc thickness at diameter d shrinks by j/(2 cos alpha_y).
"""

from __future__ import annotations

import math
from functools import cached_property

import numpy as np
import shapely

from gears.arguments import (
    MIN_TOLERANCE,
    check_angle,
    check_point,
    check_tolerance,
)
from gears.budget import check_budget
from gears.cutting.cutter import ShaperCutter, ShaperTool
from gears.cutting.sampling import (
    _BETWEEN,
    _SAFETY,
    _point_segment_distance,
    _refuse_protuberance,
    _root,
    arc_segments,
    assemble,
    check_backlash,
    check_blank,
    circle_segments,
    involute_rolls,
    one_sided,
)
from gears.errors import GearError
from gears.geometry import CROSSING, space_half_angle
from gears.involute import inv
from gears.rack import RackTool

__all__ = [
    "MIN_TOLERANCE",
    "ShaperProfile",
    "ToothProfile",
    "check_tolerance",
    "outline",
    "outline_vertices",
    "profile_of",
    "tooth_profile",
    "undercut_form_diameter",
]


class ToothProfile:
    """Exact half-space boundary of one gear, with sampling to a tolerance.

    Parameters
    ----------
    gear : Gear
        The gear (its transverse section is drawn).
    backlash : float
        Pair normal backlash in mm; this gear takes half (see the module docstring).

    Notes
    -----
    Angles ``eta`` are measured from the centre line of a tooth space, positive into the flank
    that lies clockwise of it; the tooth itself is centred at ``eta = pi/z``.
    """

    def __init__(self, gear, backlash: float = 0.0) -> None:
        self.gear = gear
        b = self.backlash = check_backlash(gear, backlash)
        self.tool = RackTool.for_gear(gear, b)
        self.z = gear.teeth
        self.rb = gear.base_diameter / 2
        self.ra = gear.tip_diameter / 2
        self.rf = self.tool.r + self.tool.xm - self.tool.s * self.tool.h
        self.alpha_t = math.radians(gear.transverse_pressure_angle)
        self.eta_p = space_half_angle(gear, b)
        self._validate()

    # --- exact curves ----------------------------------------------------------------------
    def eta_involute(self, rho):
        """Space half-angle of the involute flank at radius ``rho`` (exact)."""
        ay = np.arccos(np.clip(self.rb / np.asarray(rho, float), -1.0, 1.0))
        return self.eta_p + self.tool.s * (inv(ay) - inv(self.alpha_t))

    @property
    def v_limit(self) -> float:
        """Tool height of the interference point N1 (external gears); below it the straight
        flank undercuts (Ozols §21-7)."""
        t = self.tool
        return -t.xm - t.r * math.sin(self.alpha_t) ** 2

    @property
    def undercut(self) -> bool:
        t = self.tool
        return t.s > 0 and t.v_f < self.v_limit - 1e-12 * self.gear.module

    def fillet(self, tau):
        """The fillet curve ``(rho, eta, phi)`` at parameter ``tau``.

        ``0 <= tau <= 1`` runs over the tool round (tip land end to flank tangency); for an
        undercut gear ``1 < tau <= 2`` continues over the straight flank down to N1's height.
        """
        t = self.tool
        tau = np.asarray(tau, float)
        on_round = tau <= 1.0
        tr = -math.pi / 2 + np.minimum(tau, 1.0) * (t.t_f + math.pi / 2)
        ur, vr, nur, nvr = t.round_points(tr)
        vf = t.v_f + (np.maximum(tau, 1.0) - 1.0) * (self.v_limit - t.v_f)
        uf, vff, nuf, nvf = t.flank_points(vf)
        u = np.where(on_round, ur, uf)
        v = np.where(on_round, vr, vff)
        nu = np.where(on_round, nur, nuf)
        nv = np.where(on_round, nvr, nvf)
        return t.envelope(u, v, nu, nv)

    @property
    def has_round(self) -> bool:
        return self.tool.a > 0

    @cached_property
    def tau_form(self) -> float:
        """Fillet parameter where the flank (involute) takes over."""
        if not self.undercut:
            return self._tau_tangent()
        tau = np.linspace(0.0, 2.0, 801)[:-1]
        rho, eta, _ = self.fillet(tau)
        above = rho >= self.rb
        # below the base circle there is no involute: count the fillet as outside it (g = 1).
        # f below uses the same rule, so every bracket found is valid; in a marginal undercut the
        # fillet meets the involute right at the base circle, and the root is that jump.
        g = np.where(above, eta - self.eta_involute(np.maximum(rho, self.rb)), 1.0)
        # a hair inside the limit the fillet only touches the involute at d_b (g ~ 1e-16 > 0)
        idx = np.flatnonzero((g[:-1] > CROSSING) & (g[1:] <= CROSSING))
        cut_away = (
            f"z = {self.z}, profile_shift = {self.gear.profile_shift:g}: "
            "the undercut fillet does not "
            "meet the involute (the tooth is cut away); use a larger profile shift"
        )
        if idx.size == 0:
            raise GearError(cut_away)
        i = int(idx[0])

        def f(x):
            r_, e_, _ = self.fillet(x)
            if float(r_) < self.rb:
                return 1.0
            return float(e_ - self.eta_involute(float(r_)))

        if f(tau[i + 1]) > 0:  # touching, not crossing: where it comes within CROSSING
            return _root(lambda x: f(x) - CROSSING, tau[i], tau[i + 1], cut_away)
        return _root(f, tau[i], tau[i + 1], cut_away)

    def _land_angle(self) -> float:
        """Angle from the space centre where the root arc (the tool tip's image) ends."""
        return self.tool.u_c / self.tool.r

    @cached_property
    def _tangent_radius(self) -> float:
        t = self.tool
        u, v, nu, nv = t.flank_points(np.array([t.v_f]))
        return float(t.envelope(u, v, nu, nv)[0][0])

    def _tau_tangent(self) -> float:
        """End of the fillet when it is tangent to the involute (no undercut).

        The round's envelope may fold back just before the tangency (a swallowtail of a few
        micro-radians, seen with the rack limit of internal gears); the fillet is then ended where
        it first reaches the form radius, and the fold (inside the space by less than 1e-4 of the
        module) is dropped.
        """
        tau = np.linspace(0.0, 1.0, 801)
        rho = self.fillet(tau)[0] * self.tool.s
        r_form = self._tangent_radius * self.tool.s
        if np.all(np.diff(rho) >= 0):
            return 1.0
        idx = np.flatnonzero(rho[:-1] - r_form < 0)
        hit = np.flatnonzero(rho[1:] - r_form >= 0)
        first = int(hit[0]) if hit.size else len(tau) - 2
        if first + 1 >= len(tau) - 1 or not idx.size:
            return 1.0

        def f(x):
            return float(self.fillet(x)[0]) * self.tool.s - r_form

        return _root(
            f, tau[first], tau[first + 1],
            f"z = {self.z}, profile_shift = {self.gear.profile_shift:g}: "
            "the tool round's envelope folds "
            "where it should meet the involute; use method='shaper'",
        )  # fmt: skip

    @cached_property
    def ring_fold(self) -> tuple[float, float] | None:
        """Internal gears whose rack-limit fillet reaches beyond the root circle.

        A rack tool rolled inside a ring digs outwards on both sides of its centre position, so
        the round's envelope can pass the root circle and fold back. The part outside the root
        circle (which a real cutter's tip circle never reaches) is clipped: the boundary runs
        along the root circle to where the returning fillet branch crosses it (``tau_r``), back
        along that branch to where it crosses the involute (``tau_x``), then up the involute.
        Returns ``(tau_r, tau_x)`` or None when the fillet stays inside the root circle.
        """
        if self.tool.s > 0 or self._tangent_radius <= self.rf * (1 + 1e-12):
            return None
        tau = np.linspace(0.0, 1.0, 801)
        rho, eta, _ = self.fillet(tau)
        i_min = int(np.argmin(rho))
        out = np.flatnonzero(rho[i_min:] >= self.rf)
        j = i_min + int(out[0])

        def fr(x):
            return float(self.fillet(x)[0]) - self.rf

        no_fold = (
            f"internal z = {self.z}, profile_shift = {self.gear.profile_shift:g}: "
            "the rack-limit fillet "
            "does not meet the involute; use method='shaper'"
        )
        if j < 1:  # the whole fillet lies beyond the root circle
            raise GearError(no_fold)
        tau_r = _root(fr, tau[j - 1], tau[j], no_fold)
        g = eta[: i_min + 1] - self.eta_involute(rho[: i_min + 1])
        cross = np.flatnonzero((g[:-1] < 0) & (g[1:] >= 0))
        if not cross.size:
            raise GearError(no_fold)
        k = int(cross[-1])

        def fx(x):
            r_, e_, _ = self.fillet(x)
            return float(e_ - self.eta_involute(r_))

        tau_x = _root(fx, tau[k], tau[k + 1], no_fold)
        return tau_r, tau_x

    @cached_property
    def form_radius(self) -> float:
        """Radius where the involute starts (the fillet joins or cuts it)."""
        if self.ring_fold is not None:
            return float(self.fillet(self.ring_fold[1])[0])
        if not self.undercut:
            return self._tangent_radius
        return float(self.fillet(self.tau_form)[0])

    @cached_property
    def tip_radius(self) -> float:
        """Radius where the flank ends: the tip circle, or where the flanks meet (pointed)."""
        half = math.pi / self.z
        if self.tool.s * (half - self.eta_involute(self.ra)) >= 0 or self.tool.s < 0:
            return self.ra
        # external, pointed: eta_involute(r) = pi/z between the form and tip circles
        return _root(
            lambda r: float(self.eta_involute(r)) - half, self.form_radius, self.ra,
            f"z = {self.z}, profile_shift = {self.gear.profile_shift:g}: "
            "the tooth is pointed below its "
            "form circle (no flank left); use a smaller profile shift",
        )  # fmt: skip

    def _validate(self) -> None:
        g = self.gear
        if self.ra <= self.rb:
            raise GearError(
                f"tip circle d_a = {2 * self.ra:.6g} mm lies inside the base circle "
                f"d_b = {2 * self.rb:.6g} mm: no involute flank exists"
                + (" (internal gear: use more teeth or a negative shift)" if g.internal else "")
            )
        if self.rf <= 0:
            raise GearError(
                f"root circle radius {self.rf:.6g} mm <= 0: z = {g.teeth} with x = "
                f"{g.profile_shift:g} is too small for this tool"
            )
        half = math.pi / self.z
        if self._land_angle() >= half:
            raise GearError(f"z = {self.z}: the tool tip land is wider than the tooth pitch")
        if self.tool.s < 0 and self.eta_involute(self.ra) >= half:
            raise GearError(
                f"internal gear teeth are pointed before the tip circle d_a = {2 * self.ra:.6g}"
                " mm; use a larger profile shift (DIN 3960: it thickens a ring's teeth) or a "
                "larger tip diameter"
            )
        if self.tool.s > 0 and float(self.eta_involute(self.form_radius)) >= half:
            raise GearError(
                f"z = {self.z}, profile_shift = {g.profile_shift:g}: "
                "the tooth is pointed below its form "
                "circle (no flank left); use a smaller profile shift"
            )

    # --- sampling --------------------------------------------------------------------------
    def _involute_samples(self, r0: float, r1: float, tol: float) -> np.ndarray:
        """Radii on the involute between r0 and r1 so that every chord sag <= tol
        (:func:`involute_rolls`, with the safety factor)."""
        t0 = math.sqrt(max(r0 * r0 - self.rb**2, 0.0)) / self.rb
        t1 = math.sqrt(max(r1 * r1 - self.rb**2, 0.0)) / self.rb
        t = involute_rolls(self.rb, t0, t1, _SAFETY * tol)
        rho = self.rb * np.sqrt(1.0 + t * t)
        rho[0], rho[-1] = r0, r1
        return rho

    def _fillet_samples(self, tau0: float, tau1: float, tol: float):
        """Fillet parameters with chord deviation <= tol: density from curvature, then bisect."""
        if tau1 <= tau0:
            return np.array([tau0])
        dense = np.linspace(tau0, tau1, 257)
        rho, eta, _ = self.fillet(dense)
        x, y = rho * np.sin(eta), rho * np.cos(eta)
        ds = np.hypot(np.diff(x), np.diff(y))
        heading = np.unwrap(np.arctan2(np.diff(y), np.diff(x)))
        # turning per segment ~ kappa ds; points needed per segment = sqrt(kappa/8e) ds
        turn = np.abs(np.diff(heading))
        turn = np.concatenate([turn[:1], 0.5 * (turn[:-1] + turn[1:]), turn[-1:]])
        need = np.sqrt(turn * ds / (8.0 * _SAFETY * tol))
        cum = np.concatenate([[0.0], np.cumsum(need)])
        n = max(1, math.ceil(cum[-1]))
        taus = np.interp(np.linspace(0.0, cum[-1], n + 1), cum, dense)
        taus[0], taus[-1] = tau0, tau1
        for _ in range(30):
            mid = 0.5 * (taus[:-1] + taus[1:])
            p = self._xy(*self.fillet(taus)[:2])
            q = self._xy(*self.fillet(mid)[:2])
            dev = _point_segment_distance(q, p[:-1], p[1:])
            bad = dev > _SAFETY * tol
            if not bad.any():
                break
            taus = np.sort(np.concatenate([taus, mid[bad]]))
        return taus

    @staticmethod
    def _xy(rho, eta):
        return np.stack([rho * np.sin(eta), rho * np.cos(eta)], axis=-1)

    def half_space(self, tolerance: float = 0.001) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Sampled boundary from the space centre (root) to the tooth centre (tip), one-sided:
        no chord adds material (:func:`gears.cutting.sampling.one_sided`).

        Returns
        -------
        rho, eta : ndarray
            Polar points (radius, angle from the space centre line).
        kind : ndarray of int
            Curve each point starts: 0 root arc, 1 fillet, 2 involute, 3 tip arc.
        """
        tol = check_tolerance(tolerance, module=self.gear.module)
        pieces = []  # (kind, curve(params) -> (rho, eta), params from the start to the end)

        def arc(radius):
            return lambda e: (np.full(np.shape(e), radius), np.asarray(e, float))

        def fillet(taus):
            rho, eta, _ = self.fillet(taus)
            return rho, eta

        def involute(t):
            rho = self.rb * np.sqrt(1.0 + np.asarray(t) ** 2)
            return rho, self.eta_involute(rho)

        # root arc, from the space centre to the end of the tip land's image
        eta_land = self._land_angle()
        fold = self.ring_fold
        if fold is not None:
            eta_land = float(self.fillet(fold[0])[1])
        if eta_land > 0:
            n = arc_segments(self.rf, eta_land, tol)
            pieces.append((0, arc(self.rf), np.linspace(0.0, eta_land, n + 1)))
        if fold is not None:
            pieces.append((1, fillet, self._fillet_samples(fold[1], fold[0], tol)[::-1]))
        elif self.has_round or self.undercut:
            pieces.append((1, fillet, self._fillet_samples(0.0, self.tau_form, tol)))
        r_top = self.tip_radius
        t = self._involute_rolls(self.form_radius, r_top, tol)
        pieces.append((2, involute, t))
        half = math.pi / self.z
        if r_top >= self.ra:
            e0 = float(self.eta_involute(self.ra))
            n = arc_segments(self.ra, half - e0, tol)
            pieces.append((3, arc(self.ra), np.linspace(e0, half, n + 1)))
        rhos, etas, kinds, mids = [], [], [], []
        for i, (kind, curve, params) in enumerate(pieces):
            last = i == len(pieces) - 1
            rho, eta = curve(params if last else params[:-1])
            rhos.append(np.asarray(rho, float))
            etas.append(np.asarray(eta, float))
            kinds.append(np.full(len(rhos[-1]), kind))
            # the true curve between the samples: the middle of an arc (its largest sag), three
            # points of an involute chord, and many of the fillet's (its shape varies most)
            between = _BETWEEN[kind]
            inner = params[:-1, None] + between * (params[1:] - params[:-1])[:, None]
            r_in, e_in = curve(inner.ravel())
            mid = np.stack([np.reshape(r_in, inner.shape), np.reshape(e_in, inner.shape)], -1)
            if not last:  # a sharp tool corner leaves a step to the next curve: a straight one
                end = self._xy(*curve(params[-1:]))[0]
                start = self._xy(*pieces[i + 1][1](pieces[i + 1][2][:1]))[0]
                if np.hypot(*(end - start)) > 1e-3 * self.gear.module:
                    a = self._xy(*curve(params[-2:-1]))[0]
                    c = a + between[:, None] * (start - a)
                    mid[-1] = np.stack([np.hypot(c[:, 0], c[:, 1]), np.arctan2(c[:, 0], c[:, 1])],
                                       -1)  # fmt: skip
            mids.append(mid)
        width = max(m.shape[1] for m in mids)  # rows of one width: the last point repeated
        mids = [np.concatenate([m, np.repeat(m[:, -1:], width - m.shape[1], 1)], 1) for m in mids]
        rho, eta, mid = np.concatenate(rhos), np.concatenate(etas), np.concatenate(mids)
        rho, eta = one_sided(rho, eta, mid[..., 0], mid[..., 1], self.tool.s < 0)
        return rho, eta, np.concatenate(kinds)

    def _involute_rolls(self, r0: float, r1: float, tol: float) -> np.ndarray:
        """Roll parameters t = tan(alpha_y) of :meth:`_involute_samples`."""
        t0 = math.sqrt(max(r0 * r0 - self.rb**2, 0.0)) / self.rb
        t1 = math.sqrt(max(r1 * r1 - self.rb**2, 0.0)) / self.rb
        return involute_rolls(self.rb, t0, t1, _SAFETY * tol)

    def tooth_points(self, tolerance: float = 0.001) -> np.ndarray:
        """One tooth, centred on the +x axis, from the space centre at -pi/z to the space centre
        at +pi/z, counter-clockwise (for an internal gear the 'tooth' is the ring's)."""
        cache = self.__dict__.setdefault("_teeth", {})
        if tolerance in cache:
            return cache[tolerance]
        rho, eta, _ = self.half_space(tolerance)
        half = math.pi / self.z
        theta = half - eta  # angle from the tooth centre line, on the counter-clockwise flank
        # counter-clockwise flank runs tip -> root when walking counter-clockwise
        ccw = np.stack([rho * np.cos(theta), rho * np.sin(theta)], axis=-1)[::-1]
        cw = ccw[::-1] * np.array([1.0, -1.0])
        cache[tolerance] = out = np.concatenate([cw[:-1], ccw])
        return out

    def vertices(self, tolerance: float = 0.001) -> float:
        """Vertices of the whole toothed boundary at ``tolerance``: one tooth's samples times z
        (the estimate :func:`gears.budget.check_budget` holds an outline to)."""
        return float((len(self.tooth_points(tolerance)) - 1) * self.z)

    def ring(self, tolerance: float = 0.001, angle: float = 0.0) -> np.ndarray:
        """The whole toothed boundary (closed ring without the repeated point), counter-clockwise,
        with tooth 0 centred at ``angle`` radians; refused over the outline budget."""
        tol = check_tolerance(tolerance, module=self.gear.module)
        check_budget("outline", f"the outline of z = {self.z}", self.vertices, tol)
        tooth = self.tooth_points(tol)[:-1]
        step = 2 * math.pi / self.z
        angles = angle + step * np.arange(self.z)
        c, s = np.cos(angles)[:, None], np.sin(angles)[:, None]
        x = c * tooth[None, :, 0] - s * tooth[None, :, 1]
        y = s * tooth[None, :, 0] + c * tooth[None, :, 1]
        return np.stack([x.ravel(), y.ravel()], axis=-1)


def tooth_profile(gear, backlash: float = 0.0) -> ToothProfile:
    """The exact profile of ``gear`` (see :class:`ToothProfile`)."""
    return ToothProfile(gear, backlash)


def undercut_form_diameter(gear) -> float:
    """Diameter where the generated fillet meets (or cuts) the involute, in mm.

    For an undercut gear this is where the trochoid offset crosses the involute (found by Brent's
    method, not by sampling); otherwise it is the tangency point, equal to the closed form of
    ISO 21771's form diameter.

    Examples
    --------
    >>> from gears import Gear
    >>> round(undercut_form_diameter(Gear(20, 2)), 4)   # the closed form: 37.6401
    37.6401
    >>> d = undercut_form_diameter(Gear(8, 1))          # undercut: above the base circle
    >>> round(d, 4) > round(Gear(8, 1).base_diameter, 4)
    True
    """
    return 2.0 * ToothProfile(gear).form_radius


def outline(
    gear, tolerance: float = 0.001, backlash: float = 0.0, bore: float | None = None,
    rim: float | None = None, angle: float = 0.0, center=(0.0, 0.0), cutter=None,
) -> shapely.Polygon:  # fmt: skip
    """Analytic outline of ``gear`` as a shapely Polygon (transverse section, mm).

    Parameters
    ----------
    gear : Gear
    tolerance : float
        Largest chordal deviation from the exact curves, mm.
    backlash : float
        Normal backlash of the pair, mm; this gear's teeth are thinned by half of it.
    bore : float or None
        Bore diameter of an external gear (a hole), mm.
    rim : float or None
        Rim width of an internal gear outside its root circle, mm (default 3 m_n).
    angle : float
        Rotation in degrees; at 0 tooth 0 is centred on the +x axis (a ring's tooth too).
    center : (float, float)
        Position of the gear axis.
    cutter : ShaperCutter or None
        None: the gear's own ``cutter`` if it has one, else its rack tool (for an internal gear
        the rack limit). A :class:`gears.cutting.cutter.ShaperCutter`: the outline that shaper
        leaves
        (its fillet and root circle).

    Returns
    -------
    shapely.Polygon
        External gear: the toothed disc (with the bore as a hole). Internal gear: the ring, its
        outer circle at d_f + 2 rim, the toothed boundary as its hole.

    Examples
    --------
    >>> from gears import Gear
    >>> p = outline(Gear(20, 1), tolerance=0.01)
    >>> p.is_valid, round(p.area / (math.pi * 10**2), 2)   # teeth and spaces nearly balance
    (True, 0.98)
    """
    tol = check_tolerance(tolerance, module=gear.module)
    angle = check_angle("angle", angle)
    center = check_point("center", center)
    _refuse_protuberance(gear)
    prof = profile_of(gear, cutter, backlash)
    check_blank(gear, bore, rim, prof.rf)
    pts = prof.ring(tol, math.radians(angle))
    return assemble(gear, pts, tol, bore, rim, center, prof.rf)


def profile_of(gear, cutter=None, backlash: float = 0.0) -> ToothProfile:
    """The exact profile of ``gear``: its shaper ``cutter`` (or the gear's own) when there is
    one, else its rack tool (:class:`ShaperProfile` or :class:`ToothProfile`)."""
    if cutter is None:
        cutter = getattr(gear, "cutter", None)
    if cutter is None:
        return ToothProfile(gear, backlash)
    return ShaperProfile(gear, cutter, backlash)


def outline_vertices(gear, tolerance: float, backlash: float = 0.0, bore: float | None = None,
                     rim: float | None = None, cutter=None) -> float:  # fmt: skip
    """Vertices of :func:`outline` at ``tolerance`` (one tooth sampled, times z, plus the rim
    or bore circle), without drawing it: the estimate budgets are checked on."""
    prof = profile_of(gear, cutter, backlash)
    n = prof.vertices(tolerance)
    bd, width = check_blank(gear, bore, rim, prof.rf)
    if width is not None:
        n += circle_segments(prof.rf + width, tolerance)
    elif bd is not None:
        n += circle_segments(bd / 2, tolerance)
    return n


class ShaperProfile(ToothProfile):
    """Exact half-space boundary of ``gear`` cut by ``cutter`` (see the module docstring).

    Same interface as :class:`gears.cutting.profile.ToothProfile`: ``fillet(tau)`` runs over the
    cutter's
    tip round (``0 <= tau <= 1``, tip-land end to flank tangency) and, for an undercut external
    gear, over the cutter's involute down to the point conjugate to N1 (``1 < tau <= 2``).
    """

    def __init__(self, gear, cutter: ShaperCutter | None = None, backlash: float = 0.0) -> None:
        self.gear = gear
        b = self.backlash = check_backlash(gear, backlash)
        if cutter is None:
            cutter = getattr(gear, "cutter", None) or ShaperCutter.default_for(gear)
        self.cutter = cutter
        if not isinstance(self.cutter, ShaperCutter):
            raise GearError(f"cutter = {cutter!r}; valid is a ShaperCutter or None")
        self.tool = ShaperTool(gear, self.cutter, b)
        self.z = gear.teeth
        self.rb = gear.base_diameter / 2
        self.ra = gear.tip_diameter / 2
        self.rf = self.tool.root_radius
        self.alpha_t = math.radians(gear.transverse_pressure_angle)
        self.eta_p = space_half_angle(gear, b)
        self._validate()

    @property
    def undercut(self) -> bool:
        return self.tool.undercuts

    @property
    def v_limit(self) -> float:  # pragma: no cover - rack-only notion
        raise GearError("v_limit is a rack-tool quantity; a shaper profile has undercut_roll")

    def fillet(self, tau):
        t = self.tool
        tau = np.asarray(tau, float)
        on_round = tau <= 1.0
        g = t.gamma_tip + np.minimum(tau, 1.0) * (t.gamma_flank - t.gamma_tip)
        pr, nr = t.round_points(g)
        tr = t.t_f + (np.maximum(tau, 1.0) - 1.0) * (t.undercut_roll - t.t_f)
        pf, nf = t.flank_points(tr)
        p = np.where(on_round[..., None], pr, pf)
        n = np.where(on_round[..., None], nr, nf)
        return t.envelope(p, n)

    @property
    def has_round(self) -> bool:
        return True

    @cached_property
    def _tangent_radius(self) -> float:
        return float(self.fillet(1.0)[0])

    def _land_angle(self) -> float:
        return float(self.fillet(0.0)[1])

    def flank_contact(self, rho_w):
        """Work rotation (rad) at which the space's right flank is cut at radius ``rho_w``
        (rho_w is the work involute's curvature radius), and the cutter's curvature radius
        there: ``(phi, rho_t)``. phi = eta(r_w) + s (t - tan alpha_w0) (see the module notes)."""
        t = self.tool
        eta_w = float(self.eta_involute(t.rw))
        phi = eta_w + t.s * (np.asarray(rho_w) / self.rb - math.tan(t.alpha_w))
        rho_t = t.s * (t.length - np.asarray(rho_w))
        return phi, rho_t
