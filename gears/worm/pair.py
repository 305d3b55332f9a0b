"""Layer 10, classes: :class:`WormPair`, a cylindrical worm and its throated wheel on axes
crossed at 90 degrees, as a thin immutable view over :mod:`gears.worm.geometry` (DIN 3975 /
ISO/TR 10828), :mod:`gears.worm.flank` and :mod:`gears.worm.checks`.

ISO/TS 14521 load capacity of worm gears is not modelled (docs/worm.md says what it needs).
"""

from __future__ import annotations

import os
import pathlib
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np

from gears.arguments import (
    check_angle,
    check_choice,
    check_fps,
    check_frames,
    check_integer,
    check_length,
    check_module,
    check_positive,
    check_pressure_angle,
    check_real,
    check_teeth,
    check_tolerance,
)
from gears.budget import check_budget
from gears.errors import GearError
from gears.forces import PairForces, worm_pair_forces
from gears.meshing import check_friction
from gears.report import Finding, Report
from gears.solid.mesh import COLOURS, scene
from gears.worm.checks import MAX_WRAP_ANGLE, WormMargins, min_worm_length, worm_margins
from gears.worm.crossed import reduced_friction_angle
from gears.worm.flank import axial_half_thickness
from gears.worm.geometry import (
    DRIVERS,
    FLANKS,
    WormGeometry,
    best_lead_angle,
    sliding_velocity,
    worm_efficiency,
    worm_geometry,
)
from gears.worm.solid import wheel_solid, worm_placement, worm_solid

if TYPE_CHECKING:
    import trimesh

__all__ = ["HANDS", "MAX_STARTS", "WormPair"]

#: The hands of the thread.
HANDS = ("right", "left")

#: The most starts a worm may have (DIN 3975 tables go to 6; multi-start worms of up to a few
#: dozen starts exist as fine-pitch screws).
MAX_STARTS = 100

#: The default diameter quotient q when neither ``diameter_quotient`` nor ``worm_diameter`` is
#: given (the middle of DIN 3976's series).
DEFAULT_QUOTIENT = 10.0


@dataclass(frozen=True, init=False)
class WormPair:
    """A cylindrical worm pair, shaft angle 90 degrees (DIN 3975 / ISO/TR 10828); immutable.

    Parameters
    ----------
    starts : int
        ``z_1``, the worm's number of threads (1 ... 100).
    wheel_teeth : int
        ``z_2``.
    module : float
        The worm's axial module ``m_x`` (= the wheel's transverse module), mm.
    diameter_quotient : float, optional
        ``q = d_m1 / m_x`` (default 10 unless ``worm_diameter`` is given).
    worm_diameter : float, optional
        The worm's reference diameter ``d_m1`` in mm, instead of ``q``.
    pressure_angle : float
        ``alpha_0`` in degrees, in the section the flank form names: axial for ZA, normal for
        ZN, ZI and ZK (DIN 3975).
    flank : {"ZA", "ZN", "ZI", "ZK"}
        The flank form (:mod:`gears.worm.flank`).
    profile_shift : float
        ``x_2``, the wheel's profile shift coefficient (it moves the centre distance).
    face_width : float, optional
        ``b_2``, the wheel's face width, mm; default ``0.75 d_a1`` (within the usual wrap
        angle of 100 degrees, ``d_a1 sin 50 deg``).
    hand : {"right", "left"}
        The hand of the thread (the wheel's teeth have the same hand).
    worm_length : float, optional
        ``b_1``, the threaded length, mm; default the chord the wheel's teeth need plus one
        axial pitch.
    addendum, clearance : float
        ``h_a*`` and ``c*`` in axial modules (1 and 0.2, DIN 3975).
    tool_radius : float, optional
        ZK only: the grinding cone's radius at the reference cylinder, mm (default 10 m_x).

    Raises
    ------
    GearError
        For input no worm pair can have, naming the value and the valid range (a root inside
        the axis, a wheel's tip reaching the worm's axis, unknown names).

    Examples
    --------
    The lecture course's worm (z_1 = 2, q = 10, z_2 = 40; reduced friction f' = 0.05):

    >>> w = WormPair(2, 40, module=5, diameter_quotient=10)
    >>> round(w.lead_angle, 6), w.ratio, w.center_distance
    (11.309932, 20.0, 125.0)
    >>> round(w.efficiency(0.05 * np.cos(np.radians(20))), 4), w.self_locking(0.05)
    (0.792, False)
    """

    starts: int
    wheel_teeth: int
    module: float
    diameter_quotient: float
    pressure_angle: float
    flank: str
    profile_shift: float
    face_width: float
    hand: str
    worm_length: float
    addendum: float
    clearance: float
    tool_radius: float

    def __init__(
        self, starts: int, wheel_teeth: int, module: float, *,
        diameter_quotient: float | None = None, worm_diameter: float | None = None,
        pressure_angle: float = 20.0, flank: str = "ZI", profile_shift: float = 0.0,
        face_width: float | None = None, hand: str = "right", worm_length: float | None = None,
        addendum: float = 1.0, clearance: float = 0.2, tool_radius: float | None = None,
    ) -> None:  # fmt: skip
        set_ = object.__setattr__
        set_(self, "_solids", {})  # meshes by (member, tolerance): see worm_mesh, wheel_mesh
        set_(self, "starts", check_integer("starts", starts, 1, MAX_STARTS))
        set_(self, "wheel_teeth", check_teeth("wheel_teeth", wheel_teeth))
        set_(self, "module", check_module(module))
        if diameter_quotient is not None and worm_diameter is not None:
            raise GearError(
                f"diameter_quotient = {diameter_quotient!r} and worm_diameter = "
                f"{worm_diameter!r}; give one of them (q = d_m1 / m_x)"
            )
        if worm_diameter is not None:
            q = check_positive("worm_diameter", worm_diameter) / self.module
        else:
            q = DEFAULT_QUOTIENT if diameter_quotient is None else diameter_quotient
            q = check_real("diameter_quotient", q, 0.0, 1e6)
        set_(self, "diameter_quotient", q)
        set_(self, "pressure_angle", check_pressure_angle(pressure_angle))
        set_(self, "flank", check_choice("flank", flank, FLANKS))
        set_(self, "profile_shift", check_real("profile_shift", profile_shift, -1e3, 1e3))
        set_(self, "hand", check_choice("hand", hand, HANDS))
        set_(self, "addendum", check_real("addendum", addendum, 0.0, 10.0))
        set_(self, "clearance", check_real("clearance", clearance, 0.0, 10.0, low_open=False))
        self._validate_depths()
        g = self.geometry
        if face_width is None:
            face_width = 0.75 * float(g.worm_tip_diameter)
        b2 = check_length("face_width", face_width, self.module)
        set_(self, "face_width", b2)
        need = float(min_worm_length(self.starts, self.wheel_teeth, self.module, q,
                                     self.profile_shift, self.addendum))  # fmt: skip
        if worm_length is None:
            worm_length = need + float(g.axial_pitch)
        set_(self, "worm_length", check_length("worm_length", worm_length, self.module))
        depth = float(g.worm_tip_diameter - g.worm_root_diameter) / 2.0
        if tool_radius is None:
            tool_radius = 10.0 * self.module
        r0 = check_positive("tool_radius", tool_radius)
        if not depth < r0 <= 1e6 * self.module:
            raise GearError(
                f"tool_radius = {r0:g} mm; valid is {depth:.6g} < tool_radius <= "
                f"{1e6 * self.module:.6g} mm (the grinding cone must reach the thread's root)"
            )
        set_(self, "tool_radius", r0)

    def _validate_depths(self) -> None:
        g = self.geometry
        if not float(g.worm_root_diameter) > 0.0:
            raise GearError(
                f"diameter_quotient = {self.diameter_quotient:g}: the worm's root diameter "
                f"d_f1 = {float(g.worm_root_diameter):.6g} mm is not > 0; valid is "
                f"diameter_quotient > {2 * (self.addendum + self.clearance):g} (2 (h_a* + c*))"
            )
        if not float(g.throat_radius) > 0.0:
            raise GearError(
                f"addendum = {self.addendum:g}: the wheel's tip reaches the worm's axis; valid "
                f"is addendum < {self.diameter_quotient / 2:g} (q / 2)"
            )
        if not float(g.wheel_root_diameter) > 0.0:
            raise GearError(
                f"profile_shift = {self.profile_shift:g}: the wheel's root diameter d_f2 = "
                f"{float(g.wheel_root_diameter):.6g} mm is not > 0; valid is profile_shift > "
                f"{self.addendum + self.clearance - self.wheel_teeth / 2:g}"
            )
        if not float(g.wheel_tip_diameter) > float(g.wheel_root_diameter):
            raise GearError("the wheel has no tooth depth (tip at or below its root)")

    # --- geometry --------------------------------------------------------------------------------
    @cached_property
    def geometry(self) -> WormGeometry:
        """Every formula of :func:`gears.worm.geometry.worm_geometry` for this pair."""
        return worm_geometry(
            self.starts, self.wheel_teeth, self.module, self.diameter_quotient,
            self.pressure_angle, self.flank, self.profile_shift, self.addendum, self.clearance,
        )  # fmt: skip

    def _g(self, name: str) -> float:
        return float(getattr(self.geometry, name))

    @property
    def ratio(self) -> float:
        """``i = z_2 / z_1`` (Ozols (21.45))."""
        return self._g("ratio")

    @property
    def lead_angle(self) -> float:
        """``gamma``, degrees: ``tan gamma = z_1 / q``."""
        return self._g("lead_angle")

    @property
    def axial_module(self) -> float:
        """``m_x``, mm (the ``module`` given)."""
        return self.module

    @property
    def normal_module(self) -> float:
        """``m_n = m_x cos gamma``, mm."""
        return self._g("normal_module")

    @property
    def axial_pitch(self) -> float:
        """``p_x = pi m_x``, mm."""
        return self._g("axial_pitch")

    @property
    def lead(self) -> float:
        """``p_z = z_1 p_x``, mm: the advance of one thread per turn."""
        return self._g("lead")

    @property
    def axial_pressure_angle(self) -> float:
        """``alpha_x``, degrees."""
        return self._g("axial_pressure_angle")

    @property
    def normal_pressure_angle(self) -> float:
        """``alpha_n``, degrees."""
        return self._g("normal_pressure_angle")

    @property
    def worm_diameter(self) -> float:
        """``d_m1 = q m_x``, the worm's reference (mean) diameter, mm."""
        return self._g("worm_diameter")

    @property
    def worm_tip_diameter(self) -> float:
        """``d_a1``, mm."""
        return self._g("worm_tip_diameter")

    @property
    def worm_root_diameter(self) -> float:
        """``d_f1``, mm."""
        return self._g("worm_root_diameter")

    @property
    def worm_base_diameter(self) -> float:
        """``d_b1`` of the involute helicoid (the ZI worm's base cylinder), mm."""
        return self._g("worm_base_diameter")

    @property
    def wheel_diameter(self) -> float:
        """``d_2 = z_2 m_x``, the wheel's reference diameter, mm."""
        return self._g("wheel_diameter")

    @property
    def wheel_tip_diameter(self) -> float:
        """``d_a2``, the wheel's tip diameter at the throat (mid-plane), mm."""
        return self._g("wheel_tip_diameter")

    @property
    def wheel_root_diameter(self) -> float:
        """``d_f2``, mm."""
        return self._g("wheel_root_diameter")

    @property
    def wheel_outside_diameter(self) -> float:
        """``d_e2``, the wheel's largest diameter (at the rim's edges), mm."""
        return self._g("wheel_outside_diameter")

    @property
    def throat_radius(self) -> float:
        """``r_k = a - d_a2 / 2``, the radius of the wheel's throat about the worm's axis, mm."""
        return self._g("throat_radius")

    @property
    def center_distance(self) -> float:
        """``a = (d_m1 + d_2) / 2 + x_2 m_x``, mm."""
        return self._g("center_distance")

    @property
    def contact_ratio(self) -> float:
        """The transverse contact ratio in the mid-plane (the worm's axial section as a rack)."""
        return self._g("contact_ratio")

    def axial_profile(self, radius: float | np.ndarray) -> float | np.ndarray:
        """The thread's axial half thickness ``h(r)`` at the radii given, mm
        (:func:`gears.worm.flank.axial_half_thickness`)."""
        r = np.asarray(radius, float)
        if not np.all(np.isfinite(r)) or np.any(r <= 0.0):
            raise GearError(f"radius = {radius!r}; valid are finite radii > 0 mm")
        return axial_half_thickness(
            self.flank, r, self.starts, self.module, self.diameter_quotient,
            self.pressure_angle, tool_radius=self.tool_radius,
        )  # fmt: skip

    # --- efficiency ------------------------------------------------------------------------------
    def friction_angle(self, friction: float) -> float:
        """``phi' = atan(mu / cos alpha_n)``, degrees."""
        mu = check_friction(friction)
        return float(reduced_friction_angle(mu, self.normal_pressure_angle))

    def efficiency(self, friction: float, driving: str = "worm") -> float:
        """Tooth efficiency with the worm or the wheel driving (Ozols (14.15), (14.18));
        ``<= 0`` means the pair locks in that direction. ``friction`` is the coefficient mu,
        ``0 <= mu < 1``."""
        driving = check_choice("driving", driving, DRIVERS)
        return float(worm_efficiency(self.lead_angle, self.friction_angle(friction), driving))

    def mesh_efficiency(self, friction: float) -> tuple[float, float]:
        """``(worm driving, wheel driving)`` efficiencies at the friction coefficient
        ``friction``: what :func:`trains.power_flow` charges a worm mesh of a train in each
        direction (the second at or below zero for a self-locking pair)."""
        return self.efficiency(friction, "worm"), self.efficiency(friction, "wheel")

    def forces(self, torque: float, friction: float = 0.0, driving: str = "worm") -> PairForces:
        """The mesh forces under ``torque`` N m on the worm, with ``friction`` mu and the
        ``driving`` member: tangential, radial and axial components on worm and wheel (DIN 3996;
        :func:`gears.forces.worm_pair_forces`, which says the frame)."""
        return worm_pair_forces(self, torque, friction, driving)

    def self_locking(self, friction: float) -> bool:
        """True when the wheel cannot drive the worm (``gamma <= phi'``)."""
        return self.efficiency(friction, "wheel") <= 0.0

    def best_lead_angle(self, friction: float) -> float:
        """The lead angle of the best efficiency with the worm driving, ``45 - phi'/2`` deg."""
        return float(best_lead_angle(self.friction_angle(friction)))

    def sliding_velocity(self, worm_speed: float) -> float:
        """Sliding speed at the pitch point, m/s, for the worm turning at ``worm_speed`` rpm."""
        n = check_real("worm_speed", worm_speed, -1e7, 1e7)
        return float(sliding_velocity(self.worm_diameter, self.lead_angle, abs(n)))

    # --- checks ----------------------------------------------------------------------------------
    def margins(self, min_contact_ratio: float = 1.1, min_tip_land: float = 0.2) -> WormMargins:
        """:func:`gears.worm.checks.worm_margins` of this pair."""
        return worm_margins(
            self.starts, self.wheel_teeth, self.module, self.diameter_quotient,
            self.pressure_angle, self.flank, self.profile_shift, self.face_width,
            self.worm_length, self.addendum, self.clearance, self.tool_radius,
            min_contact_ratio, min_tip_land,
        )  # fmt: skip

    def check(self, min_contact_ratio: float = 1.1, min_tip_land: float = 0.2) -> Report:
        """Every design condition as a finding with its signed margin; never raises for a pair
        the constructor accepted."""
        eps_min = check_real("min_contact_ratio", min_contact_ratio, 0.0, 100.0, low_open=False)
        land = check_real("min_tip_land", min_tip_land, 0.0, 10.0, low_open=False)
        mg = self.margins(eps_min, land)
        g, m = self.geometry, self.module
        ha, x2 = self.addendum, self.profile_shift
        land_mm = land * m
        z_min = 2.0 * (ha - x2) / np.sin(np.radians(self.axial_pressure_angle)) ** 2
        found = [
            Finding("wheel_undercut", mg.wheel_undercut,
                    f"z_2 = {self.wheel_teeth} against {z_min:.3f} for the worm's tip not to "
                    f"undercut the wheel (h_a* - x_2 = {ha - x2:.4g}, alpha_x = "
                    f"{self.axial_pressure_angle:.4f} deg)", unit="module"),
            Finding("wheel_pointed_tip", mg.wheel_pointed_tip,
                    f"wheel tip thickness in the mid-plane {float(g.wheel_tip_thickness):.4f} mm "
                    f">= {land_mm:.4f} mm"),
            Finding("worm_tip_land", mg.worm_tip_land,
                    f"worm thread tip land {float(mg.worm_tip_land) + land_mm:.4f} mm (normal) "
                    f">= {land_mm:.4f} mm"),
            Finding("contact_ratio", mg.contact_ratio,
                    f"mid-plane contact ratio {self.contact_ratio:.4f} >= {eps_min:g}", unit=""),
        ]  # fmt: skip
        b2_max = float(mg.face_width) + self.face_width
        wrap = 2 * np.degrees(np.arcsin(min(self.face_width / self.worm_tip_diameter, 1.0)))
        if self.flank == "ZI":
            found.append(Finding(
                "flank_above_base", mg.flank_above_base,
                f"the wheel's tip reaches the worm at r = {self.throat_radius:.4f} mm, outside "
                f"the involute's base cylinder r_b = {self.worm_base_diameter / 2:.4f} mm",
            ))  # fmt: skip
        found += [
            Finding("face_width", mg.face_width,
                    f"face width b_2 = {self.face_width:.4f} mm <= {b2_max:.4f} mm (wrap angle "
                    f"{wrap:.1f} <= {MAX_WRAP_ANGLE:g} deg)"),
            Finding("worm_length", mg.worm_length,
                    f"threaded length b_1 = {self.worm_length:.4f} mm >= "
                    f"{self.worm_length - float(mg.worm_length):.4f} mm (the wheel's outside "
                    "circle at the worm's tip)"),
        ]  # fmt: skip
        return Report(found)

    # --- solids ----------------------------------------------------------------------------------
    def worm_mesh(self, tolerance: float = 0.01) -> trimesh.Trimesh:
        """The worm as a watertight mesh in its own frame (axis +z, centred): the helicoid
        threads of its flank form, to ``tolerance`` mm (:func:`gears.worm.solid.worm_solid`)."""
        key = ("worm", check_tolerance(tolerance, module=self.module))
        if key not in self._solids:
            self._solids[key] = worm_solid(self, key[1])
        return self._solids[key]

    def wheel_mesh(
        self, tolerance: float = 0.01, progress: Callable[[int, int], object] | None = None
    ) -> trimesh.Trimesh:
        """The wheel this worm cuts as a hob, a watertight mesh in its own frame (axis +z,
        mid-plane z = 0): its flanks the envelope of the worm's thread in closed form, plane by
        plane, within ``tolerance`` mm (:func:`gears.worm.solid.wheel_solid`);
        ``progress(done, total)``."""
        key = ("wheel", check_tolerance(tolerance, module=self.module))
        if key not in self._solids:
            self._solids[key] = wheel_solid(self, key[1], progress=progress)
        return self._solids[key]

    def placements(self, angle: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
        """4x4 placements ``(worm, wheel)`` in the scene's frame with the worm turned by
        ``angle`` degrees and the wheel by ``angle z_1 / z_2`` (the wheel's axis +z, the worm's
        axis along +x at ``y = a``; :mod:`gears.worm.solid`)."""
        phi1 = np.radians(check_angle("angle", angle))
        sign = 1.0 if self.hand == "right" else -1.0
        phi2 = sign * phi1 * self.starts / self.wheel_teeth
        c, s = np.cos(phi2), np.sin(phi2)
        wheel = np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]])
        return worm_placement(self, float(phi1)), wheel

    def scene(
        self, angle: float = 0.0, tolerance: float = 0.02,
        progress: Callable[[int, int], object] | None = None,
    ) -> trimesh.Scene:  # fmt: skip
        """The worm and its wheel in mesh at zero backlash (``angle``: the worm's turn,
        degrees, the wheel following by ``angle z_1 / z_2``): the flanks touch along their
        contact lines, with no volume in common beyond the chords of the tolerance."""
        worm_at, wheel_at = self.placements(angle)
        wheel = self.wheel_mesh(tolerance, progress)
        return scene([
            ("worm", self.worm_mesh(tolerance), worm_at, COLOURS["gear1"]),
            ("wheel", wheel, wheel_at, COLOURS["gear2"]),
        ])  # fmt: skip

    def animate(
        self, path: str | os.PathLike[str], frames: int = 24, fps: float = 12.0,
        turn: float | None = None, tolerance: float = 0.1, elevation: float = 25.0,
        azimuth: float = -60.0, size: int = 400,
        progress: Callable[[int, int], object] | None = None,
    ) -> pathlib.Path:  # fmt: skip
        """Write a GIF (or MP4 with ffmpeg) of the pair turning: the worm by ``turn``
        degrees (default ``360 / z_1``, which turns the wheel by one pitch), the wheel
        following, seen from ``elevation`` and ``azimuth`` degrees, ``size`` pixels square
        (:func:`gears.solid.render.write_animation_3d`; ``progress(i, n)`` after each frame).
        The solids are built once (:meth:`worm_mesh`, :meth:`wheel_mesh`) and placed per frame
        by :meth:`placements`; the work is held to the 3D animation budget."""
        from gears.solid.render import (
            ANIMATION_BUDGET_3D,
            DRAWN_PER_VERTEX,
            Camera,
            write_animation_3d,
        )
        from gears.worm.solid import wheel_estimate, worm_estimate

        n = check_frames(frames)
        fps = check_fps(fps)
        turn = 360.0 / self.starts if turn is None else check_angle("turn", turn)
        tol = check_tolerance(tolerance, module=self.module)
        check_budget(
            "animation", f"{n} frames of the worm pair {self.starts}/{self.wheel_teeth}",
            lambda t: n * DRAWN_PER_VERTEX * (worm_estimate(self, t) + wheel_estimate(self, t)),
            tol, hint="fewer frames", budget=ANIMATION_BUDGET_3D,
        )  # fmt: skip
        worm, wheel = self.worm_mesh(tol), self.wheel_mesh(tol)
        c1, c2 = COLOURS["gear1"], COLOURS["gear2"]

        def placed(mesh, matrix):
            return mesh.vertices @ matrix[:3, :3].T + matrix[:3, 3]

        def frame(i: int) -> list:
            at1, at2 = self.placements(i * turn / n)
            return [(placed(worm, at1), worm.faces, c1), (placed(wheel, at2), wheel.faces, c2)]

        return write_animation_3d(path, frame, n, Camera(elevation, azimuth), fps=fps, size=size,
                                  progress=progress)  # fmt: skip

    def describe(self) -> str:
        """The geometry of the worm and the wheel as a table (mm, degrees; DIN 3975 symbols)."""
        g = self.geometry
        worm = [
            ("starts z_1", str(self.starts)),
            ("diameter quotient q", f"{self.diameter_quotient:.4f}"),
            ("lead angle gamma, deg", f"{self.lead_angle:.6f}"),
            ("axial module m_x", f"{self.module:.4f}"),
            ("normal module m_n", f"{self.normal_module:.4f}"),
            ("axial pitch p_x", f"{self.axial_pitch:.4f}"),
            ("lead p_z", f"{self.lead:.4f}"),
            ("axial pressure angle, deg", f"{self.axial_pressure_angle:.4f}"),
            ("normal pressure angle, deg", f"{self.normal_pressure_angle:.4f}"),
            ("reference diameter d_m1", f"{self.worm_diameter:.4f}"),
            ("tip diameter d_a1", f"{self.worm_tip_diameter:.4f}"),
            ("root diameter d_f1", f"{self.worm_root_diameter:.4f}"),
            ("threaded length b_1", f"{self.worm_length:.4f}"),
        ]
        if self.flank == "ZI":
            worm.append(("base diameter d_b1", f"{self.worm_base_diameter:.4f}"))
        wheel = [
            ("teeth z_2", str(self.wheel_teeth)),
            ("profile shift x_2", f"{self.profile_shift:+.4f}"),
            ("reference diameter d_2", f"{self.wheel_diameter:.4f}"),
            ("throat (tip) diameter d_a2", f"{self.wheel_tip_diameter:.4f}"),
            ("root diameter d_f2", f"{self.wheel_root_diameter:.4f}"),
            ("outside diameter d_e2", f"{self.wheel_outside_diameter:.4f}"),
            ("throat radius r_k", f"{self.throat_radius:.4f}"),
            ("face width b_2", f"{self.face_width:.4f}"),
            ("tip thickness s_a2 (mid-plane)", f"{float(g.wheel_tip_thickness):.4f}"),
        ]
        head = (
            f"worm pair {self.starts}/{self.wheel_teeth}, flank {self.flank}, {self.hand} hand, "
            f"alpha_0 {self.pressure_angle:g} deg\n"
            f"ratio {self.ratio:.6g}, centre distance a {self.center_distance:.4f} mm, "
            f"contact ratio (mid-plane) {self.contact_ratio:.4f}"
        )
        lines = [head, "worm"]
        lines += [f"  {label:32s}{value:>14s}" for label, value in worm]
        lines.append("wheel")
        lines += [f"  {label:32s}{value:>14s}" for label, value in wheel]
        return "\n".join(lines)

    def describe_efficiency(self, friction: float, worm_speed: float | None = None) -> str:
        """Efficiency with either member driving, self-locking and the best lead angle at the
        friction coefficient ``friction`` (and the sliding speed at ``worm_speed`` rpm)."""
        phi = self.friction_angle(friction)
        fwd, back = self.efficiency(friction, "worm"), self.efficiency(friction, "wheel")
        lines = [
            f"friction mu {friction:g}: reduced friction angle phi' {phi:.4f} deg",
            f"  efficiency, worm driving   {fwd:10.4f}",
            f"  efficiency, wheel driving  {back:10.4f}"
            + ("   (self-locking: the wheel cannot drive)" if back <= 0.0 else ""),
            f"  best lead angle 45 - phi'/2 {self.best_lead_angle(friction):9.4f} deg "
            f"(this worm {self.lead_angle:.4f} deg)",
        ]
        if worm_speed is not None:
            v = self.sliding_velocity(worm_speed)
            lines.append(f"  sliding speed at {worm_speed:g} rpm {v:8.4f} m/s")
        return "\n".join(lines)

    def __str__(self) -> str:
        return (
            f"WormPair(z1={self.starts}, z2={self.wheel_teeth}, m_x={self.module:g}, "
            f"q={self.diameter_quotient:g}, {self.flank}, {self.hand} hand, "
            f"gamma={self.lead_angle:.4f} deg, a={self.center_distance:.4f} mm)"
        )
