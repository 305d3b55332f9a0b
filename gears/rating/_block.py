"""Layer 3, load capacity: every formula of ISO 6336 method B on one block of pairs.

Private to the rating family: :func:`gears.rating.iso6336.rate_pairs` checks its arguments into
a dict of (broadcastable) arrays and calls :func:`rate_block` on blocks of it. The calculation
runs in the order of the standard, one function per part: the pair (diameters, contact ratios,
loads), the load factors of ISO 6336-1, pitting (ISO 6336-2), bending (ISO 6336-3) and the
validity of each method (the ``reason`` codes of :data:`gears.rating.iso6336.REASONS`). Each
part reads and writes the dict ``q`` of quantities, keyed by the names of
:class:`gears.rating.iso6336.PairRatings` where they are reported.

The parts that depend on the gears alone (geometry, stiffness without the load, deviations,
Z_H, Z_E, Z_B, Z_D, Z_R, the root forms and Y factors, the validity of the methods) run first
and do not see the load (torque, speed, life, K_A, K_gamma: :data:`LOAD`); given a ``cache``
(one pair), they are kept by their arguments, so that rating the same pair at other loads runs
the load's part only.
"""

from __future__ import annotations

import itertools

import numpy as np

from gears.errors import GearError
from gears.geometry import root_diameter, tip_diameter, tooth_thickness
from gears.meshing import contact_ratio
from gears.namespace import FLOAT_ERRORS, SCALAR, all_plain
from gears.rating._arrays import where as _where
from gears.rating.bending import (
    deep_tooth_factor,
    form_factors,
    helix_factor_root,
    internal_root_form,
    load_distribution_factor,
    load_point,
    notch_sensitivity_factor,
    root_form,
    root_size_factor,
    root_surface_factor,
)
from gears.rating.life import bending_life_factor, pitting_life_factor
from gears.rating.load_factors import (
    dynamic_factor,
    face_load_factor,
    face_load_factor_root,
    helix_running_in,
    light_load_factor,
    mesh_stiffness,
    profile_running_in,
    single_stiffness,
    tolerances,
    transverse_load_factors,
)
from gears.rating.pitting import (
    contact_ratio_factor,
    elasticity_factor,
    lubrication_factors,
    roughness_factor,
    single_pair_factors,
    work_hardening_factors,
    zone_factor,
)

_ROOT = ("s_Fn", "rho_F", "h_Fe", "alpha_Fen")
#: the arguments of the load: the gears' part never reads them
LOAD = frozenset({"T", "n", "life", "K_A", "K_gamma", "o_K_A", "o_K_gamma"})
_CACHE_SIZE = 256
_NOT_FINITE = 9  # the last reason (gears.rating.iso6336.REASONS)


def rate_block(a, mats, fields, cache=None, key=None, gears=None):
    """Every formula of ISO 6336 method B on one block: ``a`` the checked arguments (overrides
    as ``o_<name>``), ``mats`` the two :class:`gears.rating.materials.Material`; returns the dict
    of every quantity, the ``fields`` broadcast to the block and masked by ``valid`` (zero
    safeties, NaN elsewhere). Rows outside a method's validity may produce NaN or inf on the
    way. ``cache`` (a dict, for one pair of scalar arguments) keeps the gears' part, by ``key``
    (the caller's key of the gears' arguments) or by the arguments themselves. ``gears`` is
    ``a`` without the load's arguments where the caller has it."""
    if gears is None or "o_K_A" in gears or "o_K_gamma" in gears:
        gears = {k: v for k, v in a.items() if k not in LOAD}
    if cache is None:
        key = None
    else:
        if key is None:
            key = (mats, *sorted((k, _hashable(v)) for k, v in gears.items()))
        q = cache.get(key)
    if key is None or q is None:
        q = gears_part(gears, mats)
        if key is not None:
            if len(cache) >= _CACHE_SIZE:
                cache.clear()
            cache[key] = q
    return load_part(q, a, mats, fields)


def gears_part(a, mats):
    """The gears' part of :func:`rate_block` for the checked arguments ``a`` (the load's are not
    read): what :func:`load_part` takes, for one load or many."""
    gears = {k: v for k, v in a.items() if k not in LOAD}
    return _in_namespace(_gears, gears.values(), gears, mats)


def rows_of(gears, i0, i1, n, lead):
    """The rows i0:i1 of a gears' part made for ``n`` rows (arrays with ``lead`` axes whose
    first is the rows'; the others, broadcast along it, as they are)."""
    out = {}
    for k, v in gears.items():
        if type(v) is dict:
            out[k] = rows_of(v, i0, i1, n, lead)
        elif n > 1 and type(v) is np.ndarray and v.ndim == lead and v.shape[0] == n:
            out[k] = v[i0:i1]
        else:
            out[k] = v
    return out


def load_part(gears, a, mats, fields):
    """The load's part of :func:`rate_block` on ``gears``, the gears' part that
    :func:`rate_block` made for the same arguments but the load's (kept and reused): the load
    factors, stresses and safeties at ``a``'s load. The dict returned holds ``gears`` under
    ``"gears"``."""
    q = dict(gears)
    q["gears"] = gears
    # the gears' part is in one namespace throughout: one of its numbers tells which
    numbers = itertools.chain(a.values(), (gears["eps_alpha"],))
    return _in_namespace(_load_of, numbers, q, a, mats, fields)


def _load_of(q, a, mats, fields, xp):
    o = q["overrides"]  # the gears' own; the load's given factors come with the load
    if "o_K_A" in a or "o_K_gamma" in a:
        o = {**o, **{k[2:]: a[k] for k in ("o_K_A", "o_K_gamma") if k in a}}
    given = _given(a, o)
    _load(q, a, given)
    _load_factors(q, a, mats, given, xp)
    _pitting(q, a, mats, given, xp)
    _bending(q, a, mats, given)
    return _results(q, a, fields, xp)


def _in_namespace(part, numbers, *args):
    """``part(*args, xp)`` on Python floats (:data:`gears.namespace.SCALAR`) where every one of
    ``numbers`` is one, else on numpy; where Python floats raise (a division by
    zero, an overflow, a domain error of ``math``: a pair outside the formulas' range), the same
    part again on numpy numbers, which give inf or NaN for the rating's reasons to name. On
    numpy every Python number of the dicts becomes a numpy number first (arrays beside plain
    numbers: the numbers compute as numpy's, as the arrays do)."""
    if all_plain(numbers):
        try:
            return part(*args, SCALAR)
        except FLOAT_ERRORS as error:
            if isinstance(error, GearError):
                raise
    args = tuple(_numpy_numbers(v) if type(v) is dict else v for v in args)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        return part(*args, np)


def _numpy_numbers(values: dict) -> dict:
    """A dict's Python floats and bools as numpy numbers (the path that gives inf and NaN)."""
    out = {}
    for k, v in values.items():
        t = type(v)
        if t is float:
            v = np.float64(v)
        elif t is bool:
            v = np.bool_(v)
        elif t is dict and k == "overrides":  # the factors given by their symbol
            v = _numpy_numbers(v)
        out[k] = v
    return out


def _hashable(v):
    return v.item() if type(v) is np.ndarray else v


def _overrides(a):
    """The factors given by their symbol (``o_<name>`` in ``a``), by name."""
    return {k[2:]: v for k, v in a.items() if k.startswith("o_")}


def _given(a, o=None):
    """``given(name, value)``: the factor given for ``name``, else ``value`` (``o`` the
    overrides of ``a`` when known)."""
    o = _overrides(a) if o is None else o

    def given(name, value):
        return o[name] if name in o else value

    return given


def _gears(a, mats, xp):
    """The gears' part: everything that does not depend on the load."""
    o = _overrides(a)
    given = _given(a, o)
    q = _pair(a, xp)
    q["overrides"] = o
    _stiffness(q, a, mats, given, xp)
    _contact(q, a, mats, given, xp)
    _root_forms(q, a)
    _root(q, a, mats, given, xp)
    q["reason"] = _methods(q, a, xp)
    return q


def _pair(a, xp):
    """Diameters and contact ratios of the pairs."""
    z1, z2, m, x1, x2 = a["z1"], a["z2"], a["m"], a["x1"], a["x2"]
    internal = a["internal"]
    s = _where(internal, -1.0, 1.0)
    b = a["b"]
    an = xp.radians(a["pa"])
    beta = xp.radians(xp.abs(a["helix"]))
    cos_b = xp.cos(beta)
    at = xp.arctan(xp.tan(an) / cos_b)
    cos_at = xp.cos(at)
    bb = xp.arctan(xp.tan(beta) * cos_at)
    cbb2 = xp.cos(bb) ** 2
    tan_wt = xp.tan(xp.radians(a["alpha_wt"]))
    d1 = z1 * m / cos_b
    d2 = z2 * m / cos_b
    db1, db2 = d1 * cos_at, d2 * cos_at
    ha, k = a["ha"], a["k"]
    da1 = tip_diameter(z1, m, x1, a["helix"], ha, False, k + a["k1"])
    da2 = tip_diameter(z2, m, x2, a["helix"], ha, internal, _where(internal, 0.0, k) + a["k2"])
    df1 = root_diameter(z1, m, x1, a["helix"], a["hf1"], False)
    df2 = root_diameter(z2, m, x2, a["helix"], a["hf2"], internal)
    p_bt = xp.pi * m / cos_b * cos_at
    ea = contact_ratio(da1 / 2, da2 / 2, db1 / 2, db2 / 2, tan_wt, s, p_bt)
    eb = b * xp.sin(beta) / (xp.pi * m)
    return {
        "z1": z1, "z2": z2, "m": m, "x1": x1, "x2": x2, "internal": internal, "s": s, "b": b,
        "beta": beta, "cos_b": cos_b, "at": at, "cos_at": cos_at, "bb": bb,
        "cbb2": cbb2, "tan_wt": tan_wt, "d1": d1, "d2": d2, "db1": db1, "db2": db2, "da1": da1,
        "da2": da2, "df1": df1, "df2": df2, "eps_alpha": ea, "eps_beta": eb,
        "eps_gamma": ea + eb, "u": z2 / z1,
        "zn1": z1 / (cbb2 * cos_b), "zn2": z2 / (cbb2 * cos_b),
    }  # fmt: skip


def _stiffness(q, a, mats, given, xp):
    """The single stiffness above 100 N/mm, the deviations, the reduced mass and Z_eps
    (ISO 6336-1 §9, ISO 1328-1, §6.5; ISO 6336-2 §8)."""
    m1, m2 = mats
    m, b, d1 = q["m"], q["b"], q["d1"]
    # C_B is linear in h_fP: the mean of both gears' C_B is C_B of the mean dedendum
    q["c_th"] = single_stiffness(q["zn1"], q["zn2"], q["x1"], q["x2"], a["helix"],
                                 (a["hf1"] + a["hf2"]) / 2, a["pa"], q["internal"])  # fmt: skip
    fpt1, ff1, fh1 = tolerances(m, d1, b, a["Q"])
    fpt2, ff2, fh2 = tolerances(m, q["d2"], b, a["Q"])
    q["f_pb"] = xp.maximum(fpt1, fpt2) * q["cos_at"]
    q["f_f"] = xp.maximum(ff1, ff2)
    q["f_hb"] = xp.maximum(fh1, fh2)
    if "C_a" in a:
        q["C_a"] = a["C_a"]
    else:  # running-in tip relief C_ay (ISO 6336-1 Table 8), mean of both gears
        q["C_a"] = 0.5 * sum((sh / 97.0 - 18.45) ** 2 / 18.0 + 1.5 for sh in (a["sH1"], a["sH2"]))
    # solid gears, the ring's mass infinite
    dm1, dm2 = (q["da1"] + q["df1"]) / 2, (q["da2"] + q["df2"]) / 2
    mass1 = xp.pi / 8 * m1.density * dm1**4 / q["db1"] ** 2 / a["c1"]
    mass2 = xp.pi / 8 * m2.density * dm2**4 / q["db2"] ** 2 / a["c2"]
    q["m_red"] = _where(q["internal"], mass1, mass1 * mass2 / (mass1 + mass2))
    h1 = (q["da1"] - q["df1"]) / 2
    h2 = xp.abs(q["da2"] - q["df2"]) / 2
    q["h"] = xp.maximum(h1, h2)
    q["Z_eps"] = given("Z_eps", contact_ratio_factor(q["eps_alpha"], q["eps_beta"]))


def _contact(q, a, mats, given, xp):
    """Z_H, Z_E, Z_beta, Z_B, Z_D, Z_R, Z_X (ISO 6336-2): the factors of the gears alone."""
    m1, m2 = mats
    ea, eb, s = q["eps_alpha"], q["eps_beta"], q["s"]
    q["Z_H"] = given("Z_H", zone_factor(xp.degrees(q["at"]), a["alpha_wt"], xp.degrees(q["bb"])))
    q["Z_E"] = given("Z_E", elasticity_factor(m1.youngs_modulus, m1.poisson, m2.youngs_modulus,
                                              m2.poisson))  # fmt: skip
    q["Z_beta"] = given("Z_beta", 1.0 / xp.sqrt(q["cos_b"]))
    Z_B, Z_D = single_pair_factors(q["z1"], q["z2"], q["da1"], q["da2"], q["db1"], q["db2"],
                                   a["alpha_wt"], ea, eb, q["internal"])  # fmt: skip
    q["interferes"] = (xp.isnan(Z_B) & ("o_Z_B" not in a)) | (xp.isnan(Z_D) & ("o_Z_D" not in a))
    q["Z_B"] = given("Z_B", _where(xp.isnan(Z_B), 1.0, Z_B))
    q["Z_D"] = given("Z_D", _where(xp.isnan(Z_D), 1.0, Z_D))
    q["s_min"] = xp.minimum(a["sH1"], a["sH2"])
    rho1 = q["db1"] / 2 * q["tan_wt"]
    rho2 = q["db2"] / 2 * q["tan_wt"]
    q["rho_red"] = rho1 * rho2 / (rho2 + s * rho1)
    q["rz"] = 6.0 * a["Ra"]
    q["Z_R"] = given("Z_R", roughness_factor(q["s_min"], q["rz"], q["rho_red"]))
    q["Z_X"] = given("Z_X", 1.0)


def _root_forms(q, a):
    """The load points and the root form of each gear (ISO 6336-3 §6.2), standard or given."""
    m, pa, ea, internal = q["m"], a["pa"], q["eps_alpha"], q["internal"]
    den1, aen1, _, _ = load_point(q["z1"], m, q["da1"], q["d1"], pa, a["helix"], ea, False)
    den2, aen2, _, _ = load_point(q["z2"], m, q["da2"], q["d2"], pa, a["helix"], ea, internal)
    rack1 = a["hf1"], a["rho1"], a["spr1"]
    rack2 = a["hf2"], a["rho2"], a["spr2"]
    form1 = root_form(q["zn1"], m, q["x1"], pa, den1, aen1, *rack1)
    if not (internal if type(internal) is bool else np.any(internal)):
        form2 = root_form(q["zn2"], m, q["x2"], pa, den2, aen2, *rack2)
    else:
        dfn2 = q["zn2"] * m + abs(q["df2"] - q["d2"])  # the ring's root on its virtual gear
        form2 = internal_root_form(m, pa, den2, dfn2, *rack2)
        if not np.all(internal):
            external = root_form(q["zn2"], m, q["x2"], pa, den2, aen2, *rack2)
            form2 = tuple(_where(internal, i, e) for e, i in zip(external, form2, strict=True))
    q["d_en1"], q["d_en2"] = den1, den2
    for i, form in ((1, form1), (2, form2)):
        if f"root_s_Fn{i}" in a:
            form = tuple(a[f"root_{key}{i}"] for key in _ROOT)
        for key, value in zip(_ROOT, form, strict=True):
            q[f"{key}{i}"] = value


def _root(q, a, mats, given, xp):
    """The Y factors of the gears alone (ISO 6336-3): form, stress correction, helix, deep
    tooth, rim, notch sensitivity, surface, size, mean stress."""
    m, pa = q["m"], a["pa"]
    edition = int(a["edition"])
    ean = q["eps_alpha"] / q["cbb2"]
    # the 2019 edition's Y_F carries f_eps (ISO 6336-3:2019 §6.2), the 2006 edition's none
    q["f_eps"] = load_distribution_factor(q["eps_beta"], ean) if edition == 2019 else 1.0
    for i, mat in ((1, mats[0]), (2, mats[1])):
        Y_F, Y_S, q[f"q_s{i}"] = form_factors(q[f"s_Fn{i}"], q[f"rho_F{i}"], q[f"h_Fe{i}"],
                                              q[f"alpha_Fen{i}"], m, pa)  # fmt: skip
        q[f"Y_F{i}"], q[f"Y_S{i}"] = given(f"Y_F{i}", Y_F * q["f_eps"]), given(f"Y_S{i}", Y_S)
        q[f"Y_B{i}"] = given(f"Y_B{i}", 1.0)
        delta = notch_sensitivity_factor(q[f"q_s{i}"], mat.slip_layer)
        q[f"Y_deltarelT{i}"] = given(f"Y_deltarelT{i}", delta)
        q[f"Y_RrelT{i}"] = given(f"Y_RrelT{i}", root_surface_factor(6.0 * a["Ra_root"], mat.code))
        q[f"Y_X{i}"] = given(f"Y_X{i}", root_size_factor(m, mat.code))
        q[f"Y_M{i}"] = given(f"Y_M{i}", _where(a[f"idler{i}"], 0.7, 1.0))
    q["Y_beta"] = given("Y_beta", helix_factor_root(q["eps_beta"], xp.degrees(q["beta"]),
                                                    edition))  # fmt: skip
    q["Y_DT"] = given("Y_DT", deep_tooth_factor(a["Q"], ean))
    q["Y_ST"] = given("Y_ST", 2.0)


def _load(q, a, given):
    """The nominal load, the pitch-line speed and the line load."""
    K_A = given("K_A", a["K_A"])
    K_g = given("K_gamma", a["K_gamma"])
    F_t = 2000.0 * a["T"] / q["d1"]
    q.update({
        "n": a["n"], "K_A": K_A, "K_gamma": K_g, "F_t": F_t,
        "v": np.pi * q["d1"] * a["n"] / 60000.0, "w": F_t * K_g * K_A / q["b"],  # w: N/mm
    })  # fmt: skip


def _load_factors(q, a, mats, given, xp):
    """Stiffness at the load, K_v, K_Hbeta, K_Fbeta, K_Halpha, K_Falpha (ISO 6336-1)."""
    m1, m2 = mats
    code1, code2 = m1.code, m2.code
    b, d1, ea, eg, w, v = q["b"], q["d1"], q["eps_alpha"], q["eps_gamma"], q["w"], q["v"]
    f_pb, f_f, Z_eps = q["f_pb"], q["f_f"], q["Z_eps"]

    # stiffness (ISO 6336-1 §9), lower below 100 N/mm
    c_p = given("c_prime", q["c_th"] * light_load_factor(w))
    c_ga, c_gb = mesh_stiffness(c_p, ea)
    c_ga = given("c_gamma_alpha", c_ga)
    c_gb = given("c_gamma_beta", c_gb)

    # running-in (ISO 6336-1 §8.3.3)
    sH1, sH2 = a["sH1"], a["sH2"]
    y_a = 0.5 * (profile_running_in(f_pb, code1, sH1, v) + profile_running_in(f_pb, code2, sH2, v))
    y_f = 0.5 * (profile_running_in(f_f, code1, sH1, v) + profile_running_in(f_f, code2, sH2, v))

    # K_v, method B (ISO 6336-1 §6.5)
    n_e1 = 30000.0 / (xp.pi * q["z1"]) * xp.sqrt(c_ga / q["m_red"])
    N = q["n"] / n_e1
    # ISO 6336-1 takes F_t K_A / b >= 100 N/mm in K_v and the transverse load factors
    w100 = xp.maximum(w, 100.0)
    K_v = given("K_v", dynamic_factor(N, w100, c_p, f_pb - y_a, f_f - y_f, q["C_a"], eg))

    # K_Hbeta method C, K_Fbeta (ISO 6336-1 §7.6, §7.8)
    fmb = w * K_v
    if "F_bx" in a:
        f_bx = a["F_bx"]
    else:
        f_sh = fmb * 0.023 * (b / d1) ** 2
        f_bx = xp.maximum(1.33 * f_sh + q["f_hb"], xp.maximum(0.005 * fmb, 0.5 * q["f_hb"]))
    y_b = 0.5 * (helix_running_in(f_bx, code1, sH1, v) + helix_running_in(f_bx, code2, sH2, v))
    K_Hb = given("K_Hbeta", face_load_factor(xp.maximum(f_bx - y_b, 0.0), c_gb, fmb))
    K_Fb = given("K_Fbeta", face_load_factor_root(K_Hb, b, q["h"]))

    # transverse load factors (ISO 6336-1 §8.3)
    K_Ha, K_Fa = transverse_load_factors(c_ga, f_pb, y_a, w100 * K_v * K_Hb, ea, eg, Z_eps)
    # one K_alpha (ISO 6336-1 §8.3): a given K_Halpha sets K_Falpha within its bound, and back
    if "o_K_Halpha" in a and "o_K_Falpha" not in a:
        K_Fa = xp.minimum(xp.maximum(a["o_K_Halpha"], 1.0), eg / (0.25 * ea + 0.75))
    elif "o_K_Falpha" in a and "o_K_Halpha" not in a:
        K_Ha = xp.minimum(xp.maximum(a["o_K_Falpha"], 1.0), eg / (ea * Z_eps**2))
    q.update({
        "c_prime": c_p, "c_gamma_alpha": c_ga, "c_gamma_beta": c_gb, "N": N, "K_v": K_v,
        "K_Hbeta": K_Hb, "K_Fbeta": K_Fb, "K_Halpha": given("K_Halpha", K_Ha),
        "K_Falpha": given("K_Falpha", K_Fa),
    })  # fmt: skip


def _pitting(q, a, mats, given, xp):
    """Z_L, Z_v, Z_W, Z_NT and sigma_H0, sigma_H, sigma_HP (ISO 6336-2)."""
    m1, m2 = mats
    code1, code2 = m1.code, m2.code
    v, n, u, s = q["v"], q["n"], q["u"], q["s"]
    Z_L, Z_v = lubrication_factors(q["s_min"], a["nu40"], v)
    Z_L, Z_v = given("Z_L", Z_L), given("Z_v", Z_v)
    Z_W1, Z_W2 = work_hardening_factors(code1, code2, m1.hardness, m2.hardness, q["rz"],
                                        q["rho_red"], a["nu40"], v)  # fmt: skip
    Z_W1, Z_W2 = given("Z_W1", Z_W1), given("Z_W2", Z_W2)
    hours_turns = 60.0 * a["life"] * n  # the load's; the contacts per turn the pair's
    N_L1 = hours_turns * a["c1"]
    N_L2 = hours_turns * (a["c2"] / u)
    Z_NT1 = _life(given, "Z_NT1", pitting_life_factor, N_L1, code1)
    Z_NT2 = _life(given, "Z_NT2", pitting_life_factor, N_L2, code2)
    us = s * u
    # the gears' factors multiplied first, the load's last (one pass over a spectrum's bins)
    root = xp.sqrt(q["F_t"] * ((us + 1.0) / (q["d1"] * q["b"] * us)))
    sigma_H0 = q["Z_H"] * q["Z_E"] * q["Z_eps"] * q["Z_beta"] * root
    loaded = sigma_H0 * xp.sqrt(q["K_gamma"] * q["K_A"] * q["K_v"] * q["K_Hbeta"] * q["K_Halpha"])
    common = Z_L * Z_v * q["Z_R"] * q["Z_X"]
    q.update({
        "Z_L": Z_L, "Z_v": Z_v, "Z_W1": Z_W1, "Z_W2": Z_W2, "N_L1": N_L1, "N_L2": N_L2,
        "Z_NT1": Z_NT1, "Z_NT2": Z_NT2, "u": us, "sigma_H0": sigma_H0,
        "sigma_H1": q["Z_B"] * loaded, "sigma_H2": q["Z_D"] * loaded,
        "sigma_HP1": Z_NT1 * (a["sH1"] * Z_W1 * common),
        "sigma_HP2": Z_NT2 * (a["sH2"] * Z_W2 * common),
    })  # fmt: skip


def _life(given, name, factor, cycles, code):
    """The life factor ``name`` where given (a spectrum's bins take 1: Miner's rule reads the
    S-N curve itself), else ``factor(cycles, code)``."""
    value = given(name, None)
    return factor(cycles, code) if value is None else value


def _bending(q, a, mats, given):
    """Y_NT and sigma_F0, sigma_F, sigma_FP (ISO 6336-3)."""
    # the gears' factors multiplied first, the load's last (one pass over a spectrum's bins)
    form = q["Y_beta"] * q["Y_DT"] / (q["b"] * q["m"])
    kf = q["K_gamma"] * q["K_A"] * q["K_v"] * q["K_Fbeta"] * q["K_Falpha"]
    for i, code in ((1, mats[0].code), (2, mats[1].code)):
        q[f"Y_NT{i}"] = _life(given, f"Y_NT{i}", bending_life_factor, q[f"N_L{i}"], code)
        q[f"sigma_F0{i}"] = q["F_t"] * (form * q[f"Y_F{i}"] * q[f"Y_S{i}"] * q[f"Y_B{i}"])
        q[f"sigma_F{i}"] = q[f"sigma_F0{i}"] * kf
        allowable = a[f"sF{i}"] * q["Y_ST"] * q[f"Y_deltarelT{i}"] * q[f"Y_RrelT{i}"]
        q[f"sigma_FP{i}"] = q[f"Y_NT{i}"] * (allowable * q[f"Y_X{i}"] * q[f"Y_M{i}"])


def _methods(q, a, xp):
    """The reason code of each pair from its gears (0 = every method applies): the first
    failed check in the order of REASONS, the last of which (a finite result) waits for the
    load."""
    m, pa, internal = q["m"], a["pa"], q["internal"]
    da1, da2, db1, db2 = q["da1"], q["da2"], q["db1"], q["db2"]
    pointed = False  # booleans broadcast to the rows as the checks combine
    for z, x, da, db, inside in ((q["z1"], q["x1"], da1, db1, False),
                                 (q["z2"], q["x2"], da2, db2, internal)):  # fmt: skip
        thick = tooth_thickness(xp.maximum(da, db), z, m, x, pa, a["helix"], inside, signed=True)
        pointed = pointed | (da >= db) & xp.logical_not(thick > 0)
    below_base = xp.logical_not((da1 >= db1) & (da2 >= db2))
    root_ok = qs_ok = True
    for i in (1, 2):
        root_ok = root_ok & (q[f"s_Fn{i}"] > 0) & (q[f"h_Fe{i}"] > 0) & (q[f"rho_F{i}"] > 0)
        if f"o_Y_S{i}" not in a:
            qs_ok = qs_ok & (q[f"q_s{i}"] >= 1.0) & (q[f"q_s{i}"] < 8.0)
    checks = [
        q["eps_alpha"] >= 1.0,
        xp.logical_not(below_base),
        xp.logical_not(pointed),
        xp.isfinite(q["d_en1"]) & xp.isfinite(q["d_en2"]),
        root_ok,
        qs_ok,
        xp.logical_not(q["interferes"]),
        (q["Z_eps"] > 0) | ("o_Z_eps" in a),
    ]
    reason = 0
    for code, ok in reversed(list(enumerate(checks, 1))):
        reason = _where(ok, reason, code)
    return np.asarray(reason)[()] if type(reason) is int and xp is np else reason


def _results(q, a, fields, xp):
    """The safeties, then ``fields`` broadcast to the block and masked by ``valid``."""
    for i in (1, 2):
        q[f"S_H{i}"] = q[f"sigma_HP{i}"] / q[f"sigma_H{i}"]
        q[f"S_F{i}"] = q[f"sigma_FP{i}"] / q[f"sigma_F{i}"]
    # a last guard: every safety a finite number > 0 (no NaN or inf leaves the rating)
    finite = True
    for key in ("S_H1", "S_H2", "S_F1", "S_F2"):
        finite = finite & xp.isfinite(q[key]) & (q[key] > 0)
    reason = q["reason"]
    reason = _where((reason == 0) & xp.logical_not(finite), _NOT_FINITE, reason)
    valid = reason == 0
    q["alpha_Fen1"] = xp.degrees(q["alpha_Fen1"])
    q["alpha_Fen2"] = xp.degrees(q["alpha_Fen2"])
    if (type(valid) is bool or type(valid) is np.bool_) and valid:  # one pair, rated
        q["valid"], q["reason"] = valid, reason
        return q
    shape = np.broadcast_shapes(*(np.shape(v) for v in a.values()))
    valid = np.broadcast_to(valid, shape)
    everywhere = bool(np.all(valid))
    for key in fields:
        value = q[key]
        if np.shape(value) != shape:
            value = np.broadcast_to(value, shape)
        if not everywhere:
            value = _where(valid, value, 0.0 if key.startswith("S_") else np.nan)
        q[key] = value
    q["valid"] = valid
    q["reason"] = np.broadcast_to(reason, shape)
    return q
