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
