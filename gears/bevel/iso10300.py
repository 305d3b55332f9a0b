"""Layer 3, bevel gears' load capacity: the factors of ISO 10300 method B1, vectorised.

ISO 10300 (parts 1 to 3, editions 2014 and 2023) rates a bevel pair through its virtual
cylindrical gears at the mean cone. Its own factors are here, each a function of scalars or
arrays (broadcasting), in the standard's symbols (the formulas as math: docs/bevel.md, "Load
capacity"):

* ISO 10300-1: the mounting factor K_Hbeta-be (:data:`MOUNTING_FACTORS`, by how the contact
  pattern was checked and how the members are mounted) and the face load factors
  K_Hbeta = 1.5 K_Hbeta-be, K_Fbeta = K_Hbeta / K_F0 (:func:`face_load_factors`); Annex A's
  zone of action and its contact lines (:func:`zone_of_action`,
  :func:`contact_line_positions`, :func:`contact_line_length`) and the relative radius of
  curvature rho_rel (:func:`relative_curvature`);
* ISO 10300-2, method B1: the mid-zone factor Z_M-B (:func:`mid_zone_factor`), the load sharing
  factor Z_LS (:func:`load_sharing_factor`) and the bevel gear factor Z_K
  (:data:`BEVEL_FACTOR`, on the permissible stress);
* ISO 10300-3, method B1: the tooth form and stress correction factors for the load at the tip
  Y_Fa, Y_Sa (:func:`tip_form_factors`, the root of ISO 6336-3's method B,
  :func:`gears.rating.bending.root_form`, loaded at the tip of the virtual gear), the contact
  ratio factor Y_epsilon (:func:`contact_ratio_factor_root`), the bevel spiral angle factor Y_BS
  (:func:`bevel_spiral_angle_factor`) and the load sharing factor Y_LS = Z_LS^2;
* the whole of method B1 for straight bevel pairs over arrays (:func:`method_b1`), given the
  factors it shares with ISO 6336.

The formulas are written for bevel gears without hypoid offset (a = 0); the spiral angle enters
where it is one argument, so that the published worked example (ISO/TR 10300-30, sample 1, a
spiral bevel pair) checks them; geartrain's own pairs are straight (beta_m = 0).
"""

from __future__ import annotations

import numpy as np

from gears.errors import GearError
from gears.rating.bending import form_factors, root_form

__all__ = [
    "BEVEL_FACTOR",
    "MOUNTINGS",
    "MOUNTING_FACTORS",
    "PATTERNS",
    "bevel_spiral_angle_factor",
    "contact_line_length",
    "contact_line_positions",
    "contact_ratio_factor_root",
    "face_load_factors",
    "load_sharing_factor",
    "method_b1",
    "mid_zone_factor",
    "mounting_factor",
    "relative_curvature",
    "tip_form_factors",
    "zone_of_action",
]

#: Bevel gear factor Z_K of ISO 10300-2 (method B1), a factor of the permissible contact stress:
#: sigma_HP = sigma_Hlim Z_NT Z_X Z_L Z_v Z_R Z_W Z_K. ISO/TR 10300-30 sample 1 works it as
#: 1.2 (its sigma_HP1 = 1617.8 MPa = 1500 MPa x 0.992 x 0.974 x 0.930 x 1.2), by the 2023
#: edition. The first edition (ISO 10300-2:2001) had Z_K = 0.85 on the contact stress instead.
BEVEL_FACTOR = 1.2

#: How the members are mounted (the columns of the mounting factor's table): both straddle-mounted
#: (neither cantilever), one straddle-mounted (one cantilever), neither (both cantilever).
MOUNTINGS = ("both-straddle", "one-straddle", "neither-straddle")
#: How the contact pattern was checked (the rows): for each gear set in its housing under full
#: load, for each gear set under a light test load, or on a sample set and estimated for full load.
PATTERNS = ("full-load", "light-load", "estimated")
#: The mounting factor K_Hbeta-be of ISO 10300-1 (2014: the table of the mounting factor, as the
#: FVA-Workbench documentation of ISO 10300 (2014) prints it), by pattern, then by mounting.
MOUNTING_FACTORS = {
    "full-load": {"both-straddle": 1.00, "one-straddle": 1.00, "neither-straddle": 1.00},
    "light-load": {"both-straddle": 1.05, "one-straddle": 1.10, "neither-straddle": 1.25},
    "estimated": {"both-straddle": 1.20, "one-straddle": 1.32, "neither-straddle": 1.50},
}


def mounting_factor(mounting: str = "both-straddle", pattern: str = "light-load") -> float:
    """K_Hbeta-be of ISO 10300-1 for a ``mounting`` (:data:`MOUNTINGS`) and the way the contact
    pattern was checked (``pattern``, :data:`PATTERNS`).

    >>> mounting_factor("one-straddle", "light-load")   # ISO/TR 10300-30 sample 1: 1.10
    1.1
    """
    if pattern not in MOUNTING_FACTORS:
        raise GearError(f"pattern = {pattern!r}; valid are {', '.join(map(repr, PATTERNS))}")
    if mounting not in MOUNTING_FACTORS[pattern]:
        raise GearError(f"mounting = {mounting!r}; valid are {', '.join(map(repr, MOUNTINGS))}")
    return MOUNTING_FACTORS[pattern][mounting]


def face_load_factors(k_hbeta_be, k_f0=1.0):
    """``(K_Hbeta, K_Fbeta)`` of ISO 10300-1 (method C) for a contact pattern that is
    satisfactory under load: ``K_Hbeta = 1.5 K_Hbeta-be``, ``K_Fbeta = K_Hbeta / K_F0`` with the
    lengthwise curvature factor K_F0 (1 for straight bevel gears).

    >>> [round(float(k), 3) for k in face_load_factors(1.10)]   # ISO/TR 10300-30 sample 1
    [1.65, 1.65]
    """
    kh = 1.5 * np.asarray(k_hbeta_be, float)
    return kh, kh / np.asarray(k_f0, float)


# --- ISO 10300-1, Annex A: the zone of action and its contact lines ----------------------------
def zone_of_action(g_va, b_veff, beta_vb=0.0):
    """``(f_max, l_b0)`` of the zone of action of the virtual cylindrical gears without offset:
    the largest distance of a contact line from the zone's centre,
    ``f_max = (g_va + b_v,eff tan beta_vb) cos beta_vb / 2``, and the length of a contact line
    across the zone, ``l_b0 = min(b_v,eff / cos beta_vb, g_va / sin beta_vb)`` (the face width
    for straight teeth, where the lines run across the face at ``f`` along the path).

    ``g_va`` is the length of the path of contact, ``b_veff`` the effective face width (mm),
    ``beta_vb`` the helix angle at the base circle (degrees).

    >>> [round(float(v), 3) for v in zone_of_action(13.0, 20.0)]
    [6.5, 20.0]
    """
    b = np.radians(np.asarray(beta_vb, float))
    g, w = np.asarray(g_va, float), np.asarray(b_veff, float)
    f_max = 0.5 * (g + w * np.tan(b)) * np.cos(b)
    with np.errstate(divide="ignore", over="ignore"):
        l_b0 = np.minimum(w / np.cos(b), np.where(b > 0.0, g / np.sin(b), np.inf))
    return f_max, l_b0


def contact_line_positions(p_vet, eps_va, eps_vb, beta_vb=0.0):
    """``(f_t, f_m, f_r)``: the distances of the tip, middle and root contact lines from the
    centre of the zone of action (ISO 10300-1, Annex A). With ``eps_vb >= 1`` the middle line
    runs through the centre; below it moves by
    ``X = p_vet (1 - eps_va / 2) cos beta_vb (1 - eps_vb)``: ``f_m = -X``, and the tip and root
    lines lie one base pitch ``p_vet cos beta_vb`` either side. For straight teeth the middle
    line is the inner point of single contact, ``g_va / 2 - p_vet``.

    >>> [round(float(f), 3) for f in contact_line_positions(10.0, 1.5, 0.0)]
    [7.5, -2.5, -12.5]
    """
    p = np.asarray(p_vet, float) * np.cos(np.radians(np.asarray(beta_vb, float)))
    e_a, e_b = np.asarray(eps_va, float), np.asarray(eps_vb, float)
    x = np.where(e_b >= 1.0, 0.0, (1.0 - e_a / 2.0) * p * (1.0 - np.minimum(e_b, 1.0)))
    return -x + p, -x, -x - p


def contact_line_length(f, f_max, l_b0, b_veff, b_v):
    """Length l_b of the contact line at ``f`` (ISO 10300-1, Annex A): the line across the
    zone, ``l_b0``, shortened to the elliptical contact pattern of a crowned tooth,
    ``l_b = l_b0 (1 - C_lb)`` with ``C_lb = sqrt((f / f_max)^2 + k^2 (1 - (f / f_max)^2))`` and
    ``k = 1 - sqrt(b_v,eff / b_v)``; zero outside the zone (``|f| >= f_max``).

    >>> round(float(contact_line_length(0.0, 6.5, 17.0, 17.0, 20.0)), 3)   # 17 sqrt(0.85)
    15.673
    """
    r2 = np.minimum((np.asarray(f, float) / np.asarray(f_max, float)) ** 2, 1.0)
    k = 1.0 - np.sqrt(np.asarray(b_veff, float) / np.asarray(b_v, float))
    c_lb = np.sqrt(r2 + k * k * (1.0 - r2))
    return np.asarray(l_b0, float) * np.maximum(1.0 - c_lb, 0.0)


def load_sharing_factor(f, f_max, l_b, exponent=1.5):
    """Load sharing factor Z_LS of ISO 10300-2 (method B1) from the tip, middle and root contact
    lines: ``f`` and ``l_b`` are triples ``(tip, middle, root)`` (each a scalar or array). The
    peak load of each line follows a parabola over the zone, ``p* = 1 - |f / f_max|^e_LS`` (0
    outside it; ``exponent`` e_LS = 1.5 for profile-crowned industrial gears, 3 for little
    profile crowning, e.g. automotive), each line carries ``A* = pi/4 p* l_b`` and the middle
    line's share gives ``Z_LS = sqrt(A*_m / (A*_t + A*_m + A*_r))``. Y_LS = Z_LS^2 (ISO
    10300-3).

    >>> round(float(load_sharing_factor((7.5, -2.5, -12.5), 7.5, (0.0, 11.0, 0.0))), 3)
    1.0
    """
    fm = np.asarray(f_max, float)
    areas = []
    for fi, li in zip(f, l_b, strict=True):
        p = np.maximum(1.0 - np.abs(np.asarray(fi, float) / fm) ** exponent, 0.0)
        areas.append(np.pi / 4.0 * p * np.asarray(li, float))
    a_t, a_m, a_r = areas
    return np.sqrt(a_m / (a_t + a_m + a_r))


def relative_curvature(d_v1, d_v2, pressure_angle, beta_m=0.0):
    """Relative radius of curvature rho_rel at the mean point, normal to the contact line (ISO
    10300-1, Annex A, without offset and with the effective pressure angle alpha_e =
    alpha_n): ``rho_t = sin alpha_n / (cos^2 beta_m (2 / d_v1 + 2 / d_v2))``,
    ``beta_B = atan(tan beta_m sin alpha_n)``, ``rho_rel = rho_t cos^2 beta_B`` (``d_v`` the
    virtual reference diameters d_m / cos delta, mm; angles in degrees). For straight teeth it is
    the relative radius of the virtual gears at the pitch point, ``sin alpha r_v1 r_v2 / (r_v1
    + r_v2)``.

    >>> round(float(relative_curvature(60.0, 120.0, 20.0)), 4)   # sin 20 x 30 x 60 / 90
    6.8404
    """
    an = np.radians(np.asarray(pressure_angle, float))
    bm = np.radians(np.asarray(beta_m, float))
    rho_t = np.sin(an) / (np.cos(bm) ** 2 * (2.0 / np.asarray(d_v1, float)
                                             + 2.0 / np.asarray(d_v2, float)))  # fmt: skip
    return rho_t * np.cos(np.arctan(np.tan(bm) * np.sin(an))) ** 2


# --- ISO 10300-2, method B1 ----------------------------------------------------------------------
def mid_zone_factor(alpha_vt, d_va1, d_vb1, z_v1, d_va2, d_vb2, z_v2, eps_va, eps_vb):
    """Mid-zone factor Z_M-B of ISO 10300-2 (method B1): the contact stress at the pitch point
    carried to the determinant point of the zone of action,
    ``Z_M-B = tan alpha_vt / sqrt((sqrt((d_va1/d_vb1)^2 - 1) - F1 pi/z_v1)
    (sqrt((d_va2/d_vb2)^2 - 1) - F2 pi/z_v2))`` with ``F1 = 2``, ``F2 = 2 (eps_va - 1)`` for
    ``eps_vb = 0`` (the inner point of single contact of the pinion, ISO 6336-2's Z_B),
    ``F1 = F2 = eps_va`` for ``eps_vb >= 1`` (the middle of the zone) and the linear blend
    ``F1 = 2 + (eps_va - 2) eps_vb``, ``F2 = 2 eps_va - 2 + (2 - eps_va) eps_vb`` between.
    ``alpha_vt`` in degrees.

    >>> round(float(mid_zone_factor(20.0, 66.0, 56.382, 20.0, 126.0, 112.763, 40.0, 1.6, 0.0)), 4)
    1.0551
    """
    e_a = np.asarray(eps_va, float)
    e_b = np.clip(np.asarray(eps_vb, float), 0.0, 1.0)
    f1 = 2.0 + (e_a - 2.0) * e_b
    f2 = 2.0 * e_a - 2.0 + (2.0 - e_a) * e_b
    t1 = np.sqrt((np.asarray(d_va1, float) / d_vb1) ** 2 - 1.0) - f1 * np.pi / z_v1
    t2 = np.sqrt((np.asarray(d_va2, float) / d_vb2) ** 2 - 1.0) - f2 * np.pi / z_v2
    with np.errstate(invalid="ignore"):
        return np.tan(np.radians(alpha_vt)) / np.sqrt(t1 * t2)


# --- ISO 10300-3, method B1 ----------------------------------------------------------------------
def tip_form_factors(z_vn, m_mn, x_hm, x_sm, pressure_angle, d_van, d_vbn, h_a0=1.25,
                     rho_a0=0.25, s_pr=0.0):  # fmt: skip
    """Tooth form factor Y_Fa and stress correction factor Y_Sa of ISO 10300-3 (method B1) for
    the load at the tip of the virtual gear in its normal section (z_vn teeth, tip and base
    diameters d_van, d_vbn) generated by a tool of addendum ``h_a0`` and tip radius ``rho_a0``
    (coefficients of the mean normal module m_mn) with protuberance ``s_pr`` (of m_mn).

    ISO 10300-3 writes the root chord s_Fn, the fillet radius rho_F and the bending arm h_Fa as
    ISO 6336-3 writes s_Fn, rho_F and h_Fe, with the thickness modification x_sm among the
    auxiliary values (``E = (pi/4 - x_sm) m_mn - ...``, ``G = rho_a0 - h_a0 + x_hm``) and the
    load at the tip (``alpha_an = acos(d_vbn / d_van)``, ``gamma_a = (pi/2 + 2 (x_hm tan
    alpha_n + x_sm)) / z_vn + inv alpha_n - inv alpha_an``, ``alpha_Fan = alpha_an -
    gamma_a``): the same equations as :func:`gears.rating.bending.root_form` with the shift
    ``x_hm + x_sm / tan alpha_n`` and the tool addendum ``h_a0 + x_sm / tan alpha_n``. Then
    ``Y_Fa = 6 (h_Fa / m_mn) cos alpha_Fan / ((s_Fn / m_mn)^2 cos alpha_n)``,
    ``Y_Sa = (1.2 + 0.13 L_a) q_s^(1 / (1.21 + 2.3 / L_a))``, ``L_a = s_Fn / h_Fa``,
    ``q_s = s_Fn / (2 rho_F)``.

    Returns ``(Y_Fa, Y_Sa, s_Fn, rho_F, h_Fa, alpha_Fan, q_s)`` (mm; alpha_Fan in radians).
    """
    an = np.radians(np.asarray(pressure_angle, float))
    dx = np.asarray(x_sm, float) / np.tan(an)
    d_van = np.asarray(d_van, float)
    alpha_an = np.arccos(np.clip(np.asarray(d_vbn, float) / d_van, -1.0, 1.0))
    s_fn, rho_f, h_fa, a_fan = root_form(
        z_vn, m_mn, np.asarray(x_hm, float) + dx, pressure_angle, d_van, alpha_an,
        np.asarray(h_a0, float) + dx, rho_a0, s_pr,
    )  # fmt: skip
    y_fa, y_sa, q_s = form_factors(s_fn, rho_f, h_fa, a_fan, m_mn, pressure_angle)
    return y_fa, y_sa, s_fn, rho_f, h_fa, a_fan, q_s


def contact_ratio_factor_root(eps_va, eps_vb):
    """Contact ratio factor Y_epsilon of ISO 10300-3 (method B1) for the load at the tip:
    ``0.25 + 0.75 / eps_va`` for ``eps_vb = 0``, 0.625 for ``eps_vb >= 1``, linear between,
    and never below 0.625.

    >>> round(float(contact_ratio_factor_root(1.5, 0.0)), 4)
    0.75
    """
    y0 = 0.25 + 0.75 / np.asarray(eps_va, float)
    e_b = np.clip(np.asarray(eps_vb, float), 0.0, 1.0)
    return np.maximum(y0 - e_b * (y0 - 0.625), 0.625)


def bevel_spiral_angle_factor(beta_v, beta_vb, l_bm, b_v, h_m1, h_m2):
    """Bevel spiral angle factor Y_BS of ISO 10300-3 (method B1): with the developed tooth
    length ``b_a = b_v / cos beta_v``, the part of it the middle contact line covers
    ``l_bb = l_bm cos beta_vb / cos beta_v`` and ``x = 2 b_a / (h_m1 + h_m2)`` (the mean whole
    depths), ``a_BS = -0.0182 x^2 + 0.4736 x - 0.32``, ``b_BS = -0.0032 x^2 + 0.0526 x +
    0.712``, ``c_BS = -0.0050 x^2 + 0.0850 x + 0.54`` and
    ``Y_BS = a_BS / c_BS (l_bb / b_a - 1.05 b_BS)^2 + 1``. Straight teeth (``beta_v = 0``)
    have Y_BS = 1. Angles in degrees.

    >>> float(bevel_spiral_angle_factor(0.0, 0.0, 10.0, 20.0, 6.0, 6.0))
    1.0
    """
    bv, bvb = np.radians(np.asarray(beta_v, float)), np.radians(np.asarray(beta_vb, float))
    b_a = np.asarray(b_v, float) / np.cos(bv)
    l_bb = np.asarray(l_bm, float) * np.cos(bvb) / np.cos(bv)
    x = 2.0 * b_a / (np.asarray(h_m1, float) + np.asarray(h_m2, float))
    a = -0.0182 * x * x + 0.4736 * x - 0.32
    b = -0.0032 * x * x + 0.0526 * x + 0.712
    c = -0.0050 * x * x + 0.0850 * x + 0.54
    return np.where(bv > 0.0, a / c * (l_bb / b_a - 1.05 * b) ** 2 + 1.0, 1.0)


# --- the whole method B1 for straight teeth -------------------------------------------------------
def method_b1(torque, d_m1, face_width, m_mn, pressure_angle, d_v, d_va, d_vb, eps_va, x_hm,
              x_sm, h_a0, rho_a0, s_pr, loads, z_e, sigma_hp, sigma_fp, effective_width=0.85,
              exponent=1.5):  # fmt: skip
    """Pitting and bending of straight bevel pairs by ISO 10300-2/-3 method B1, over arrays.

    ``torque`` N m on the pinion, ``d_m1`` its mean pitch diameter, ``face_width`` b, ``m_mn``
    the mean module (mm), ``pressure_angle`` (degrees); per gear, as pairs ``(pinion, wheel)``:
    the virtual gears' reference, tip and base diameters ``d_v``, ``d_va``, ``d_vb``, the
    generating tool's ``x_hm``, ``x_sm``, ``h_a0``, ``rho_a0``, ``s_pr`` (as
    :func:`tip_form_factors` takes them), and the permissible stresses of ISO 6336 that ISO 10300
    shares, ``sigma_hp`` = sigma_Hlim Z_NT Z_L Z_v Z_R Z_W Z_X and ``sigma_fp`` = sigma_Flim Y_ST
    Y_NT Y_deltarelT Y_RrelT Y_X (Y_M); ``eps_va`` the virtual transverse contact ratio,
    ``loads`` = ``(K_A, K_v, K_Hbeta, K_Fbeta, K_Halpha, K_Falpha)``, ``z_e`` the elasticity
    factor. Everything broadcasts.

    ``sigma_H0 = sqrt(F_n / (l_bm rho_rel)) Z_M-B Z_LS Z_E``, ``sigma_H = sigma_H0 sqrt(K_A K_v
    K_Hbeta K_Halpha)``, ``sigma_HP = sigma_hp Z_K``; ``sigma_F0 = F_mt / (b m_mn) Y_Fa Y_Sa
    Y_eps Y_BS Y_LS``, ``sigma_F = sigma_F0 K_A K_v K_Fbeta K_Falpha``; ``S = sigma_P / sigma``.
    Returns a dict of arrays by ISO symbol (per gear ``S_H1``, ``S_H2``, ...).
    """
    an = np.radians(np.asarray(pressure_angle, float))
    m = np.asarray(m_mn, float)
    b = np.asarray(face_width, float)
    eps = np.asarray(eps_va, float)
    p_et = np.pi * m * np.cos(an)
    b_eff = np.asarray(effective_width, float) * b
    f_max, l_b0 = zone_of_action(eps * p_et, b_eff)
    f = contact_line_positions(p_et, eps, 0.0)
    l_b = tuple(contact_line_length(fi, f_max, l_b0, b_eff, b) for fi in f)
    z_ls = load_sharing_factor(f, f_max, l_b, exponent)
    rho = relative_curvature(d_v[0], d_v[1], pressure_angle)
    z_v = (np.asarray(d_v[0], float) / m, np.asarray(d_v[1], float) / m)
    z_mb = mid_zone_factor(pressure_angle, d_va[0], d_vb[0], z_v[0], d_va[1], d_vb[1], z_v[1],
                           eps, 0.0)  # fmt: skip
    k_a, k_v, k_hb, k_fb, k_ha, k_fa = (np.asarray(k, float) for k in loads)
    f_mt = 2000.0 * np.asarray(torque, float) / np.asarray(d_m1, float)
    f_n = f_mt / np.cos(an)
    with np.errstate(divide="ignore", invalid="ignore"):
        s_h0 = np.sqrt(f_n / (l_b[1] * rho)) * z_mb * z_ls * np.asarray(z_e, float)
    s_h = s_h0 * np.sqrt(k_a * k_v * k_hb * k_ha)
    y_eps = contact_ratio_factor_root(eps, 0.0)
    y_bs = bevel_spiral_angle_factor(0.0, 0.0, l_b[1], b, 1.0, 1.0)
    y_ls = z_ls * z_ls
    out = {
        "sigma_H0": s_h0, "sigma_H": s_h, "Z_M-B": z_mb, "Z_LS": z_ls, "Z_K": BEVEL_FACTOR,
        "Y_eps": y_eps, "Y_BS": y_bs, "Y_LS": y_ls, "F_mt": f_mt, "F_n": f_n, "b_veff": b_eff,
        "f_max": f_max, "f_m": f[1], "l_bm": l_b[1], "rho_rel": rho, "eps_valpha": eps,
        "eps_vbeta": np.zeros_like(eps),
    }  # fmt: skip
    for i in (0, 1):
        y_fa, y_sa, s_fn, rho_f, h_fa, a_fan, q_s = tip_form_factors(
            z_v[i], m, x_hm[i], x_sm[i], pressure_angle, d_va[i], d_vb[i], h_a0, rho_a0[i],
            s_pr[i],
        )  # fmt: skip
        s_f0 = f_mt / (b * m) * y_fa * y_sa * y_eps * y_bs * y_ls
        s_f = s_f0 * k_a * k_v * k_fb * k_fa
        s_hp = np.asarray(sigma_hp[i], float) * BEVEL_FACTOR
        s_fp = np.asarray(sigma_fp[i], float)
        with np.errstate(divide="ignore", invalid="ignore"):
            s_hs, s_fs = s_hp / s_h, s_fp / s_f
        n = i + 1
        out.update({
            f"sigma_HP{n}": s_hp, f"S_H{n}": s_hs, f"sigma_F0{n}": s_f0, f"sigma_F{n}": s_f,
            f"sigma_FP{n}": s_fp, f"S_F{n}": s_fs, f"Y_Fa{n}": y_fa, f"Y_Sa{n}": y_sa,
            f"s_Fn{n}": s_fn, f"rho_F{n}": rho_f, f"h_Fa{n}": h_fa,
            f"alpha_Fan{n}": np.degrees(a_fan), f"q_s{n}": q_s, f"z_v{n}": z_v[i],
        })  # fmt: skip
    return out
