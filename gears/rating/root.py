"""Layer 6, root form: the tooth-root quantities of ISO 6336-3 method B measured on the real tooth.

Method B's tooth form factor Y_F and stress correction factor Y_S need three lengths of the
tooth root (ISO 6336-3 §6.2, §7.2): the chord ``s_Fn`` between the points where a tangent
inclined at 30 deg to the tooth centre line touches the root fillets (60 deg for internal gears,
T = pi/6), the fillet radius ``rho_F`` there, and the moment arm ``h_Fe`` of the load applied at
the outer point of single pair contact (diameter ``d_en``, along the flank normal, angle
``alpha_Fen``) measured from the tangent points. The standard gives closed equations for a
rack-generated fillet (:func:`gears.rating.bending.root_form`) and a rack approximation for internal
gears (:func:`gears.rating.bending.internal_root_form`); here the same lengths are measured on the
tooth the cutter actually leaves:

* ``method="exact"``: on the exact envelope of the rack or shaper cutter
  (:class:`gears.cutting.profile.ToothProfile`, :class:`gears.cutting.profile.ShaperProfile`): the
  30 (60) deg point by Brent's method on the fillet's tangent angle, rho_F from the curve's
  derivatives;
* ``method="simulated"``: on the polygon of a simulated cut (:mod:`gears.cutting.generate`, spur
  gears): quartics in the arc length fitted to the points within 0.1 m_n of arc around the place
  where the polyline's direction crosses the angle, the tangent point and rho_F taken on them.

Both work on the virtual spur gear of the normal section, as the standard does: a helical gear
is measured on its exact virtual spur gear (``z_n = z / (cos^2 beta_b cos beta)`` teeth, shifts
and tool in the normal section; a shaper cutter of z0 teeth becomes one of ``z0_n`` teeth).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from gears.cutting.cutter import ShaperCutter
from gears.cutting.generate import rack_outline, shaper_outline
from gears.cutting.profile import ShaperProfile, ToothProfile, check_tolerance
from gears.errors import GearError
from gears.geometry import tooth_thickness
from gears.rating.bending import form_factors

__all__ = ["RootForm", "measure_root", "virtual_gear"]


class RootForm(NamedTuple):
    """The root quantities of one gear, measured (mm and radians).

    Coordinates are in the tooth frame of the virtual spur gear: the tooth centre line is the
    y axis, pointing from the root towards the tip, the measured flank at x > 0.
    """

    s_Fn: float  # chord between the tangent points
    rho_F: float  # fillet radius at the tangent point
    h_Fe: float  # moment arm of the load
    alpha_Fen: float  # load direction, rad (from the normal to the tooth centre line)
    tangent_point: tuple[float, float]  # (x, y) of the tangent point on the measured flank
    load_point: tuple[float, float]  # (x, y) of the load on the flank (at d_en)
    load_axis: tuple[float, float]  # where the load line crosses the tooth centre line
    tangent: float  # the tangent angle used, degrees (30 external, 60 internal)

    @property
    def standard(self) -> tuple[float, float, float, float]:
        """``(s_Fn, rho_F, h_Fe, alpha_Fen)``, as :func:`gears.rating.iso6336.rate_pairs` takes
        it."""
        return self.s_Fn, self.rho_F, self.h_Fe, self.alpha_Fen

    def factors(self, module: float, pressure_angle: float = 20.0):
        """``(Y_F, Y_S, q_s)`` of this root (:func:`gears.rating.bending.form_factors`)."""
        yf, ys, qs = form_factors(self.s_Fn, self.rho_F, self.h_Fe, self.alpha_Fen, module,
                                  pressure_angle)  # fmt: skip
        return float(yf), float(ys), float(qs)


@dataclass(frozen=True)
class _VirtualGear:
    """The virtual spur gear of a helical gear's normal section, with the attributes the exact
    envelopes read (:class:`gears.cutting.profile.ToothProfile`); its tooth count need not be
    whole."""

    teeth: float
    module: float
    pressure_angle: float
    profile_shift: float
    internal: bool
    rack: object
    tip_diameter: float
    cutter: object = None
    helix_angle: float = 0.0
    tip_alteration: float = 0.0

    @property
    def transverse_pressure_angle(self) -> float:
        return self.pressure_angle

    @property
    def transverse_module(self) -> float:
        return self.module

    @property
    def reference_diameter(self) -> float:
        return self.teeth * self.module

    @property
    def base_diameter(self) -> float:
        return self.reference_diameter * math.cos(math.radians(self.pressure_angle))

    @property
    def reference_thickness(self) -> float:
        return float(
            tooth_thickness(
                self.reference_diameter, self.teeth, self.module, self.profile_shift,
                self.pressure_angle, 0.0, self.internal,
            )
        )  # fmt: skip


@dataclass(frozen=True)
class _VirtualCutter(ShaperCutter):
    """A shaper cutter on the virtual gear: its tooth count z0_n need not be whole."""

    def __post_init__(self) -> None:
        object.__setattr__(self, "teeth", float(self.teeth))


def _virtual_factor(gear) -> float:
    """z_n / z = 1 / (cos^2 beta_b cos beta)."""
    b = math.radians(abs(gear.helix_angle))
    at = math.atan(math.tan(math.radians(gear.pressure_angle)) / math.cos(b))
    bb = math.atan(math.tan(b) * math.cos(at))
    return 1.0 / (math.cos(bb) ** 2 * math.cos(b))


def virtual_gear(gear, cutter=None):
    """The virtual spur gear of ``gear`` in its normal section (ISO 6336-3 §6.2): ``z_n``
    teeth, module m_n, the normal pressure angle, the same shift and rack, tip diameter
    ``d_an = d_n + d_a - d``; with the virtual cutter (``z0_n`` teeth) of a shaper ``cutter``.
    A spur gear is its own virtual gear (returned as is)."""
    if gear.helix_angle == 0:
        return gear, cutter
    f = _virtual_factor(gear)
    zn = gear.teeth * f
    dn = zn * gear.module
    virtual_cutter = None
    if cutter is not None:
        virtual_cutter = _VirtualCutter(cutter.teeth * f, cutter.shift, cutter.addendum,
                                        cutter.tip_radius)  # fmt: skip
    v = _VirtualGear(
        zn, gear.module, gear.pressure_angle, gear.profile_shift, gear.internal, gear.rack,
        dn + gear.tip_diameter - gear.reference_diameter, virtual_cutter,
    )  # fmt: skip
    return v, virtual_cutter


def _profile(gear, cutter):
    if gear.rack.protuberance > 0:
        raise GearError(
            f"rack protuberance = {gear.rack.protuberance:g} m: the measured root form needs an "
            "outline, which protuberance tools do not have yet; use root='standard'"
        )
    if cutter is None and not gear.internal:
        return ToothProfile(gear)
    return ShaperProfile(gear, cutter)


def measure_root(gear, d_en: float, method: str = "exact", cutter=None, tolerance=None,
                 tangent: float | None = None) -> RootForm:  # fmt: skip
    """Measure ``s_Fn``, ``rho_F``, ``h_Fe`` and ``alpha_Fen`` on the real tooth of ``gear``.

    Parameters
    ----------
    gear : Gear
        The gear as mounted (tip alterations applied); rack-cut, or cut by ``cutter`` (or its
        own ``cutter``; an internal gear by default by
        :meth:`gears.cutting.cutter.ShaperCutter.default_for`).
    d_en : float
        Diameter of the load point on the virtual spur gear, mm
        (:func:`gears.rating.bending.load_point`).
    method : {"exact", "simulated"}
        Measure on the exact envelope or on a simulated cut (spur gears).
    cutter : ShaperCutter, optional
        The shaper cutter (default: the gear's own; for a ring the default cutter).
    tolerance : float, optional
        Outline tolerance of the simulated cut, mm (default m_n / 2000).
    tangent : float, optional
        Tangent angle in degrees (default 30 for external gears, 60 for internal gears).

    Returns
    -------
    RootForm

    Raises
    ------
    GearError
        When the tangent does not touch the fillet, the load point is off the flank, or the
        tooth is pointed (method B does not apply), or for bad input.

    Examples
    --------
    ISO 6336-3's closed form and the measurement agree on a rack-cut gear:

    >>> from gears import Gear
    >>> from gears.rating.bending import root_form, load_point
    >>> g = Gear(20, 2, profile_shift=0.2)
    >>> d_en = 2 * 20.5 + 1.5   # a load point on the flank
    >>> r = measure_root(g, d_en)
    >>> s, rho, h, a = root_form(20, 2, 0.2, 20, d_en, math.acos(g.base_diameter / d_en))
    >>> [round(float(a / b), 6) for a, b in zip(r.standard, (s, rho, h, a))]
    [1.0, 1.0, 1.0, 1.0]
    """
    if method not in ("exact", "simulated"):
        raise GearError(f"method = {method!r}; valid are 'exact', 'simulated'")
    cutter = cutter if cutter is not None else getattr(gear, "cutter", None)
    if cutter is None and gear.internal:
        cutter = ShaperCutter.default_for(gear)
    if cutter is not None and not isinstance(cutter, ShaperCutter):
        raise GearError(f"cutter = {cutter!r}; valid is a ShaperCutter or None")
    d_en = float(d_en)
    if tangent is None:
        tangent = 60.0 if gear.internal else 30.0
    if not (isinstance(tangent, int | float) and 5.0 <= tangent <= 85.0):
        raise GearError(f"tangent = {tangent!r}; valid is 5 <= tangent <= 85 deg")
    vgear, vcutter = virtual_gear(gear, cutter)
    prof = _profile(vgear, vcutter)
    s = -1.0 if gear.internal else 1.0
    half = math.pi / prof.z
    r_en = d_en / 2
    lo, hi = sorted((prof.form_radius, prof.tip_radius))
    if not (math.isfinite(r_en) and lo - 1e-9 <= r_en <= hi + 1e-9):
        raise GearError(
            f"the load point d_en = {d_en:.4f} mm lies off the involute flank (it runs from "
            f"d = {2 * lo:.4f} to {2 * hi:.4f} mm on the virtual gear): method B does not apply"
        )
    if method == "exact":
        point, rho_f = _exact_tangent(prof, s, half, math.radians(tangent))
        lx, ly = _xy(r_en, float(prof.eta_involute(r_en)), s, half)
        dr = 1e-5 * r_en  # a central difference towards the tip: the flank's direction
        ax, ay = _xy(r_en + s * dr, float(prof.eta_involute(r_en + s * dr)), s, half)
        bx, by = _xy(r_en - s * dr, float(prof.eta_involute(r_en - s * dr)), s, half)
        tx, ty = ax - bx, ay - by
    else:
        if gear.helix_angle != 0:
            raise GearError(
                "method='simulated' measures spur gears (a helical gear's normal section is its "
                "virtual spur gear, which has no whole tooth count); use method='exact'"
            )
        tol = gear.module / 2000 if tolerance is None else check_tolerance(tolerance)
        x, y = _simulated_flank(gear, cutter, tol, s, half)
        point, rho_f = _polyline_tangent(x, y, math.radians(tangent), 0.1 * gear.module)
        (lx, ly), (tx, ty) = _polyline_at_radius(x, y, r_en, 0.1 * gear.module)
    # the load acts along the flank normal pointing into the tooth (towards x < 0)
    nx, ny = ty, -tx
    if nx > 0:
        nx, ny = -nx, -ny
    alpha = math.atan2(-ny, -nx)
    axis_y = ly - lx * ny / nx
    s_fn = 2.0 * point[0]
    h_fe = axis_y - point[1]
    if not (s_fn > 0 and h_fe > 0 and rho_f > 0):
        raise GearError(
            f"the {tangent:g} deg tangent meets no fillet that carries the tooth (s_Fn = "
            f"{s_fn:.4g}, h_Fe = {h_fe:.4g} mm): method B does not apply"
        )
    return RootForm(s_fn, rho_f, h_fe, alpha, point, (lx, ly), (0.0, axis_y), float(tangent))


def _xy(rho, eta, s, half):
    """Tooth-frame coordinates of profile points (radius, angle from the space centre)."""
    theta = half - np.asarray(eta, float)
    return np.asarray(rho) * np.sin(theta), s * np.asarray(rho) * np.cos(theta)


def _exact_tangent(prof, s, half, target):
    """The point of the exact fillet where its tangent is inclined ``target`` rad to the tooth
    centre line, and the curvature radius there."""
    from scipy.optimize import brentq  # heavy: imported where used

    fold = prof.ring_fold if hasattr(prof, "ring_fold") else None
    if fold is not None:  # a ring's rack-limit fillet: its returning branch, root to flank
        t_root, t_flank = fold
    else:
        t_root, t_flank = 0.0, prof.tau_form if (prof.has_round or prof.undercut) else 0.0
    if t_flank == t_root:
        raise GearError("the tooth has no root fillet (sharp tool corner): method B needs one")
    span = t_flank - t_root  # negative on a folded fillet: walking from the root lowers tau
    h = 1e-5

    def curve(u):  # u = 0 at the root, 1 where the fillet meets the flank
        rho, eta, _ = prof.fillet(t_root + np.asarray(u) * span)
        return _xy(rho, eta, s, half)

    def angle(u):
        x0, y0 = curve(np.asarray(u) - h)
        x1, y1 = curve(np.asarray(u) + h)
        return np.arctan2(-(x1 - x0), y1 - y0)

    taus = np.linspace(2 * h, 1 - 2 * h, 2001)
    phi = angle(taus) - target
    cross = np.flatnonzero((phi[:-1] > 0) & (phi[1:] <= 0))
    if cross.size == 0:
        raise GearError(
            f"no tangent at {math.degrees(target):g} deg touches the root fillet (its tangent "
            f"turns from {math.degrees(phi[0] + target):.1f} to "
            f"{math.degrees(phi[-1] + target):.1f} deg): method B does not apply"
        )
    i = int(cross[0])
    tau = brentq(lambda t: float(angle(t)) - target, taus[i], taus[i + 1], xtol=1e-14, rtol=1e-15)
    x, y = (float(v) for v in curve(tau))
    k = 1e-3
    xs, ys = curve(np.array([tau - k, tau, tau + k]))
    dx, dy = (xs[2] - xs[0]) / (2 * k), (ys[2] - ys[0]) / (2 * k)
    ddx, ddy = (xs[2] - 2 * xs[1] + xs[0]) / k**2, (ys[2] - 2 * ys[1] + ys[0]) / k**2
    rho_f = (dx * dx + dy * dy) ** 1.5 / abs(dx * ddy - dy * ddx)
    return (x, y), float(rho_f)


def _simulated_flank(gear, cutter, tol, s, half):
    """One flank of tooth 0 of a simulated cut, tooth frame, root (space centre) to tip."""
    if cutter is None:
        poly = rack_outline(gear, tol)
        ring = poly.exterior
    else:
        poly = shaper_outline(gear, tol, cutter=cutter)
        ring = poly.exterior if not gear.internal else poly.interiors[0]
    c = np.asarray(ring.coords)[:-1]
    psi = np.arctan2(c[:, 1], c[:, 0])  # tooth 0 is centred on +x
    rho = np.hypot(c[:, 0], c[:, 1])
    inside = (psi <= 1e-12) & (psi >= -half - 1e-12)
    # the arc of the boundary in the window, in boundary order, starting at the space centre
    idx = np.flatnonzero(inside)
    breaks = np.flatnonzero(np.diff(idx) != 1)
    runs = np.split(idx, breaks + 1)
    if len(runs) > 1 and runs[0][0] == 0 and runs[-1][-1] == len(c) - 1:
        runs = [np.concatenate([runs[-1], runs[0]]), *runs[1:-1]]
    run = max(runs, key=len)
    theta = -psi[run]
    x, y = rho[run] * np.sin(theta), s * rho[run] * np.cos(theta)
    if theta[0] < theta[-1]:  # walk from the space centre (theta = pi/z) to the tooth centre
        x, y = x[::-1], y[::-1]
    return x, y


def _polyline_tangent(x, y, target, window):
    """Where the polyline's direction crosses ``target`` rad from the y axis (walking from the
    root): quartics x(s), y(s) in the arc length s are fitted by least squares to the points
    within ``window`` of arc around the crossing (the simulation's scallops average out, the
    fillet's changing curvature is followed), the tangent point is solved on them by Newton's
    method and rho_F is their curvature radius there."""
    from numpy.polynomial import polynomial as poly

    dx, dy = np.diff(x), np.diff(y)
    phi = np.arctan2(-dx, dy) - target
    cross = np.flatnonzero((phi[:-1] > 0) & (phi[1:] <= 0))
    if cross.size == 0:
        raise GearError(
            f"no tangent at {math.degrees(target):g} deg touches the simulated root fillet: "
            "method B does not apply"
        )
    i = int(cross[0])
    arc = np.concatenate([[0.0], np.cumsum(np.hypot(dx, dy))])
    near = np.abs(arc - arc[i + 1]) <= window
    if near.sum() < 6:
        raise GearError("the simulated fillet has too few points; use a finer tolerance")
    t = arc[near] - arc[i + 1]
    px, py = poly.polyfit(t, x[near], 4), poly.polyfit(t, y[near], 4)
    d1x, d1y = poly.polyder(px), poly.polyder(py)
    d2x, d2y = poly.polyder(d1x), poly.polyder(d1y)

    def turn(s):
        return math.atan2(-poly.polyval(s, d1x), poly.polyval(s, d1y)) - target

    s, h = 0.0, 1e-7 * window
    for _ in range(50):
        step = turn(s) / ((turn(s + h) - turn(s - h)) / (2 * h))
        s -= step
        if abs(step) < 1e-12 * window:
            break
    a, b = poly.polyval(s, d1x), poly.polyval(s, d1y)
    c, d = poly.polyval(s, d2x), poly.polyval(s, d2y)
    radius = (a * a + b * b) ** 1.5 / abs(a * d - b * c)
    return (float(poly.polyval(s, px)), float(poly.polyval(s, py))), float(radius)


def _polyline_at_radius(x, y, r, window):
    """The point of the polyline at radius ``r`` from the gear centre (the crossing nearest the
    tip) and the direction towards the tip there, from quadratics in the arc length fitted to the
    points within ``window`` of arc (averaging the simulation's scallops)."""
    from numpy.polynomial import polynomial as poly

    rr = np.hypot(x, y)
    hit = np.flatnonzero((rr[:-1] - r) * (rr[1:] - r) <= 0)
    if hit.size == 0:
        raise GearError(f"the simulated flank does not reach the load point d_en = {2 * r:.4f} mm")
    i = int(hit[-1])
    arc = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(x), np.diff(y)))])
    f = (r - rr[i]) / (rr[i + 1] - rr[i])
    s0 = arc[i] + f * (arc[i + 1] - arc[i])
    near = np.abs(arc - s0) <= window
    if near.sum() < 4:
        return (x[i] + f * (x[i + 1] - x[i]), y[i] + f * (y[i + 1] - y[i])), (
            x[i + 1] - x[i], y[i + 1] - y[i])  # fmt: skip
    t = arc[near] - s0
    px, py = poly.polyfit(t, x[near], 2), poly.polyfit(t, y[near], 2)
    point = (float(poly.polyval(0.0, px)), float(poly.polyval(0.0, py)))
    return point, (float(px[1]), float(py[1]))
