"""Layer 4, checks: every finding of ``Gear.check()`` and ``GearPair.check()`` as a vectorised
signed margin (positive = satisfied), over arrays of gears and pairs.

The classes call these functions for one gear or one pair; :func:`gears.search.engine.pairs` calls
them for millions (issue 13). Each margin is the one the finding of the same name reports:

* gear: ``undercut`` (x - x_min, module), ``tip_above_base`` ((d_a - d_b)/2, mm),
  ``pointed_tip`` (normal tip land minus the required land, mm; the tip margin when the tip is
  inside the base circle), ``tooth_height`` (the tip above the root and above the form circle;
  inside both for a ring; mm);
* pair: ``contact_ratio`` (eps_alpha - required), ``tip_interference`` and
  ``tip_interference_2`` (mm along the line of action from each gear's form circle to where the
  mate's tip meets its flank), the largest specific sliding of each flank (Ozols §21-4), and for
  internal pairs the KHK involute, trochoid and radial conditions
  (:func:`gears.meshing.internal_interference`) and ``ring_tip_above_base``.

The form circle of an undercut gear is where the generated fillet cuts the involute:
:func:`undercut_form_diameter` solves it for arrays of gears (a grid bracket, then bisection to
machine precision), on the same envelope equations as :class:`gears.cutting.profile.ToothProfile`
(:meth:`gears.rack.RackTool.envelope`; Litvin & Fuentes).
"""

from __future__ import annotations

import math
from dataclasses import replace
from functools import lru_cache
from types import SimpleNamespace
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from gears.errors import GearError
from gears.geometry import (
    CROSSING,
    base_diameter,
    form_diameter,
    half_angle_at_reference,
    min_profile_shift,
    reference_diameter,
    root_diameter,
    tip_diameter,
    tooth_thickness,
    transverse_pressure_angle,
)
from gears.involute import inv
from gears.meshing import (
    internal_interference,
    line_positions,
    pair_geometry,
    specific_sliding,
)
from gears.rack import BasicRack, RackTool

__all__ = [
    "GearMargins",
    "PairMargins",
    "center_distance_reach",
    "equal_sliding_split",
    "flank_depth",
    "form_lengths",
    "gear_margins",
    "has_working_angle",
    "pair_margins",
    "pointed_tip_margin",
    "proportional_split",
    "split_shift_sum",
    "tip_diameter_limits",
    "tip_interference",
    "tooth_height_margin",
    "undercut_form_diameter",
]

_GRID = 801  # fillet parameter samples that bracket the crossing (as ToothProfile.tau_form)
_BISECT = 64  # halvings of the bracket: below 1e-18 of the fillet parameter


def _out(a):
    a = np.asarray(a)
    return a[()] if a.ndim == 0 else a


class GearMargins(NamedTuple):
    """Signed margins of one gear's findings (arrays)."""

    undercut: np.ndarray  # module; +inf for an internal gear (not checked on the gear)
    tip_above_base: np.ndarray  # mm
    pointed_tip: np.ndarray  # mm
    tooth_height: np.ndarray  # mm


def pointed_tip_margin(z, module, profile_shift, pressure_angle, helix_angle, internal,
                       tip_diameter, min_tip_land=0.2):  # fmt: skip
    """Normal tip land minus ``min_tip_land`` m_n, in mm (finding ``pointed_tip``).

    s_an = s_at cos beta_a with tan beta_a = tan beta d_a / d (ISO 21771). A tip inside
    the base circle has no involute land: the margin is then ``(d_a - d_b)/2`` (negative).
    """
    z, m, da = (np.asarray(v, float) for v in (z, module, tip_diameter))
    db = base_diameter(z, m, pressure_angle, helix_angle)
    tip = (da - db) / 2.0
    above = tip >= 0
    # the signed thickness: negative where the flanks have crossed below the tip
    dy = np.where(above, da, db)
    s_at = tooth_thickness(
        dy, z, m, profile_shift, pressure_angle, helix_angle, internal, signed=True
    )
    d = reference_diameter(z, m, helix_angle)
    beta_a = np.arctan(np.tan(np.radians(helix_angle)) * da / d)
    land = s_at * np.cos(beta_a) - np.asarray(min_tip_land, float) * m
    return _out(np.where(above, land, tip))


def tooth_height_margin(tip_diameter, root_diameter, form_diameter, internal=False):
    """Finding ``tooth_height``: the tip lies above the root circle and above the form circle
    (a ring's: inside both), in mm of radius: ``min(d_a - d_f, d_a - d_Ff) / 2``, mirrored for
    a ring. A NaN form diameter (the fillet cuts the whole involute away) counts as the tip."""
    da, df, dff = (np.asarray(v, float) for v in (tip_diameter, root_diameter, form_diameter))
    s = np.where(np.asarray(internal, bool), -1.0, 1.0)
    dff = np.where(np.isnan(dff), da + s * np.abs(da - df), dff)
    return _out(s * (da - np.where(s > 0, np.maximum(df, dff), np.minimum(df, dff))) / 2.0)


def flank_depth(rack, pressure_angle):
    """The rack tool's straight-flank depth h*_eff at each pressure angle (arrays): the rack
    re-angled as :class:`gears.Gear` re-angles it (:meth:`BasicRack.with_pressure_angle`: its
    root radius capped to fit the tool), one rack per distinct angle.

    >>> round(float(flank_depth(BasicRack.iso53("A"), 30.0)), 6)   # the round capped at 30 deg
    1.194825
    """
    pa = np.asarray(pressure_angle, float)
    out = np.empty(pa.shape)
    for a in np.unique(pa):
        r = rack if a == rack.pressure_angle else rack.with_pressure_angle(float(a))
        out[pa == a] = r.straight_flank_depth
    return _out(out)


def gear_margins(z: ArrayLike, module: ArrayLike, profile_shift: ArrayLike = 0.0,
                 pressure_angle: ArrayLike = 20.0, helix_angle: ArrayLike = 0.0,
                 internal: ArrayLike = False, rack: BasicRack | None = None,
                 tip_alteration: ArrayLike = 0.0, min_tip_land: float = 0.2,
                 form: ArrayLike | None = None,
                 root: ArrayLike | None = None) -> GearMargins:  # fmt: skip
    """All margins of ``Gear.check()`` for rack-cut gears (arrays broadcast).

    ``form`` and ``root`` give the form- and root-circle diameters when the caller has them (a
    shaper-cut gear); by default they come from the rack: the closed form of
    :func:`gears.geometry.form_diameter`, or :func:`undercut_form_diameter` for undercut
    external gears.

    Examples
    --------
    >>> g = gear_margins(12, 3, 0.6)   # KHK's 12-tooth pinion, x = 0.6: no undercut
    >>> round(float(g.undercut), 4), round(float(g.tip_above_base), 4)
    (0.3019, 5.8855)
    """
    rack = rack or BasicRack.iso53()
    z, m, x = (np.asarray(v, float) for v in (z, module, profile_shift))
    internal = np.asarray(internal, bool)
    depth = flank_depth(rack, pressure_angle)
    da = tip_diameter(z, m, x, helix_angle, rack.addendum, internal, tip_alteration)
    db = base_diameter(z, m, pressure_angle, helix_angle)
    df = root_diameter(z, m, x, helix_angle, rack.dedendum, internal) if root is None else root
    x_min = min_profile_shift(z, pressure_angle, helix_angle, depth)
    undercut = np.where(internal, np.inf, x - x_min)
    if form is None:
        form = form_diameter(z, m, x, pressure_angle, helix_angle, depth, internal,
                             rack.dedendum)  # fmt: skip
        cut = ~internal & (undercut < -1e-12)
        if np.any(cut):
            form = np.array(np.broadcast_to(form, np.broadcast_shapes(np.shape(form),
                                                                       cut.shape)))  # fmt: skip
            cut = np.broadcast_to(cut, form.shape)
            pick = [np.broadcast_to(v, form.shape)[cut] for v in (z, m, x)]
            pa = np.broadcast_to(np.asarray(pressure_angle, float), form.shape)[cut]
            hb = np.broadcast_to(np.asarray(helix_angle, float), form.shape)[cut]
            form[cut] = undercut_form_diameter(*pick, pa, hb, rack)
    tip = (da - db) / 2.0
    land = pointed_tip_margin(z, m, x, pressure_angle, helix_angle, internal, da, min_tip_land)
    height = tooth_height_margin(da, df, form, internal)
    return GearMargins(*(_out(v) for v in (undercut, tip, land, height)))


def undercut_form_diameter(z, module, profile_shift, pressure_angle=20.0, helix_angle=0.0,
                           rack=None):  # fmt: skip
    """Form-circle diameter of rack-cut external gears, undercut or not (arrays), in mm.

    Not undercut: the closed form (ISO 21771's form diameter). Undercut: where the fillet generated
    by the tool's tip round (and the straight flank below the limit point N1) cuts the involute,
    on the envelope of :meth:`gears.rack.RackTool.envelope`: the first crossing on a grid of
    the fillet parameter, then bisection to machine precision (the array form of
    :func:`gears.cutting.profile.undercut_form_diameter`, which uses Brent's method per gear). NaN
    where the fillet never meets the involute (the tooth is cut away).

    Examples
    --------
    >>> round(float(undercut_form_diameter(20, 2, 0.0)), 4)   # the closed form: 37.6401
    37.6401
    >>> d = undercut_form_diameter([8, 9], 1, 0.0)             # undercut: above the base circle
    >>> bool(np.all(d > np.array([8, 9]) * np.cos(np.radians(20))))
    True
    """
    rack = rack or BasicRack.iso53()
    args = np.broadcast_arrays(
        *(np.asarray(v, float) for v in (z, module, profile_shift, pressure_angle, helix_angle))
    )
    shape = args[0].shape
    z, m, x, pa, hb = (v.ravel() for v in args)
    depth = flank_depth(rack, pa)
    out = np.asarray(form_diameter(z, m, x, pa, hb, depth, False, rack.dedendum), float).copy()
    cut = x < min_profile_shift(z, pa, hb, depth) - 1e-12
    groups = np.unique(np.stack([m[cut], pa[cut], hb[cut]], axis=1), axis=0) if cut.any() else []
    for mg, pg, bg in groups:
        sel = cut & (m == mg) & (pa == pg) & (hb == bg)
        out[sel] = _undercut_group(z[sel], x[sel], float(mg), float(pg), float(bg), rack)
    return _out(out.reshape(shape))


def _undercut_group(z, x, module, pressure_angle, helix_angle, rack):
    """Undercut form diameters of gears sharing module, pressure angle and helix angle."""
    if pressure_angle != rack.pressure_angle:
        rack = rack.with_pressure_angle(pressure_angle)
    at_deg = math.degrees(float(transverse_pressure_angle(pressure_angle, helix_angle)))
    cb = math.cos(math.radians(helix_angle))
    proxy = SimpleNamespace(  # the tool's shape needs only these (RackTool.for_gear)
        module=module, pressure_angle=pressure_angle, transverse_pressure_angle=at_deg,
        helix_angle=helix_angle, internal=False, rack=rack, reference_diameter=2.0 * module / cb,
        transverse_module=module / cb, profile_shift=0.0,
    )  # fmt: skip
    r = (z * module / cb / 2.0)[:, None]
    xm = (x * module)[:, None]
    tool = replace(RackTool.for_gear(proxy), r=r, xm=xm)
    at = math.radians(at_deg)
    rb = r * math.cos(at)
    psi = half_angle_at_reference(z, x, pressure_angle, helix_angle, False)[:, None]
    eta_p = np.pi / z[:, None] - psi
    v_limit = -xm - r * math.sin(at) ** 2
    inv_at = float(inv(at))

    def fillet(tau):
        on_round = tau <= 1.0
        tr = -math.pi / 2 + np.minimum(tau, 1.0) * (tool.t_f + math.pi / 2)
        ur, vr, nur, nvr = tool.round_points(tr)
        vf = tool.v_f + (np.maximum(tau, 1.0) - 1.0) * (v_limit - tool.v_f)
        uf, vff, nuf, nvf = tool.flank_points(vf)
        rho, eta, _ = tool.envelope(
            np.where(on_round, ur, uf), np.where(on_round, vr, vff),
            np.where(on_round, nur, nuf), np.where(on_round, nvr, nvf),
        )  # fmt: skip
        return rho, eta

    def gap(tau):
        rho, eta = fillet(tau)
        ay = np.arccos(np.clip(rb / np.maximum(rho, rb), -1.0, 1.0))
        return rho, np.where(rho >= rb, eta - (eta_p + (inv(ay) - inv_at)), 1.0)

    grid = np.linspace(0.0, 2.0, _GRID)[:-1]
    _, g = gap(grid[None, :])
    hit = (g[:, :-1] > CROSSING) & (g[:, 1:] <= CROSSING)
    found = hit.any(axis=1)
    i = np.argmax(hit, axis=1)
    lo, hi = grid[i][:, None], grid[np.minimum(i + 1, grid.size - 1)][:, None]
    # the crossing itself (g = 0), or where a fillet that only touches comes within CROSSING
    level = np.where(g[np.arange(len(i)), np.minimum(i + 1, grid.size - 1)] > 0, CROSSING, 0.0)
    level = level[:, None]
    for _ in range(_BISECT):
        mid = 0.5 * (lo + hi)
        _, gm = gap(mid)
        right = gm > level
        lo, hi = np.where(right, mid, lo), np.where(right, hi, mid)
    rho, _ = fillet(0.5 * (lo + hi))
    return np.where(found, 2.0 * rho[:, 0], np.nan)


def has_working_angle(z1, z2, x1, x2, pressure_angle=20.0, helix_angle=0.0, internal=False):
    """True where a working pressure angle exists: inv alpha_t + 2 tan alpha_n (x1 + x2) /
    (z1 +- z2) >= 0 (a ring's x2 in DIN 3960's sign; the condition
    :func:`gears.meshing.pair_geometry` raises on)."""
    s = np.where(np.asarray(internal, bool), -1.0, 1.0)
    at = transverse_pressure_angle(pressure_angle, helix_angle)
    xs = np.asarray(x1, float) + np.asarray(x2, float)
    zs = np.asarray(z1, float) + s * np.asarray(z2, float)
    return _out(inv(at) + 2.0 * np.tan(np.radians(pressure_angle)) * xs / zs >= 0.0)


def proportional_split(z1, z2, total):
    """x1 of the ``"proportional"`` split of a shift sum (external pairs; Roloff/Matek's
    approximation of DIN 3992): x1 = S/2 + (0.5 - S/2) lg(u) / lg(z1 z2 / 100), S/2 when u = 1 or
    lg(z1 z2/100) = 0 (the DIN 3992 / ISO/TR 4467 style suggestion as approximated by Roloff/Matek;
    the rule of ``GearPair.at_center_distance(..., split="proportional")``).

    >>> round(float(proportional_split(12, 30, 0.8)), 6)
    0.471533
    """
    z1, z2, total = (np.asarray(v, float) for v in (z1, z2, total))
    den = np.log10(z1 * z2 / 100.0)
    flat = (z1 == z2) | (np.abs(den) < 1e-9)
    with np.errstate(divide="ignore", invalid="ignore"):
        x1 = total / 2 + (0.5 - total / 2) * np.log10(z2 / z1) / np.where(flat, 1.0, den)
    return _out(np.where(flat, total / 2, x1))


def equal_sliding_split(z1, z2, module, total, pressure_angle=20.0, helix_angle=0.0,
                        internal=False, addendum=1.0, tip_shortening=True):  # fmt: skip
    """x1 of the ``"equal_sliding"`` split of a shift sum (arrays): the largest specific sliding
    of both flanks is equal, ``|zeta_1(u_A)| = |zeta_2(u_E)|`` (Joldasbekov §12 rule 3), the rule of
    ``GearPair.at_center_distance(..., split="equal_sliding")``. As there:
    ``log(abs(zeta_1)) - log(abs(zeta_2))`` on 61 values of x1 (S/2 +- 1.5 external, -1.5 ...
    1.5 internal), the first sign change between two finite values, then bisection to machine
    precision. NaN where no split balances (the pair method raises there).

    >>> round(float(equal_sliding_split(12, 30, 4, 0.8)), 4)   # GearPair.at_center_distance
    0.5271
    """
    args = np.broadcast_arrays(*(np.asarray(v, float) for v in (z1, z2, module, total)))
    shape = args[0].shape
    z1, z2, m, total = (v.ravel() for v in args)
    s = -1.0 if internal else 1.0
    grid = np.linspace(-1.5, 1.5, 61)[None, :] + (
        total[:, None] / 2 if s > 0 else 0.0 * total[:, None]
    )

    def imbalance(x1):
        x2 = total[:, None] - x1  # x1 + x2 = S, a ring's x2 too (DIN 3960)
        g = pair_geometry(z1[:, None], z2[:, None], m[:, None], x1, x2, pressure_angle,
                          helix_angle, internal, addendum, tip_shortening, threads=1)  # fmt: skip
        rb1 = base_diameter(z1, m, pressure_angle, helix_angle)[:, None] / 2
        rb2 = base_diameter(z2, m, pressure_angle, helix_angle)[:, None] / 2
        ra1, ra2 = g.tip_diameter_1 / 2, g.tip_diameter_2 / 2
        tan_wt = np.tan(np.radians(g.working_pressure_angle))
        u_a, u_e, _ = line_positions(ra1, ra2, rb1, rb2, tan_wt, s)
        u = (z2 / z1)[:, None]
        with np.errstate(all="ignore"):
            zeta1, _ = specific_sliding(u_a, rb1, rb2, tan_wt, u, internal)
            _, zeta2 = specific_sliding(u_e, rb1, rb2, tan_wt, u, internal)
            a, b = np.abs(zeta1), np.abs(zeta2)
            v = np.log(a) - np.log(b)
        return np.where((ra1 >= rb1) & (ra2 >= rb2) & (a > 0) & (b > 0), v, np.nan)

    v = imbalance(grid)
    ok = np.isfinite(v)
    hit = ok[:, :-1] & ok[:, 1:] & (v[:, :-1] * v[:, 1:] <= 0)
    found = hit.any(axis=1)
    i = np.argmax(hit, axis=1)
    rows = np.arange(len(z1))
    lo, hi = grid[rows, i][:, None], grid[rows, i + 1][:, None]
    f_lo = v[rows, i][:, None]
    exact = f_lo == 0
    for _ in range(_BISECT):
        mid = 0.5 * (lo + hi)
        fm = imbalance(mid)
        same = np.sign(fm) == np.sign(f_lo)
        lo, hi = np.where(same, mid, lo), np.where(same, hi, mid)
    x1 = np.where(exact, lo, 0.5 * (lo + hi))[:, 0]
    return _out(np.where(found, x1, np.nan).reshape(shape))


def form_lengths(form_diameter, base_diameter, tip_diameter=None):
    """Distance along the line of action from the base-circle tangent point to the form circle:
    ``sqrt(r_Ff^2 - r_b^2)`` (0 when the form circle is the base circle). A NaN form diameter
    (the undercut fillet cuts the whole involute away) counts as the tip: no flank is left for
    the mate to meet (as in :func:`tooth_height_margin`)."""
    form = np.asarray(form_diameter, float)
    if tip_diameter is not None:
        form = np.where(np.isnan(form), np.asarray(tip_diameter, float), form)
    rff, rb = form / 2, np.asarray(base_diameter, float) / 2
    return _out(np.sqrt(np.maximum(rff * rff - rb * rb, 0.0)))


def tip_interference(u_a, u_e, u_n2, l1, l2, internal=False):
    """Findings ``tip_interference`` (gear 2's tip against gear 1's form circle) and
    ``tip_interference_2`` (gear 1's tip against gear 2's), mm along the line of action.

    ``u_A - l1``; external ``(u_N2 - u_E) - l2``, internal ``l2 - (u_E - u_N2)``.
    """
    s = np.asarray(internal, bool)
    m1 = np.asarray(u_a, float) - l1
    m2 = np.where(s, l2 - (u_e - u_n2), (u_n2 - u_e) - l2)
    return _out(m1), _out(m2)


def tip_diameter_limits(rb1, rb2, u_n2, l1, l2, internal=False):
    """Tip diameters at which each tip meets the mate's flank at the mate's form circle:
    ``(largest d_a1, limit of d_a2)`` (a tip circle of radius sqrt(r_b^2 + (u - u_N)^2) cuts the
    line of action at u)."""
    s = np.where(np.asarray(internal, bool), -1.0, 1.0)
    lim1 = 2.0 * np.sqrt(rb1 * rb1 + (u_n2 - s * l2) ** 2)
    lim2 = 2.0 * np.sqrt(rb2 * rb2 + (u_n2 - l1) ** 2)
    return _out(lim1), _out(lim2)


class PairMargins(NamedTuple):
    """Geometry and signed margins of :func:`pair_margins` (arrays of one shape)."""

    center_distance: np.ndarray
    working_pressure_angle: np.ndarray
    tip_diameter_1: np.ndarray
    tip_diameter_2: np.ndarray
    contact_ratio: np.ndarray
    sliding_1: np.ndarray  # largest |specific sliding| of gear 1's flank (at contact start)
    sliding_2: np.ndarray  # gear 2's (at contact end)
    g1: GearMargins
    g2: GearMargins
    contact_ratio_margin: np.ndarray
    tip_interference: np.ndarray
    tip_interference_2: np.ndarray
    involute_interference: np.ndarray  # +inf on external pairs (not a finding there)
    trochoid_interference: np.ndarray
    radial_interference: np.ndarray
    ring_tip_above_base: np.ndarray

    def findings(self) -> dict[str, np.ndarray]:
        """Margins by the finding names of ``GearPair.check()`` (``g1.undercut`` ...)."""
        out = {}
        for i, g in (("g1", self.g1), ("g2", self.g2)):
            out.update({f"{i}.{k}": v for k, v in g._asdict().items()})
        for k in ("contact_ratio_margin", "tip_interference", "tip_interference_2",
                  "involute_interference", "trochoid_interference", "radial_interference",
                  "ring_tip_above_base"):  # fmt: skip
            out[k.removesuffix("_margin")] = getattr(self, k)
        return out

    def ok(self, allow_undercut: bool = False) -> np.ndarray:
        """True where every finding holds (``allow_undercut`` skips the undercut findings)."""
        names = [k for k in self.findings() if not (allow_undercut and k.endswith(".undercut"))]
        f = self.findings()
        # a scalar input leaves some margins 0-d: broadcast them to the pairs' shape
        return np.logical_and.reduce(np.broadcast_arrays(*[np.asarray(f[k]) >= 0 for k in names]))


def pair_margins(z1: ArrayLike, z2: ArrayLike, module: ArrayLike, x1: ArrayLike = 0.0,
                 x2: ArrayLike = 0.0, pressure_angle: ArrayLike = 20.0,
                 helix_angle: ArrayLike = 0.0, internal: ArrayLike = False,
                 rack: BasicRack | None = None, tip_shortening: bool = True,
                 min_contact_ratio: float = 1.1, min_tip_land: float = 0.2,
                 allow_undercut: bool = True, threads: int | None = 1) -> PairMargins:  # fmt: skip
    """Every finding of ``GearPair(Gear(z1, ...), Gear(z2, ...)).check()`` over arrays of
    rack-cut pairs: the geometry of :func:`gears.meshing.pair_geometry`, each gear's
    :func:`gear_margins` and the mesh margins, with the largest specific sliding.

    ``helix_angle`` is gear 1's (gear 2 has the opposite hand externally). Pairs whose shift
    sum leaves no working pressure angle raise :class:`GearError` (filter them first, as
    :func:`gears.search.engine.pairs` does). ``allow_undercut=False`` skips the undercut form-circle
    solve (undercut gears fail their ``undercut`` finding anyway; their tip-interference margin
    then uses the closed form).

    Examples
    --------
    >>> p = pair_margins(12, 24, 3, 0.6, 0.36)   # KHK example: a_w = 56.4999, eps = 1.2021
    >>> round(float(p.center_distance), 4), round(float(p.contact_ratio), 4)
    (56.4999, 1.2021)
    >>> bool(p.ok())
    True
    """
    rack = rack or BasicRack.iso53()
    g = pair_geometry(z1, z2, module, x1, x2, pressure_angle, helix_angle, internal,
                      rack.addendum, tip_shortening, threads=threads)  # fmt: skip
    k = g.tip_alteration
    shape = np.broadcast_shapes(
        np.shape(g.center_distance), *(np.shape(v) for v in (z1, z2, module, x1, x2,
                                                             pressure_angle, helix_angle))
    )  # fmt: skip
    internal = np.asarray(internal, bool)  # stays 0-d (and its helix trigonometry scalar)
    s = np.where(internal, -1.0, 1.0)
    z1, z2, m = (np.asarray(v, float) for v in (z1, z2, module))
    hb2 = np.where(internal, helix_angle, -np.asarray(helix_angle, float))
    depth = flank_depth(rack, pressure_angle)
    if allow_undercut:
        f1 = f2 = None
    else:  # closed form only: rows where it differs fail their undercut finding anyway
        f1 = form_diameter(z1, m, x1, pressure_angle, helix_angle, depth, False, rack.dedendum)
        f2 = form_diameter(z2, m, x2, pressure_angle, hb2, depth, internal, rack.dedendum)
    m1 = gear_margins(z1, m, x1, pressure_angle, helix_angle, False, rack, k, min_tip_land, f1)
    m2 = gear_margins(z2, m, x2, pressure_angle, hb2, internal, rack, np.where(internal, 0, k),
                      min_tip_land, f2)  # fmt: skip
    if f1 is None:
        f1 = _form(z1, m, x1, pressure_angle, helix_angle, False, rack)
        f2 = _form(z2, m, x2, pressure_angle, hb2, internal, rack)
    ra1, ra2 = g.tip_diameter_1 / 2, g.tip_diameter_2 / 2
    rb1 = base_diameter(z1, m, pressure_angle, helix_angle) / 2
    rb2 = base_diameter(z2, m, pressure_angle, helix_angle) / 2
    tan_wt = np.tan(np.radians(g.working_pressure_angle))
    u_a, u_e, u_n2 = line_positions(ra1, ra2, rb1, rb2, tan_wt, s)
    meshes = (ra1 >= rb1) & (ra2 >= rb2)
    cr_margin = np.where(meshes, g.contact_ratio - min_contact_ratio, -min_contact_ratio)
    l1, l2 = form_lengths(f1, 2 * rb1, 2 * ra1), form_lengths(f2, 2 * rb2, 2 * ra2)
    t1, t2 = tip_interference(u_a, u_e, u_n2, l1, l2, internal)
    big = np.inf
    t1 = np.where(meshes, t1, big)  # not reported when the contact ratio fails first
    t2 = np.where(meshes, t2, big)
    with np.errstate(divide="ignore", invalid="ignore"):
        zeta1, _ = specific_sliding(u_a, rb1, rb2, tan_wt, z2 / z1, internal)
        _, zeta2 = specific_sliding(u_e, rb1, rb2, tan_wt, z2 / z1, internal)
    sl1 = np.where(meshes & np.isfinite(zeta1), np.abs(zeta1), big)
    sl2 = np.where(meshes & np.isfinite(zeta2), np.abs(zeta2), big)
    if np.any(internal):
        ok = internal & meshes & (ra2 > rb2) & (ra1 > rb1)
        ii = internal_interference(
            z1, z2, g.center_distance, np.maximum(ra1, rb1), np.maximum(ra2, rb2), rb1, rb2,
            g.working_pressure_angle,
        )  # fmt: skip
        inv_m, tro_m, rad_m = (np.where(ok, v, np.where(internal & meshes, -big, big))
                               for v in ii)  # fmt: skip
        ring = np.where(internal & meshes, ra2 - rb2, big)
    else:
        inv_m = tro_m = rad_m = ring = big

    def full(v):  # every margin of one shape: a scalar input never leaves one 0-d
        return np.broadcast_to(np.asarray(v, float), shape)

    return PairMargins(
        *(full(v) for v in (g.center_distance, g.working_pressure_angle, g.tip_diameter_1,
                            g.tip_diameter_2, np.where(meshes, g.contact_ratio, 0.0), sl1, sl2)),
        GearMargins(*(full(v) for v in m1)), GearMargins(*(full(v) for v in m2)),
        *(full(v) for v in (cr_margin, t1, t2, inv_m, tro_m, rad_m, ring)),
    )  # fmt: skip


def _form(z, m, x, pressure_angle, helix_angle, internal, rack):
    """Form diameters: the undercut solve for external gears, the closed form for rings."""
    ext = undercut_form_diameter(z, m, x, pressure_angle, helix_angle, rack)
    ring = form_diameter(z, m, x, pressure_angle, helix_angle, flank_depth(rack, pressure_angle),
                         True, rack.dedendum)  # fmt: skip
    return np.where(internal, ring, ext)


@lru_cache(maxsize=256)
def center_distance_reach(
    z1, z2, module, pressure_angle, helix_angle, internal, tip_shortening, whole
):
    """``(low, high)``: the centre distances profile shift can reach for the pair's data (not
    its shifts: the range does not depend on them; :meth:`gears.GearPair.center_distance_range`
    says how); ``whole`` is the smaller whole depth h_a* + h_f* in module units. Cached: a
    search over centre distances asks it once per candidate."""
    from scipy.optimize import brentq  # heavy: imported where used

    s = -1.0 if internal else 1.0
    zsum = z2 + s * z1
    # alpha_t as Gear.transverse_pressure_angle gives it (degrees, then back to radians)
    at = math.radians(math.degrees(transverse_pressure_angle(pressure_angle, helix_angle)))
    a_d = zsum * (module / math.cos(math.radians(helix_angle))) / 2
    low = a_d * math.cos(at)
    if internal or not tip_shortening:
        return low, math.inf

    def left(total: float) -> float:  # tooth left after shortening, module units
        k = pair_geometry(z1, z2, module, total, 0.0, pressure_angle, helix_angle).tip_alteration
        return float(k) + whole

    lowest = -zsum * float(inv(at))
    lowest /= 2 * math.tan(math.radians(pressure_angle))
    lowest += 1e-9 * max(1.0, abs(lowest))  # just inside: inv alpha_wt >= 0 despite rounding
    # the tooth left is whole at x1 + x2 = 0 and shrinks on both sides (k = y - sum <= 0)
    top = max(1.0, zsum / 4)
    while left(top) > 0 and top < 250:
        top *= 2

    def distance(total: float) -> float:
        return float(
            pair_geometry(z1, z2, module, total, 0.0, pressure_angle, helix_angle).center_distance
        )

    high = distance(brentq(left, 0.0, top, xtol=1e-12)) if left(top) <= 0 else math.inf
    if left(lowest) <= 0:
        low = distance(brentq(left, lowest, 0.0, xtol=1e-12))
    return low, high


def split_shift_sum(z1, z2, module, total, pressure_angle, helix_angle, internal, addendum,
                    tip_shortening, split, x1_kept):  # fmt: skip
    """Gear 1's shift x1 when the shift sum ``total`` (x1 + x2, a ring's x2 in DIN 3960's sign) is
    split by ``split`` (:meth:`gears.GearPair.at_center_distance` says how each rule splits it):
    ``"keep"`` keeps ``x1_kept``, ``"proportional"`` (external pairs) and ``"equal_sliding"``
    solve for it. Raises GearError where the rule has no answer."""
    if split == "keep":
        return x1_kept
    if split == "proportional":
        if internal:
            raise GearError("split='proportional' is defined for external pairs; use 'keep'")
        return float(proportional_split(z1, z2, total))
    x1 = float(
        equal_sliding_split(
            z1, z2, module, total, pressure_angle, helix_angle, internal, addendum, tip_shortening
        )
    )
    if not math.isfinite(x1):
        raise GearError(
            f"no split of the shift sum {total:.4f} balances the specific sliding of "
            f"z1 = {z1} and z2 = {z2}; use split='keep' or 'proportional'"
        )
    return x1
