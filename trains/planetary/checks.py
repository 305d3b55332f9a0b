"""Layer 3, planetary: the conditions of a stage, each a finding with a signed margin.

The three textbook conditions are evaluated on the real gears (profile shifts, tip shortening,
helix), each with a signed margin (Ozols §21-13; lectures §4.3; KHK Gear Technical Reference):

* coaxiality: the working centre distances of the meshes agree (each a_w from its own working
  pressure angle), or for the double-planet scheme the planet triangle closes with clearance;
* assembly: the exact gcd form ``N / (k gcd(z_c, z_d)) in Z`` with
  ``N = |z_b z_c - s_a s_b z_a z_d|`` (s = -1 external, +1 internal mesh; lectures §4.3,
  KHK), and the textbook sufficient form ``(z_a i_aH / k)(1 + k p) in Z`` reported
  beside it; both in integer arithmetic;
* neighbour: the smallest gap between the tip circles of planets that do not mesh, against a
  clearance (``2 a_w sin(pi/k) - d_a`` for one planet row).

The functions take a :class:`~trains.planetary.stage.Planetary` (``stage``) and are the bodies of
its :meth:`~trains.planetary.stage.Planetary.check`, ``assembly`` and ``max_planets``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from gears.checks import form_lengths, undercut_form_diameter
from gears.meshing import pair_geometry
from gears.rack import BasicRack
from gears.report import Finding, Report
from trains.planetary.schemes import assembly_ticks, stage_ratio, textbook_assembly

__all__ = ["MAX_PLANETS", "NEIGHBOUR_TOLERANCE", "Assembly", "ring_tip_alteration"]


@dataclass(frozen=True)
class Assembly:
    """The assembly condition of a stage (see :meth:`Planetary.assembly`).

    Attributes
    ----------
    n_planets : int
    ticks : int
        Assembly number T: positions per turn at which a planet fits (tick angle 360/T deg).
    exact : bool
        T is a multiple of n_planets (necessary and sufficient for identical planets with the
        same tooth phase on both steps).
    textbook : bool
        The sufficient textbook form ``(z_a i_aH / k)(1 + k p) in Z``.
    tick_angle : float
        360 / T degrees.
    spacing : tuple of float
        Planet centre angles in degrees: equal when ``exact``, otherwise the feasible unequal
        spacing closest to equal (each angle a multiple of the tick).
    max_deviation : float
        Largest deviation of ``spacing`` from equal spacing, degrees.
    nearest_counts : tuple of int
        The assemblable counts (divisors of T) nearest below and above n_planets.
    """

    n_planets: int
    ticks: int
    exact: bool
    textbook: bool
    tick_angle: float
    spacing: tuple[float, ...]
    max_deviation: float
    nearest_counts: tuple[int, ...]


#: How far (in modules) a gap between planet tip circles may fall short of the clearance and
#: still pass: the rounding of ``2 a_w sin(pi / k)`` (six planets at clearance 0 touch exactly,
#: and land 1.8e-15 mm short). :func:`trains.synthesize` filters with the same tolerance, so its
#: candidates pass their own stage's check.
NEIGHBOUR_TOLERANCE = 1e-9

#: The most planets a stage may have (and the most :func:`max_planets` reports): far past any
#: stage that has been built, and a bound on the work of the assembly and neighbour checks.
MAX_PLANETS = 10_000


def planet_tips(stage) -> tuple[float, ...]:
    """The tip diameters of the distinct planet gears, mm."""
    return tuple(g.tip_diameter for g in stage.planet_gears)


def assembly(stage) -> Assembly:
    """The exact and textbook assembly conditions (:meth:`Planetary.assembly`)."""
    z1, z2, z2p, z3 = stage._z()
    k = stage.n_planets
    t = int(assembly_ticks(stage.scheme, z1, z2, z2p, z3))
    exact = t % k == 0 if t else True
    r = Fraction(*map(int, stage_ratio(stage.scheme, z1, z2, z2p, z3)))  # i_aH, ring fixed
    textbook = textbook_assembly(z1, r, k) if r != 0 else exact
    if t == 0:  # i0 = 1: any position (the stage turns as a block)
        return Assembly(k, 0, True, textbook, 0.0, tuple(360.0 * j / k for j in range(k)),
                        0.0, (k,))  # fmt: skip
    ticks = [round(Fraction(j * t, k)) for j in range(k)]
    spacing = tuple(360.0 * x / t for x in ticks)
    dev = max(abs(s - 360.0 * j / k) for j, s in enumerate(spacing))
    small = [d for d in range(1, math.isqrt(t) + 1) if t % d == 0]  # O(sqrt t), not O(t)
    divisors = sorted({*small, *(t // d for d in small)})
    below = [d for d in divisors if d < k]
    above = [d for d in divisors if d > k]
    near = tuple(x for x in ((below[-1] if below else None), (above[0] if above else None))
                 if x is not None)  # fmt: skip
    if exact:
        near = (k,)
    return Assembly(k, t, exact, textbook, 360.0 / t, spacing, dev, near)


def centres(stage, n: int) -> list[tuple[np.ndarray, float]]:
    """Planet centres (k x 2 arrays) with their tip radii, for ``n`` equal positions."""
    th = 2 * np.pi * np.arange(n) / n
    out = []
    tips = planet_tips(stage)
    if stage.scheme == "double-planet":
        a1 = stage._pairs["sun-planet"].center_distance
        a12 = stage._pairs["planet-planet2"].center_distance
        a2 = stage._pairs["planet2-ring"].center_distance
        cos_psi = (a1 * a1 + a2 * a2 - a12 * a12) / (2 * a1 * a2)
        psi = math.acos(min(1.0, max(-1.0, cos_psi)))
        out.append((a1 * np.stack([np.cos(th), np.sin(th)], 1), tips[0] / 2))
        out.append((a2 * np.stack([np.cos(th + psi), np.sin(th + psi)], 1), tips[1] / 2))
    else:
        a = stage._pairs["sun-planet"].center_distance
        out.append((a * np.stack([np.cos(th), np.sin(th)], 1), max(tips) / 2))
    return out


def neighbour_gap(stage, n: int) -> float:
    """Smallest tip-circle gap between planets that do not mesh, n planets (mm)."""
    if n < 2:
        return math.inf
    groups = centres(stage, n)
    gaps = []
    # the clusters are equally spaced, so cluster 0 sees every distance there is: its planets
    # against all others (O(n) instead of every pair, O(n^2))
    for ci, ri in groups:
        for cj, rj in groups:
            d = np.linalg.norm(ci[0] - cj, axis=1)
            mask = np.arange(n) != 0  # itself, or its own cluster's partner, which it meshes
            gaps.append(float(np.min(np.where(mask, d - ri - rj, np.inf))))
    return min(gaps)


def max_planets(stage) -> int:
    """The largest planet count that passes the neighbour condition (>= 1)."""
    need = (stage.clearance - NEIGHBOUR_TOLERANCE) * stage.module

    def fits(n: int) -> bool:
        return neighbour_gap(stage, n) >= need

    # the gap shrinks as planets are added (their spacing 360/n deg does): double the count
    # until one does not fit, then bisect (O(log n) gaps instead of one per count)
    lo = 1
    while lo < MAX_PLANETS and fits(min(2 * lo, MAX_PLANETS)):
        lo = min(2 * lo, MAX_PLANETS)
    if lo == MAX_PLANETS:
        return lo
    hi = min(2 * lo, MAX_PLANETS)  # does not fit
    while hi - lo > 1:
        mid = (lo + hi) // 2
        lo, hi = (mid, hi) if fits(mid) else (lo, mid)
    return lo


def coaxiality(stage, tolerance: float) -> Finding:
    """The ``coaxiality`` finding: the meshes' working centre distances agree (mm)."""
    pairs = stage._pairs
    if stage.scheme == "double-planet":
        a1 = pairs["sun-planet"].center_distance
        a12 = pairs["planet-planet2"].center_distance
        a2 = pairs["planet2-ring"].center_distance
        c = stage.clearance * stage.module
        ra_s = stage.sun.tip_diameter / 2
        ra_p1, ra_p2 = (g.tip_diameter / 2 for g in stage.planet_gears)
        ra_r = stage.ring.tip_diameter / 2
        margins = {
            "planet triangle closes (a12 > |a1 - a2|)": a12 - abs(a1 - a2),
            "planet triangle closes (a12 < a1 + a2)": a1 + a2 - a12,
            "outer planet clears the sun": a2 - ra_s - ra_p2 - c,
            "inner planet clears the ring": ra_r - a1 - ra_p1 - c,
        }
        worst = min(margins, key=margins.get)
        return Finding(
            "coaxiality", margins[worst],
            f"double-planet closure: a_sun-planet {a1:.4f}, a_planet-planet2 {a12:.4f}, "
            f"a_planet2-ring {a2:.4f} mm; tightest: {worst} by {margins[worst]:+.4f} mm",
            ok=margins[worst] >= -NEIGHBOUR_TOLERANCE * stage.module,  # as the search
        )  # fmt: skip
    a = [p.center_distance for p in pairs.values()]
    spread = max(a) - min(a)
    names = list(pairs)
    if all(p.g1.profile_shift == 0 and p.g2.profile_shift == 0 for p in pairs.values()):
        how = "zero shifts: the tooth-count condition"
    else:
        how = "with shifts, each a_w from its working pressure angle"
    return Finding(
        "coaxiality", tolerance - spread,
        f"working centre distances {names[0]} {a[0]:.4f} mm and {names[1]} {a[1]:.4f} mm "
        f"differ by {spread:.4f} mm (tolerance {tolerance:g} mm; {how})",
    )  # fmt: skip


def check(
    stage,
    tolerance: float = 0.01,
    min_contact_ratio: float = 1.1,
    min_tip_land: float = 0.2,
) -> Report:
    """Every condition of the stage (:meth:`Planetary.check`)."""
    k = stage.n_planets
    findings = [coaxiality(stage, tolerance)]
    asm = assembly(stage)
    r = asm.ticks % k if asm.ticks else 0
    if asm.exact:
        msg = (
            f"{k} equally spaced planets assemble: assembly number T = {asm.ticks} is a "
            f"multiple of {k} ({asm.ticks // k if k else 0} ticks apart; tick "
            f"{asm.tick_angle:.4f} deg)"
        )
    else:
        spacing = ", ".join(f"{s:.3f}" for s in asm.spacing)
        near = " or ".join(map(str, asm.nearest_counts))
        msg = (
            f"{k} equally spaced planets do not assemble: T = {asm.ticks} is not a multiple "
            f"of {k}; feasible unequal spacing on the tick {asm.tick_angle:.4f} deg: "
            f"[{spacing}] deg (max {asm.max_deviation:.3f} deg from equal); nearest "
            f"assemblable counts: {near}"
        )
    findings.append(Finding("assembly", -float(min(r, k - r)) or 0.0, msg, unit="teeth",
                            ok=asm.exact))  # fmt: skip
    tb = "accepts" if asm.textbook else "rejects"
    findings.append(
        Finding(
            "assembly_textbook", 0.0 if asm.textbook else -1.0,
            f"the textbook sufficient form (z_a i_aH / k)(1 + k p) in Z {tb} {k} planets "
            f"(informative; the exact gcd form decides)", unit="", ok=True,
        )
    )  # fmt: skip
    gap = neighbour_gap(stage, k)
    need = stage.clearance * stage.module
    tips = planet_tips(stage)
    if math.isinf(gap):
        nb = Finding("neighbour", 0.0, f"one planet: no neighbours (up to "
                     f"{max_planets(stage)} fit)", ok=True)  # fmt: skip
    else:
        nb = Finding(
            "neighbour", gap - need,
            f"smallest gap between planet tip circles {gap:.4f} mm (largest planet tip "
            f"d_a = {max(tips):.4f} mm after tip shortening) vs clearance {need:.4f} mm; "
            f"the largest planet count that fits is {max_planets(stage)}",
            ok=gap - need >= -NEIGHBOUR_TOLERANCE * stage.module,
        )  # fmt: skip
    findings.append(nb)
    findings.append(
        Finding(
            "redundant_constraints", float(k - 1),
            f"{k} planets add q = {k - 1} redundant (passive) constraints (Ozols §21-13); "
            "equal load sharing needs a floating sun or ring, or flexible pins",
            unit="", ok=True,
        )
    )  # fmt: skip
    for key, (nominal, relieved) in stage._relief.items():
        findings.append(
            Finding(
                f"{key}_tip_relief", (relieved - nominal) / 2,
                f"{key} tip diameter enlarged from {nominal:.4f} to {relieved:.4f} mm so its "
                "tip stays on the planet's involute (above the planet's form circle); make the "
                "ring blank to this diameter", ok=True,
            )
        )  # fmt: skip
    for name, pair in stage._pairs.items():
        findings.extend(pair.check(min_contact_ratio, min_tip_land).prefixed(name).values())
    return Report(findings)


def ring_tip_alteration(z_planet, z_ring, module, rack: BasicRack | None = None) -> np.ndarray:
    """Tip alteration k (modules) :class:`trains.Planetary` gives a zero-shift ring meshing a
    zero-shift spur planet (``ring_tip_relief``): 0 where the ring's tip clears the planet's
    form circle, else the k that enlarges its tip circle to the limit rounded up to 1 um
    (``GearPair.tip_diameter_limits``)."""
    rack = rack or BasicRack.iso53()
    pa = rack.pressure_angle
    zp, zr, m = np.broadcast_arrays(*(np.asarray(v, float) for v in (z_planet, z_ring, module)))
    shape = zp.shape
    zp, zr, m = (v.ravel() for v in (zp, zr, m))  # pair_geometry takes flat arrays
    g = pair_geometry(zp, zr, m, 0.0, 0.0, pa, 0.0, True, rack.addendum, True, threads=1)
    cos_a = math.cos(math.radians(pa))
    rb1, rb2 = zp * m * cos_a / 2, zr * m * cos_a / 2
    tan_wt = np.tan(np.radians(g.working_pressure_angle))
    u_n2 = rb1 * tan_wt - rb2 * tan_wt
    with np.errstate(invalid="ignore"):
        l1 = form_lengths(undercut_form_diameter(zp, m, 0.0, pa, 0.0, rack), 2 * rb1)
    limit = 2.0 * np.sqrt(rb2 * rb2 + (u_n2 - l1) ** 2)
    target = np.ceil(limit * 1000.0) / 1000.0
    k = (zr * m - target) / (2 * m) - rack.addendum
    relieve = np.isfinite(limit) & (np.asarray(g.tip_diameter_2) < limit)
    return np.where(relieve, k, 0.0).reshape(shape)
