"""Layer 5, sizing: what carries a load, over arrays: the smallest face width of a set that
meets the minimum safeties, the gears' volume and mass, the ISO 54 module series (issue 20),
and the rating of many pairs under a load spectrum (:func:`rate_spectrum`, ISO 6336-6).

A :class:`Load` is one load case and its demands, checked once: the torque on gear 1 (N m),
its speed (rpm), the materials, the life (h), the minimum safeties against pitting and
bending, and every other option of ``GearPair.rating`` (``quality``, ``application_factor``,
factors such as ``K_v=1.0``). :func:`rate` rates arrays of rack-cut pairs under it with
:func:`gears.rating.iso6336.rate_pairs`, the function ``GearPair.rating`` calls for one pair, with
ISO 6336-3's root form of every gear (a ring by the standard's rack approximation: the
``root="standard"`` route of ``GearPair.rating``); :func:`smallest_width` finds the smallest
face width of a set at which each pair meets the safeties. The design searches
(:func:`gears.search.engine.pairs`, ``trains.synthesize_gearbox``) size their candidates with these.

Volume is the material of each gear's pitch cylinder, ``pi/4 d^2 b`` (d = z m_n / cos beta), and
for a ring the annulus from its reference circle out to a rim of :data:`RING_RIM` modules below
its root circle (the rim ISO 6336-3 §9 asks of an internal gear for Y_B = 1, which the rating
takes); mass is volume times the material's density.
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from gears.arguments import common_shape
from gears.errors import GearError
from gears.geometry import reference_diameter, root_diameter
from gears.rating._arrays import shown
from gears.rating.iso6336 import FACTORS, PairRatings, rate_pairs, rate_reduced
from gears.rating.losses import pair_losses
from gears.rating.materials import Material, material
from gears.rating.miner import SpectrumRatings, _combine, check_spectrum

__all__ = [
    "ISO54",
    "ISO54_SECOND",
    "MIN_SAFETY",
    "RATING_OPTIONS",
    "RING_RIM",
    "Load",
    "gear_volume",
    "load_case",
    "pair_volume",
    "rate",
    "rate_spectrum",
    "smallest_width",
]

#: ISO 54:1996 normal modules, series I (preferred), mm
ISO54 = (1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 16.0, 20.0, 25.0, 32.0,
         40.0, 50.0)  # fmt: skip
#: ISO 54:1996 normal modules, series II (second choice), mm
ISO54_SECOND = (1.125, 1.375, 1.75, 2.25, 2.75, 3.5, 4.5, 5.5, 7.0, 9.0, 11.0, 14.0, 18.0, 22.0,
                28.0, 36.0, 45.0)  # fmt: skip
#: minimum safeties by default (``Rating.check``'s): pitting S_H >= 1.0, bending S_F >= 1.4
MIN_SAFETY = {"pitting": 1.0, "bending": 1.4}
#: rim below a ring's root circle, in modules, counted in its volume (ISO 6336-3:2006 §9: an
#: internal gear's Y_B is 1 for a rim s_R >= 3.5 m_n)
RING_RIM = 3.5
#: the options of ``GearPair.rating`` a :class:`Load` passes to
#: :func:`gears.rating.iso6336.rate_pairs`
#: (besides torque, speed, material, life and face_width); any other keyword is a factor
RATING_OPTIONS = (
    "application_factor", "quality", "roughness", "oil_viscosity", "tip_relief", "sigma_Hlim",
    "sigma_Flim", "contacts", "idler", "misalignment", "root", "root_roughness", "edition",
)  # fmt: skip
#: the options GearPair.rating takes as one number each (a search applies them to every pair)
_ONE_NUMBER = ("application_factor", "quality", "roughness", "oil_viscosity", "tip_relief",
               "misalignment", "root_roughness")  # fmt: skip
_FACTOR_NAMES = tuple(f[0] for f in FACTORS)
_SAFETIES = ("S_H1", "S_H2", "S_F1", "S_F2")


@dataclass(frozen=True)
class Load:
    """One load case and its demands (see :func:`load_case`, which checks them).

    Attributes
    ----------
    torque : float
        Torque on gear 1, N m.
    speed : float
        Speed of gear 1, rpm.
    materials : (Material, Material)
    life : float
        Hours.
    min_pitting, min_bending : float
        Minimum safeties S_H and S_F of both gears.
    options : dict
        Further keyword arguments of :func:`gears.rating.iso6336.rate_pairs` (``quality``,
        ``factors``).
    spectrum : tuple of (torque, speed, hours), optional
        A load spectrum (ISO 6336-6) instead of one load: the safeties are its equivalent
        safeties (:func:`gears.rating.spectrum.rate_spectrum`); ``torque`` and ``speed`` are
        then its bin of the largest torque and ``life`` its hours.
    """

    torque: float
    speed: float
    materials: tuple[Material, Material]
    life: float = 20000.0
    min_pitting: float = MIN_SAFETY["pitting"]
    min_bending: float = MIN_SAFETY["bending"]
    options: dict = field(default_factory=dict)
    spectrum: tuple | None = None

    @property
    def density(self) -> tuple[float, float]:
        """Both materials' densities, kg/mm^3."""
        return self.materials[0].density, self.materials[1].density

    def rating_options(self) -> dict[str, Any]:
        """The keyword arguments of ``GearPair.rating`` that reproduce this load case (with
        ``root="standard"``, the route the searches rate by)."""
        out = {k: v for k, v in self.options.items() if k != "factors"}
        out.update(self.options.get("factors", {}))
        if self.spectrum is not None:
            out["spectrum"] = [list(b) for b in self.spectrum]
        else:
            out["life"] = self.life
        out["root"] = "standard"
        return out

    def efficiency(self, z1, z2, module, face_width, x1=0.0, x2=0.0, pressure_angle=20.0,
                   helix_angle=0.0, internal=False, rack=None,
                   tip_shortening=True) -> np.ndarray:  # fmt: skip
        """The mesh efficiency of rack-cut pairs under this load (ISO/TR 14179-2,
        :func:`gears.rating.losses.pair_losses` with ``GearPair.efficiency``'s oil and the
        load's flank roughness; arrays broadcast). Under a spectrum, the energy's: one less
        the energy lost over the energy transmitted, sum(P_i h_i (1 - eta_i)) / sum(P_i h_i).
        A pair the friction equation does not apply to gets 0."""
        if np.size(z1) == 0:  # no pairs
            return np.zeros(0)
        bins = self.spectrum if self.spectrum is not None else ((self.torque, self.speed, 1.0),)
        torques, speeds, hours = (np.array(v, float) for v in zip(*bins, strict=True))
        columns = [np.asarray(v)[..., None] if np.ndim(v) else v
                   for v in (z1, z2, module, face_width, x1, x2)]  # fmt: skip
        geometry = dict(pressure_angle=pressure_angle, helix_angle=helix_angle,
                        internal=internal, tip_shortening=tip_shortening)  # fmt: skip
        if rack is not None:
            geometry["addendum"] = rack.addendum
        r = pair_losses(torques, speeds, *columns, roughness=self.options.get("roughness", 1.0),
                        errors="mask", **geometry)  # fmt: skip
        energy = torques * speeds * hours  # proportional to P_i h_i
        lost = np.sum(np.where(r.efficiency > 0.0, 1.0 - r.efficiency, 1.0) * energy, axis=-1)
        return np.asarray(1.0 - lost / energy.sum())[()]

    def meets(self, r: PairRatings) -> np.ndarray:
        """True where both gears meet both minimum safeties (a pair with no rating fails)."""
        return (
            (r.S_H1 >= self.min_pitting)
            & (r.S_H2 >= self.min_pitting)
            & (r.S_F1 >= self.min_bending)
            & (r.S_F2 >= self.min_bending)
            & np.asarray(r.valid, bool)
        )


def _positive(name: str, value, error=GearError) -> float:
    try:
        v = float(value) if isinstance(value, numbers.Real) else math.nan
    except OverflowError:  # an int beyond the range of floats
        v = math.inf
    if isinstance(value, bool) or not (math.isfinite(v) and v > 0):
        raise error(f"{name} = {shown(value)}; valid is a finite number > 0")
    return v


def min_safeties(min_safety, error=GearError) -> tuple[float, float]:
    """``(pitting, bending)`` from a mapping ``{"pitting": S_Hmin, "bending": S_Fmin}`` (a key
    left out takes :data:`MIN_SAFETY`'s value); each a finite number >= 0."""
    if min_safety is None:
        min_safety = {}
    if not isinstance(min_safety, Mapping):
        raise error(
            f"min_safety = {min_safety!r}; valid is a mapping like "
            "{'pitting': 1.0, 'bending': 1.4}"
        )
    unknown = [k for k in min_safety if k not in MIN_SAFETY]
    if unknown:
        raise error(
            f"min_safety has {unknown[0]!r}; valid keys are 'pitting' (S_H) and 'bending' (S_F)"
        )
    out = []
    for key, default in MIN_SAFETY.items():
        v = min_safety.get(key, default)
        if (
            isinstance(v, bool)
            or not isinstance(v, numbers.Real)
            or not (math.isfinite(float(v)) and float(v) >= 0)
        ):
            raise error(f"min_safety[{key!r}] = {v!r}; valid is a finite number >= 0")
        out.append(float(v))
    return out[0], out[1]


def load_case(
    torque, speed, material_="case-carburized", life=20000.0, min_safety=None, error=GearError,
    *, spectrum=None, **options,
) -> Load:  # fmt: skip
    """A checked :class:`Load`: every value is tried on one reference pair before any work, so
    a bad one is ``error`` (GearError, or the caller's class) naming it and its valid range.
    With ``spectrum`` (bins ``(torque, speed, hours)``; ``torque`` and ``speed`` None) the load
    is that spectrum (ISO 6336-6).

    ``options`` are ``GearPair.rating``'s (:data:`RATING_OPTIONS`; ``root`` only
    ``"standard"``, the route a search can vectorise) and factors by their ISO symbols.

    >>> load = load_case(60, 1500, min_safety={"pitting": 1.1, "bending": 1.5}, quality=6)
    >>> load.min_pitting, load.min_bending, load.options
    (1.1, 1.5, {'quality': 6})
    """
    bins = None
    if spectrum is not None:
        if torque is not None or speed is not None:
            raise error("give either torque and speed or spectrum=, not both")
        try:
            torques, speeds, hours = check_spectrum(spectrum)
        except GearError as exc:
            raise error(str(exc)) from None
        bins = tuple(zip(torques.tolist(), speeds.tolist(), hours.tolist(), strict=True))
        i = int(np.argmax(torques))
        torque, speed, life = torques[i], speeds[i], float(hours.sum())
    t = _positive("torque", torque, error)
    n = _positive("speed", speed, error)
    h = _positive("life", life, error)
    pitting, bending = min_safeties(min_safety, error)
    mats = material_ if isinstance(material_, tuple | list) else (material_, material_)
    if len(mats) != 2:
        raise error(f"material = {material_!r}; give one material or a pair (gear 1, gear 2)")
    try:
        pair = (material(mats[0]), material(mats[1]))
    except GearError as exc:
        raise error(str(exc)) from None
    kw: dict[str, Any] = {}
    factors: dict[str, Any] = {}
    for key, value in options.items():
        if key == "root":
            if value != "standard":
                raise error(
                    f"root = {value!r}: a search rates every candidate with ISO 6336-3's root "
                    "form (root='standard'); measure a chosen design's root with "
                    "GearPair.rating(root='measured')"
                )
            continue
        if key in RATING_OPTIONS:
            if key in _ONE_NUMBER and np.ndim(value) != 0:
                raise error(f"{key} = {value!r}; valid is one number (the same for every pair)")
            kw[key] = value
        elif key in _FACTOR_NAMES:
            factors[key] = value
        else:
            raise error(
                f"unknown rating option {key!r}; valid are {', '.join(RATING_OPTIONS)} and the "
                f"factors {', '.join(_FACTOR_NAMES)}"
            )
    if factors:
        kw["factors"] = factors
    load = Load(t, n, pair, h, pitting, bending, kw, bins)
    try:  # every value once, on a reference pair (20/40, m = 2, b = 20)
        rate(load, 20, 40, 2.0, 20.0)
    except GearError as exc:
        raise error(str(exc)) from None
    return load


def rate(load: Load, z1, z2, module, face_width, x1=0.0, x2=0.0, pressure_angle=20.0,
         helix_angle=0.0, internal=False, rack=None, tip_shortening=True, *, torque=None,
         speed=None, threads=1, **overrides) -> PairRatings:  # fmt: skip
    """The safeties ``S_H1, S_H2, S_F1, S_F2`` of rack-cut pairs under ``load`` (arrays
    broadcast; ``torque``/``speed`` replace the load's, per row; ``overrides`` replace options
    such as ``contacts``, ``idler``, ``load_sharing`` or ``tip_alteration``). A pair with no
    rating (:data:`gears.rating.iso6336.REASONS`) gets ``valid = False`` and zero safeties.
    Under a spectrum the safeties are the equivalent safeties of ISO 6336-6 (no ``torque`` or
    ``speed`` per row then) and the other fields None.
    """
    rack_kw = {}
    if rack is not None:
        rack_kw = dict(addendum=rack.addendum, dedendum=rack.dedendum,
                       root_radius=rack.root_radius, protuberance=rack.protuberance)  # fmt: skip
    kw = dict(load.options)
    kw.update(overrides)
    if load.spectrum is not None:
        if torque is not None or speed is not None:
            raise GearError("a load spectrum gives the torques and speeds: no torque= or speed=")
        r = rate_spectrum(
            z1, z2, module, face_width, load.spectrum, x1=x1, x2=x2,
            pressure_angle=pressure_angle, helix_angle=helix_angle, internal=internal,
            material=load.materials, tip_shortening=tip_shortening, errors="mask",
            threads=threads, **rack_kw, **kw,
        )  # fmt: skip
        values = {f: getattr(r, f) for f in _SAFETIES}
        values.update(valid=r.valid, reason=np.where(r.valid, 0, -1))
        return PairRatings(**{f: values.get(f) for f in PairRatings._fields})
    return rate_pairs(
        z1, z2, module, face_width, load.torque if torque is None else torque,
        load.speed if speed is None else speed, x1=x1, x2=x2, pressure_angle=pressure_angle,
        helix_angle=helix_angle, internal=internal, material=load.materials, life=load.life,
        tip_shortening=tip_shortening, errors="mask", fields=_SAFETIES, threads=threads,
        **rack_kw, **kw,
    )  # fmt: skip


def smallest_width(load: Load, widths, z1, z2, module, x1=0.0, x2=0.0, pressure_angle=20.0,
                   helix_angle=0.0, internal=False, rack=None, tip_shortening=True,
                   **overrides) -> tuple[np.ndarray, PairRatings]:  # fmt: skip
    """For each pair, the index into ``widths`` (ascending) of the smallest face width at which
    it meets the load's minimum safeties, or -1, and its safeties there (zeros where none).

    The widths are tried in order, each only on the pairs that failed every smaller one, so the
    answer is exactly "the smallest b of the set" (safety need not grow with b: K_Hbeta does).

    >>> load = load_case(60, 1500)
    >>> i, r = smallest_width(load, [10.0, 15.0, 20.0, 30.0], [17, 20, 25], 51, 2.0)
    >>> i.tolist(), [round(float(s), 3) for s in r.S_H1]   # GearPair.rating: 1.107, 1.110
    ([-1, 3, 1], [0.0, 1.107, 1.11])
    """
    widths = np.asarray(widths, float)
    arrays = [np.asarray(v, float) for v in (z1, z2, module, x1, x2)]
    shape = common_shape(
        {
            **dict(zip(("z1", "z2", "module", "x1", "x2"), (a.shape for a in arrays), strict=True)),
            **_row_shapes(overrides),
        }
    )
    z1, z2, module, x1, x2 = (np.broadcast_to(a, shape).ravel() for a in arrays)
    n = z1.size
    index = np.full(n, -1, np.int64)
    out = {f: np.zeros(n) for f in _SAFETIES}
    pending = np.arange(n)
    for j, b in enumerate(widths):
        if not pending.size:
            break
        sub = {k: _take(v, shape, pending) for k, v in overrides.items()}
        r = rate(load, z1[pending], z2[pending], module[pending], float(b), x1[pending],
                 x2[pending], pressure_angle, helix_angle, internal, rack, tip_shortening,
                 **sub)  # fmt: skip
        ok = load.meets(r)
        hit = pending[ok]
        index[hit] = j
        for f in _SAFETIES:
            out[f][hit] = np.broadcast_to(getattr(r, f), ok.shape)[ok]
        pending = pending[~ok]
    valid = index >= 0
    ratings = PairRatings(**{f: None for f in PairRatings._fields})._replace(
        **{f: out[f].reshape(shape) for f in _SAFETIES}, valid=valid.reshape(shape)
    )
    return index.reshape(shape), ratings


_PER_PAIR = ("x1", "x2", "pressure_angle", "helix_angle", "internal", "application_factor",
             "quality", "roughness", "oil_viscosity", "load_sharing", "misalignment",
             "tip_relief", "addendum", "root_roughness")  # fmt: skip
_SPECTRUM_CHUNK = 1 << 17  # ratings (pairs x bins) a block: Miner's rule takes whole blocks
_NEEDED = ("sigma_H1", "sigma_H2", "sigma_HP1", "sigma_HP2", "Z_NT1", "Z_NT2", "sigma_F1",
           "sigma_F2", "sigma_FP1", "sigma_FP2", "Y_NT1", "Y_NT2", "N_L1", "N_L2")  # fmt: skip


def _trailing(v):
    """``v`` with a trailing axis for the bins when it is an array (as it is when not even
    that: rate_pairs names it)."""
    try:
        return v if np.ndim(v) == 0 else np.asarray(v)[..., None]
    except ValueError:  # a ragged sequence
        return v


def _trailing_factors(factors):
    """The given factors with a trailing axis for the bins on their arrays (on each of a
    per-gear factor's pair)."""
    per_gear = {f[0] for f in FACTORS if f[1]}
    return {k: type(v)(map(_trailing, v)) if k in per_gear and isinstance(v, tuple | list)
            else _trailing(v) for k, v in factors.items()}  # fmt: skip


def rate_spectrum(
    z1: ArrayLike, z2: ArrayLike, module: ArrayLike, face_width: ArrayLike, spectrum: Any, *,
    errors: str = "raise", **options: Any,
) -> SpectrumRatings:  # fmt: skip
    """ISO 6336-6 ratings of many pairs under one load spectrum (arrays broadcast).

    Parameters
    ----------
    z1, z2, module, face_width
        The pairs, as for :func:`gears.rating.iso6336.rate_pairs`.
    spectrum : list of (torque, speed, hours)
        The bins: torque on gear 1 (N m), its speed relative to the carrier (rpm), hours.
    errors : {"raise", "mask"}
        A pair with no rating at some bin raises a GearError naming it ("raise") or gets
        ``valid = False`` ("mask"), as in :func:`gears.rating.iso6336.rate_pairs`.
    **options
        Passed to :func:`gears.rating.iso6336.rate_pairs` (``material``, ``x1``, ``quality``,
        ``factors``, ``threads``, ...; not ``torque``, ``speed``, ``life``, ``fields``). The
        per-pair arrays among them broadcast against the pairs, and so do ``factors``' arrays
        (each of a per-gear factor's pair too); materials and per-gear pairs of other options
        are one for all. A life factor given (``Z_NT``, ``Y_NT``) cancels: Miner's rule reads
        the material's S-N curve.

    Returns
    -------
    SpectrumRatings

    Examples
    --------
    >>> r = rate_spectrum([19, 21], 61, 3, 30, [(150, 1450, 2000), (250, 1450, 200)])
    >>> [round(float(s), 3) for s in r.S_H1], [round(float(d), 4) for d in r.D_H1]
    ([1.122, 1.241], [0.0944, 0.0034])
    """
    for key in ("torque", "speed", "life", "fields"):
        if key in options:
            raise GearError(f"{key}= is not an option of rate_spectrum (the spectrum gives it)")
    if errors not in ("raise", "mask"):
        raise GearError(f"errors = {errors!r}; valid are 'raise', 'mask'")
    torques, speeds, hours = check_spectrum(spectrum)
    extra = {k: _trailing(v) if k in _PER_PAIR else v for k, v in options.items()}
    # Miner's rule reads the S-N curve itself: the bins rated without life factors (a Z_NT or
    # Y_NT given cancels too, in sigma_HP / Z_NT and sigma_FP / Y_NT); a factor's arrays are
    # per pair (each of a per-gear pair's too)
    given = extra.get("factors")
    if given is None or isinstance(given, Mapping):
        extra["factors"] = {"Z_NT": 1.0, "Y_NT": 1.0, **_trailing_factors(given or {})}
    m1, m2 = _materials(options.get("material", "case-carburized"))
    total = float(hours.sum())
    parts = {}

    def reduce(q, i0, i1):
        """Miner's rule on a block of pairs as soon as its bins are rated (in the cache)."""
        parts[i0] = (_combine(q, m1.code, m2.code, total), np.all(q["valid"], axis=-1))

    # pairs one a row, the bins on the last axis; blocks of whole rows (pairs given as numbers:
    # one row of at most MAX_BINS ratings, one block)
    rate_reduced(reduce, _SPECTRUM_CHUNK, z1=_trailing(z1), z2=_trailing(z2),
                 module=_trailing(module), face_width=_trailing(face_width), torque=torques,
                 speed=speeds, life=hours, fields=_NEEDED, errors=errors, **extra)  # fmt: skip
    blocks = [parts[i] for i in sorted(parts)]
    if len(blocks) == 1:
        out, valid = blocks[0]
    else:
        out = SpectrumRatings(*(np.concatenate([b[0][j] for b in blocks])
                                for j in range(len(SpectrumRatings._fields) - 1)))  # fmt: skip
        valid = np.concatenate([b[1] for b in blocks])
    if np.all(valid):
        return out
    masked = {k: np.where(valid, v, np.nan if k.startswith("D_") else 0.0)
              for k, v in out._asdict().items() if k != "valid"}  # fmt: skip
    return SpectrumRatings(**{k: v[()] for k, v in masked.items()}, valid=valid[()])


def _materials(value):
    mats = value if isinstance(value, tuple | list) else (value, value)
    if len(mats) != 2:
        raise GearError(f"material = {value!r}; give one material or a pair")
    return material(mats[0]), material(mats[1])


def _row_shapes(overrides: dict) -> dict[str, tuple[int, ...]]:
    """Shapes of the per-row arrays among ``overrides`` by name (a pair's elements count too)."""
    out = {}
    for k, v in overrides.items():
        for i, item in enumerate(v if isinstance(v, tuple | list) else (v,)):
            if isinstance(item, np.ndarray):
                out[f"{k}[{i}]" if isinstance(v, tuple | list) else k] = item.shape
    return out


def _take(value, shape, rows):
    """``value`` at the flat ``rows`` of ``shape`` where it is an array (each element of a pair
    too); scalars as they are."""
    if isinstance(value, tuple | list):
        return type(value)(_take(v, shape, rows) for v in value)
    if isinstance(value, np.ndarray):
        return np.broadcast_to(value, shape).ravel()[rows]
    return value


def gear_volume(z, module, face_width, helix_angle=0.0, internal=False, profile_shift=0.0,
                dedendum=1.25):  # fmt: skip
    """Material of a gear, mm^3: its pitch cylinder ``pi/4 d^2 b``, or for a ring the annulus
    from d out to :data:`RING_RIM` modules below its root circle (arrays broadcast).

    >>> round(float(gear_volume(20, 2, 10)), 1)   # pi/4 40^2 10
    12566.4
    >>> round(float(gear_volume(80, 2, 10, internal=True)), 1)   # pi/4 (179^2 - 160^2) 10
    50587.5
    """
    d = np.asarray(reference_diameter(z, module, helix_angle), float)
    b = np.asarray(face_width, float)
    d_f = np.asarray(root_diameter(z, module, profile_shift, helix_angle, dedendum, True), float)
    outer = d_f + 2.0 * RING_RIM * np.asarray(module, float)
    v = np.where(np.asarray(internal, bool), outer * outer - d * d, d * d) * (np.pi / 4) * b
    return v[()] if v.ndim == 0 else v


def pair_volume(z1, z2, module, face_width, helix_angle=0.0, internal=False, x2=0.0,
                dedendum=1.25, density=None):  # fmt: skip
    """``(volume, mass)`` of a pair's two gears: mm^3 and, with ``density = (rho1, rho2)`` in
    kg/mm^3, kg (else None).

    >>> v, m = pair_volume(20, 40, 2, 10, density=(7.83e-6, 7.83e-6))
    >>> round(float(v), 1), round(float(m), 4)
    (62831.9, 0.492)
    """
    v1 = gear_volume(z1, module, face_width, helix_angle)
    v2 = gear_volume(z2, module, face_width, helix_angle, internal, x2, dedendum)
    mass = None if density is None else density[0] * v1 + density[1] * v2
    return v1 + v2, mass
