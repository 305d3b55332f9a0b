"""Layer 3, generating tools: the shaper (pinion-type, Fellows) cutter and its own geometry.

A shaper cutter is an involute gear of ``z0`` teeth with a long addendum (``h_a0 = 1.25 m_n`` by
default, the rack tool's), tip rounds of radius ``rho_a0`` tangent to its flanks and its tip
circle, and a profile shift ``x0``. Work and cutter turn as a gear pair at zero backlash
(Ozols §21-6, the Fellows method; Joldasbekov §2.8: "an involute generating contour also
generates an involute"), on the cutting centre distance::

    inv alpha_w0 = 2 tan alpha_n (x + x0) / (z +- z0) + inv alpha_t,
    a0 = m_t |z +- z0| / 2 * cos alpha_t / cos alpha_w0          (+ external, - internal work)

(ISO 21771's working pressure angle, the cutter as the mating gear; a ring's x in DIN 3960's
sign). Hence the shaper-cut root circle
``d_f = 2 (a0 - r_a0)`` (external) or ``2 (a0 + r_a0)`` (internal), which differs from the rack
formula unless ``x + x0 = 0`` (``x = -x0``, external and internal work alike)
(:meth:`ShaperCutter.root_diameter`), and the form circle where the cutter's involute ends
(:meth:`ShaperCutter.form_diameter`).

**Envelope in closed form** (the same meshing condition as for the rack; Litvin & Fuentes): a
cutter point ``p`` with outward normal ``n`` touches the work when its normal passes through the
pitch point, i.e. when the point ``Q = p + lambda n`` where the normal meets the cutter's working
circle (radius ``r_w0``; ``lambda = -p.n + sqrt(r_w0^2 - (p x n)^2)``, the root on the contact's
side) is turned onto the line of centres. The cutter angle follows directly, the work angle from
the ratio, and the generated point by two rotations - no iteration. Applied to the tip round it
gives the fillet (the offset of the epi- or hypotrochoid of the round's centre), to the tip circle
the root circle, to the involute flank the work's involute, and, past the line-of-action limit
point, the undercut.

:class:`gears.cutting.profile.ShaperProfile` plugs this tool into
:class:`gears.cutting.profile.ToothProfile`, so
the sampling to a tolerance, undercut crossing and tip handling are shared with the rack outline.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from gears.errors import GearError
from gears.geometry import base_diameter, half_angle_at_reference, tip_diameter
from gears.involute import inv
from gears.meshing import internal_interference, pair_geometry
from gears.report import Finding, Report

__all__ = ["ShaperCutter", "ShaperTool"]

# A "3 inch" (76 mm) disc cutter is the common Fellows size; the default cutter is the nearest
# tooth count to that pitch diameter, within these bounds.
_DEFAULT_PITCH_DIAMETER = 76.0
_DEFAULT_TEETH = (12, 100)


@dataclass(frozen=True)
class ShaperCutter:
    """A pinion-type cutter; lengths are coefficients of the work's normal module.

    The cutter takes its module, pressure angle and helix angle from the gear it cuts (a helical
    gear is cut by a helical cutter; its transverse section is simulated).

    Parameters
    ----------
    teeth : int
        z0, at least 5.
    shift : float
        Profile shift x0 of the cutter (a resharpened cutter has a smaller one).
    addendum : float or None
        h_a0* (tip height above the reference circle before the shift); None takes the work's
        rack tool addendum (1.25 for ISO 53), so that ``teeth -> infinity`` gives the rack cutter.
    tip_radius : float or None
        rho_a0*, the tip-round radius; None takes the work's rack tool tip radius (0.38 for ISO 53
        A). 0 gives a sharp-cornered cutter.

    Examples
    --------
    >>> from gears import Gear
    >>> c = ShaperCutter(25)
    >>> g = Gear(40, 2)
    >>> round(c.center_distance(g), 6), round(c.root_diameter(g), 6)   # x = x0 = 0: as a rack
    (65.0, 75.0)
    >>> ShaperCutter.default_for(Gear(80, 2, internal=True)).teeth     # 76 mm / 2 mm, <= z/2
    38
    """

    teeth: int
    shift: float = 0.0
    addendum: float | None = None
    tip_radius: float | None = None

    def __post_init__(self) -> None:
        z0 = self.teeth
        if isinstance(z0, bool) or not isinstance(z0, int | np.integer) or z0 < 5:
            raise GearError(f"z0 = {z0!r} cutter teeth; valid is an integer >= 5")
        object.__setattr__(self, "teeth", int(z0))
        for name in ("shift", "addendum", "tip_radius"):
            v = getattr(self, name)
            if v is None and name != "shift":
                continue
            if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v):
                raise GearError(f"cutter {name} = {v!r}; valid is a finite number")
            object.__setattr__(self, name, float(v))
        if self.addendum is not None and self.addendum <= 0:
            raise GearError(f"cutter addendum = {self.addendum}; valid is > 0 (module units)")
        if self.tip_radius is not None and self.tip_radius < 0:
            raise GearError(f"cutter tip_radius = {self.tip_radius}; valid is >= 0")

    @classmethod
    def default_for(cls, gear: Any) -> ShaperCutter:
        """The cutter used when none is given: the tooth count nearest a 76 mm pitch diameter,
        between 12 and 100 teeth, and for an internal gear at most half the ring's teeth (so the
        cutter clears the ring's tips on its way out). For a ring, the nearest such cutter that
        passes its own :meth:`check` (no trimming, no tip past N1, radial infeed) is taken, so
        the default never rounds or trims the ring it cuts when a cutter exists that does not
        (issue 11: a 12-tooth default rounded a z = 215, m = 10 ring's tips by 19 tolerances).
        """
        z0 = round(_DEFAULT_PITCH_DIAMETER / gear.transverse_module)
        low, high = _DEFAULT_TEETH
        z0 = min(max(z0, low), high)
        if not gear.internal:
            return cls(z0)
        high = min(high, gear.teeth // 2)
        if high < 5:
            raise GearError(
                f"internal z = {gear.teeth}: no default shaper cutter fits (it needs at most "
                "z/2 >= 5 teeth); pass cutter=ShaperCutter(...)"
            )
        low = min(low, high)
        z0 = min(z0, high)
        for candidate in sorted(range(low, high + 1), key=lambda k: (abs(k - z0), k)):
            if cls(candidate).check(gear).ok:
                return cls(candidate)
        return cls(z0)

    # --- geometry with a given work gear ------------------------------------------------------
    def _h(self, gear) -> tuple[float, float]:
        h = gear.rack.tool_addendum if self.addendum is None else self.addendum
        rho = gear.rack.tool_tip_radius if self.tip_radius is None else self.tip_radius
        return h, rho

    def _mesh(self, gear):
        """The cutting mesh as a pair (cutter = gear 1): :func:`gears.meshing.pair_geometry`."""
        if gear.internal and gear.teeth - self.teeth < 1:
            raise GearError(
                f"z0 = {self.teeth} cutter teeth "
                f"for an internal gear of z = {gear.teeth}; valid is "
                "z0 < z"
            )
        return pair_geometry(
            self.teeth, gear.teeth, gear.module, self.shift, gear.profile_shift,
            gear.pressure_angle, gear.helix_angle, gear.internal, tip_shortening=False,
        )  # fmt: skip

    def working_pressure_angle(self, gear: Any) -> float:
        """alpha_w0 of the cutting mesh, degrees (transverse)."""
        return float(self._mesh(gear).working_pressure_angle)

    def center_distance(self, gear: Any) -> float:
        """Cutting centre distance a0 in mm."""
        return float(self._mesh(gear).center_distance)

    def tip_diameter_of_cutter(self, gear: Any) -> float:
        """d_a0 = m_t z0 + 2 (h_a0* + x0) m_n (:func:`gears.geometry.tip_diameter`)."""
        h, _ = self._h(gear)
        return float(tip_diameter(self.teeth, gear.module, self.shift, gear.helix_angle, h))

    def root_diameter(self, gear: Any) -> float:
        """Root diameter the cutter leaves on ``gear``: 2 (a0 -+ r_a0) (- external, + internal).

        >>> from gears import Gear
        >>> g = Gear(20, 1, profile_shift=0.5)
        >>> round(ShaperCutter(20).root_diameter(g), 4), g.root_diameter   # shaper vs rack
        (18.4251, 18.5)
        """
        a0, ra0 = self.center_distance(gear), self.tip_diameter_of_cutter(gear) / 2
        return 2 * (a0 + ra0) if gear.internal else 2 * (a0 - ra0)

    def form_diameter(self, gear: Any) -> float:
        """Diameter where the generated involute ends: the work point conjugate to the end of the
        cutter's involute (its tangency with the tip round), on the line of action.

        For an external gear whose conjugate point lies past the interference point N1 the flank
        is undercut and the form circle comes from the undercut crossing
        (:attr:`ShaperProfile.form_radius`); this method then returns the base diameter.
        """
        rho_w = ShaperTool(gear, self).form_roll_length
        rb = gear.base_diameter / 2
        return 2 * math.sqrt(rb * rb + max(rho_w, 0.0) ** 2)

    def check(self, gear: Any) -> Report:
        """Can this cutter cut ``gear``? A :class:`gears.Report` with

        * ``undercut`` (external gear): the cutter's involute must end before the interference
          point N1 (margin in mm along the cutting line of action);
        * ``trimming`` (internal gear): on its way out of a space the cutter tooth must clear
          the ring's tips (the KHK Gear Technical Reference's trochoid-interference condition, with
          the cutter as the pinion at the cutting centre distance; margin in rad). A failing margin
          beyond about -0.005 rad shows as cut-off ring tips in ``method='shaper'``;
        * ``tip_past_n1`` (internal gear): the ring's tip must not pass the cutter's
          interference point N1 (KHK involute-interference condition), else the cutter's
          non-involute root rounds the ring's tip corners (the simulation draws the cutter
          radial below its base circle, so it shows this only approximately);
        * ``radial_infeed`` (internal gear): the cutter can be fed in radially to full depth
          without cutting the ring's tips (KHK trimming condition; margin in rad). The
          simulation models generation at full depth only, so it does not show this one.

        >>> from gears import Gear
        >>> ring = Gear(40, 1, internal=True, profile_shift=-0.3)
        >>> ShaperCutter(20).check(ring).ok, ShaperCutter(37).check(ring).failed()
        (True, ['trimming', 'radial_infeed'])
        """
        if not gear.internal:
            margin = ShaperTool(gear, self).form_roll_length
            return Report(
                [
                    Finding(
                        "undercut", margin,
                        f"cutter z0 = {self.teeth}: its involute ends {margin:+.4f} mm before N1 "
                        "on the cutting line of action"
                        + ("" if margin >= 0 else " (it undercuts the flank)"),
                    )
                ]
            )  # fmt: skip
        # the cutter meshes with the ring as the pinion at the cutting centre distance
        rb0 = float(base_diameter(self.teeth, gear.module, gear.pressure_angle, gear.helix_angle))
        a0, ra0 = self.center_distance(gear), self.tip_diameter_of_cutter(gear) / 2
        found = internal_interference(
            self.teeth, gear.teeth, a0, ra0, gear.tip_diameter / 2, rb0 / 2,
            gear.base_diameter / 2, self.working_pressure_angle(gear),
        )  # fmt: skip
        out = []
        for margin, name, what, unit in [
            (found.involute, "tip_past_n1", "the ring's tip stays before the cutter's N1", ""),
            (found.trochoid, "trimming", "the cutter clears the ring's tips leaving", "rad"),
            (found.radial, "radial_infeed", "the cutter can be fed in radially", "rad"),
        ]:
            text = f"cutter z0 = {self.teeth}: {what}"
            out.append(Finding(name, float(margin), text, unit=unit))
        return Report(out)


def _wrap(a):
    return (a + math.pi) % (2 * math.pi) - math.pi


class ShaperTool:
    """A shaper cutter set up against one gear, in the transverse section (mm, radians).

    Cutter frame: cutter centre at the origin, the cutting tooth centred on the line towards the
    work (``-y`` for an external work gear, ``+y`` for an internal one); the work centre is at
    ``(0, -a0)`` from it. Fixed frame: work centre at the origin, cutter centre at ``(0, a0)``,
    pitch point ``(0, r_w)``.
    """

    def __init__(self, gear, cutter: ShaperCutter, backlash: float = 0.0) -> None:
        from scipy.optimize import brentq  # heavy: imported where used

        self.gear, self.cutter = gear, cutter
        self.s = -1.0 if gear.internal else 1.0
        self.sigma = -self.s  # cutter tooth direction in the cutter frame (+y internal)
        mt, mn = gear.transverse_module, gear.module
        self.z, self.z0 = gear.teeth, cutter.teeth
        at = math.radians(gear.transverse_pressure_angle)
        _, rho = cutter._h(gear)
        self.alpha_t = at
        self.r0 = mt * self.z0 / 2
        self.rb0 = self.r0 * math.cos(at)
        self.ra0 = cutter.tip_diameter_of_cutter(gear) / 2
        self.rho = rho * mn
        self.a0 = cutter.center_distance(gear)
        aw = math.radians(cutter.working_pressure_angle(gear))
        self.alpha_w = aw
        self.rw0 = self.rb0 / math.cos(aw)
        self.rw = (gear.base_diameter / 2) / math.cos(aw)
        self.length = self.a0 * math.sin(aw)  # N1 N2 on the line of action
        # half tooth angle on the cutter's base circle (flanks moved j/4 out for the backlash)
        psi = half_angle_at_reference(
            self.z0, cutter.shift, gear.pressure_angle, gear.helix_angle, False
        )
        self.psi_b = float(psi) + inv(at) + backlash / (4 * self.rb0)
        self.ratio = self.z0 / self.z
        # relative angular speed of cutter against work, per unit work rotation
        self.omega_rel = 1 + self.z / self.z0 if self.s > 0 else self.z / self.z0 - 1
        if cutter.tip_radius is None and self.rho > 0 and self._land(self.rho) <= 0:
            # the rack tool's round does not fit a small cutter's narrow tip: take the largest
            # round that leaves a land of 2 % of the round-free one
            free = self._land(0.0)
            if free > 0:
                self.rho = brentq(lambda r: self._land(r) - 0.02 * free, 0.0, self.rho)
        self._round()

    # --- the cutter tooth (right half, 'up' frame: tooth on +y, clockwise angles from +y) -----
    def _round_at(self, rho: float):
        """Tip round of radius ``rho`` tangent to the tip circle and the right flank:
        ``(t_f, n_in, centre)`` (flank roll angle at the tangency, inward flank normal there),
        or None when the round would reach below the base circle."""
        rc = self.ra0 - rho
        if rc <= self.rb0:
            return None
        t_f = (rho + math.sqrt(rc * rc - self.rb0 * self.rb0)) / self.rb0
        pf = self._flank_xy(t_f)
        tt = self._base_xy(t_f)  # the flank's centre of curvature lies inside the tooth
        n_in = (tt - pf) / np.hypot(*(tt - pf))
        return t_f, n_in, pf + rho * n_in

    def _land(self, rho: float) -> float:
        """Clockwise angle of the tip-round centre (> 0: the rounds leave a tip land)."""
        found = self._round_at(rho)
        return -1.0 if found is None else math.atan2(found[2][0], found[2][1])

    def _round(self) -> None:
        rho = self.rho
        found = self._round_at(rho)
        if found is None:
            raise GearError(
                f"shaper cutter z0 = {self.z0}: its tip round (rho = {rho:.4g} mm) would reach "
                f"below the cutter's base circle; use a smaller tip_radius or a larger addendum"
            )
        t_f, n_in, c = found
        self.t_f = t_f  # roll angle of the flank tangency
        self.rho_t_flank = self.rb0 * t_f  # cutter involute curvature radius at the tangency
        self.center_up = c
        self.gamma_tip = math.atan2(c[0], c[1])  # clockwise angle of the radial normal
        self.gamma_flank = math.atan2(-n_in[0], -n_in[1])
        if self.gamma_tip <= 0:
            raise GearError(
                f"shaper cutter z0 = {self.z0}, x0 = {self.cutter.shift:g}: its teeth are pointed "
                "(the tip rounds meet before the tip circle); use a smaller addendum, tip_radius "
                "or shift"
            )

    def _flank_xy(self, t):
        """Right-flank involute point at roll angle ``t`` (up frame)."""
        t = np.asarray(t, float)
        ang = self.psi_b - (t - np.arctan(t))
        rr = self.rb0 * np.sqrt(1 + t * t)
        return np.stack([rr * np.sin(ang), rr * np.cos(ang)], axis=-1)

    def _base_xy(self, t):
        ang = self.psi_b - np.asarray(t, float)
        return np.stack([self.rb0 * np.sin(ang), self.rb0 * np.cos(ang)], axis=-1)

    def flank_points(self, t):
        """Right-flank points and outward normals at roll ``t`` (cutter frame)."""
        p = self._flank_xy(t)
        n = p - self._base_xy(t)
        n = n / np.hypot(n[..., 0], n[..., 1])[..., None]
        return self._frame(p), self._frame(n)

    def round_points(self, gamma):
        """Right tip-round points and outward normals at normal angle ``gamma`` (cutter frame)."""
        g = np.asarray(gamma, float)
        n = np.stack([np.sin(g), np.cos(g)], axis=-1)
        return self._frame(self.center_up + self.rho * n), self._frame(n)

    def _frame(self, v):
        return v * np.array([1.0, self.sigma])

    @property
    def land_half_angle(self) -> float:
        """Half the angle of the cutter's tip land (its flat tip arc), radians."""
        return self.gamma_tip

    # --- envelope ------------------------------------------------------------------------------
    def envelope(self, p, n):
        """Work-frame points generated by cutter points ``p`` with outward normals ``n``.

        Returns ``(rho, eta, phi)``: radius, clockwise angle from the space centre line (+y),
        work rotation at contact.
        """
        px, py, nx, ny = p[..., 0], p[..., 1], n[..., 0], n[..., 1]
        lam = self.contact_lambda(p, n)
        qx, qy = px + lam * nx, py + lam * ny
        theta0 = _wrap(math.atan2(self.sigma * self.rw0, 0.0) - np.arctan2(qy, qx))
        phi = -self.s * theta0 * self.ratio
        c0, s0 = np.cos(theta0), np.sin(theta0)
        x = c0 * px - s0 * py
        y = s0 * px + c0 * py + self.a0
        c, s = np.cos(phi), np.sin(phi)
        wx, wy = c * x + s * y, -s * x + c * y
        return np.hypot(wx, wy), np.arctan2(wx, wy), phi

    def contact_lambda(self, p, n):
        """Signed distance along the normal from ``p`` to the pitch point at contact (where
        the normal line meets the cutter's working circle on the contact's side)."""
        px, py, nx, ny = p[..., 0], p[..., 1], n[..., 0], n[..., 1]
        dot = px * nx + py * ny
        cross = px * ny - py * nx
        return -dot + np.sqrt(np.maximum(self.rw0 * self.rw0 - cross * cross, 0.0))

    def place(self, pts, phi):
        """Cutter-frame points ``pts`` (n, 2) placed at work rotations ``phi`` (k,): (k, n, 2)."""
        phi = np.asarray(phi, float)[:, None]
        theta0 = -self.s * phi / self.ratio
        c0, s0 = np.cos(theta0), np.sin(theta0)
        x = c0 * pts[None, :, 0] - s0 * pts[None, :, 1]
        y = s0 * pts[None, :, 0] + c0 * pts[None, :, 1] + self.a0
        c, s = np.cos(phi), np.sin(phi)
        return np.stack([c * x + s * y, -s * x + c * y], axis=-1)

    @property
    def root_radius(self) -> float:
        return self.cutter.root_diameter(self.gear) / 2

    @property
    def form_roll_length(self) -> float:
        """Distance from N1 along the line of action to the work point conjugate to the end of
        the cutter's involute (its tangency with the tip round); negative past N1 (undercut)."""
        return self.length - self.s * self.rho_t_flank

    @property
    def undercuts(self) -> bool:
        """True when the cutter's involute reaches past N1 of an external work gear."""
        return self.s > 0 and self.form_roll_length < -1e-12 * self.length

    @property
    def undercut_roll(self) -> float:
        """Cutter roll angle whose conjugate point is the work's N1 (external only)."""
        return self.length / self.rb0
