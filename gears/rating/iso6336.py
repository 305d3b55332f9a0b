"""Layer 4, load capacity: ISO 6336 method B pitting and tooth-root bending, vectorised.

Every factor of ISO 6336-1 (load factors), ISO 6336-2 (pitting) and ISO 6336-3 (bending) is a
numpy function over arrays (broadcasting), and :func:`rate_pairs` rates 10^6 pairs at once the
way :func:`gears.meshing.pair_geometry` computes their geometry; ``GearPair.rating`` (a
:class:`gears.rating.capacity.Rating`) is a thin view over it for one pair.

The calculation (references are to the clauses of ISO 6336-1/-2/-3:2006 and the reference card
``rating.md``; ISO/TR 6336-30 Example 1 is the test):

* nominal load ``F_t = 2000 T1 / d1`` (N; T1 in N m, d1 in mm), pitch-line speed
  ``v = pi d1 n1 / 60000`` (m/s, n1 the speed of gear 1 relative to its carrier);
* single and mesh stiffness by method B (ISO 6336-1 §9): ``q'`` polynomial in ``z_n`` and ``x``,
  ``c' = c'_th C_M C_R C_B cos beta`` (C_M = 0.8, C_R = 1 for solid gears, C_B from the basic
  rack), ``c_gamma_alpha = c'(0.75 eps_alpha + 0.25)``, ``c_gamma_beta = 0.85 c_gamma_alpha``;
* dynamic factor K_v by method B (§6.5): the resonance ratio ``N = n1 / n_E1`` from the reduced
  mass of solid gears, then the sub-critical, main-resonance, intermediate or super-critical
  formula with ``B_p``, ``B_f``, ``B_k`` from the ISO 1328-1 deviations of the accuracy grade;
* face load factor K_Hbeta by method C (§7.6) from the effective misalignment
  ``F_betay = F_betax - y_beta`` (``F_betax = 1.33 f_sh + f_ma``, ``f_sh`` of a pinion shaft
  without bending influence, ``f_ma = f_Hbeta``) or given; ``K_Fbeta = K_Hbeta^N_F`` (§7.8);
* transverse load factors K_Halpha, K_Falpha by method B (§8.3);
* pitting (ISO 6336-2): ``sigma_H0 = Z_H Z_E Z_eps Z_beta sqrt(F_t (u + 1)/(d1 b u))`` (u < 0
  for internal pairs), ``sigma_H = Z_B,D sigma_H0 sqrt(K_gamma K_A K_v K_Hbeta K_Halpha)``,
  ``sigma_HP = sigma_Hlim Z_NT Z_L Z_v Z_R Z_W Z_X`` (for S_Hmin = 1),
  ``S_H = sigma_HP / sigma_H``;
* bending (ISO 6336-3): ``sigma_F0 = F_t/(b m_n) Y_F Y_S Y_beta Y_B Y_DT``,
  ``sigma_F = sigma_F0 K_gamma K_A K_v K_Fbeta K_Falpha``,
  ``sigma_FP = sigma_Flim Y_ST Y_NT Y_deltarelT Y_RrelT Y_X Y_M`` (S_Fmin = 1),
  ``S_F = sigma_FP / sigma_F``; Y_F and Y_S by method B from the 30 deg tangent on the root
  fillet of the virtual spur gear (:func:`root_form`), or measured on the real outline
  (:mod:`gears.rating.root`) and passed in.

Choices this module makes where the standard leaves one (each named where it is used): the
ISO 1328-1:1995 deviations are evaluated at the gear's own module, diameter and face width,
unrounded; the reduced mass takes solid gears; an internal gear's mass counts as infinite (the
ring is held by the housing or carrier); the internal gear's Y_F and Y_S use the standard's rack
approximation (ISO 6336-3 §6.3) unless measured; an idler's Y_M is 0.7 (the reversed-bending
rule for idler gears, ISO 6336-5 §5.2). AGMA 2101, scuffing, micropitting and load spectra are
not covered.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from gears.errors import GearError
from gears.geometry import root_diameter, tip_diameter, tooth_thickness
from gears.involute import inv
from gears.meshing import _CHUNK, _pool, contact_ratio, default_threads, pair_geometry
from gears.rating.materials import (
    KINDS,
    Material,
    bending_life_factor,
    material,
    pitting_life_factor,
)

__all__ = [
    "FACTORS",
    "QUANTITIES",
    "REASONS",
    "PairRatings",
    "contact_ratio_factor",
    "dynamic_factor",
    "elasticity_factor",
    "face_load_factor",
    "form_factors",
    "internal_root_form",
    "load_point",
    "lubrication_factors",
    "mesh_stiffness",
    "rate_pairs",
    "root_form",
    "roughness_factor",
    "single_pair_factors",
    "single_stiffness",
    "tolerances",
    "transverse_load_factors",
    "zone_factor",
]

# --- the factors and their clauses: (symbol, per gear, what, clause) --------------------------
#: Every factor :func:`rate_pairs` reports and accepts as an override (``K_v=1.0``,
#: ``Y_F=(2.1, 2.2)``): ISO symbol in ASCII, whether it has one value per gear, what it is, where
#: it comes from.
FACTORS = (
    ("K_A", False, "application factor (given)", "ISO 6336-1 §6.2"),
    ("K_gamma", False, "mesh load factor (planets)", "AGMA 6123 table"),
    ("K_v", False, "dynamic factor, method B", "ISO 6336-1 §6.5"),
    ("K_Hbeta", False, "face load factor, contact, method C", "ISO 6336-1 §7.6"),
    ("K_Fbeta", False, "face load factor, root", "ISO 6336-1 §7.8"),
    ("K_Halpha", False, "transverse load factor, contact, B", "ISO 6336-1 §8.3"),
    ("K_Falpha", False, "transverse load factor, root, B", "ISO 6336-1 §8.3"),
    ("c'", False, "single stiffness, N/(mm um), B", "ISO 6336-1 §9.3"),
    ("c_gamma_alpha", False, "mesh stiffness (K_v, K_alpha)", "ISO 6336-1 §9.4"),
    ("c_gamma_beta", False, "mesh stiffness (K_beta)", "ISO 6336-1 §9.4"),
    ("Z_H", False, "zone factor", "ISO 6336-2 §6.1"),
    ("Z_E", False, "elasticity factor, sqrt(MPa)", "ISO 6336-2 §7"),
    ("Z_eps", False, "contact ratio factor", "ISO 6336-2 §8"),
    ("Z_beta", False, "helix angle factor", "ISO 6336-2 §9"),
    ("Z_B", False, "single pair contact factor, gear 1", "ISO 6336-2 §6.2"),
    ("Z_D", False, "single pair contact factor, gear 2", "ISO 6336-2 §6.2"),
    ("Z_L", False, "lubricant factor", "ISO 6336-2 §11"),
    ("Z_v", False, "velocity factor", "ISO 6336-2 §11"),
    ("Z_R", False, "roughness factor", "ISO 6336-2 §11"),
    ("Z_W", True, "work hardening factor", "ISO 6336-2 §12"),
    ("Z_X", False, "size factor, contact", "ISO 6336-2 §13"),
    ("Z_NT", True, "life factor, contact", "ISO 6336-2 §10"),
    ("Y_F", True, "tooth form factor, method B", "ISO 6336-3 §6.2"),
    ("Y_S", True, "stress correction factor, method B", "ISO 6336-3 §7.2"),
    ("Y_beta", False, "helix angle factor, root", "ISO 6336-3 §8"),
    ("Y_B", True, "rim thickness factor (solid)", "ISO 6336-3 §9"),
    ("Y_DT", False, "deep tooth factor", "ISO 6336-3 §10"),
    ("Y_ST", False, "stress correction of test gears", "ISO 6336-3 §5"),
    ("Y_NT", True, "life factor, root", "ISO 6336-3 §12"),
    ("Y_deltarelT", True, "relative notch sensitivity factor", "ISO 6336-3 §13"),
    ("Y_RrelT", True, "relative surface factor", "ISO 6336-3 §14"),
    ("Y_X", True, "size factor, root", "ISO 6336-3 §15"),
    ("Y_M", True, "mean stress factor (idler 0.7)", "ISO 6336-5 §5.2"),
)

#: Other quantities :func:`rate_pairs` reports: (name, per gear, what, unit).
QUANTITIES = (
    ("F_t", False, "nominal tangential load", "N"),
    ("v", False, "pitch-line speed (relative to the carrier)", "m/s"),
    ("u", False, "gear ratio z2/z1 (< 0 internal)", ""),
    ("N", False, "resonance ratio n1 / n_E1 (K_v)", ""),
    ("eps_alpha", False, "transverse contact ratio", ""),
    ("eps_beta", False, "overlap ratio", ""),
    ("eps_gamma", False, "total contact ratio", ""),
    ("N_L", True, "load cycles over the life", ""),
    ("s_Fn", True, "root chord at the tangent points", "mm"),
    ("rho_F", True, "root fillet radius there", "mm"),
    ("h_Fe", True, "bending moment arm", "mm"),
    ("alpha_Fen", True, "load direction angle", "deg"),
    ("q_s", True, "notch parameter s_Fn / (2 rho_F)", ""),
)

#: Why a rating cannot be given (the ``reason`` code of :class:`PairRatings`; 0 = rated).
REASONS = (
    "",
    "the transverse contact ratio is below 1: the teeth do not mesh continuously (ISO 6336 "
    "needs eps_alpha >= 1)",
    "a tip circle lies inside its base circle: there is no involute flank to load",
    "a tooth comes to a point below its tip circle: method B's Y_F needs a tooth with a tip land",
    "the outer point of single contact lies inside the base circle of the virtual gear: method "
    "B's Y_F does not apply",
    "the 30 deg tangent does not meet a root fillet that carries the tooth (s_Fn <= 0 or "
    "h_Fe <= 0, or ISO 6336-3's theta iteration has no solution): method B's Y_F does not apply",
    "q_s = s_Fn / (2 rho_F) lies outside 1 <= q_s < 8, the range of Y_S by method B",
    "an inner point of single contact lies inside a base circle (the mesh interferes): Z_B or "
    "Z_D does not apply",
)

_FIELDS = ["S_H1", "S_H2", "S_F1", "S_F2", "sigma_H0", "sigma_H1", "sigma_H2", "sigma_HP1",
           "sigma_HP2", "sigma_F01", "sigma_F02", "sigma_F1", "sigma_F2", "sigma_FP1",
           "sigma_FP2"]  # fmt: skip
for _name, _per, *_ in (*FACTORS, *QUANTITIES):
    _FIELDS += [f"{_name}1", f"{_name}2"] if _per else [_name]
_FIELDS = [f.replace("'", "_prime") for f in _FIELDS] + ["valid", "reason"]


class PairRatings(NamedTuple):
    S_H1: np.ndarray
    S_H2: np.ndarray
    S_F1: np.ndarray
    S_F2: np.ndarray
    sigma_H0: np.ndarray
    sigma_H1: np.ndarray
    sigma_H2: np.ndarray
    sigma_HP1: np.ndarray
    sigma_HP2: np.ndarray
    sigma_F01: np.ndarray
    sigma_F02: np.ndarray
    sigma_F1: np.ndarray
    sigma_F2: np.ndarray
    sigma_FP1: np.ndarray
    sigma_FP2: np.ndarray
    K_A: np.ndarray
    K_gamma: np.ndarray
    K_v: np.ndarray
    K_Hbeta: np.ndarray
    K_Fbeta: np.ndarray
    K_Halpha: np.ndarray
    K_Falpha: np.ndarray
    c_prime: np.ndarray
    c_gamma_alpha: np.ndarray
    c_gamma_beta: np.ndarray
    Z_H: np.ndarray
    Z_E: np.ndarray
    Z_eps: np.ndarray
    Z_beta: np.ndarray
    Z_B: np.ndarray
    Z_D: np.ndarray
    Z_L: np.ndarray
    Z_v: np.ndarray
    Z_R: np.ndarray
    Z_W1: np.ndarray
    Z_W2: np.ndarray
    Z_X: np.ndarray
    Z_NT1: np.ndarray
    Z_NT2: np.ndarray
    Y_F1: np.ndarray
    Y_F2: np.ndarray
    Y_S1: np.ndarray
    Y_S2: np.ndarray
    Y_beta: np.ndarray
    Y_B1: np.ndarray
    Y_B2: np.ndarray
    Y_DT: np.ndarray
    Y_ST: np.ndarray
    Y_NT1: np.ndarray
    Y_NT2: np.ndarray
    Y_deltarelT1: np.ndarray
    Y_deltarelT2: np.ndarray
    Y_RrelT1: np.ndarray
    Y_RrelT2: np.ndarray
    Y_X1: np.ndarray
    Y_X2: np.ndarray
    Y_M1: np.ndarray
    Y_M2: np.ndarray
    F_t: np.ndarray
    v: np.ndarray
    u: np.ndarray
    N: np.ndarray
    eps_alpha: np.ndarray
    eps_beta: np.ndarray
    eps_gamma: np.ndarray
    N_L1: np.ndarray
    N_L2: np.ndarray
    s_Fn1: np.ndarray
    s_Fn2: np.ndarray
    rho_F1: np.ndarray
    rho_F2: np.ndarray
    h_Fe1: np.ndarray
    h_Fe2: np.ndarray
    alpha_Fen1: np.ndarray
    alpha_Fen2: np.ndarray
    q_s1: np.ndarray
    q_s2: np.ndarray
    valid: np.ndarray
    reason: np.ndarray


PairRatings.__doc__ = """Arrays returned by :func:`rate_pairs`, one value per pair.

``S_H1, S_H2`` and ``S_F1, S_F2`` are the safety factors against pitting and tooth-root
breakage of gear 1 and gear 2; ``sigma_*`` the stresses in MPa (``sigma_HP``, ``sigma_FP`` for
minimum safeties of 1); then every factor of :data:`FACTORS` (``c'`` as ``c_prime``, per-gear
factors with suffix 1 and 2) and every quantity of :data:`QUANTITIES` (``alpha_Fen`` in
degrees). ``valid`` is False where no rating exists (with ``errors="mask"``), ``reason`` the
index into :data:`REASONS`; such rows carry NaN stresses and factors and zero safeties.
"""
assert list(PairRatings._fields) == _FIELDS, "PairRatings fields out of step with FACTORS"
_RESULTS = tuple(_FIELDS[:-2])


def _out(a):
    a = np.asarray(a)
    return a[()] if a.ndim == 0 else a


def _where(cond, a, b):
    """``np.where`` that keeps one pair's numbers numpy scalars (a Python branch: ten times
    faster than 0-d arrays, which is most of rating one pair)."""
    if _scalar(cond) and _scalar(a) and _scalar(b):
        return a if cond else b
    return np.where(cond, a, b)


def _scalar(v) -> bool:
    """Whether ``v`` is one number (``np.ndim(v) == 0`` without its cost on numbers)."""
    if type(v) is np.ndarray:
        return v.ndim == 0
    return isinstance(v, (float, int, np.generic)) or np.ndim(v) == 0


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
    m, d, b = (np.asarray(v, float) for v in (module, diameter, face_width))
    step = np.exp2((np.asarray(quality, float) - 5.0) / 2.0)
    sd = np.sqrt(d)
    f_pt = (0.3 * (m + 0.4 * sd) + 4.0) * step
    f_f = (2.5 * np.sqrt(m) + 0.17 * sd + 0.5) * step
    f_h = (0.07 * sd + 0.45 * np.sqrt(b) + 3.0) * step
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
    zn1 = np.asarray(zn1, float)
    inv2 = _where(np.asarray(internal, bool), 0.0, 1.0 / np.asarray(zn2, float))
    x1, x2 = np.asarray(x1, float), np.asarray(x2, float)
    c1, c2, c3, c4, c5, c6, c7, c8, c9 = _Q
    q = c1 + c2 / zn1 + c3 * inv2 + c4 * x1 + c5 * x1 / zn1 + c6 * x2 + c7 * x2 * inv2
    q = q + c8 * x1 * x1 + c9 * x2 * x2
    c_b = (1.0 + 0.5 * (1.2 - np.asarray(dedendum, float))) * (
        1.0 - 0.02 * (20.0 - np.asarray(pressure_angle, float))
    )
    c = 0.8 * c_b * np.cos(np.radians(helix_angle)) / q
    if line_load is not None:
        w = np.asarray(line_load, float)
        c = c * _where(w < 100.0, np.sqrt(np.sqrt(np.maximum(w, 0.0) / 100.0)), 1.0)
    return _out(c)


def mesh_stiffness(c_prime, eps_alpha):
    """``(c_gamma_alpha, c_gamma_beta)``: c'(0.75 eps_alpha + 0.25) and 0.85 of it
    (ISO 6336-1 §9.4).

    >>> [round(float(c), 2) for c in mesh_stiffness(12.37047, 1.54909)]   # TR: 17.46, 14.85
    [17.46, 14.85]
    """
    c = np.asarray(c_prime, float) * (0.75 * np.asarray(eps_alpha, float) + 0.25)
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
    n = np.asarray(resonance_ratio, float)
    w = np.asarray(line_load, float)
    c = np.asarray(c_prime, float)
    eg = np.asarray(eps_gamma, float)
    bp = c * np.asarray(f_pb_eff, float) / w
    bf = c * np.asarray(f_f_eff, float) / w
    bk = np.abs(1.0 - c * np.asarray(tip_relief, float) / w)
    low = eg <= 2.0
    egx = _where(low, 3.0, eg)  # keeps the eps_gamma > 2 branch finite where unused
    cv1 = 0.32
    cv2 = _where(low, 0.34, 0.57 / (egx - 0.3))
    cv3 = _where(low, 0.23, 0.096 / (egx - 1.56))
    cv4 = _where(low, 0.90, (0.57 - 0.05 * egx) / (egx - 1.44))
    cv5 = 0.47
    cv6 = _where(low, 0.47, 0.12 / (egx - 1.74))
    cv7 = _where(eg <= 1.5, 0.75, _where(eg <= 2.5, 0.125 * np.sin(np.pi * (eg - 2.0)) + 0.875,
                                             1.0))  # fmt: skip
    ns = _where(w < 100.0, 0.5 + 0.35 * np.sqrt(np.maximum(w, 0.0) / 100.0), 0.85)
    sub = n * (cv1 * bp + cv2 * bf + cv3 * bk) + 1.0
    main = cv1 * bp + cv2 * bf + cv4 * bk + 1.0
    sup = cv5 * bp + cv6 * bf + cv7
    between = sup + (main - sup) * (1.5 - n) / 0.35
    k = _where(n <= ns, sub, _where(n <= 1.15, main, _where(n < 1.5, between, sup)))
    return _out(k)


# --- face and transverse load factors -----------------------------------------------------------
def face_load_factor(misalignment, c_gamma_beta, line_load):
    """K_Hbeta by method C (ISO 6336-1 §7.6) from the effective misalignment F_betay (um),
    c_gamma_beta and the line load F_m / b (N/mm): ``1 + F_betay c_gamma_beta / (2 F_m/b)``
    while that is <= 2, else ``sqrt(2 F_betay c_gamma_beta / (F_m/b))``.

    >>> round(float(face_load_factor(10.0, 14.845, 1500.0)), 4)
    1.0495
    """
    k = np.asarray(misalignment, float) * np.asarray(c_gamma_beta, float)
    k = k / (2.0 * np.asarray(line_load, float))
    return _out(_where(k <= 1.0, 1.0 + k, np.sqrt(4.0 * np.maximum(k, 0.0))))


def face_load_factor_root(k_hbeta, face_width, tooth_height):
    """K_Fbeta = K_Hbeta^N_F, N_F = (b/h)^2 / (1 + b/h + (b/h)^2) with b/h >= 3 (ISO 6336-1 §7.8).

    >>> round(float(face_load_factor_root(1.16, 100.0, 19.2)), 4)   # ISO/TR 6336-30: 1.12803
    1.1284
    """
    bh = np.maximum(np.asarray(face_width, float) / np.asarray(tooth_height, float), 3.0)
    nf = bh * bh / (1.0 + bh + bh * bh)
    return _out(np.asarray(k_hbeta, float) ** nf)


def transverse_load_factors(c_gamma_alpha, f_pb, y_alpha, line_load_h, eps_alpha, eps_gamma,
                            z_eps):  # fmt: skip
    """``(K_Halpha, K_Falpha)`` by method B (ISO 6336-1 §8.3): with
    ``q = c_gamma_alpha (f_pb - y_alpha) / (F_tH / b)``, ``eps_gamma / 2 (0.9 + 0.4 q)`` for
    eps_gamma <= 2, else ``0.9 + 0.4 sqrt(2 (eps_gamma - 1)/eps_gamma) q``; at least 1 and at
    most ``eps_gamma / (eps_alpha Z_eps^2)`` (contact) and ``eps_gamma / (0.25 eps_alpha +
    0.75)`` (root). ``line_load_h`` is F_tH / b = F_t K_gamma K_A K_v K_Hbeta / b.
    """
    q = np.asarray(c_gamma_alpha, float) * (np.asarray(f_pb, float) - np.asarray(y_alpha, float))
    q = q / np.asarray(line_load_h, float)
    ea, eg = np.asarray(eps_alpha, float), np.asarray(eps_gamma, float)
    low = eg / 2.0 * (0.9 + 0.4 * q)
    high = 0.9 + 0.4 * np.sqrt(2.0 * np.maximum(eg - 1.0, 0.0) / eg) * q
    k = np.maximum(_where(eg <= 2.0, low, high), 1.0)
    kh = np.minimum(k, eg / (ea * np.asarray(z_eps, float) ** 2))
    kf = np.minimum(k, eg / (0.25 * ea + 0.75))
    return _out(kh), _out(kf)


# --- pitting factors --------------------------------------------------------------------------
def zone_factor(alpha_t, alpha_wt, beta_b):
    """Z_H = sqrt(2 cos beta_b cos alpha_wt / (cos^2 alpha_t sin alpha_wt)) (ISO 6336-2 §6.1;
    angles in degrees).

    >>> round(float(zone_factor(20.0, 20.0, 0.0)), 4)          # spur, no shift: 2.4946
    2.4946
    """
    at, awt, bb = (np.radians(np.asarray(a, float)) for a in (alpha_t, alpha_wt, beta_b))
    return _out(np.sqrt(2.0 * np.cos(bb) * np.cos(awt) / (np.cos(at) ** 2 * np.sin(awt))))


def elasticity_factor(e1, nu1, e2, nu2):
    """Z_E = sqrt(1 / (pi ((1 - nu1^2)/E1 + (1 - nu2^2)/E2))), sqrt(MPa) (ISO 6336-2 §7).

    >>> round(float(elasticity_factor(206000, 0.3, 206000, 0.3)), 2)   # steel: 189.81
    189.81
    """
    e1, nu1, e2, nu2 = (np.asarray(v, float) for v in (e1, nu1, e2, nu2))
    return _out(np.sqrt(1.0 / (np.pi * ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2))))


def contact_ratio_factor(eps_alpha, eps_beta):
    """Z_eps (ISO 6336-2 §8): ``sqrt((4 - eps_alpha)/3 (1 - eps_beta) + eps_beta/eps_alpha)``
    for eps_beta < 1 (``sqrt((4 - eps_alpha)/3)`` for spur gears), ``sqrt(1/eps_alpha)`` for
    eps_beta >= 1.

    >>> round(float(contact_ratio_factor(1.5491, 1.083)), 4)   # ISO/TR 6336-30 Ex. 1: 0.803
    0.8035
    """
    ea = np.asarray(eps_alpha, float)
    eb = np.minimum(np.asarray(eps_beta, float), 1.0)
    return _out(np.sqrt((4.0 - ea) / 3.0 * (1.0 - eb) + eb / ea))


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
    s = _where(np.asarray(internal, bool), -1.0, 1.0)
    z1, z2 = np.asarray(z1, float), np.asarray(z2, float)
    l1 = np.sqrt(np.maximum((np.asarray(da1) / db1) ** 2 - 1.0, 0.0))
    l2 = np.sqrt(np.maximum((np.asarray(da2) / db2) ** 2 - 1.0, 0.0))
    ea = np.asarray(eps_alpha, float)
    tw = np.tan(np.radians(alpha_wt))
    with np.errstate(invalid="ignore", divide="ignore"):
        m1 = tw / np.sqrt((l1 - 2 * np.pi / z1) * (l2 - s * (ea - 1.0) * 2 * np.pi / z2))
        m2 = tw / np.sqrt((l2 - s * 2 * np.pi / z2) * (l1 - (ea - 1.0) * 2 * np.pi / z1))
    eb = np.minimum(np.asarray(eps_beta, float), 1.0)
    # eps_beta >= 1: 1 whatever M (the single-contact points do not matter then); else NaN
    # where M does not exist (the point lies inside a base circle: the mesh interferes)
    zb = _where(eb >= 1.0, 1.0, np.maximum(1.0, m1 - eb * (m1 - 1.0)))
    zd = _where(s < 0, 1.0, _where(eb >= 1.0, 1.0, np.maximum(1.0, m2 - eb * (m2 - 1.0))))
    zb = _where(np.isnan(m1) & (eb < 1.0), np.nan, zb)
    zd = _where(np.isnan(m2) & (eb < 1.0) & (s > 0), np.nan, zd)
    return _out(zb), _out(zd)


def _c_zl(sigma_hlim):
    s = np.asarray(sigma_hlim, float)
    return _where(s < 850.0, 0.83, _where(s < 1200.0, s / 4375.0 + 0.6357, 0.91))


def lubrication_factors(sigma_hlim, oil_viscosity, speed):
    """``(Z_L, Z_v)`` (ISO 6336-2 §11, method B): ``Z_L = C_ZL + 4 (1 - C_ZL)/(1.2 + 134 /
    nu_40)^2``, ``Z_v = C_Zv + 2 (1 - C_Zv) / sqrt(0.8 + 32 / v)``, C_ZL from sigma_Hlim (the
    smaller of the pair), C_Zv = C_ZL + 0.02; nu_40 in mm^2/s, v in m/s.

    >>> [round(float(f), 5) for f in lubrication_factors(1500, 320, 2.664)]   # TR: 1.04739, 0.96911
    [1.04739, 0.96911]
    """
    czl = _c_zl(sigma_hlim)
    zl = czl + 4.0 * (1.0 - czl) / (1.2 + 134.0 / np.asarray(oil_viscosity, float)) ** 2
    czv = czl + 0.02
    zv = czv + 2.0 * (1.0 - czv) / np.sqrt(0.8 + 32.0 / np.asarray(speed, float))
    return _out(zl), _out(zv)


def roughness_factor(sigma_hlim, rz, rho_red):
    """Z_R = (3 / R_z10)^C_ZR, R_z10 = R_z (10 / rho_red)^(1/3) (ISO 6336-2 §11; R_z the mean
    peak-to-valley roughness of the flanks in um, rho_red the relative radius of curvature at the
    pitch point in mm); C_ZR = 0.15 below 850 MPa, 0.32 - 0.0002 sigma_Hlim to 1200, then 0.08.

    >>> round(float(roughness_factor(1500, 6.0, 21.8)), 3)   # ISO/TR 6336-30 Ex. 1: 0.96599
    0.966
    """
    s = np.asarray(sigma_hlim, float)
    czr = _where(s < 850.0, 0.15, _where(s < 1200.0, 0.32 - 0.0002 * s, 0.08))
    rz10 = np.asarray(rz, float) * np.cbrt(10.0 / np.asarray(rho_red, float))
    return _out((3.0 / rz10) ** czr)


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
    an = np.radians(pressure_angle)
    beta = np.radians(np.abs(helix_angle))
    at = np.arctan(np.tan(an) / np.cos(beta))
    cbb2 = np.cos(np.arctan(np.tan(beta) * np.cos(at))) ** 2
    m = np.asarray(module, float)
    zn = np.asarray(z, float) / (cbb2 * np.cos(beta))
    dn = m * zn
    dbn = dn * np.cos(an)
    dan = dn + np.asarray(tip_diameter_, float) - np.asarray(reference_diameter, float)
    ean = np.asarray(eps_alpha, float) / cbb2
    s = _where(np.asarray(internal, bool), -1.0, 1.0)
    la = np.sqrt(np.maximum(dan * dan - dbn * dbn, 0.0)) / 2.0
    le = la - s * np.pi * m * np.cos(an) * (ean - 1.0)
    le = _where((dan >= dbn) & (le >= 0.0), le, np.nan)
    den = 2.0 * np.sqrt(le * le + dbn * dbn / 4.0)
    return _out(den), _out(np.arccos(dbn / den)), _out(zn), _out(dbn)


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
    m = np.asarray(module, float)
    zn = np.asarray(zn, float)
    x = np.asarray(profile_shift, float)
    an = np.radians(pressure_angle)
    hf, rho, spr = (np.asarray(v, float) for v in (dedendum, root_radius, protuberance))
    e = np.pi / 4 - hf * np.tan(an) + spr / np.cos(an) - (1.0 - np.sin(an)) * rho / np.cos(an)
    g = rho - hf + x
    h = 2.0 / zn * (np.pi / 2 - e) - np.pi / 3
    k = 2.0 * g / zn
    # theta - k tan theta + h = 0 by Newton's method from pi/6 (the standard iterates the fixed
    # point, a contraction on real teeth; six Newton steps from pi/6 reach 1e-15 from z_n = 5 to
    # 1000, x = -0.8 ... 1.5); where it has not converged (no real tooth) the root form is NaN
    theta = np.pi / 6 - (np.pi / 6 - k * math.tan(np.pi / 6) + h) / (1.0 - k * 4.0 / 3.0)
    for _ in range(5):
        ct = np.cos(theta)
        theta = theta - (theta - k * np.tan(theta) + h) / (1.0 - k / (ct * ct))
    theta = _where(np.abs(theta - k * np.tan(theta) + h) < 1e-9, theta, np.nan)
    ct = np.cos(theta)
    s_fn = m * (zn * np.sin(np.pi / 3 - theta) + np.sqrt(3.0) * (g / ct - rho))
    rho_f = m * (rho + 2.0 * g * g / (ct * (zn * ct * ct - 2.0 * g)))
    aen = np.asarray(alpha_en, float)
    gamma = (np.pi / 2 + 2.0 * x * np.tan(an)) / zn + inv(an) - inv(aen)
    afen = aen - gamma
    den = np.asarray(d_en, float)
    h_fe = m / 2 * ((np.cos(gamma) - np.sin(gamma) * np.tan(afen)) * den / m
                    - zn * np.cos(np.pi / 3 - theta) - g / ct + rho)  # fmt: skip
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
    m = np.asarray(module, float)
    an = np.radians(np.asarray(pressure_angle, float))
    hf, rho, spr = (np.asarray(v, float) for v in (dedendum, root_radius, protuberance))
    ta = np.tan(an)
    t = np.radians(60.0)
    u_c = m * (np.pi / 4 + (hf - rho) * ta + (rho - spr) / np.cos(an))
    s_fn = 2.0 * (u_c - rho * m * np.cos(t))
    h_l = (np.asarray(d_fn, float) - np.asarray(d_en, float)) / 2.0
    w_l = np.pi / 4 * m + (hf * m - h_l) * ta
    h_fe = h_l - w_l * ta - rho * m * (1.0 - np.sin(t))
    afen = np.broadcast_to(an, np.shape(h_fe)).astype(float)
    return _out(s_fn), _out(rho * m), _out(h_fe), _out(afen)


def form_factors(s_fn, rho_f, h_fe, alpha_fen, module, pressure_angle):
    """``(Y_F, Y_S, q_s)`` from the root form (ISO 6336-3 §6.2, §7.2):
    ``Y_F = 6 (h_Fe/m_n) cos alpha_Fen / ((s_Fn/m_n)^2 cos alpha_n)``,
    ``Y_S = (1.2 + 0.13 L) q_s^(1 / (1.21 + 2.3 / L))``, ``L = s_Fn / h_Fe``,
    ``q_s = s_Fn / (2 rho_F)`` (``alpha_fen`` in radians).
    """
    m = np.asarray(module, float)
    s, r, h = (np.asarray(v, float) for v in (s_fn, rho_f, h_fe))
    yf = 6.0 * (h / m) * np.cos(alpha_fen) / ((s / m) ** 2 * np.cos(np.radians(pressure_angle)))
    with np.errstate(divide="ignore", invalid="ignore"):
        big_l = s / h
        qs = s / (2.0 * r)
        ys = (1.2 + 0.13 * big_l) * qs ** (1.0 / (1.21 + 2.3 / big_l))
    return _out(yf), _out(ys), _out(qs)


# --- material-group tables (index = gears.rating.materials.KINDS)
# --------------------------------------
def _by_kind(mapping):
    return np.array([mapping[k] for k in KINDS])


_HARD = _by_kind({"St": 0, "V": 0, "GGG": 0, "GG": 0, "Eh": 1, "IF": 1, "NT": 1, "NV": 1})
_GREY = _by_kind({"St": 0, "V": 0, "GGG": 0, "GG": 1, "Eh": 0, "IF": 0, "NT": 0, "NV": 0})
# Y_RrelT classes (ISO 6336-3 §14): 0 V, GGG, Eh, IF; 1 St; 2 GG, NT, NV
_ROUGH = _by_kind({"St": 1, "V": 0, "GGG": 0, "GG": 2, "Eh": 0, "IF": 0, "NT": 2, "NV": 2})
# Y_X classes (ISO 6336-3 §15): 0 St, V, GGG; 1 Eh, IF, NT, NV; 2 GG
_SIZE = _by_kind({"St": 0, "V": 0, "GGG": 0, "GG": 2, "Eh": 1, "IF": 1, "NT": 1, "NV": 1})


def _running_in(deviation, code, sigma_hlim, v, hard, soft, grey, limits):
    """Running-in allowance of one gear (ISO 6336-1 §8.3.3 y_alpha, §7.6 y_beta): hardened
    steels ``hard[0] d`` up to ``hard[1]`` um; grey cast iron ``grey d`` (limits[2:] above 5 and
    10 m/s); others ``soft / sigma_Hlim d`` (limits[:2] / sigma_Hlim above 5 and 10 m/s)."""
    s = np.asarray(sigma_hlim, float)
    d = np.asarray(deviation, float)
    if _HARD[code]:
        return np.minimum(hard[0] * d, hard[1])
    if _GREY[code]:
        cap = _where(v > 10.0, limits[3], _where(v > 5.0, limits[2], np.inf))
        return np.minimum(grey * d, cap)
    cap = _where(v > 10.0, limits[1] / s, _where(v > 5.0, limits[0] / s, np.inf))
    return np.minimum(soft / s * d, cap)


def _y_alpha(deviation, code, sigma_hlim, v):
    return _running_in(deviation, code, sigma_hlim, v, (0.075, 3.0), 160.0, 0.275,
                       (12800, 6400, 22, 11))  # fmt: skip


def _y_beta(deviation, code, sigma_hlim, v):
    return _running_in(deviation, code, sigma_hlim, v, (0.15, 6.0), 320.0, 0.55,
                       (25600, 12800, 45, 22))  # fmt: skip


def _surface_factor(rz, code):
    """Y_RrelT of a material group (``code`` a Python int) at root roughness R_z (um)."""
    rz = np.asarray(rz, float)
    cls = _ROUGH[code]
    r1 = rz + 1.0
    if cls == 0:
        return _where(rz < 1.0, 1.120, 1.674 - 0.529 * r1**0.1)
    if cls == 1:
        return _where(rz < 1.0, 1.070, 5.306 - 4.203 * r1**0.01)
    return _where(rz < 1.0, 1.025, 4.299 - 3.259 * r1**0.0058)


def _size_factor(m, code):
    """Y_X of a material group (``code`` a Python int) at normal module m (mm)."""
    m = np.asarray(m, float)
    slope, top, floor_ = ((0.006, 30.0, 0.85), (0.01, 25.0, 0.8), (0.015, 25.0, 0.7))[_SIZE[code]]
    base = 1.0 + slope * 5.0  # the lines meet 1.0 at m = 5
    return _where(m <= 5.0, 1.0, _where(m < top, base - slope * m, floor_))


# --- input checking ---------------------------------------------------------------------------
def _number(name, value, low, high, low_open=True, high_open=True, integer=False):
    """``value`` as a float array, or a GearError naming the first bad entry and the range."""
    if type(value) is float or type(value) is int:  # the one-pair path: no array needed
        v = float(value)
        if (
            math.isfinite(v) and (v > low if low_open else v >= low)
            and (v < high if high_open else v <= high) and (not integer or v == round(v))
        ):  # fmt: skip
            return np.float64(v)
    try:
        a = np.asarray(value, float)
    except (TypeError, ValueError):
        raise GearError(f"{name} = {value!r}; valid is a number") from None
    if isinstance(value, bool | np.bool_) or a.dtype == object:
        raise GearError(f"{name} = {value!r}; valid is a number")
    ok = np.isfinite(a) & ((a > low) if low_open else (a >= low))
    ok &= (a < high) if high_open else (a <= high)
    if integer:
        ok &= a == np.round(a)
    if not np.all(ok):
        bad = np.ravel(a)[np.argmax(~np.ravel(ok))]
        where = "" if a.ndim == 0 else f" at row {int(np.argmax(~np.ravel(ok)))}"
        lo = f"{low:g} {'<' if low_open else '<='} "
        hi = f" {'<' if high_open else '<='} {high:g}"
        kind = "an integer " if integer else ""
        raise GearError(f"{name} = {float(bad):g}{where}; valid is {kind}{lo}{name}{hi}")
    return a


def _pair_of(name, value):
    """A per-gear value: a scalar/array for both gears or a pair ``(gear 1, gear 2)``."""
    if isinstance(value, tuple | list) and len(value) == 2:
        return value[0], value[1]
    if isinstance(value, tuple | list):
        raise GearError(f"{name} = {value!r}; give one value or a pair (gear 1, gear 2)")
    return value, value


_OVERRIDABLE = {f[0]: f[1] for f in FACTORS}


def _overrides(factors):
    out = {}
    for key, value in factors.items():
        if key not in _OVERRIDABLE:
            raise GearError(
                f"unknown factor {key!r}; the factors that can be given are "
                f"{', '.join(_OVERRIDABLE)}"
            )
        name = key.replace("'", "_prime")
        if _OVERRIDABLE[key]:
            v1, v2 = _pair_of(key, value)
            out[f"{name}1"] = _number(key, v1, 0.0, 1e6)
            out[f"{name}2"] = _number(key, v2, 0.0, 1e6)
        else:
            if isinstance(value, tuple | list):
                raise GearError(f"{key} = {value!r} is one value for the mesh, not a pair")
            out[name] = _number(key, value, 0.0, 1e6)
    return out


# --- the rating -------------------------------------------------------------------------------
def rate_pairs(
    z1: ArrayLike, z2: ArrayLike, module: ArrayLike, face_width: ArrayLike, torque: ArrayLike,
    speed: ArrayLike, *, x1: ArrayLike = 0.0, x2: ArrayLike = 0.0,
    pressure_angle: ArrayLike = 20.0, helix_angle: ArrayLike = 0.0, internal: ArrayLike = False,
    material: Any = ("case-carburized", "case-carburized"), sigma_Hlim: Any = None,
    sigma_Flim: Any = None, life: ArrayLike = 20000.0, application_factor: ArrayLike = 1.0,
    quality: ArrayLike = 6, roughness: ArrayLike = 1.0, root_roughness: ArrayLike | None = None,
    oil_viscosity: ArrayLike = 220.0, tip_relief: ArrayLike | None = None,
    load_sharing: ArrayLike = 1.0, contacts: Any = (1, 1), idler: Any = (False, False),
    misalignment: ArrayLike | None = None, addendum: ArrayLike = 1.0,
    dedendum: ArrayLike = 1.25, root_radius: ArrayLike = 0.38, protuberance: ArrayLike = 0.0,
    tip_shortening: ArrayLike = True, tip_alteration: Any = (0.0, 0.0), root: Any = (None, None),
    factors: dict[str, Any] | None = None, errors: str = "raise",
    fields: Sequence[str] | None = None, threads: int | None = None, geometry: Any = None,
) -> PairRatings:  # fmt: skip
    """ISO 6336 method B pitting and bending ratings of many pairs at once (arrays broadcast).

    Parameters
    ----------
    z1, z2, module, x1, x2, pressure_angle, helix_angle, internal, addendum, tip_shortening
        The pairs, as for :func:`gears.meshing.pair_geometry` (gear 2 the ring when internal).
    face_width : array_like
        Common face width b, mm.
    torque : array_like
        Torque on gear 1 per mesh, N m (> 0).
    speed : array_like
        Speed of gear 1 relative to the carrier, rpm (> 0).
    material : name, Material or pair of them
        ISO 6336-5 material of both gears or ``(gear 1, gear 2)`` (:mod:`gears.rating.materials`).
    sigma_Hlim, sigma_Flim : array_like or pair, optional
        Allowable stress numbers (MPa) replacing the material's, per gear or for both.
    life : array_like
        Required life, hours.
    application_factor : array_like
        K_A >= 1.
    quality : array_like
        ISO 1328 accuracy grade, an integer 1 ... 12.
    roughness : array_like
        Arithmetic mean roughness Ra of the flanks, um (R_z = 6 Ra).
    root_roughness : array_like, optional
        Ra of the root fillets, um (default: ``roughness``).
    oil_viscosity : array_like
        Kinematic viscosity nu_40 of the oil at 40 deg C, mm^2/s.
    tip_relief : array_like, optional
        Tip relief C_a in mm; default the running-in amount C_ay of ISO 6336-1 Table 8.
    load_sharing : array_like
        K_gamma >= 1 (planet load sharing; 1 for a single mesh).
    contacts : pair
        Meshes per revolution of gear 1 and gear 2 on one flank (a sun with three planets: 3):
        the load cycles, and the gear's share of the reduced mass.
    idler : pair of bool
        A gear loaded on both flanks (a planet, an idler): Y_M = 0.7.
    misalignment : array_like, optional
        Effective equivalent misalignment F_betax in um, replacing method C's estimate.
    dedendum, root_radius, protuberance
        The basic rack's h_fP*, rho_fP* and protuberance s_pr* (module units), for both gears
        or a pair: the tool, for Y_F, Y_S, C_B and the root diameters.
    tip_alteration : pair
        Each gear's own tip alteration k (module units) on top of the pair's tip shortening.
    root : pair
        Per gear None (the standard's root form) or a measured ``(s_Fn, rho_F, h_Fe,
        alpha_Fen)`` (mm, mm, mm, rad), e.g. from :func:`gears.rating.root.measure_root`.
    factors : dict, optional
        Factors that replace the computed ones (``{"K_v": 1.0, "K_Hbeta": 1.16}``; names of
        :data:`FACTORS`, a pair for per-gear factors); later factors follow from the given ones.
    errors : {"raise", "mask"}
        A pair outside a method's validity (:data:`REASONS`) raises a GearError naming it and
        the reason ("raise"), or gets ``valid = False`` with NaN factors and zero safeties.
    fields : sequence of str, optional
        The fields of :class:`PairRatings` to return (default all); the others are None. A
        search over 10^6 pairs that needs the safeties only asks for
        ``("S_H1", "S_H2", "S_F1", "S_F2")`` (``valid`` and ``reason`` always come).
    threads : int, optional
        As for :func:`gears.meshing.pair_geometry`.
    geometry : PairGeometry, optional
        The pairs' :func:`gears.meshing.pair_geometry` when the caller has it (``GearPair``
        passes its own): it is then not computed again.

    Returns
    -------
    PairRatings

    Raises
    ------
    GearError
        For bad input (naming the value and its valid range), and with ``errors="raise"`` for a
        pair no rating exists for (naming the row and the reason).

    Examples
    --------
    ISO/TR 6336-30 Example 1 (rating.md) with K_Hbeta = 1.16 given as in the TR:

    >>> from gears.rack import BasicRack
    >>> r = rate_pairs(17, 103, 8, 100, 9000, 360, x1=0.14522, helix_angle=15.8, quality=5,
    ...                life=50000, oil_viscosity=320, tip_relief=0.070, dedendum=1.4,
    ...                root_radius=0.39, tip_shortening=False, factors={"K_Hbeta": 1.16})
    >>> round(float(r.S_H1), 4), round(float(r.S_H2), 4)   # TR: 1.0285, 1.0870
    (1.0284, 1.0868)
    """
    if errors not in ("raise", "mask"):
        raise GearError(f"errors = {errors!r}; valid are 'raise', 'mask'")
    if fields is None:
        fields = _RESULTS
    else:
        unknown = [f for f in fields if f not in _RESULTS and f not in ("valid", "reason")]
        if unknown or isinstance(fields, str):
            raise GearError(f"fields = {fields!r}; valid are names of PairRatings: {_RESULTS}")
        fields = tuple(f for f in fields if f in _RESULTS)
    m1, m2 = (_as_material(v) for v in _pair_of("material", material))
    h1, h2 = _pair_of("sigma_Hlim", sigma_Hlim)
    f1, f2 = _pair_of("sigma_Flim", sigma_Flim)
    c1, c2 = _pair_of("contacts", contacts)
    i1, i2 = _pair_of("idler", idler)
    k1, k2 = _pair_of("tip_alteration", tip_alteration)
    r1, r2 = _pair_of("root", root) if root is not None else (None, None)
    hf1, hf2 = _pair_of("dedendum", dedendum)
    rho1, rho2 = _pair_of("root_radius", root_radius)
    spr1, spr2 = _pair_of("protuberance", protuberance)
    a = {
        "b": _number("face_width", face_width, 0.0, 1e5),
        "T": _number("torque", torque, 0.0, 1e12),
        "n": _number("speed", speed, 0.0, 1e7),
        "life": _number("life", life, 0.0, 1e9),
        "K_A": _number("application_factor", application_factor, 1.0, 100.0, low_open=False),
        "Q": _number("quality", quality, 1.0, 12.0, False, False, integer=True),
        "Ra": _number("roughness", roughness, 0.0, 100.0),
        "Ra_root": _number(
            "root_roughness", roughness if root_roughness is None else root_roughness, 0.0, 100.0
        ),
        "nu40": _number("oil_viscosity", oil_viscosity, 0.0, 1e5),
        "K_gamma": _number("load_sharing", load_sharing, 1.0, 10.0, low_open=False),
        "c1": _number("contacts", c1, 1.0, 1e3, low_open=False),
        "c2": _number("contacts", c2, 1.0, 1e3, low_open=False),
        "idler1": np.asarray(i1, bool),
        "idler2": np.asarray(i2, bool),
        "k1": _number("tip_alteration", k1, -10.0, 10.0),
        "k2": _number("tip_alteration", k2, -10.0, 10.0),
        "hf1": _number("dedendum", hf1, 0.0, 10.0),
        "hf2": _number("dedendum", hf2, 0.0, 10.0),
        "rho1": _number("root_radius", rho1, 0.0, 10.0, low_open=False),
        "rho2": _number("root_radius", rho2, 0.0, 10.0, low_open=False),
        "spr1": _number("protuberance", spr1, 0.0, 1.0, low_open=False),
        "spr2": _number("protuberance", spr2, 0.0, 1.0, low_open=False),
        "sH1": _number("sigma_Hlim", m1.sigma_Hlim if h1 is None else h1, 0.0, 1e5),
        "sH2": _number("sigma_Hlim", m2.sigma_Hlim if h2 is None else h2, 0.0, 1e5),
        "sF1": _number("sigma_Flim", m1.sigma_Flim if f1 is None else f1, 0.0, 1e5),
        "sF2": _number("sigma_Flim", m2.sigma_Flim if f2 is None else f2, 0.0, 1e5),
    }
    if tip_relief is not None:
        a["C_a"] = _number("tip_relief", tip_relief, 0.0, 10.0, low_open=False) * 1000.0
    if misalignment is not None:
        a["F_bx"] = _number("misalignment", misalignment, 0.0, 1e5, low_open=False)
    for i, r in ((1, r1), (2, r2)):
        if r is not None:
            if not isinstance(r, tuple | list) or len(r) != 4:
                raise GearError(f"root of gear {i} = {r!r}; give (s_Fn, rho_F, h_Fe, alpha_Fen)")
            for key, value, low in zip(("s_Fn", "rho_F", "h_Fe", "alpha_Fen"), r,
                                       (0.0, 0.0, 0.0, -1.6), strict=True):  # fmt: skip
                a[f"root_{key}{i}"] = _number(f"{key} of gear {i}", value, low, 1e6)
    a.update({f"o_{k}": v for k, v in _overrides(factors or {}).items()})
    if geometry is None:
        geo = pair_geometry(z1, z2, module, x1, x2, pressure_angle, helix_angle, internal,
                            addendum, tip_shortening, threads)  # fmt: skip
    else:
        geo = geometry
    base = [np.asarray(v, float) for v in (z1, z2, module, x1, x2, pressure_angle, helix_angle,
                                           addendum)]  # fmt: skip
    base.append(np.asarray(internal, bool))
    names = ["z1", "z2", "m", "x1", "x2", "pa", "helix", "ha", "internal"]
    a.update(zip(names, base, strict=True))
    a["alpha_wt"] = np.asarray(geo.working_pressure_angle)
    a["k"] = np.asarray(geo.tip_alteration)
    mats = (m1, m2)
    shape = np.broadcast_shapes(*(v.shape for v in a.values()))
    n = math.prod(shape)
    if threads is None:
        threads = default_threads()
    if n < 2 * _CHUNK:
        res = _rate_block(a, mats, fields)
        wanted = {*fields, "valid", "reason"}  # as the blocked path: the others are None
        if n == 1 and shape == ():
            result = PairRatings(
                **{f: np.asarray(res[f])[()] if f in wanted else None for f in _FIELDS}
            )
        else:
            result = PairRatings(
                **{f: np.broadcast_to(res[f], shape) if f in wanted else None for f in _FIELDS}
            )
    else:
        flat = {k: v if v.ndim == 0 else np.broadcast_to(v, shape).ravel() for k, v in a.items()}
        store = {f: np.empty(n, bool if f == "valid" else int if f == "reason" else float)
                 for f in (*fields, "valid", "reason")}  # fmt: skip

        def work(bounds):
            i0, i1 = bounds
            part = {k: v if v.ndim == 0 else v[i0:i1] for k, v in flat.items()}
            res = _rate_block(part, mats, fields)
            for f, column in store.items():
                column[i0:i1] = res[f]

        blocks = list(itertools.pairwise([*range(0, n, _CHUNK), n]))
        if threads == 1:
            for blk in blocks:
                work(blk)
        else:
            for _ in _pool(threads).map(work, blocks):
                pass
        result = PairRatings(
            **{f: store[f].reshape(shape) if f in store else None for f in _FIELDS}
        )
    if errors == "raise" and not np.all(result.valid):
        bad = np.ravel(~np.asarray(result.valid))
        i = int(np.argmax(bad))
        where = f" (row {i})" if np.ndim(result.valid) else ""
        raise GearError(f"no ISO 6336 rating{where}: {REASONS[int(np.ravel(result.reason)[i])]}")
    return result


def _as_material(value) -> Material:
    return material(value)


def _rate_block(a, mats, fields):
    """Every formula of :func:`rate_pairs` on one block of (broadcastable) arrays; rows outside
    a method's validity may produce NaN or inf on the way: ``fields`` are masked by ``valid``."""
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        return _rate(a, mats, fields)


def _rate(a, mats, fields):
    o = {k[2:]: v for k, v in a.items() if k.startswith("o_")}

    def given(name, value):
        return o[name] if name in o else value

    m1, m2 = mats
    code1, code2 = m1.code, m2.code
    z1, z2, m, x1, x2 = a["z1"], a["z2"], a["m"], a["x1"], a["x2"]
    internal = a["internal"]
    s = _where(internal, -1.0, 1.0)
    b, T, n = a["b"], a["T"], a["n"]
    an = np.radians(a["pa"])
    tan_an = np.tan(an)
    beta = np.radians(np.abs(a["helix"]))
    cos_b = np.cos(beta)
    at = np.arctan(tan_an / cos_b)
    cos_at = np.cos(at)
    bb = np.arctan(np.tan(beta) * cos_at)
    cbb2 = np.cos(bb) ** 2
    awt = np.radians(a["alpha_wt"])
    tan_wt = np.tan(awt)
    d1 = z1 * m / cos_b
    d2 = z2 * m / cos_b
    db1, db2 = d1 * cos_at, d2 * cos_at
    ha = a["ha"]
    k = a["k"]
    da1 = tip_diameter(z1, m, x1, a["helix"], ha, False, k + a["k1"])
    da2 = tip_diameter(z2, m, x2, a["helix"], ha, internal, _where(internal, 0.0, k) + a["k2"])
    df1 = root_diameter(z1, m, x1, a["helix"], a["hf1"], False)
    df2 = root_diameter(z2, m, x2, a["helix"], a["hf2"], internal)
    p_bt = np.pi * m / cos_b * cos_at
    ea = contact_ratio(da1 / 2, da2 / 2, db1 / 2, db2 / 2, tan_wt, s, p_bt)
    eb = b * np.sin(beta) / (np.pi * m)
    eg = ea + eb
    u = z2 / z1
    K_A = given("K_A", a["K_A"])
    K_g = given("K_gamma", a["K_gamma"])
    F_t = 2000.0 * T / d1
    v = np.pi * d1 * n / 60000.0
    w = F_t * K_g * K_A / b  # line load, N/mm

    # stiffness (ISO 6336-1 §9)
    zn1 = z1 / (cbb2 * cos_b)
    zn2 = z2 / (cbb2 * cos_b)
    # C_B is linear in h_fP: the mean of both gears' C_B is C_B of the mean dedendum
    c_p = single_stiffness(zn1, zn2, x1, x2, a["helix"], (a["hf1"] + a["hf2"]) / 2, a["pa"],
                           internal, w)  # fmt: skip
    c_p = given("c_prime", c_p)
    c_ga, c_gb = mesh_stiffness(c_p, ea)
    c_ga = given("c_gamma_alpha", c_ga)
    c_gb = given("c_gamma_beta", c_gb)

    # deviations and running-in (ISO 1328-1; ISO 6336-1 §8.3.3)
    Q = a["Q"]
    fpt1, ff1, fh1 = tolerances(m, d1, b, Q)
    fpt2, ff2, fh2 = tolerances(m, d2, b, Q)
    f_pb = np.maximum(fpt1, fpt2) * cos_at
    f_f = np.maximum(ff1, ff2)
    f_hb = np.maximum(fh1, fh2)
    sH1, sH2 = a["sH1"], a["sH2"]
    y_a = 0.5 * (_y_alpha(f_pb, code1, sH1, v) + _y_alpha(f_pb, code2, sH2, v))
    y_f = 0.5 * (_y_alpha(f_f, code1, sH1, v) + _y_alpha(f_f, code2, sH2, v))
    if "C_a" in a:
        c_a = a["C_a"]
    else:  # running-in tip relief C_ay (ISO 6336-1 Table 8), mean of both gears
        c_a = 0.5 * sum((sh / 97.0 - 18.45) ** 2 / 18.0 + 1.5 for sh in (sH1, sH2))

    # K_v, method B (ISO 6336-1 §6.5): solid gears, the ring's mass infinite
    dm1, dm2 = (da1 + df1) / 2, (da2 + df2) / 2
    mass1 = np.pi / 8 * m1.density * dm1**4 / db1**2 / a["c1"]
    mass2 = np.pi / 8 * m2.density * dm2**4 / db2**2 / a["c2"]
    m_red = _where(internal, mass1, mass1 * mass2 / (mass1 + mass2))
    n_e1 = 30000.0 / (np.pi * z1) * np.sqrt(c_ga / m_red)
    N = n / n_e1
    K_v = given("K_v", dynamic_factor(N, w, c_p, f_pb - y_a, f_f - y_f, c_a, eg))

    # K_Hbeta method C, K_Fbeta (ISO 6336-1 §7.6, §7.8)
    fmb = w * K_v
    if "F_bx" in a:
        f_bx = a["F_bx"]
    else:
        f_sh = fmb * 0.023 * (b / d1) ** 2
        f_bx = np.maximum(1.33 * f_sh + f_hb, np.maximum(0.005 * fmb, 0.5 * f_hb))
    y_b = 0.5 * (_y_beta(f_bx, code1, sH1, v) + _y_beta(f_bx, code2, sH2, v))
    K_Hb = given("K_Hbeta", face_load_factor(np.maximum(f_bx - y_b, 0.0), c_gb, fmb))
    h1 = (da1 - df1) / 2
    h2 = np.abs(da2 - df2) / 2
    K_Fb = given("K_Fbeta", face_load_factor_root(K_Hb, b, np.maximum(h1, h2)))

    # transverse load factors (ISO 6336-1 §8.3)
    Z_eps = given("Z_eps", contact_ratio_factor(ea, eb))
    K_Ha, K_Fa = transverse_load_factors(c_ga, f_pb, y_a, fmb * K_Hb, ea, eg, Z_eps)
    K_Ha = given("K_Halpha", K_Ha)
    K_Fa = given("K_Falpha", K_Fa)

    # pitting (ISO 6336-2)
    Z_H = given("Z_H", zone_factor(np.degrees(at), a["alpha_wt"], np.degrees(bb)))
    Z_E = given("Z_E", elasticity_factor(m1.youngs_modulus, m1.poisson, m2.youngs_modulus,
                                         m2.poisson))  # fmt: skip
    Z_beta = given("Z_beta", 1.0 / np.sqrt(cos_b))
    Z_B, Z_D = single_pair_factors(z1, z2, da1, da2, db1, db2, a["alpha_wt"], ea, eb, internal)
    interferes = (np.isnan(Z_B) & ("o_Z_B" not in a)) | (np.isnan(Z_D) & ("o_Z_D" not in a))
    Z_B = given("Z_B", _where(np.isnan(Z_B), 1.0, Z_B))
    Z_D = given("Z_D", _where(np.isnan(Z_D), 1.0, Z_D))
    s_min = np.minimum(sH1, sH2)
    Z_L, Z_v = lubrication_factors(s_min, a["nu40"], v)
    Z_L, Z_v = given("Z_L", Z_L), given("Z_v", Z_v)
    rho1 = db1 / 2 * tan_wt
    rho2 = db2 / 2 * tan_wt
    rho_red = rho1 * rho2 / (rho2 + s * rho1)
    rz = 6.0 * a["Ra"]
    Z_R = given("Z_R", roughness_factor(s_min, rz, rho_red))
    Z_W1, Z_W2 = _work_hardening(code1, code2, m1.hardness, m2.hardness, rz, rho_red,
                                 a["nu40"], v)  # fmt: skip
    Z_W1, Z_W2 = given("Z_W1", Z_W1), given("Z_W2", Z_W2)
    Z_X = given("Z_X", np.ones_like(F_t))
    N_L1 = 60.0 * a["life"] * n * a["c1"]
    N_L2 = 60.0 * a["life"] * n / u * a["c2"]
    Z_NT1 = given("Z_NT1", pitting_life_factor(N_L1, code1))
    Z_NT2 = given("Z_NT2", pitting_life_factor(N_L2, code2))
    us = s * u
    sigma_H0 = Z_H * Z_E * Z_eps * Z_beta * np.sqrt(F_t * (us + 1.0) / (d1 * b * us))
    load = np.sqrt(K_g * K_A * K_v * K_Hb * K_Ha)
    sigma_H1 = Z_B * sigma_H0 * load
    sigma_H2 = Z_D * sigma_H0 * load
    common = Z_L * Z_v * Z_R * Z_X
    sigma_HP1 = sH1 * Z_NT1 * common * Z_W1
    sigma_HP2 = sH2 * Z_NT2 * common * Z_W2

    # bending (ISO 6336-3): the root form of each gear, standard or measured
    pa = a["pa"]
    den1, aen1, _, _ = load_point(z1, m, da1, d1, pa, a["helix"], ea, False)
    den2, aen2, _, _ = load_point(z2, m, da2, d2, pa, a["helix"], ea, internal)
    rack1 = a["hf1"], a["rho1"], a["spr1"]
    rack2 = a["hf2"], a["rho2"], a["spr2"]
    form1 = root_form(zn1, m, x1, pa, den1, aen1, *rack1)
    if not np.any(internal):
        form2 = root_form(zn2, m, x2, pa, den2, aen2, *rack2)
    else:
        dfn2 = zn2 * m + np.abs(df2 - d2)  # the ring's root on its virtual gear (a rack)
        form2 = internal_root_form(m, pa, den2, dfn2, *rack2)
        if not np.all(internal):
            external = root_form(zn2, m, x2, pa, den2, aen2, *rack2)
            form2 = tuple(_where(internal, i, e) for e, i in zip(external, form2, strict=True))
    forms = []
    for i, form in ((1, form1), (2, form2)):
        if f"root_s_Fn{i}" in a:
            form = tuple(a[f"root_{key}{i}"] for key in ("s_Fn", "rho_F", "h_Fe", "alpha_Fen"))
        forms.append(form)
    (s1, rf1, hfe1, af1), (s2, rf2, hfe2, af2) = forms
    Y_F1, Y_S1, q1 = form_factors(s1, rf1, hfe1, af1, m, pa)
    Y_F2, Y_S2, q2 = form_factors(s2, rf2, hfe2, af2, m, pa)
    Y_F1, Y_F2 = given("Y_F1", Y_F1), given("Y_F2", Y_F2)
    Y_S1, Y_S2 = given("Y_S1", Y_S1), given("Y_S2", Y_S2)
    Y_beta = given("Y_beta", 1.0 - np.minimum(eb, 1.0) * np.minimum(np.degrees(beta), 30.0) / 120.0)
    Y_B1 = given("Y_B1", np.ones_like(F_t))
    Y_B2 = given("Y_B2", np.ones_like(F_t))
    ean = ea / cbb2
    Y_DT = _where((Q <= 4) & (ean > 2.05), _where(ean > 2.5, 0.9, -0.666 * ean + 2.366), 1.0)
    Y_DT = given("Y_DT", Y_DT)
    Y_ST = given("Y_ST", np.full_like(F_t, 2.0))
    Y_NT1 = given("Y_NT1", bending_life_factor(N_L1, code1))
    Y_NT2 = given("Y_NT2", bending_life_factor(N_L2, code2))
    xt = 1.2  # chi*_T = (1 + 2 * 2.5) / 5
    with np.errstate(invalid="ignore"):
        yd = [(1.0 + np.sqrt(mt.slip_layer * (1.0 + 2.0 * np.maximum(q, 0.0)) / 5.0))
              / (1.0 + np.sqrt(mt.slip_layer * xt)) for mt, q in ((m1, q1), (m2, q2))]  # fmt: skip
    Y_d1, Y_d2 = given("Y_deltarelT1", yd[0]), given("Y_deltarelT2", yd[1])
    rz_root = 6.0 * a["Ra_root"]
    Y_R1 = given("Y_RrelT1", _surface_factor(rz_root, code1))
    Y_R2 = given("Y_RrelT2", _surface_factor(rz_root, code2))
    Y_X1 = given("Y_X1", _size_factor(m, code1))
    Y_X2 = given("Y_X2", _size_factor(m, code2))
    Y_M1 = given("Y_M1", _where(a["idler1"], 0.7, 1.0))
    Y_M2 = given("Y_M2", _where(a["idler2"], 0.7, 1.0))
    nominal = F_t / (b * m) * Y_beta * Y_DT
    sigma_F01 = nominal * Y_F1 * Y_S1 * Y_B1
    sigma_F02 = nominal * Y_F2 * Y_S2 * Y_B2
    kf = K_g * K_A * K_v * K_Fb * K_Fa
    sigma_F1, sigma_F2 = sigma_F01 * kf, sigma_F02 * kf
    sigma_FP1 = a["sF1"] * Y_ST * Y_NT1 * Y_d1 * Y_R1 * Y_X1 * Y_M1
    sigma_FP2 = a["sF2"] * Y_ST * Y_NT2 * Y_d2 * Y_R2 * Y_X2 * Y_M2

    # validity, in the order of REASONS
    shape = np.broadcast_shapes(*(np.shape(v) for v in a.values()))
    pointed = np.zeros(shape, bool)
    for z, x, da, db, inside in ((z1, x1, da1, db1, False), (z2, x2, da2, db2, internal)):
        thick = tooth_thickness(np.maximum(da, db), z, m, x, pa, a["helix"], inside, signed=True)
        pointed |= (da >= db) & ~(thick > 0)
    below_base = ~((da1 >= db1) & (da2 >= db2))
    root_ok = np.ones(shape, bool)
    qs_ok = np.ones(shape, bool)
    for i, (sf, rf, he, q) in enumerate(((s1, rf1, hfe1, q1), (s2, rf2, hfe2, q2)), 1):
        root_ok &= (sf > 0) & (he > 0) & (rf > 0)
        if f"o_Y_S{i}" not in a:
            qs_ok &= (q >= 1.0) & (q < 8.0)
    checks = [
        ea >= 1.0,
        ~below_base,
        ~pointed,
        np.isfinite(den1) & np.isfinite(den2),
        root_ok,
        qs_ok,
        ~interferes,
    ]
    reason = np.zeros(shape, int)
    for code, ok in reversed(list(enumerate(checks, 1))):
        reason = _where(ok, reason, code)
    valid = reason == 0
    res = {
        "sigma_H0": sigma_H0, "sigma_H1": sigma_H1, "sigma_H2": sigma_H2,
        "sigma_HP1": sigma_HP1, "sigma_HP2": sigma_HP2, "sigma_F01": sigma_F01,
        "sigma_F02": sigma_F02, "sigma_F1": sigma_F1, "sigma_F2": sigma_F2,
        "sigma_FP1": sigma_FP1, "sigma_FP2": sigma_FP2, "K_A": K_A, "K_gamma": K_g, "K_v": K_v,
        "K_Hbeta": K_Hb, "K_Fbeta": K_Fb, "K_Halpha": K_Ha, "K_Falpha": K_Fa, "c_prime": c_p,
        "c_gamma_alpha": c_ga, "c_gamma_beta": c_gb, "Z_H": Z_H, "Z_E": Z_E, "Z_eps": Z_eps,
        "Z_beta": Z_beta, "Z_B": Z_B, "Z_D": Z_D, "Z_L": Z_L, "Z_v": Z_v, "Z_R": Z_R,
        "Z_W1": Z_W1, "Z_W2": Z_W2, "Z_X": Z_X, "Z_NT1": Z_NT1, "Z_NT2": Z_NT2, "Y_F1": Y_F1,
        "Y_F2": Y_F2, "Y_S1": Y_S1, "Y_S2": Y_S2, "Y_beta": Y_beta, "Y_B1": Y_B1, "Y_B2": Y_B2,
        "Y_DT": Y_DT, "Y_ST": Y_ST, "Y_NT1": Y_NT1, "Y_NT2": Y_NT2, "Y_deltarelT1": Y_d1,
        "Y_deltarelT2": Y_d2, "Y_RrelT1": Y_R1, "Y_RrelT2": Y_R2, "Y_X1": Y_X1, "Y_X2": Y_X2,
        "Y_M1": Y_M1, "Y_M2": Y_M2, "F_t": F_t, "v": v, "u": us, "N": N, "eps_alpha": ea,
        "eps_beta": eb, "eps_gamma": eg, "N_L1": N_L1, "N_L2": N_L2, "s_Fn1": s1, "s_Fn2": s2,
        "rho_F1": rf1, "rho_F2": rf2, "h_Fe1": hfe1, "h_Fe2": hfe2,
        "alpha_Fen1": np.degrees(af1), "alpha_Fen2": np.degrees(af2), "q_s1": q1, "q_s2": q2,
    }  # fmt: skip
    with np.errstate(divide="ignore", invalid="ignore"):
        res["S_H1"] = sigma_HP1 / sigma_H1
        res["S_H2"] = sigma_HP2 / sigma_H2
        res["S_F1"] = sigma_FP1 / sigma_F1
        res["S_F2"] = sigma_FP2 / sigma_F2
    everywhere = bool(np.all(valid))
    for key in fields:
        value = res[key]
        if np.shape(value) != shape:
            value = np.broadcast_to(value, shape)
        if not everywhere:
            value = _where(valid, value, 0.0 if key.startswith("S_") else np.nan)
        res[key] = value
    res["valid"] = valid
    res["reason"] = reason
    return res


def _work_hardening(code1, code2, hb1, hb2, rz, rho_red, nu40, v):
    """Z_W of each gear (ISO 6336-2 §12): for a through-hardened gear meshing with a hardened
    (surface-hardened or nitrided) one, ``(1.2 - (HB - 130)/1700)(3/R_zH)^0.15`` with HB in
    130 ... 470 and ``R_zH = R_z (10/rho_red)^0.33 / (nu_40 v / 1500)^0.33`` in 3 ... 16 (both
    flanks of equal roughness); 1 otherwise."""
    rzh = np.clip(rz * (10.0 / rho_red) ** 0.33 / (nu40 * v / 1500.0) ** 0.33, 3.0, 16.0)
    out = []
    for mine, other, hb in ((code1, code2, hb1), (code2, code1, hb2)):
        if _HARD[mine] or not _HARD[other]:
            out.append(np.ones_like(rzh))
            continue
        hb = min(max(hb, 130.0), 470.0)
        out.append((1.2 - (hb - 130.0) / 1700.0) * (3.0 / rzh) ** 0.15)
    return out[0], out[1]
