"""Layer 5, load capacity: scuffing by the flash temperature method (ISO/TS 6336-20) and the
integral temperature method (ISO/TS 6336-21), over arrays.

Both methods go back to Blok's contact temperature: where the flanks slide under load, the
friction heat raises the flank above the gear's bulk temperature by the *flash temperature*;
the teeth scuff when the contact temperature reaches the oil's scuffing temperature, which the
FZG test A/8.3/90 (ISO 14635-1) measures as a *load stage*. ISO/TS 6336-20:2017 (from
DIN 3990-4 and ISO/TR 13989-1) rates the largest contact temperature along the path of contact;
ISO/TS 6336-21:2017 (from ISO/TR 13989-2) rates the mean ("integral") temperature. The formulas
as math: docs/rating.md, "Scuffing".

Along the path of contact, a point is named by Gamma, its distance from the pitch point C over
rho_1C = r_b1 tan alpha_wt (rho_1 = rho_1C (1 + Gamma)): Gamma_A at the start of contact (gear
2's tip), Gamma_E at its end (gear 1's tip). There the local flash temperature is

    theta_fl = mu X_M X_J X_G (X_Gamma w_Bt)^0.75 v^0.5 / a^0.25

(:func:`flash_temperature`) with the thermo-elastic factor X_M (:func:`thermoelastic_factor`:
50 K N^-3/4 s^1/2 m^-1/2 mm for steel), the geometry factor X_G = X_alphabeta X_BE(Gamma)
(:func:`angle_factor`, :func:`geometry_factor`), the load sharing factor X_Gamma
(:func:`load_sharing`), the transverse unit load w_Bt = K_A K_gamma K_v K_Hbeta K_Halpha F_t / b,
the pitch-line speed v and the centre distance a.

The documents' text was not at hand when this module was written, nor a published worked
example. Its formulas are checked against an open implementation of ISO/TR 13989-1/-2:2000 that
quotes them with equation and table numbers (hakangunes258/mekanika on GitHub): X_alphabeta
reproduces ISO/TR 13989-2 Table 2, and the approach factor X_J with C_eff (ISO/TR 13989-1
Eq. (45)-(48), (B.1)), the integral method's friction, bulk temperature (with X_S) and scuffing
integral temperature (T_1T = 3.726 S_FZG^2) follow the quotes; and by physics (Blok's flash
temperature) and the FZG test (tests/gears/test_rating_scuffing.py). Where the quotes differ
from this module, the quotes themselves are unsure and docs/rating.md says so: the flash
method's friction here is the 0.12 (w_Bt Ra / (eta v rho))^0.25 form (the quoted ISO/TR 13989-1
Eq. (25) is 0.060 (w_Bt / (v rho))^0.2 eta^-0.05 X_R X_L with an uncertain X_R) and the spur
X_Gamma rises from 1/3 to 2/3 in double contact (the quoted one from (Q - 2)/15 to 1).

Choices made here where the documents leave one or where their text was not at hand (each says
so where it is used): X_Gamma is that of unmodified flanks (a tip relief C_a enters X_J only);
the oil's viscosity is taken at the oil temperature (no iteration on the bulk temperature); the
integral method's mean flash temperature is the mean of the local flash temperature (without
the flash method's X_J) along the path of contact, integrated numerically (Gauss-Legendre on the
segments between A, B, C, D and E), where ISO/TS 6336-21 approximates that mean by closed forms
(the contact ratio factor X_eps, the approach factor X_Q and the tip relief factor X_Ca); for
two materials the thermal contact coefficient B_M is their mean.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from gears.arguments import common_shape
from gears.errors import GearError
from gears.geometry import tip_diameter
from gears.rating._arrays import number as _number
from gears.rating._arrays import pair_of as _pair_of
from gears.rating.iso6336 import rate_pairs
from gears.rating.losses import lubricant_factor
from gears.rating.materials import material as _material

__all__ = [
    "FZG_TORQUES",
    "LUBRICATION",
    "STEEL_THERMAL_CONTACT",
    "Oil",
    "ScuffingRatings",
    "angle_factor",
    "approach_factor",
    "flash_friction",
    "flash_temperature",
    "fzg_torque",
    "geometry_factor",
    "helical_load_factor",
    "integral_friction",
    "integral_scuffing_temperature",
    "load_sharing",
    "oil_dynamic_viscosity",
    "optimal_tip_relief",
    "rate_scuffing",
    "scuffing_block",
    "scuffing_temperature",
    "thermoelastic_factor",
]

#: Pinion torque T_1T (N m) of the FZG test A/8.3/90 at each load stage 1 ... 12
#: (ISO 14635-1, the load stages of the test gear type A).
FZG_TORQUES = (3.3, 13.7, 35.3, 60.8, 94.1, 135.5, 183.4, 239.3, 302.0, 372.6, 450.1, 534.5)

#: The lubrication factor X_S of the bulk temperature by the way the oil reaches the mesh.
LUBRICATION = {"dip": 1.0, "spray": 1.2}

#: Thermal contact coefficient B_M = sqrt(lambda_M rho_M c_M) of steel, N/(mm s^0.5 K).
STEEL_THERMAL_CONTACT = 13.795

#: Weights of the integral method (ISO/TS 6336-21): the bulk temperature's C_1 and the flash
#: temperature's C_2 in the integral temperature.
C_1, C_2 = 0.7, 1.5

_GAUSS = np.polynomial.legendre.leggauss(8)  # nodes and weights per segment of the path


@dataclass(frozen=True)
class Oil:
    """A gear oil for the scuffing rating.

    Parameters
    ----------
    fzg_stage : int
        Failure load stage of the FZG test A/8.3/90 (ISO 14635-1), 1 ... 12 (an oil rated
        "> 12" is 12 here).
    temperature : float
        Oil temperature theta_oil before the mesh (sump or spray), deg C.
    viscosity_40, viscosity_100 : float
        Kinematic viscosity at 40 and 100 deg C, mm^2/s (viscosity_40 > viscosity_100).
    density : float
        Density at 15 deg C, kg/m^3.
    base : str or float
        Base oil for the lubricant factor X_L (:data:`gears.rating.losses.LUBRICANT_FACTORS`)
        or X_L itself.
    lubrication : str
        ``"dip"`` or ``"spray"`` (:data:`LUBRICATION`: X_S of the bulk temperature).

    Examples
    --------
    >>> oil = Oil(fzg_stage=12, temperature=90, viscosity_40=220, viscosity_100=19)
    >>> round(float(oil_dynamic_viscosity(220, 19, 90, 890)), 2)   # mPa s at 90 deg C
    21.55
    """

    fzg_stage: int
    temperature: float
    viscosity_40: float
    viscosity_100: float
    density: float = 890.0
    base: str | float = "mineral"
    lubrication: str = "dip"

    def __post_init__(self):
        stage = self.fzg_stage
        if (
            isinstance(stage, bool)
            or not isinstance(stage, int | np.integer)
            or not (1 <= stage <= len(FZG_TORQUES))
        ):
            raise GearError(
                f"fzg_stage = {stage!r}; valid is an FZG load stage 1 ... {len(FZG_TORQUES)} "
                "(ISO 14635-1 A/8.3/90)"
            )
        limits = (("temperature", -40.0, 200.0), ("viscosity_40", 1.0, 1e5),
                  ("viscosity_100", 0.5, 1e4), ("density", 500.0, 2000.0))  # fmt: skip
        for name, low, high in limits:
            value = getattr(self, name)
            _number(f"oil {name}", value, low, high, low_open=False)
            if not isinstance(value, int | float | np.integer | np.floating) or isinstance(
                value, bool
            ):
                raise GearError(f"oil {name} = {value!r}; valid is one number")
        if not self.viscosity_40 > self.viscosity_100:
            raise GearError(
                f"oil viscosity_40 = {self.viscosity_40:g} <= viscosity_100 = "
                f"{self.viscosity_100:g} mm^2/s; an oil thins as it warms"
            )
        lubricant_factor(self.base)
        if self.lubrication not in LUBRICATION:
            raise GearError(
                f"oil lubrication = {self.lubrication!r}; valid are {', '.join(LUBRICATION)}"
            )

    @property
    def lubricant_factor(self) -> float:
        """X_L of the base oil."""
        return lubricant_factor(self.base)

    @property
    def dynamic_viscosity(self) -> float:
        """Dynamic viscosity at the oil temperature, mPa s."""
        return float(oil_dynamic_viscosity(self.viscosity_40, self.viscosity_100,
                                           self.temperature, self.density))  # fmt: skip


# --- the factors --------------------------------------------------------------------------------
def fzg_torque(stage: ArrayLike) -> np.ndarray:
    """Pinion torque T_1T (N m) of an FZG A/8.3/90 load stage (:data:`FZG_TORQUES`).

    >>> float(fzg_torque(12))
    534.5
    """
    s = _number("fzg_stage", stage, 1.0, len(FZG_TORQUES), False, False, integer=True)
    return np.asarray(FZG_TORQUES)[np.asarray(s, int) - 1]


def oil_dynamic_viscosity(nu40, nu100, temperature, density=890.0):
    """Dynamic viscosity (mPa s) at ``temperature`` (deg C) of an oil of kinematic viscosities
    ``nu40``, ``nu100`` (mm^2/s) and density ``density`` (kg/m^3 at 15 deg C): Ubbelohde-Walther
    (ASTM D341) log log(nu + 0.7) linear in log T through the two points, the density falling by
    0.07 % per kelvin from 15 deg C (arrays broadcast)."""
    t40, t100 = math.log10(313.15), math.log10(373.15)
    w40 = np.log10(np.log10(np.asarray(nu40, float) + 0.7))
    w100 = np.log10(np.log10(np.asarray(nu100, float) + 0.7))
    t = np.log10(np.asarray(temperature, float) + 273.15)
    w = w40 + (w100 - w40) * (t - t40) / (t100 - t40)
    nu = 10.0 ** (10.0**w) - 0.7
    rho = np.asarray(density, float) * 1e-3 * (1.0 - 0.0007 * (np.asarray(temperature) - 15.0))
    return nu * rho


_B_STEEL = STEEL_THERMAL_CONTACT  # short for the signatures


def thermoelastic_factor(youngs_1, poisson_1, youngs_2, poisson_2, thermal_1=_B_STEEL,
                         thermal_2=_B_STEEL):  # fmt: skip
    """Thermo-elastic factor X_M = E_r^0.25 / B_M in K N^-3/4 s^1/2 m^-1/2 mm, with
    E_r = 2 / ((1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2) (MPa) and B_M the mean thermal contact
    coefficient (N/(mm s^0.5 K); the factor sqrt(1000) turns the speed's m/s into mm/s).

    >>> round(float(thermoelastic_factor(206000, 0.3, 206000, 0.3)), 2)   # steel: 50
    50.0
    """
    e_r = 2.0 / ((1.0 - np.square(poisson_1)) / youngs_1 + (1.0 - np.square(poisson_2)) / youngs_2)
    b_m = 0.5 * (np.asarray(thermal_1, float) + np.asarray(thermal_2, float))
    return e_r**0.25 / b_m * math.sqrt(1000.0)


def angle_factor(alpha_wt, alpha_n, alpha_t, beta):
    """Pressure angle factor X_alphabeta = 1.22 sin^0.25 alpha_wt cos^0.25 alpha_n cos^0.25 beta
    / (cos^0.5 alpha_wt cos^0.5 alpha_t) (degrees in; arrays broadcast).

    >>> round(float(angle_factor(20, 20, 20, 0)), 4)
    0.9775
    """
    awt, an, at, b = (np.radians(np.asarray(x, float)) for x in (alpha_wt, alpha_n, alpha_t, beta))
    num = np.sin(awt) ** 0.25 * np.cos(an) ** 0.25 * np.cos(b) ** 0.25
    return 1.22 * num / (np.cos(awt) ** 0.5 * np.cos(at) ** 0.5)


def geometry_factor(gamma, u):
    """Geometry factor ``X_BE(Gamma) = 0.51 |u + 1|^0.5 |sqrt(1 + Gamma) - sqrt(1 - Gamma/u)|
    / ((1 + Gamma)^0.25 |u - Gamma|^0.25)`` at the point Gamma of the path of contact (u = z2/z1,
    negative for an internal pair); X_G = X_alphabeta X_BE. Zero at the pitch point.

    >>> float(geometry_factor(0.0, 2.0))
    0.0
    """
    g = np.asarray(gamma, float)
    u = np.asarray(u, float)
    slide = np.abs(np.sqrt(1.0 + g) - np.sqrt(1.0 - g / u))
    return 0.51 * np.sqrt(np.abs(u + 1.0)) * slide / ((1.0 + g) ** 0.25 * np.abs(u - g) ** 0.25)


def load_sharing(gamma, gamma_a, gamma_b, gamma_d, gamma_e, eps_alpha, eps_beta):
    """Load sharing factor X_Gamma at Gamma: the share of w_Bt the flank at Gamma carries.

    Spur gears (unmodified flanks, eps_alpha < 2): 1/3 at A rising linearly to 2/3 at B, 1 in
    single contact B ... D, 2/3 at D falling to 1/3 at E (the two pairs in double contact carry
    1/3 + 2/3); helical gears with eps_beta >= 1: 1/eps_alpha along the whole path; between
    them (eps_beta < 1) the two weighted by (1 - eps_beta) and eps_beta; spur gears with
    eps_alpha >= 2: 1/eps_alpha (the mean share). Arrays broadcast.

    >>> float(load_sharing(-0.3, -0.3, -0.1, 0.1, 0.3, 1.5, 0.0))   # at A
    0.3333333333333333
    """
    g = np.asarray(gamma, float)
    with np.errstate(invalid="ignore", divide="ignore"):
        rise = 1.0 / 3.0 + (g - gamma_a) / (gamma_b - gamma_a) / 3.0
        fall = 1.0 / 3.0 + (gamma_e - g) / (gamma_e - gamma_d) / 3.0
    spur = np.where(g < gamma_b, rise, np.where(g > gamma_d, fall, 1.0))
    ea = np.asarray(eps_alpha, float)
    mean = 1.0 / ea
    spur = np.where(ea < 2.0, np.clip(spur, 1.0 / 3.0, 1.0), mean)
    eb = np.minimum(np.asarray(eps_beta, float), 1.0)
    return (1.0 - eb) * spur + eb * mean


def flash_friction(w_bt, roughness, viscosity, sum_velocity, curvature_radius,
                   lubricant_factor=1.0):  # fmt: skip
    """Mean coefficient of friction of the flash temperature method (ISO/TS 6336-20):
    mu_m = 0.12 (w_Bt Ra / (eta v_SigmaC rho_redC))^0.25 X_L, with w_Bt N/mm, Ra um (mean of
    both flanks), eta mPa s, v_SigmaC = 2 v sin alpha_wt m/s, rho_redC mm (normal section).

    >>> round(float(flash_friction(500.0, 0.5, 20.0, 5.0, 10.0)), 4)
    0.0849
    """
    x = w_bt * np.asarray(roughness, float) / (viscosity * sum_velocity * curvature_radius)
    return 0.12 * x**0.25 * lubricant_factor


def integral_friction(w_bt, helical_factor, roughness, viscosity, sum_velocity,
                      curvature_radius, lubricant_factor=1.0):  # fmt: skip
    """Mean coefficient of friction of the integral temperature method (ISO/TS 6336-21):
    mu_mC = 0.045 (w_Bt K_Bgamma / (v_SigmaC rho_redC))^0.2 eta^-0.05 X_R X_L with the
    roughness factor X_R = 2.2 (Ra / rho_redC)^0.25 (units as :func:`flash_friction`).

    >>> round(float(integral_friction(500.0, 1.0, 0.5, 20.0, 5.0, 10.0)), 4)
    0.0639
    """
    x_r = 2.2 * (np.asarray(roughness, float) / curvature_radius) ** 0.25
    load = w_bt * helical_factor / (sum_velocity * curvature_radius)
    return 0.045 * load**0.2 * np.asarray(viscosity, float) ** -0.05 * x_r * lubricant_factor


def helical_load_factor(eps_gamma):
    """Helical load factor K_Bgamma of the integral method: 1 for eps_gamma <= 2,
    1 + 0.2 sqrt((eps_gamma - 2)(5 - eps_gamma)) up to 3.5, 1.3 above.

    >>> [round(float(helical_load_factor(e)), 4) for e in (1.5, 3.0, 4.0)]
    [1.0, 1.2828, 1.3]
    """
    e = np.asarray(eps_gamma, float)
    mid = 1.0 + 0.2 * np.sqrt(np.clip((e - 2.0) * (5.0 - e), 0.0, None))
    return np.where(e <= 2.0, 1.0, np.where(e < 3.5, mid, 1.3))


def optimal_tip_relief(application, F_t, face_width, alpha_t, c_gamma):
    """Effective tip relief C_eff = K_A F_t / (b cos alpha_t c_gamma) (um; F_t N, b mm, alpha_t
    deg, the mesh stiffness c_gamma N/(mm um)): the relief that just takes the tooth's
    deflection under the load (ISO/TR 13989-1:2000 Eq. (B.1)). Arrays broadcast.

    >>> round(float(optimal_tip_relief(1.0, 4000.0, 20.0, 20.0, 20.0)), 3)
    10.642
    """
    at = np.radians(np.asarray(alpha_t, float))
    load = np.asarray(application, float) * np.asarray(F_t, float)
    return load / (np.asarray(face_width, float) * np.cos(at) * np.asarray(c_gamma, float))


def approach_factor(gamma, gamma_a, gamma_e, c_eff, relief=0.0, driver=1):
    """Approach factor X_J at Gamma (ISO/TR 13989-1:2000 Eq. (45)-(48)): the approach zone of
    the driven gear's tip, where the unrelieved tip meets the driving flank with a shock, runs
    hotter. Gear 1 driving (``driver`` 1): X_J = 1 + max(C_eff - C_a2, 0)/50
    (-Gamma/(Gamma_E - Gamma_A))^3 for Gamma < 0, else 1; gear 2 driving (``driver`` 2):
    1 + max(C_eff - C_a1, 0)/50 (Gamma/(Gamma_E - Gamma_A))^3 for Gamma > 0, else 1;
    ``relief`` the driven gear's tip relief C_a (um), ``c_eff`` from
    :func:`optimal_tip_relief`. Arrays broadcast.

    >>> round(float(approach_factor(-0.5, -0.5, 0.5, 20.0)), 4)   # at A, no relief
    1.05
    """
    g = np.asarray(gamma, float)
    side = np.where(np.asarray(driver) == 2, 1.0, -1.0)
    reach = np.clip(side * g / (np.asarray(gamma_e, float) - gamma_a), 0.0, None)
    excess = np.maximum(np.asarray(c_eff, float) - np.asarray(relief, float), 0.0)
    return 1.0 + excess / 50.0 * reach**3


def flash_temperature(friction, thermoelastic, angle, gamma, u, sharing, w_bt, speed, center,
                      approach=1.0):  # fmt: skip
    """The local flash temperature theta_fl = mu X_M X_J X_G (X_Gamma w_Bt)^0.75 v^0.5 /
    a^0.25 (K; X_J ``approach`` (:func:`approach_factor`), X_G = X_alphabeta X_BE(Gamma));
    ``speed`` the pitch-line speed in m/s, ``center`` the centre distance in mm (arrays
    broadcast).

    >>> round(float(flash_temperature(0.08, 50.0, 0.9775, 0.5, 2.0, 1/3, 500.0, 10.0, 150.0)), 1)
    42.4
    """
    x_g = angle * geometry_factor(gamma, u)
    load = (np.asarray(sharing, float) * w_bt) ** 0.75
    heat = friction * thermoelastic * np.asarray(approach, float) * x_g * load
    return heat * np.sqrt(speed) / np.abs(center) ** 0.25


def scuffing_temperature(stage, welding=1.0, lubricant=1.0):
    """Scuffing temperature of the flash temperature method from the oil's FZG load stage:
    theta_S = 80 + (0.85 + 1.4 X_W) X_L S_FZG^2 (deg C; X_W the welding factor).

    >>> float(scuffing_temperature(12))
    404.0
    """
    s = np.asarray(stage, float)
    return 80.0 + (0.85 + 1.4 * np.asarray(welding, float)) * lubricant * s**2


def integral_scuffing_temperature(stage, viscosity_40, welding=1.0, lubricant=1.0):
    """Scuffing integral temperature of the integral method from the FZG test:
    theta_intS = theta_MT + C_2 X_WrelT theta_flaintT with the test's bulk temperature
    theta_MT = 80 + 0.23 T_1T X_L and mean flash temperature theta_flaintT = 0.2 T_1T
    (100/nu_40)^0.02 X_L, where T_1T = 3.726 S_FZG^2 N m is the method's fit of the test's
    pinion torque (ISO/TR 13989-2:2000 Eq. (94)-(97); within 0.5 % of :data:`FZG_TORQUES`
    from stage 7 up, equal at stage 10); deg C.

    >>> round(float(integral_scuffing_temperature(12, 100.0)), 2)
    364.37
    """
    s = _number("fzg_stage", stage, 1.0, len(FZG_TORQUES), False, False, integer=True)
    t = 3.726 * np.square(np.asarray(s, float))
    theta_mt = 80.0 + 0.23 * t * lubricant
    theta_flat = 0.2 * t * (100.0 / np.asarray(viscosity_40, float)) ** 0.02 * lubricant
    return theta_mt + C_2 * np.asarray(welding, float) * theta_flat


# --- the rating ---------------------------------------------------------------------------------
class ScuffingRatings(NamedTuple):
    """Arrays of :func:`rate_scuffing` (temperatures in deg C, flash temperatures in K).

    ``S_B`` the safety of the flash temperature method, (theta_S - theta_oil) /
    (theta_B - theta_oil); ``theta_B`` the largest contact temperature theta_M + theta_fl along
    the path; ``theta_flmax`` the largest flash temperature, at ``gamma_flmax`` (Gamma) on the
    diameter ``d_flmax`` of gear 1; ``theta_flm`` the mean flash temperature; ``theta_M`` the
    bulk temperature; ``theta_S`` the scuffing temperature; ``mu_m`` the mean coefficient of
    friction. ``S_intS`` the safety of the integral method, theta_intS / theta_int, with the
    mean flash temperature ``theta_flaint``, the bulk temperature ``theta_M_int``, the integral
    temperature ``theta_int`` and its scuffing value ``theta_intS``, and the friction
    ``mu_mC``. Then X_M, X_alphabeta, K_Bgamma, the unit load ``w_Bt`` (N/mm), the oil's
    dynamic viscosity ``eta_oil`` (mPa s) and the ends of the path ``gamma_A``, ``gamma_E``.
    ``valid`` and ``reason`` as in :class:`gears.rating.iso6336.PairRatings`.
    """

    S_B: Any
    S_intS: Any
    theta_B: Any
    theta_flmax: Any
    gamma_flmax: Any
    d_flmax: Any
    theta_flm: Any
    theta_M: Any
    theta_S: Any
    mu_m: Any
    theta_flaint: Any
    theta_M_int: Any
    theta_int: Any
    theta_intS: Any
    mu_mC: Any
    X_M: Any
    X_alphabeta: Any
    K_Bgamma: Any
    w_Bt: Any
    eta_oil: Any
    gamma_A: Any
    gamma_E: Any
    valid: Any
    reason: Any


def _path(gamma_a, gamma_b, gamma_d, gamma_e):
    """Points along the path (Gauss-Legendre nodes on the segments between A, B, C, D, E, then
    those five points) and the nodes' weights for the mean over A ... E: (points, weights)."""
    ends = [gamma_a, np.clip(gamma_b, gamma_a, gamma_e), np.clip(0.0, gamma_a, gamma_e),
            np.clip(gamma_d, gamma_a, gamma_e), gamma_e]  # fmt: skip
    ends = np.sort(np.stack(np.broadcast_arrays(*ends), axis=-1), axis=-1)
    lo, hi = ends[..., :-1, None], ends[..., 1:, None]
    xi, wi = _GAUSS
    half = 0.5 * (hi - lo)
    nodes = (0.5 * (hi + lo) + half * xi).reshape(*ends.shape[:-1], -1)
    weights = (half * wi).reshape(*ends.shape[:-1], -1)
    length = (gamma_e - gamma_a)[..., None]
    return np.concatenate([nodes, ends], axis=-1), weights / length


def scuffing_block(z1, z2, module, pressure_angle, helix_angle, internal, alpha_wt, center,
                   da1, da2, face_width, F_t, speed, load_factor, roughness, oil: Oil,
                   thermoelastic, welding=1.0, meshes=1, application=1.0, c_gamma=np.inf,
                   relief_1=0.0, relief_2=0.0, driver=1) -> dict:  # fmt: skip
    """Both scuffing methods over arrays of pairs (no checks; :func:`rate_scuffing` checks):
    the pairs' teeth, module (mm), pressure and helix angles (deg), ``internal``, the working
    pressure angle (deg), centre distance and tip diameters (mm), face width (mm), the nominal
    load F_t (N) and pitch-line speed (m/s), ``load_factor`` K_A K_gamma K_v K_Hbeta K_Halpha,
    the mean flank roughness Ra (um), the ``oil``, X_M, the welding factor X_W and the number of
    meshes of the gear (X_mp = (1 + meshes)/2); for the approach factor X_J the application
    factor K_A, the mesh stiffness c_gamma (N/(mm um); infinite: X_J = 1), the tip reliefs
    C_a1, C_a2 (um) and the driving gear (1 or 2). Returns a dict of the fields of
    :class:`ScuffingRatings` but ``valid`` and ``reason``."""
    z1 = np.asarray(z1, float)
    s = np.where(np.asarray(internal, bool), -1.0, 1.0)
    u = s * np.asarray(z2, float) / z1
    m = np.asarray(module, float)
    beta = np.radians(np.abs(np.asarray(helix_angle, float)))
    an = np.radians(np.asarray(pressure_angle, float))
    at = np.arctan(np.tan(an) / np.cos(beta))
    db1 = z1 * m / np.cos(beta) * np.cos(at)
    db2 = np.abs(u) * db1
    awt = np.radians(np.asarray(alpha_wt, float))
    tw = np.tan(awt)
    a = np.abs(np.asarray(center, float))
    rho1c = db1 / 2.0 * tw
    gamma_e = np.sqrt(np.maximum((np.asarray(da1) / db1) ** 2 - 1.0, 0.0)) / tw - 1.0
    rho_a2 = db2 / 2.0 * np.sqrt(np.maximum((np.asarray(da2) / db2) ** 2 - 1.0, 0.0))
    gamma_a = s * (a * np.sin(awt) - rho_a2) / rho1c - 1.0
    pitch = 2.0 * np.pi / (z1 * tw)  # one base pitch in Gamma
    eps_alpha = (gamma_e - gamma_a) / pitch
    eps_beta = np.asarray(face_width, float) * np.sin(beta) / (np.pi * m)
    beta_b = np.arctan(np.tan(beta) * np.cos(at))
    w_bt = np.asarray(load_factor, float) * np.asarray(F_t, float) / face_width
    v = np.asarray(speed, float)
    v_sum = 2.0 * v * np.sin(awt)
    rho_red = np.abs(u) / (1.0 + u) ** 2 * a * np.sin(awt) / np.cos(beta_b)
    eta = oil.dynamic_viscosity
    x_l = oil.lubricant_factor
    mu_m = flash_friction(w_bt, roughness, eta, v_sum, rho_red, x_l)
    k_bg = helical_load_factor(eps_alpha + eps_beta)
    # the integral method's sum of the rolling speeds at C with v on the reference circle,
    # 2 v tan(alpha_wt) cos(alpha_t) (ISO/TR 13989-2 Eq. (2)): 2 omega_1 rho_1C exactly
    v_sum_c = 2.0 * v * tw * np.cos(at)
    mu_c = integral_friction(w_bt, k_bg, roughness, eta, v_sum_c, rho_red, x_l)
    x_ab = angle_factor(np.degrees(awt), np.degrees(an), np.degrees(at), np.degrees(beta))
    # the flash temperature per unit friction at every point of the path
    pts, weights = _path(gamma_a, gamma_e - pitch, gamma_a + pitch, gamma_e)
    ex = (..., None)
    share = load_sharing(pts, gamma_a[ex], (gamma_e - pitch)[ex], (gamma_a + pitch)[ex],
                         gamma_e[ex], eps_alpha[ex], eps_beta[ex])  # fmt: skip
    unit = flash_temperature(1.0, np.asarray(thermoelastic)[ex], x_ab[ex], pts, u[ex], share,
                             w_bt[ex], v[ex], a[ex])  # fmt: skip
    c_eff = optimal_tip_relief(application, F_t, face_width, np.degrees(at), c_gamma)
    driver = np.asarray(driver)
    relief = np.where(driver == 2, relief_1, relief_2)
    x_j = approach_factor(pts, gamma_a[ex], gamma_e[ex], np.asarray(c_eff)[ex],
                          np.asarray(relief)[ex], driver[ex])  # fmt: skip
    n_nodes = weights.shape[-1]
    mean = np.sum(unit[..., :n_nodes] * weights, axis=-1)  # the integral method: no X_J
    unit = unit * x_j
    mean_j = np.sum(unit[..., :n_nodes] * weights, axis=-1)
    i = np.argmax(unit, axis=-1)
    peak = np.take_along_axis(unit, i[..., None], axis=-1)[..., 0]
    # the path's points have the geometry's shape, the temperatures the load's too
    g_peak = np.take_along_axis(np.broadcast_to(pts, unit.shape), i[..., None], axis=-1)[..., 0]
    x_mp = 0.5 * (1.0 + np.asarray(meshes, float))
    theta_oil = float(oil.temperature)
    theta_flmax, theta_flm = mu_m * peak, mu_m * mean_j
    theta_m = theta_oil + 0.47 * LUBRICATION[oil.lubrication] * x_mp * theta_flm
    theta_b = theta_m + theta_flmax
    theta_s = scuffing_temperature(oil.fzg_stage, welding, x_l)
    theta_flaint = mu_c * k_bg**0.75 * mean
    theta_m_int = theta_oil + C_1 * LUBRICATION[oil.lubrication] * x_mp * theta_flaint
    theta_int = theta_m_int + C_2 * theta_flaint
    theta_ints = integral_scuffing_temperature(oil.fzg_stage, oil.viscosity_40, welding, x_l)
    return {
        "S_B": (theta_s - theta_oil) / (theta_b - theta_oil), "S_intS": theta_ints / theta_int,
        "theta_B": theta_b, "theta_flmax": theta_flmax, "gamma_flmax": g_peak,
        "d_flmax": db1 * np.sqrt(1.0 + (tw * (1.0 + g_peak)) ** 2), "theta_flm": theta_flm,
        "theta_M": theta_m, "theta_S": theta_s, "mu_m": mu_m, "theta_flaint": theta_flaint,
        "theta_M_int": theta_m_int, "theta_int": theta_int, "theta_intS": theta_ints,
        "mu_mC": mu_c, "X_M": thermoelastic, "X_alphabeta": x_ab, "K_Bgamma": k_bg,
        "w_Bt": w_bt, "eta_oil": eta, "gamma_A": gamma_a, "gamma_E": gamma_e,
    }  # fmt: skip


_LOADS = ("K_A", "K_gamma", "K_v", "K_Hbeta", "K_Halpha", "F_t", "v", "c_gamma_alpha")
_NOT_FINITE = 9  # gears.rating.iso6336.REASONS: "a stress or safety is not a finite number"


def _results(out: dict, valid, reason, shape) -> ScuffingRatings:
    """The block's dict as :class:`ScuffingRatings`, masked where no rating exists (zero
    safeties, NaN elsewhere) and where a temperature is not finite."""
    finite = np.ones(shape, bool)
    for key in ("S_B", "S_intS", "theta_B", "theta_int"):
        finite &= np.broadcast_to(np.isfinite(out[key]), shape)
    valid = np.broadcast_to(valid, shape) & finite
    reason = np.where(np.broadcast_to(reason, shape) == 0, np.where(finite, 0, _NOT_FINITE),
                      np.broadcast_to(reason, shape))  # fmt: skip
    fields = {}
    for key, value in out.items():
        value = np.broadcast_to(np.asarray(value, float), shape)
        value = np.where(valid, value, 0.0 if key.startswith("S_") else np.nan)
        fields[key] = value[()] if value.ndim == 0 else value
    return ScuffingRatings(**fields, valid=valid[()] if valid.ndim == 0 else valid,
                           reason=reason[()] if reason.ndim == 0 else reason)  # fmt: skip


def _relief_um(tip_relief):
    """The tip relief C_a of both gears, um, from the rating's ``tip_relief`` (mm; None: 0)."""
    if tip_relief is None:
        return 0.0
    return 1000.0 * _number("tip_relief", tip_relief, 0.0, 10.0, low_open=False)


def _checked(oil, welding, meshes, thermal_contact, driver=1):
    if not isinstance(oil, Oil):
        raise GearError(f"oil = {oil!r}; give a gears.rating.scuffing.Oil(fzg_stage=..., ...)")
    if isinstance(driver, bool) or not isinstance(driver, int | np.integer) or driver not in (1, 2):
        raise GearError(f"driver = {driver!r}; valid are 1 (gear 1 drives) and 2")
    x_w = _number("welding", welding, 0.0, 10.0)
    n_p = _number("meshes", meshes, 1.0, 100.0, low_open=False, integer=True)
    b1, b2 = _pair_of("thermal_contact", thermal_contact)
    b1 = _number("thermal_contact", b1, 0.0, 1e3)
    b2 = _number("thermal_contact", b2, 0.0, 1e3)
    return x_w, n_p, b1, b2


def rate_scuffing(
    z1: ArrayLike, z2: ArrayLike, module: ArrayLike, face_width: ArrayLike, torque: ArrayLike,
    speed: ArrayLike, *, oil: Oil, welding: ArrayLike = 1.0, meshes: ArrayLike = 1,
    thermal_contact: Any = STEEL_THERMAL_CONTACT, driver: int = 1, errors: str = "raise",
    **rating: Any,
) -> ScuffingRatings:  # fmt: skip
    """Scuffing safety of many pairs at once by the flash temperature method (ISO/TS 6336-20)
    and the integral temperature method (ISO/TS 6336-21); arrays broadcast.

    Parameters
    ----------
    z1, z2, module, face_width, torque, speed
        As for :func:`gears.rating.iso6336.rate_pairs` (torque on gear 1 in N m, speed of gear
        1 relative to the carrier in rpm).
    oil : Oil
        The oil: FZG load stage, temperature, viscosities, base, lubrication.
    welding : array_like
        Welding (structural) factor X_W of the flank material, 1 for the test gears' case-
        carburized steel (the standard's table gives the others).
    meshes : array_like
        Meshes of the hotter gear (a planet meshing sun and ring: 2): X_mp = (1 + meshes)/2.
    thermal_contact : float or pair
        Thermal contact coefficient B_M of the flanks, N/(mm s^0.5 K) (steel: 13.795).
    driver : {1, 2}
        The driving gear: the driven gear's tip starts contact and heats the approach zone.
    errors : {"raise", "mask"}
        As for :func:`gears.rating.iso6336.rate_pairs`.
    **rating
        Every other argument of :func:`gears.rating.iso6336.rate_pairs` (shifts, angles,
        ``internal``, ``material``, ``application_factor``, ``quality``, ``roughness`` (the
        flanks' Ra, um), ``factors``, ...): the load factors K_A, K_gamma, K_v, K_Hbeta and
        K_Halpha come from that rating; ``oil_viscosity`` defaults to the oil's nu_40;
        ``tip_relief`` (C_a in mm, of both gears; none given: unmodified flanks here) enters the
        approach factor X_J (:func:`approach_factor`) too, not X_Gamma.

    Returns
    -------
    ScuffingRatings

    Examples
    --------
    >>> oil = Oil(fzg_stage=9, temperature=80, viscosity_40=100, viscosity_100=11)
    >>> r = rate_scuffing(17, [40, 60], 4, 40, 600, 3000, oil=oil, roughness=0.6)
    >>> [round(float(s), 2) for s in r.S_B], [round(float(s), 2) for s in r.S_intS]
    ([0.68, 0.65], [1.13, 1.2])
    """
    x_w, n_p, b1, b2 = _checked(oil, welding, meshes, thermal_contact, driver)
    shapes = dict(z1=z1, z2=z2, module=module, face_width=face_width, torque=torque, speed=speed)
    common_shape({k: np.shape(v) for k, v in (shapes | {"welding": x_w, "meshes": n_p}).items()})
    for key in ("fields", "geometry"):
        if key in rating:
            raise GearError(f"{key}= is not an argument of rate_scuffing")
    rating.setdefault("oil_viscosity", oil.viscosity_40)
    values = rate_pairs(z1, z2, module, face_width, torque, speed, errors=errors,
                        fields=_LOADS, **rating)  # fmt: skip
    g = {k: rating.get(k, d) for k, d in (("x1", 0.0), ("x2", 0.0), ("pressure_angle", 20.0),
         ("helix_angle", 0.0), ("internal", False), ("addendum", 1.0),
         ("tip_shortening", True), ("tip_alteration", (0.0, 0.0)), ("roughness", 1.0),
         ("material", "case-carburized"))}  # fmt: skip
    from gears.meshing import pair_geometry

    geo = pair_geometry(z1, z2, module, g["x1"], g["x2"], g["pressure_angle"], g["helix_angle"],
                        g["internal"], g["addendum"], g["tip_shortening"])  # fmt: skip
    k1, k2 = _pair_of("tip_alteration", g["tip_alteration"])
    internal = np.asarray(g["internal"], bool)
    k = np.asarray(geo.tip_alteration, float)
    da1 = tip_diameter(z1, module, g["x1"], g["helix_angle"], g["addendum"], False, k + k1)
    da2 = tip_diameter(z2, module, g["x2"], g["helix_angle"], g["addendum"], internal,
                       np.where(internal, 0.0, k) + k2)  # fmt: skip
    m1, m2 = (_material(x) for x in _pair_of("material", g["material"]))
    x_m = thermoelastic_factor(m1.youngs_modulus, m1.poisson, m2.youngs_modulus, m2.poisson,
                               b1, b2)  # fmt: skip
    load = values.K_A * values.K_gamma * values.K_v * values.K_Hbeta * values.K_Halpha
    inputs = [z1, z2, module, g["pressure_angle"], g["helix_angle"], internal,
              geo.working_pressure_angle, geo.center_distance, da1, da2, face_width, values.F_t,
              values.v, load, g["roughness"]]  # fmt: skip
    inputs = [np.asarray(v, bool if i == 5 else float) for i, v in enumerate(inputs)]
    c_a = 1000.0 * np.asarray(0.0 if rating.get("tip_relief") is None else rating["tip_relief"])
    extra = [np.asarray(v, float) for v in (x_m, x_w, n_p, values.K_A, values.c_gamma_alpha,
                                            c_a, c_a, driver)]  # fmt: skip
    shape = np.broadcast_shapes(*(v.shape for v in (*inputs, *extra)),
                                np.shape(values.valid))  # fmt: skip
    out = _in_blocks(inputs, oil, extra, shape)
    result = _results(out, values.valid, values.reason, shape)
    if errors == "raise" and not np.all(result.valid):
        from gears.rating.iso6336 import REASONS

        i = int(np.argmax(~np.ravel(result.valid)))
        raise GearError(f"no scuffing rating (row {i}): {REASONS[int(np.ravel(result.reason)[i])]}")
    return result


#: Pairs per block of :func:`rate_scuffing` (each pair evaluates its path at 37 points).
_BLOCK = 16384


def _in_blocks(inputs, oil, extra, shape):
    """:func:`scuffing_block` over the broadcast ``shape`` in blocks of :data:`_BLOCK` pairs
    (the points along the path stay within a few tens of MB)."""
    n = math.prod(shape)
    if n <= _BLOCK:
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            return scuffing_block(*inputs[:15], oil, *extra)
    flat = [np.broadcast_to(v, shape).ravel() for v in (*inputs, *extra)]
    parts = []
    for i0 in range(0, n, _BLOCK):
        part = [v[i0 : i0 + _BLOCK] for v in flat]
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            parts.append(scuffing_block(*part[:15], oil, *part[15:]))
    return {k: np.concatenate([np.broadcast_to(p[k], np.shape(p["S_B"])) for p in parts])
            .reshape(shape) for k in parts[0]}  # fmt: skip


def pair_scuffing(pair: Any, values: Any, oil: Oil, face_width: float, roughness: float,
                  materials: tuple, welding: float = 1.0, meshes: int = 1,
                  tip_relief: Any = None, thermal_contact: Any = STEEL_THERMAL_CONTACT,
                  driver: int = 1) -> ScuffingRatings:  # fmt: skip
    """The scuffing rating of one :class:`gears.GearPair` from its ISO 6336 rating ``values``
    (a :class:`gears.rating.iso6336.PairRatings`): :meth:`gears.GearPair.rating` with
    ``scuffing=`` (``tip_relief`` the rating's C_a in mm or None, ``driver`` as for
    :func:`rate_scuffing`)."""
    x_w, n_p, b1, b2 = _checked(oil, welding, meshes, thermal_contact, driver)
    c1 = c2 = _relief_um(tip_relief)
    g1, g2 = pair.mounted
    m1, m2 = materials
    x_m = thermoelastic_factor(m1.youngs_modulus, m1.poisson, m2.youngs_modulus, m2.poisson,
                               b1, b2)  # fmt: skip
    load = values.K_A * values.K_gamma * values.K_v * values.K_Hbeta * values.K_Halpha
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        out = scuffing_block(g1.teeth, g2.teeth, g1.module, g1.pressure_angle, g1.helix_angle,
                             g2.internal, pair.working_pressure_angle, pair.center_distance,
                             g1.tip_diameter, g2.tip_diameter, face_width, values.F_t, values.v,
                             load, roughness, oil, x_m, x_w, n_p, values.K_A,
                             values.c_gamma_alpha, c1, c2, driver)  # fmt: skip
    result = _results(out, values.valid, values.reason, ())
    if not result.valid:
        raise GearError(
            "no scuffing rating: a temperature is not a finite number (the load and the gear lie "
            "outside the range of the method's formulas)"
        )
    return result
