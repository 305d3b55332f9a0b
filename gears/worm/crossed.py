"""Layer 2, crossed axes: the hyperboloid axodes of two shafts on crossed axes and the
crossed-helical pair, as vectorised formulas (degrees, mm; every argument broadcasts).

**Axodes** (Joldasbekov, Theory of Mechanisms, §6-2, (6.1)-(6.10)). Two bodies turn at
``omega_1`` and ``omega_2`` about crossed axes whose common perpendicular has the length ``l``
(the centre distance); the crossing angle ``Sigma`` is the angle between ``omega_1`` and
``-omega_2``, so ``Sigma = 0`` is an external pair on parallel axes. Their relative motion is a
screw motion about the instantaneous screw axis, which crosses the common perpendicular at the
distances ``r_1`` and ``r_2`` (the throat radii of the two one-sheet hyperboloids of revolution,
the axodes):

* (6.1) ``omega_12 = sqrt(omega_1^2 + omega_2^2 + 2 omega_1 omega_2 cos Sigma)``;
* (6.3) ``tan phi_1 = sin Sigma / (i + cos Sigma)``, ``phi_2 = Sigma - phi_1`` with
  ``i = omega_1 / omega_2`` (``phi_k`` the angle of the screw axis to axis ``k``);
* (6.6) the sliding speed along the screw axis ``v_a = omega_1 omega_2 l sin Sigma / omega_12``;
* (6.8)/(6.9) ``r_2 = l omega_1 cos phi_1 / omega_12``, ``r_1 = l omega_2 cos phi_2 /
  omega_12``, ``r_1 + r_2 = l`` and (6.10) ``r_1 / r_2 = tan phi_1 / tan phi_2``.

``Sigma = 0`` gives the pitch cylinders ``r_1 / r_2 = omega_2 / omega_1``; ``l = 0`` gives the
bevel pitch cones, ``phi_k = delta_k`` (:func:`gears.bevel.cone.pitch_angles`).

**Crossed-helical pair** (Ozols, Theory of Mechanisms, §21-11, (21.41)-(21.44); ISO 21771's
helical gear on each shaft). Two helical gears of the same normal module ``m_n`` and normal
pressure angle, helix angles ``beta_1``, ``beta_2`` (signed: positive right hand), on shafts at
``Sigma = beta_1 + beta_2`` (same hand adds; ``beta_2 = -beta_1`` is the parallel helical pair):
reference diameters ``d_k = z_k m_n / cos beta_k``, centre distance ``a = (d_1 + d_2) / 2``,
ratio ``i = z_2 / z_1 = d_2 cos beta_2 / (d_1 cos beta_1)`` (21.44). At the pitch point the
teeth slide along their common tangent at ``v_g = v_1 sin Sigma / cos beta_2``
(``v_1 = omega_1 d_1 / 2``). With the friction coefficient ``mu`` on flanks of normal pressure
angle ``alpha_n`` the reduced friction angle is ``phi' = atan(mu / cos alpha_n)`` (Ozols (12.28),
the thread of flank angle ``alpha_n``), and the efficiency of the lengthwise sliding, gear 1
driving, is (a force balance in the common tangent plane, derived in the docstring of
:func:`crossed_efficiency`)::

    eta_12 = cos beta_1 cos(beta_2 + phi') / (cos beta_2 cos(beta_1 - phi'))

which for a worm (``beta_1 = 90 - gamma``, ``beta_2 = gamma``) is Ozols (14.15),
``tan gamma / tan(gamma + phi')``, and with gear 2 driving Ozols (14.18),
``tan(gamma - phi') / tan gamma``. A value at or below zero means the drive locks (the driver
cannot turn the driven member whatever its torque).

Examples
--------
Joldasbekov's case (``omega_1 = 3``, ``omega_2 = 1``, ``l = 2``, crossed at right angles):

>>> ax = axodes(3.0, 90.0, 2.0, speed=3.0)
>>> [round(float(v), 6) for v in (ax.throat_radius1, ax.throat_radius2, ax.axial_sliding)]
[0.2, 1.8, 1.897367]
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

__all__ = [
    "Axodes",
    "CrossedHelical",
    "axodes",
    "crossed_efficiency",
    "crossed_helical",
    "crossed_sliding_velocity",
    "reduced_friction_angle",
]


def _out(a):
    a = np.asarray(a)
    return a[()] if a.ndim == 0 else a


class Axodes(NamedTuple):
    """Arrays of :func:`axodes` (degrees, mm, the speeds' unit)."""

    angle1: np.ndarray  # phi_1: screw axis to axis 1, deg
    angle2: np.ndarray  # phi_2: screw axis to axis 2 (reversed), deg
    throat_radius1: np.ndarray  # r_1: axis 1 to the screw axis, mm
    throat_radius2: np.ndarray  # r_2
    relative_speed: np.ndarray  # omega_12, the screw's angular speed
    axial_sliding: np.ndarray  # v_a along the screw axis, mm per unit of time


def axodes(ratio, shaft_angle, center_distance, speed=1.0) -> Axodes:
    """The instantaneous screw axis and the hyperboloid axodes of two shafts on crossed axes
    (Joldasbekov (6.1)-(6.10); module docstring).

    Parameters
    ----------
    ratio : float or array
        ``i = omega_1 / omega_2 > 0``.
    shaft_angle : float or array
        ``Sigma`` in degrees, ``0 <= Sigma < 180``: the angle between ``omega_1`` and
        ``-omega_2`` (0: external pair on parallel axes, 90: crossed at right angles).
    center_distance : float or array
        ``l >= 0``, the common perpendicular of the axes, mm (0: intersecting axes).
    speed : float or array
        ``omega_1`` (any unit; ``omega_2 = omega_1 / i``).

    No validation happens here (a sweep may hold impossible rows); the throat radii are
    finite for ``i > 0`` and ``0 <= Sigma < 180``.

    Examples
    --------
    >>> ax = axodes(3.0, 0.0, 2.0)       # parallel axes: pitch cylinders r_1 = l / (1 + i)
    >>> [round(float(v), 6) for v in (ax.throat_radius1, ax.throat_radius2, ax.axial_sliding)]
    [0.5, 1.5, 0.0]
    """
    i = np.asarray(ratio, float)
    s = np.radians(np.asarray(shaft_angle, float))
    l_ = np.asarray(center_distance, float)
    w1 = np.asarray(speed, float)
    w2 = w1 / i
    w12 = np.sqrt(w1**2 + w2**2 + 2.0 * w1 * w2 * np.cos(s))  # (6.1)
    phi1 = np.arctan2(np.sin(s), i + np.cos(s))  # (6.3)
    phi2 = s - phi1
    r2 = l_ * w1 * np.cos(phi1) / w12  # (6.8)
    r1 = l_ * w2 * np.cos(phi2) / w12  # (6.9)
    va = w1 * w2 * l_ * np.sin(s) / w12  # (6.6)
    return Axodes(
        _out(np.degrees(phi1)), _out(np.degrees(phi2)), _out(r1), _out(r2), _out(w12), _out(va)
    )


def reduced_friction_angle(friction, pressure_angle=20.0):
    """``phi' = atan(mu / cos alpha_n)`` in degrees: the friction angle of a flank inclined at
    the normal pressure angle ``alpha_n`` (Ozols (12.28); ISO/TS 14521's
    ``tan rho' = mu / cos alpha_n``).

    >>> round(float(reduced_friction_angle(0.05, 0.0)), 6)    # f' = 0.05 directly
    2.862405
    """
    a = np.radians(np.asarray(pressure_angle, float))
    return _out(np.degrees(np.arctan(np.asarray(friction, float) / np.cos(a))))


def crossed_efficiency(helix_angle1, helix_angle2, friction_angle):
    """Efficiency of the lengthwise sliding of a crossed-helical mesh, gear 1 driving (swap the
    helix angles for gear 2 driving); ``friction_angle`` is ``phi'`` in degrees
    (:func:`reduced_friction_angle`).

    Derivation (the screw of Ozols (14.15) generalised to two helical gears): in the
    common tangent plane at the pitch point let ``t`` run along the teeth and ``n`` across them;
    the peripheral directions of the two gears make the angles ``beta_1`` and ``-beta_2`` with
    ``n``. Rolling makes the ``n`` components equal, ``v_1 cos beta_1 = v_2 cos beta_2``; the
    teeth slide along ``t`` at ``v_1 sin Sigma / cos beta_2``. The tooth force on gear 2 is
    ``N n + s mu' N t`` (``s = sign Sigma``, friction drags the driven flank along), so
    ``eta = v_2 (cos beta_2 - s mu' sin beta_2) / (v_1 (cos beta_1 + s mu' sin beta_1))``,
    which with ``mu' = tan phi'`` is the formula of the module docstring.

    A value ``<= 0`` means the mesh locks in this direction. Where even the driver's own push
    lies inside the friction cone (``cos(beta_1 - s phi') <= 0``, helices of opposite hand
    steeper than ``90 - phi'`` apart) the result is -1: locked.

    >>> round(float(crossed_efficiency(90 - 11.309932, 11.309932, 2.862405)), 4)  # a worm
    0.792
    >>> float(crossed_efficiency(20.0, -20.0, 5.0))     # parallel helical: no lengthwise sliding
    1.0
    """
    b1 = np.radians(np.asarray(helix_angle1, float))
    b2 = np.radians(np.asarray(helix_angle2, float))
    phi = np.radians(np.asarray(friction_angle, float)) * np.sign(b1 + b2)
    num = np.cos(b1) * np.cos(b2 + phi)
    den = np.cos(b2) * np.cos(b1 - phi)
    ok = den > 1e-12 * np.maximum(np.abs(num), 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        eta = np.where(ok, num / np.where(ok, den, 1.0), -1.0)
    return _out(eta)


def crossed_sliding_velocity(pitch_velocity1, helix_angle1, helix_angle2):
    """Sliding speed along the teeth at the pitch point, ``v_g = v_1 sin Sigma / cos beta_2``
    (``Sigma = beta_1 + beta_2``; the unit of ``pitch_velocity1``, the peripheral speed of
    gear 1). For a worm (``beta_1 = 90 - gamma``, ``beta_2 = gamma``) it is
    ``v_1 / cos gamma``.

    >>> round(float(crossed_sliding_velocity(1.0, 45.0, 45.0)), 6)
    1.414214
    """
    b1 = np.radians(np.asarray(helix_angle1, float))
    b2 = np.radians(np.asarray(helix_angle2, float))
    return _out(np.asarray(pitch_velocity1, float) * np.abs(np.sin(b1 + b2)) / np.cos(b2))


class CrossedHelical(NamedTuple):
    """Arrays of :func:`crossed_helical` (mm, degrees)."""

    shaft_angle: np.ndarray  # Sigma = beta_1 + beta_2
    reference_diameter1: np.ndarray  # d_1 = z_1 m_n / cos beta_1
    reference_diameter2: np.ndarray
    center_distance: np.ndarray  # a = (d_1 + d_2) / 2
    ratio: np.ndarray  # i = z_2 / z_1
    transverse_module1: np.ndarray  # m_t1 = m_n / cos beta_1
    transverse_module2: np.ndarray


def crossed_helical(z1, z2, normal_module, helix_angle1, helix_angle2) -> CrossedHelical:
    """The geometry of crossed-helical pairs (Ozols (21.41)-(21.44); module docstring).

    Helix angles in degrees, signed (positive right hand), each ``|beta| < 90``; the two gears
    share the normal module (Ozols (21.42): equal normal pitches).

    Examples
    --------
    Ozols' case: ``Sigma = 90``, ``i = 2``, ``a = 100`` with ``tan beta_1 / tan beta_2 =
    r_1 / r_2 = 1/4``: ``beta_1 = 26.565``, ``beta_2 = 63.435``, ``r_1 = 20``, ``r_2 = 80``.

    >>> b1 = 26.56505117707799; mn = 40 * np.cos(np.radians(b1)) / 20
    >>> g = crossed_helical(20, 40, mn, b1, 90 - b1)
    >>> [round(float(v), 6) for v in (g.reference_diameter1, g.reference_diameter2, g.ratio)]
    [40.0, 160.0, 2.0]
    """
    z1, z2 = np.asarray(z1, float), np.asarray(z2, float)
    mn = np.asarray(normal_module, float)
    c1 = np.cos(np.radians(np.asarray(helix_angle1, float)))
    c2 = np.cos(np.radians(np.asarray(helix_angle2, float)))
    d1, d2 = z1 * mn / c1, z2 * mn / c2
    sigma = np.asarray(helix_angle1, float) + np.asarray(helix_angle2, float)
    return CrossedHelical(
        _out(sigma), _out(d1), _out(d2), _out((d1 + d2) / 2.0), _out(z2 / z1),
        _out(mn / c1), _out(mn / c2),
    )  # fmt: skip
