"""Layer 2, load capacity: the load factors of ISO 6336-1, vectorised.

The deviations of the accuracy grade (ISO 1328-1), the single and mesh stiffness (method B,
§9), the dynamic factor K_v (method B, §6.5), the face load factors K_Hbeta (method C, §7.6) and
K_Fbeta (§7.8), the transverse load factors K_Halpha and K_Falpha (method B, §8.3) and the
running-in allowances y_alpha and y_beta they use. Every function takes scalars or arrays
(broadcasting); :func:`gears.rating.iso6336.rate_pairs` strings them together.
"""

from __future__ import annotations

import numpy as np

from gears.namespace import of
from gears.rating._arrays import out as _out
from gears.rating._arrays import where as _where
from gears.rating.materials import GREY_IRON, HARDENED

__all__ = [
    "dynamic_factor",
    "face_load_factor",
    "face_load_factor_root",
    "helix_running_in",
    "light_load_factor",
    "mesh_stiffness",
    "profile_running_in",
    "single_stiffness",
    "tolerances",
    "transverse_load_factors",
]


# --- ISO 1328-1 deviations --------------------------------------------------------------------
def tolerances(module, diameter, face_width, quality):
    """ISO 1328-1:1995 single pitch, profile form and helix slope deviations, um:
    ``(f_pt, f_falpha, f_Hbeta)`` for accuracy grade Q (arrays broadcast).

    f_pt = 0.3 (m + 0.4 sqrt d) + 4, f_falpha = 2.5 sqrt m + 0.17 sqrt d + 0.5,
    f_Hbeta = 0.07 sqrt d + 0.45 sqrt b + 3, each at grade 5, times 2^((Q - 5)/2) (ISO 1328-1
    §5.3, evaluated at the gear's own m, d, b, unrounded).

    >>> [round(float(f), 3) for f in tolerances(8, 141.34, 100, 5)]
    [7.827, 9.592, 8.332]
    """
    m, d, b, q = module, diameter, face_width, quality
    xp = of(m, d, b, q)
    if xp is np:
        m, d, b, q = (np.asarray(v, float) for v in (m, d, b, q))
    step = xp.exp2((q - 5.0) / 2.0)
    sd = xp.sqrt(d)
    f_pt = (0.3 * (m + 0.4 * sd) + 4.0) * step
    f_f = (2.5 * xp.sqrt(m) + 0.17 * sd + 0.5) * step
    f_h = (0.07 * sd + 0.45 * xp.sqrt(b) + 3.0) * step
    return _out(f_pt), _out(f_f), _out(f_h)


# --- stiffness --------------------------------------------------------------------------------
_Q = (0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182)


def single_stiffness(zn1, zn2, x1, x2, helix_angle=0.0, dedendum=1.25, pressure_angle=20.0,
                     internal=False, line_load=None):  # fmt: skip
    """Single stiffness c' (N/(mm um)) by method B (ISO 6336-1 §9.3), solid gears.

    ``1/q' = 1 / (C1 + C2/z_n1 + C3/z_n2 + C4 x1 + C5 x1/z_n1 + C6 x2 + C7 x2/z_n2 + C8 x1^2
    + C9 x2^2)`` (z_n2 = inf for an internal gear), ``c' = c'_th C_M C_R C_B cos beta`` with
    C_M = 0.8, C_R = 1 (solid), ``C_B = (1 + 0.5 (1.2 - h_fP/m_n))(1 - 0.02 (20 - alpha_n))``,
    and times ``(F_t K_A / b / 100)^0.25`` below a line load of 100 N/mm.

    >>> round(float(single_stiffness(18.905, 114.543, 0.145, 0.0, 15.8, 1.4)), 3)  # TR: 12.370
    12.37
    """
    hf, pa = dedendum, pressure_angle
    xp = of(zn1, zn2, x1, x2, helix_angle, hf, pa, internal)
    if xp is np:
        zn1, zn2, x1, x2, hf, pa = (np.asarray(v, float) for v in (zn1, zn2, x1, x2, hf, pa))
        internal = np.asarray(internal, bool)
    inv2 = _where(internal, 0.0, 1.0 / zn2)
    c1, c2, c3, c4, c5, c6, c7, c8, c9 = _Q
    q = c1 + c2 / zn1 + c3 * inv2 + c4 * x1 + c5 * x1 / zn1 + c6 * x2 + c7 * x2 * inv2
    q = q + c8 * x1 * x1 + c9 * x2 * x2
    c_b = (1.0 + 0.5 * (1.2 - hf)) * (1.0 - 0.02 * (20.0 - pa))
    c = 0.8 * c_b * xp.cos(xp.radians(helix_angle)) / q
    if line_load is not None:
        c = c * light_load_factor(line_load)
    return _out(c)


def light_load_factor(line_load):
    """``(F_t K_A / b / 100)^0.25`` below a line load of 100 N/mm, else 1: the single stiffness
    at light loads (ISO 6336-1 §9.3).

    >>> float(light_load_factor(6.25)), float(light_load_factor(500.0))
    (0.5, 1.0)
    """
    w, xp = line_load, of(line_load)
    if xp is np:
        w = np.asarray(w, float)
    return _where(w < 100.0, xp.sqrt(xp.sqrt(xp.maximum(w, 0.0) / 100.0)), 1.0)


def mesh_stiffness(c_prime, eps_alpha):
    """``(c_gamma_alpha, c_gamma_beta)``: c'(0.75 eps_alpha + 0.25) and 0.85 of it
    (ISO 6336-1 §9.4).

    >>> [round(float(c), 2) for c in mesh_stiffness(12.37047, 1.54909)]   # TR: 17.46, 14.85
    [17.46, 14.85]
    """
    c, ea = c_prime, eps_alpha
    if of(c, ea) is np:
        c, ea = np.asarray(c, float), np.asarray(ea, float)
    c = c * (0.75 * ea + 0.25)
    return _out(c), _out(0.85 * c)


# --- dynamic factor ---------------------------------------------------------------------------
def dynamic_factor(resonance_ratio, line_load, c_prime, f_pb_eff, f_f_eff, tip_relief, eps_gamma):
    """K_v by method B (ISO 6336-1 §6.5) from the resonance ratio N = n1 / n_E1, the line load
    F_t K_gamma K_A / b (N/mm), c' and the effective deviations and tip relief (um).

    Sub-critical (N <= N_S): ``K_v = N (C_v1 B_p + C_v2 B_f + C_v3 B_k) + 1``; main resonance
    (N_S < N <= 1.15): ``C_v1 B_p + C_v2 B_f + C_v4 B_k + 1``; super-critical (N >= 1.5):
    ``C_v5 B_p + C_v6 B_f + C_v7``; linear between 1.15 and 1.5. ``B_p = c' f_pb,eff / w``,
    ``B_f = c' f_falpha,eff / w``, ``B_k = |1 - c' C_a / w|``; N_S = 0.85 or
    ``0.5 + 0.35 sqrt(w / 100)`` below 100 N/mm; C_v from Table 8 by eps_gamma.

    >>> round(float(dynamic_factor(0.0396, 1273.5, 12.37, 8.65, 11.6, 70.0, 2.632)), 4)
    1.0033
    """
    n, w, c, eg = resonance_ratio, line_load, c_prime, eps_gamma
    f_pb, f_f, c_a = f_pb_eff, f_f_eff, tip_relief
    xp = of(n, w, c, eg, f_pb, f_f, c_a)
    if xp is np:
        n, w, c, eg, f_pb, f_f, c_a = (np.asarray(v, float) for v in (n, w, c, eg, f_pb, f_f, c_a))
    bp = c * f_pb / w
    bf = c * f_f / w
    bk = xp.abs(1.0 - c * c_a / w)
    low = eg <= 2.0
    egx = _where(low, 3.0, eg)  # keeps the eps_gamma > 2 branch finite where unused
    cv2 = _where(low, 0.34, 0.57 / (egx - 0.3))
    cv3 = _where(low, 0.23, 0.096 / (egx - 1.56))
    ns = _where(w < 100.0, 0.5 + 0.35 * xp.sqrt(xp.maximum(w, 0.0) / 100.0), 0.85)
    sub = n * (_CV1 * bp + cv2 * bf + cv3 * bk) + 1.0
    if xp is np and not np.any(n > ns):  # every pair sub-critical
        return _out(sub)
    shape = () if xp is not np else np.broadcast_shapes(
        *(np.shape(v) for v in (n, bp, bf, bk, eg, cv2, sub)))  # fmt: skip
    over = n > ns if shape else None
    # one pair, or many in them (the share of over's, which broadcasts to the rest uniformly)
    if not shape or 8 * np.count_nonzero(over) > np.size(over):
        return _out(_where(n <= ns, sub, _resonant(n, bp, bf, bk, eg, low, egx, cv2, xp)))
    # the resonance ranges only where a pair is in them (a few of a sweep's pairs)
    k = np.array(np.broadcast_to(sub, shape))
    at = np.nonzero(np.broadcast_to(over, shape))
    k[at] = _resonant(*(np.broadcast_to(v, shape)[at] for v in (n, bp, bf, bk, eg, low, egx, cv2)),
                      np)  # fmt: skip
    return _out(k)


_CV1, _CV5 = 0.32, 0.47  # ISO 6336-1 Table 8, for every eps_gamma


def _resonant(n, bp, bf, bk, eg, low, egx, cv2, xp):
    """K_v above the sub-critical range (N > N_S): the main resonance up to 1.15, the
    super-critical range from 1.5, linear between."""
    cv4 = _where(low, 0.90, (0.57 - 0.05 * egx) / (egx - 1.44))
    cv6 = _where(low, 0.47, 0.12 / (egx - 1.74))
    cv7 = _where(eg <= 1.5, 0.75, _where(eg <= 2.5, 0.125 * xp.sin(xp.pi * (eg - 2.0)) + 0.875,
                                             1.0))  # fmt: skip
    main = _CV1 * bp + cv2 * bf + cv4 * bk + 1.0
    sup = _CV5 * bp + cv6 * bf + cv7
    between = sup + (main - sup) * (1.5 - n) / 0.35
    return _where(n <= 1.15, main, _where(n < 1.5, between, sup))


# --- face and transverse load factors -----------------------------------------------------------
def face_load_factor(misalignment, c_gamma_beta, line_load):
    """K_Hbeta by method C (ISO 6336-1 §7.6) from the effective misalignment F_betay (um),
    c_gamma_beta and the line load F_m / b (N/mm): ``1 + F_betay c_gamma_beta / (2 F_m/b)``
    while that is <= 2, else ``sqrt(2 F_betay c_gamma_beta / (F_m/b))``.

    >>> round(float(face_load_factor(10.0, 14.845, 1500.0)), 4)
    1.0495
    """
    f, c, w = misalignment, c_gamma_beta, line_load
    xp = of(f, c, w)
    if xp is np:
        f, c, w = (np.asarray(v, float) for v in (f, c, w))
    k = f * c / (2.0 * w)
    return _out(_where(k <= 1.0, 1.0 + k, xp.sqrt(4.0 * xp.maximum(k, 0.0))))


def face_load_factor_root(k_hbeta, face_width, tooth_height):
    """K_Fbeta = K_Hbeta^N_F, N_F = (b/h)^2 / (1 + b/h + (b/h)^2) with b/h >= 3 (ISO 6336-1 §7.8).

    >>> round(float(face_load_factor_root(1.16, 100.0, 19.2)), 4)   # ISO/TR 6336-30: 1.12803
    1.1284
    """
    k, b, h = k_hbeta, face_width, tooth_height
    xp = of(k, b, h)
    if xp is np:
        k, b, h = (np.asarray(v, float) for v in (k, b, h))
    bh = xp.maximum(b / h, 3.0)
    nf = bh * bh / (1.0 + bh + bh * bh)
    return _out(xp.power(k, nf))


def transverse_load_factors(c_gamma_alpha, f_pb, y_alpha, line_load_h, eps_alpha, eps_gamma,
                            z_eps):  # fmt: skip
    """``(K_Halpha, K_Falpha)`` by method B (ISO 6336-1 §8.3): with
    ``q = c_gamma_alpha (f_pb - y_alpha) / (F_tH / b)``, ``eps_gamma / 2 (0.9 + 0.4 q)`` for
    eps_gamma <= 2, else ``0.9 + 0.4 sqrt(2 (eps_gamma - 1)/eps_gamma) q``; at least 1 and at
    most ``eps_gamma / (eps_alpha Z_eps^2)`` (contact) and ``eps_gamma / (0.25 eps_alpha +
    0.75)`` (root). ``line_load_h`` is F_tH / b = F_t K_gamma K_A K_v K_Hbeta / b.
    """
    c, y, w, ea, eg, ze = c_gamma_alpha, y_alpha, line_load_h, eps_alpha, eps_gamma, z_eps
    xp = of(c, f_pb, y, w, ea, eg, ze)
    if xp is np:
        c, f_pb, y, w, ea, eg, ze = (np.asarray(v, float) for v in (c, f_pb, y, w, ea, eg, ze))
    q = c * (f_pb - y)
    q = q / w
    low = eg / 2.0 * (0.9 + 0.4 * q)
    high = 0.9 + 0.4 * xp.sqrt(2.0 * xp.maximum(eg - 1.0, 0.0) / eg) * q
    k = xp.maximum(_where(eg <= 2.0, low, high), 1.0)
    kh = xp.minimum(k, eg / (ea * ze**2))
    kf = xp.minimum(k, eg / (0.25 * ea + 0.75))
    return _out(kh), _out(kf)


# --- running-in (ISO 6336-1 §8.3.3 y_alpha, §7.6 y_beta) --------------------------------------
def _running_in(deviation, code, sigma_hlim, v, hard, soft, grey, limits):
    """Running-in allowance of one gear: hardened steels ``hard[0] d`` up to ``hard[1]`` um;
    grey cast iron ``grey d`` (limits[2:] above 5 and 10 m/s); others ``soft / sigma_Hlim d``
    (limits[:2] / sigma_Hlim above 5 and 10 m/s)."""
    s, d = sigma_hlim, deviation
    xp = of(s, d, v)
    if xp is np:
        s, d = np.asarray(s, float), np.asarray(d, float)
    if HARDENED[code]:
        return xp.minimum(hard[0] * d, hard[1])
    if GREY_IRON[code]:
        cap = _where(v > 10.0, limits[3], _where(v > 5.0, limits[2], np.inf))
        return xp.minimum(grey * d, cap)
    cap = _where(v > 10.0, limits[1] / s, _where(v > 5.0, limits[0] / s, np.inf))
    return xp.minimum(soft / s * d, cap)


def profile_running_in(deviation, code, sigma_hlim, v):
    """y_alpha (um), the running-in allowance of a pitch or profile deviation (ISO 6336-1
    §8.3.3) for one gear of material group ``code`` (an int,
    :func:`gears.rating.materials.kind_code`) at sigma_Hlim (MPa) and pitch-line speed v (m/s).

    >>> round(float(profile_running_in(10.0, 4, 1500.0, 2.0)), 3)   # hardened: 0.075 f_pb
    0.75
    """
    return _running_in(deviation, code, sigma_hlim, v, (0.075, 3.0), 160.0, 0.275,
                       (12800, 6400, 22, 11))  # fmt: skip


def helix_running_in(deviation, code, sigma_hlim, v):
    """y_beta (um), the running-in allowance of the misalignment F_betax (ISO 6336-1 §7.6), as
    :func:`profile_running_in`.

    >>> round(float(helix_running_in(10.0, 1, 800.0, 2.0)), 3)   # through-hardened: 320/s F
    4.0
    """
    return _running_in(deviation, code, sigma_hlim, v, (0.15, 6.0), 320.0, 0.55,
                       (25600, 12800, 45, 22))  # fmt: skip
