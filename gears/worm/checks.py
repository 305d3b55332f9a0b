"""Layer 5, worm checks: every finding of ``WormPair.check()`` as a vectorised signed margin
(positive = satisfied), over arrays of worm pairs.

* ``wheel_undercut`` (axial modules): the worm's tip line, a rack in the mid-plane, stays
  outside the wheel's interference point, ``z_2 sin^2(alpha_x) / 2 - (h_a* - x_2)`` (DIN 3975:
  ``z_2 >= 2 (h_a* - x_2) / sin^2 alpha_x``);
* ``wheel_pointed_tip`` (mm): the wheel's mid-plane tip thickness ``s_a2`` less the required land
  (``min_tip_land`` axial modules);
* ``worm_tip_land`` (mm): the worm's normal thread thickness at its tip cylinder,
  ``2 h(r_a1) cos gamma_a1`` (``tan gamma_a1 = p / r_a1``, ``h`` the flank's axial section,
  :mod:`gears.worm.flank`), less the same land;
* ``contact_ratio`` (mid-plane): ``eps - min_contact_ratio``;
* ``flank_above_base`` (ZI only, mm): the lowest point of the worm the wheel's tip reaches in
  the mid-plane, the throat radius ``r_k = a - d_a2 / 2``, lies on the involute, outside the
  base cylinder: ``r_k - r_b1``;
* ``face_width`` (mm): the wheel's face width within the usual wrap angle of the throat,
  ``2 asin(b_2 / d_a1) <= 100`` degrees, i.e. ``d_a1 sin 50 deg - b_2``;
* ``worm_length`` (mm): the threaded length covers the chord of the wheel's outside circle at
  the worm's tip cylinder (the mid-plane region the wheel's teeth sweep),
  ``b_1 - 2 sqrt((d_e2 / 2)^2 - (a - d_a1 / 2)^2)``.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from gears.worm.flank import axial_half_thickness
from gears.worm.geometry import worm_geometry

__all__ = ["MAX_WRAP_ANGLE", "WormMargins", "min_worm_length", "worm_margins"]

#: The usual largest wrap angle of the wheel's throat around the worm, degrees.
MAX_WRAP_ANGLE = 100.0


class WormMargins(NamedTuple):
    """Arrays of :func:`worm_margins` (units in the module docstring)."""

    wheel_undercut: np.ndarray
    wheel_pointed_tip: np.ndarray
    worm_tip_land: np.ndarray
    contact_ratio: np.ndarray
    flank_above_base: np.ndarray  # ZI only; +inf-free: r_k - r_b1 for every flank
    face_width: np.ndarray
    worm_length: np.ndarray


def min_worm_length(z1, z2, module, diameter_quotient, profile_shift=0.0, addendum=1.0):
    """The chord of the wheel's outside circle at the worm's tip cylinder, mm (module
    docstring): the shortest threaded length the wheel's teeth need."""
    g = worm_geometry(z1, z2, module, diameter_quotient, profile_shift=profile_shift,
                      addendum=addendum)  # fmt: skip
    re2 = np.asarray(g.wheel_outside_diameter) / 2.0
    off = np.asarray(g.center_distance) - np.asarray(g.worm_tip_diameter) / 2.0
    out = 2.0 * np.sqrt(np.maximum(re2**2 - off**2, 0.0))
    return out[()] if out.ndim == 0 else out


def worm_margins(
    z1, z2, module, diameter_quotient, pressure_angle=20.0, flank="ZI", profile_shift=0.0,
    face_width=None, worm_length=None, addendum=1.0, clearance=0.2, tool_radius=None,
    min_contact_ratio=1.1, min_tip_land=0.2,
) -> WormMargins:  # fmt: skip
    """Every margin of the module docstring for arrays of worm pairs (every argument but
    ``flank`` broadcasts). ``face_width`` defaults to the wrap-angle limit and ``worm_length``
    to :func:`min_worm_length` plus one axial pitch (both margins then positive)."""
    g = worm_geometry(z1, z2, module, diameter_quotient, pressure_angle, flank, profile_shift,
                      addendum, clearance)  # fmt: skip
    m = np.asarray(module, float)
    land = min_tip_land * m
    ra1 = np.asarray(g.worm_tip_diameter) / 2.0
    p = np.asarray(g.lead) / (2.0 * np.pi)
    h_tip = axial_half_thickness(flank, ra1, z1, module, diameter_quotient, pressure_angle,
                                 tool_radius=tool_radius)  # fmt: skip
    tip_land = 2.0 * np.asarray(h_tip) * np.cos(np.arctan(p / ra1))
    da1 = np.asarray(g.worm_tip_diameter)
    b2_max = da1 * np.sin(np.radians(MAX_WRAP_ANGLE / 2.0))
    b2 = b2_max if face_width is None else np.asarray(face_width, float)
    need = min_worm_length(z1, z2, module, diameter_quotient, profile_shift, addendum)
    b1 = need + np.asarray(g.axial_pitch) if worm_length is None else worm_length
    shape = np.broadcast(*(np.asarray(v) for v in g), h_tip, b2, np.asarray(b1)).shape

    def full(v):
        out = np.broadcast_to(np.asarray(v, float), shape).copy()
        return out[()] if out.ndim == 0 else out

    return WormMargins(
        wheel_undercut=full(g.undercut_margin),
        wheel_pointed_tip=full(np.asarray(g.wheel_tip_thickness) - land),
        worm_tip_land=full(tip_land - land),
        contact_ratio=full(np.asarray(g.contact_ratio) - min_contact_ratio),
        flank_above_base=full(np.asarray(g.throat_radius) - np.asarray(g.worm_base_diameter) / 2),
        face_width=full(b2_max - b2),
        worm_length=full(np.asarray(b1, float) - need),
    )
