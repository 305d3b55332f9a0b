"""Layer 4, worm flanks: the axial-section profiles of the DIN 3975 flank forms ZA, ZN, ZI and
ZK, which define each thread as a helicoid (a screw surface).

A thread flank of a worm of lead ``p_z`` is a helicoid: a point ``(r, theta, z)`` (cylindrical,
the worm's axis ``z``) lies on it when ``z = h(r) + p theta`` (right hand; ``-p theta`` left)
with ``p = p_z / (2 pi)``. The axial section ``h(r)`` (at ``theta = 0``) of the flank facing
``+z`` of the thread centred at ``z = 0`` is the *axial half thickness*; the other flank is its
mirror ``-h(r)``. With ``r_m = d_m1 / 2``, ``h(r_m) = s_x / 2`` (the axial thread thickness at
the reference cylinder; ``p_x / 2`` at zero backlash) and (DIN 3975-1, ISO/TR 10828):

* **ZA** (Archimedean): straight in the axial section, ``h = s_x / 2 - (r - r_m) tan alpha_x``;
* **ZI** (involute helicoid): an involute of the base circle ``r_b = p / tan gamma_b`` in every
  transverse section, ``h = s_x / 2 - p (inv alpha_t(r) - inv alpha_t(r_m))``,
  ``cos alpha_t(r) = r_b / r``; below the base cylinder, where no involute exists, the thread
  keeps the base cylinder's axial thickness (the check ``flank_above_base`` says whether the
  contact reaches there);
* **ZN** (convolute, ZN1): straight in the normal section of the thread at the reference
  cylinder, at ``alpha_n`` to the radial direction; a point ``u`` along that line is
  ``(r_m + u, -w sin gamma, w cos gamma)`` with ``w = w_0 - u tan alpha_n``, so
  ``r^2 = (r_m + u)^2 + w^2 sin^2 gamma`` (a quadratic in ``u``) and
  ``h = w cos gamma + p atan(w sin gamma / (r_m + u))``; ``w_0`` is set so that the section
  passes through ``(r_m, s_x / 2)``;
* **ZK** (ZK1): ground by a double cone (a disc wheel of radius ``R_0`` at the reference
  cylinder, profile angle ``alpha_n``) whose axis is the thread's normal at the reference
  cylinder and whose mid-plane holds the thread's tangent; the flank is the envelope of the
  cone in the worm's screw motion. A point of the cone touches the flank where its normal
  ``n`` is perpendicular to the screw's velocity ``V = e_z x P + p e_z`` (Joldasbekov §6-3,
  Olivier's condition); ``n . V`` is ``A cos psi + B sin psi + D`` in the cone's polar angle
  ``psi``, solved in closed form.

Examples
--------
>>> h = axial_half_thickness("ZA", [20.0, 22.0], 2, 4.0, 10.0)
>>> [round(float(v), 6) for v in h]       # p_x / 4 = pi, then 2 tan 20 deg less
[3.141593, 2.413652]
"""

from __future__ import annotations

import numpy as np

from gears.involute import inv
from gears.worm.geometry import worm_geometry

__all__ = ["axial_half_thickness", "zk_contact"]

#: Samples of the ZK envelope over the depth (then interpolated; the profile is smooth, the
#: interpolation error is below 1e-9 modules at this count).
ZK_SAMPLES = 4097


def _out(a):
    a = np.asarray(a)
    return a[()] if a.ndim == 0 else a


def axial_half_thickness(
    flank, radius, z1, module, diameter_quotient, pressure_angle=20.0, thickness=None,
    tool_radius=None,
):  # fmt: skip
    """The axial half thickness ``h(r)`` (mm) of the thread at the radii ``radius`` (module
    docstring). ``thickness`` is the axial thread thickness ``s_x`` at the reference cylinder
    (default ``p_x / 2``); ``tool_radius`` the ZK wheel's radius ``R_0`` at the reference
    cylinder (default 10 axial modules). Every argument but ``flank`` broadcasts (ZK computes
    its envelope once per distinct row of parameters).
    """
    g = worm_geometry(z1, 1, module, diameter_quotient, pressure_angle, flank)
    m = np.asarray(module, float)
    rm = np.asarray(g.worm_diameter) / 2.0
    p = np.asarray(g.lead) / (2.0 * np.pi)
    s_x = np.asarray(g.axial_pitch) / 2.0 if thickness is None else np.asarray(thickness, float)
    half = s_x / 2.0
    r = np.asarray(radius, float)
    gamma = np.radians(np.asarray(g.lead_angle))
    an = np.radians(np.asarray(g.normal_pressure_angle))
    if flank == "ZA":
        return _out(half - (r - rm) * np.tan(np.radians(np.asarray(g.axial_pressure_angle))))
    if flank == "ZI":
        rb = np.asarray(g.worm_base_diameter) / 2.0

        def theta(rr):
            return inv(np.arccos(np.minimum(rb / np.maximum(rr, rb), 1.0)))

        return _out(half - p * (theta(r) - theta(rm)))
    if flank == "ZN":
        return _out(_zn(r, rm, p, half, gamma, an))
    if flank == "ZK":
        r0 = 10.0 * m if tool_radius is None else np.asarray(tool_radius, float)
        params = np.broadcast_arrays(rm, p, half, gamma, an, r0, m)
        if params[0].size == 1:  # one worm: one envelope, interpolated at every radius
            rr, hh = zk_contact(*(float(v.ravel()[0]) for v in params))
            return _out(_interp(r, rr, hh))
        rows = np.broadcast_arrays(r, *params)
        out = np.empty(rows[0].shape)
        cache: dict[tuple, tuple] = {}
        for idx in np.ndindex(out.shape):
            key = tuple(float(v[idx]) for v in rows[1:])
            if key not in cache:
                cache[key] = zk_contact(*key)
            rr, hh = cache[key]
            out[idx] = _interp(rows[0][idx], rr, hh)
        return _out(out)
    raise ValueError(f"flank = {flank!r}; valid are 'ZA', 'ZN', 'ZI', 'ZK'")


def _interp(x, xs, ys):
    """``np.interp`` continued along the end tangents beyond the samples (ZK's flank past the
    fold of its generated branch, which the checks keep outside the working depth)."""
    y = np.interp(x, xs, ys)
    k0 = (ys[1] - ys[0]) / (xs[1] - xs[0])
    k1 = (ys[-1] - ys[-2]) / (xs[-1] - xs[-2])
    y = np.where(x < xs[0], ys[0] + (x - xs[0]) * k0, y)
    return np.where(x > xs[-1], ys[-1] + (x - xs[-1]) * k1, y)


def _zn_section(r, rm, p, w0, gamma, an):
    s, t = np.sin(gamma), np.tan(an)
    # (1 + t^2 s^2) u^2 + 2 (r_m - w0 t s^2) u + (r_m^2 + w0^2 s^2 - r^2) = 0, the root near 0
    qa = 1.0 + (t * s) ** 2
    qb = 2.0 * (rm - w0 * t * s**2)
    qc = rm**2 + (w0 * s) ** 2 - r**2
    disc = np.sqrt(np.maximum(qb**2 - 4.0 * qa * qc, 0.0))
    u = -2.0 * qc / (qb + disc)  # the stable form of (-qb + disc) / (2 qa)
    w = w0 - u * t
    return w * np.cos(gamma) + p * np.arctan2(w * s, rm + u)


def _zn(r, rm, p, half, gamma, an):
    # w0 so that the section passes (r_m, half): Newton on a smooth equation (every row at
    # once; the slope is near cos(gamma) + p sin(gamma) / r_m, far from zero)
    w0 = half * np.cos(gamma)
    for _ in range(8):
        f = _zn_section(rm, rm, p, w0, gamma, an) - half
        step = 1e-6 * rm
        df = (_zn_section(rm, rm, p, w0 + step, gamma, an) - half - f) / step
        w0 = w0 - f / df
    return _zn_section(r, rm, p, w0, gamma, an)


def zk_contact(rm, p, half, gamma, an, tool_radius, module, samples=ZK_SAMPLES):
    """The ZK flank's axial section ``(r, h)`` sampled over the depth ``r_m +- 2.5 m`` (module
    docstring): for each radius ``rho`` of the grinding cone, the contact point solved in
    closed form, then rotated back to ``theta = 0``. Returns increasing radii: the branch of
    the contact through the reference cylinder (on a steep lead it folds near the root, where
    :func:`axial_half_thickness` continues the flank along its tangent)."""
    s, c = np.sin(gamma), np.cos(gamma)
    ex = np.array([1.0, 0.0, 0.0])
    k = np.array([0.0, -s, c])  # the cone's axis: the thread's normal at the reference cylinder
    b = np.array([0.0, -c, -s])  # completes (-e_x, b, k)
    # the cone sits in the space above the thread: its lower face grinds the flank +h
    space_half = (np.pi * module - 2.0 * half) / 2.0  # axial half width of the space
    centre = np.array([rm + tool_radius, 0.0, half + space_half])
    t = np.tan(an)
    depth = np.linspace(-2.5 * module, 2.5 * module, samples)  # r - r_m at psi = 0
    rho = tool_radius - depth  # cone radius: smaller reaches deeper into the worm
    zeta = -space_half * c + (rho - tool_radius) * t  # lower face, the cone narrows inward

    def point_normal(psi):
        e_rho = np.cos(psi)[:, None] * (-ex) + np.sin(psi)[:, None] * b
        pt = centre + rho[:, None] * e_rho + zeta[:, None] * k
        n = -t * e_rho + k  # gradient of zeta - zeta(rho) (sign irrelevant)
        return pt, n

    def f(psi):
        pt, n = point_normal(np.full(rho.shape, psi) if np.ndim(psi) == 0 else psi)
        v = np.stack([-pt[:, 1], pt[:, 0], np.full(len(pt), p)], axis=1)
        return np.einsum("ij,ij->i", n, v)

    f0, f90, f180 = f(0.0), f(np.pi / 2.0), f(np.pi)
    a_, d_ = (f0 - f180) / 2.0, (f0 + f180) / 2.0
    b_ = f90 - d_
    amp = np.hypot(a_, b_)
    base = np.arctan2(b_, a_)
    spread = np.arccos(np.clip(-d_ / amp, -1.0, 1.0))
    roots = np.stack([base + spread, base - spread])
    roots = (roots + np.pi) % (2.0 * np.pi) - np.pi
    psi = roots[np.argmin(np.abs(roots), axis=0), np.arange(len(rho))]
    pt, _ = point_normal(psi)
    r = np.hypot(pt[:, 0], pt[:, 1])
    theta = np.arctan2(pt[:, 1], pt[:, 0])
    h = pt[:, 2] - p * theta
    # keep the branch through the reference cylinder on which the radius grows with the depth:
    # on a steep lead the contact folds back near the root (the cone's face stops generating)
    ok = np.abs(d_) <= amp
    i0 = int(np.argmin(np.abs(depth)))
    lo = i0
    while lo > 0 and ok[lo - 1] and r[lo - 1] < r[lo]:
        lo -= 1
    hi = i0
    while hi < len(r) - 1 and ok[hi + 1] and r[hi + 1] > r[hi]:
        hi += 1
    r, h = r[lo : hi + 1], h[lo : hi + 1]
    # the wheel's reference point was placed at r_m by construction only to first order:
    # shift the section axially so that it passes (r_m, half) exactly
    h = h - (np.interp(rm, r, h) - half)
    return r, h
