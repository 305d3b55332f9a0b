"""Layer 8, classes: :class:`Gear`, one involute gear as a thin immutable view.

External or internal, spur or helical, with profile shift. Every quantity is computed by the
vectorised formulas of :mod:`gears.geometry` (ISO 21771 symbols are mapped there); the cutter,
the exact envelope and the outline come from the layers below (:mod:`gears.cutting.cutter`,
:mod:`gears.cutting.profile`, :mod:`gears.cutting.outline`).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np
import shapely
from numpy.typing import ArrayLike

from gears.arguments import (
    check_callback,
    check_choice,
    check_flag,
    check_length,
    check_module,
    check_positive,
    check_pressure_angle,
    check_tolerance,
)
from gears.budget import check_budget
from gears.checks import gear_margins, undercut_form_diameter
from gears.contact.modification import Modification
from gears.cutting.cutter import ShaperCutter, ShaperTool
from gears.errors import GearError
from gears.geometry import (
    base_diameter,
    check_real,
    check_teeth,
    form_diameter,
    half_angle_at_reference,
    min_profile_shift,
    over_pins,
    pin_contact_diameter,
    pointed_tip_diameter,
    reference_diameter,
    root_diameter,
    span,
    span_teeth,
    tip_diameter,
    tooth_thickness,
    transverse_pressure_angle,
)
from gears.involute import inv, inv_inverse, pressure_angle_at
from gears.rack import BasicRack
from gears.report import Finding, Report
from gears.solid.mesh import COLOURS, gear_solid, helix_twist, solid_levels

if TYPE_CHECKING:
    import trimesh

__all__ = ["Gear"]


@dataclass(frozen=True)
class Gear:
    """An involute gear; immutable. Lengths in mm, angles in degrees.

    Parameters
    ----------
    teeth : int
        Number of teeth z >= 1 (positive also for internal gears).
    module : float
        Normal module m_n > 0.
    pressure_angle : float, optional
        Normal pressure angle alpha_n in degrees; defaults to the rack's (20 for ISO 53).
        Giving it with a rack of another angle re-angles the rack.
    helix_angle : float
        beta in degrees, -60 < beta < 60; positive = right hand.
    profile_shift : float
        Normal profile-shift coefficient x (in modules). An internal gear's follows DIN 3960 /
        ISO 21771: a positive x makes a ring's teeth thicker and its tip circle smaller (the
        tool moves towards the axis), so a ring is entered as a report of such a tool prints it
        (KHK's Gear Technical Reference, and geartrain up to 0.2.0, count it the other way).
    face_width : float or None
        b in mm, for the overlap ratio and meshes.
    internal : bool
        True for an internal (ring) gear.
    rack : BasicRack
        The basic rack (ISO 53 A by default); its addendum, dedendum and tool tip radius set the
        tip, root, form circle and undercut limit.
    tip_alteration : float
        Tip alteration coefficient k (DIN 3960): d_a changes by 2 k m_n. A :class:`GearPair`
        sets it for tip shortening; leave 0 for a gear on its own.
    cutter : ShaperCutter or None
        The gear is cut by this shaper (:class:`gears.cutting.cutter.ShaperCutter`) instead of the
        rack-type tool: its root and form circles, undercut, outline and the pair checks then
        follow that cutter. None (default): rack-cut (an internal gear: the shaper's rack limit).
    modification : Modification or None
        Flank modifications (tip and root relief, crowning, end relief, helix slope:
        :class:`gears.contact.modification.Modification`), which the contact analysis
        (:meth:`GearPair.contact`) takes into account, :meth:`outline` draws (tip and root
        relief) and :meth:`mesh` and every scene draw along the face (crowning, end relief,
        helix slope). None: the unmodified involute.

    Examples
    --------
    >>> g = Gear(teeth=12, module=3, profile_shift=0.6)
    >>> float(g.reference_diameter), round(float(g.tip_diameter), 6)
    (36.0, 45.6)
    >>> round(float(g.tooth_thickness(g.reference_diameter)), 6)
    6.022682
    """

    teeth: int
    module: float
    pressure_angle: float | None = None
    helix_angle: float = 0.0
    profile_shift: float = 0.0
    face_width: float | None = None
    internal: bool = False
    rack: BasicRack = field(default_factory=BasicRack.iso53)
    tip_alteration: float = 0.0
    cutter: ShaperCutter | None = None
    modification: Modification | None = None

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        set_(self, "teeth", self._valid_teeth(self.teeth))
        set_(self, "module", check_module(self.module))
        if not isinstance(self.rack, BasicRack):
            raise GearError(f"rack must be a BasicRack; got {self.rack!r}")
        if self.pressure_angle is None:
            set_(self, "pressure_angle", self.rack.pressure_angle)
        pa = check_pressure_angle(self.pressure_angle)
        set_(self, "pressure_angle", pa)
        if pa != self.rack.pressure_angle:
            set_(self, "rack", self.rack.with_pressure_angle(pa))
        set_(self, "helix_angle", check_real("helix_angle", self.helix_angle, -60.0, 60.0))
        # shifts beyond +-1000 modules draw no gear and would swamp d in d + 2 x m_n
        for name in ("profile_shift", "tip_alteration"):
            set_(self, name, check_real(name, getattr(self, name), -1000.0, 1000.0))
        if self.face_width is not None:
            set_(self, "face_width", check_real("face_width", self.face_width, 0.0))
        set_(self, "internal", bool(self.internal))
        if self.cutter is not None:
            if not isinstance(self.cutter, ShaperCutter):
                raise GearError(f"cutter must be a ShaperCutter or None; got {self.cutter!r}")
            _ = self._shaper_tool  # the cutter must fit this gear: a clear error now
        if self.modification is not None and not isinstance(self.modification, Modification):
            raise GearError(
                f"modification must be a Modification or None; got {self.modification!r}"
            )
        self._require_real_dimensions()

    @staticmethod
    def _valid_teeth(z) -> int:
        """The tooth count as validated (a whole number >= 1; a virtual gear relaxes it)."""
        return check_teeth("teeth", z)

    def _require_real_dimensions(self) -> None:
        """Refuse a gear no blank can carry: a root or tip diameter <= 0, or a tip at or below
        the root (a merely bad tooth, e.g. a tip below the form circle, is a finding)."""
        da, df = self.tip_diameter, self.root_diameter
        s = -1.0 if self.internal else 1.0
        zc = self.reference_diameter / (2 * self.module)  # d / (2 m_n)
        ha, hf, k = self.rack.addendum, self.rack.dedendum, self.tip_alteration
        where = f"z = {self.teeth}, m = {self.module:g}"
        if (da - df) * s <= 0:  # tip at or below the root: k <= -(h_a + h_f)
            raise GearError(
                f"tip_alteration = {k:g} puts the tip (d_a = {da:.4f} mm) at or below the root "
                f"(d_f = {df:.4f} mm) of {where}; valid is tip_alteration > {-(ha + hf):g}"
            )
        if min(da, df) <= 0:
            # external d_f = d - 2 m_n (h_f - x) > 0; a ring's d_a = d - 2 m_n (h_a + x + k) > 0
            bound = f"< {zc - ha - k:.4f}" if self.internal else f"> {hf - zc:.4f}"
            which = "tip" if self.internal else "root"
            raise GearError(
                f"profile_shift = {self.profile_shift:g} gives {where} a {which} diameter of "
                f"{min(da, df):.4f} mm; valid is profile_shift {bound}"
            )

    # --- basic quantities ------------------------------------------------------------------
    @property
    def z(self) -> int:
        """Tooth count (ISO symbol)."""
        return self.teeth

    @property
    def hand(self) -> str:
        """``"right"``, ``"left"`` or ``"spur"``."""
        return "spur" if self.helix_angle == 0 else ("right" if self.helix_angle > 0 else "left")

    @cached_property
    def transverse_module(self) -> float:
        """m_t = m_n / cos beta."""
        return self.module / math.cos(math.radians(self.helix_angle))

    @cached_property
    def transverse_pressure_angle(self) -> float:
        """alpha_t in degrees."""
        return math.degrees(transverse_pressure_angle(self.pressure_angle, self.helix_angle))

    @cached_property
    def base_helix_angle(self) -> float:
        """beta_b in degrees: tan beta_b = tan beta cos alpha_t (Ozols 21.30)."""
        at = math.radians(self.transverse_pressure_angle)
        return math.degrees(math.atan(math.tan(math.radians(self.helix_angle)) * math.cos(at)))

    @cached_property
    def reference_diameter(self) -> float:
        """d = z m_t."""
        return float(reference_diameter(self.teeth, self.module, self.helix_angle))

    @cached_property
    def base_diameter(self) -> float:
        """d_b = d cos alpha_t."""
        return float(base_diameter(self.teeth, self.module, self.pressure_angle, self.helix_angle))

    @cached_property
    def tip_diameter(self) -> float:
        """d_a (with this gear's ``tip_alteration``; 0 unless set by a pair)."""
        return float(
            tip_diameter(
                self.teeth, self.module, self.profile_shift, self.helix_angle,
                self.rack.addendum, self.internal, self.tip_alteration,
            )
        )  # fmt: skip

    @cached_property
    def _shaper_tool(self):
        return ShaperTool(self, self.cutter)

    @cached_property
    def root_diameter(self) -> float:
        """d_f generated by the rack-type tool (or by the gear's shaper ``cutter``)."""
        if self.cutter is not None:
            return self.cutter.root_diameter(self)
        return float(
            root_diameter(
                self.teeth, self.module, self.profile_shift, self.helix_angle,
                self.rack.dedendum, self.internal,
            )
        )  # fmt: skip

    @property
    def base_pitch(self) -> float:
        """Transverse base pitch p_bt = pi m_t cos alpha_t."""
        return math.pi * self.base_diameter / self.teeth

    @property
    def normal_base_pitch(self) -> float:
        """p_bn = pi m_n cos alpha_n."""
        return math.pi * self.module * math.cos(math.radians(self.pressure_angle))

    @cached_property
    def virtual_teeth(self) -> float:
        """Virtual tooth number z_n = z / (cos^2 beta_b cos beta) (ISO 21771); Ozols (21.33)
        gives the approximation z / cos^3 beta."""
        b = math.radians(self.helix_angle)
        bb = math.radians(self.base_helix_angle)
        return self.teeth / (math.cos(bb) ** 2 * math.cos(b))

    # --- tooth thickness ---------------------------------------------------------------------
    def tooth_thickness(self, diameter: ArrayLike) -> float | np.ndarray:
        """Transverse arc tooth thickness at ``diameter`` (mm; array in, array out).

        Raises :class:`GearError` for a diameter inside the base circle or past the pointed tip
        (no thickness exists there).
        """
        return tooth_thickness(
            diameter, self.teeth, self.module, self.profile_shift, self.pressure_angle,
            self.helix_angle, self.internal,
        )  # fmt: skip

    @property
    def reference_thickness(self) -> float:
        """Transverse arc thickness at the reference circle s_t."""
        return float(self.tooth_thickness(self.reference_diameter))

    @property
    def base_thickness(self) -> float:
        """Transverse arc thickness at the base circle s_b = d_b (s_t/d +- inv alpha_t)."""
        return float(self.tooth_thickness(self.base_diameter))

    @property
    def tip_thickness(self) -> float:
        """Transverse arc thickness at the tip circle s_at (negative: the flanks cross below the
        tip, the tooth is pointed: a signed margin, not a size). Raises for a tip inside the base
        circle."""
        return float(
            tooth_thickness(
                self.tip_diameter, self.teeth, self.module, self.profile_shift,
                self.pressure_angle, self.helix_angle, self.internal, signed=True,
            )
        )  # fmt: skip

    @cached_property
    def pointed_tip_diameter(self) -> float:
        """Diameter where the tooth thickness vanishes.

        External gears: above the reference circle (ISO 21771, tooth thickness). Internal gears: the
        teeth thin towards the centre; if they are still positive at the base circle no pointed
        diameter exists above it and the base diameter is returned.
        """
        if not self.internal:
            return float(
                pointed_tip_diameter(
                    self.teeth, self.module, self.profile_shift, self.pressure_angle,
                    self.helix_angle,
                )
            )  # fmt: skip
        at = math.radians(self.transverse_pressure_angle)
        psi = float(
            half_angle_at_reference(self.teeth, self.profile_shift, self.pressure_angle, 0, True)
        )
        y = float(inv(at)) - psi
        if y <= 0:
            return self.base_diameter
        return self.base_diameter / math.cos(float(inv_inverse(y)))

    # --- undercut and form circle -----------------------------------------------------------
    @cached_property
    def min_profile_shift(self) -> float:
        """x_min against undercut by the rack-type tool (uses the tool's straight-flank depth)."""
        return float(
            min_profile_shift(
                self.teeth, self.pressure_angle, self.helix_angle, self.rack.straight_flank_depth
            )
        )

    @property
    def undercut(self) -> bool:
        """True when the rack-type tool (or the gear's shaper ``cutter``) undercuts this
        (external) gear."""
        if self.cutter is not None:
            return self._shaper_tool.undercuts
        return (not self.internal) and self.profile_shift < self.min_profile_shift - 1e-12

    @cached_property
    def _form(self) -> float:
        """:attr:`form_diameter`, or NaN where the undercut fillet cuts the whole involute away
        (the checks count the flank as gone up to the tip)."""
        if self.cutter is not None:
            if not self.undercut:
                return self.cutter.form_diameter(self)
            try:
                from gears.cutting.profile import ShaperProfile  # the cutting family: when cut

                return 2.0 * ShaperProfile(self, self.cutter).form_radius
            except GearError:
                return math.nan
        if self.undercut:  # the one vectorised solve the margins use too
            return float(
                undercut_form_diameter(
                    self.teeth, self.module, self.profile_shift, self.pressure_angle,
                    self.helix_angle, self.rack,
                )
            )  # fmt: skip
        return float(
            form_diameter(
                self.teeth, self.module, self.profile_shift, self.pressure_angle,
                self.helix_angle, self.rack.straight_flank_depth, self.internal,
                self.rack.dedendum,
            )
        )  # fmt: skip

    @property
    def form_diameter(self) -> float:
        """Form-circle diameter d_Ff, the start of the usable involute (ISO 21771).

        For an undercut external gear the fillet cuts the involute; the exact point comes from
        :func:`gears.checks.undercut_form_diameter`. Raises :class:`GearError` where the fillet
        cuts the whole involute away (no form circle exists; the checks report it).
        """
        form = self._form
        if math.isnan(form):
            raise GearError(
                f"z = {self.teeth}, profile_shift = {self.profile_shift:g}: "
                "the undercut fillet does not "
                "meet the involute (the tooth is cut away); use a larger profile shift"
            )
        return form

    # --- measurements -----------------------------------------------------------------------
    def span(self, k: int | None = None) -> tuple[int, float]:
        """Base tangent length ``(k, W_k)`` over ``k`` teeth (default: the standard k rule).

        Raises :class:`GearError` for internal gears (use :meth:`over_pins`) or k outside
        1 <= k < z.
        """
        if self.internal:
            raise GearError("span measurement applies to external gears; use over_pins() for rings")
        if k is None:
            k = int(
                span_teeth(self.teeth, self.profile_shift, self.pressure_angle, self.helix_angle)
            )
        k = check_teeth("k", k)
        if k >= self.teeth and self.teeth > 1:
            raise GearError(f"k = {k} spans the whole gear; valid is 1 <= k <= {self.teeth - 1}")
        w = span(
            k, self.teeth, self.module, self.profile_shift, self.pressure_angle, self.helix_angle
        )
        return k, float(w)

    def over_pins(self, pin_diameter: float) -> float:
        """Dimension over two pins (spur) or balls (helical) of ``pin_diameter`` mm; between
        pins for an internal gear (ISO 21771 / DIN 3960)."""
        dp = check_real("pin_diameter", pin_diameter, 0.0)
        dc = float(
            pin_contact_diameter(
                dp, self.teeth, self.module, self.profile_shift, self.pressure_angle,
                self.helix_angle, self.internal,
            )
        )  # fmt: skip
        low, high = sorted((self.form_diameter, self.tip_diameter))
        if not low <= dc <= high:
            where = (
                "is too small to reach the involute"
                if dc == 0
                else (f"would touch the flanks at d = {dc:.4f} mm, off the involute")
            )
            raise GearError(
                f"pin_diameter = {dp:g} mm {where} (it runs from d = {low:.4f} to {high:.4f} "
                "mm); choose a pin that touches it there"
                + ("" if self.internal or self.helix_angle else
                   f", e.g. ideal_pin_diameter() = {self.ideal_pin_diameter():.4f} mm")
            )  # fmt: skip
        return float(
            over_pins(
                dp, self.teeth, self.module, self.profile_shift, self.pressure_angle,
                self.helix_angle, self.internal,
            )
        )  # fmt: skip

    def ideal_pin_diameter(self) -> float:
        """Pin diameter touching the flanks on the circle d + 2 x m_n (KHK Gear Technical Reference;
        external spur gears)."""
        if self.internal or self.helix_angle:
            raise GearError("ideal_pin_diameter is defined here for external spur gears only")
        a = math.radians(self.pressure_angle)
        z, x, m = self.teeth, self.profile_shift, self.module
        ac = float(pressure_angle_at(self.base_diameter, self.reference_diameter + 2 * x * m))
        phi = math.tan(ac) + math.pi / (2 * z) - float(inv(a)) - 2 * x * math.tan(a) / z
        return self.base_diameter * (math.tan(phi) - math.tan(ac))

    def chordal_thickness(self) -> tuple[float, float]:
        """Chordal tooth thickness and chordal height ``(s, h)`` at the reference circle, normal
        section (KHK / SDP-SI; helical gears through the virtual tooth number).

        theta = 90 deg/z_v + 360 deg x tan alpha_n / (pi z_v) (a ring's x in DIN 3960's sign);
        s = z_v m_n sin theta; h = h_a +- (z_v m_n / 2)(1 - cos theta), upper sign external.
        """
        zv = self.virtual_teeth if self.helix_angle else float(self.teeth)
        s = -1.0 if self.internal else 1.0
        tan_a = math.tan(math.radians(self.pressure_angle))
        theta = math.pi / (2 * zv) + 2 * self.profile_shift * tan_a / zv
        ha = s * (self.tip_diameter - self.reference_diameter) / 2
        chord = zv * self.module * math.sin(theta)
        height = ha + s * zv * self.module / 2 * (1 - math.cos(theta))
        return chord, height

    # --- checks -----------------------------------------------------------------------------
    def check(self, min_tip_land: float = 0.2) -> Report:
        """Findings ``undercut``, ``pointed_tip`` (tip land >= ``min_tip_land`` m_n),
        ``tip_above_base`` and ``tooth_height`` (the tip above the root and the form circle),
        each with a signed margin (from :func:`gears.checks.gear_margins`, the functions a
        search over arrays of gears calls). ``min_tip_land`` is finite and >= 0."""
        min_tip_land = check_real("min_tip_land", min_tip_land, 0.0, low_open=False)
        return Report(self._findings(min_tip_land))

    def _findings(self, min_tip_land: float) -> list[Finding]:
        out = []
        m = self.module
        form = self._form  # NaN: the undercut fillet cuts the whole involute away
        g = gear_margins(
            self.teeth, m, self.profile_shift, self.pressure_angle, self.helix_angle,
            self.internal, self.rack, self.tip_alteration, min_tip_land, form,
            self.root_diameter,
        )  # fmt: skip
        if not self.internal and self.cutter is not None:
            out.extend(self.cutter.check(self).values())
        elif not self.internal:  # rings: cutter interference is checked on the pair
            margin = float(g.undercut)
            out.append(
                Finding(
                    "undercut", margin,
                    f"x = {self.profile_shift:.4f} {'>=' if margin >= 0 else '<'} x_min = "
                    f"{self.min_profile_shift:.4f} (no undercut by the tool below it)",
                    unit="module",
                )
            )  # fmt: skip
        tip_margin = float(g.tip_above_base)
        out.append(
            Finding(
                "tip_above_base", tip_margin,
                f"tip circle d_a = {self.tip_diameter:.4f} mm vs base circle d_b = "
                f"{self.base_diameter:.4f} mm (the involute exists only outside d_b)",
            )
        )  # fmt: skip
        if tip_margin >= 0:
            need = min_tip_land * m
            s_a = float(g.pointed_tip) + need
            out.append(
                Finding(
                    "pointed_tip", float(g.pointed_tip),
                    f"normal tip land s_an = {s_a:.4f} mm vs required {need:.4f} mm "
                    f"({min_tip_land:g} m_n)",
                )
            )  # fmt: skip
        else:
            out.append(
                Finding(
                    "pointed_tip", tip_margin,
                    "tip inside the base circle: no involute tip land exists",
                )
            )  # fmt: skip
        where = "inside" if self.internal else "above"
        form_text = "cut away by the undercut" if math.isnan(form) else f"{form:.4f} mm"
        out.append(
            Finding(
                "tooth_height", float(g.tooth_height),
                f"tip circle d_a = {self.tip_diameter:.4f} mm must lie {where} the root circle "
                f"d_f = {self.root_diameter:.4f} mm and the form circle d_Ff = {form_text}",
            )
        )  # fmt: skip
        return out

    def _tip_helix_angle(self) -> float:
        """Helix angle at the tip cylinder, degrees: tan beta_a = tan beta d_a / d."""
        b = math.radians(self.helix_angle)
        return math.degrees(math.atan(math.tan(b) * self.tip_diameter / self.reference_diameter))

    def outline(
        self, tolerance: float = 0.001, method: str = "analytic", backlash: float = 0.0,
        bore: float | None = None, rim: float | None = None, angle: float = 0.0,
        center: tuple[float, float] = (0.0, 0.0), cutter: ShaperCutter | None = None,
        progress: Callable[[int, int], object] | None = None,
    ) -> shapely.Polygon:  # fmt: skip
        """Transverse tooth outline as a shapely Polygon (see :func:`gears.cutting.profile.outline`,
        :func:`gears.cutting.generate.rack_outline`, :func:`gears.cutting.generate.shaper_outline`).

        ``method`` is ``"analytic"``, ``"rack"`` or ``"shaper"``; ``tolerance`` is the largest
        deviation from the exact curves in mm; ``backlash`` the pair's normal backlash (this
        gear takes half); ``bore`` a hole (external; default none); ``rim`` the ring's width
        outside its root circle (internal; default 3 modules);
        ``cutter`` a :class:`gears.cutting.cutter.ShaperCutter` (for ``"shaper"``, and for
        ``"analytic"`` to draw that shaper's exact envelope instead of the rack's);
        ``progress(done, total)`` is called as a simulation advances. The finest tolerance is
        :data:`gears.cutting.profile.MIN_TOLERANCE` (1e-6 mm); larger work is refused with the
        tolerance that fits.
        The gear's ``modification`` takes its tip and root relief off the flanks (external
        and internal gears: :func:`gears.contact.flank.relieved_outline`; a length left None
        is the short relief against the basic rack; in a pair, the pair's own); :meth:`mesh`
        adds the lead modifications (crowning, end relief, helix slope) along the face.
        """
        from gears.cutting.outline import gear_outline  # the cutting family: when drawn

        return gear_outline(
            self, tolerance, method, backlash, bore, rim, angle, center, cutter, progress
        )

    def mesh(
        self, face_width: float | None = None, tolerance: float = 0.01, method: str = "analytic",
        backlash: float = 0.0, bore: float | None = None, herringbone: bool = False,
        cutter: ShaperCutter | None = None, rim: float | None = None,
        progress: Callable[[int, int], object] | None = None,
    ) -> trimesh.Trimesh:  # fmt: skip
        """The gear as a watertight ``trimesh.Trimesh`` (the ``mesh`` extra): axis +z, mid-plane
        z = 0, the section at z turned by ``2 z tan(beta) / d`` (right hand > 0).

        ``face_width`` (mm) defaults to the gear's own (``Gear(face_width=...)``), else 10
        modules, as in :meth:`GearPair.scene`, ``Planetary.scene`` and ``geartrain mesh``;
        ``tolerance`` (mm) drives both the outline and the axial slices
        (:func:`gears.solid.mesh.gear_solid`); ``method``, ``backlash``, ``bore``, ``rim`` (a ring's
        width outside its root circle, default 3 modules) and ``cutter`` are those of
        :meth:`outline`; ``herringbone`` makes two opposite-hand halves meeting at z = 0;
        ``progress`` follows a simulated outline. Every argument is checked and the solid's
        size estimated before any work: a solid over the mesh budget
        (:data:`gears.budget.BUDGETS`) is refused with the tolerance that fits.

        Examples
        --------
        >>> m = Gear(20, 1, helix_angle=20).mesh(face_width=10, tolerance=0.05)
        >>> m.is_watertight, m.is_winding_consistent
        (True, True)
        """
        b = self.face_width if face_width is None else face_width
        b = check_positive("face_width", 10.0 * self.module if b is None else b)
        tol = check_tolerance(tolerance, module=self.module)
        from gears.cutting.outline import METHODS

        method = check_choice("method", method, METHODS)
        herringbone = check_flag("herringbone", herringbone)
        check_callback("progress", progress)
        radius = self.solid_radius(rim)
        b = check_length("face_width", b, radius, "the gear's outer radius")
        from gears.contact.flank import solid_lead

        lead, extra = solid_lead(self, b, tol)  # the modification's crowning, end relief, slope
        twist = helix_twist(b, self.helix_angle, self.reference_diameter) + extra
        self.check_solid_budget(tol, twist, method, backlash, bore, rim, cutter, herringbone)
        shape = self.outline(tol, method, backlash, bore=bore, rim=rim, cutter=cutter,
                             progress=progress)  # fmt: skip
        return gear_solid(shape, b, twist, tol, herringbone=herringbone, lead=lead)

    def solid_radius(self, rim: float | None = None) -> float:
        """The outer radius of this gear's solid, mm: the tip radius, or a ring's root radius
        plus its rim (before any outline is drawn)."""
        if self.internal:
            from gears.cutting.sampling import default_rim

            width = default_rim(self) if rim is None else check_positive("rim", rim)
            return self.root_diameter / 2 + width
        return self.tip_diameter / 2

    def solid_vertices(self, tolerance: float, twist: float = 0.0, method: str = "analytic",
                       backlash: float = 0.0, bore: float | None = None,
                       rim: float | None = None, cutter: ShaperCutter | None = None,
                       herringbone: bool = False) -> float:  # fmt: skip
        """Estimated vertices of :meth:`mesh` at ``tolerance`` (one tooth sampled, times z and
        the slices and a lead modification's levels:
        :func:`gears.cutting.outline.outline_vertices`, :func:`gears.contact.flank.lead_levels`),
        before any outline is drawn."""
        from gears.contact.flank import lead_levels
        from gears.cutting.outline import outline_vertices

        n = outline_vertices(self, tolerance, method, backlash, bore, rim, cutter)
        levels = solid_levels(twist, self.solid_radius(rim), tolerance, herringbone)
        return n * (float(levels) + lead_levels(self.modification, tolerance))

    def check_solid_budget(
        self, tolerance: float, twist: float = 0.0, method: str = "analytic",
        backlash: float = 0.0, bore: float | None = None, rim: float | None = None,
        cutter: ShaperCutter | None = None, herringbone: bool = False,
    ) -> float:  # fmt: skip
        """:meth:`solid_vertices`, or a GearError over the mesh budget naming the tolerance
        that fits."""
        return check_budget(
            "mesh", f"the solid of z = {self.teeth}, m = {self.module:g}",
            lambda t: self.solid_vertices(t, twist, method, backlash, bore, rim, cutter,
                                          herringbone), tolerance,
        )  # fmt: skip

    def with_(self, **changes) -> Gear:
        """A copy with some fields changed (validated again)."""
        return replace(self, **changes)

    def _repr_svg_(self) -> str:
        """The gear's outline as an SVG picture, what a notebook shows
        (:func:`gears.figures.drawing.gear_svg`; a text instead when it cannot be drawn)."""
        from gears.figures.drawing import gear_svg  # drawn in a notebook only

        return gear_svg(self, COLOURS["gear1"])
