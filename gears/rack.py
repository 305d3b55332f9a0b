"""The basic rack (ISO 53) and the generating tool derived from it.

All lengths of a :class:`BasicRack` are coefficients of the normal module (``addendum = 1.0``
means ``h_aP = 1.0 m_n``). The generating tool (rack cutter, hob) is the rack's mirror image: its
addendum is the rack's dedendum ``h_aP0 = h_fP`` and its tip radius is the rack's root radius
``rho_aP0 = rho_fP`` (standards.md §1.1).

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

from gears.errors import GearError

__all__ = ["BasicRack"]

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
        the outlines of :mod:`gears.profile` and :mod:`gears.generate` do not model it yet and
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
            raise GearError(
                f"dedendum = {self.dedendum} m at {self.pressure_angle} deg leaves the tool no tip "
                f"land (tool tooth thickness at its tip <= 0); reduce the dedendum"
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
        """Largest tool tip radius that still leaves a (zero-width) flat tool tip land.

        Half the tool tooth at its tip line is ``pi/4 - h_fP tan(alpha)``; a tip round of radius
        rho consumes ``rho (1 - sin alpha) / cos alpha`` of it.
        """
        a = math.radians(self.pressure_angle)
        half_land = math.pi / 4 - self.dedendum * math.tan(a)
        return half_land * math.cos(a) / (1.0 - math.sin(a))

    @property
    def straight_flank_depth(self) -> float:
        """h*_eff = h_aP0* - rho_aP0* (1 - sin alpha): depth below the reference line where the
        tool's straight flank ends. It sets the undercut limit and the form circle
        (standards.md §1.1)."""
        return self.dedendum - self.root_radius * (
            1.0 - math.sin(math.radians(self.pressure_angle))
        )
