"""Layer 3, bevel formulas: the geometry of straight bevel gear pairs as vectorised functions.

ISO 23509 / DIN 3971 for straight bevel gears (the symbols of ISO 23509; the textbooks' bevel
section is Ozols §21-10, (21.34)-(21.36)). All angles in degrees, lengths in mm; every function
broadcasts over numpy arrays, so a sweep over 10^6 pairs calls the same code as one
:class:`gears.BevelPair`. Per-gear results are stacked on a leading axis of length 2 (pinion,
wheel).

* **Pitch cones** (Ozols (21.34); Joldasbekov, axes crossing at l = 0): ``tan delta_1 = sin Sigma /
  (z_2/z_1 + cos Sigma)``, ``delta_2 = Sigma - delta_1``, for any shaft angle
  ``0 < Sigma < 180``.
* **Cone distances**: outer ``R_e = m_et z / (2 sin delta)`` (``module`` is the outer transverse
  module m_et, the module of the outer pitch diameter ``d_e = m_et z``), mean
  ``R_m = R_e - b/2``, inner ``R_i = R_e - b``; mean module ``m_m = m_et R_m / R_e``.
* **Heights at the mean cone** (ISO 23509): ``h_am = m_m (k_hap + x_hm)``,
  ``h_fm = m_m (k_hfp - x_hm)`` with ``x_hm2 = -x_hm1`` (the pitch cones stay the reference
  cones); dedendum angle ``theta_f = atan(h_fm / R_m)`` (the root line passes the pitch apex).
  Addendum angle: *tapered* clearance (standard depth, KHK Table 4.10: every cone meets the
  pitch apex) ``theta_a = atan(h_am / R_m)``; *constant* clearance (ISO 23509 and Gleason: the
  face cone of each gear parallel to the root cone of its mate) ``theta_a1 = theta_f2``,
  ``theta_a2 = theta_f1``. Outer heights ``h_ae = h_am + (b/2) tan theta_a``; face angle
  ``delta_a = delta + theta_a``, root angle ``delta_f = delta - theta_f``.
* **Blank dimensions** (KHK Tables 4.10/4.11): outside diameter ``d_ae = d_e + 2 h_ae cos delta``,
  pitch apex to crown ``X = R_e cos delta - h_ae sin delta``, axial face width
  ``X_b = b cos delta_a / cos theta_a``, inner outside diameter
  ``d_ai = d_ae - 2 b sin delta_a / cos theta_a``.
* **Tooth thickness** on the mean pitch cone (ISO 23509 mean normal circular thickness; straight
  teeth: normal = transverse): ``s_m = m_m (pi/2 + 2 x_hm tan alpha + x_sm)``, ``x_sm2 = -x_sm1``
  (the thickness modification moves thickness from one gear to the other).
* **Virtual (Tredgold) spur gears** at the mean cone (Ozols (21.35)/(21.36), ISO 10300):
  ``z_v = z / cos delta``, ``d_v = d_m / cos delta``, module ``m_m``; their contact ratio and
  checks stand for the bevel pair's. A wheel with ``delta = 90`` deg is a crown gear (its
  virtual gear a rack); ``delta > 90`` deg an internal bevel gear (a virtual ring). Whether a
  gear is a crown gear is decided once, by :func:`is_crown` (within :data:`CROWN_TOLERANCE`),
  and :func:`pitch_angles` returns such an angle as exactly 90 deg, so every check and solid
  agrees (``Sigma - delta_1`` of a crown wheel rounds to 89.99999999999999).

The Gleason straight-bevel proportions (KHK Table 4.11: working depth 2 m, whole depth
2.188 m, the wheel's addendum ``0.54 m + 0.46 m / (z_2 cos delta_1 / (z_1 cos delta_2))``, all at
the outer end, constant clearance) are expressed in these mean-cone coefficients by
:func:`gleason_coefficients`.

Examples
--------
KHK Table 4.10 (standard straight bevel gears, tapered clearance):

>>> g = bevel_geometry(20, 40, 3.0, 22.0, clearance="tapered")
>>> [round(float(v), 5) for v in g.pitch_angle], round(float(g.cone_distance), 5)
([26.56505, 63.43495], 67.08204)
>>> [round(float(v), 5) for v in g.dedendum_angle], [round(float(v), 5) for v in g.face_angle]
([3.1996, 3.1996], [29.12569, 65.99559])
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from gears.arguments import check_real, common_shape
from gears.errors import GearError

__all__ = [
    "CLEARANCES",
    "CROWN_TOLERANCE",
    "SHAFT_ANGLES",
    "BevelGeometry",
    "axial_section",
    "bevel_geometry",
    "check_shaft_angle",
    "cone_distance",
    "face_width_margins",
    "full_round_radius",
    "gleason_coefficients",
    "is_crown",
    "max_face_width",
    "pitch_angles",
    "virtual_teeth",
]

#: The two ways the tip cone may run (see the module docstring).
CLEARANCES = ("constant", "tapered")


def _out(a):
    a = np.asarray(a)
    return a[()] if a.ndim == 0 else a


#: A pitch angle within this many degrees of 90 is a crown gear's (:func:`is_crown`): far
#: below any shaft angle a drawing or a machine can hold (a wheel of 40 teeth 1e-9 deg from
#: 90 would have z_v = 2e12), far above the rounding of ``Sigma - delta_1`` (1e-14 deg).
CROWN_TOLERANCE = 1e-9


def is_crown(pitch_angle):
    """True where a pitch angle (degrees) is a crown gear's, ``|delta - 90| <= CROWN_TOLERANCE``:
    the one decision that the virtual gears, the checks and the solids share.

    >>> bool(is_crown(89.99999999999999)), bool(is_crown(89.9999))
    (True, False)
    """
    return _out(np.abs(np.asarray(pitch_angle, float) - 90.0) <= CROWN_TOLERANCE)


def pitch_angles(z1, z2, shaft_angle=90.0):
    """Pitch cone angles ``(delta_1, delta_2)`` in degrees (Ozols (21.34)).

    ``tan delta_1 = sin Sigma / (z_2/z_1 + cos Sigma)``, ``delta_2 = Sigma - delta_1``; arctan2
    keeps ``delta_1`` in (0, 180) for any ``0 < Sigma < 180``. A crown gear's angle
    (:func:`is_crown`) is returned as exactly 90.

    Examples
    --------
    >>> [round(float(d), 4) for d in pitch_angles(20, 60, 60.0)]   # Ozols (21.34): i = 3
    [13.8979, 46.1021]
    >>> float(pitch_angles(20, 40, 120.0)[1])   # a crown wheel: Sigma - delta_1 = 90
    90.0
    """
    s = np.radians(np.asarray(shaft_angle, float))
    z1, z2 = np.asarray(z1, float), np.asarray(z2, float)
    d1 = np.degrees(np.arctan2(np.sin(s), z2 / z1 + np.cos(s)))
    d2 = np.degrees(s) - d1
    return _out(np.where(is_crown(d1), 90.0, d1)), _out(np.where(is_crown(d2), 90.0, d2))


def cone_distance(z, module, pitch_angle):
    """Outer cone distance ``R_e = m_et z / (2 sin delta)`` in mm."""
    d = np.radians(np.asarray(pitch_angle, float))
    return _out(np.asarray(module, float) * np.asarray(z, float) / (2.0 * np.sin(d)))


def virtual_teeth(z, pitch_angle):
    """Virtual (Tredgold) tooth number ``z_v = z / cos delta`` (Ozols (21.36)); negative for an
    internal bevel gear (``delta > 90`` deg), infinite for a crown gear."""
    c = np.cos(np.radians(np.asarray(pitch_angle, float)))
    with np.errstate(divide="ignore"):
        return _out(np.asarray(z, float) / np.where(is_crown(pitch_angle), 0.0, c))


def full_round_radius(addendum, dedendum, pressure_angle=20.0):
    """Tip radius of the generating tool that rounds the whole bottom clearance,
    ``rho_a0 = (k_hfp - k_hap) / (1 - sin alpha)``, in modules (0.38 for ISO 53 A).

    >>> round(float(full_round_radius(1.0, 1.25)), 4)
    0.38
    """
    a = np.radians(np.asarray(pressure_angle, float))
    c = np.asarray(dedendum, float) - np.asarray(addendum, float)
    return _out(np.maximum(c, 0.0) / (1.0 - np.sin(a)))


class BevelGeometry(NamedTuple):
    """Arrays of :func:`bevel_geometry` (mm, degrees). Per-gear fields have a leading axis of
    length 2: ``[pinion, wheel]``."""

    pitch_angle: np.ndarray  # delta, deg
    cone_distance: np.ndarray  # R_e, outer
    mean_cone_distance: np.ndarray  # R_m
    mean_module: np.ndarray  # m_m
    reference_diameter: np.ndarray  # d_e = m_et z (outer pitch diameter)
    mean_diameter: np.ndarray  # d_m
    profile_shift: np.ndarray  # x_hm
    thickness_modification: np.ndarray  # x_sm
    mean_addendum: np.ndarray  # h_am
    mean_dedendum: np.ndarray  # h_fm
    addendum_angle: np.ndarray  # theta_a, deg
    dedendum_angle: np.ndarray  # theta_f, deg
    addendum: np.ndarray  # h_ae, outer
    dedendum: np.ndarray  # h_fe, outer
    inner_addendum: np.ndarray  # h_ai
    face_angle: np.ndarray  # delta_a, deg
    root_angle: np.ndarray  # delta_f, deg
    tip_diameter: np.ndarray  # d_ae, outer
    inner_tip_diameter: np.ndarray  # d_ai
    crown_to_apex: np.ndarray  # X, pitch apex to crown
    axial_face_width: np.ndarray  # X_b
    mean_thickness: np.ndarray  # s_m, arc on the mean pitch cone
    virtual_teeth: np.ndarray  # z_v = z / cos delta
    virtual_diameter: np.ndarray  # d_v = d_m / cos delta


def _check_clearance(clearance) -> str:
    if clearance not in CLEARANCES:
        raise GearError(f"clearance = {clearance!r}; valid are {', '.join(map(repr, CLEARANCES))}")
    return clearance


def bevel_geometry(
    z1, z2, module, face_width, shaft_angle=90.0, pressure_angle=20.0, profile_shift=0.0,
    thickness_modification=0.0, addendum=1.0, dedendum=1.25, clearance="constant",
) -> BevelGeometry:  # fmt: skip
    """The geometry of straight bevel pairs (every argument but ``clearance`` broadcasts).

    Parameters
    ----------
    z1, z2 : int or array
        Teeth of the pinion and the wheel.
    module : float or array
        Outer transverse module m_et, mm.
    face_width : float or array
        b, mm (along the pitch cone).
    shaft_angle : float or array
        Sigma, degrees, 0 < Sigma < 180.
    pressure_angle : float or array
        alpha, degrees (of the generating crown gear).
    profile_shift, thickness_modification : float or array
        x_hm1 and x_sm1 of the pinion; the wheel takes their negatives.
    addendum, dedendum : float or array
        k_hap and k_hfp, coefficients of the mean module.
    clearance : {"constant", "tapered"}
        How the face cones run (module docstring).

    Returns
    -------
    BevelGeometry
        No validation happens here (a sweep may hold impossible rows): a face width at or
        beyond the cone distance gives ``mean_module <= 0``; :class:`gears.BevelPair` refuses
        such input with a :class:`GearError`.

    Examples
    --------
    KHK Table 4.11 (Gleason straight bevel gears), through :func:`gleason_coefficients`:

    >>> k = gleason_coefficients(20, 40, 3.0, 22.0)
    >>> g = bevel_geometry(20, 40, 3.0, 22.0, addendum=k[0], dedendum=k[1], profile_shift=k[2])
    >>> [round(float(v), 3) for v in g.addendum], [round(float(v), 5) for v in g.face_angle]
    ([4.035, 1.965], [30.48699, 65.59398])
    """
    clearance = _check_clearance(clearance)
    m = np.asarray(module, float)
    b = np.asarray(face_width, float)
    alpha = np.radians(np.asarray(pressure_angle, float))
    x1 = np.asarray(profile_shift, float)
    xs1 = np.asarray(thickness_modification, float)
    za, zb = np.asarray(z1, float), np.asarray(z2, float)
    shape = common_shape({"z1": za.shape, "z2": zb.shape, "module": m.shape, "face_width": b.shape,
                          "pressure_angle": alpha.shape, "profile_shift": x1.shape,
                          "thickness_modification": xs1.shape,
                          "shaft_angle": np.shape(shaft_angle), "addendum": np.shape(addendum),
                          "dedendum": np.shape(dedendum)})  # fmt: skip

    def pair(a, c):  # (pinion, wheel) stacked on a leading axis, broadcast to every row
        return np.stack([np.broadcast_to(a, shape), np.broadcast_to(c, shape)])

    z = pair(za, zb)
    d1, d2 = pitch_angles(z[0], z[1], shaft_angle)
    delta = pair(d1, d2)
    dr = np.radians(delta)
    r_e = m * z[0] / (2.0 * np.sin(dr[0]))
    r_m = r_e - b / 2.0
    m_m = m * r_m / r_e
    x = pair(x1, -x1)
    xs = pair(xs1, -xs1)
    h_am = m_m * (np.asarray(addendum, float) + x)
    h_fm = m_m * (np.asarray(dedendum, float) - x)
    with np.errstate(divide="ignore", invalid="ignore"):
        theta_f = np.arctan(h_fm / r_m)
        theta_a = theta_f[::-1] if clearance == "constant" else np.arctan(h_am / r_m)
    h_ae = h_am + b / 2.0 * np.tan(theta_a)
    h_fe = h_fm + b / 2.0 * np.tan(theta_f)
    h_ai = h_am - b / 2.0 * np.tan(theta_a)
    delta_a = dr + theta_a
    d_e = m * z
    d_ae = d_e + 2.0 * h_ae * np.cos(dr)
    crown = r_e * np.cos(dr) - h_ae * np.sin(dr)
    axial = b * np.cos(delta_a) / np.cos(theta_a)
    d_ai = d_ae - 2.0 * b * np.sin(delta_a) / np.cos(theta_a)
    s_m = m_m * (np.pi / 2.0 + 2.0 * x * np.tan(alpha) + xs)
    d_m = m_m * z
    with np.errstate(divide="ignore"):
        c = np.where(is_crown(delta), 0.0, np.cos(dr))
        z_v = z / c
        d_v = d_m / c
    return BevelGeometry(*(_out(v) for v in (
        delta, r_e, r_m, m_m, d_e, d_m, x, xs, h_am, h_fm, np.degrees(theta_a),
        np.degrees(theta_f), h_ae, h_fe, h_ai, np.degrees(delta_a), np.degrees(dr - theta_f),
        d_ae, d_ai, crown, axial, s_m, z_v, d_v,
    )))  # fmt: skip


def gleason_coefficients(z1, z2, module, face_width, shaft_angle=90.0):
    """``(addendum, dedendum, profile_shift)``, the mean-cone coefficients (k_hap, k_hfp, x_hm1)
    of the Gleason straight-bevel proportions with constant clearance (KHK Table 4.11).

    At the outer end the wheel's addendum is ``h_a2 = 0.54 m + 0.46 m / (z_2 cos delta_1 /
    (z_1 cos delta_2))``, the pinion's ``h_a1 = 2 m - h_a2`` and the dedendum
    ``h_f = 2.188 m - h_a``; the root lines pass the pitch apex and each face cone is parallel to
    the mate's root cone. :func:`bevel_geometry` with these coefficients and
    ``clearance="constant"`` reproduces those outer heights exactly: with
    ``theta_f = atan(h_fe / R_e)``, ``h_am = h_ae - (b/2) tan theta_f(mate)``, so
    ``k_hap = (h_am1 + h_am2) / (2 m_m)``, ``x_hm1 = (h_am1 - h_am2) / (2 m_m)`` and
    ``k_hfp = h_fe1 / m + x_hm1``.

    >>> [round(float(v), 6) for v in gleason_coefficients(20, 40, 3.0, 22.0)]
    [0.963125, 1.188, 0.345]
    """
    d1, d2 = pitch_angles(z1, z2, shaft_angle)
    c1, c2 = np.cos(np.radians(d1)), np.cos(np.radians(d2))
    m = np.asarray(module, float)
    z1, z2 = np.asarray(z1, float), np.asarray(z2, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        ha2 = 0.54 * m + 0.46 * m / (z2 * c1 / (z1 * c2))
    ha1 = 2.0 * m - ha2
    hf1, hf2 = 2.188 * m - ha1, 2.188 * m - ha2
    r_e = m * z1 / (2.0 * np.sin(np.radians(d1)))
    b = np.asarray(face_width, float)
    r_m = r_e - b / 2.0
    m_m = m * r_m / r_e
    ham1 = ha1 - b / 2.0 * hf2 / r_e
    ham2 = ha2 - b / 2.0 * hf1 / r_e
    k_hap = (ham1 + ham2) / (2.0 * m_m)
    x = (ham1 - ham2) / (2.0 * m_m)
    return _out(k_hap), _out(hf1 / m + x), _out(x)


def face_width_margins(face_width, cone_distance, module):
    """Margins of the face-width rules of thumb (KHK, ISO 23509): ``(R_e/3 - b, 10 m - b)`` mm.

    >>> [round(float(v), 4) for v in face_width_margins(22.0, 67.08204, 3.0)]
    [0.3607, 8.0]
    """
    b = np.asarray(face_width, float)
    return _out(np.asarray(cone_distance, float) / 3.0 - b), _out(10.0 * np.asarray(module) - b)


#: The shaft angles a pair may have, degrees: within 0.01 deg of 0 or 180 the pitch cones
#: degenerate (their cone distance grows as 1 / sin delta and the formulas divide by nothing).
SHAFT_ANGLES = (0.01, 179.99)


def check_shaft_angle(shaft_angle) -> float:
    """``shaft_angle`` in degrees as a float, or a :class:`GearError` naming the valid range
    (:data:`SHAFT_ANGLES`)."""
    lo, hi = SHAFT_ANGLES
    return check_real("shaft_angle", shaft_angle, lo, hi, low_open=False, high_open=False)


def max_face_width(z1, z2, module, shaft_angle=90.0) -> float:
    """The face width at which the inner end reaches the pitch apex: ``R_e`` (mm); a real
    pair needs ``b < R_e`` (and ``b <= R_e / 3`` by the rule of thumb)."""
    d1, _ = pitch_angles(z1, z2, shaft_angle)
    return float(cone_distance(z1, module, d1))


def axial_section(pitch_angle, face_angle, root_angle, cone_distance, face_width, addendum,
                  dedendum):  # fmt: skip
    """The tooth zone of a bevel gear in its axial section (arrays broadcast): the corners
    ``(rho, z)`` (mm, z along the axis from the pitch apex, rho from the axis) of the
    quadrilateral between the face cone, the back cone, the root cone and the front cone, in the
    order outer tip, outer root, inner root, inner tip: shape ``(..., 4, 2)``.

    The outer pitch point lies at ``R_e (sin delta, cos delta)``; the outer tip and root lie
    ``h_ae`` and ``h_fe`` from it along the back-cone generator ``(cos delta, -sin delta)``
    (so the tip is at ``(d_ae / 2, X)``, KHK Table 4.10); the face and root lines run from them
    at ``delta_a`` and ``delta_f`` to the axis, and the front cone is the back cone's parallel
    through ``R_i = R_e - b``. Angles in degrees.

    >>> g = bevel_geometry(20, 40, 3.0, 22.0, clearance="tapered")
    >>> s = axial_section(g.pitch_angle[0], g.face_angle[0], g.root_angle[0], g.cone_distance,
    ...                   22.0, g.addendum[0], g.dedendum[0])
    >>> [round(float(v), 4) for v in s[0]]   # the outer tip: (d_ae / 2, X) of bevel_geometry
    [32.6833, 58.6584]
    >>> round(float(g.tip_diameter[0]) / 2, 4), round(float(g.crown_to_apex[0]), 4)
    (32.6833, 58.6584)
    """
    d, da, df = (np.radians(np.asarray(a, float)) for a in (pitch_angle, face_angle, root_angle))
    r_e = np.asarray(cone_distance, float)
    g = np.stack([np.sin(d), np.cos(d)], axis=-1)  # along the pitch generator
    n = np.stack([np.cos(d), -np.sin(d)], axis=-1)  # along the back cone, away from the axis
    pitch_e = r_e[..., None] * g
    pitch_i = (r_e - np.asarray(face_width, float))[..., None] * g
    tip = pitch_e + np.asarray(addendum, float)[..., None] * n
    root = pitch_e - np.asarray(dedendum, float)[..., None] * n

    def front(point, angle):  # where the line from point at angle to the axis meets the front
        u = np.stack([np.sin(angle), np.cos(angle)], axis=-1)
        w = pitch_i - point
        s = (w[..., 0] * n[..., 1] - w[..., 1] * n[..., 0]) / (
            u[..., 0] * n[..., 1] - u[..., 1] * n[..., 0]
        )
        return point + s[..., None] * u

    return np.stack([tip, root, front(root, df), front(tip, da)], axis=-2)
