"""Layer 2, cycloid: cycloidal tooth profiles and the cycloidal drive's disc, as vectorised
functions of the rolling angle (radians, mm).

* :func:`epicycloid`, :func:`hypocycloid`: the curves a point at ``offset`` from the centre of a
  circle of ``rolling_radius`` traces as it rolls outside / inside a ``base_radius`` circle (the
  tooth profiles of cycloidal (clock) gearing: an addendum is an epicycloid on the pitch circle,
  a dedendum a hypocycloid; Joldasbekov section 7). ``offset`` below the rolling radius gives
  the curtate curves (trochoids) that pin gearing's pin centres trace.
* :func:`pin_path`: the curve pin 0's centre traces in the frame of a cycloidal drive's disc:
  N pins on a circle of radius R about the fixed centre, the disc's centre on the eccentric at
  e (cos theta, sin theta), the disc turning by -theta / (N - 1) (the K-H-V train of N - 1 and N
  teeth with the eccentric as carrier: Ozols Fig 7-9b, i = 1 - N / (N - 1)). Every pin lies on
  this one curve at every theta (pin j is pin 0 at theta + (N - 1) 2 pi j / N), so the disc that
  touches all pins is its inward parallel curve at the pin radius: :func:`disc_profile`.
* :func:`path_curvature`: the pin path's signed curvature; the disc has no cusp (undercut)
  where the pin radius stays below the radius of curvature of the path's convex stretches.

Examples
--------
>>> import numpy as np
>>> p = pin_path(np.array([0.0]), 10, 2.0, 50.0)   # theta = 0: pin 0 at R - e from the disc centre
>>> [round(float(v), 9) for v in p[0]]
[48.0, 0.0]
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "cycloidal_gear_outline",
    "cycloidal_tooth_flank",
    "disc_profile",
    "epicycloid",
    "hypocycloid",
    "path_curvature",
    "pin_path",
    "pin_path_derivatives",
]


def epicycloid(t, base_radius, rolling_radius, offset=None):
    """(x, y) of the point at ``offset`` (default: on the rim) from the centre of a circle of
    ``rolling_radius`` rolling outside the ``base_radius`` circle, at the rolling angle t about
    the base centre (the point starts on the base circle at t = 0, on the +x axis)."""
    t = np.asarray(t, dtype=float)
    big, r = np.asarray(base_radius, float), np.asarray(rolling_radius, float)
    d = r if offset is None else np.asarray(offset, float)
    k = (big + r) / r
    x = (big + r) * np.cos(t) - d * np.cos(k * t)
    y = (big + r) * np.sin(t) - d * np.sin(k * t)
    return np.stack([x, y], axis=-1)


def hypocycloid(t, base_radius, rolling_radius, offset=None):
    """(x, y) of the point at ``offset`` (default: on the rim) from the centre of a circle of
    ``rolling_radius`` rolling inside the ``base_radius`` circle (starting on it at +x)."""
    t = np.asarray(t, dtype=float)
    big, r = np.asarray(base_radius, float), np.asarray(rolling_radius, float)
    d = r if offset is None else np.asarray(offset, float)
    k = (big - r) / r
    x = (big - r) * np.cos(t) + d * np.cos(k * t)
    y = (big - r) * np.sin(t) - d * np.sin(k * t)
    return np.stack([x, y], axis=-1)


def pin_path_derivatives(theta, pins, eccentricity, pin_circle_radius):
    """(Q, Q', Q'') of :func:`pin_path` with respect to theta, each (..., 2):
    Q = Rot(w theta) V with w = 1/(N - 1) and V = (R - e cos theta, -e sin theta)."""
    th = np.asarray(theta, dtype=float)
    n = np.asarray(pins, dtype=float)
    e = np.asarray(eccentricity, dtype=float)
    big = np.asarray(pin_circle_radius, dtype=float)
    w = 1.0 / (n - 1.0)
    vx, vy = big - e * np.cos(th), -e * np.sin(th)
    dvx, dvy = e * np.sin(th), -e * np.cos(th)
    ddvx, ddvy = e * np.cos(th), e * np.sin(th)
    c, s = np.cos(w * th), np.sin(w * th)

    def rot(x, y):
        return np.stack([c * x - s * y, s * x + c * y], axis=-1)

    # d/dtheta Rot(w theta) V = Rot(w theta) (w J V + V'), J the quarter turn
    q = rot(vx, vy)
    dq = rot(-w * vy + dvx, w * vx + dvy)
    ddq = rot(-w * w * vx - 2.0 * w * dvy + ddvx, -w * w * vy + 2.0 * w * dvx + ddvy)
    return q, dq, ddq


def pin_path(theta, pins, eccentricity, pin_circle_radius):
    """Pin 0's centre in the disc's frame at the eccentric angle theta (module docstring);
    theta over 0 ... 2 pi (N - 1) traces the whole closed curve of N - 1 lobes."""
    return pin_path_derivatives(theta, pins, eccentricity, pin_circle_radius)[0]


def path_curvature(theta, pins, eccentricity, pin_circle_radius):
    """Signed curvature (1/mm) of the pin path, positive where it bends about the disc's centre
    (convex, seen from inside)."""
    _, d1, d2 = pin_path_derivatives(theta, pins, eccentricity, pin_circle_radius)
    cross = d1[..., 0] * d2[..., 1] - d1[..., 1] * d2[..., 0]
    return cross / np.power(np.hypot(d1[..., 0], d1[..., 1]), 3)


def disc_profile(theta, pins, pin_radius, eccentricity, pin_circle_radius):
    """The disc's profile: the pin path moved inwards along its normal by the pin radius
    (points (..., 2), mm). With the clearance modifications, call it with the modified pin
    radius (equidistant: rp + d_rp) and pin circle (radial: R - d_R)."""
    q, d1, _ = pin_path_derivatives(theta, pins, eccentricity, pin_circle_radius)
    speed = np.hypot(d1[..., 0], d1[..., 1])
    # the path runs counter-clockwise: its outward normal is the tangent turned clockwise
    normal = np.stack([d1[..., 1], -d1[..., 0]], axis=-1) / speed[..., None]
    return q - np.asarray(pin_radius, dtype=float)[..., None] * normal


def _flank_end(curve, radius: float, target: float, t_max: float) -> float:
    """The rolling angle at which ``curve(t)`` (starting on the pitch circle) reaches the
    radius ``target`` (Brent's method)."""
    from scipy.optimize import brentq  # heavy: imported where used

    def f(t):
        p = curve(np.array([t]))[0]
        return float(np.hypot(p[0], p[1]) - target)

    return brentq(f, 0.0, t_max, xtol=1e-14)


def cycloidal_tooth_flank(teeth, module, rolling_radius, addendum=1.0, dedendum=1.25,
                          samples=200):  # fmt: skip
    """The right flank of a cycloidal (clock) gear tooth centred on +x, from the root to the
    tip, (samples, 2) points: a hypocycloid of ``rolling_radius`` inside the pitch circle (the
    dedendum) and an epicycloid of it outside (the addendum), meeting on the pitch circle at
    half a tooth thickness (p/4) from the tooth's centre line (Joldasbekov section 7). Gears of
    one rolling circle are conjugate: a tooth's addendum and its mate's dedendum are traced by
    the same point of the circle."""
    z, m, rho = float(teeth), float(module), float(rolling_radius)
    r = z * m / 2.0
    n = max(int(samples) // 2, 4)
    t_tip = _flank_end(lambda t: epicycloid(t, r, rho), r, r + addendum * m, np.pi * rho / r)
    t_root = _flank_end(lambda t: hypocycloid(t, r, rho), r, r - dedendum * m, np.pi * rho / r)
    up = epicycloid(np.linspace(0.0, t_tip, n), r, rho)
    down = hypocycloid(np.linspace(t_root, 0.0, n), r, rho) * [1.0, -1.0]
    flank = np.vstack([down[:-1], up])
    beta = -np.pi / (2.0 * z)  # the pitch point half a tooth's angle below the centre line
    c, s = np.cos(beta), np.sin(beta)
    return flank @ np.array([[c, s], [-s, c]])


def cycloidal_gear_outline(teeth, module, rolling_radius, tolerance=0.01, addendum=1.0,
                           dedendum=1.25):  # fmt: skip
    """A cycloidal (clock) gear's outline, a shapely Polygon centred on the origin, tooth 0 on
    +x: :func:`cycloidal_tooth_flank` and its mirror image, tip and root arcs, patterned
    ``teeth`` times; the flanks sampled densely enough that their chords sag below
    ``tolerance`` mm (the epicycloid's least radius of curvature on the flank is near the
    pitch circle, 4 rho (r + rho) / (r + 2 rho) sin(t/2) -> its chord rule is taken at the
    flank's middle, the cusp itself lies off the flank)."""
    import shapely  # heavy: imported where used

    from gears.arguments import check_integer, check_module, check_real, check_tolerance

    z, m = check_integer("teeth", teeth, 3, 10_000), check_module(module)
    r = z * m / 2.0
    check_real("rolling_radius", rolling_radius, 0.0, r)
    tolerance = check_tolerance(tolerance, module=m)
    check_real("addendum", addendum, 0.0, 2.0, low_open=False)
    check_real("dedendum", dedendum, 0.0, min(2.0, 0.95 * r / m))
    length = (addendum + dedendum) * m * 1.5
    n = int(min(max(16, np.ceil(length / np.sqrt(8.0 * tolerance * m))), 20_000))
    right = cycloidal_tooth_flank(z, m, rolling_radius, addendum, dedendum, 2 * n)
    left = (right * [1.0, -1.0])[::-1]
    ra, rf = r + addendum * m, r - dedendum * m

    def arc(radius, a0, a1):
        k = max(
            2, int(np.ceil(abs(a1 - a0) / (2.0 * np.arccos(max(-1.0, 1.0 - tolerance / radius)))))
        )
        t = np.linspace(a0, a1, k + 1)[1:-1]
        return radius * np.stack([np.cos(t), np.sin(t)], axis=-1)

    tip = arc(ra, np.arctan2(right[-1, 1], right[-1, 0]), np.arctan2(left[0, 1], left[0, 0]))
    a_root = np.arctan2(left[-1, 1], left[-1, 0])
    root = arc(rf, a_root, a_root + 2.0 * np.pi / z - 2.0 * (a_root))
    tooth = np.vstack([right, tip, left, root])
    step = 2.0 * np.pi / z
    rings = []
    for k in range(z):
        c, s = np.cos(k * step), np.sin(k * step)
        rings.append(tooth @ np.array([[c, s], [-s, c]]))
    return shapely.Polygon(np.vstack(rings))
