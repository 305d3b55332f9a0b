"""Layer 6, load spectra (ISO 6336-6): Miner's damage per gear and failure mode, the equivalent
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

This module is the view of one mesh (:class:`SpectrumRating`, what
``GearPair.rating(spectrum=...)`` returns) and the spectrum file (:func:`read_spectrum`); the
array entry :func:`rate_spectrum` lives with the load cases in :mod:`gears.rating.sizing` (the
searches size for a spectrum with it), Miner's rule over arrays in :mod:`gears.rating.miner`;
both are named here too.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np

from gears.display import html_table
from gears.errors import GearError
from gears.rating.miner import (
    LIFE_CAP,
    MAX_BINS,
    MODES,
    SpectrumRatings,
    _combine,
    check_spectrum,
    cycles_to_failure,
    equivalent_safety,
    miner_damage,
)
from gears.rating.sizing import _materials, rate_spectrum
from gears.report import Finding, Report

__all__ = [
    "LIFE_CAP",
    "MAX_BINS",
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

    @property
    def safety_scuffing(self) -> tuple[float, float] | None:
        """The lowest ``(S_B, S_intS)`` over the bins when an oil was given (``scuffing=``):
        scuffing is no fatigue, the worst bin decides; None without an oil."""
        found = [b.safety_scuffing for b in self.bins if b.safety_scuffing is not None]
        if not found:
            return None
        return min(s[0] for s in found), min(s[1] for s in found)

    def check(self, min_pitting: float = 1.0, min_bending: float = 1.4,
              min_scuffing: tuple[float, float] | None = None) -> Report:  # fmt: skip
        """Findings ``pitting_1 ... bending_2``: each equivalent safety against its minimum;
        with an oil, ``scuffing_flash`` and ``scuffing_integral`` of the worst bin against
        ``min_scuffing`` (default: :meth:`gears.rating.capacity.Rating.check`'s)."""
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
        if self.safety_scuffing is not None:
            oiled = [(i, b) for i, b in enumerate(self.bins) if b.scuffing is not None]
            for name, k in (("scuffing_flash", 0), ("scuffing_integral", 1)):
                i, worst = min(oiled, key=lambda ib: ib[1].safety_scuffing[k])
                given = {} if min_scuffing is None else {"min_scuffing": min_scuffing}
                f = worst.check(**given)[name]
                out.append(Finding(name, f.margin, f"{f.message}; bin {i + 1} of the spectrum",
                                   unit=""))  # fmt: skip
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

    def _summary(self, sep: str = ", ") -> str:
        hours = sum(h for _, _, h in self.spectrum)
        edition = getattr(self.bins[0], "edition", None) if self.bins else None
        rated = "" if edition is None else f"{sep}bins rated by ISO 6336-1/-2/-3:{edition}"
        return (f"ISO 6336-6 load spectrum: {len(self.spectrum)} bins, {hours:g} h "
                f"(Miner's elementary rule){rated}")  # fmt: skip

    def __str__(self) -> str:
        lines = [self._summary("\n"), "", f"{'':26s} {'gear 1':>10s} {'gear 2':>10s}"]
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
    values = _combine(stacked._asdict(), m1.code, m2.code, hours)
    bins = tuple((float(t), float(n), float(h)) for t, n, h in spectrum)
    return SpectrumRating(tuple(ratings), bins, values)
