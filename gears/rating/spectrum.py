"""Layer 5, load spectra (ISO 6336-6): Miner's damage per gear and failure mode, the equivalent
safety and the life of a mesh under a duty of several loads (the formulas as math:
docs/rating.md, "Load spectra").

A spectrum is a list of bins ``(torque, speed, hours)``. Each bin is rated as a load of its own
(ISO 6336 method B at its torque and speed, so every load factor follows the load), which gives
per gear and failure mode the stress sigma_i and the allowable stress at the bin's own cycles;
dividing the latter by its life factor (Z_NT, Y_NT) leaves the strength at the endurance knot
with every other factor of that bin, sigma_inf,i. The material's S-N curve (the knots of Z_NT
and Y_NT in :mod:`gears.rating.life`, straight lines in log-log) read backwards gives the cycles
to failure N_f,i at sigma_i / sigma_inf,i, and Miner's rule sums the damage
D = sum(N_L,i / N_f,i), with N_L,i = 60 n_i h_i times the contacts per turn (ISO 6336-6,
Miner's elementary rule: a stress above the curve's static knot fails in one cycle, a stress
below its last knot, the endurance limit, does no damage).

The **equivalent safety** S is the factor by which every bin's stress may grow before D reaches
1 (for one bin it is the single-load safety sigma_HP / sigma_H, sigma_FP / sigma_F); the
**life** is the spectrum's hours over D, the hours the duty can be repeated until D = 1 (an
endless life is reported as :data:`LIFE_CAP` hours).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from gears.display import html_table
from gears.errors import GearError
from gears.rating.iso6336 import rate_pairs
from gears.rating.life import _BENDING_TABLE, _PITTING_TABLE
from gears.rating.materials import material
from gears.report import Finding, Report

__all__ = [
    "LIFE_CAP",
    "MODES",
    "SpectrumRating",
    "SpectrumRatings",
    "check_spectrum",
    "cycles_to_failure",
    "equivalent_safety",
    "miner_damage",
    "rate_spectrum",
    "read_spectrum",
    "spectrum_rating",
]

#: The life reported where the spectrum does no damage (every stress below the endurance limit).
LIFE_CAP = 1e12
#: Failure modes and the life curve each reads: pitting (Z_NT), tooth-root bending (Y_NT).
MODES = ("pitting", "bending")
#: Most bins a spectrum may have.
MAX_BINS = 10_000
_TABLES = {"pitting": _PITTING_TABLE, "bending": _BENDING_TABLE}
_BISECTIONS = 48  # halvings of ln S over [ln 1e-4, ln 1e4]: 18.4 / 2^48 ~ 7e-14 (at most)


def _mode_table(mode: str):
    if mode not in _TABLES:
        raise GearError(f"mode = {mode!r}; valid are {', '.join(MODES)}")
    return _TABLES[mode]


def _knots(code, table):
    """The curve's knots (k0, k1, k2, y0, y1, y2) for material ``code`` (arrays with a trailing
    axis for the bins, or numbers)."""
    logn, logy = table
    code = np.asarray(code)
    if code.ndim == 0:
        c = int(code)
        return tuple(float(v) for v in (*logn[c], *logy[c]))
    return tuple(v[..., None] for v in (*logn[code].T, *logy[code].T))


def _log_cycles(z, knots):
    """``(ln N_f, d ln N_f / d z)`` at ``z = ln(sigma / sigma_inf)``: ln N_f = +inf below the
    endurance knot, 0 (one cycle) above the static knot, the log-log lines between."""
    k0, k1, k2, y0, y1, y2 = knots
    a1 = (k1 - k0) / (y1 - y0)
    a2 = (k2 - k1) / (y2 - y1)
    upper = z > y1
    slope = np.where(upper, a1, a2)
    ln_nf = np.where(upper, k1 + (z - y1) * a1, k1 + (z - y1) * a2)
    static = z > y0
    ln_nf = np.where(static, 0.0, ln_nf)
    slope = np.where(static, 0.0, slope)
    endless = z <= y2
    return np.where(endless, np.inf, ln_nf), np.where(endless, 0.0, slope)


def cycles_to_failure(ratio, code, mode="pitting"):
    """Cycles to failure N_f at the stress ratio ``sigma / sigma_inf`` on the S-N curve of the
    material group ``code`` (:func:`gears.rating.materials.kind_code`) for ``mode`` (arrays
    broadcast). Below the endurance knot the curve is flat and the life endless: returned as
    ``LIFE_CAP * 3.6e6`` cycles (finite); above the static knot, 1 cycle.

    >>> from gears.rating.materials import kind_code
    >>> round(float(cycles_to_failure(1.0, kind_code("Eh"))))   # Z_NT = 1 at 5 x 10^7
    50000000
    """
    code = np.asarray(code)
    z = np.log(np.asarray(ratio, float))
    knots = _knots(code, _mode_table(mode))
    if code.ndim:
        knots = tuple(v[..., 0] for v in knots)
    ln_nf, _ = _log_cycles(z, knots)
    return np.exp(np.minimum(ln_nf, math.log(LIFE_CAP * 3.6e6)))


def _log_ratio_cycles(stress, strength, cycles, axis):
    """ln(sigma / sigma_inf) and ln N_L with the bins moved to the last axis."""
    z = np.log(np.asarray(stress, float)) - np.log(np.asarray(strength, float))
    with np.errstate(divide="ignore"):
        lc = np.log(np.asarray(cycles, float))
    z, lc = np.broadcast_arrays(z, lc)
    return np.moveaxis(z, axis, -1), np.moveaxis(lc, axis, -1)


def miner_damage(stress, strength, cycles, code, mode="pitting", axis=-1):
    """Miner's sum D = sum N_L,i / N_f,i over the bins on ``axis``: ``stress`` sigma_i,
    ``strength`` sigma_inf,i (the allowable stress over its life factor) in MPa, ``cycles``
    N_L,i, ``code`` the material group (arrays broadcast; an array ``code`` has the shape of the
    result).

    >>> round(float(miner_damage([1000.0], [1000.0], [2.5e7], 4)), 6)   # Eh: half of 5 x 10^7
    0.5
    """
    z, lc = _log_ratio_cycles(stress, strength, cycles, axis)
    ln_nf, _ = _log_cycles(z, _knots(code, _mode_table(mode)))
    return np.sum(np.exp(lc - ln_nf), axis=-1)


def equivalent_safety(stress, strength, cycles, code, mode="pitting", axis=-1):
    """The factor S by which every bin's stress may grow until Miner's sum reaches 1: the bound
    between D(S sigma) < 1 and D(S sigma) >= 1 in [1e-4, 1e4] (arrays broadcast, the bins on
    ``axis``; an array ``code`` has the shape of the result).

    Found by Newton's method on ln D(ln S), kept inside a bracket that each step narrows, and by
    bisection where Newton cannot step (no damage yet, or the jump at the endurance limit),
    until the bracket or the step is below 10^-13.

    >>> round(float(equivalent_safety([1000.0], [1000.0], [5e7], 4)), 9)   # one bin at its knot
    1.0
    """
    z, lc = _log_ratio_cycles(stress, strength, cycles, axis)
    knots = _knots(code, _mode_table(mode))
    shape = z.shape[:-1]
    bins = z.shape[-1]
    z = z.reshape(-1, bins)
    lc = lc.reshape(-1, bins)
    knots = tuple(np.broadcast_to(k, (*shape, 1)).reshape(-1, 1) if np.ndim(k) else k
                  for k in knots)  # fmt: skip
    lo, hi, x, active = _jump_bracket(z, lc, knots)
    for _ in range(_BISECTIONS + 40):
        if active.size == 0:
            break
        kn = tuple(k[active] if np.ndim(k) else k for k in knots)
        xa = x[active]
        ln_nf, slope = _log_cycles(z[active] + xa[:, None], kn)
        terms = np.exp(lc[active] - ln_nf)
        d = terms.sum(axis=1)
        dd = -(terms * slope).sum(axis=1)  # dD / dx >= 0
        failed = d >= 1.0
        la = np.where(failed, lo[active], xa)
        ha = np.where(failed, xa, hi[active])
        with np.errstate(divide="ignore", invalid="ignore"):
            step = xa - np.log(d) * d / dd
        newton = np.isfinite(step) & (d > 0) & (dd > 0) & (step > la) & (step < ha)
        nxt = np.where(newton, step, 0.5 * (la + ha))
        finished = (ha - la < 1e-13) | (newton & (np.abs(step - xa) < 1e-13))
        lo[active], hi[active], x[active] = la, ha, nxt
        active = active[~finished]
    return np.exp(x).reshape(shape)[()] if not shape else np.exp(x).reshape(shape)


def _jump_bracket(z, lc, knots):
    """The start of :func:`equivalent_safety` on ``(pairs, bins)`` arrays: D jumps where a bin
    reaches the endurance knot (x_j = y2 - z_j). Where D crosses 1 in a jump, that x_j is the
    answer; elsewhere the jumps bracket a stretch where D is continuous, for Newton's method.
    Returns ``(lo, hi, x, active)``: the brackets, the start (the answer where found) and the
    rows still to solve."""
    y2 = knots[5]
    k2 = knots[2]
    xe = y2 - z  # (n, B) jump points
    kn = tuple(k[:, :, None] if np.ndim(k) else k for k in knots)
    # D just below each jump point: bin j itself (and any bin jumping there too) is endless
    ln_nf, _ = _log_cycles(z[:, None, :] + xe[:, :, None], kn)
    left = np.exp(lc[:, None, :] - ln_nf).sum(axis=2)  # (n, B): D(x_j - 0)
    same = xe[:, :, None] == xe[:, None, :]
    right = left + (same * np.exp(lc - k2)[:, None, :]).sum(axis=2)  # D(x_j + 0)
    lo0, hi0 = math.log(1e-4), math.log(1e4)
    inside = (xe > lo0) & (xe < hi0)
    jump = inside & (left < 1.0) & (right >= 1.0)
    found = jump.any(axis=1)
    x_jump = np.where(jump, xe, np.inf).min(axis=1)
    lo = np.where(inside & (right < 1.0), xe, lo0).max(axis=1)
    hi = np.where(inside & (left >= 1.0), xe, hi0).min(axis=1)
    lo = np.maximum(lo, lo0)
    hi = np.minimum(hi, hi0)
    x = np.where(found, x_jump, 0.5 * (lo + hi))
    return lo, hi, x, np.flatnonzero(~found)


def check_spectrum(spectrum: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(torques, speeds, hours)`` as float arrays from a list of bins ``(torque N m, speed rpm,
    hours)`` or three sequences, every value finite and > 0, or a GearError naming the bin."""
    try:
        arr = np.asarray(spectrum, dtype=float)
    except (TypeError, ValueError):
        raise GearError(
            f"spectrum = {spectrum!r:.80}; valid is a list of bins (torque, speed, hours)"
        ) from None
    if arr.ndim != 2 or arr.shape[1] != 3 or not 1 <= arr.shape[0] <= MAX_BINS:
        raise GearError(
            f"spectrum of shape {arr.shape}; valid is a list of 1 ... {MAX_BINS} bins "
            "(torque N m, speed rpm, hours)"
        )
    bad = ~(np.isfinite(arr) & (arr > 0.0))
    if bad.any():
        i, j = (int(k) for k in np.argwhere(bad)[0])
        what = ("torque", "speed", "hours")[j]
        raise GearError(f"spectrum bin {i}: {what} = {arr[i, j]!r}; valid is a finite number > 0")
    return arr[:, 0].copy(), arr[:, 1].copy(), arr[:, 2].copy()


def read_spectrum(path) -> list[tuple[float, float, float]]:
    """The bins of a spectrum file: one bin a line, ``torque, speed, hours`` (N m, rpm, h)
    separated by commas or blanks; ``#`` starts a comment, a first line of names is skipped.
    A GearError names the file and line of a bad entry."""
    import pathlib

    p = pathlib.Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise GearError(
            f"spectrum = {str(path)!r}: cannot read it ({exc.__class__.__name__})"
        ) from None
    bins = []
    for k, raw in enumerate(text.splitlines(), 1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        parts = line.replace(",", " ").replace(";", " ").split()
        try:
            values = [float(v) for v in parts]
        except ValueError:
            if not bins and k == 1:
                continue  # a header
            raise GearError(
                f"spectrum = {str(path)!r}, line {k}: {raw.strip()!r} is not three numbers"
            ) from None
        if len(values) != 3:
            raise GearError(
                f"spectrum = {str(path)!r}, line {k}: {len(values)} values; valid is torque, "
                "speed, hours"
            )
        bins.append(tuple(values))
    check_spectrum(bins) if bins else None
    if not bins:
        raise GearError(f"spectrum = {str(path)!r} has no bins (torque, speed, hours per line)")
    return bins


class SpectrumRatings(NamedTuple):
    """Arrays returned by :func:`rate_spectrum`, one value per pair: Miner's sums ``D_H1, D_H2,
    D_F1, D_F2``, the equivalent safeties ``S_H1 ... S_F2`` and the lives ``L_H1 ... L_F2``
    (hours, :data:`LIFE_CAP` where endless)."""

    D_H1: np.ndarray
    D_H2: np.ndarray
    D_F1: np.ndarray
    D_F2: np.ndarray
    S_H1: np.ndarray
    S_H2: np.ndarray
    S_F1: np.ndarray
    S_F2: np.ndarray
    L_H1: np.ndarray
    L_H2: np.ndarray
    L_F1: np.ndarray
    L_F2: np.ndarray


_PER_PAIR = ("x1", "x2", "pressure_angle", "helix_angle", "internal", "application_factor",
             "quality", "roughness", "oil_viscosity", "load_sharing", "misalignment",
             "tip_relief", "addendum", "root_roughness")  # fmt: skip
_NEEDED = ("sigma_H1", "sigma_H2", "sigma_HP1", "sigma_HP2", "Z_NT1", "Z_NT2", "sigma_F1",
           "sigma_F2", "sigma_FP1", "sigma_FP2", "Y_NT1", "Y_NT2", "N_L1", "N_L2")  # fmt: skip


def _trailing(v):
    """``v`` with a trailing axis for the bins when it is an array."""
    return v if np.ndim(v) == 0 else np.asarray(v)[..., None]


def rate_spectrum(z1: ArrayLike, z2: ArrayLike, module: ArrayLike, face_width: ArrayLike,
                  spectrum: Any, **options: Any) -> SpectrumRatings:  # fmt: skip
    """ISO 6336-6 ratings of many pairs under one load spectrum (arrays broadcast).

    Parameters
    ----------
    z1, z2, module, face_width
        The pairs, as for :func:`gears.rating.iso6336.rate_pairs`.
    spectrum : list of (torque, speed, hours)
        The bins: torque on gear 1 (N m), its speed relative to the carrier (rpm), hours.
    **options
        Passed to :func:`gears.rating.iso6336.rate_pairs` (``material``, ``x1``, ``quality``,
        ``factors``, ``threads``, ...; not ``torque``, ``speed``, ``life``, ``fields``). The
        per-pair arrays among them broadcast against the pairs; materials and per-gear pairs
        are one for all.

    Returns
    -------
    SpectrumRatings

    Examples
    --------
    >>> r = rate_spectrum([19, 21], 61, 3, 30, [(150, 1450, 2000), (250, 1450, 200)])
    >>> [round(float(s), 3) for s in r.S_H1], [round(float(d), 4) for d in r.D_H1]
    ([1.122, 1.241], [0.0944, 0.0034])
    """
    for key in ("torque", "speed", "life", "fields", "errors"):
        if key in options:
            raise GearError(f"{key}= is not an option of rate_spectrum (the spectrum gives it)")
    torques, speeds, hours = check_spectrum(spectrum)
    extra = {k: _trailing(v) if k in _PER_PAIR else v for k, v in options.items()}
    r = rate_pairs(_trailing(z1), _trailing(z2), _trailing(module), _trailing(face_width),
                   torques, speeds, life=hours, fields=_NEEDED, errors="raise",
                   **extra)  # fmt: skip
    m1, m2 = _materials(options.get("material", "case-carburized"))
    return _combine(r, m1.code, m2.code, float(hours.sum()))


def _materials(value):
    mats = value if isinstance(value, tuple | list) else (value, value)
    if len(mats) != 2:
        raise GearError(f"material = {value!r}; give one material or a pair")
    return material(mats[0]), material(mats[1])


def _combine(r, code1: int, code2: int, total_hours: float) -> SpectrumRatings:
    """Miner's sums, equivalent safeties and lives from the bins' stresses (bins on the last
    axis of every field of ``r``)."""
    out = {}
    for mode, s, p, f, sym in (("pitting", "sigma_H", "sigma_HP", "Z_NT", "H"),
                               ("bending", "sigma_F", "sigma_FP", "Y_NT", "F")):  # fmt: skip
        for i, code in ((1, code1), (2, code2)):
            stress = np.asarray(getattr(r, f"{s}{i}"), float)
            strength = np.asarray(getattr(r, f"{p}{i}"), float) / np.asarray(
                getattr(r, f"{f}{i}"), float
            )
            cycles = np.asarray(getattr(r, f"N_L{i}"), float)
            d = miner_damage(stress, strength, cycles, code, mode)
            out[f"D_{sym}{i}"] = d
            out[f"S_{sym}{i}"] = equivalent_safety(stress, strength, cycles, code, mode)
            with np.errstate(divide="ignore"):
                out[f"L_{sym}{i}"] = np.where(d > 0, np.minimum(total_hours / d, LIFE_CAP),
                                              LIFE_CAP)  # fmt: skip
    return SpectrumRatings(**{k: v[()] if np.ndim(v) == 0 else v for k, v in out.items()})


class _Bins(NamedTuple):
    """The per-bin fields of one pair's ratings stacked on a last axis (what :func:`_combine`
    reads)."""

    sigma_H1: np.ndarray
    sigma_H2: np.ndarray
    sigma_HP1: np.ndarray
    sigma_HP2: np.ndarray
    Z_NT1: np.ndarray
    Z_NT2: np.ndarray
    sigma_F1: np.ndarray
    sigma_F2: np.ndarray
    sigma_FP1: np.ndarray
    sigma_FP2: np.ndarray
    Y_NT1: np.ndarray
    Y_NT2: np.ndarray
    N_L1: np.ndarray
    N_L2: np.ndarray


@dataclass(frozen=True)
class SpectrumRating:
    """The ISO 6336-6 rating of one mesh under a load spectrum (a thin view).

    Attributes
    ----------
    bins : tuple of Rating
        Each bin rated as a load of its own (life = the bin's hours).
    spectrum : tuple of (torque, speed, hours)
    values : SpectrumRatings
        Miner's sums, equivalent safeties and lives (one number each).
    """

    bins: tuple
    spectrum: tuple
    values: SpectrumRatings

    @property
    def damage(self) -> dict[str, tuple[float, float]]:
        """Miner's sums ``{"pitting": (D_H1, D_H2), "bending": (D_F1, D_F2)}``."""
        v = self.values
        return {"pitting": (float(v.D_H1), float(v.D_H2)),
                "bending": (float(v.D_F1), float(v.D_F2))}  # fmt: skip

    @property
    def safety_pitting(self) -> tuple[float, float]:
        """Equivalent safeties against pitting ``(S_H1, S_H2)``."""
        return float(self.values.S_H1), float(self.values.S_H2)

    @property
    def safety_bending(self) -> tuple[float, float]:
        """Equivalent safeties against tooth-root breakage ``(S_F1, S_F2)``."""
        return float(self.values.S_F1), float(self.values.S_F2)

    @property
    def life(self) -> dict[str, tuple[float, float]]:
        """Hours until Miner's sum reaches 1 per mode and gear (:data:`LIFE_CAP` if endless)."""
        v = self.values
        return {"pitting": (float(v.L_H1), float(v.L_H2)),
                "bending": (float(v.L_F1), float(v.L_F2))}  # fmt: skip

    @property
    def pair(self):
        return self.bins[0].pair

    def check(self, min_pitting: float = 1.0, min_bending: float = 1.4) -> Report:
        """Findings ``pitting_1 ... bending_2``: each equivalent safety against its minimum."""
        for name, minimum in (("min_pitting", min_pitting), ("min_bending", min_bending)):
            if (isinstance(minimum, bool) or not isinstance(minimum, int | float)
                    or not (math.isfinite(minimum) and minimum >= 0)):  # fmt: skip
                raise GearError(f"{name} = {minimum!r}; valid is a number >= 0")
        out = []
        for kind, safeties, minimum, sym in (
            ("pitting", self.safety_pitting, min_pitting, "S_H"),
            ("bending", self.safety_bending, min_bending, "S_F"),
        ):
            for i in (0, 1):
                d = self.damage[kind][i]
                out.append(Finding(
                    f"{kind}_{i + 1}", safeties[i] - minimum,
                    f"{sym}{i + 1} = {safeties[i]:.3f} (spectrum, ISO 6336-6) vs required "
                    f"{minimum:g}; Miner's sum D = {d:.4g}", unit="",
                ))  # fmt: skip
        return Report(out)

    def _rows(self) -> list[tuple[str, str, str]]:
        rows = []
        for label, values in (("equivalent safety S_H", self.safety_pitting),
                              ("equivalent safety S_F", self.safety_bending),
                              ("Miner's sum D_H", self.damage["pitting"]),
                              ("Miner's sum D_F", self.damage["bending"]),
                              ("life, pitting [h]", self.life["pitting"]),
                              ("life, bending [h]", self.life["bending"])):  # fmt: skip
            rows.append((label, *(f"{v:.4g}" for v in values)))
        return rows

    def _summary(self) -> str:
        hours = sum(h for _, _, h in self.spectrum)
        return (f"ISO 6336-6 load spectrum: {len(self.spectrum)} bins, {hours:g} h "
                "(Miner's elementary rule)")  # fmt: skip

    def __str__(self) -> str:
        lines = [self._summary(), "", f"{'':26s} {'gear 1':>10s} {'gear 2':>10s}"]
        lines += [f"{a:26s} {b:>10s} {c:>10s}" for a, b, c in self._rows()]
        lines += ["", f"{'torque N m':>12s} {'speed rpm':>12s} {'hours':>10s} {'S_H1':>8s} "
                  f"{'S_F1':>8s}"]  # fmt: skip
        for (t, n, h), r in zip(self.spectrum, self.bins, strict=True):
            lines.append(f"{t:12.5g} {n:12.5g} {h:10.5g} {r.safety_pitting[0]:8.3f} "
                         f"{r.safety_bending[0]:8.3f}")  # fmt: skip
        return "\n".join(lines)

    def __repr__(self) -> str:
        sh, sf = self.safety_pitting, self.safety_bending
        return (f"SpectrumRating({len(self.bins)} bins, S_H = {sh[0]:.3f} / {sh[1]:.3f}, "
                f"S_F = {sf[0]:.3f} / {sf[1]:.3f})")  # fmt: skip

    def _repr_html_(self) -> str:
        failed = self.check().failed()
        marks = [
            any(n.startswith("pitting") for n in failed),
            any(n.startswith("bending") for n in failed),
            False,
            False,
            False,
            False,
        ]
        bins = [(f"{t:.5g}", f"{n:.5g}", f"{h:.5g}", *(f"{s:.3f}" for s in r.safety_pitting),
                 *(f"{s:.3f}" for s in r.safety_bending))
                for (t, n, h), r in zip(self.spectrum, self.bins, strict=True)]  # fmt: skip
        return "\n".join([
            html_table(["", "gear 1", "gear 2"], self._rows(), failing=marks,
                       caption=self._summary()),
            html_table(["torque [N m]", "speed [rpm]", "hours", "S_H1", "S_H2", "S_F1", "S_F2"],
                       bins, caption="each bin rated alone (life = its hours)"),
        ])  # fmt: skip


def spectrum_rating(ratings: Sequence, materials: Any,
                    spectrum: Sequence[tuple[float, float, float]]) -> SpectrumRating:  # fmt: skip
    """The :class:`SpectrumRating` of one mesh from its bins' :class:`gears.Rating` (each rated
    at its bin's torque, speed and hours, in the order of ``spectrum``) and its ``materials``
    (one or a pair)."""
    if len(ratings) != len(spectrum) or not ratings:
        raise GearError(f"{len(ratings)} ratings for {len(spectrum)} bins")
    stacked = _Bins(*(np.array([float(getattr(r.values, f)) for r in ratings])
                      for f in _Bins._fields))  # fmt: skip
    m1, m2 = _materials(materials)
    hours = float(sum(h for _, _, h in spectrum))
    values = _combine(stacked, m1.code, m2.code, hours)
    bins = tuple((float(t), float(n), float(h)) for t, n, h in spectrum)
    return SpectrumRating(tuple(ratings), bins, values)
