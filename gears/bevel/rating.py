"""Layer 4, bevel gears' load capacity by ISO 10300 method B1: :func:`bevel_rating` and its view
:class:`BevelRating` (the formulas as math: docs/bevel.md, "Load capacity").

ISO 10300 rates a bevel pair on its virtual cylindrical gears at the mean cone
(``BevelPair.virtual_pair``: z_v = z / cos delta, d_v = d_m / cos delta, the mean module).
:func:`bevel_rating` takes from ISO 10300 (:mod:`gears.bevel.iso10300`):

* the face load factors K_Hbeta = 1.5 K_Hbeta-be, K_Fbeta = K_Hbeta / K_F0 (K_F0 = 1 for
  straight teeth) from the mounting factor K_Hbeta-be (by ``mounting`` and ``pattern``);
* the contact stress of ISO 10300-2 method B1 on the middle contact line,
  sigma_H0 = sqrt(F_n / (l_bm rho_rel)) Z_M-B Z_LS Z_E, sigma_H = sigma_H0 sqrt(K_A K_v K_Hbeta
  K_Halpha), and the bevel gear factor Z_K on the permissible stress;
* the root stress of ISO 10300-3 method B1 for the load at the tip,
  sigma_F0 = F_mt / (b m_mn) Y_Fa Y_Sa Y_epsilon Y_BS Y_LS,
  sigma_F = sigma_F0 K_A K_v K_Fbeta K_Falpha;

and from ISO 6336 on the virtual pair (:meth:`gears.GearPair.rating`, which ISO 10300 follows or
refers to): K_v and K_Halpha (ISO 10300-1's method B is written on the same virtual gears, with
its own stiffness and mass; see docs/bevel.md), Z_E, Z_L, Z_v, Z_R, Z_W, Z_X, the material
values and the root's Y_ST, Y_deltarelT, Y_RrelT, Y_X and Y_M (an idler, ISO 6336-5). The load
cycles are the real gears' (60 n L per contact): Z_NT and Y_NT are taken at them, not at the
virtual speeds. Straight bevel gears only (the only kind geartrain builds); a crown or internal
bevel wheel is not rated.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from gears.arguments import check_real
from gears.bevel.iso10300 import face_load_factors, method_b1, mounting_factor
from gears.display import factor_lines, factor_text, html_table
from gears.errors import GearError
from gears.rating.life import bending_life_factor, pitting_life_factor
from gears.rating.materials import material as as_material
from gears.report import Finding, Report

__all__ = ["BEVEL_FACTORS", "BEVEL_QUANTITIES", "BevelRating", "bevel_rating"]

_B1 = "ISO 10300-2 B1"
_R1 = "ISO 10300-3 B1"
_ON_V = "ISO 6336 (virtual)"
#: The factors of a :class:`BevelRating`: symbol, per gear, what, where it comes from.
BEVEL_FACTORS = (
    ("K_A", False, "application factor (given)", "ISO 10300-1"),
    ("K_v", False, "dynamic factor, method B, virtual pair", "ISO 6336-1 §6.5"),
    ("K_Hbeta-be", False, "mounting factor", "ISO 10300-1 (table)"),
    ("K_Hbeta", False, "face load factor, contact: 1.5 K_Hbeta-be", "ISO 10300-1 C"),
    ("K_Fbeta", False, "face load factor, root: K_Hbeta / K_F0", "ISO 10300-1 C"),
    ("K_Halpha", False, "transverse load factor, contact, B", "ISO 6336-1 §8.3"),
    ("K_Falpha", False, "transverse load factor, root, B", "ISO 6336-1 §8.3"),
    ("Z_M-B", False, "mid-zone factor", _B1),
    ("Z_LS", False, "load sharing factor", _B1),
    ("Z_E", False, "elasticity factor, sqrt(MPa)", _ON_V),
    ("Z_K", False, "bevel gear factor (permissible stress)", _B1),
    ("Z_L", False, "lubricant factor", _ON_V),
    ("Z_v", False, "velocity factor", _ON_V),
    ("Z_R", False, "roughness factor", _ON_V),
    ("Z_W", True, "work hardening factor", _ON_V),
    ("Z_X", False, "size factor, contact", _ON_V),
    ("Z_NT", True, "life factor, contact (real load cycles)", "ISO 6336-2 §10"),
    ("Y_Fa", True, "tooth form factor, load at the tip", _R1),
    ("Y_Sa", True, "stress correction factor, load at the tip", _R1),
    ("Y_eps", False, "contact ratio factor, root", _R1),
    ("Y_BS", False, "bevel spiral angle factor (1: straight)", _R1),
    ("Y_LS", False, "load sharing factor, root: Z_LS^2", _R1),
    ("Y_ST", False, "stress correction of test gears", _ON_V),
    ("Y_NT", True, "life factor, root (real load cycles)", "ISO 6336-3 §12"),
    ("Y_deltarelT", True, "relative notch sensitivity factor", _ON_V),
    ("Y_RrelT", True, "relative surface factor", _ON_V),
    ("Y_X", True, "size factor, root", _ON_V),
    ("Y_M", True, "mean stress factor (idler 0.7)", "ISO 6336-5 §5.2"),
)
#: The quantities of a :class:`BevelRating`: symbol, per gear, what, unit.
BEVEL_QUANTITIES = (
    ("F_mt", False, "tangential force at the mean cone", "N"),
    ("F_n", False, "normal force at the mean point", "N"),
    ("v_mt", False, "pitch-line speed at the mean cone", "m/s"),
    ("z_v", True, "virtual teeth z / cos delta", ""),
    ("eps_valpha", False, "transverse contact ratio (virtual)", ""),
    ("eps_vbeta", False, "face contact ratio (virtual)", ""),
    ("b_veff", False, "effective face width", "mm"),
    ("f_max", False, "half the zone of action", "mm"),
    ("f_m", False, "middle contact line from the zone's centre", "mm"),
    ("l_bm", False, "length of the middle contact line", "mm"),
    ("rho_rel", False, "relative radius of curvature", "mm"),
    ("N_L", True, "load cycles over the life (real)", ""),
    ("s_Fn", True, "root chord at the tangent points", "mm"),
    ("rho_F", True, "root fillet radius there", "mm"),
    ("h_Fa", True, "bending moment arm, load at the tip", "mm"),
    ("alpha_Fan", True, "load direction angle at the tip", "deg"),
    ("q_s", True, "notch parameter s_Fn / (2 rho_F)", ""),
)


@dataclass(frozen=True)
class BevelRating:
    """ISO 10300 method B1 rating of one straight bevel mesh (gear 1 = the pinion).

    Attributes
    ----------
    pair : BevelPair
        The rated pair.
    values : dict
        Every number by its ISO symbol: the safeties ``S_H1`` ... ``S_F2``, the stresses, the
        factors (:data:`BEVEL_FACTORS`; per gear ``Z_NT1``, ``Z_NT2``, ...) and the quantities
        (:data:`BEVEL_QUANTITIES`).
    settings : dict
        The operating conditions and choices (torque and speed of the pinion, materials, life,
        mounting, pattern, ...).
    virtual : Rating
        The ISO 6336 rating of the virtual pair whose factors ISO 10300 shares.
    """

    pair: object
    values: dict
    settings: dict = field(default_factory=dict)
    virtual: object = None

    def _get(self, name: str) -> float:
        return float(self.values[name])

    def _pair(self, name: str) -> tuple[float, float]:
        return self._get(f"{name}1"), self._get(f"{name}2")

    @property
    def safety_pitting(self) -> tuple[float, float]:
        """``(S_H1, S_H2)``: safety against pitting of the pinion and the wheel."""
        return self._pair("S_H")

    @property
    def safety_bending(self) -> tuple[float, float]:
        """``(S_F1, S_F2)``: safety against tooth-root breakage of the pinion and the wheel."""
        return self._pair("S_F")

    @property
    def stresses(self) -> dict[str, float | tuple[float, float]]:
        """Stresses in MPa: ``sigma_H0``, ``sigma_H`` (one for both members), ``sigma_HP``
        (S_Hmin = 1), ``sigma_F0``, ``sigma_F``, ``sigma_FP`` (S_Fmin = 1) per gear."""
        return {
            "sigma_H0": self._get("sigma_H0"), "sigma_H": self._get("sigma_H"),
            "sigma_HP": self._pair("sigma_HP"), "sigma_F0": self._pair("sigma_F0"),
            "sigma_F": self._pair("sigma_F"), "sigma_FP": self._pair("sigma_FP"),
        }  # fmt: skip

    def _table(self, rows) -> dict[str, float | tuple[float, float]]:
        return {s: self._pair(s) if per else self._get(s) for s, per, *_ in rows}

    @property
    def factors(self) -> dict[str, float | tuple[float, float]]:
        """Every factor by its ISO symbol (:data:`BEVEL_FACTORS`), a pair ``(pinion, wheel)``
        where it is per gear."""
        return self._table(BEVEL_FACTORS)

    @property
    def quantities(self) -> dict[str, float | tuple[float, float]]:
        """Forces, speed, the virtual gears' contact ratios and contact lines, load cycles and
        the root at the tip load (:data:`BEVEL_QUANTITIES`)."""
        return self._table(BEVEL_QUANTITIES)

    def check(self, min_pitting: float = 1.0, min_bending: float = 1.4) -> Report:
        """Findings ``pitting_1``, ``pitting_2``, ``bending_1``, ``bending_2``: each safety
        against its minimum (margin ``S - S_min``). The minimums are numbers >= 0.

        >>> from gears import BevelPair
        >>> BevelPair(20, 40, module=3, face_width=20).rating(20, 1500).check().ok
        True
        """
        for name, minimum in (("min_pitting", min_pitting), ("min_bending", min_bending)):
            check_real(name, minimum, 0.0, low_open=False)
        out = []
        sh, shp = self._get("sigma_H"), self._pair("sigma_HP")
        sf, sfp = self._pair("sigma_F"), self._pair("sigma_FP")
        for i in (0, 1):
            s = self.safety_pitting[i]
            out.append(Finding(
                f"pitting_{i + 1}", s - min_pitting, f"S_H{i + 1} = {s:.3f} vs required "
                f"{min_pitting:g} (sigma_H = {sh:.1f} MPa, sigma_HP = {shp[i]:.1f} MPa)", unit="",
            ))  # fmt: skip
        for i in (0, 1):
            s = self.safety_bending[i]
            out.append(Finding(
                f"bending_{i + 1}", s - min_bending, f"S_F{i + 1} = {s:.3f} vs required "
                f"{min_bending:g} (sigma_F = {sf[i]:.1f} MPa, sigma_FP = {sfp[i]:.1f} MPa)",
                unit="",
            ))  # fmt: skip
        return Report(out)

    def _summary(self) -> list[str]:
        st, p = self.settings, self.pair
        return [
            f"ISO 10300 method B1 rating: straight bevel {p.z1}/{p.z2}, m_et = {p.module:g} mm, "
            f"b = {p.face_width:g} mm, shaft angle {p.shaft_angle:g} deg",
            f"torque {st['torque']:g} N m on the pinion at {st['speed']:g} rpm, life "
            f"{st['life']:g} h, materials {st['materials']}",
            f"{st['mounting']}, contact pattern checked {st['pattern']} (K_Hbeta-be "
            f"{self._get('K_Hbeta-be'):g}), b_eff = {st['effective_width']:g} b",
        ]

    def __str__(self) -> str:
        lines = [*self._summary(), "", f"{'':26s} {'pinion':>10s} {'wheel':>10s}"]
        for label, (a, b) in (("safety pitting S_H", self.safety_pitting),
                              ("safety bending S_F", self.safety_bending)):  # fmt: skip
            lines.append(f"{label:26s} {a:10.4f} {b:10.4f}")
        for name, value in self.stresses.items():
            a, b = value if isinstance(value, tuple) else (value, value)
            lines.append(f"{name + ' [MPa]':26s} {a:10.2f} {b:10.2f}")
        lines += factor_lines(
            [(s, self.factors[s], where, what) for s, _, what, where in BEVEL_FACTORS],
            [(s, self.quantities[s], f"{what} [{unit}]" if unit else what)
             for s, _, what, unit in BEVEL_QUANTITIES], "from", 19,
        )  # fmt: skip
        return "\n".join(lines)

    def __repr__(self) -> str:
        sh, sf = self.safety_pitting, self.safety_bending
        return f"BevelRating(S_H = {sh[0]:.3f} / {sh[1]:.3f}, S_F = {sf[0]:.3f} / {sf[1]:.3f})"

    def _repr_html_(self) -> str:
        """The safeties (a row marked when one is below :meth:`check`'s default minimum) and
        stresses, then every factor with its source and the quantities, as HTML tables."""
        failed = self.check().failed()
        rows = [("safety pitting S_H", *(f"{s:.4f}" for s in self.safety_pitting)),
                ("safety bending S_F", *(f"{s:.4f}" for s in self.safety_bending))]  # fmt: skip
        marks = [any(n.startswith("pitting") for n in failed),
                 any(n.startswith("bending") for n in failed)]  # fmt: skip
        for name, value in self.stresses.items():
            both = value if isinstance(value, tuple) else (value, value)
            rows.append((f"{name} [MPa]", *(f"{v:.2f}" for v in both)))
            marks.append(False)
        factors = [(s, factor_text(self.factors[s]), w, what) for s, _, what, w in BEVEL_FACTORS]
        quantities = [(s, factor_text(self.quantities[s]), f"{what} [{unit}]" if unit else what)
                      for s, _, what, unit in BEVEL_QUANTITIES]  # fmt: skip
        return "\n".join([
            html_table(["", "pinion", "wheel"], rows, failing=marks,
                       caption="; ".join(self._summary())),
            html_table(["factor", "value (pinion / wheel)", "from", "what"], factors),
            html_table(["quantity", "value (pinion / wheel)", "what"], quantities),
        ])  # fmt: skip


def _positive(name: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float | np.floating | np.integer):
        raise GearError(f"{name} = {value!r}; valid is a finite number > 0")
    return check_real(name, value, 0.0)


def bevel_rating(pair: Any, torque: float, speed: float, material: Any = "case-carburized", *,
                 life: float = 20000.0, mounting: str = "both-straddle",
                 pattern: str = "light-load", effective_width: float = 0.85,
                 contacts: tuple[int, int] = (1, 1), **options: Any) -> BevelRating:  # fmt: skip
    """The ISO 10300 method B1 rating of a straight bevel ``pair`` (a :class:`gears.BevelPair`)
    under ``torque`` N m on its pinion at ``speed`` rpm (module docstring).

    ``mounting`` (:data:`gears.bevel.iso10300.MOUNTINGS`) and ``pattern`` (how the contact
    pattern was checked, :data:`gears.bevel.iso10300.PATTERNS`) give the mounting factor
    K_Hbeta-be; ``effective_width`` is b_eff / b, the share of the face the loaded contact
    pattern covers (ISO 10300-1 takes 0.85 where it is not known); ``contacts`` the load cycles
    per turn of each gear. ``options`` go to :meth:`gears.GearPair.rating` of the virtual pair
    (``quality``, ``roughness``, ``oil_viscosity``, ``idler``, ``application_factor``, factors
    by symbol such as ``K_v=1.0``; ``K_Hbeta`` / ``K_Fbeta`` given replace the mounting
    factor's).
    """
    kbe = mounting_factor(mounting, pattern)
    t, n = _positive("torque", torque), _positive("speed", speed)
    life = _positive("life", life)
    if isinstance(effective_width, bool) or not isinstance(effective_width, int | float):
        raise GearError(f"effective_width = {effective_width!r}; valid is 0 < b_eff / b <= 1")
    w = check_real("effective_width", effective_width, 0.0, 1.0, high_open=False)
    for key in ("Z_NT", "Y_NT", "face_width", "spectrum"):
        if key in options:
            raise GearError(f"{key} is set by the bevel rating; it cannot be given")
    delta1, delta2 = pair.pitch_angles
    if not (delta1 < 90.0 and delta2 < 90.0):
        raise GearError(
            f"pitch angles {delta1:.4g} / {delta2:.4g} deg: a crown or internal bevel wheel "
            "(delta >= 90 deg) is not rated"
        )
    mats = material if isinstance(material, tuple | list) else (material, material)
    if len(mats) != 2:
        raise GearError(f"material = {material!r}; give one material or a pair")
    m1, m2 = (as_material(m) for m in mats)
    if not (isinstance(contacts, tuple | list) and len(contacts) == 2):
        raise GearError(f"contacts = {contacts!r}; valid is a pair of integers >= 1")
    vp = pair.virtual_pair
    eps = float(vp.contact_ratio)
    if not 1.0 < eps < 2.0:
        raise GearError(
            f"the virtual pair's transverse contact ratio eps_valpha = {eps:.4g}: ISO 10300 "
            "rates virtual gears with 1 < eps_valpha < 2"
        )
    c1 = math.cos(math.radians(delta1))
    # the real load cycles, on the real speeds (the virtual pinion turns at n cos delta_1)
    n_l = (60.0 * life * n * contacts[0], 60.0 * life * n * pair.z1 / pair.z2 * contacts[1])
    life_factors = {
        "Z_NT": (float(pitting_life_factor(n_l[0], m1.kind)),
                 float(pitting_life_factor(n_l[1], m2.kind))),
        "Y_NT": (float(bending_life_factor(n_l[0], m1.kind)),
                 float(bending_life_factor(n_l[1], m2.kind))),
    }  # fmt: skip
    kh, kf = (float(k) for k in face_load_factors(kbe))  # K_F0 = 1: straight teeth
    options.setdefault("K_Hbeta", kh)
    options.setdefault("K_Fbeta", options["K_Hbeta"] * kf / kh)
    b = float(pair.face_width)
    try:  # the factors ISO 10300 shares with ISO 6336, on the virtual pair
        r6 = vp.rating(t / c1, n * c1, (m1, m2), life=life, face_width=b,
                       contacts=tuple(contacts), **life_factors, **options)  # fmt: skip
    except GearError as exc:
        raise GearError(f"the virtual cylindrical pair of this bevel pair: {exc}") from None
    v = _iso10300(pair, vp, t, w, r6)
    bad = [k for k, x in v.items() if not math.isfinite(x)]
    if bad:  # a tooth the method cannot load (e.g. the tip load point of a stubby virtual gear)
        raise GearError(
            f"ISO 10300 method B1 does not apply to this pair: {bad[0]} = {v[bad[0]]} (z_v = "
            f"{vp.g1.teeth:.4g} / {vp.g2.teeth:.4g}, x_hm = {pair.profile_shift:g})"
        )
    v["N_L1"], v["N_L2"] = n_l
    v["K_Hbeta-be"] = kbe
    settings = {
        **r6.settings, "torque": t, "speed": n, "mounting": mounting, "pattern": pattern,
        "effective_width": w, "materials": m1.name if m1 == m2 else f"{m1.name} / {m2.name}",
    }  # fmt: skip
    return BevelRating(pair, v, settings, r6)


def _iso10300(pair, vp, torque: float, w: float, r6) -> dict:
    """The numbers of ISO 10300-2/-3 method B1 for a straight pair (:func:`method_b1`), with the
    factors it shares with ISO 6336 taken from ``r6``, the rating of the virtual pair ``vp``."""
    f6, s6 = r6.factors, r6.stresses
    gears = (vp.g1, vp.g2)
    x, xs = pair.profile_shift, pair.thickness_modification / 2.0  # ISO 10300-3 writes x_sm per
    v = method_b1(  # flank: half the s_m / m_m change BevelPair's thickness_modification writes
        torque, pair.geometry.mean_diameter[0], pair.face_width, pair.mean_module,
        pair.pressure_angle, [g.reference_diameter for g in gears],
        [g.tip_diameter for g in gears], [g.base_diameter for g in gears], vp.contact_ratio,
        (x, -x), (xs, -xs), pair.dedendum, [g.rack.root_radius for g in gears],
        [g.rack.protuberance for g in gears],
        [f6[k] for k in ("K_A", "K_v", "K_Hbeta", "K_Fbeta", "K_Halpha", "K_Falpha")],
        f6["Z_E"], s6["sigma_HP"], s6["sigma_FP"], w,
    )  # fmt: skip
    v = {k: float(a) for k, a in v.items()}
    for s, per, *_ in BEVEL_FACTORS:
        if s in f6 and s not in v:
            if per:
                v[f"{s}1"], v[f"{s}2"] = f6[s]
            else:
                v[s] = f6[s]
    v["v_mt"] = r6.quantities["v"]
    return v
