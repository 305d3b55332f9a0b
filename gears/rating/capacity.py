"""Layer 8, classes: :class:`Rating`, the ISO 6336 rating of one mesh as a thin view.

``GearPair.rating(...)`` calls :func:`rate_pair`, which gathers the pair's geometry, measures
the root of internal and shaper-cut gears on their real outline (:mod:`gears.rating.root`) and calls
the vectorised :func:`gears.rating.iso6336.rate_pairs` for the one pair; :class:`Rating` shows the
result: the safety factors, the stresses, every factor with its ISO symbol and clause, and a
:class:`gears.report.Report` against minimum safeties.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

from gears.display import factor_lines, factor_text, html_table
from gears.errors import GearError
from gears.rating._arrays import number, one_number
from gears.rating._arrays import pair_of as _pair_of
from gears.rating.bending import load_point
from gears.rating.iso6336 import (
    FACTORS,
    QUANTITIES,
    OnePair,
    PairRatings,
    check_edition,
    rate_again,
    rate_one,
)
from gears.rating.materials import material
from gears.rating.root import measure_root
from gears.rating.scuffing import Oil, ScuffingRatings, pair_scuffing
from gears.rating.spectrum import SpectrumRating, check_spectrum, spectrum_rating
from gears.report import Finding, Report

__all__ = [
    "MIN_SCUFFING",
    "ROOT_ROUTES",
    "Rating",
    "load_diameters",
    "rate_pair",
    "rate_pair_spectrum",
]

#: How the root form of each gear is found: ``"auto"`` (the standard's equations for rack-cut
#: external gears, measured on the exact envelope for internal and shaper-cut gears),
#: ``"standard"`` (ISO 6336-3's equations; the rack approximation for internal gears),
#: ``"measured"`` (exact envelopes) or ``"simulated"`` (simulated cuts, spur gears).
ROOT_ROUTES = ("auto", "standard", "measured", "simulated")

#: Default minimum safeties against scuffing (S_Bmin, S_intSmin) of :meth:`Rating.check`.
MIN_SCUFFING = (2.0, 1.8)


def _field(symbol: str) -> str:
    return symbol.replace("'", "_prime")


@dataclass(frozen=True)
class Rating:
    """ISO 6336 method B rating of one mesh (gear 1 = the pair's g1).

    Attributes
    ----------
    pair : GearPair
        The rated pair.
    values : PairRatings
        Every number of :func:`gears.rating.iso6336.rate_pairs` for this pair.
    settings : dict
        The operating conditions and choices (torque, speed, materials, life, ...).
    roots : (str, str)
        How each gear's root form was found (``"ISO 6336-3 (rack)"``, ``"measured (exact
        envelope)"``, ...).
    kept : OnePair or None
        The rating's checked arguments but the load's and its gears' part
        (:class:`gears.rating.iso6336.OnePair`), which :meth:`at` rates at another load.
    scuffing : ScuffingRatings or None
        The scuffing rating (ISO/TS 6336-20 and -21) when an oil was given (``scuffing=``).
    """

    pair: object
    values: PairRatings
    settings: dict = field(default_factory=dict)
    roots: tuple[str, str] = ("", "")
    kept: OnePair | None = field(default=None, repr=False, compare=False)
    scuffing: ScuffingRatings | None = None

    def at(
        self, torque: float | None = None, speed: float | None = None, *,
        life: float | None = None, application_factor: float | None = None,
    ) -> Rating:  # fmt: skip
        """The same mesh rated at another load: ``torque`` (N m on gear 1), ``speed`` (rpm),
        ``life`` (h) and ``application_factor`` K_A, each this rating's where not given.

        Equals ``pair.rating(...)`` with this rating's other settings at that load; only the
        load's part runs again (F_t, v, K_v, K_Hbeta, K_alpha, Z_L, Z_v, Z_W, the life factors,
        the stresses; :attr:`kept` holds the rest), the fastest way to rate one pair at many
        loads. Every factor given to the first rating stays as given (a K_Hbeta or K_Halpha
        from the contact analysis was found at the first torque: rate again with
        ``pair.rating`` for it).

        >>> from gears import Gear, GearPair
        >>> r = GearPair(Gear(20, 3, face_width=30), Gear(50, 3, face_width=30)).rating(200, 1500)
        >>> [round(s, 3) for s in r.at(100).safety_bending]
        [5.519, 5.983]
        """
        st = self.settings
        load = {"torque": st.get("torque") if torque is None else torque,
                "speed": st.get("speed") if speed is None else speed,
                "life": st.get("life") if life is None else life,
                "application_factor": (st.get("application_factor") if application_factor is None
                                       else application_factor)}  # fmt: skip
        for name, v in load.items():
            if type(v) is not float and type(v) is not int:
                one_number(name, v)
        if self.kept is None:
            raise GearError("this Rating keeps no gears' part to rate again: use pair.rating")
        values = rate_again(self.kept, load_sharing=1.0, **load)
        settings = dict(st)
        settings.update({k: float(v) for k, v in load.items()})
        scuff = None
        if self.scuffing is not None:  # the oil's rating at the new load
            scuff = pair_scuffing(self.pair, values, *st["scuffing"])
        return Rating(self.pair, values, settings, self.roots, self.kept, scuff)

    def _get(self, name: str) -> float:
        return float(getattr(self.values, name))

    @property
    def edition(self) -> int:
        """The edition of ISO 6336-1/-2/-3 the rating follows, 2019 or 2006
        (:data:`gears.rating.bending.EDITIONS`)."""
        return int(self.settings.get("edition", 2019))

    @property
    def safety_pitting(self) -> tuple[float, float]:
        """``(S_H1, S_H2)``: safety against pitting of gear 1 and gear 2."""
        return self._get("S_H1"), self._get("S_H2")

    @property
    def safety_bending(self) -> tuple[float, float]:
        """``(S_F1, S_F2)``: safety against tooth-root breakage of gear 1 and gear 2."""
        return self._get("S_F1"), self._get("S_F2")

    @property
    def safety_scuffing(self) -> tuple[float, float] | None:
        """``(S_B, S_intS)``: safety against scuffing by the flash temperature method
        (ISO/TS 6336-20) and by the integral temperature method (ISO/TS 6336-21); None
        without an oil (``scuffing=``)."""
        if self.scuffing is None:
            return None
        return float(self.scuffing.S_B), float(self.scuffing.S_intS)

    @property
    def temperatures(self) -> dict[str, float] | None:
        """The scuffing rating's temperatures (deg C; flash temperatures in K) and where the
        flash temperature peaks (:class:`gears.rating.scuffing.ScuffingRatings`); None without
        an oil."""
        if self.scuffing is None:
            return None
        keys = ("theta_B", "theta_flmax", "gamma_flmax", "d_flmax", "theta_flm", "theta_M",
                "theta_S", "mu_m", "theta_flaint", "theta_M_int", "theta_int", "theta_intS",
                "mu_mC")  # fmt: skip
        return {k: float(getattr(self.scuffing, k)) for k in keys}

    @property
    def stresses(self) -> dict[str, float | tuple[float, float]]:
        """Stresses in MPa: ``sigma_H0``, ``sigma_H``, ``sigma_HP`` (for S_Hmin = 1),
        ``sigma_F0``, ``sigma_F``, ``sigma_FP`` (S_Fmin = 1); a pair where per gear."""
        g = self._get
        return {
            "sigma_H0": g("sigma_H0"),
            "sigma_H": (g("sigma_H1"), g("sigma_H2")),
            "sigma_HP": (g("sigma_HP1"), g("sigma_HP2")),
            "sigma_F0": (g("sigma_F01"), g("sigma_F02")),
            "sigma_F": (g("sigma_F1"), g("sigma_F2")),
            "sigma_FP": (g("sigma_FP1"), g("sigma_FP2")),
        }

    def _table(self, rows) -> dict[str, float | tuple[float, float]]:
        out = {}
        for symbol, per_gear, *_ in rows:
            name = _field(symbol)
            if per_gear:
                out[symbol] = (self._get(f"{name}1"), self._get(f"{name}2"))
            else:
                out[symbol] = self._get(name)
        return out

    @property
    def factors(self) -> dict[str, float | tuple[float, float]]:
        """Every factor by its ISO symbol in ASCII (``"Z_H"``, ``"K_Hbeta"``, ``"c'"``, ...;
        :data:`gears.rating.iso6336.FACTORS`), a pair ``(gear 1, gear 2)`` where it is per gear."""
        return self._table(FACTORS)

    @property
    def quantities(self) -> dict[str, float | tuple[float, float]]:
        """F_t (N), v (m/s), the resonance ratio N, contact ratios, load cycles N_L and the root
        form s_Fn, rho_F, h_Fe (mm), alpha_Fen (deg), q_s
        (:data:`gears.rating.iso6336.QUANTITIES`)."""
        return self._table(QUANTITIES)

    def check(self, min_pitting: float = 1.0, min_bending: float = 1.4,
              min_scuffing: tuple[float, float] = MIN_SCUFFING) -> Report:  # fmt: skip
        """Findings ``pitting_1``, ``pitting_2``, ``bending_1``, ``bending_2`` and, with an oil,
        ``scuffing_flash`` and ``scuffing_integral``: each safety against its minimum (margin
        ``S - S_min``). The minimums are numbers >= 0; ``min_scuffing`` is (S_Bmin, S_intSmin).

        >>> from gears import Gear, GearPair
        >>> p = GearPair(Gear(20, 3, face_width=30), Gear(50, 3, face_width=30))
        >>> p.rating(200, 1500).check().ok
        True
        """
        out = []
        s_b, s_int = _pair_of("min_scuffing", min_scuffing)
        for name, minimum in (("min_pitting", min_pitting), ("min_bending", min_bending),
                              ("min_scuffing", s_b), ("min_scuffing", s_int)):  # fmt: skip
            if (
                isinstance(minimum, bool)
                or not isinstance(minimum, int | float)
                or not (math.isfinite(minimum) and minimum >= 0)
            ):
                raise GearError(f"{name} = {minimum!r}; valid is a number >= 0")
        stress = self.stresses
        for kind, safeties, minimum, s, p, what in (
            ("pitting", self.safety_pitting, min_pitting, "sigma_H", "sigma_HP", "S_H"),
            ("bending", self.safety_bending, min_bending, "sigma_F", "sigma_FP", "S_F"),
        ):
            for i in (0, 1):
                sf = safeties[i]
                out.append(
                    Finding(
                        f"{kind}_{i + 1}", sf - minimum,
                        f"{what}{i + 1} = {sf:.3f} vs required {minimum:g} ({s} = "
                        f"{stress[s][i]:.1f} MPa, {p} = {stress[p][i]:.1f} MPa)", unit="",
                    )
                )  # fmt: skip
        if self.scuffing is not None:
            t = self.temperatures
            for name, safety, minimum, what in (
                ("scuffing_flash", self.safety_scuffing[0], s_b,
                 f"S_B = {self.safety_scuffing[0]:.3f} vs required {s_b:g} (contact temperature "
                 f"theta_B = {t['theta_B']:.1f} C, scuffing temperature theta_S = "
                 f"{t['theta_S']:.1f} C; ISO/TS 6336-20)"),
                ("scuffing_integral", self.safety_scuffing[1], s_int,
                 f"S_intS = {self.safety_scuffing[1]:.3f} vs required {s_int:g} (integral "
                 f"temperature theta_int = {t['theta_int']:.1f} C, scuffing integral temperature "
                 f"theta_intS = {t['theta_intS']:.1f} C; ISO/TS 6336-21)"),
            ):  # fmt: skip
                out.append(Finding(name, safety - minimum, what, unit=""))
        return Report(out)

    def _summary(self) -> list[str]:
        """The pair, the operating conditions, the root-form routes and the edition, one line
        each."""
        st = self.settings
        g1, g2 = self.pair.g1, self.pair.g2
        kind = "internal" if getattr(g2, "internal", False) else "external"
        return [
            f"ISO 6336 method B rating: {g1.teeth}/{g2.teeth} ({kind}), m_n = {g1.module:g} mm, "
            f"b = {st.get('face_width', float('nan')):g} mm",
            f"torque {st.get('torque', float('nan')):g} N m on gear 1 at "
            f"{st.get('speed', float('nan')):g} rpm, life {st.get('life', float('nan')):g} h, "
            f"materials {st.get('materials', '?')}",
            f"root form: gear 1 {self.roots[0]}, gear 2 {self.roots[1]}",
            f"edition: ISO 6336-1/-2/-3:{self.edition}",
        ]

    def __str__(self) -> str:
        lines = [
            *self._summary(),
            "",
            f"{'':26s} {'gear 1':>10s} {'gear 2':>10s}",
            f"{'safety pitting S_H':26s} {self.safety_pitting[0]:10.4f} "
            f"{self.safety_pitting[1]:10.4f}",
            f"{'safety bending S_F':26s} {self.safety_bending[0]:10.4f} "
            f"{self.safety_bending[1]:10.4f}",
        ]
        if self.scuffing is not None:
            lines.append(f"{'scuffing S_B (flash)':26s} {self.safety_scuffing[0]:10.4f}")
            lines.append(f"{'scuffing S_intS (integral)':26s} {self.safety_scuffing[1]:10.4f}")
            for key, value in self.temperatures.items():
                lines.append(f"{key:26s} {value:10.4g}")
        for name, value in self.stresses.items():
            if isinstance(value, tuple):
                lines.append(f"{name + ' [MPa]':26s} {value[0]:10.2f} {value[1]:10.2f}")
            else:
                lines.append(f"{name + ' [MPa]':26s} {value:10.2f}")
        lines += factor_lines(
            [(s, self.factors[s], clause, what) for s, _, what, clause in FACTORS],
            [(s, self.quantities[s], f"{what} [{unit}]" if unit else what)
             for s, _, what, unit in QUANTITIES], "clause", 16,
        )  # fmt: skip
        return "\n".join(lines)

    def __repr__(self) -> str:
        sh, sf = self.safety_pitting, self.safety_bending
        return f"Rating(S_H = {sh[0]:.3f} / {sh[1]:.3f}, S_F = {sf[0]:.3f} / {sf[1]:.3f})"

    def _repr_html_(self) -> str:
        """What a notebook shows: the safeties (a row marked when a safety is below the default
        minimum of :meth:`check`) and stresses per gear, then every factor with its ISO clause
        and the quantities, as HTML tables under the pair and its operating conditions."""
        failed = self.check().failed()
        rows = [
            ("safety pitting S_H", *(f"{s:.4f}" for s in self.safety_pitting)),
            ("safety bending S_F", *(f"{s:.4f}" for s in self.safety_bending)),
        ]
        marks = [any(n.startswith("pitting") for n in failed),
                 any(n.startswith("bending") for n in failed)]  # fmt: skip
        if self.scuffing is not None:  # one value per mesh: shown in the gear 1 column
            shown = (("scuffing S_B (flash)", "scuffing_flash", 0),
                     ("scuffing S_intS (integral)", "scuffing_integral", 1))  # fmt: skip
            for label, key, safety in shown:
                rows.append((label, f"{self.safety_scuffing[safety]:.4f}", ""))
                marks.append(key in failed)
            t = self.temperatures
            rows.append(("theta_B / theta_S [C]", f"{t['theta_B']:.1f}", f"{t['theta_S']:.1f}"))
            rows.append(("theta_int / theta_intS [C]", f"{t['theta_int']:.1f}",
                         f"{t['theta_intS']:.1f}"))  # fmt: skip
            marks += [False, False]
        for name, value in self.stresses.items():
            both = value if isinstance(value, tuple) else (value, value)
            rows.append((f"{name} [MPa]", *(f"{v:.2f}" for v in both)))
            marks.append(False)
        factors = [(s, factor_text(self.factors[s]), clause, what)
                   for s, _, what, clause in FACTORS]  # fmt: skip
        quantities = [(s, factor_text(self.quantities[s]), f"{what} [{unit}]" if unit else what)
                      for s, _, what, unit in QUANTITIES]  # fmt: skip
        return "\n".join([
            html_table(["", "gear 1", "gear 2"], rows, failing=marks,
                       caption="; ".join(self._summary())),
            html_table(["factor", "value (gear 1 / gear 2)", "clause", "what"], factors),
            html_table(["quantity", "value (gear 1 / gear 2)", "what"], quantities),
        ])  # fmt: skip


def load_diameters(pair) -> tuple[float, float]:
    """``(d_en1, d_en2)``: where method B loads each gear of ``pair`` (as mounted), the outer
    point of single contact on its virtual spur gear (:func:`gears.rating.bending.load_point`); NaN
    where that point lies inside the base circle.

    >>> from gears import Gear, GearPair
    >>> [round(d, 4) for d in load_diameters(GearPair(Gear(20, 2), Gear(40, 2)))]
    [40.6096, 80.9323]
    """
    eps = pair.contact_ratio
    out = []
    for gear in pair.mounted:
        d_en = load_point(gear.teeth, gear.module, gear.tip_diameter, gear.reference_diameter,
                          gear.pressure_angle, gear.helix_angle, eps, gear.internal)[0]  # fmt: skip
        out.append(float(d_en))
    return out[0], out[1]


@functools.lru_cache(maxsize=256)
def _measured(gear, d_en: float, method: str):
    """The measured root of ``gear`` (cached: a torque sweep measures each gear once)."""
    return measure_root(gear, d_en, "exact" if method == "measured" else "simulated")


def rate_pair(
    pair, torque, speed, material_="case-carburized", *, life=20000.0, application_factor=1.0,
    quality=6, roughness=1.0, oil_viscosity=220.0, tip_relief=None, sigma_Hlim=None,
    sigma_Flim=None, face_width=None, contacts=(1, 1), idler=(False, False), misalignment=None,
    root="auto", root_roughness=None, scuffing=None, welding_factor=1.0, edition=2019,
    **factors,
) -> Rating:  # fmt: skip
    """The :class:`Rating` of ``pair`` (see :meth:`gears.GearPair.rating` for the parameters).

    ``face_width`` (mm) defaults to the smaller of the gears' face widths; ``root`` is one of
    :data:`ROOT_ROUTES`; ``contacts`` and ``idler`` are those of
    :func:`gears.rating.iso6336.rate_pairs` (a planet, a sun meshing several planets).
    """
    _one_pair(locals(), factors)
    edition = check_edition(edition)
    if scuffing is not None and not isinstance(scuffing, Oil):
        raise GearError(
            f"scuffing = {scuffing!r}; give the oil: gears.rating.scuffing.Oil(fzg_stage=..., "
            "temperature=..., viscosity_40=..., viscosity_100=...)"
        )
    if getattr(pair, "is_rack", False):
        raise GearError("a pinion-and-rack pair has no ISO 6336 rating here; rate a gear pair")
    if root not in ROOT_ROUTES:
        raise GearError(f"root = {root!r}; valid are {', '.join(map(repr, ROOT_ROUTES))}")
    g1, g2 = pair.mounted
    if face_width is None:
        widths = [w for w in (pair.g1.face_width, pair.g2.face_width) if w]
        if not widths:
            raise GearError("face_width = None: give face_width (mm) or set the gears' face widths")
        face_width = min(widths)
    b = float(number("face_width", face_width, 0.0, 1e5))
    mats = material_ if isinstance(material_, tuple | list) else (material_, material_)
    if len(mats) != 2:
        raise GearError(f"material = {material_!r}; give one material or a pair")
    m1, m2 = (material(m) for m in mats)
    # the root of each gear: the standard's equations or measured on its real tooth
    roots, routes = [None, None], ["", ""]
    for i, gear in enumerate((g1, g2)):
        shaper = gear.internal or gear.cutter is not None
        route = root if root != "auto" else ("measured" if shaper else "standard")
        if route == "standard":
            routes[i] = "ISO 6336-3 rack approximation" if gear.internal else "ISO 6336-3 (rack)"
            continue
        d_en = load_diameters(pair)[i]
        if not math.isfinite(d_en):
            raise GearError(
                f"gear {i + 1}: the outer point of single contact lies inside the base circle of "
                "the virtual gear: method B's Y_F does not apply"
            )
        form = _measured(gear, round(d_en, 9), route)
        roots[i] = form.standard
        cutter = "shaper" if shaper else "rack"
        where = "exact envelope" if route == "measured" else "simulated cut"
        routes[i] = f"measured on the {where} ({cutter}-cut)"
    values, kept = rate_one(
        z1=g1.teeth, z2=g2.teeth, module=g1.module, face_width=b, torque=torque, speed=speed,
        x1=g1.profile_shift,
        x2=g2.profile_shift, pressure_angle=g1.pressure_angle, helix_angle=g1.helix_angle,
        internal=g2.internal, material=(m1, m2), sigma_Hlim=sigma_Hlim, sigma_Flim=sigma_Flim,
        life=life, application_factor=application_factor, quality=quality, roughness=roughness,
        oil_viscosity=oil_viscosity, tip_relief=tip_relief, contacts=contacts, idler=idler,
        root_roughness=root_roughness,
        misalignment=misalignment, addendum=g1.rack.addendum,
        dedendum=(g1.rack.dedendum, g2.rack.dedendum),
        root_radius=(g1.rack.root_radius, g2.rack.root_radius),
        protuberance=(g1.rack.protuberance, g2.rack.protuberance),
        tip_shortening=pair.tip_shortening,
        tip_alteration=(pair.g1.tip_alteration, pair.g2.tip_alteration), root=tuple(roots),
        factors=factors, edition=edition, errors="raise", threads=1, geometry=pair._geometry,
    )  # fmt: skip
    settings = {
        "torque": float(torque), "speed": float(speed), "life": float(life), "face_width": b,
        "materials": m1.name if m1 == m2 else f"{m1.name} / {m2.name}",
        "application_factor": application_factor, "quality": quality, "roughness": roughness,
        "root_roughness": roughness if root_roughness is None else root_roughness,
        "oil_viscosity": oil_viscosity, "tip_relief": tip_relief, "contacts": contacts,
        "idler": idler, "given": dict(factors), "edition": edition,
    }  # fmt: skip
    scuff = None
    if scuffing is not None:
        c1, c2 = contacts
        meshes = max(int(c1), int(c2), 2 if any(idler) else 1)  # X_mp of the busiest gear
        scuff = pair_scuffing(pair, values, scuffing, b, roughness, (m1, m2), welding_factor,
                              meshes, tip_relief)  # fmt: skip
        settings |= {
            "oil": scuffing,
            "welding_factor": welding_factor,
            "scuffing": (scuffing, b, roughness, (m1, m2), welding_factor, meshes, tip_relief),
        }
    return Rating(pair, values, settings, (routes[0], routes[1]), kept, scuff)


def rate_pair_spectrum(pair, spectrum, material_="case-carburized", **options) -> SpectrumRating:
    """``pair.rating(spectrum=...)``: the first bin rated by :func:`rate_pair` (life = its
    hours), the others by :meth:`Rating.at` on the gears' part it kept (each bin a load of its
    own, ISO 6336-6), then Miner's rule (:func:`gears.rating.spectrum.spectrum_rating`)."""
    if "contact" in (options.get("K_Hbeta"), options.get("K_Halpha")):
        raise GearError('K_Hbeta="contact" / K_Halpha="contact" take the contact analysis '
                        "at one torque: give torque and speed, not spectrum=")  # fmt: skip
    rows = list(zip(*(b.tolist() for b in check_spectrum(spectrum)), strict=True))
    (t, n, h), rest = rows[0], rows[1:]
    first = rate_pair(pair, t, n, material_, life=h, **options)
    ratings = [first, *(first.at(t, n, life=h) for t, n, h in rest)]
    return spectrum_rating(ratings, material_, rows)


_ONE = ("torque", "speed", "life", "application_factor", "quality", "roughness", "oil_viscosity",
        "tip_relief", "face_width", "misalignment", "root_roughness", "welding_factor")  # fmt: skip
_PER_GEAR = ("sigma_Hlim", "sigma_Flim", "contacts", "idler")


def _one_pair(args: dict, factors: dict) -> None:
    """Every value of one pair's rating is one number (or a pair of them): arrays belong to
    :func:`gears.rating.iso6336.rate_pairs`."""
    for name in _ONE:
        v = args[name]
        if v is not None and type(v) is not float and type(v) is not int:
            one_number(name, v)
    for name, value in (*((n, args[n]) for n in _PER_GEAR), *factors.items()):
        for v in value if isinstance(value, tuple | list) else (value,):
            if (
                v is not None
                and type(v) is not float
                and type(v) is not int
                and type(v) is not bool
            ):
                one_number(name, v)
