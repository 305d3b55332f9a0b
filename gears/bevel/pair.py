"""Layer 10, classes: :class:`BevelPair` (its gears :class:`gears.bevel.gear.BevelGear`), straight
bevel gears as thin views over :mod:`gears.bevel.cone` (the cone formulas, ISO 23509 / DIN 3971).

A bevel gear exists only with its mate (the pitch cones follow from both tooth counts and the
shaft angle), so :class:`BevelGear` is a view of one member of a :class:`BevelPair`. The checks
are those of the virtual (Tredgold) spur pair at the mean cone (:attr:`BevelPair.virtual_pair`,
a :class:`gears.GearPair` of :class:`VirtualGear`) plus the bevel rules (face width, the tip land
at both ends of the face). The load capacity, after ISO 10300 method B1 through the virtual
cylindrical gears, is :meth:`BevelPair.rating` (:mod:`gears.bevel.rating`).
"""

from __future__ import annotations

import math
import os
import pathlib
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING, Any

import numpy as np

from gears.arguments import (
    check_angle,
    check_fps,
    check_frames,
    check_module,
    check_pressure_angle,
    check_tolerance,
)
from gears.bevel.cone import (
    CLEARANCES,
    BevelGeometry,
    bevel_geometry,
    check_shaft_angle,
    face_width_margins,
    full_round_radius,
    gleason_coefficients,
    max_face_width,
)
from gears.bevel.gear import BevelGear, VirtualGear
from gears.bevel.solid import bevel_placement
from gears.budget import check_budget
from gears.errors import GearError
from gears.forces import PairForces, bevel_pair_forces
from gears.geometry import check_real, check_teeth
from gears.mating import Rack
from gears.pair import GearPair
from gears.rack import BasicRack
from gears.report import Finding, Report
from gears.solid.mesh import COLOURS, scene
from gears.solid.render import ANIMATION_BUDGET_3D, DRAWN_PER_VERTEX

if TYPE_CHECKING:
    import trimesh

    from gears.bevel.rating import BevelRating

__all__ = [
    "ANIMATION_BUDGET_3D",
    "DRAWN_PER_VERTEX",
    "PROFILES",
    "BevelPair",
]

#: The tooth forms a bevel pair can be drawn with (docs/bevel.md, "Octoid or spherical involute").
PROFILES = ("octoid", "spherical_involute")


#: The smallest tool tip radius other than 0, mean modules: a round of 5e-324 modules left the
#: fillet's formulas with 0/0 (the LENGTH_RANGE floor of gears.arguments).
TOOL_RADIUS_FLOOR = 1e-6


def _number(name: str, value, low=None, high=None, low_open=True) -> float:
    return check_real(name, value, low, high, low_open=low_open)


def _placed(mesh, matrix) -> np.ndarray:
    """The mesh's vertices moved by a 4x4 placement."""
    return mesh.vertices @ matrix[:3, :3].T + matrix[:3, 3]


@dataclass(frozen=True, init=False)
class BevelPair:
    """A straight bevel gear pair on intersecting axes (ISO 23509 / DIN 3971); immutable.

    Parameters
    ----------
    z1, z2 : int
        Teeth of the pinion (gear 1) and the wheel (gear 2).
    module : float
        Outer transverse module m_et, mm (``d_e = m_et z`` at the outer end).
    face_width : float
        b, mm, along the pitch cone; ``0 < b < R_e`` (``b <= R_e / 3`` is checked as a
        finding).
    shaft_angle : float
        Sigma in degrees, 0 < Sigma < 180 (90: a right-angle pair).
    pressure_angle : float
        alpha of the generating crown gear, degrees (0 < alpha < 45).
    profile_shift : float
        x_hm1 of the pinion at the mean cone; the wheel has ``-x_hm1``.
    thickness_modification : float
        x_sm1 of the pinion; the wheel has ``-x_sm1``.
    addendum, dedendum : float
        k_hap and k_hfp (coefficients of the mean module; 1.0 and 1.25 by default).
    clearance : {"constant", "tapered"}
        ``"constant"``: each face cone parallel to the mate's root cone (ISO 23509, Gleason);
        ``"tapered"``: every cone meets the pitch apex (KHK's standard bevel gears).
    tool_radius : float or None
        Tip radius of the generating crown gear's teeth, in mean modules (it forms the root
        fillet); default the full round of the bottom clearance, ``(k_hfp - k_hap) /
        (1 - sin alpha)`` (0.38 for the default heights, ISO 53 A's value).
    profile : {"octoid", "spherical_involute"}
        The tooth form of the meshes: the octoid that a crown gear with plane flanks cuts (what
        straight-bevel generators cut) or the spherical involute (docs/bevel.md).

    Raises
    ------
    GearError
        For input no blank can carry, naming the value and the valid range: a face width at or
        beyond the cone distance, a root cone through the axis, unknown names.

    Examples
    --------
    KHK Table 4.10 (standard straight bevel gears):

    >>> p = BevelPair(20, 40, module=3, face_width=22, clearance="tapered")
    >>> [round(d, 5) for d in p.pitch_angles], round(p.cone_distance, 5)
    ([26.56505, 63.43495], 67.08204)
    >>> [round(z, 4) for z in p.virtual_teeth], round(p.contact_ratio, 4)
    ([22.3607, 89.4427], 1.7122)
    """

    z1: int
    z2: int
    module: float
    face_width: float
    shaft_angle: float
    pressure_angle: float
    profile_shift: float
    thickness_modification: float
    addendum: float
    dedendum: float
    clearance: str
    tool_radius: float
    profile: str

    def __init__(
        self, z1: int, z2: int, module: float, face_width: float, shaft_angle: float = 90.0,
        pressure_angle: float = 20.0, profile_shift: float = 0.0,
        thickness_modification: float = 0.0, addendum: float = 1.0, dedendum: float = 1.25,
        clearance: str = "constant", tool_radius: float | None = None, profile: str = "octoid",
    ) -> None:  # fmt: skip
        set_ = object.__setattr__
        set_(self, "_teeth", {})  # SphericalTooth by (gear, backlash): see BevelGear.tooth
        set_(self, "z1", check_teeth("z1", z1))
        set_(self, "z2", check_teeth("z2", z2))
        set_(self, "module", check_module(module))
        set_(self, "face_width", _number("face_width", face_width, 0.0))
        set_(self, "shaft_angle", check_shaft_angle(shaft_angle))
        # the ranges of a spur gear's (gears.arguments, gears.meshing): beyond them the cone
        # formulas divide by sin(alpha) of nearly nothing or overflow
        set_(self, "pressure_angle", check_pressure_angle(pressure_angle))
        set_(self, "profile_shift", _number("profile_shift", profile_shift, -1000.0, 1000.0))
        xs = _number("thickness_modification", thickness_modification, -1000.0, 1000.0)
        set_(self, "thickness_modification", xs)
        set_(self, "addendum", _number("addendum", addendum, 0.0, 10.0))
        set_(self, "dedendum", _number("dedendum", dedendum, 0.0, 10.0))
        if clearance not in CLEARANCES:
            raise GearError(f"clearance = {clearance!r}; valid are 'constant', 'tapered'")
        set_(self, "clearance", clearance)
        if profile not in PROFILES:
            raise GearError(f"profile = {profile!r}; valid are 'octoid', 'spherical_involute'")
        set_(self, "profile", profile)
        try:
            self._derive(tool_radius)
        except GearError as exc:  # a shift can cause any of them: say which shift was given
            x, xs = self.profile_shift, self.thickness_modification
            if (x or xs) and "profile_shift" not in str(exc):
                raise GearError(
                    f"{exc} (with profile_shift = {x:g}, thickness_modification = {xs:g})"
                ) from None
            raise

    def _derive(self, tool_radius) -> None:
        """The tool radius (default: the full round that fits) and the checks of the derived
        geometry."""
        set_ = object.__setattr__
        if tool_radius is None:
            full = float(full_round_radius(self.addendum, self.dedendum, self.pressure_angle))
            # the tool tip land of the rack, less 5 %: the crown tooth on the sphere is a little
            # narrower at its tip than the planar rack (checked exactly in _validate)
            fits = min(self._rack(i, 0.0).max_root_radius for i in (0, 1))
            tool_radius = max(min(full, 0.95 * fits), 0.0)
        set_(self, "tool_radius", _number("tool_radius", tool_radius, 0.0, low_open=False))
        if 0.0 < self.tool_radius < TOOL_RADIUS_FLOOR:
            raise GearError(
                f"tool_radius = {self.tool_radius:g} (mean modules); valid is 0 (a sharp tool "
                f"tip) or at least {TOOL_RADIUS_FLOOR:g}: a smaller round is no round at all"
            )
        fits = min(self._rack(i, 0.0).max_root_radius for i in (0, 1))
        if self.tool_radius > fits + 1e-12:
            raise GearError(
                f"tool_radius = {self.tool_radius:g} (mean modules) does not fit the tip of the "
                f"generating crown gear's tooth; valid is 0 <= tool_radius <= {fits:.4f} for this "
                "pressure angle, dedendum and thickness"
            )
        self._validate()

    @classmethod
    def gleason(
        cls, z1: int, z2: int, module: float, face_width: float, shaft_angle: float = 90.0,
        pressure_angle: float = 20.0, thickness_modification: float = 0.0, **kwargs,
    ) -> BevelPair:  # fmt: skip
        """The Gleason straight-bevel proportions (KHK Table 4.11): working depth 2 m, whole
        depth 2.188 m, the wheel's outer addendum ``0.54 m + 0.46 m / (z_2 cos delta_1 / (z_1 cos
        delta_2))``, constant clearance (:func:`gears.bevel.cone.gleason_coefficients`).
        ``thickness_modification`` is KHK's tooth-thickness factor K (x_sm1 = K).

        >>> p = BevelPair.gleason(20, 40, module=3, face_width=22)
        >>> [round(h, 3) for h in (p.g1.addendum, p.g2.addendum, p.g1.dedendum, p.g2.dedendum)]
        [4.035, 1.965, 2.529, 4.599]
        """
        z1, z2 = check_teeth("z1", z1), check_teeth("z2", z2)
        module = check_module(module)
        shaft_angle = check_shaft_angle(shaft_angle)
        # below the outer cone distance R_e (the pair's own check, needed before the heights)
        r_e = float(max_face_width(z1, z2, module, shaft_angle))
        face_width = _number("face_width", face_width, 0.0, r_e)
        given = sorted(set(kwargs) & {"profile_shift", "addendum", "dedendum", "clearance"})
        if given:
            raise GearError(
                f"{', '.join(given)} given to BevelPair.gleason, which sets the profile shift, "
                "the heights and the clearance itself (KHK Table 4.11); valid is BevelPair(...) "
                "for your own proportions, or gleason(...) without them"
            )
        k_a, k_f, x = (float(v) for v in gleason_coefficients(z1, z2, module, face_width,
                                                              shaft_angle))  # fmt: skip
        return cls(
            z1, z2, module, face_width, shaft_angle, pressure_angle, x, thickness_modification,
            k_a, k_f, "constant", **kwargs,
        )  # fmt: skip

    # --- validation ------------------------------------------------------------------------------
    def _validate(self) -> None:
        r_e = max_face_width(self.z1, self.z2, self.module, self.shaft_angle)
        if not self.face_width < r_e:
            raise GearError(
                f"face_width = {self.face_width:g} mm reaches the pitch apex (the outer cone "
                f"distance R_e = {r_e:.4f} mm); valid is 0 < face_width < {r_e:.4f} mm, and "
                f"face_width <= {r_e / 3:.4f} mm (R_e/3) cuts well"
            )
        if self.dedendum < self.addendum:
            raise GearError(
                f"dedendum = {self.dedendum:g} < addendum = {self.addendum:g}: the bottom "
                "clearance would be negative (valid: dedendum >= addendum)"
            )
        g = self._geometry
        for i in (0, 1):
            if not g.root_angle[i] > 0.0:
                raise GearError(
                    f"gear {i + 1} (z = {(self.z1, self.z2)[i]}): the root cone angle "
                    f"delta_f = {g.root_angle[i]:.4f} deg is not > 0 (its dedendum angle "
                    f"{g.dedendum_angle[i]:.4f} deg exceeds the pitch angle "
                    f"{g.pitch_angle[i]:.4f} deg); use more teeth or a smaller dedendum"
                )
            if not g.face_angle[i] < 180.0:
                raise GearError(
                    f"gear {i + 1}: the face cone angle delta_a = {g.face_angle[i]:.4f} deg "
                    "reaches 180 deg; use a smaller shaft angle or addendum"
                )
            if not (g.mean_addendum[i] + g.mean_dedendum[i]) > 0.0:
                raise GearError(f"gear {i + 1}: no tooth depth is left")
            if not g.mean_thickness[i] > 0.0:  # the shift or thickness took the whole tooth
                x, xs = self.profile_shift, self.thickness_modification
                used = abs(2 * x * math.tan(math.radians(self.pressure_angle)) + xs)
                raise GearError(
                    f"profile_shift = {x:g}, thickness_modification = {xs:g}: gear {i + 1}'s "
                    f"tooth has no thickness at the mean cone (s_m = {g.mean_thickness[i]:.4g} "
                    "mm); valid is |2 profile_shift tan(alpha) + thickness_modification| < pi/2 "
                    f"(here {used:.4g})"
                )
        self._rack(0)  # the generating tool must fit: a clear error now
        self._rack(1)
        _ = self.virtual_pair  # the virtual gears must exist (tips, roots): a clear error now
        for gear in self.gears:
            if gear.pitch_angle >= 90.0:
                continue  # a crown or internal bevel wheel: its teeth are not drawn
            try:
                gear.tooth()
            except GearError as exc:
                if "no thickness" in str(exc):  # the shift closed a tooth space: name it
                    x, xs = self.profile_shift, self.thickness_modification
                    used = abs(2 * x * math.tan(math.radians(self.pressure_angle)) + xs)
                    raise GearError(
                        f"profile_shift = {x:g}, thickness_modification = {xs:g}: gear "
                        f"{gear.index + 1}'s tooth space closes at the mean cone; valid is "
                        f"|2 profile_shift tan(alpha) + thickness_modification| < pi/2 "
                        f"(here {used:.4g})"
                    ) from None
                if "tip land" not in str(exc):
                    raise
                raise GearError(
                    f"tool_radius = {self.tool_radius:g} (mean modules): the generating crown "
                    f"gear's tip rounds of gear {gear.index + 1} do not fit its tip land; valid "
                    f"is tool_radius <= {gear._largest_tool_radius():.4f}"
                ) from None

    # --- geometry --------------------------------------------------------------------------------
    @cached_property
    def _geometry(self) -> BevelGeometry:
        return bevel_geometry(
            self.z1, self.z2, self.module, self.face_width, self.shaft_angle,
            self.pressure_angle, self.profile_shift, self.thickness_modification, self.addendum,
            self.dedendum, self.clearance,
        )  # fmt: skip

    @property
    def geometry(self) -> BevelGeometry:
        """Every formula of :func:`gears.bevel.cone.bevel_geometry` for this pair (arrays of 2)."""
        return self._geometry

    @cached_property
    def g1(self) -> BevelGear:
        """The pinion (gear 1)."""
        return BevelGear(self, 0)

    @cached_property
    def g2(self) -> BevelGear:
        """The wheel (gear 2)."""
        return BevelGear(self, 1)

    @property
    def gears(self) -> tuple[BevelGear, BevelGear]:
        return self.g1, self.g2

    @property
    def pitch_angles(self) -> tuple[float, float]:
        """Pitch cone angles ``(delta_1, delta_2)`` in degrees; they add up to the shaft angle."""
        d = self._geometry.pitch_angle
        return float(d[0]), float(d[1])

    @property
    def cone_distance(self) -> float:
        """Outer cone distance R_e, mm."""
        return float(self._geometry.cone_distance)

    @property
    def mean_cone_distance(self) -> float:
        """Mean cone distance R_m = R_e - b/2, mm."""
        return float(self._geometry.mean_cone_distance)

    @property
    def mean_module(self) -> float:
        """Mean module m_m = m_et R_m / R_e, mm."""
        return float(self._geometry.mean_module)

    @property
    def ratio(self) -> float:
        """Gear ratio u = z2 / z1 = sin delta_2 / sin delta_1 (Ozols (21.34))."""
        return self.z2 / self.z1

    @property
    def internal(self) -> bool:
        """False: a bevel mesh is counted like an external one when both speeds are measured
        about the axes pointing away from the common apex (see docs/bevel.md)."""
        return False

    @property
    def virtual_teeth(self) -> tuple[float, float]:
        """Virtual (Tredgold) tooth numbers ``z / cos delta`` (Ozols (21.36)); negative for an
        internal bevel gear, infinite for a crown gear."""
        z = self._geometry.virtual_teeth
        return float(z[0]), float(z[1])

    @property
    def tip_diameters(self) -> tuple[float, float]:
        """Outer tip (outside) diameters d_ae, mm."""
        d = self._geometry.tip_diameter
        return float(d[0]), float(d[1])

    def _rack(self, index: int, rho: float | None = None) -> BasicRack:
        """The basic rack of virtual gear ``index``: this pair's heights written for the
        thickness-equivalent shift ``x_hm + x_sm / (2 tan alpha)`` (see :attr:`virtual_pair`)."""
        xs = self.thickness_modification * (-1.0 if index else 1.0)
        shift = xs / (2.0 * math.tan(math.radians(self.pressure_angle)))
        rho = self.tool_radius if rho is None else rho
        try:
            return BasicRack(
                self.pressure_angle, self.addendum - shift, self.dedendum + shift, rho,
                name="bevel crown gear",
            )  # fmt: skip
        except GearError as exc:
            raise GearError(f"the generating crown gear of gear {index + 1}: {exc}") from None

    @cached_property
    def virtual_pair(self) -> GearPair:
        """The virtual (Tredgold) spur pair at the mean cone (ISO 10300): ``z_v = z / cos
        delta`` teeth of the mean module, centre distance ``(d_v1 + d_v2) / 2``.

        Its gears are :class:`VirtualGear` objects whose profile shift is the
        thickness-equivalent ``x_hm + x_sm / (2 tan alpha)`` and whose rack heights are moved
        by the same amount, so that their tips, roots, tooth thickness and undercut are the
        bevel gear's exactly (a thickness modification is the tool moved sideways; a profile
        shift with its heights compensated draws the same tool). A crown wheel (delta = 90 deg)
        gives a :class:`gears.Rack`; an internal bevel wheel (delta > 90 deg) a ring (the
        external gear comes first).
        """
        g = self._geometry
        mm = float(g.mean_module)
        gears = []
        for i, x in enumerate((self.profile_shift, -self.profile_shift)):
            zv = float(g.virtual_teeth[i])
            rack = self._rack(i)
            x_eq = x + rack.dedendum - self.dedendum  # x + x_sm / (2 tan alpha)
            if not math.isfinite(zv):
                gears.append(Rack(mm, self.pressure_angle, addendum=rack.addendum + x_eq))
                continue
            internal = zv < 0
            try:
                gears.append(
                    VirtualGear(
                        abs(zv), mm, self.pressure_angle, profile_shift=-x_eq if internal else x_eq,
                        internal=internal, rack=rack,
                    )
                )  # fmt: skip
            except GearError as exc:
                raise GearError(
                    f"gear {i + 1} of this bevel pair (its virtual gear): {exc}"
                ) from None
        a, b = gears
        if isinstance(a, Rack) or getattr(a, "internal", False):
            a, b = b, a
        try:
            return GearPair(a, b, tip_shortening=False)
        except GearError as exc:
            raise GearError(f"the virtual (Tredgold) pair of this bevel pair: {exc}") from None

    @property
    def contact_ratio(self) -> float:
        """Transverse contact ratio of the virtual pair at the mean cone, epsilon_v_alpha (the
        bevel pair's contact ratio by Tredgold's approximation; ISO 10300)."""
        return self.virtual_pair.contact_ratio

    def mesh_efficiency(self, friction: float = 0.1) -> float:
        """Ozols (14.25) on the virtual pair: ``1 - (pi f eps / 2)(1/z_v1 + 1/z_v2)`` (the
        sliding of a straight bevel mesh is that of its Tredgold pair)."""
        return self.virtual_pair.mesh_efficiency(friction)

    # --- load capacity ---------------------------------------------------------------------------
    def rating(self, torque: float, speed: float, material: Any = "case-carburized", *,
               life: float = 20000.0, mounting: str = "both-straddle",
               pattern: str = "light-load", **options: Any) -> BevelRating:  # fmt: skip
        """Pitting and bending rating by ISO 10300 method B1 through the virtual cylindrical
        gears at the mean cone (:func:`gears.bevel.rating.bevel_rating`: what is ISO 10300's
        there and what it shares with ISO 6336).

        ``torque`` N m on the pinion at ``speed`` rpm; ``mounting`` and ``pattern`` (how the
        contact pattern was checked) set the mounting factor K_Hbeta-be
        (:data:`gears.bevel.iso10300.MOUNTING_FACTORS`); ``effective_width`` (b_eff / b,
        default 0.85), ``contacts`` and the options of :meth:`gears.GearPair.rating`
        (``quality``, ``idler``, factors by symbol) pass on. Returns a
        :class:`gears.bevel.rating.BevelRating`.

        >>> r = BevelPair(20, 40, module=3, face_width=20).rating(50, 1500)
        >>> [round(s, 3) for s in r.safety_pitting]
        [1.239, 1.266]
        """
        from gears.bevel.rating import bevel_rating  # the rating family: loaded when rated

        return bevel_rating(self, torque, speed, material, life=life, mounting=mounting,
                            pattern=pattern, **options)  # fmt: skip

    # --- forces ----------------------------------------------------------------------------------
    def forces(self, torque: float) -> PairForces:
        """The mesh forces at the mean cone under ``torque`` N m on the pinion (ISO 10300-1 /
        DIN 3991): ``F_t = 2000 T / d_m1``, ``F_r = F_t tan alpha cos delta``, ``F_a = F_t
        tan alpha sin delta`` for each gear, as vectors in the frame of :meth:`placement`
        (:func:`gears.forces.bevel_mesh_forces`).

        >>> f = BevelPair(20, 40, module=3, face_width=20).forces(50)
        >>> [round(v, 2) for v in (*f.radial, *f.axial)]     # swapped at 90 deg
        [637.63, 318.81, 318.81, 637.63]
        """
        return bevel_pair_forces(self, torque)

    # --- placement -------------------------------------------------------------------------------
    def placement(self, angle: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
        """4x4 placements ``(gear 1, gear 2)`` on the common apex when gear 1 has turned by
        ``angle`` degrees (:func:`gears.bevel.solid.bevel_placement`): gear 1's axis +z, gear 2's
        ``(sin Sigma, 0, cos Sigma)``, phased so the teeth interleave."""
        angle = check_real("angle", angle)
        return bevel_placement(self.z1, self.z2, self.shaft_angle, angle)

    def scene(
        self, angle: float = 0.0, tolerance: float = 0.01, backlash: float = 0.0,
        bore: float | None = None, back_cone: bool = True,
    ) -> trimesh.Scene:  # fmt: skip
        """Both gears as a ``trimesh.Scene`` (nodes ``gear1``, ``gear2``): a common apex at the
        origin, the axes at the shaft angle (:meth:`placement`), gear 1 turned by ``angle``
        degrees and gear 2 rolling with it. At zero ``backlash`` (mm, normal, at the mean
        cone; each gear takes half) the flanks touch without interpenetrating: the teeth are
        sampled one-sidedly (:mod:`gears.bevel.spherical`).

        Examples
        --------
        >>> sc = BevelPair(20, 40, module=3, face_width=20).scene(tolerance=0.05)
        >>> sorted(sc.graph.nodes_geometry)
        ['gear1', 'gear2']
        """
        p1, p2 = self.placement(angle)
        tolerance = check_tolerance(tolerance, module=self.module)
        check_budget(
            "mesh", f"the scene of the bevel pair {self.z1}/{self.z2}",
            lambda t: sum(g._vertices(back_cone)(t) for g in self.gears), tolerance,
        )  # fmt: skip
        m1 = self.g1.mesh(tolerance, bore, back_cone, backlash)
        m2 = self.g2.mesh(tolerance, bore, back_cone, backlash)
        return scene([("gear1", m1, p1, COLOURS["gear1"]), ("gear2", m2, p2, COLOURS["gear2"])])

    def animate(
        self, path: str | os.PathLike[str], frames: int = 24, fps: float = 12.0,
        turn: float | None = None, tolerance: float = 0.05, backlash: float = 0.0,
        elevation: float = 30.0, azimuth: float = -30.0, size: int = 400,
        progress: Callable[[int, int], object] | None = None,
    ) -> pathlib.Path:  # fmt: skip
        """Write a GIF (or MP4 with ffmpeg) of the pair turning: gear 1 by ``turn`` degrees
        (default one pitch, ``360 / z1``), gear 2 rolling with it, seen from ``elevation`` and
        ``azimuth`` degrees, ``size`` pixels square (:func:`gears.solid.render.write_animation_3d`;
        ``progress(i, n)`` after each frame)."""
        from gears.solid.render import Camera, write_animation_3d

        n = check_frames(frames)
        fps = check_fps(fps)
        turn = 360.0 / self.z1 if turn is None else check_angle("turn", turn)
        tolerance = check_tolerance(tolerance, module=self.module)
        check_budget(
            "animation", f"{n} frames of the bevel pair {self.z1}/{self.z2}",
            lambda t: n * DRAWN_PER_VERTEX * sum(g._vertices(True)(t) for g in self.gears),
            tolerance, hint="fewer frames", budget=ANIMATION_BUDGET_3D,
        )  # fmt: skip
        m1 = self.g1.mesh(tolerance, backlash=backlash)
        m2 = self.g2.mesh(tolerance, backlash=backlash)
        c1, c2 = COLOURS["gear1"], COLOURS["gear2"]

        def frame(i: int) -> list:
            q1, q2 = self.placement(i * turn / n)
            return [(_placed(m1, q1), m1.faces, c1), (_placed(m2, q2), m2.faces, c2)]

        return write_animation_3d(path, frame, n, Camera(elevation, azimuth), fps=fps, size=size,
                                  progress=progress)  # fmt: skip

    # --- checks ----------------------------------------------------------------------------------
    def check(self, min_contact_ratio: float = 1.1, min_tip_land: float = 0.2) -> Report:
        """Every finding of the pair, each with its margin; never raises for a bad design.

        * the virtual pair's findings at the mean cone (:meth:`gears.GearPair.check`:
          ``g1.undercut``, ``g1.pointed_tip``, ``g1.tip_above_base``, ``g1.tooth_height`` and
          the same for ``g2``, ``contact_ratio``, ``tip_interference``, ``tip_interference_2``);
        * ``g1.tip_land_ends`` / ``g2.tip_land_ends``: the normal tip land at the outer and the
          inner end of the face (with constant clearance the relative addendum changes along
          the face) minus ``min_tip_land`` modules of that end, mm;
        * ``face_width``: ``R_e / 3 - b`` (mm), the rule of ISO 23509 and KHK;
        * ``face_width_module``: ``10 m_et - b`` (mm), KHK's second rule.
        """
        min_contact_ratio = check_real("min_contact_ratio", min_contact_ratio, 0.0,
                                       low_open=False)  # fmt: skip
        min_tip_land = check_real("min_tip_land", min_tip_land, 0.0, low_open=False)
        note = "virtual (Tredgold) pair at the mean cone: "
        findings = [
            Finding(f.name, f.margin, note + f.message, f.unit, f.ok)
            for f in self.virtual_pair.check(min_contact_ratio, min_tip_land).values()
        ]
        for gear in self.gears:
            findings.append(gear._tip_land_finding(min_tip_land))
        g = self._geometry
        third, tenth = (float(v) for v in face_width_margins(self.face_width, g.cone_distance,
                                                              self.module))  # fmt: skip
        findings.append(Finding(
            "face_width", third,
            f"face width b = {self.face_width:g} mm vs R_e/3 = {g.cone_distance / 3:.4f} mm "
            "(ISO 23509, KHK: a wider face is hard to cut and weak at its inner end)",
        ))  # fmt: skip
        findings.append(Finding(
            "face_width_module", tenth,
            f"face width b = {self.face_width:g} mm vs 10 m_et = {10 * self.module:g} mm (KHK)",
        ))  # fmt: skip
        return Report(findings)

    def describe(self) -> str:
        """The geometry of both gears as a table (mm, degrees), like KHK's Tables 4.10/4.11."""
        g = self._geometry
        rows = [
            ("teeth z", (self.z1, self.z2), "d"),
            ("pitch angle delta, deg", g.pitch_angle, ".5f"),
            ("outer pitch diameter d_e", g.reference_diameter, ".4f"),
            ("profile shift x_hm", g.profile_shift, "+.4f"),
            ("thickness modification x_sm", g.thickness_modification, "+.4f"),
            ("outer addendum h_ae", g.addendum, ".4f"),
            ("outer dedendum h_fe", g.dedendum, ".4f"),
            ("addendum angle theta_a, deg", g.addendum_angle, ".5f"),
            ("dedendum angle theta_f, deg", g.dedendum_angle, ".5f"),
            ("face angle delta_a, deg", g.face_angle, ".5f"),
            ("root angle delta_f, deg", g.root_angle, ".5f"),
            ("outside diameter d_ae", g.tip_diameter, ".4f"),
            ("pitch apex to crown", g.crown_to_apex, ".4f"),
            ("axial face width", g.axial_face_width, ".4f"),
            ("inner outside diameter d_ai", g.inner_tip_diameter, ".4f"),
            ("mean thickness s_m (arc)", g.mean_thickness, ".4f"),
            ("virtual teeth z_v", g.virtual_teeth, ".4f"),
        ]
        try:
            ratio = f"{self.contact_ratio:.4f}"
        except GearError:  # a virtual tip inside its base circle: check() reports it
            ratio = "none (a virtual tip lies inside its base circle)"
        head = (
            f"straight bevel pair {self.z1}/{self.z2}, m_et {self.module:g} mm, b "
            f"{self.face_width:g} mm, shaft angle {self.shaft_angle:g} deg, alpha "
            f"{self.pressure_angle:g} deg, {self.clearance} clearance, {self.profile} teeth\n"
            f"cone distance R_e {self.cone_distance:.4f} mm, R_m {self.mean_cone_distance:.4f} "
            f"mm, mean module {self.mean_module:.4f} mm, contact ratio (virtual) {ratio}"
        )
        lines = [head, f"{'':32s}{'pinion':>14s}{'wheel':>14s}"]
        for label, values, fmt in rows:
            a, b = (format(float(v) if fmt != "d" else int(v), fmt) for v in values)
            lines.append(f"{label:32s}{a:>14s}{b:>14s}")
        return "\n".join(lines)

    def __repr__(self) -> str:
        return (
            f"BevelPair({self.z1}, {self.z2}, module={self.module:g}, face_width="
            f"{self.face_width:g}, shaft_angle={self.shaft_angle:g})"
        )

    def _repr_svg_(self) -> str:
        """The pair in axial section as an SVG picture, what a notebook shows
        (:func:`gears.bevel.drawing.bevel_pair_svg`; a text instead when it cannot be drawn)."""
        from gears.bevel.drawing import bevel_pair_svg  # drawn in a notebook only

        return bevel_pair_svg(self, (COLOURS["gear1"], COLOURS["gear2"]))
