"""Layer 2, load capacity: the pitting factors of ISO 6336-2, vectorised.

The zone factor Z_H (§6.1), the single pair contact factors Z_B and Z_D (§6.2), the elasticity
factor Z_E (§7), the contact ratio factor Z_eps (§8), the lubricant, velocity and roughness
factors Z_L, Z_v, Z_R (§11) and the work hardening factor Z_W (§12). Every function takes
scalars or arrays (broadcasting); :func:`gears.rating.iso6336.rate_pairs` strings them together
into ``sigma_H`` and ``sigma_HP``.
"""

from __future__ import annotations

import numpy as np

from gears.namespace import of
from gears.rating._arrays import out as _out
from gears.rating._arrays import where as _where
from gears.rating.materials import HARDENED

__all__ = [
    "contact_ratio_factor",
    "elasticity_factor",
    "lubrication_factors",
    "roughness_factor",
    "single_pair_factors",
    "work_hardening_factors",
    "zone_factor",
]


def zone_factor(alpha_t, alpha_wt, beta_b):
    """Z_H = sqrt(2 cos beta_b cos alpha_wt / (cos^2 alpha_t sin alpha_wt)) (ISO 6336-2 §6.1;
    angles in degrees).

    >>> round(float(zone_factor(20.0, 20.0, 0.0)), 4)          # spur, no shift: 2.4946
    2.4946
    """
    xp = of(alpha_t, alpha_wt, beta_b)
    if xp is np:
        alpha_t, alpha_wt, beta_b = (np.asarray(a, float) for a in (alpha_t, alpha_wt, beta_b))
    at, awt, bb = xp.radians(alpha_t), xp.radians(alpha_wt), xp.radians(beta_b)
    return _out(xp.sqrt(2.0 * xp.cos(bb) * xp.cos(awt) / (xp.cos(at) ** 2 * xp.sin(awt))))


def elasticity_factor(e1, nu1, e2, nu2):
    """Z_E = sqrt(1 / (pi ((1 - nu1^2)/E1 + (1 - nu2^2)/E2))), sqrt(MPa) (ISO 6336-2 §7).

    >>> round(float(elasticity_factor(206000, 0.3, 206000, 0.3)), 2)   # steel: 189.81
    189.81
    """
    xp = of(e1, nu1, e2, nu2)
    if xp is np:
        e1, nu1, e2, nu2 = (np.asarray(v, float) for v in (e1, nu1, e2, nu2))
    return _out(xp.sqrt(1.0 / (xp.pi * ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2))))


def contact_ratio_factor(eps_alpha, eps_beta):
    """Z_eps (ISO 6336-2 §8): ``sqrt((4 - eps_alpha)/3 (1 - eps_beta) + eps_beta/eps_alpha)``
    for eps_beta < 1 (``sqrt((4 - eps_alpha)/3)`` for spur gears), ``sqrt(1/eps_alpha)`` for
    eps_beta >= 1.

    >>> round(float(contact_ratio_factor(1.5491, 1.083)), 4)   # ISO/TR 6336-30 Ex. 1: 0.803
    0.8035
    """
    xp = of(eps_alpha, eps_beta)
    ea, eb = eps_alpha, eps_beta
    if xp is np:
        ea, eb = np.asarray(ea, float), np.asarray(eb, float)
    eb = xp.minimum(eb, 1.0)
    return _out(xp.sqrt((4.0 - ea) / 3.0 * (1.0 - eb) + eb / ea))


def single_pair_factors(z1, z2, da1, da2, db1, db2, alpha_wt, eps_alpha, eps_beta,
                        internal=False):  # fmt: skip
    """``(Z_B, Z_D)`` (ISO 6336-2 §6.2), the ratio of the contact stress at the inner points of
    single contact B (gear 1) and D (gear 2) to the pitch point's.

    ``M1 = tan alpha_wt / sqrt((sqrt(da1^2/db1^2 - 1) - 2 pi/z1)(sqrt(da2^2/db2^2 - 1)
    - sigma (eps_alpha - 1) 2 pi/z2))`` (sigma = -1 internal: the ring's flank radius grows
    towards its root) and M2 likewise; ``Z = max(1, M - min(eps_beta, 1)(M - 1))``;
    ``Z_D = 1`` for internal gears, both 1 for eps_beta >= 1. NaN where a single-contact point lies
    inside a base circle (and eps_beta < 1).
    """
    ea, eb, pi = eps_alpha, eps_beta, np.pi
    xp = of(z1, z2, da1, da2, db1, db2, alpha_wt, ea, eb, internal)
    if xp is np:
        internal = np.asarray(internal, bool)
        z1, z2, da1, da2, ea, eb = (np.asarray(v, float) for v in (z1, z2, da1, da2, ea, eb))
    s = _where(internal, -1.0, 1.0)
    l1 = xp.sqrt(xp.maximum((da1 / db1) ** 2 - 1.0, 0.0))
    l2 = xp.sqrt(xp.maximum((da2 / db2) ** 2 - 1.0, 0.0))
    tw = xp.tan(xp.radians(alpha_wt))
    with xp.errstate(invalid="ignore", divide="ignore"):
        m1 = tw / xp.sqrt((l1 - 2 * pi / z1) * (l2 - s * (ea - 1.0) * 2 * pi / z2))
        m2 = tw / xp.sqrt((l2 - s * 2 * pi / z2) * (l1 - (ea - 1.0) * 2 * pi / z1))
    eb = xp.minimum(eb, 1.0)
    # eps_beta >= 1: 1 whatever M (the single-contact points do not matter then); else NaN
    # where M does not exist (the point lies inside a base circle: the mesh interferes)
    zb = _where(eb >= 1.0, 1.0, xp.maximum(1.0, m1 - eb * (m1 - 1.0)))
    zd = _where(s < 0, 1.0, _where(eb >= 1.0, 1.0, xp.maximum(1.0, m2 - eb * (m2 - 1.0))))
    zb = _where(xp.isnan(m1) & (eb < 1.0), xp.nan, zb)
    zd = _where(xp.isnan(m2) & (eb < 1.0) & (s > 0), xp.nan, zd)
    return _out(zb), _out(zd)


def _c_zl(sigma_hlim):
    s = sigma_hlim if type(sigma_hlim) is float else np.asarray(sigma_hlim, float)
    return _where(s < 850.0, 0.83, _where(s < 1200.0, s / 4375.0 + 0.6357, 0.91))


def lubrication_factors(sigma_hlim, oil_viscosity, speed):
    """``(Z_L, Z_v)`` (ISO 6336-2 §11, method B): ``Z_L = C_ZL + 4 (1 - C_ZL)/(1.2 + 134 /
    nu_40)^2``, ``Z_v = C_Zv + 2 (1 - C_Zv) / sqrt(0.8 + 32 / v)``, C_ZL from sigma_Hlim (the
    smaller of the pair), C_Zv = C_ZL + 0.02; nu_40 in mm^2/s, v in m/s.

    >>> [round(float(f), 5) for f in lubrication_factors(1500, 320, 2.664)]   # TR: 1.04739, 0.96911
    [1.04739, 0.96911]
    """
    xp = of(sigma_hlim, oil_viscosity, speed)
    if xp is np:
        oil_viscosity, speed = np.asarray(oil_viscosity, float), np.asarray(speed, float)
    czl = _c_zl(sigma_hlim)
    zl = czl + 4.0 * (1.0 - czl) / (1.2 + 134.0 / oil_viscosity) ** 2
    czv = czl + 0.02
    zv = czv + 2.0 * (1.0 - czv) / xp.sqrt(0.8 + 32.0 / speed)
    return _out(zl), _out(zv)


def roughness_factor(sigma_hlim, rz, rho_red):
    """Z_R = (3 / R_z10)^C_ZR, R_z10 = R_z (10 / rho_red)^(1/3) (ISO 6336-2 §11; R_z the mean
    peak-to-valley roughness of the flanks in um, rho_red the relative radius of curvature at the
    pitch point in mm); C_ZR = 0.15 below 850 MPa, 0.32 - 0.0002 sigma_Hlim to 1200, then 0.08.

    >>> round(float(roughness_factor(1500, 6.0, 21.8)), 3)   # ISO/TR 6336-30 Ex. 1: 0.96599
    0.966
    """
    s, xp = sigma_hlim, of(sigma_hlim, rz, rho_red)
    if xp is np:
        s, rz, rho_red = (np.asarray(v, float) for v in (s, rz, rho_red))
    czr = _where(s < 850.0, 0.15, _where(s < 1200.0, 0.32 - 0.0002 * s, 0.08))
    rz10 = rz * xp.cbrt(10.0 / rho_red)
    return _out(xp.power(3.0 / rz10, czr))


def work_hardening_factors(code1, code2, hb1, hb2, rz, rho_red, nu40, v):
    """``(Z_W1, Z_W2)`` (ISO 6336-2 §12): for a through-hardened gear meshing with a hardened
    (surface-hardened or nitrided) one, ``(1.2 - (HB - 130)/1700)(3/R_zH)^0.15`` with HB in
    130 ... 470 and ``R_zH = R_z (10/rho_red)^0.33 / (nu_40 v / 1500)^0.33`` in 3 ... 16 (both
    flanks of equal roughness); 1 otherwise. ``code1``, ``code2`` are the material groups' codes
    (:func:`gears.rating.materials.kind_code`), ``hb1``, ``hb2`` their hardness (HB), R_z in um,
    rho_red in mm, nu_40 in mm^2/s, v in m/s.

    >>> z = work_hardening_factors(1, 4, 285.0, 700.0, 2.0, 10.0, 220.0, 5.0)  # R_zH 2.2 -> 3
    >>> [round(float(v), 4) for v in z]   # 1.2 - (285 - 130)/1700 = 1.1088; hardened gear: 1
    [1.1088, 1.0]
    """
    xp = of(hb1, hb2, rz, rho_red, nu40, v)
    rzh = rz * xp.power(10.0 / rho_red, 0.33) / xp.power(nu40 * v / 1500.0, 0.33)
    rzh = xp.clip(rzh, 3.0, 16.0)
    out = []
    for mine, other, hb in ((code1, code2, hb1), (code2, code1, hb2)):
        if HARDENED[mine] or not HARDENED[other]:
            out.append(1.0 if xp is not np else np.ones_like(rzh))
            continue
        hb = min(max(hb, 130.0), 470.0)
        out.append((1.2 - (hb - 130.0) / 1700.0) * xp.power(3.0 / rzh, 0.15))
    return out[0], out[1]
