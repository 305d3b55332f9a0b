"""Layer 2, centrodes: the pitch curves of a non-circular pair from its motion law.

Two bodies turning about fixed centres O1, O2 (centre distance a) with the ratio
i(phi) = omega1/omega2 roll their centrodes on each other; the pole P lies on O1O2 where
(Ozols section 19-1)

* (19.1) O1P / O2P = omega2 / omega1;
* (19.2) O1P = a / (1 + omega1/omega2) for an external pair (P between the centres), and
  ``O1P = a / |1 - omega1/omega2|`` for an internal one (P outside them);
* (19.3) the centrodes in polar coordinates: gear 1's radius O1P laid off at the angle
  phi = integral(omega1 dt) opposite to its rotation, gear 2's radius O2P at
  psi = integral(omega2 dt), so psi(phi) = integral(d phi / i);
* (19.4), (19.5) a body turning on a translating one (a rack): O1P = v / omega = ds/dphi, the
  rack's centrode the curve (s(phi), O1P(phi)).

Every formula here is a vectorised numpy function of arrays (radians, mm). The motion law
itself is held by :class:`MotionLaw`, a periodic cubic spline of d psi / d phi over one period
of the law, whose antiderivative is the output angle and whose lobes say how the curves close.

Examples
--------
>>> float(pole_radius(2.0, 100.0))              # Ozols (19.2): a = 100, omega1/omega2 = 2
33.333333333333336
>>> float(pole_radius(0.5, 100.0, "internal"))  # Ozols (19.2), internal: O1P = 200
200.0
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy.interpolate import CubicSpline
from scipy.optimize import brentq

from gears.arguments import check_choice, check_integer, check_positive, check_real
from gears.errors import GearError

__all__ = [
    "KINDS",
    "LAW_SAMPLES",
    "MAX_LOBES",
    "MotionLaw",
    "center_distance_for_lobes",
    "eccentric_radius",
    "elliptical_radius",
    "polar_arc_length",
    "polar_curvature",
    "pole_radii",
    "pole_radius",
    "rack_centrode",
]

#: The kinds of pair: gear 2 an external gear, an internal gear (a ring), or gear 1 a ring.
KINDS = ("external", "internal")

#: Samples of the law over one period (the spline's knots): a smooth law's output angle is then
#: exact to about 1e-12 of a turn (the cubic spline's error falls as h^4).
LAW_SAMPLES = 1024

#: The most lobes a centrode may have.
MAX_LOBES = 64


def pole_radius(ratio, center_distance, kind: str = "external"):
    """O1P, the pole's distance from gear 1's centre, mm (Ozols (19.2)).

    ``ratio`` is omega1/omega2 (> 0; for an internal pair != 1), arrays broadcast.
    """
    i = np.asarray(ratio, dtype=float)
    a = np.asarray(center_distance, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):  # a ratio of 1 puts P at infinity
        if kind == "external":
            return a / (1.0 + i)
        return a / np.abs(1.0 - i)


def pole_radii(ratio, center_distance, kind: str = "external"):
    """(O1P, O2P) in mm: gear 1's and gear 2's centrode radii at the pole (Ozols (19.1),
    (19.2)); O2P = i O1P for both kinds."""
    r1 = pole_radius(ratio, center_distance, kind)
    return r1, np.asarray(ratio, dtype=float) * r1


def polar_curvature(r, dr, ddr):
    """Signed curvature (1/mm) of the polar curve r(theta) from r, dr/dtheta, d2r/dtheta2:
    (r^2 + 2 r'^2 - r r'') / (r^2 + r'^2)^(3/2), positive where the curve is convex."""
    r, dr, ddr = (np.asarray(x, dtype=float) for x in (r, dr, ddr))
    return (r * r + 2.0 * dr * dr - r * ddr) / np.power(r * r + dr * dr, 1.5)


def polar_arc_length(r, dr):
    """ds/dtheta = sqrt(r^2 + r'^2) of a polar curve (mm per radian)."""
    return np.hypot(np.asarray(r, dtype=float), np.asarray(dr, dtype=float))


def elliptical_radius(phi, semi_major, eccentricity, lobes=1):
    """An ellipse's radius from its focus, A (1 - e^2) / (1 - e cos(n phi)) (Litvin, elliptical
    gears; ``lobes`` n > 1 gives the n-lobed oval of the same law)."""
    e = np.asarray(eccentricity, dtype=float)
    return (
        np.asarray(semi_major, dtype=float)
        * (1.0 - e * e)
        / (1.0 - e * np.cos(np.asarray(lobes) * np.asarray(phi, dtype=float)))
    )


def eccentric_radius(phi, radius, offset):
    """A circle of ``radius`` turning about a point ``offset`` from its centre: the distance
    from that point to the circle at the polar angle phi, e cos phi + sqrt(R^2 - e^2 sin^2 phi)."""
    phi = np.asarray(phi, dtype=float)
    e = np.asarray(offset, dtype=float)
    return e * np.cos(phi) + np.sqrt(np.asarray(radius) ** 2 - (e * np.sin(phi)) ** 2)


def rack_centrode(s, ds_dphi):
    """The centrodes of a gear turning on a translating rack (Ozols (19.4), (19.5)): gear 1's
    radius O1P = v/omega = ds/dphi and the rack's pitch curve (x, y) = (s, ds/dphi)."""
    r1 = np.asarray(ds_dphi, dtype=float)
    return r1, np.stack(np.broadcast_arrays(np.asarray(s, dtype=float), r1), axis=-1)


def _samples(name: str, law, period: float) -> np.ndarray:
    """The law sampled at LAW_SAMPLES points of one period (radians in, floats out)."""
    n = LAW_SAMPLES
    phi = np.arange(n) * (period / n)
    if callable(law):
        deg = np.degrees(phi)
        try:
            out = np.asarray(law(deg), dtype=float)
            if out.shape != deg.shape:
                out = np.broadcast_to(out, deg.shape).astype(float)
        except GearError:
            raise
        except Exception:  # a scalar-only callable: one call a sample
            try:
                out = np.array([float(law(float(d))) for d in deg])
            except Exception as exc:
                raise GearError(
                    f"{name} = {law!r} could not be evaluated at the input angle (degrees): {exc}"
                ) from None
        return out
    try:
        values = np.asarray(law, dtype=float)
    except (TypeError, ValueError):
        raise GearError(
            f"{name} = {law!r}; valid is a number, a callable of the input angle (degrees) or "
            "samples over one period"
        ) from None
    if values.ndim == 0:
        return np.full(n, float(values))
    if values.ndim != 1 or not 4 <= values.size <= 100_000:
        raise GearError(
            f"{name} has {values.size} samples; valid is 4 ... 100000 samples of one period, "
            "equally spaced, the period's end left out"
        )
    # periodic resampling of the user's samples onto the spline's grid
    grid = np.arange(values.size + 1) * (period / values.size)
    if not np.all(np.isfinite(values)):
        bad = values[~np.isfinite(values)][0]
        raise GearError(f"{name} has the sample {bad}; valid are finite numbers")
    spline = CubicSpline(grid, np.append(values, values[0]), bc_type="periodic")
    return spline(phi)


@dataclass(frozen=True)
class MotionLaw:
    """q(phi) = d psi / d phi = omega2 / omega1 over one period of gear 1 (``period`` radians,
    2 pi / lobes1), as a periodic cubic spline; psi(phi) its integral, continued period by
    period. ``advance`` is psi over one period (2 pi / lobes2 when the curves close)."""

    spline: CubicSpline
    period: float
    advance: float

    @classmethod
    def from_speed_ratio(cls, q: np.ndarray, period: float) -> MotionLaw:
        """The law of q = omega2/omega1 sampled at LAW_SAMPLES points of one period."""
        grid = np.arange(q.size + 1) * (period / q.size)
        spline = CubicSpline(grid, np.append(q, q[0]), bc_type="periodic")
        advance = float(spline.integrate(0.0, period))
        return cls(spline, period, advance)

    def q(self, phi, nu: int = 0):
        """d psi/d phi (``nu`` = 0), or its derivatives (1, 2), at phi (radians)."""
        x = np.mod(np.asarray(phi, dtype=float), self.period)
        return self.spline(x, nu)

    def psi(self, phi):
        """The output angle psi(phi), radians (psi(0) = 0)."""
        phi = np.asarray(phi, dtype=float)
        k = np.floor(phi / self.period)
        x = phi - k * self.period
        return k * self.advance + self.spline.antiderivative()(x)


def law_from_ratio(ratio, lobes: int = 1, name: str = "ratio") -> MotionLaw:
    """A :class:`MotionLaw` from omega1/omega2: a number, a callable of the input angle in
    degrees (vectorised or not), or samples over one period (360/lobes degrees)."""
    period = 2.0 * math.pi / lobes
    i = _samples(name, ratio, period)
    if not np.all(np.isfinite(i)) or np.any(i <= 0.0):
        k = int(np.argmin(np.where(np.isfinite(i), i, -np.inf)))
        raise GearError(
            f"{name} = {i[k]:g} at the input angle {math.degrees(k * period / i.size):.4g} deg; "
            "valid is a finite ratio omega1/omega2 > 0 over the whole cycle"
        )
    return MotionLaw.from_speed_ratio(1.0 / i, period)


def law_from_output(psi, lobes: int = 1, name: str = "psi") -> MotionLaw:
    """A :class:`MotionLaw` from the output law psi(phi) (degrees to degrees, a callable or
    samples over one period with the end value: LAW_SAMPLES + 1 or any count >= 5)."""
    period = 2.0 * math.pi / lobes
    if callable(psi):
        n = LAW_SAMPLES
        values = _samples(name, lambda d: psi(d), period)
        end = _samples(name, lambda d: psi(np.asarray(d) + math.degrees(period)), period)[:1]
        values = np.radians(np.append(values, end))
    else:
        try:
            values = np.radians(np.asarray(psi, dtype=float))
        except (TypeError, ValueError):
            raise GearError(f"{name} = {psi!r}; valid is a callable or samples (degrees)") from None
        if values.ndim != 1 or not 5 <= values.size <= 100_001:
            raise GearError(
                f"{name} has {values.size} samples; valid is 5 ... 100001 samples of one period, "
                "equally spaced, both ends included"
            )
    if not np.all(np.isfinite(values)):
        raise GearError(f"{name} has a sample that is not finite; valid are finite angles")
    n = values.size - 1
    advance = values[-1] - values[0]
    if not advance > 0:
        raise GearError(
            f"{name} advances {math.degrees(advance):g} deg over one period; valid is an "
            "output that turns forwards (psi(phi + period) > psi(phi))"
        )
    grid = np.arange(n + 1) * (period / n)
    trend = advance * grid / period
    spline = CubicSpline(grid, values - values[0] - trend, bc_type="periodic")
    q = spline(grid[:-1], 1) + advance / period
    fine = np.arange(LAW_SAMPLES) * (period / LAW_SAMPLES)
    q = np.interp(fine, grid, np.append(q, q[0])) if n != LAW_SAMPLES else q
    if np.any(q <= 0.0):
        k = int(np.argmin(q))
        raise GearError(
            f"{name} turns backwards near the input angle {math.degrees(fine[k]):.4g} deg "
            f"(d psi/d phi = {q[k]:.3g}); valid is an output law that increases everywhere"
        )
    return MotionLaw.from_speed_ratio(q, period)


def closing_lobes(law: MotionLaw, name: str = "ratio") -> int:
    """Gear 2's lobes: 2 pi / (psi over one period), a whole number when the curves close, or a
    :class:`GearError` saying by how much the law misses closing."""
    lobes = 2.0 * math.pi / law.advance
    n2 = round(lobes)
    if n2 < 1 or n2 > MAX_LOBES or abs(lobes - n2) > 1e-6 * max(1.0, lobes):
        near = max(1, min(MAX_LOBES, n2))
        scale = lobes / near
        raise GearError(
            f"{name} cannot close: one period of the law ({math.degrees(law.period):.6g} deg of "
            f"gear 1) turns gear 2 by {math.degrees(law.advance):.9g} deg, which is "
            f"360/{lobes:.9g}; valid is 360/n2 for a whole number of lobes n2 = 1 ... "
            f"{MAX_LOBES} (multiply the ratio by {scale:.9g} for n2 = {near}"
            + (", or give gear 1 more lobes)" if lobes < 1 else ")")
        )
    return n2


def center_distance_for_lobes(radius: Callable, lobes1: int, lobes2: int, kind: str = "external"):
    """The centre distance at which gear 1's centrode ``radius(phi)`` (radians in, mm out,
    vectorised, period 2 pi / lobes1) rolls on a closed gear 2 of ``lobes2`` lobes: psi over one
    period, the integral of r1 / (a -+ r1), equals 2 pi / lobes2 (Litvin's closure condition)."""
    kind = check_choice("kind", kind, KINDS)
    n1 = check_integer("lobes1", lobes1, 1, MAX_LOBES)
    n2 = check_integer("lobes2", lobes2, 1, MAX_LOBES)
    period = 2.0 * math.pi / n1
    phi = np.arange(LAW_SAMPLES) * (period / LAW_SAMPLES)
    r = np.asarray(radius(phi), dtype=float)
    if not np.all(np.isfinite(r)) or np.any(r <= 0):
        raise GearError("the pitch curve's radius must be finite and > 0 over the whole turn")
    target = 2.0 * math.pi / n2
    grid = np.append(phi, period)
    r_closed = np.append(r, r[0])

    def advance(a: float) -> float:
        q = r_closed / (a - r_closed) if kind == "external" else r_closed / (a + r_closed)
        return float(CubicSpline(grid, q, bc_type="periodic").integrate(0.0, period)) - target

    rmax = float(r.max())
    if kind == "internal" and n2 <= n1:
        raise GearError(
            f"lobes = ({n1}, {n2}); an internal gear 2 around gear 1 needs more lobes than "
            f"gear 1: valid is lobes2 > {n1}"
        )
    lo = rmax * (1.0 + 1e-9) if kind == "external" else 1e-12 * rmax
    hi = rmax * 2.0
    while advance(hi) > 0:
        hi *= 2.0
        if hi > 1e9 * rmax:  # pragma: no cover - advance falls to 0 as a grows
            raise GearError(f"no centre distance closes lobes = ({n1}, {n2})")
    return brentq(advance, lo, hi, xtol=1e-13 * rmax, rtol=1e-15)


def check_law_radii(ratio, r1, r2, kind: str) -> None:
    """Refuse centrodes with a radius that is not positive and finite (a ratio of 1 on an
    internal pair, a law crossing it)."""
    side = np.sign(1.0 - np.asarray(ratio, dtype=float))
    if kind == "internal" and not (np.all(side > 0) or np.all(side < 0)):
        raise GearError(
            f"the internal pair's ratio omega1/omega2 runs from {float(np.min(ratio)):.4g} to "
            f"{float(np.max(ratio)):.4g}; valid is a ratio that stays on one side of 1 (a ratio "
            "of 1 puts the pole at infinity: the centrodes' radii are not positive and finite)"
        )
    for k, r in ((1, r1), (2, r2)):
        if not np.all(np.isfinite(r)) or np.any(r <= 0.0):
            raise GearError(
                f"the {kind} pair's centrode of gear {k} has a radius that is not positive and "
                "finite (an internal pair's ratio omega1/omega2 must stay on one side of 1)"
            )


def check_center_distance(value) -> float:
    """A centre distance in mm (finite, > 0, and not beyond 1e9 mm)."""
    v = check_positive("center_distance", value)
    return check_real("center_distance", v, 0.0, 1e9)
