"""Layer 3, the load-dependent power loss of a mesh and its efficiency (ISO/TR 14179-2).

The power lost by sliding in the mesh is P_VZP = P mu_mz H_V: the input power, the mean
coefficient of friction over the path of contact and the loss factor H_V of the path of contact
(ISO/TR 14179-2; Ohlendorf). The mesh efficiency is then eta_z = 1 - mu_mz H_V (the
load-independent losses, churning and windage, and the bearings' are not counted). The formulas
as math: docs/rating.md, "Mesh losses and efficiency".

Loss factor (:func:`loss_factor`). Along the transverse path of contact the sliding speed grows
linearly from the pitch point C, v_g = abs(t) p_bt omega_1 (1 +- 1/u) at the position t p_bt
from C (+ external, - internal), and the load is shared equally by the tooth pairs in contact.
The mean over one mesh cycle of sum(F_i v_g,i) / (F_bt v_bt) is

    H_V = 2 pi (u +- 1) / (z_1 u cos beta_b) * integral from -eps_2 to eps_1 of abs(t) / n(t) dt

with n(t) the number of pairs in contact when one is at t (floor(eps_alpha) or one more). It is
written here in closed form for any eps_alpha >= 1; where the pitch point lies in single contact
and eps_alpha < 2 it is Ohlendorf's H_V = pi (u + 1) / (z_1 u cos beta_b) (1 - eps_alpha +
eps_1^2 + eps_2^2). eps_1, eps_2 are the addendum contact ratios of gear 1 (C to E, its tip) and
gear 2 (A to C).

Coefficient of friction (:func:`friction_coefficient`), the empirical equation of ISO/TR
14179-2: mu_mz = 0.048 ((F_bt / b) / (v_SigmaC rho_redC))^0.2 eta_oil^-0.05 Ra^0.25 X_L, with
F_bt / b in N/mm, the sum of the rolling speeds at the pitch point v_SigmaC = 2 v_t sin
alpha_wt in m/s, the relative radius of curvature at the pitch point rho_redC in mm (normal
section), the oil's dynamic viscosity at its working temperature in mPa s, the mean roughness
Ra = (Ra_1 + Ra_2) / 2 in um and the lubricant factor X_L (:data:`LUBRICANT_FACTORS`).
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from gears.arguments import check_positive, common_shape
from gears.errors import GearError
from gears.geometry import tip_diameter
from gears.meshing import line_positions, pair_geometry

__all__ = [
    "LUBRICANT_FACTORS",
    "MeshLosses",
    "friction_coefficient",
    "loss_factor",
    "lubricant_factor",
    "mesh_losses",
    "pair_efficiency",
    "pair_losses",
]

#: Lubricant factor X_L of ISO/TR 14179-2 by base oil (as quoted from the report's table).
LUBRICANT_FACTORS = {
    "mineral": 1.0,
    "polyalphaolefin": 0.8,
    "polyglycol": 0.7,
    "polyglycol-water-soluble": 0.6,
    "traction": 1.5,
    "phosphate-ester": 1.3,
}

#: Contact ratios above this are refused (the load-sharing sum runs over floor(eps) + 1 zones).
MAX_CONTACT_RATIO = 8.0


class MeshLosses(NamedTuple):
    """The load-dependent mesh loss (arrays): ``loss_factor`` H_V, ``friction`` mu_mz,
    ``efficiency`` eta_z = 1 - mu_mz H_V and ``power_loss`` P_VZP in W."""

    loss_factor: np.ndarray
    friction: np.ndarray
    efficiency: np.ndarray
    power_loss: np.ndarray


def lubricant_factor(lubricant) -> float:
    """X_L of a base oil named in :data:`LUBRICANT_FACTORS`, or a number > 0 given as is."""
    if isinstance(lubricant, str):
        if lubricant not in LUBRICANT_FACTORS:
            raise GearError(
                f"lubricant = {lubricant!r}; valid is one of {', '.join(LUBRICANT_FACTORS)} "
                "or a factor X_L > 0"
            )
        return LUBRICANT_FACTORS[lubricant]
    if isinstance(lubricant, bool) or not isinstance(lubricant, int | float | np.floating):
        raise GearError(f"lubricant = {lubricant!r}; valid is a base oil name or X_L > 0")
    x = float(lubricant)
    if not (math.isfinite(x) and 0.0 < x <= 10.0):
        raise GearError(f"lubricant factor X_L = {lubricant!r}; valid is 0 < X_L <= 10")
    return x


def _abs_integral(a, b):
    """The integral of abs(t) from a to b (a <= b)."""
    return 0.5 * (b * np.abs(b) - a * np.abs(a))


def loss_factor(z1, u, epsilon_1, epsilon_2, base_helix_angle=0.0, internal=False):
    """Loss factor H_V of the real path of contact (see the module docstring; arrays broadcast).

    Parameters
    ----------
    z1 : array_like
        Teeth of gear 1 (the pinion; u = z2 / z1).
    u : array_like
        Gear ratio z2 / z1 (> 0; for a rack, ``inf``).
    epsilon_1, epsilon_2 : array_like
        Addendum contact ratios: (C to E) / p_bt of gear 1's tip, (A to C) / p_bt of gear 2's
        (either may be negative when the pitch point lies outside the path of contact); their
        sum, the transverse contact ratio, must be >= 1.
    base_helix_angle : array_like
        beta_b, degrees.
    internal : array_like
        True where gear 2 is a ring (sliding speed ``omega_1 t (1 - 1/u)``).

    Examples
    --------
    Ohlendorf's closed form: pi (u + 1) / (z1 u) (1 - eps + eps_1^2 + eps_2^2).

    >>> round(float(loss_factor(20, 2.0, 0.8, 0.8)), 6)   # pi 3/40 (1 - 1.6 + 2 * 0.64)
    0.160221
    """
    e1 = np.asarray(epsilon_1, float)
    e2 = np.asarray(epsilon_2, float)
    eps = e1 + e2
    if not np.all(np.isfinite(eps) & (eps >= 1.0 - 1e-12) & (eps <= MAX_CONTACT_RATIO)):
        bad = np.broadcast_to(eps, np.broadcast(eps, eps).shape)
        bad = bad[~(np.isfinite(bad) & (bad >= 1.0 - 1e-12) & (bad <= MAX_CONTACT_RATIO))]
        raise GearError(
            f"transverse contact ratio epsilon_alpha = {bad.ravel()[:3].tolist()}; the loss "
            f"factor H_V needs 1 <= epsilon_alpha <= {MAX_CONTACT_RATIO:g} (continuous mesh)"
        )
    eps = np.maximum(eps, 1.0)
    n = np.floor(eps + 1e-12)  # pairs in contact outside the zones of one more pair
    frac = np.maximum(eps - n, 0.0)
    total = _abs_integral(-e2, e1)
    extra = np.zeros(np.broadcast(e1, e2).shape)
    for k in range(int(np.max(n)) + 1):  # zones [-eps_2 + k, -eps_2 + k + frac], k = 0 ... n
        start = -e2 + k
        extra = extra + np.where(k <= n, _abs_integral(start, start + frac), 0.0)
    integral = total / n - (1.0 / n - 1.0 / (n + 1.0)) * extra
    s = np.where(np.asarray(internal, bool), -1.0, 1.0)
    with np.errstate(divide="ignore"):
        inv_u = np.where(np.isinf(u), 0.0, 1.0 / np.asarray(u, float))
    cos_bb = np.cos(np.radians(base_helix_angle))
    return 2.0 * np.pi * (1.0 + s * inv_u) / (np.asarray(z1, float) * cos_bb) * integral


def friction_coefficient(load_per_width, sum_velocity, curvature_radius, viscosity,
                         roughness=1.0, lubricant_factor=1.0):  # fmt: skip
    """Mean coefficient of friction mu_mz of the mesh, ISO/TR 14179-2 (see the module
    docstring): ``load_per_width`` F_bt / b in N/mm, ``sum_velocity`` v_SigmaC in m/s,
    ``curvature_radius`` rho_redC in mm, ``viscosity`` the oil's dynamic viscosity at its working
    temperature in mPa s, ``roughness`` the mean Ra in um, ``lubricant_factor`` X_L (arrays
    broadcast; every input > 0).

    >>> round(float(friction_coefficient(500.0, 10.0, 10.0, 30.0, 1.0)), 5)
    0.05587
    """
    checked = (("load_per_width", load_per_width), ("sum_velocity", sum_velocity),
               ("curvature_radius", curvature_radius), ("viscosity", viscosity),
               ("roughness", roughness), ("lubricant_factor", lubricant_factor))  # fmt: skip
    for name, value in checked:
        _positive(name, value)
    w = np.asarray(load_per_width, float)
    with np.errstate(over="ignore"):  # a speed near float's smallest: mu = inf, refused after
        ratio = w / (np.asarray(sum_velocity, float) * np.asarray(curvature_radius, float))
    return (
        0.048
        * ratio**0.2
        * np.asarray(viscosity, float) ** -0.05
        * np.asarray(roughness, float) ** 0.25
        * np.asarray(lubricant_factor, float)
    )


def mesh_losses(torque, speed, z1, u, base_radius, working_pressure_angle, epsilon_1, epsilon_2,
                face_width, base_helix_angle=0.0, internal=False, roughness=1.0, viscosity=30.0,
                lubricant_factor=1.0) -> MeshLosses:  # fmt: skip
    """The mesh loss from a pair's path of contact (arrays broadcast; no checks: see
    :func:`pair_losses` and :meth:`gears.GearPair.efficiency`).

    ``torque`` on gear 1 in N m, ``speed`` of gear 1 relative to the carrier in rpm,
    ``base_radius`` r_b1 in mm, ``working_pressure_angle`` alpha_wt in degrees, ``face_width`` b
    in mm, the rest as for :func:`loss_factor` and :func:`friction_coefficient`.
    """
    s = np.where(np.asarray(internal, bool), -1.0, 1.0)
    rb1 = np.asarray(base_radius, float)
    awt = np.radians(working_pressure_angle)
    f_bt = 2000.0 * np.asarray(torque, float) / rb1 / 2.0  # F_bt = 2000 T / d_b1
    rw1 = rb1 / np.cos(awt)
    v_t = rw1 * 1e-3 * np.asarray(speed, float) * np.pi / 30.0  # m/s at the working circle
    v_sum = 2.0 * v_t * np.sin(awt)
    cos_bb = np.cos(np.radians(base_helix_angle))
    rho1 = rb1 * np.tan(awt)
    u = np.asarray(u, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        # rho_red = rho1 rho2 / (rho2 +- rho1), rho2 = u rho1: rho1 u / (u +- 1); a rack: rho1
        rho_red = np.where(np.isinf(u), rho1, rho1 * u / (u + s)) / cos_bb
    mu = friction_coefficient(f_bt / np.asarray(face_width, float), v_sum, rho_red, viscosity,
                              roughness, lubricant_factor)  # fmt: skip
    h_v = loss_factor(z1, u, epsilon_1, epsilon_2, base_helix_angle, internal)
    loss = mu * h_v
    power = np.asarray(torque, float) * np.asarray(speed, float) * np.pi / 30.0
    return MeshLosses(h_v, mu, 1.0 - loss, power * loss)


def _positive(name: str, value) -> None:
    """A GearError naming ``name`` unless every entry of ``value`` is a finite number > 0."""
    try:
        v = np.asarray(value, float)
    except (TypeError, ValueError):
        raise GearError(f"{name} = {value!r}; valid is a finite number > 0") from None
    ok = np.isfinite(v) & (v > 0.0)
    if not np.all(ok):
        bad = np.ravel(v[~ok] if v.ndim else v)[:3].tolist()
        raise GearError(f"{name} = {bad}; valid is a finite number > 0")


def pair_losses(torque: ArrayLike, speed: ArrayLike, z1: ArrayLike, z2: ArrayLike,
                module: ArrayLike, face_width: ArrayLike, x1: ArrayLike = 0.0,
                x2: ArrayLike = 0.0, pressure_angle: ArrayLike = 20.0,
                helix_angle: ArrayLike = 0.0, internal: ArrayLike = False,
                roughness: ArrayLike = 1.0, viscosity: ArrayLike = 30.0,
                lubricant: str | float = "mineral", *, addendum: ArrayLike = 1.0,
                tip_shortening: ArrayLike = True, tip_alteration: Any = (0.0, 0.0),
                errors: str = "raise") -> MeshLosses:  # fmt: skip
    """The mesh loss of many pairs at once, from their tooth data (ISO 21771 geometry by
    :func:`gears.meshing.pair_geometry` with the basic rack's ``addendum`` and
    ``tip_shortening`` as there; arrays broadcast).

    ``tip_alteration`` ``(k1, k2)`` alters the tips beyond the rack's (modules, DIN 3960's k,
    as :func:`gears.geometry.tip_diameter` takes it; a ring's tip relieved as
    :class:`trains.Planetary` relieves it is a k2 < 0), arrays broadcast.

    With ``errors="mask"`` a pair whose loss the friction equation does not give (a loss
    reaching the power, no continuous mesh) gets efficiency 0 and its whole power as loss
    instead of an error (a search ranks it last).

    Raises
    ------
    GearError
        Naming the value: a torque, speed, face width, roughness or viscosity not > 0, a pair
        whose contact ratio is below 1, or a loss reaching the power (efficiency <= 0).

    Examples
    --------
    >>> r = pair_losses([100.0, 200.0], 1500.0, 20, 50, 3.0, 30.0)
    >>> [round(float(e), 4) for e in r.efficiency]
    [0.9912, 0.9898]
    """
    for name, value in (("torque", torque), ("speed", speed), ("face_width", face_width),
                        ("roughness", roughness), ("viscosity", viscosity)):  # fmt: skip
        _positive(name, value)
    if errors not in ("raise", "mask"):
        raise GearError(f"errors = {errors!r}; valid are 'raise', 'mask'")
    shapes = dict(torque=torque, speed=speed, z1=z1, z2=z2, module=module, face_width=face_width,
                  x1=x1, x2=x2, pressure_angle=pressure_angle, helix_angle=helix_angle,
                  internal=internal, roughness=roughness, viscosity=viscosity)  # fmt: skip
    common_shape({k: np.shape(v) for k, v in shapes.items()})
    x_l = lubricant_factor(lubricant)
    g = pair_geometry(z1, z2, module, x1, x2, pressure_angle, helix_angle, internal, addendum,
                      tip_shortening)  # fmt: skip
    s = np.where(np.asarray(internal, bool), -1.0, 1.0)
    beta = np.radians(helix_angle)
    at = np.arctan(np.tan(np.radians(pressure_angle)) / np.cos(beta))
    mt = np.asarray(module, float) / np.cos(beta)
    rb1 = np.asarray(z1, float) * mt * np.cos(at) / 2.0
    rb2 = np.asarray(z2, float) * mt * np.cos(at) / 2.0
    tw = np.tan(np.radians(g.working_pressure_angle))
    da1, da2 = g.tip_diameter_1, g.tip_diameter_2
    k1, k2 = tip_alteration
    if np.any(np.asarray(k1) != 0.0) or np.any(np.asarray(k2) != 0.0):  # from the rack's tips
        k = np.asarray(g.tip_alteration, float)
        da1 = tip_diameter(z1, module, x1, helix_angle, addendum, False, k + k1)
        da2 = tip_diameter(z2, module, x2, helix_angle, addendum, internal,
                           np.where(internal, 0.0, k) + k2)  # fmt: skip
    u_a, u_e, _ = line_positions(da1 / 2, da2 / 2, rb1, rb2, tw, s)
    pb = np.pi * mt * np.cos(at)
    u_c = rb1 * tw
    beta_b = np.degrees(np.arcsin(np.sin(beta) * np.cos(np.radians(pressure_angle))))
    e1, e2 = (u_e - u_c) / pb, (u_c - u_a) / pb
    if errors == "mask":  # no continuous mesh: a stand-in path (eps = 1), masked below
        eps = e1 + e2
        no_mesh = ~(np.isfinite(eps) & (eps >= 1.0 - 1e-12) & (eps <= MAX_CONTACT_RATIO))
        e1, e2 = np.where(no_mesh, 0.5, e1), np.where(no_mesh, 0.5, e2)
    out = mesh_losses(torque, speed, z1, np.asarray(z2, float) / np.asarray(z1, float), rb1,
                      g.working_pressure_angle, e1, e2, face_width, beta_b, internal, roughness,
                      viscosity, x_l)  # fmt: skip
    if errors == "mask":
        bad = ~(np.isfinite(out.efficiency) & (out.efficiency > 0.0)) | no_mesh
        power = np.asarray(torque, float) * np.asarray(speed, float) * np.pi / 30.0
        return MeshLosses(*(np.where(bad, fill, v)[()] for v, fill in
                            zip(out, (np.nan, np.nan, 0.0, power), strict=True)))  # fmt: skip
    return _checked(out)


def _checked(out: MeshLosses) -> MeshLosses:
    """``out``, or a GearError where the loss reaches the power (the empirical friction at a
    crawl, or a long path of contact)."""
    if not np.all(np.isfinite(out.efficiency) & (out.efficiency > 0.0)):
        bad = np.ravel(out.efficiency)[~(np.isfinite(np.ravel(out.efficiency))
                                         & (np.ravel(out.efficiency) > 0.0))]  # fmt: skip
        raise GearError(
            f"mesh efficiency = {bad[:3].tolist()}: the friction loss mu_mz H_V reaches the "
            "power; ISO/TR 14179-2's friction equation does not apply here (raise the speed)"
        )
    return out


def pair_efficiency(pair: Any, torque: float, speed: float, face_width: float,
                    roughness: float | tuple[float, float], viscosity: float,
                    lubricant: str | float) -> MeshLosses:  # fmt: skip
    """:meth:`gears.GearPair.efficiency` of ``pair`` with its face width ``face_width`` mm
    resolved (its docstring says what it computes)."""
    t = check_positive("torque", torque, "N m")
    n = check_positive("speed", speed, "rpm")
    b = face_width  # resolved by the pair
    ra = roughness if isinstance(roughness, tuple) else (roughness, roughness)
    if len(ra) != 2:
        raise GearError(f"roughness = {roughness!r}; valid is Ra > 0 (um) or a pair")
    ra_m = 0.5 * sum(check_positive("roughness", r, "um") for r in ra)
    eta = check_positive("viscosity", viscosity, "mPa s")
    x_l = lubricant_factor(lubricant)
    p = pair.path_of_contact
    eps = p.length / p.base_pitch
    if eps < 1.0:
        raise GearError(
            f"contact ratio epsilon_alpha = {eps:.4f}; the mesh loss needs a continuous "
            "mesh (epsilon_alpha >= 1)"
        )
    g1 = pair.g1
    u = math.inf if pair.is_rack else pair.g2.teeth / g1.teeth
    beta_b = math.degrees(math.asin(math.sin(math.radians(g1.helix_angle))
                                    * math.cos(math.radians(g1.pressure_angle))))  # fmt: skip
    out = mesh_losses(t, n, g1.teeth, u, g1.base_diameter / 2, pair.working_pressure_angle,
                      (p.end - p.pitch_point) / p.base_pitch,
                      (p.pitch_point - p.start) / p.base_pitch, b, beta_b, pair.internal,
                      ra_m, eta, x_l)  # fmt: skip
    if not (math.isfinite(float(out.efficiency)) and float(out.efficiency) > 0.0):
        raise GearError(
            f"mesh efficiency = {float(out.efficiency):.4g} at speed = {n:g} rpm: the "
            "friction loss mu_mz H_V reaches the power; ISO/TR 14179-2's friction equation "
            "does not apply here (raise the speed)"
        )
    return MeshLosses(*(float(v) for v in out))
