"""Layer 9, classes: :class:`BevelGear`, one gear of a :class:`gears.bevel.pair.BevelPair` as a thin
view of its row of :func:`gears.bevel.cone.bevel_geometry` (its tooth on the sphere, its solid,
its findings), and :class:`VirtualGear`, the virtual (Tredgold) spur gear of a bevel gear.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from gears.arguments import check_flag, check_positive, check_tolerance
from gears.bevel.solid import BevelBlank, bevel_solid, solid_estimate
from gears.bevel.spherical import SphericalTooth
from gears.checks import pointed_tip_margin
from gears.errors import GearError
from gears.gear import Gear
from gears.geometry import check_real
from gears.report import Finding, Report

if TYPE_CHECKING:
    import trimesh

__all__ = ["BevelGear", "VirtualGear"]


@dataclass(frozen=True)
class VirtualGear(Gear):
    """The virtual (Tredgold) spur gear of a bevel gear: ``z_v = z / cos delta`` teeth of the
    mean module, in general not a whole number (Ozols (21.36)).

    It has every formula and check of :class:`gears.Gear` but no outline or mesh (a gear of
    22.36 teeth does not close); draw the bevel gear itself (:meth:`BevelGear.mesh`).

    Examples
    --------
    >>> v = VirtualGear(22.360680, 2.5)
    >>> round(v.reference_diameter, 4)
    55.9017
    """

    @staticmethod
    def _valid_teeth(z) -> float:
        return check_real("teeth", z, 0.0)

    def outline(self, *args, **kwargs):
        raise GearError(
            f"a virtual gear of z_v = {self.teeth:.4f} teeth has no outline; draw the bevel gear "
            "(BevelGear.mesh, BevelPair.scene)"
        )

    def mesh(self, *args, **kwargs):
        raise GearError(
            f"a virtual gear of z_v = {self.teeth:.4f} teeth has no mesh; mesh the bevel gear "
            "(BevelGear.mesh, BevelPair.scene)"
        )


def _backlash(backlash, thickness: float) -> float:
    """The pair's normal backlash at the mean cone, 0 <= j < the tooth's normal thickness."""
    j = check_real("backlash", backlash, 0.0, low_open=False)
    if not j < thickness:
        raise GearError(
            f"backlash = {j:g} mm; valid is 0 <= backlash < {thickness:.4f} mm (the mean tooth "
            "thickness: a larger backlash leaves no tooth)"
        )
    return j


@dataclass(frozen=True)
class BevelGear:
    """One gear of a :class:`gears.bevel.pair.BevelPair` (``pair.g1``, ``pair.g2``): a thin view
    of its row of :func:`gears.bevel.cone.bevel_geometry`. Lengths in mm, angles in degrees; outer
    values unless the name says mean.

    Examples
    --------
    >>> from gears import BevelPair
    >>> g = BevelPair(20, 40, module=3, face_width=22, clearance="tapered").g2
    >>> g.teeth, round(g.pitch_angle, 5), round(g.tip_diameter, 4), round(g.root_angle, 5)
    (40, 63.43495, 122.6833, 60.23535)
    """

    pair: BevelPair  # noqa: F821 - the pair (gears.bevel.pair, the layer above) holds its gears
    index: int

    def _row(self, field: str) -> float:
        return float(np.asarray(getattr(self.pair.geometry, field))[self.index])

    @property
    def mate(self) -> BevelGear:
        """The other gear of the pair."""
        return self.pair.g2 if self.index == 0 else self.pair.g1

    @property
    def teeth(self) -> int:
        return self.pair.z2 if self.index else self.pair.z1

    @property
    def z(self) -> int:
        return self.teeth

    @property
    def module(self) -> float:
        """Outer transverse module m_et."""
        return self.pair.module

    @property
    def face_width(self) -> float:
        return self.pair.face_width

    @property
    def pressure_angle(self) -> float:
        return self.pair.pressure_angle

    @property
    def helix_angle(self) -> float:
        """0: straight teeth."""
        return 0.0

    @property
    def internal(self) -> bool:
        """True for an internal bevel gear (pitch angle above 90 deg)."""
        return self.pitch_angle > 90.0

    @property
    def profile_shift(self) -> float:
        """x_hm (the wheel's is the pinion's negative)."""
        return self._row("profile_shift")

    @property
    def thickness_modification(self) -> float:
        """x_sm (the wheel's is the pinion's negative)."""
        return self._row("thickness_modification")

    @property
    def pitch_angle(self) -> float:
        return self._row("pitch_angle")

    @property
    def cone_distance(self) -> float:
        return self.pair.cone_distance

    @property
    def reference_diameter(self) -> float:
        """Outer pitch diameter d_e = m_et z."""
        return self._row("reference_diameter")

    @property
    def mean_diameter(self) -> float:
        return self._row("mean_diameter")

    @property
    def addendum(self) -> float:
        """Outer addendum h_ae."""
        return self._row("addendum")

    @property
    def dedendum(self) -> float:
        """Outer dedendum h_fe."""
        return self._row("dedendum")

    @property
    def addendum_angle(self) -> float:
        return self._row("addendum_angle")

    @property
    def dedendum_angle(self) -> float:
        return self._row("dedendum_angle")

    @property
    def face_angle(self) -> float:
        """Face (tip) cone angle delta_a = delta + theta_a."""
        return self._row("face_angle")

    @property
    def root_angle(self) -> float:
        """Root cone angle delta_f = delta - theta_f."""
        return self._row("root_angle")

    @property
    def tip_diameter(self) -> float:
        """Outside diameter d_ae at the outer end."""
        return self._row("tip_diameter")

    @property
    def inner_tip_diameter(self) -> float:
        return self._row("inner_tip_diameter")

    @property
    def crown_to_apex(self) -> float:
        """Pitch apex to crown, X = R_e cos delta - h_ae sin delta."""
        return self._row("crown_to_apex")

    @property
    def axial_face_width(self) -> float:
        return self._row("axial_face_width")

    @property
    def mean_thickness(self) -> float:
        """Tooth thickness s_m, an arc on the mean pitch cone (ISO 23509)."""
        return self._row("mean_thickness")

    @property
    def virtual_teeth(self) -> float:
        """z_v = z / cos delta."""
        return self._row("virtual_teeth")

    def _tip_land_finding(self, min_tip_land: float) -> Finding:
        """The normal tip land at the outer and the inner end (the virtual gear of each end;
        the thickness scales with the cone distance, the addendum follows the face cone)."""
        p, g = self.pair, self.pair.geometry
        i = self.index
        r_e = float(g.cone_distance)
        x_eq = self.profile_shift + self.thickness_modification / (
            2.0 * math.tan(math.radians(p.pressure_angle))
        )
        zv = abs(self.virtual_teeth)
        worst, where = math.inf, ""
        if not math.isfinite(zv):
            return Finding(
                f"g{i + 1}.tip_land_ends", math.inf, "a crown gear: no tip to check", ok=True
            )
        for end, r, h_a in (
            ("outer", r_e, self.addendum),
            ("inner", r_e - p.face_width, float(g.inner_addendum[i])),
        ):
            m = p.module * r / r_e
            d_va = zv * m + 2.0 * h_a
            margin = float(pointed_tip_margin(zv, m, x_eq, p.pressure_angle, 0.0, False, d_va,
                                              min_tip_land))  # fmt: skip
            if margin < worst:
                worst, where, at_m = margin, end, m
        need = min_tip_land * at_m
        return Finding(
            f"g{i + 1}.tip_land_ends", worst,
            f"normal tip land at the {where} end {worst + need:.4f} mm vs required {need:.4f} mm "
            f"({min_tip_land:g} m of that end; virtual gears of both ends)",
        )  # fmt: skip

    # --- teeth and solids ----------------------------------------------------------------------
    def tooth(self, backlash: float = 0.0) -> SphericalTooth:
        """The exact tooth space on the unit sphere (:class:`gears.bevel.spherical.SphericalTooth`),
        generated by the pair's crown gear: this gear's half of the normal ``backlash`` (mm, at
        the mean cone) widens the crown tooth by ``j / (4 cos alpha)`` on each flank."""
        j = _backlash(backlash, self.mean_thickness)
        cache = self.pair._teeth  # the tooth's envelope roots are worth keeping (immutable)
        key = (self.index, j)
        if key not in cache:
            if len(cache) > 8:
                cache.clear()
            cache[key] = self._tooth(j)
        return cache[key]

    def _tooth(self, j: float) -> SphericalTooth:
        p, g = self.pair, self.pair.geometry
        r_m, m_m = float(g.mean_cone_distance), float(g.mean_module)
        alpha = math.radians(p.pressure_angle)
        psi_p = (math.pi * m_m - self.mean_thickness) / (2.0 * r_m) + j / (
            4.0 * r_m * math.cos(alpha)
        )
        return SphericalTooth(
            self.teeth, math.radians(self.pitch_angle), alpha, psi_p,
            math.radians(self.dedendum_angle), p.tool_radius * m_m / r_m, p.profile,
        )  # fmt: skip

    def _largest_tool_radius(self) -> float:
        """The largest crown-tooth tip radius (mean modules) that leaves a tip land (bisection
        on the crown tooth's land longitude)."""
        p, g = self.pair, self.pair.geometry
        r_m, m_m = float(g.mean_cone_distance), float(g.mean_module)
        lo, hi = 0.0, max(p.tool_radius, 1e-6)
        base = dict(
            teeth=self.teeth, pitch_angle=math.radians(self.pitch_angle),
            pressure_angle=math.radians(p.pressure_angle),
            crown_half_thickness=(math.pi * m_m - self.mean_thickness) / (2.0 * r_m),
            root_angle=math.radians(self.dedendum_angle), kind=p.profile,
        )  # fmt: skip

        def fits(rho: float) -> bool:
            try:
                SphericalTooth(tool_radius=rho * m_m / r_m, **base)
            except GearError:
                return False
            return True

        for _ in range(40):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if fits(mid) else (lo, mid)
        return lo

    @property
    def blank(self) -> BevelBlank:
        """Cone angles (radians), cone distance, face width and heights for the solid."""
        return BevelBlank(
            math.radians(self.pitch_angle), math.radians(self.face_angle), self.cone_distance,
            self.face_width, self.addendum, self.dedendum, math.radians(self.dedendum_angle),
            self.module,
        )  # fmt: skip

    def mesh(
        self, tolerance: float = 0.01, bore: float | None = None, back_cone: bool = True,
        backlash: float = 0.0,
    ) -> trimesh.Trimesh:  # fmt: skip
        """The gear as a watertight ``trimesh.Trimesh`` (the ``mesh`` extra): axis +z, pitch
        apex at the origin, tooth 0 centred on +x; the teeth between the cone distances
        ``R_e - b`` and ``R_e`` (:func:`gears.bevel.solid.bevel_solid`).

        ``tolerance`` (mm) bounds the deviation from the exact octoid (or spherical involute)
        at the back end; ``bore`` a bore diameter (mm); ``back_cone`` ends the teeth on the
        back and front cones (True) or on planes normal to the axis (False); ``backlash`` is
        the pair's normal backlash at the mean cone (this gear takes half).

        Examples
        --------
        >>> from gears import BevelPair
        >>> m = BevelPair(20, 40, module=3, face_width=20).g1.mesh(tolerance=0.05)
        >>> m.is_watertight, m.is_winding_consistent, bool(m.volume > 0)
        (True, True, True)
        """
        tolerance = check_tolerance(tolerance, module=self.module)
        if bore is not None:
            bore = check_positive("bore", bore)
        back_cone = check_flag("back_cone", back_cone)
        return bevel_solid(self.tooth(backlash), self.blank, tolerance, bore, back_cone)

    def _vertices(self, back_cone: bool = True):
        """The solid's vertex count as a function of the tolerance (the budget's estimate)."""
        return solid_estimate(self.tooth(), self.blank, back_cone, 4)

    def check(self, min_tip_land: float = 0.2) -> Report:
        """This gear's findings of :meth:`gears.bevel.pair.BevelPair.check` (without the ``gN.``
        prefix)."""
        prefix = f"g{self.index + 1}."
        rep = self.pair.check(min_tip_land=min_tip_land)
        return Report(
            Finding(f.name[len(prefix) :], f.margin, f.message, f.unit, f.ok)
            for f in rep.values()
            if f.name.startswith(prefix)
        )

    def __repr__(self) -> str:
        return f"BevelGear({self.teeth} teeth of {self.pair!r})"
