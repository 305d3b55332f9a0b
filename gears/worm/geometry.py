"""Layer 3, worm formulas: the geometry, efficiency and self-locking of cylindrical worm pairs
(shaft angle 90 degrees) as vectorised functions, DIN 3975-1 / ISO/TR 10828 symbols.

Symbols: ``z_1`` starts of the worm, ``z_2`` teeth of the wheel, ``m = m_x`` the axial module
of the worm (= the transverse module of the wheel), ``q = d_m1 / m`` the diameter quotient,
``gamma`` the lead angle at the reference (mean) cylinder, ``x_2`` the wheel's profile shift
coefficient, ``h_a*`` and ``c*`` the addendum and bottom clearance coefficients (1 and 0.2,
DIN 3975). The textbooks' worm (Ozols §21-12 and (14.15)-(14.18); the lecture course §8.15)
writes ``q`` and ``gamma`` the same way.

* worm: ``tan gamma = z_1 / q`` (DIN 3975; lecture course §8.15), ``d_m1 = q m``,
  ``m_n = m cos gamma``, axial pitch ``p_x = pi m``, lead ``p_z = z_1 p_x``,
  ``d_a1 = d_m1 + 2 h_a* m``, ``d_f1 = d_m1 - 2 (h_a* + c*) m``;
* pressure angles: the flank form fixes the section its profile angle ``alpha_0`` is given in
  (DIN 3975): the axial section for ZA (``alpha_x = alpha_0``), the normal section for ZN, ZI
  and ZK (``alpha_n = alpha_0``); ``tan alpha_x = tan alpha_n / cos gamma``;
* involute helicoid (ZI): base lead angle ``cos gamma_b = cos gamma cos alpha_n``, base
  diameter ``d_b1 = d_m1 tan gamma / tan gamma_b``;
* wheel: ``d_2 = z_2 m``, throat (tip) diameter ``d_a2 = d_2 + 2 m (h_a* + x_2)``, root
  ``d_f2 = d_2 - 2 m (h_a* + c* - x_2)``, outside diameter ``d_e2 = d_a2 + 6 m / (z_1 + 2)``
  (GOST 19650's upper limit), throat radius ``r_k = a - d_a2 / 2``;
* centre distance ``a = (d_m1 + d_2) / 2 + x_2 m``, ratio ``i = z_2 / z_1`` (Ozols (21.45));
* mid-plane mesh: the worm's axial section is a rack of pressure angle ``alpha_x`` rolling on
  the wheel's reference circle. Contact ratio ``eps = [sqrt(r_a2^2 - r_b2^2) - r_2 sin alpha_x
  + min((h_a* - x_2) m / sin alpha_x, r_2 sin alpha_x)] / (pi m cos alpha_x)`` with
  ``r_b2 = r_2 cos alpha_x``; the wheel is undercut by the worm's tip when
  ``h_a* - x_2 > z_2 sin^2(alpha_x) / 2``; its tooth is pointed when the mid-plane tip
  thickness ``s_a2 = d_a2 (s_2 / d_2 + inv alpha_x - inv alpha_a2)``,
  ``s_2 = m (pi / 2 + 2 x_2 tan alpha_x)``, reaches zero.

Efficiency (Ozols (14.15)-(14.18); the tooth losses only, as ISO/TS 14521 separates them): with
``phi' = atan(mu / cos alpha_n)``, the worm driving ``eta = tan gamma / tan(gamma + phi')``, the
wheel driving ``eta' = tan(gamma - phi') / tan gamma``; the pair is self-locking (the wheel
cannot drive) when ``gamma <= phi'``. Both are :func:`gears.worm.crossed.crossed_efficiency` of
the helix angles ``90 - gamma`` and ``gamma``. The best lead angle is
``gamma = 45 - phi' / 2`` (Ozols (14.16)), ``eta_max = tan^2(45 - phi' / 2)`` (14.17).

Examples
--------
The lecture course's worm (z_1 = 2, q = 10, f' = 0.05, z_2 = 40):

>>> from gears.worm.crossed import reduced_friction_angle
>>> g = worm_geometry(2, 40, 5.0, 10.0)
>>> round(float(g.lead_angle), 6), float(g.ratio)
(11.309932, 20.0)
>>> round(float(worm_efficiency(g.lead_angle, reduced_friction_angle(0.05, 0.0))), 4)
0.792
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from gears.involute import inv
from gears.worm.crossed import crossed_efficiency, crossed_sliding_velocity

__all__ = [
    "DRIVERS",
    "FLANKS",
    "WormGeometry",
    "best_lead_angle",
    "self_locking",
    "sliding_velocity",
    "worm_efficiency",
    "worm_geometry",
]

#: The flank forms of DIN 3975 (ISO/TR 10828): straight in the axial section (ZA), straight in
#: the normal section (ZN), involute helicoid (ZI), ground by a cone (ZK).
FLANKS = ("ZA", "ZN", "ZI", "ZK")

#: Which member drives.
DRIVERS = ("worm", "wheel")


def _out(a):
    a = np.asarray(a)
    return a[()] if a.ndim == 0 else a


class WormGeometry(NamedTuple):
    """Arrays of :func:`worm_geometry` (mm, degrees)."""

    lead_angle: np.ndarray  # gamma at d_m1
    ratio: np.ndarray  # i = z_2 / z_1
    axial_module: np.ndarray  # m = m_x
    normal_module: np.ndarray  # m_n = m cos gamma
    axial_pitch: np.ndarray  # p_x = pi m
    lead: np.ndarray  # p_z = z_1 p_x
    axial_pressure_angle: np.ndarray  # alpha_x
    normal_pressure_angle: np.ndarray  # alpha_n
    worm_diameter: np.ndarray  # d_m1 = q m, the worm's reference (mean) diameter
    worm_tip_diameter: np.ndarray  # d_a1
    worm_root_diameter: np.ndarray  # d_f1
    base_lead_angle: np.ndarray  # gamma_b (of the involute helicoid, ZI)
    worm_base_diameter: np.ndarray  # d_b1 (ZI)
    wheel_diameter: np.ndarray  # d_2 = z_2 m
    wheel_tip_diameter: np.ndarray  # d_a2, at the throat (mid-plane)
    wheel_root_diameter: np.ndarray  # d_f2
    wheel_outside_diameter: np.ndarray  # d_e2
    throat_radius: np.ndarray  # r_k = a - d_a2 / 2
    center_distance: np.ndarray  # a
    contact_ratio: np.ndarray  # eps in the mid-plane
    wheel_thickness: np.ndarray  # s_2, mid-plane arc thickness at d_2
    wheel_tip_thickness: np.ndarray  # s_a2, mid-plane arc thickness at d_a2
    undercut_margin: np.ndarray  # z_2 sin^2(alpha_x) / 2 - (h_a* - x_2), modules


def worm_geometry(
    z1, z2, module, diameter_quotient, pressure_angle=20.0, flank="ZI", profile_shift=0.0,
    addendum=1.0, clearance=0.2,
) -> WormGeometry:  # fmt: skip
    """The DIN 3975 geometry of cylindrical worm pairs (module docstring); every argument but
    ``flank`` broadcasts.

    Parameters
    ----------
    z1, z2 : int or array
        Starts of the worm and teeth of the wheel.
    module : float or array
        Axial module ``m_x`` of the worm, mm.
    diameter_quotient : float or array
        ``q = d_m1 / m_x``.
    pressure_angle : float or array
        ``alpha_0``, degrees, in the section the flank form names (axial for ZA, normal for ZN,
        ZI, ZK).
    flank : {"ZA", "ZN", "ZI", "ZK"}
    profile_shift : float or array
        ``x_2`` of the wheel.
    addendum, clearance : float or array
        ``h_a*`` and ``c*`` in axial modules.

    No validation happens here (a sweep may hold impossible rows): :class:`gears.WormPair`
    refuses impossible input with a :class:`gears.GearError`.

    Examples
    --------
    >>> g = worm_geometry(1, 40, 4.0, 10.0, flank="ZA", profile_shift=0.5)
    >>> float(g.center_distance), float(g.wheel_tip_diameter), float(g.worm_root_diameter)
    (102.0, 172.0, 30.4)
    """
    z1, z2 = np.asarray(z1, float), np.asarray(z2, float)
    m, q = np.asarray(module, float), np.asarray(diameter_quotient, float)
    a0 = np.radians(np.asarray(pressure_angle, float))
    x2 = np.asarray(profile_shift, float)
    ha, c = np.asarray(addendum, float), np.asarray(clearance, float)
    gamma = np.arctan2(z1, q)
    if flank == "ZA":
        ax = a0 + 0.0 * gamma
        an = np.arctan(np.tan(a0) * np.cos(gamma))
    else:
        an = a0 + 0.0 * gamma
        ax = np.arctan(np.tan(a0) / np.cos(gamma))
    d1 = q * m
    gamma_b = np.arccos(np.cos(gamma) * np.cos(an))
    d2 = z2 * m
    a = (d1 + d2) / 2.0 + x2 * m
    da2 = d2 + 2.0 * m * (ha + x2)
    r2, ra2 = d2 / 2.0, da2 / 2.0
    rb2 = r2 * np.cos(ax)
    sin_x = np.sin(ax)
    rack_side = np.minimum((ha - x2) * m / sin_x, r2 * sin_x)
    tip_side = np.sqrt(np.maximum(ra2**2 - rb2**2, 0.0)) - r2 * sin_x
    eps = (tip_side + rack_side) / (np.pi * m * np.cos(ax))
    s2 = m * (np.pi / 2.0 + 2.0 * x2 * np.tan(ax))
    # impossible rows (a tip at or inside the axis) take the base circle: finite, flagged by the
    # view's validation
    ratio = np.where(ra2 > 0.0, np.clip(rb2 / np.where(ra2 > 0.0, ra2, 1.0), 0.0, 1.0), 1.0)
    alpha_a2 = np.arccos(ratio)
    sa2 = da2 * (s2 / d2 + inv(ax) - inv(alpha_a2))
    return WormGeometry(
        lead_angle=_out(np.degrees(gamma)),
        ratio=_out(z2 / z1),
        axial_module=_out(m + 0.0 * gamma),
        normal_module=_out(m * np.cos(gamma)),
        axial_pitch=_out(np.pi * m + 0.0 * gamma),
        lead=_out(z1 * np.pi * m),
        axial_pressure_angle=_out(np.degrees(ax)),
        normal_pressure_angle=_out(np.degrees(an)),
        worm_diameter=_out(d1),
        worm_tip_diameter=_out(d1 + 2.0 * ha * m),
        worm_root_diameter=_out(d1 - 2.0 * (ha + c) * m),
        base_lead_angle=_out(np.degrees(gamma_b)),
        worm_base_diameter=_out(d1 * np.tan(gamma) / np.tan(gamma_b)),
        wheel_diameter=_out(d2 + 0.0 * gamma),
        wheel_tip_diameter=_out(da2 + 0.0 * gamma),
        wheel_root_diameter=_out(d2 - 2.0 * m * (ha + c - x2) + 0.0 * gamma),
        wheel_outside_diameter=_out(da2 + 6.0 * m / (z1 + 2.0)),
        throat_radius=_out(a - ra2),
        center_distance=_out(a),
        contact_ratio=_out(eps),
        wheel_thickness=_out(s2),
        wheel_tip_thickness=_out(sa2),
        undercut_margin=_out(z2 * np.sin(ax) ** 2 / 2.0 - (ha - x2)),
    )


def worm_efficiency(lead_angle, friction_angle, driving="worm"):
    """Tooth efficiency of a worm pair: the worm driving ``tan gamma / tan(gamma + phi')``
    (Ozols (14.15)), the wheel driving ``tan(gamma - phi') / tan gamma`` (Ozols (14.18)); a
    value ``<= 0`` means the pair locks in that direction. ``friction_angle`` is ``phi'`` in
    degrees (:func:`reduced_friction_angle`). Computed as the crossed-helical mesh of the
    helix angles ``90 - gamma`` (worm) and ``gamma`` (wheel),
    :func:`gears.worm.crossed.crossed_efficiency`.

    >>> round(float(worm_efficiency(11.309932, 2.862405, "wheel")), 4)
    0.7426
    """
    g = np.asarray(lead_angle, float)
    if driving == "worm":
        return crossed_efficiency(90.0 - g, g, friction_angle)
    if driving == "wheel":
        return crossed_efficiency(g, 90.0 - g, friction_angle)
    raise ValueError(f"driving = {driving!r}; valid are 'worm', 'wheel'")


def self_locking(lead_angle, friction_angle):
    """True where the wheel cannot drive the worm: ``gamma <= phi'`` (Ozols (14.18)), i.e. the
    efficiency with the wheel driving is ``<= 0``.

    >>> bool(self_locking(3.0, 5.0)), bool(self_locking(11.3, 2.86))
    (True, False)
    """
    return _out(np.asarray(worm_efficiency(lead_angle, friction_angle, "wheel")) <= 0.0)


def best_lead_angle(friction_angle):
    """The lead angle of the best efficiency with the worm driving, ``45 - phi' / 2`` degrees
    (Ozols (14.16); the efficiency there is ``tan^2(45 - phi' / 2)``, (14.17)).

    >>> round(float(best_lead_angle(5.710593)), 4)     # Ozols §14-3: f = 0.1
    42.1447
    """
    return _out(45.0 - np.asarray(friction_angle, float) / 2.0)


def sliding_velocity(worm_diameter, lead_angle, worm_speed):
    """Sliding speed at the pitch point, m/s: ``v_g = pi d_m1 n_1 / (60000 cos gamma)`` for
    ``d_m1`` in mm and the worm's speed ``n_1`` in rpm (DIN 3975; the crossed-helical sliding of
    :func:`gears.worm.crossed.crossed_sliding_velocity`).

    >>> round(float(sliding_velocity(50.0, 11.309932, 1500.0)), 4)
    4.0048
    """
    g = np.asarray(lead_angle, float)
    v1 = np.pi * np.asarray(worm_diameter, float) * np.asarray(worm_speed, float) / 60000.0
    return crossed_sliding_velocity(v1, 90.0 - g, g)
