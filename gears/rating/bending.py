"""Layer 2, load capacity: the tooth-root bending factors of ISO 6336-3, vectorised.

The load point on the virtual spur gear and the root form by method B (§6.2: the chord s_Fn at
the 30 deg tangent, the fillet radius rho_F, the moment arm h_Fe; the rack approximation for an
internal gear), the form factors Y_F and Y_S (§6.2, §7.2) with the load distribution influence
factor f_eps of the 2019 edition's Y_F, the helix factor Y_beta (§8, of either edition), the
deep tooth factor Y_DT (§10), and the factors of the allowable stress: the relative notch
sensitivity Y_deltarelT (§13), the relative surface factor Y_RrelT (§14) and the size factor Y_X
(§15). Every function takes scalars or arrays (broadcasting);
:func:`gears.rating.iso6336.rate_pairs` strings them together into ``sigma_F`` and ``sigma_FP``.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from gears.errors import GearError
from gears.involute import inv
from gears.namespace import of
from gears.rating._arrays import out as _out
from gears.rating._arrays import where as _where
from gears.rating.materials import ROOT_SURFACE_CLASS, SIZE_CLASS

__all__ = [
    "EDITIONS",
    "check_edition",
    "deep_tooth_factor",
    "form_factors",
    "helix_factor_root",
    "internal_root_form",
    "load_distribution_factor",
    "load_point",
    "notch_sensitivity_factor",
    "root_form",
    "root_size_factor",
    "root_surface_factor",
]


#: The editions of ISO 6336-1/-2/-3 a rating follows (``edition=``), the default first. They
#: differ in ISO 6336-3's Y_F (the 2019 edition's load distribution influence factor f_eps) and
#: Y_beta (its 1/cos^3 beta); docs/rating.md, "The edition".
EDITIONS = (2019, 2006)


def check_edition(edition: Any) -> int:
    """``edition`` as one of :data:`EDITIONS`, or a GearError naming it and the valid ones."""
    # an integer (not a bool, a float or a string), numpy's of any width
    if (type(edition) is int or isinstance(edition, np.integer)) and int(edition) in EDITIONS:
        return int(edition)
    raise GearError(
        f"edition = {edition!r}; valid are 2019 (ISO 6336-1/-2/-3:2019, the default) and 2006 "
        "(ISO 6336-1/-2/-3:2006)"
    )


# --- the root: load point and form ------------------------------------------------------------
def load_point(z, module, tip_diameter_, reference_diameter, pressure_angle, helix_angle,
               eps_alpha, internal=False):  # fmt: skip
    """Diameter d_en and pressure angle alpha_en (radians) of the outer point of single pair
    contact on the virtual spur gear (ISO 6336-3 §6.2), where method B applies the load.

    ``z_n = z / (cos^2 beta_b cos beta)``, ``d_n = m_n z_n``, ``d_bn = d_n cos alpha_n``,
    ``d_an = d_n + d_a - d``, ``eps_alpha_n = eps_alpha / cos^2 beta_b``, and the point lies
    ``p_bn (eps_alpha_n - 1)`` along the line of action from the tip towards the root (towards
    the centre for an external gear, outwards for a ring):
    ``d_en = 2 sqrt((sqrt(r_an^2 - r_bn^2) -+ p_bn (eps_alpha_n - 1))^2 + r_bn^2)``.
    Returns ``(d_en, alpha_en, z_n, d_bn)``; d_en is NaN where the point lies inside the base
    circle.
    """
    m, da, d = module, tip_diameter_, reference_diameter
    xp = of(z, m, da, d, pressure_angle, helix_angle, eps_alpha, internal)
    if xp is np:
        z, m, da, d, eps_alpha = (np.asarray(v, float) for v in (z, m, da, d, eps_alpha))
        internal = np.asarray(internal, bool)
    an = xp.radians(pressure_angle)
    beta = xp.radians(xp.abs(helix_angle))
    at = xp.arctan(xp.tan(an) / xp.cos(beta))
    cbb2 = xp.cos(xp.arctan(xp.tan(beta) * xp.cos(at))) ** 2
    zn = z / (cbb2 * xp.cos(beta))
    dn = m * zn
    dbn = dn * xp.cos(an)
    dan = dn + da - d
    ean = eps_alpha / cbb2
    s = _where(internal, -1.0, 1.0)
    la = xp.sqrt(xp.maximum(dan * dan - dbn * dbn, 0.0)) / 2.0
    le = la - s * xp.pi * m * xp.cos(an) * (ean - 1.0)
    le = _where((dan >= dbn) & (le >= 0.0), le, xp.nan)
    den = 2.0 * xp.sqrt(le * le + dbn * dbn / 4.0)
    return _out(den), _out(xp.arccos(dbn / den)), _out(zn), _out(dbn)


def root_form(zn, module, profile_shift, pressure_angle, d_en, alpha_en, dedendum=1.25,
              root_radius=0.38, protuberance=0.0):  # fmt: skip
    """Root form of a rack-generated external gear by ISO 6336-3 §6.2 (method B): the chord
    s_Fn between the 30 deg tangent points on the fillet, the fillet radius rho_F there, the
    moment arm h_Fe of the load at d_en and its angle alpha_Fen (radians).

    With the tool's addendum h_fP and tip radius rho_fP (coefficients of m_n):
    ``E = pi/4 - h_fP tan alpha_n + s_pr / cos alpha_n - (1 - sin alpha_n) rho_fP /
    cos alpha_n``, ``G = rho_fP - h_fP + x``, ``H = 2/z_n (pi/2 - E) - T`` (T = pi/3 for the
    30 deg tangent of an external gear), ``theta = 2 G / z_n tan theta - H`` (iterated from
    pi/6), then ``s_Fn = m_n (z_n sin(pi/3 - theta) + sqrt(3) (G / cos theta - rho_fP))``,
    ``rho_F = m_n (rho_fP + 2 G^2 / (cos theta (z_n cos^2 theta - 2 G)))``,
    ``gamma_e = (pi/2 + 2 x tan alpha_n)/z_n + inv alpha_n - inv alpha_en``,
    ``alpha_Fen = alpha_en - gamma_e`` and ``h_Fe = m_n/2 ((cos gamma_e - sin gamma_e tan
    alpha_Fen) d_en/m_n - z_n cos(pi/3 - theta) - G / cos theta + rho_fP)``.

    Returns ``(s_Fn, rho_F, h_Fe, alpha_Fen)`` (mm, mm, mm, rad).

    >>> s, r, h, a = root_form(18.905, 8, 0.145, 20, 154.834, 0.40808, 1.4, 0.39)
    >>> round(float(s / 8), 4), round(float(r / 8), 4), round(float(h / 8), 4)
    (2.0228, 0.5812, 1.0546)
    """
    m, x, hf, rho, spr = module, profile_shift, dedendum, root_radius, protuberance
    aen, den = alpha_en, d_en
    xp = of(zn, m, x, pressure_angle, den, aen, hf, rho, spr)
    if xp is np:
        zn, m, x, hf, rho, spr, aen, den = (np.asarray(v, float) for v in (zn, m, x, hf, rho, spr,
                                                                          aen, den))  # fmt: skip
    an = xp.radians(pressure_angle)
    e = xp.pi / 4 - hf * xp.tan(an) + spr / xp.cos(an) - (1.0 - xp.sin(an)) * rho / xp.cos(an)
    g = rho - hf + x
    h = 2.0 / zn * (xp.pi / 2 - e) - xp.pi / 3
    k = 2.0 * g / zn
    # theta - k tan theta + h = 0 by Newton's method from pi/6 (the standard iterates the fixed
    # point, a contraction on real teeth; six Newton steps from pi/6 reach 1e-15 from z_n = 5 to
    # 1000, x = -0.8 ... 1.5); where it has not converged (no real tooth) the root form is NaN
    theta = np.pi / 6 - (np.pi / 6 - k * math.tan(np.pi / 6) + h) / (1.0 - k * 4.0 / 3.0)
    for _ in range(5):
        ct = xp.cos(theta)
        theta = theta - (theta - k * xp.tan(theta) + h) / (1.0 - k / (ct * ct))
    theta = _where(xp.abs(theta - k * xp.tan(theta) + h) < 1e-9, theta, xp.nan)
    ct = xp.cos(theta)
    s_fn = m * (zn * xp.sin(xp.pi / 3 - theta) + xp.sqrt(3.0) * (g / ct - rho))
    rho_f = m * (rho + 2.0 * g * g / (ct * (zn * ct * ct - 2.0 * g)))
    # no load point (NaN from load_point): NaN lengths, for the rating's reason to name
    known = xp.isfinite(aen)
    gamma = (xp.pi / 2 + 2.0 * x * xp.tan(an)) / zn + inv(an) - inv(_where(known, aen, an))
    afen = _where(known, aen - gamma, xp.nan)
    h_fe = m / 2 * ((xp.cos(gamma) - xp.sin(gamma) * xp.tan(afen)) * den / m
                    - zn * xp.cos(xp.pi / 3 - theta) - g / ct + rho)  # fmt: skip
    return _out(s_fn), _out(rho_f), _out(h_fe), _out(afen)


def internal_root_form(module, pressure_angle, d_en, d_fn, dedendum=1.25, root_radius=0.38,
                       protuberance=0.0):  # fmt: skip
    """Root form of an internal gear by the rack approximation of ISO 6336-3 (the tooth of the
    generating rack, T = pi/6: the 60 deg tangent on its root round of radius rho_fP).

    The round's centre lies ``u_c = m_n (pi/4 + (h_fP - rho_fP) tan alpha_n + (rho_fP - s_pr)
    / cos alpha_n)`` from the tooth centre line and rho_fP above the root line, so
    ``s_Fn = 2 (u_c - rho_fP m_n cos 60 deg)``, ``rho_F = rho_fP m_n``, the tangent point lies
    ``rho_fP m_n (1 - sin 60 deg)`` above the root, and the load at ``h_L = (d_fn - d_en)/2``
    above the root, normal to the straight flank (``alpha_Fen = alpha_n``), where the tooth is
    ``w_L = m_n (pi/4 + (h_fP - h_L/m_n) tan alpha_n)`` wide each side, gives
    ``h_Fe = h_L - w_L tan alpha_n - rho_fP m_n (1 - sin 60 deg)`` (docs/rating.md).

    Returns ``(s_Fn, rho_F, h_Fe, alpha_Fen)``.

    >>> s, r, h, a = internal_root_form(1, 20, 82.0, 85.0)
    >>> round(float(s), 4), round(float(r), 4), round(float(h), 4)
    (2.6329, 0.38, 1.1963)
    """
    m, pa, hf, rho, spr = module, pressure_angle, dedendum, root_radius, protuberance
    xp = of(m, pa, d_en, d_fn, hf, rho, spr)
    if xp is np:
        m, pa, d_en, d_fn, hf, rho, spr = (np.asarray(v, float) for v in (m, pa, d_en, d_fn, hf,
                                                                         rho, spr))  # fmt: skip
    an = xp.radians(pa)
    ta = xp.tan(an)
    t = xp.radians(60.0)
    u_c = m * (xp.pi / 4 + (hf - rho) * ta + (rho - spr) / xp.cos(an))
    s_fn = 2.0 * (u_c - rho * m * xp.cos(t))
    h_l = (d_fn - d_en) / 2.0
    w_l = xp.pi / 4 * m + (hf * m - h_l) * ta
    h_fe = h_l - w_l * ta - rho * m * (1.0 - xp.sin(t))
    afen = an if xp is not np else np.broadcast_to(an, np.shape(h_fe)).astype(float)
    return _out(s_fn), _out(rho * m), _out(h_fe), _out(afen)


def form_factors(s_fn, rho_f, h_fe, alpha_fen, module, pressure_angle):
    """``(Y_F, Y_S, q_s)`` from the root form (ISO 6336-3 §6.2, §7.2):
    ``Y_F = 6 (h_Fe/m_n) cos alpha_Fen / ((s_Fn/m_n)^2 cos alpha_n)``,
    ``Y_S = (1.2 + 0.13 L) q_s^(1 / (1.21 + 2.3 / L))``, ``L = s_Fn / h_Fe``,
    ``q_s = s_Fn / (2 rho_F)`` (``alpha_fen`` in radians).
    """
    m, s, r, h = module, s_fn, rho_f, h_fe
    xp = of(m, s, r, h, alpha_fen, pressure_angle)
    if xp is np:
        m, s, r, h = (np.asarray(v, float) for v in (m, s, r, h))
    yf = 6.0 * (h / m) * xp.cos(alpha_fen) / ((s / m) ** 2 * xp.cos(xp.radians(pressure_angle)))
    with xp.errstate(divide="ignore", invalid="ignore"):
        big_l = s / h
        qs = s / (2.0 * r)
        ys = (1.2 + 0.13 * big_l) * xp.power(qs, 1.0 / (1.21 + 2.3 / big_l))
    return _out(yf), _out(ys), _out(qs)


def load_distribution_factor(eps_beta, eps_alpha_n):
    """The load distribution influence factor f_eps of ISO 6336-3:2019 §6.2 (Formulae (10) to
    (14)), the factor on the 2019 edition's Y_F (the 2006 edition has none: 1), from the overlap
    ratio eps_beta and the virtual contact ratio ``eps_alpha_n = eps_alpha / cos^2 beta_b``:

    * spur (eps_beta = 0): 1 for eps_alpha_n < 2, else 0.7;
    * eps_beta >= 1: ``eps_alpha_n^-0.5``;
    * 0 < eps_beta < 1: ``sqrt(1 - eps_beta + eps_beta / eps_alpha_n)`` for eps_alpha_n < 2,
      else ``sqrt((1 - eps_beta) / 2 + eps_beta / eps_alpha_n)``.

    >>> round(float(load_distribution_factor(0.6, 1.65 / 0.84231)), 3)   # beta 25 deg: 0.840
    0.84
    """
    xp = of(eps_beta, eps_alpha_n)
    low = eps_alpha_n < 2.0
    part = _where(low, 1.0 - eps_beta, (1.0 - eps_beta) / 2.0) + eps_beta / eps_alpha_n
    between = xp.sqrt(xp.maximum(part, 0.0))
    full = 1.0 / xp.sqrt(eps_alpha_n)
    spur = _where(low, 1.0, 0.7)
    return _out(_where(eps_beta <= 0.0, spur, _where(eps_beta >= 1.0, full, between)))


def helix_factor_root(eps_beta, helix_angle, edition=2019):
    """Y_beta (ISO 6336-3 §8; beta in degrees) of the 2019 edition (Formula (66)),
    ``(1 - min(eps_beta, 1) min(beta, 30 deg) / 120 deg) / cos^3 min(beta, 30 deg)``, or of the
    2006 edition (``edition=2006``), the same without the division by cos^3 beta.

    >>> round(float(helix_factor_root(1.083, 15.8, 2006)), 4)   # ISO/TR 6336-30 Ex. 1: 0.8683
    0.8683
    >>> round(float(helix_factor_root(1.0, 25.0)), 3)   # ISO 6336-3:2019 Formula (66): 1.063
    1.063
    """
    xp = of(eps_beta, helix_angle)
    beta = xp.minimum(xp.abs(helix_angle), 30.0)
    y = 1.0 - xp.minimum(eps_beta, 1.0) * beta / 120.0
    if edition == 2006:
        return y
    return y / xp.cos(xp.radians(beta)) ** 3


def deep_tooth_factor(quality, eps_alpha_n):
    """Y_DT (ISO 6336-3 §10): for accuracy grade Q <= 4 and eps_alpha_n > 2.05,
    ``-0.666 eps_alpha_n + 2.366`` (0.7 above 2.5, where the line reaches 0.701); 1 otherwise
    (as IACS UR M56 Rev.4 §M56.3.7 reproduces it).

    >>> float(deep_tooth_factor(4, 2.6)), float(deep_tooth_factor(6, 2.6))
    (0.7, 1.0)
    """
    q, ean = quality, eps_alpha_n
    return _where((q <= 4) & (ean > 2.05), _where(ean > 2.5, 0.7, -0.666 * ean + 2.366), 1.0)


def notch_sensitivity_factor(q_s, slip_layer):
    """Y_deltarelT (ISO 6336-3 §13, method B): ``(1 + sqrt(rho' chi*)) / (1 + sqrt(rho'
    chi*_T))`` with ``chi* = (1 + 2 q_s) / 5`` and chi*_T = 1.2 (the test gear's q_s = 2.5);
    rho' is the material's slip-layer thickness (mm).

    >>> round(float(notch_sensitivity_factor(2.5, 0.003)), 6)   # the test gear itself
    1.0
    """
    xt = 1.2  # chi*_T = (1 + 2 * 2.5) / 5
    xp = of(q_s, slip_layer)
    with xp.errstate(invalid="ignore"):
        return (1.0 + xp.sqrt(slip_layer * (1.0 + 2.0 * xp.maximum(q_s, 0.0)) / 5.0)) / (
            1.0 + xp.sqrt(slip_layer * xt)
        )


def root_surface_factor(rz, code):
    """Y_RrelT (ISO 6336-3 §14, method B) of a material group (``code`` a Python int,
    :func:`gears.rating.materials.kind_code`) at root roughness R_z (um).

    >>> round(float(root_surface_factor(6.0, 4)), 4)   # case-hardened: 1.674 - 0.529 7^0.1
    1.0314
    """
    rz = rz if type(rz) is float else np.asarray(rz, float)
    cls = ROOT_SURFACE_CLASS[code]
    r1 = rz + 1.0
    if cls == 0:
        return _where(rz < 1.0, 1.120, 1.674 - 0.529 * r1**0.1)
    if cls == 1:
        return _where(rz < 1.0, 1.070, 5.306 - 4.203 * r1**0.01)
    return _where(rz < 1.0, 1.025, 4.299 - 3.259 * r1**0.0058)


def root_size_factor(module, code):
    """Y_X (ISO 6336-3 §15) of a material group (``code`` a Python int) at normal module m (mm).

    >>> round(float(root_size_factor(8.0, 4)), 3)   # case-hardened, m 8: 1.05 - 0.01 m
    0.97
    """
    m = module if type(module) is float else np.asarray(module, float)
    slope, top, floor_ = ((0.006, 30.0, 0.85), (0.01, 25.0, 0.8), (0.015, 25.0, 0.7))[
        SIZE_CLASS[code]
    ]
    base = 1.0 + slope * 5.0  # the lines meet 1.0 at m = 5
    return _where(m <= 5.0, 1.0, _where(m < top, base - slope * m, floor_))
