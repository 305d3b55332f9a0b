"""Layer 2, tooth compliance by the potential-energy method, as vectorised functions.

One tooth is a cantilever of varying section on its centreline, from the root circle to the
point of contact; the load acts along the line of action, at ``alpha_1`` to the perpendicular of
the centreline. The strain energy of bending, shear and axial compression (Yang and Lin 1987;
Tian 2004; Chen and Shao 2011, where the root circle lies below the base circle the tooth
continues there with the base circle's thickness) gives the compliance of each, as the integral
over the centreline ``y`` of

    bending   12 [(y_K - y) cos alpha_1 - h_K sin alpha_1]^2 / (E L (2 h)^3)
    shear     1.2 cos^2 alpha_1 / (G L 2 h),  G = E / (2 (1 + nu))
    axial     sin^2 alpha_1 / (E L 2 h)

with ``h(y)`` the half chord of the tooth, and ``(y_K, h_K)`` the point of contact. The gear body
under the tooth adds the fillet-foundation compliance of Sainsot, Velex and Duverger (2004,
J. Mech. Des. 126, eq. 8), and the two flanks the Hertzian approach of a line contact, taken
constant with the load (Yang and Sun 1985: 4 (1 - nu^2) / (pi E L)).

A ring's (internal gear's) tooth is the same cantilever turned inside out: its root circle lies
outside, its flanks are concave involutes that spread apart toward the root (the half angle at
roll ``t`` is ``psi_0 + inv``, where an external tooth's is ``psi_0 - inv``), and the load meets
its centreline at ``alpha_1 = t + psi_0`` (an external tooth's ``t - psi_0``); the integrals
run from the point of contact out to the root circle, and the moment arm keeps its form with
the distance measured outward (the internal-gear potential-energy model of Chen and Shao 2013,
Mech. Mach. Theory 69; Liang, Zuo and Pandey 2014, Mech. Mach. Theory 76). Its foundation takes
Sainsot's fit with the same body ratio as an external gear's default (a thick rim): as the
tooth count grows, an internal and an external tooth both tend to the basic rack's tooth, which
a test checks.

Every function returns a compliance times ``E L`` (dimensionless): divide by the Young modulus
and the face width of a slice to get mm/N. The involute is parametrised by its roll angle
``t = tan alpha_y`` (radians), so a contact ``u`` mm along the line of action from the base
circle's tangent point has ``t = u / r_b``. The integrals are Gauss-Legendre sums over the roll
angle (``nodes`` points), exact to about 1e-10 relative at the default; a test checks them
against the closed-form integrands of Tian (2004) integrated by adaptive quadrature.

Examples
--------
>>> c = tooth_compliance(0.4, 30.0, 0.08, 28.0)   # roll 0.4 rad on a base circle of 30 mm
>>> sorted(c)
['axial', 'bending', 'foundation', 'shear']
>>> round(float(hertz_compliance(0.3)), 6)   # 4 (1 - 0.09) / pi
1.158648
"""

from __future__ import annotations

import numpy as np

__all__ = ["SAINSOT", "hertz_compliance", "mesh_compliance", "tooth_compliance"]

#: Sainsot, Velex and Duverger (2004), Table 1: X*(h_fi, theta_f) = A / theta_f^2 + B h_fi^2 +
#: C h_fi / theta_f + D / theta_f + E h_fi + F for X = L*, M*, P*, Q* (rows), where
#: h_fi = r_f / r_int (root over bore radius) and theta_f the half tooth angle at the root circle.
SAINSOT = np.array(
    [
        [-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045],
        [60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086],
        [-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236],
        [-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904],
    ]
)

_NODES: dict[int, tuple[np.ndarray, np.ndarray]] = {}


def _gauss(n: int) -> tuple[np.ndarray, np.ndarray]:
    if n not in _NODES:
        _NODES[n] = np.polynomial.legendre.leggauss(n)
    return _NODES[n]


def _involute_point(t, rb, alpha2):
    """``(y, h)``: the point of roll ``t`` on the flank, along and across the centreline."""
    r = rb * np.sqrt(1.0 + t * t)
    psi = alpha2 - (t - np.arctan(t))  # half the angle the tooth subtends at radius r
    return r * np.cos(psi), r * np.sin(psi)


def tooth_compliance(t, rb, alpha2, rf, bore_radius=None, poisson=0.3, nodes=24,
                     internal=False):  # fmt: skip
    """Compliance times ``E L`` of one tooth loaded at the roll angle ``t`` (radians):
    ``{"bending", "shear", "axial", "foundation"}`` (arrays over ``t``; the gear's values
    broadcast with it).

    Parameters
    ----------
    t : array_like
        Roll angle of the point of contact, ``tan`` of its pressure angle (radians).
    rb, alpha2, rf : float or array
        Base radius (mm), half the angle the tooth subtends on the base circle (s_b / d_b,
        radians; a ring's: s_t / d - inv alpha_t, which may be negative), root radius (mm).
    bore_radius : float, optional
        r_int of the gear body for the foundation (default: half the root radius; a ring's
        foundation takes the same body ratio).
    poisson : float
        Poisson's ratio nu.
    nodes : int
        Gauss-Legendre points over each part of the tooth.
    internal : bool
        A ring's tooth (see the module docstring).
    """
    t = np.asarray(t, float)
    rb, alpha2, rf = (np.asarray(v, float) for v in (rb, alpha2, rf))
    r_int = rf / 2.0 if bore_radius is None else np.asarray(bore_radius, float)
    if internal:
        return _ring_tooth(t, rb, alpha2, rf, r_int, poisson, nodes)
    x, w = _gauss(nodes)
    # the tooth starts at the root circle: on the involute when it lies above the base circle,
    # else at the base circle with a straight part of the base thickness below it
    t0 = np.sqrt(np.maximum((rf / rb) ** 2 - 1.0, 0.0))
    t = np.maximum(t, t0)
    yk, hk = _involute_point(t, rb, alpha2)
    a1 = t - alpha2
    cos1, sin1 = np.cos(a1), np.sin(a1)
    yb, hb = _involute_point(t0, rb, alpha2)
    below = rf < rb
    hf = hb  # the half chord where the tooth meets the root circle
    yf = np.where(below, np.sqrt(np.maximum(rf * rf - hb * hb, 0.0)), yb)

    def parts(y, h, dy):
        arm = (yk[..., None] - y) * cos1[..., None] - hk[..., None] * sin1[..., None]
        bend = np.sum(1.5 * arm * arm / h**3 * dy, axis=-1)
        inv_h = np.sum(dy / h, axis=-1)
        return bend, inv_h

    # involute part, over the roll angle
    half = (t - t0)[..., None] / 2.0
    tau = t0[..., None] + half * (x + 1.0) if t0.ndim else t0 + half * (x + 1.0)
    r = rb[..., None] * np.sqrt(1.0 + tau * tau) if rb.ndim else rb * np.sqrt(1.0 + tau * tau)
    a2 = alpha2[..., None] if alpha2.ndim else alpha2
    psi = a2 - (tau - np.arctan(tau))
    dr = r * tau / (1.0 + tau * tau)
    dy = (dr * np.cos(psi) + r * np.sin(psi) * tau * tau / (1.0 + tau * tau)) * (half * w)
    bend, inv_h = parts(r * np.cos(psi), r * np.sin(psi), dy)
    # straight part below the base circle (zero length when the root lies above it)
    length = (yb - yf)[..., None] / 2.0
    ys = (yf[..., None] if yf.ndim else yf) + length * (x + 1.0)
    hs = np.broadcast_to(hb[..., None] if hb.ndim else hb, ys.shape)
    b2, i2 = parts(ys, hs, length * w)
    bend, inv_h = bend + b2, inv_h + i2
    # fillet foundation, Sainsot et al. (2004) eq. 8
    found = _foundation(yk - hk * np.tan(a1) - yf, hf, rf, r_int, a1)
    return _parts(bend, inv_h, a1, found, poisson)


def _parts(bend, inv_h, a1, found, poisson):
    cos1, sin1 = np.cos(a1), np.sin(a1)
    return {
        "bending": bend,
        "shear": 1.2 * (1.0 + poisson) * cos1**2 * inv_h,
        "axial": 0.5 * sin1**2 * inv_h,
        "foundation": found,
    }


def _foundation(uf, hf, rf, r_int, a1):
    """Sainsot, Velex and Duverger (2004) eq. 8 times ``E L``: ``uf`` the distance along the
    centreline from where the load line crosses it to the root section, ``hf`` the half chord
    there."""
    sf = 2.0 * hf
    theta_f = np.arcsin(np.clip(hf / rf, -1.0, 1.0))
    hfi = rf / r_int
    coef = [
        row[0] / theta_f**2 + row[1] * hfi**2 + row[2] * hfi / theta_f + row[3] / theta_f
        + row[4] * hfi + row[5]
        for row in SAINSOT
    ]  # fmt: skip
    ratio = uf / sf
    return np.cos(a1) ** 2 * (
        coef[0] * ratio**2 + coef[1] * ratio + coef[2] * (1 + coef[3] * np.tan(a1) ** 2)
    )


def _ring_tooth(t, rb, psi0, rf, r_int, poisson, nodes):
    """A ring's tooth loaded at roll ``t``: the involute from the point of contact out to the
    root circle (where the fillet starts the tooth is taken as involute, as an external tooth
    whose root lies above its base circle), half angle ``psi0 + t - atan t``."""
    x, w = _gauss(nodes)
    tf = np.sqrt(np.maximum((rf / rb) ** 2 - 1.0, 0.0))
    t = np.minimum(t, tf)

    def point(tau):
        r = rb * np.sqrt(1.0 + tau * tau)
        psi = psi0 + tau - np.arctan(tau)
        return r, psi

    rk, psik = point(t)
    xk, hk = rk * np.cos(psik), rk * np.sin(psik)
    a1 = t + psi0
    half = (tf - t)[..., None] / 2.0
    tau = t[..., None] + half * (x + 1.0)
    rb_, p0 = (np.asarray(v)[..., None] if np.ndim(v) else v for v in (rb, psi0))
    r = rb_ * np.sqrt(1.0 + tau * tau)
    psi = p0 + tau - np.arctan(tau)
    slope = tau / (1.0 + tau * tau)
    dx = r * (slope * np.cos(psi) - np.sin(psi) * tau * slope) * (half * w)
    xs, hs = r * np.cos(psi), r * np.sin(psi)
    arm = (xs - xk[..., None]) * np.cos(a1)[..., None] - hk[..., None] * np.sin(a1)[..., None]
    bend = np.sum(1.5 * arm * arm / hs**3 * dx, axis=-1)
    inv_h = np.sum(dx / hs, axis=-1)
    r_f, psi_f = point(tf)
    xf, hf = r_f * np.cos(psi_f), r_f * np.sin(psi_f)
    found = _foundation(xf - xk - hk * np.tan(a1), hf, rf, r_int, a1)
    return _parts(bend, inv_h, a1, found, poisson)


def hertz_compliance(poisson=0.3):
    """The Hertzian approach of two steel flanks in line contact, times ``E L``: 4 (1 - nu^2)
    / pi (Yang and Sun 1985), the same at every load."""
    return 4.0 * (1.0 - np.asarray(poisson, float) ** 2) / np.pi


def mesh_compliance(t1, t2, gear1, gear2, poisson=0.3, nodes=24, internal=False):
    """Compliance times ``E L`` of one tooth pair touching at the roll angles ``t1`` (gear 1)
    and ``t2`` (gear 2): both teeth (bending, shear, axial, foundation) and the Hertzian
    approach, in series. ``gear1`` and ``gear2`` are ``(rb, alpha2, rf, bore_radius)``;
    ``internal``: gear 2 is a ring."""
    c1 = tooth_compliance(t1, *gear1, poisson=poisson, nodes=nodes)
    c2 = tooth_compliance(t2, *gear2, poisson=poisson, nodes=nodes, internal=internal)
    return sum(c1.values()) + sum(c2.values()) + hertz_compliance(poisson)
