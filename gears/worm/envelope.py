"""Layer 2, worm envelopes: the wheel's tooth in any plane normal to its axis, in closed form, as
the envelope of the worm's thread (the conjugate surface of the worm's helicoid).

Frames (those of :mod:`gears.worm.solid`): the wheel's axis is +z through the origin, the
worm's axis runs along +x through ``(0, a, 0)``; the worm's own ``(X, Y, Z)`` (axis ``Z``) are
the scene's ``(y - a, z, x)``. A thread flank is the helicoid ``Z = +-h(r) + s p theta``
(``p = p_z / (2 pi)``, ``s`` +1 for a right hand, -1 for a left; ``h`` the axial half thickness
of :mod:`gears.worm.flank`).

**Every plane of the wheel is a rack mesh.** Turning the worm by ``phi_1`` maps its thread onto
itself moved along its axis by ``s p phi_1`` (a helicoid is invariant under its screw motion),
and a move along the worm's axis (+x) keeps each plane ``z = zeta`` of the wheel in place. So in
the plane ``zeta`` the worm's section is a *rack* of pitch ``p_x`` translating along x while the
wheel turns about z: rolling without slip on the pitch circle ``r_2 = d_2 / 2``
(``r_2 = p z_2 / z_1``), a move ``u`` of the rack turns the wheel by ``-u / r_2``. The rack's
flank in that plane is the helicoid's section, a curve in the worm's own coordinate ``X``
towards the wheel (negative on the wheel's side of the worm's axis):

    x = s p theta +- h(r),    y = a + X,    r = hypot(X, zeta),    theta = atan2(zeta, X)

(``theta`` taken continuous through ``pi``), and its tip the
straight line ``y = a - sqrt(r_t^2 - zeta^2)`` of the hob's tip cylinder ``r_t``.

**Contact** (the theorem of meshing, Willis; Litvin's ``n . v_12 = 0`` reduced to the plane): a
point ``P`` of the rack with normal ``n`` touches the wheel when its normal passes through the
pitch point ``(0, r_2)``: at the rack's move ``u = -P_x - lambda n_x``,
``lambda = (r_2 - P_y) / n_y``. The wheel's flank is then ``P + (u, 0)`` turned back by
``u / r_2`` (:func:`rack_conjugate`): one closed-form point for each point of the worm's flank,
no iteration. The rack's tip corner draws the root fillet, a trochoid (:func:`rolled`), and its
tip line the root circle ``a - sqrt(r_t^2 - zeta^2)`` (a torus about the worm's axis, as the
throat ``a - sqrt(r_k^2 - zeta^2)`` bounds the wheel's tips).

Examples
--------
A ZA worm's axial section is a straight rack: in the mid-plane the conjugate of its flank is the
involute of ``r_2 cos alpha_x`` (the point of the rack at the pitch line touches at the pitch
point itself):

>>> import numpy as np
>>> x, y, nx, ny = plane_rack(0.0, -20.0, 1.0, 1.5, -np.tan(np.radians(20)), 60.0, 0.0)
>>> px, py, u = rack_conjugate(x, y, nx, ny, 40.0)
>>> round(float(np.hypot(px, py)), 9), round(float(u), 9)
(40.0, -1.5)
"""

from __future__ import annotations

import numpy as np

__all__ = ["plane_rack", "rack_conjugate", "rolled"]


def plane_rack(zeta, depth, side, half, slope, center_distance, screw):
    """The worm's flank in the wheel's plane ``z = zeta`` (module docstring): the point
    ``(x, y)`` at ``depth``, the worm's own coordinate ``X = y - a`` (negative on the wheel's
    side of the worm's axis; the worm's radius is ``r = hypot(X, zeta)``, and past the axis's
    line, where ``|zeta| > r_f``, the same helicoid goes on over the worm's far side), and a
    normal ``(n_x, n_y)`` (not of unit length).

    ``side`` is +1 for the flank ``+h`` (facing +x), -1 for ``-h``; ``half`` and ``slope`` are
    ``h(r)`` and ``dh/dr`` at that radius; ``screw`` is ``s p`` (mm a radian, signed by the
    hand). Every argument broadcasts.
    """
    zeta, xw = np.asarray(zeta, float), np.asarray(depth, float)
    r2 = np.maximum(xw * xw + zeta * zeta, 1e-300)
    theta = np.arctan2(zeta, xw)
    theta = np.where(theta < 0.0, theta + 2.0 * np.pi, theta)  # pi on the wheel's side
    x = screw * theta + side * half
    y = center_distance + xw
    # the tangent d/dX (x, y) = (dx/dX, 1); the normal turns it
    dx = -screw * zeta / r2 + side * slope * xw / np.sqrt(r2)
    return x, y, np.ones_like(dx), -dx


def rolled(x, y, shift, pitch_radius):
    """A rack point ``(x, y)`` moved by ``shift`` along x, seen from the wheel turned by
    ``-shift / r_2`` (rolling on the pitch circle): ``(x', y')`` in the wheel's own frame."""
    ang = np.asarray(shift, float) / pitch_radius
    px = np.asarray(x, float) + shift
    c, s = np.cos(ang), np.sin(ang)
    return c * px - s * y, s * px + c * y


def rack_conjugate(x, y, nx, ny, pitch_radius):
    """The wheel's point conjugate to the rack point ``(x, y)`` of normal ``(n_x, n_y)``: its
    coordinates in the wheel's frame and the rack's move ``u`` at contact (module docstring).
    A normal parallel to the pitch line (``n_y = 0``) never passes through the pitch point: its
    point is sent far away (``lambda`` of 1e12), outside every wheel."""
    nx, ny = np.asarray(nx, float), np.asarray(ny, float)
    flat = np.abs(ny) < 1e-12 * np.maximum(np.abs(nx), 1e-300)
    lam = np.where(flat, 1e12, (pitch_radius - np.asarray(y, float)) / np.where(flat, 1.0, ny))
    u = -np.asarray(x, float) - lam * nx
    px, py = rolled(x, y, u, pitch_radius)
    return px, py, u
