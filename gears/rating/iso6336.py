"""Layer 4, load capacity: ISO 6336 method B pitting and tooth-root bending over arrays.

Every factor of ISO 6336-1 (load factors, :mod:`gears.rating.load_factors`), ISO 6336-2
(pitting, :mod:`gears.rating.pitting`), ISO 6336-3 (bending, :mod:`gears.rating.bending`) and the
life curves (:mod:`gears.rating.life`) is a numpy function over arrays (broadcasting), and
:func:`rate_pairs`, the array entry, rates 10^6 pairs at once the way
:func:`gears.meshing.pair_geometry` computes their geometry; ``GearPair.rating`` (a
:class:`gears.rating.capacity.Rating`) is a thin view over it for one pair. This module checks the
arguments, names the factors and the results (:data:`FACTORS`, :data:`QUANTITIES`,
:data:`REASONS`, :class:`PairRatings`) and runs the calculation in blocks on threads.

The calculation (references are to the clauses of ISO 6336-1/-2/-3, whose 2019 and 2006
editions (``edition=``, :data:`gears.rating.bending.EDITIONS`) differ here in ISO 6336-3's Y_F
and Y_beta only; ISO/TR 6336-30 Example 1, by the 2006 parts, is the test):

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
* bending (ISO 6336-3): ``sigma_F0 = F_t/(b m_n) Y_F Y_S Y_beta Y_B Y_DT`` (by the 2019
  edition Y_F times the load distribution influence factor f_eps of §6.2 and Y_beta over
  cos^3 beta, Clause 8),
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

import functools
import inspect
import itertools
import math
import operator
from collections.abc import Mapping, Sequence
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from gears.arguments import common_shape
from gears.errors import GearError
from gears.meshing import _CHUNK, _pool, contact_ratio, default_threads, pair_geometry
from gears.rack import BasicRack, max_root_radius
from gears.rating._arrays import number, reducer
from gears.rating._arrays import pair_of as _pair_of
from gears.rating._arrays import public_name as _public
from gears.rating._block import gears_part, load_part, rate_block, rows_of
from gears.rating._one import PLAIN as _PLAIN
from gears.rating._one import plain_key, plain_numbers, plain_or_array
from gears.rating.bending import check_edition, load_point
from gears.rating.materials import material

__all__ = [
    "FACTORS",
    "QUANTITIES",
    "REASONS",
    "OnePair",
    "PairRatings",
    "rate_again",
    "rate_one",
    "rate_pairs",
    "rate_reduced",
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
    ("f_eps", False, "load distribution in Y_F (2019; 2006: 1)", ""),
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
    "the contact ratio factor Z_eps of ISO 6336-2 §8 has no value here: (4 - eps_alpha)/3 "
    "(1 - eps_beta) + eps_beta/eps_alpha <= 0 (a transverse contact ratio near 4 or above)",
    "a stress or safety is not a finite number: the load and the gear lie outside the range of "
    "the rating's formulas",
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
    f_eps: np.ndarray
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


_OVERRIDABLE = {f[0]: f[1] for f in FACTORS}
# a checked number: one pair's a Python float (the rating computes on those), else an array
_number = functools.partial(number, plain=True)
# the smallest value a rating takes: torque (N m), flank and root roughness Ra (um, below
# ISO 1302's finest class N1 = 0.025 um), face width and largest tip relief (module units)
_MIN_TORQUE, _MIN_RA, _MIN_WIDTH, _MAX_RELIEF = 1e-9, 0.01, 0.1, 0.1
_FACTOR_RANGE = (1e-3, 1e6)  # a factor given by its symbol (the load factors from 1)
# one pair's load-independent part, by its arguments (gears.rating._block): rating the same pair
# at other loads computes the load's part only
_GEARS: dict = {}
_GEOMETRY: dict = {}  # and its pair_geometry, by its arguments
_ARGUMENTS: dict = {}  # and its checked arguments but the load's (plain_key)
_LOAD_ARGS = frozenset({"torque", "speed", "life", "application_factor", "load_sharing"})
_LOAD_KEYS = ("T", "n", "life", "K_A", "K_gamma")
_NOT_KEYED = _LOAD_ARGS | {"geometry"}


def _overrides(factors):
    if not isinstance(factors, Mapping | None):
        raise GearError(f"factors = {factors!r:.80}; valid is a dict of factors by symbol, or None")
    out = {}
    for key, value in (factors or {}).items():
        if key not in _OVERRIDABLE:
            raise GearError(f"unknown factor {key!r}; the factors that can be given are "
                            f"{', '.join(_OVERRIDABLE)}")  # fmt: skip
        name = key.replace("'", "_prime")
        if _OVERRIDABLE[key]:
            v1, v2 = _pair_of(key, value)
            out[f"{name}1"] = _number(key, v1, *_FACTOR_RANGE, low_open=False)
            out[f"{name}2"] = _number(key, v2, *_FACTOR_RANGE, low_open=False)
        else:
            if isinstance(value, tuple | list):
                raise GearError(f"{key} = {value!r} is one value for the mesh, not a pair")
            # the load factors are at least 1 (ISO 6336-1: K_A, K_gamma, K_v, K_beta, K_alpha)
            low = 1.0 if key.startswith("K_") else _FACTOR_RANGE[0]
            out[name] = _number(key, value, low, _FACTOR_RANGE[1], low_open=False)
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
    dedendum: ArrayLike = 1.25, root_radius: ArrayLike | None = None, protuberance: ArrayLike = 0.0,
    tip_shortening: ArrayLike = True, tip_alteration: Any = (0.0, 0.0), root: Any = (None, None),
    factors: dict[str, Any] | None = None, edition: int = 2019, errors: str = "raise",
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
        or a pair: the tool, for Y_F, Y_S, C_B and the root diameters. ``root_radius=None``
        takes :class:`gears.rack.BasicRack`'s, capped to fit the tool at this pressure angle
        and dedendum (:func:`gears.rack.max_root_radius`), as :class:`gears.Gear` does.
    tip_alteration : pair
        Each gear's own tip alteration k (module units) on top of the pair's tip shortening.
    root : pair
        Per gear None (the standard's root form) or a measured ``(s_Fn, rho_F, h_Fe,
        alpha_Fen)`` (mm, mm, mm, rad), e.g. from :func:`gears.rating.root.measure_root`.
    factors : dict, optional
        Factors that replace the computed ones (``{"K_v": 1.0, "K_Hbeta": 1.16}``; names of
        :data:`FACTORS`, a pair for per-gear factors); later factors follow from the given ones.
    edition : {2019, 2006}
        The edition of ISO 6336-1/-2/-3 (:data:`gears.rating.bending.EDITIONS`): 2019
        multiplies Y_F by its load distribution influence factor f_eps and divides Y_beta by
        cos^3 beta (ISO 6336-3:2019 §6.2, Clause 8); 2006 is the edition ISO/TR 6336-30:2017
        works by.
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
    ISO/TR 6336-30 Example 1 (docs/rating.md) with K_Hbeta = 1.16 given as in the TR:

    >>> from gears.rack import BasicRack
    >>> r = rate_pairs(17, 103, 8, 100, 9000, 360, x1=0.14522, helix_angle=15.8, quality=5,
    ...                life=50000, oil_viscosity=320, tip_relief=0.070, dedendum=1.4,
    ...                root_radius=0.39, tip_shortening=False, factors={"K_Hbeta": 1.16},
    ...                edition=2006)
    >>> round(float(r.S_H1), 4), round(float(r.S_H2), 4)   # TR: 1.0285, 1.0870
    (1.0284, 1.0868)
    """
    return _rate(dict(locals()))[0]  # the arguments by name


_DEFAULTS = {k: p.default for k, p in inspect.signature(rate_pairs).parameters.items()
             if p.default is not inspect.Parameter.empty}  # fmt: skip


class OnePair(NamedTuple):
    """One pair's checked arguments but the load's, its materials and its gears' part (the
    dict of :func:`gears.rating._block.rate_block` that does not depend on the load): what
    :func:`rate_again` rates at another load."""

    arguments: dict
    materials: tuple
    gears: dict


def rate_one(**arguments: Any) -> tuple[PairRatings, OnePair | None]:
    """:func:`rate_pairs` (its arguments by name) and, for one pair, its :class:`OnePair` (None
    for arrays)."""
    return _rate({**_DEFAULTS, **arguments})


def rate_again(one: OnePair, torque, speed, life, application_factor, load_sharing=1.0,
               fields: Sequence[str] | None = None) -> PairRatings:  # fmt: skip
    """The pair of ``one`` rated at another load (torque N m, speed rpm, life h, K_A, K_gamma;
    checked as by :func:`rate_pairs`): its gears' part is not computed again, nor its other
    arguments checked. Raises a GearError where the pair has no rating at this load."""
    load = {"torque": torque, "speed": speed, "life": life,
            "application_factor": application_factor, "load_sharing": load_sharing}  # fmt: skip
    a = dict(one.arguments)
    a.update(_load_arguments(load))
    res = load_part(one.gears, a, one.materials, _RESULTS if fields is None else fields)
    result, _ = _one_result(res, _RESULTS if fields is None else fields)
    _raise_invalid(result)
    return result


def rate_reduced(reduce, chunk: int = _CHUNK, **arguments: Any) -> PairRatings:
    """:func:`rate_pairs` (its arguments by name) where each block of whole rows of the first
    axis hands its dict of quantities (:func:`gears.rating._block.rate_block`: ``fields``
    broadcast to the block and masked) to ``reduce(q, i0, i1)`` (its rows i0:i1) as soon as it
    is rated, on the block's thread, instead of storing them: a caller that reduces the last
    axis (a spectrum's bins) reads each block while it is in the cache. Blocks of about
    ``chunk`` ratings; the last axis is never cut. With more than one rating a row, the rows
    go in pieces (at most 32 768, at least one a thread), each piece's gears' part computed at
    once and its blocks' load parts from it. Returns ``valid`` and ``reason`` only (the other
    fields None) and raises as :func:`rate_pairs`."""
    chunk = reducer(reduce, chunk, arguments, rate_pairs)
    return _rate({**_DEFAULTS, **arguments}, reduce, chunk)[0]


def _rate(args, reduce=None, chunk=_CHUNK):
    """:func:`rate_pairs` on ``args`` (every argument by name), with the :class:`OnePair` of
    one pair of plain numbers (else None); ``reduce`` and ``chunk`` as for
    :func:`rate_reduced`."""
    errors, fields = args["errors"], args["fields"]
    if errors not in ("raise", "mask"):
        raise GearError(f"errors = {errors!r}; valid are 'raise', 'mask'")
    if fields is None:
        fields = _RESULTS
    else:
        unknown = [f for f in fields if f not in _RESULTS and f not in ("valid", "reason")]
        if unknown or isinstance(fields, str):
            raise GearError(f"fields = {fields!r}; valid are names of PairRatings: {_RESULTS}")
        fields = tuple(f for f in fields if f in _RESULTS)
    a, mats, key, rest = _arguments(args)
    threads = args["threads"]
    result, gears = _blocks(a, mats, fields, default_threads() if threads is None else threads,
                            key, reduce, chunk, rest)  # fmt: skip
    if errors == "raise":
        _raise_invalid(result, a, args["tip_shortening"])
    if gears is None:
        return result, None
    if rest is None:
        rest = {k: v for k, v in a.items() if k not in _LOAD_KEYS}
    return result, OnePair(rest, mats, gears)


def _raise_invalid(result, a=None, tip_shortening=True):
    """A GearError naming the first pair without a rating (row and reason), if any; a pair
    without method B's load point (reason 4) also names its pressure angle and the range where
    that point exists (from the checked arguments ``a``)."""
    valid = result.valid
    if type(valid) is np.bool_ and valid:  # one pair, rated
        return
    if not np.all(valid):
        bad = np.ravel(~np.asarray(result.valid))
        i = int(np.argmax(bad))
        where = f" (row {i})" if np.ndim(result.valid) else ""
        reason = int(np.ravel(result.reason)[i])
        hint = _load_point_range(a, i, np.shape(result.valid), tip_shortening) if (
            reason == 4 and a is not None) else ""  # fmt: skip
        raise GearError(f"no ISO 6336 rating{where}: {REASONS[reason]}{hint}")


def _load_point_range(a, i, shape, tip_shortening) -> str:
    """`` (pressure_angle = ... deg: ...)``: the pressure angle of row ``i`` and the smallest
    (to 0.1 deg, below 45) at which the outer points of single contact of both gears lie on
    their flanks (ISO 6336-3 §6.2), the rest of the pair kept; a small pressure angle gives a
    long path of contact (eps_alpha_n - 1 pitches past the tip reach the base circle)."""

    def row(key):
        return float(np.ravel(np.broadcast_to(a[key], shape))[i])

    z1, z2, m, x1, x2, pa, beta, ha = (row(k) for k in ("z1", "z2", "m", "x1", "x2", "pa",
                                                          "helix", "ha"))  # fmt: skip
    k1, k2 = row("k1"), row("k2")
    internal = bool(np.ravel(np.broadcast_to(a["internal"], shape))[i])
    short = bool(np.ravel(np.broadcast_to(np.asarray(tip_shortening, bool), shape))[i])
    grid = pa + 0.1 * np.arange(0, int((45.0 - pa) / 0.1))
    try:
        g = pair_geometry(z1, z2, m, x1, x2, grid, beta, internal, ha, short, threads=1)
    except GearError:
        return f" (pressure_angle = {pa:g} deg)"
    s = -1.0 if internal else 1.0
    cos_b = math.cos(math.radians(beta))
    at = np.arctan(np.tan(np.radians(grid)) / cos_b)
    d1, d2 = z1 * m / cos_b, z2 * m / cos_b
    da1 = g.tip_diameter_1 + 2 * m * k1
    da2 = g.tip_diameter_2 + 2 * s * m * k2
    tan_wt = np.tan(np.radians(g.working_pressure_angle))
    eps = contact_ratio(da1 / 2, da2 / 2, d1 * np.cos(at) / 2, d2 * np.cos(at) / 2, tan_wt, s,
                        np.pi * m / cos_b * np.cos(at))  # fmt: skip
    den1 = load_point(z1, m, da1, d1, grid, beta, eps, False)[0]
    den2 = load_point(z2, m, da2, d2, grid, beta, eps, internal)[0]
    ok = np.isfinite(den1) & np.isfinite(den2) & (eps >= 1.0)
    if not ok.any():
        return f" (pressure_angle = {pa:g} deg; no pressure angle below 45 deg puts it there)"
    return (
        f" (pressure_angle = {pa:g} deg gives eps_alpha = {eps[0]:.3f}; with the rest of this "
        f"pair kept, valid is pressure_angle >= {grid[int(np.argmax(ok))]:.1f} deg)"
    )


def _arguments(args):
    """The checked arguments of :func:`rate_pairs` as a dict of float arrays (overrides as
    ``o_<name>``) with the pairs' geometry, the two materials and, for one pair of plain
    arguments, the key its gears' part is kept by and its arguments but the load's (else
    None, None): those are then checked once."""
    key = plain_key(args, _NOT_KEYED)
    kept = _ARGUMENTS.get(key) if key is not None else None
    if kept is None:
        a, mats = _all_arguments(args)
        if key is None:
            return a, mats, None, None
        a = plain_numbers(a)
        if len(_ARGUMENTS) >= 256:
            _ARGUMENTS.clear()
        rest = {k: v for k, v in a.items() if k not in _LOAD_KEYS}
        _ARGUMENTS[key] = (rest, mats)
        return a, mats, key, rest
    rest, mats = kept
    a = dict(rest)
    a.update(_load_arguments(args))
    return a, mats, key, rest


def _load_arguments(args):
    """The load's arguments, checked: torque, speed, life, K_A, K_gamma."""
    return {
        "T": _number("torque", args["torque"], _MIN_TORQUE, 1e12, low_open=False),
        "n": _number("speed", args["speed"], 0.0, 1e7),
        "life": _number("life", args["life"], 0.0, 1e9),
        "K_A": _number("application_factor", args["application_factor"], 1.0, 100.0, False),
        "K_gamma": _number("load_sharing", args["load_sharing"], 1.0, 10.0, low_open=False),
    }


def _all_arguments(args):
    """Every argument checked, the geometry computed (or kept for one pair)."""
    m1, m2 = (material(v) for v in _pair_of("material", args["material"]))
    a = _checked(args, m1, m2)
    r1, r2 = _pair_of("root", args["root"]) if args["root"] is not None else (None, None)
    for i, r in ((1, r1), (2, r2)):
        if r is not None:
            if not isinstance(r, tuple | list) or len(r) != 4:
                raise GearError(f"root of gear {i} = {r!r}; give (s_Fn, rho_F, h_Fe, alpha_Fen)")
            for key, value, low in zip(("s_Fn", "rho_F", "h_Fe", "alpha_Fen"), r,
                                       (0.0, 0.0, 0.0, -1.6), strict=True):  # fmt: skip
                a[f"root_{key}{i}"] = _number(f"{key} of gear {i}", value, low, 1e6)
    a.update({f"o_{k}": v for k, v in _overrides(args["factors"]).items()})
    names = ("z1", "z2", "module", "x1", "x2", "pressure_angle", "helix_angle", "internal",
             "addendum", "tip_shortening", "threads")  # fmt: skip
    geo = args["geometry"]
    if geo is None:
        values = tuple(args[k] for k in names)
        one = all(type(v) in _PLAIN for v in values)  # one pair of plain numbers: kept
        geo = _GEOMETRY.get(values) if one else None
        if geo is None:
            geo = pair_geometry(*values)
            if one:
                if len(_GEOMETRY) >= 256:
                    _GEOMETRY.clear()
                _GEOMETRY[values] = geo
    # one pair's numbers stay Python numbers (gears.namespace.SCALAR); arrays become arrays
    base = [float(v) if type(v) is int or type(v) is float else np.asarray(v, float)
            for v in (*(args[k] for k in names[:7]), args["addendum"])]  # fmt: skip
    internal = args["internal"]
    base.append(internal if type(internal) is bool else np.asarray(internal, bool))
    a.update(zip(("z1", "z2", "m", "x1", "x2", "pa", "helix", "ha", "internal"), base, strict=True))
    a["alpha_wt"] = plain_or_array(geo.working_pressure_angle)
    a["k"] = plain_or_array(geo.tip_alteration)
    _per_module(a)
    return a, (m1, m2)


def _per_module(a):
    """The lengths a tooth of module m_n bounds: a face width of at least 0.1 m_n and a tip
    relief of at most 0.1 m_n (then converted to um)."""
    m = a["m"]
    checks = [("b", "face_width", a["b"] >= _MIN_WIDTH * m, f"face_width >= {_MIN_WIDTH:g} m_n")]
    if "C_a" in a:
        valid = f"0 <= tip_relief <= {_MAX_RELIEF:g} m_n"
        checks.append(("C_a", "tip_relief", a["C_a"] <= _MAX_RELIEF * m, valid))
    for key, name, good, valid in checks:
        if good if type(good) is np.bool_ or type(good) is bool else np.all(good):
            continue
        shape = np.shape(good)
        i = int(np.argmax(~np.ravel(good)))
        v, mi = (float(np.ravel(np.broadcast_to(x, shape))[i]) for x in (a[key], m))
        at = f" at row {i}" if shape else ""
        unit = " (tip relief is in mm: 5 um is 0.005)" if key == "C_a" else ""
        limit = (_MIN_WIDTH if key == "b" else _MAX_RELIEF) * mi
        raise GearError(
            f"{name} = {v:g} mm{at}; valid is {valid} = {limit:g} mm for m_n = {mi:g} mm{unit}"
        )
    if "C_a" in a:
        a["C_a"] = a["C_a"] * 1000.0  # um


def _checked(args, m1, m2):
    """The operating conditions, the tools and the allowable stresses, each checked."""
    h1, h2 = _pair_of("sigma_Hlim", args["sigma_Hlim"])
    f1, f2 = _pair_of("sigma_Flim", args["sigma_Flim"])
    c1, c2 = _pair_of("contacts", args["contacts"])
    i1, i2 = _pair_of("idler", args["idler"])
    k1, k2 = _pair_of("tip_alteration", args["tip_alteration"])
    hf1, hf2 = _pair_of("dedendum", args["dedendum"])
    rho1, rho2 = _pair_of("root_radius", args["root_radius"])
    if rho1 is None or rho2 is None:  # the Gear's default: ISO 53 A's, capped to fit the tool
        pa = _number("pressure_angle", args["pressure_angle"], 1.0, 45.0, False)
        rho1, rho2 = (
            np.minimum(BasicRack.root_radius, max_root_radius(pa, _number("dedendum", hf, 0, 10)))
            if rho is None else rho
            for rho, hf in ((rho1, hf1), (rho2, hf2))
        )  # fmt: skip
    spr1, spr2 = _pair_of("protuberance", args["protuberance"])
    roughness, root_roughness = args["roughness"], args["root_roughness"]
    root_roughness = roughness if root_roughness is None else root_roughness
    a = _load_arguments(args)
    a |= {
        "b": _number("face_width", args["face_width"], 0.0, 1e5),
        "Q": _number("quality", args["quality"], 1.0, 12.0, False, False, integer=True),
        "Ra": _number("roughness", roughness, _MIN_RA, 100.0, low_open=False),
        "Ra_root": _number("root_roughness", root_roughness, _MIN_RA, 100.0, low_open=False),
        "nu40": _number("oil_viscosity", args["oil_viscosity"], 0.0, 1e5),
        "edition": float(check_edition(args["edition"])),
        "c1": _number("contacts", c1, 1.0, 1e3, low_open=False),
        "c2": _number("contacts", c2, 1.0, 1e3, low_open=False),
        "idler1": i1 if type(i1) is bool else np.asarray(i1, bool),
        "idler2": i2 if type(i2) is bool else np.asarray(i2, bool),
        "k1": _number("tip_alteration", k1, -10.0, 10.0),
        "k2": _number("tip_alteration", k2, -10.0, 10.0),
        "hf1": _number("dedendum", hf1, 0.0, 10.0),
        "hf2": _number("dedendum", hf2, 0.0, 10.0),
        "rho1": _number("root_radius", rho1, 0.0, 10.0, low_open=False),
        "rho2": _number("root_radius", rho2, 0.0, 10.0, low_open=False),
        "spr1": _number("protuberance", spr1, 0.0, 1.0, low_open=False),
        "spr2": _number("protuberance", spr2, 0.0, 1.0, low_open=False),
        "sH1": _number("sigma_Hlim", m1.sigma_Hlim if h1 is None else h1, 1.0, 1e5, False),
        "sH2": _number("sigma_Hlim", m2.sigma_Hlim if h2 is None else h2, 1.0, 1e5, False),
        "sF1": _number("sigma_Flim", m1.sigma_Flim if f1 is None else f1, 1.0, 1e5, False),
        "sF2": _number("sigma_Flim", m2.sigma_Flim if f2 is None else f2, 1.0, 1e5, False),
    }
    if args["tip_relief"] is not None:
        a["C_a"] = _number("tip_relief", args["tip_relief"], 0.0, 10.0, low_open=False)
    if args["misalignment"] is not None:
        a["F_bx"] = _number("misalignment", args["misalignment"], 0.0, 1e5, low_open=False)
    return a


def _blocks(a, mats, fields, threads, key=None, reduce=None, chunk=_CHUNK, rest=None):
    """:func:`gears.rating._block.rate_block` on the whole broadcast, or on blocks of about
    ``chunk`` pairs (whole rows of the first axis) on ``threads`` threads, as
    :class:`PairRatings`, with one pair's gears' part (else None); each block handed to
    ``reduce`` when given (:func:`rate_reduced`); ``rest``, ``a`` but the load's arguments,
    where the caller has it."""
    if key is not None and reduce is None and all(type(a[k]) is float for k in _LOAD_KEYS):
        shape = ()  # one pair of plain arguments, its load one number each
    else:
        shape = common_shape({_public(k): np.shape(v) for k, v in a.items()})
    n = math.prod(shape)
    if n < 2 * chunk:
        one = n == 1 and shape == ()
        res = rate_block(a, mats, fields, _GEARS if one else None, key, rest)
        if one:
            return _one_result(res, fields)
        wanted = {"valid", "reason"} if reduce else {*fields, "valid", "reason"}  # others None
        if reduce is not None:
            reduce(res, 0, shape[0] if shape else 1)
        return PairRatings(
            **{f: np.broadcast_to(res[f], shape) if f in wanted else None for f in _FIELDS}
        ), None
    wanted = {"valid", "reason"} if reduce else {*fields, "valid", "reason"}  # others None
    out_shape, inner = shape, n // shape[0]
    if len(shape) > 1 and inner > chunk and reduce is None:  # rows too long: pairs one by one
        a = {k: v if np.ndim(v) == 0 else np.broadcast_to(v, shape).ravel() for k, v in a.items()}
        shape, inner = (n,), 1
    # blocks of whole rows along the first axis: an argument constant along it (a spectrum's
    # bins, shape (bins,) beside pairs of shape (pairs, 1)) is not copied to each row, and the
    # gears' part runs once per pair, not once per pair and bin
    rows = max(1, chunk // inner)
    lead = len(shape)
    part_of = {k: np.ndim(v) == lead and np.shape(v)[0] > 1 for k, v in a.items()}
    store = {f: np.empty(shape, bool if f == "valid" else int if f == "reason" else float)
             for f in wanted}  # fmt: skip

    def work(bounds):
        i0, i1 = bounds
        part = {k: v[i0:i1] if part_of[k] else v for k, v in a.items()}
        res = rate_block(part, mats, fields)
        for f, column in store.items():
            column[i0:i1] = res[f]
        if reduce is not None:
            reduce(res, i0, i1)

    def piece(bounds):
        """Rows p0:p1, whole blocks: their gears' part at once (long arrays, a call's cost
        spread over many pairs), then the load's part and ``reduce`` block by block."""
        p0, p1 = bounds
        part = {k: v[p0:p1] if part_of[k] else v for k, v in a.items()}
        gears = gears_part(part, mats)
        for i0 in range(p0, p1, rows):
            i1 = min(i0 + rows, p1)
            block = {k: v[i0 - p0 : i1 - p0] if part_of[k] else v for k, v in part.items()}
            res = load_part(rows_of(gears, i0 - p0, i1 - p0, p1 - p0, lead), block, mats, fields)
            for f, column in store.items():
                column[i0:i1] = res[f]
            reduce(res, i0, i1)

    blocks = list(itertools.pairwise([*range(0, shape[0], rows), shape[0]]))
    if reduce is not None and inner > 1:  # many loads a pair (a spectrum's bins): by pieces
        many = -(-shape[0] // (threads * _CHUNK))  # pieces a thread, of at most _CHUNK pairs
        per = -(-shape[0] // (threads * many))
        k = -(-per // rows)  # blocks a piece, of equal rows: the threads get equal work
        rows = -(-per // k)
        per = rows * k
        work = piece
        blocks = list(itertools.pairwise([*range(0, shape[0], per), shape[0]]))
    if threads == 1:
        for blk in blocks:
            work(blk)
    else:
        for _ in _pool(threads).map(work, blocks):
            pass
    return PairRatings(
        **{f: store[f].reshape(out_shape) if f in store else None for f in _FIELDS}
    ), None


def _one_result(res, fields):
    """One pair's :class:`PairRatings` from the dict of its rating, and its gears' part."""
    if len(fields) == len(_RESULTS):
        # numpy numbers, as for arrays: one array of the numbers, then its elements
        numbers = list(np.array(_ALL_RESULTS(res), float))
        result = PairRatings._make([*numbers, _number_of(res["valid"]), _number_of(res["reason"])])
    else:
        wanted = {*fields, "valid", "reason"}
        result = PairRatings(*(_number_of(res[f]) if f in wanted else None for f in _FIELDS))
    return result, res["gears"]


_ALL_RESULTS = operator.itemgetter(*_RESULTS)


def _number_of(v):
    """One pair's value as a numpy scalar."""
    t = type(v)
    if t is np.float64:
        return v
    if t is float:
        return np.float64(v)
    return np.asarray(v)[()]
