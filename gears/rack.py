"""Layer 3, generating tools: the basic rack (ISO 53) and the rack tool derived from it.

All lengths of a :class:`BasicRack` are coefficients of the normal module (``addendum = 1.0``
means ``h_aP = 1.0 m_n``). The generating tool (rack cutter, hob) is the rack's mirror image: its
addendum is the rack's dedendum ``h_aP0 = h_fP`` and its tip radius is the rack's root radius
``rho_aP0 = rho_fP`` (ISO 53).

Examples
--------
>>> a = BasicRack.iso53("A")
>>> a.pressure_angle, a.addendum, a.dedendum, a.root_radius
(20.0, 1.0, 1.25, 0.38)
>>> round(a.straight_flank_depth, 4)
1.0
>>> round(BasicRack.iso53("D").straight_flank_depth, 4)
1.1434
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from gears.errors import GearError

__all__ = ["BasicRack", "RackTool", "max_root_radius"]


def max_root_radius(pressure_angle, dedendum):
    """Largest tool tip radius rho_fP* (module units) that still leaves a (zero-width) flat tool
    tip land, for the rack's pressure angle (degrees) and dedendum h_fP* (arrays broadcast).

    Half the tool tooth at its tip line is ``pi/4 - h_fP tan(alpha)``; a tip round of radius
    rho consumes ``rho (1 - sin alpha) / cos alpha`` of it.

    >>> round(float(max_root_radius(20, 1.25)), 4), round(float(max_root_radius(30, 1.25)), 4)
    (0.4719, 0.1103)
    """
    a = np.radians(pressure_angle)
    half_land = np.pi / 4 - np.asarray(dedendum, float) * np.tan(a)
    out = half_land * np.cos(a) / (1.0 - np.sin(a))
    return out[()] if np.ndim(out) == 0 else out


# ISO 53:1998 profiles: (h_fP*, rho_fP*); all have alpha_P = 20 deg, h_aP* = 1.0.
_ISO53 = {"A": (1.25, 0.38), "B": (1.25, 0.30), "C": (1.25, 0.25), "D": (1.40, 0.39)}


@dataclass(frozen=True)
class BasicRack:
    """A basic rack profile; lengths are coefficients of the normal module.

    Parameters
    ----------
    pressure_angle : float
        Profile angle alpha_P in degrees, 0 < alpha_P < 45.
    addendum : float
        h_aP* (the gear's addendum; 1.0 for ISO 53, 0.8 for the stub tooth).
    dedendum : float
        h_fP* (the gear's dedendum, the tool's addendum), >= addendum.
    root_radius : float
        rho_fP* (the tool's tip radius); at most the radius that keeps a tool tip land.
    name : str
        Label shown in reports.
    protuberance : float
        Protuberance of the tool flank near its tip, in module units (0 = none). Recorded only:
        the outlines of :mod:`gears.cutting.profile` and :mod:`gears.cutting.generate` do not model
        it yet and
        refuse a rack with a protuberance rather than draw it without one.

    Raises
    ------
    GearError
        If a value is outside its valid range; the message names it.
    """

    pressure_angle: float = 20.0
    addendum: float = 1.0
    dedendum: float = 1.25
    root_radius: float = 0.38
    name: str = "custom"
    protuberance: float = 0.0

    def __post_init__(self) -> None:
        for field_name in ("pressure_angle", "addendum", "dedendum", "root_radius", "protuberance"):
            value = getattr(self, field_name)
            if not isinstance(value, int | float) or not math.isfinite(value):
                raise GearError(f"BasicRack {field_name} must be a finite number; got {value!r}")
            object.__setattr__(self, field_name, float(value))
        if not 0.0 < self.pressure_angle < 45.0:
            raise GearError(
                f"pressure_angle = {self.pressure_angle} deg; valid is 0 < pressure_angle < 45"
            )
        if self.addendum <= 0.0:
            raise GearError(f"addendum = {self.addendum} m; valid is > 0")
        if self.dedendum < self.addendum:
            raise GearError(
                f"dedendum = {self.dedendum} m < addendum = {self.addendum} m; the bottom "
                "clearance would be negative (valid: dedendum >= addendum)"
            )
        if self.root_radius < 0.0:
            raise GearError(f"root_radius = {self.root_radius} m; valid is >= 0")
        if self.protuberance < 0.0:
            raise GearError(f"protuberance = {self.protuberance} m; valid is >= 0")
        limit = self.max_root_radius
        if limit <= 0.0:
            # the tool's teeth come to a point where pi/4 = h_fP tan(alpha)
            steepest = math.degrees(math.atan(math.pi / (4 * self.dedendum)))
            deepest = math.pi / (4 * math.tan(math.radians(self.pressure_angle)))
            raise GearError(
                f"pressure_angle = {self.pressure_angle:g} deg is too steep for a tool of "
                f"dedendum {self.dedendum:g} m: its teeth come to a point; valid is "
                f"pressure_angle < {steepest:.2f} deg with this dedendum, or a rack with "
                f"dedendum < {deepest:.4f} m at {self.pressure_angle:g} deg"
            )
        if self.root_radius > limit + 1e-12:
            raise GearError(
                f"root_radius = {self.root_radius} m does not fit the tool tip; valid is "
                f"0 <= root_radius <= {limit:.4f} m for this pressure angle and dedendum"
            )

    @classmethod
    def iso53(cls, profile: str = "A") -> BasicRack:
        """ISO 53 profile ``"A"``, ``"B"``, ``"C"`` or ``"D"`` (alpha 20 deg, h_aP 1.0 m)."""
        key = str(profile).upper()
        if key not in _ISO53:
            raise GearError(f"ISO 53 profile {profile!r} unknown; valid are {sorted(_ISO53)}")
        dedendum, radius = _ISO53[key]
        return cls(20.0, 1.0, dedendum, radius, name=f"ISO 53 {key}")

    @classmethod
    def stub(cls, pressure_angle: float = 20.0) -> BasicRack:
        """The textbooks' stub tooth: h_a* = 0.8, c* = 0.3 (Ozols §21-5, Joldasbekov §10).

        The tool's tip round rho = c*/(1 - sin alpha) only forms the clearance and does not cut
        the involute (Joldasbekov §8), so the straight flank reaches h_a* = 0.8 and
        z_min = 2 * 0.8 / sin^2(20 deg) = 13.68 ("14", Ozols §21-5). A sharp-cornered tool
        (rho = 0) would reach 1.1 m and undercut up to z = 18.8.
        """
        c = 0.3
        rho = c / (1.0 - math.sin(math.radians(pressure_angle))) if 0 < pressure_angle < 45 else 0
        return cls(pressure_angle, 0.8, 0.8 + c, rho, name="stub 0.8")

    def with_pressure_angle(self, pressure_angle: float) -> BasicRack:
        """The same rack at another pressure angle; the root radius is capped to fit the tool."""
        trial = replace(self, pressure_angle=float(pressure_angle), root_radius=0.0)
        radius = min(self.root_radius, trial.max_root_radius)
        return replace(trial, root_radius=radius, name=f"{self.name} @ {pressure_angle:g} deg")

    @property
    def bottom_clearance(self) -> float:
        """c* = h_fP* - h_aP*."""
        return self.dedendum - self.addendum

    @property
    def tool_addendum(self) -> float:
        """h_aP0* of the generating tool = the rack's dedendum."""
        return self.dedendum

    @property
    def tool_tip_radius(self) -> float:
        """rho_aP0* of the generating tool = the rack's root radius."""
        return self.root_radius

    @property
    def max_root_radius(self) -> float:
        """Largest tool tip radius that still leaves a (zero-width) flat tool tip land
        (:func:`max_root_radius`)."""
        return float(max_root_radius(self.pressure_angle, self.dedendum))

    @property
    def straight_flank_depth(self) -> float:
        """h*_eff = h_aP0* - rho_aP0* (1 - sin alpha): depth below the reference line where the
        tool's straight flank ends. It sets the undercut limit and the form circle
        (ISO 53: ``h_aP0 - rho_aP0 (1 - sin alpha)``)."""
        return self.dedendum - self.root_radius * (
            1.0 - math.sin(math.radians(self.pressure_angle))
        )


@dataclass(frozen=True)
class RackTool:
    """The generating rack in the transverse section (lengths in mm).

    ``s = +1`` cuts an external gear (tool tip towards the axis), ``s = -1`` an internal one.
    The right half of the tool tooth (u >= 0) is: tip land ``0 <= u <= u_c`` at
    ``v = -s h``; a tip round, centre ``(u_c, v_c)``, semi-axes ``a`` (along u) and ``b``; the
    straight flank ``u = c + s v tan(alpha_t)`` from ``v_f`` upwards.
    """

    r: float  # reference radius (transverse)
    xm: float  # the tool line's offset from the reference circle, away from the axis: s x m_n
    s: float  # +1 external, -1 internal
    tan_a: float  # tan alpha_t
    c: float  # flank: u = c + s v tan_a (half tooth width at the tool reference line)
    h: float  # tool addendum h_aP0 m_n
    a: float  # round semi-axis along u
    b: float  # round semi-axis along v
    u_c: float
    v_c: float
    t_f: float  # round parameter where it meets the flank

    @classmethod
    def for_gear(cls, gear, backlash: float = 0.0) -> RackTool:
        mn = gear.module
        an = math.radians(gear.pressure_angle)
        at = math.radians(gear.transverse_pressure_angle)
        cb = math.cos(math.radians(gear.helix_angle))
        s = -1.0 if gear.internal else 1.0
        h = gear.rack.tool_addendum * mn
        rho = gear.rack.tool_tip_radius * mn
        if rho < 1e-9 * mn:  # a round this small is a sharp corner (its normals would underflow)
            rho = 0.0
        delta = backlash / (4.0 * math.cos(at))
        v_c = -s * (h - rho)
        # tangency in the normal section, then stretched by 1/cos(beta) along the pitch line
        u_c = (math.pi * mn / 4 - (h - rho) * math.tan(an) - rho / math.cos(an)) / cb + delta
        a, b = rho / cb, rho
        t_f = -math.atan(math.tan(at) * b / a) if rho > 0 else -at
        return cls(
            # xm: the tool's offset away from the axis; a ring's positive shift (DIN 3960)
            # moves it towards the axis
            r=gear.reference_diameter / 2, xm=s * gear.profile_shift * mn, s=s,
            tan_a=math.tan(at),
            c=math.pi * gear.transverse_module / 4 + delta, h=h, a=a, b=b, u_c=max(u_c, 0.0),
            v_c=v_c, t_f=t_f,
        )  # fmt: skip

    @property
    def v_f(self) -> float:
        """Tool height where the round ends and the straight flank starts."""
        return self.v_c + self.s * self.b * math.sin(self.t_f)

    def envelope(self, u, v, nu, nv):
        """Gear-frame points generated by tool points (u, v) with normals (nu, nv).

        Returns ``(rho, eta, phi)``: radius, angle from the space centre line (clockwise, i.e.
        into the right flank), roll angle of contact.
        """
        phi = ((v + self.xm) * nu / nv - u) / self.r
        x0 = u + self.r * phi
        y0 = self.r + self.xm + v
        c, s_ = np.cos(phi), np.sin(phi)
        px, py = c * x0 - s_ * y0, s_ * x0 + c * y0
        return np.hypot(px, py), np.arctan2(px, py), phi

    def place(self, pts, phi):
        """Tool points ``pts`` (n, 2) rolled to angles ``phi`` (k,) in the gear frame: (k, n, 2)
        (rolling without slip on the reference circle: Q(phi) = Rot(phi) (u + r phi, r + x m +
        v))."""
        phi = np.asarray(phi, float)[:, None]
        c, s_ = np.cos(phi), np.sin(phi)
        x0 = pts[None, :, 0] + self.r * phi
        y0 = self.r + self.xm + pts[None, :, 1]
        return np.stack([c * x0 - s_ * y0, s_ * x0 + c * y0], axis=-1)

    def round_points(self, t):
        t = np.asarray(t, float)
        u = self.u_c + self.a * np.cos(t)
        v = self.v_c + self.s * self.b * np.sin(t)
        if self.a == 0:  # sharp tool corner: its normals fan from the tip land to the flank
            return u, v, np.cos(t), self.s * np.sin(t)
        return u, v, self.b * np.cos(t), self.s * self.a * np.sin(t)

    def flank_points(self, v):
        v = np.asarray(v, float)
        u = self.c + self.s * v * self.tan_a
        cos_a = 1.0 / math.sqrt(1.0 + self.tan_a**2)
        return u, v, np.full_like(v, cos_a), np.full_like(v, -self.s * self.tan_a * cos_a)
