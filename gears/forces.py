"""Layer 2, formulas: the forces of a mesh and the reactions of a shaft's bearings, over arrays.

The frame of a pair of parallel axes (spur, helical, internal): the origin on gear 1's axis, x
from gear 1's axis towards the pitch point P (so gear 2's axis lies at ``+a_w x`` for an external
pair and at ``-a_w x`` for an internal one), z along gear 1's axis, y = z x x. A torque ``T``
(N m) on gear 1 is signed about +z. The mesh force on gear 1 acts along the line of action
through P (Ozols (11.8): ``R = M_1 / (r_1 cos alpha)``); its components there are

* tangential ``F_t = 2000 T / d_w1`` (the working pitch diameter, mm; ISO 6336-1 (1) with the
  reference diameter, which it is for ``x_1 + x_2 = 0``), acting against the torque:
  ``-F_t y`` for ``T > 0``;
* radial ``F_r = F_t tan alpha_wt`` (working transverse pressure angle), towards gear 1's axis
  (``-x``), for external and internal pairs alike;
* axial ``F_a = F_t tan beta_w`` (helix angle on the working pitch cylinder,
  ``tan beta_w = tan beta_b / cos alpha_wt``, ``tan beta_b = tan beta cos alpha_t``): the
  normal force is perpendicular to the tooth, so on gear 1 ``F_z = (2000 T / d_w1) tan beta_w``
  with beta signed (right hand > 0);
* normal ``F_n = |F| = F_t / (cos alpha_wt cos beta_b)`` (the load on the flank).

Gear 2 carries the opposite force (Newton's third law). Straight bevel gears (ISO 10300-1 /
DIN 3991, at the mean cone, diameter ``d_m``): ``F_t = 2000 T / d_m``, ``F_r = F_t tan alpha
cos delta``, ``F_a = F_t tan alpha sin delta``, the axial force pushing each gear away from the
apex and the radial force towards its axis, in the frame of :func:`gears.bevel.solid
.bevel_placement` (apex at the origin, gear 1's axis +z, gear 2's ``(sin Sigma, 0, cos Sigma)``).

Friction along the path of contact (Ozols (21.15)-(21.18)): the resultant Q leans by the
friction angle ``phi = atan f`` from the line of action, towards the driver's axis in the
approach and away from it in the recess, so that ``Q = P cos(alpha - Theta) / (cos alpha
cos(alpha + phi - Theta))`` with ``P = M_1 / r_1`` the driver's tangential force and Theta the
angle at the driver's centre between the pitch point and the contact point (``Theta = alpha_w -
alpha_y``, alpha_y the driver's pressure angle at the contact point); at the pitch point
``Q = P / cos(alpha + phi)`` and its radial component ``P tan(alpha + phi)``.

Examples
--------
Ozols section 11-2: ``M_1 = 100 N m``, ``r_1 = 50 mm``, ``alpha = 20 deg``.

>>> f = mesh_forces(100.0, 100.0, 20.0)
>>> round(float(f.tangential), 6), round(float(f.normal), 2)     # R = M_1 / (r_1 cos alpha)
(2000.0, 2128.36)
"""

from __future__ import annotations

import numbers
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from gears.display import html_table
from gears.errors import GearError

__all__ = [
    "FrictionForce",
    "MeshForces",
    "PairForces",
    "bearing_reactions",
    "bevel_mesh_forces",
    "bevel_pair_forces",
    "centrifugal_force",
    "friction_mesh_force",
    "mesh_forces",
    "pair_forces",
    "rotate_forces",
    "tangential_force",
    "working_helix_angle",
    "worm_mesh_forces",
    "worm_pair_forces",
    "worm_torque_forces",
]


class MeshForces(NamedTuple):
    """Arrays returned by :func:`mesh_forces` and :func:`bevel_mesh_forces` (N, degrees).

    ``tangential``, ``radial``, ``axial`` and ``normal`` are magnitudes (>= 0) on gear 1 (a bevel
    pair's ``radial`` and ``axial`` are gear 1's, ``radial_2`` and ``axial_2`` gear 2's);
    ``vector`` is the force on gear 1 in the pair's frame (shape ``(..., 3)``: x, y, z);
    gear 2 carries ``-vector``.
    """

    tangential: np.ndarray
    radial: np.ndarray
    axial: np.ndarray
    normal: np.ndarray
    vector: np.ndarray
    radial_2: np.ndarray
    axial_2: np.ndarray


class FrictionForce(NamedTuple):
    """Arrays returned by :func:`friction_mesh_force` (N): the resultant Q of the contact, its
    normal part ``Q cos phi`` and friction part ``Q sin phi``, its components along the common
    tangent at the pitch point (``tangential``) and along the line of centres (``radial``,
    towards the driver's axis), and ``approach`` (True before the pitch point)."""

    resultant: np.ndarray
    normal: np.ndarray
    friction: np.ndarray
    tangential: np.ndarray
    radial: np.ndarray
    approach: np.ndarray


def _array(name: str, value: ArrayLike, low: float | None = None, high: float | None = None,
           low_open: bool = True) -> np.ndarray:  # fmt: skip
    """``value`` as a float array of finite numbers within ``(low, high)``, or a GearError
    naming the first bad value and the valid range."""
    scalar = isinstance(value, numbers.Real) and not isinstance(value, bool | np.bool_)
    try:
        raw = np.asarray(value)
        a = raw.astype(float) if scalar or raw.dtype.kind in "iuf" else None
    except (TypeError, ValueError, OverflowError):
        a = None
    if a is None:
        raise GearError(f"{name} = {value!r}; valid is a finite number or an array of numbers")
    bad = ~np.isfinite(a)
    if low is not None:
        bad |= (a <= low) if low_open else (a < low)
    if high is not None:
        bad |= a >= high
    if np.any(bad):
        first = a[bad].flat[0]
        lo = "" if low is None else f"{'>' if low_open else '>='} {low:g}"
        hi = "" if high is None else f"< {high:g}"
        span = " and ".join(s for s in (lo, hi) if s) or "finite"
        raise GearError(f"{name} = {first:g}; valid is {span}")
    return a


def _finite(result, what: str):
    """``result`` (an array or a tuple of arrays) when every value is finite, else a GearError:
    the inputs were finite but their forces lie beyond the floating-point range."""
    for arr in result if isinstance(result, tuple) else (result,):
        if not np.all(np.isfinite(arr)):
            raise GearError(
                f"{what} overflow the floating-point range (about 1e308); valid are torques and "
                "lengths whose forces stay finite"
            )
    return result


def _norm(v: np.ndarray) -> np.ndarray:
    """``abs(v)`` over the last axis without squaring past the float range."""
    return np.hypot(np.hypot(v[..., 0], v[..., 1]), v[..., 2])


def tangential_force(torque: ArrayLike, diameter: ArrayLike) -> np.ndarray:
    """``F_t = 2000 T / d``: N from a torque in N m at a diameter in mm (ISO 6336-1 (1)),
    signed like the torque.

    >>> float(tangential_force(100, 100))
    2000.0
    """
    t = _array("torque", torque)
    d = _array("diameter", diameter, 0.0)
    with np.errstate(over="ignore", invalid="ignore"):
        return _finite(2000.0 * t / d, "the tangential forces")


def working_helix_angle(helix_angle: ArrayLike, pressure_angle: ArrayLike,
                        working_pressure_angle: ArrayLike) -> np.ndarray:  # fmt: skip
    """beta_w, degrees (signed like beta): ``tan beta_w = tan beta_b / cos alpha_wt`` with
    ``tan beta_b = tan beta cos alpha_t`` and ``tan alpha_t = tan alpha_n / cos beta``
    (ISO 21771 (24), (12)); beta_w = beta when alpha_wt = alpha_t.

    >>> round(float(working_helix_angle(15.0, 20.0, 20.646896)), 6)
    15.0
    """
    b = np.radians(_array("helix_angle", helix_angle, -90.0, 90.0))
    an = np.radians(_array("pressure_angle", pressure_angle, 0.0, 90.0))
    awt = np.radians(_array("working_pressure_angle", working_pressure_angle, 0.0, 90.0))
    at = np.arctan(np.tan(an) / np.cos(b))
    tb_b = np.tan(b) * np.cos(at)
    return np.degrees(np.arctan(tb_b / np.cos(awt)))


def mesh_forces(
    torque: ArrayLike, working_diameter: ArrayLike, working_pressure_angle: ArrayLike,
    helix_angle: ArrayLike = 0.0, pressure_angle: ArrayLike = 20.0,
) -> MeshForces:  # fmt: skip
    """The mesh force of spur, helical and internal pairs (all arguments broadcast).

    Parameters
    ----------
    torque : array_like
        Torque on gear 1, N m, signed about gear 1's axis (+z).
    working_diameter : array_like
        Gear 1's working pitch diameter d_w1, mm (> 0).
    working_pressure_angle : array_like
        alpha_wt, degrees (0 < alpha_wt < 90).
    helix_angle : array_like
        Gear 1's helix angle beta at the reference cylinder, degrees (right hand > 0).
    pressure_angle : array_like
        Normal pressure angle alpha_n, degrees (for beta_b).

    Returns
    -------
    MeshForces
        Magnitudes and the force on gear 1 in the pair's frame (module docstring).

    Examples
    --------
    A helical pinion, 50 N m at d_w = 80 mm, alpha_wt = alpha_t, beta = 15 deg:

    >>> at = np.degrees(np.arctan(np.tan(np.radians(20)) / np.cos(np.radians(15))))
    >>> f = mesh_forces(50, 80, at, 15)
    >>> round(float(f.tangential), 3), round(float(f.axial), 3)      # F_t, F_t tan 15 deg
    (1250.0, 334.936)
    >>> np.round(f.vector, 3).tolist()                    # on gear 1: -F_r x, -F_t y, +F_a z
    [-471.012, -1250.0, 334.936]
    """
    t = tangential_force(torque, working_diameter)
    awt = _array("working_pressure_angle", working_pressure_angle, 0.0, 90.0)
    bw = np.radians(working_helix_angle(helix_angle, pressure_angle, awt))
    with np.errstate(over="ignore", invalid="ignore"):
        ft = np.abs(t)
        fr = ft * np.tan(np.radians(awt))
        fa_signed = t * np.tan(bw)
        vec = np.stack(np.broadcast_arrays(-fr, -t, fa_signed), axis=-1)
        fn = _norm(vec)
        fa = np.abs(fa_signed)
        out = MeshForces(ft, fr, fa, fn, vec, fr + 0.0 * fa, fa + 0.0 * fr)
    return _finite(out, "the mesh forces")


def bevel_mesh_forces(
    torque: ArrayLike, mean_diameter: ArrayLike, pitch_angle: ArrayLike,
    shaft_angle: ArrayLike = 90.0, pressure_angle: ArrayLike = 20.0,
) -> MeshForces:  # fmt: skip
    """The mesh force of straight bevel gears at the mean cone (ISO 10300-1 / DIN 3991).

    Parameters
    ----------
    torque : array_like
        Torque on gear 1, N m, signed about gear 1's axis (+z, pointing away from the apex).
    mean_diameter : array_like
        Gear 1's mean pitch diameter d_m1, mm.
    pitch_angle : array_like
        Gear 1's pitch angle delta_1, degrees; gear 2's is ``shaft_angle - delta_1``.
    shaft_angle : array_like
        Sigma, degrees.
    pressure_angle : array_like
        alpha, degrees.

    Returns
    -------
    MeshForces
        ``radial = F_t tan alpha cos delta_1``, ``axial = F_t tan alpha sin delta_1`` (gear 1),
        ``radial_2``, ``axial_2`` the same with delta_2; ``vector`` the force on gear 1 at the
        mean point ``R_m (sin delta_1, 0, cos delta_1)`` of the frame in the module docstring.

    Examples
    --------
    A right-angle pair 20/40 (delta_1 = 26.565 deg), 50 N m at d_m = 50 mm:

    >>> f = bevel_mesh_forces(50, 50, np.degrees(np.arctan(0.5)))
    >>> round(float(f.tangential), 3), round(float(f.radial), 3), round(float(f.axial), 3)
    (2000.0, 651.09, 325.545)
    >>> round(float(f.radial_2), 3), round(float(f.axial_2), 3)   # swapped at 90 deg
    (325.545, 651.09)
    """
    t = tangential_force(torque, mean_diameter)
    sigma = _array("shaft_angle", shaft_angle, 0.0, 180.0)
    d1 = _array("pitch_angle", pitch_angle, 0.0, 180.0)
    d2 = sigma - d1
    if np.any(d2 <= 0.0):
        first = np.broadcast_to(d1, np.broadcast_shapes(d1.shape, sigma.shape))[d2 <= 0.0]
        raise GearError(
            f"pitch_angle = {first.flat[0]:g}; valid is 0 < pitch_angle < shaft_angle (deg)"
        )
    alpha = np.radians(_array("pressure_angle", pressure_angle, 0.0, 90.0))
    with np.errstate(over="ignore", invalid="ignore"):
        ft = np.abs(t)
        side = ft * np.tan(alpha)  # the normal force's part in the plane of the axes
        r1, a1 = side * np.cos(np.radians(d1)), side * np.sin(np.radians(d1))
        r2, a2 = side * np.cos(np.radians(d2)), side * np.sin(np.radians(d2))
        # on gear 1: towards its axis (-x), against the torque (-y), away from the apex (+z)
        vec = np.stack(np.broadcast_arrays(-r1, -t, a1), axis=-1)
        out = MeshForces(ft + 0.0 * side, r1, a1, _norm(vec), vec, r2, a2)
    return _finite(out, "the mesh forces")


def worm_mesh_forces(
    torque: ArrayLike, worm_diameter: ArrayLike, lead_angle: ArrayLike,
    normal_pressure_angle: ArrayLike = 20.0, friction: ArrayLike = 0.0, driving: str = "worm",
) -> MeshForces:  # fmt: skip
    """The mesh force of a cylindrical worm pair (shaft angle 90 deg) at the worm's reference
    cylinder, with friction (the normal force W and the friction mu W along the thread; DIN
    3996 / ISO/TR 14521, Shigley's W_x, W_y, W_z):

    * worm tangential ``F_t1 = 2000 T_1 / d_1 = W (cos alpha_n sin gamma + s mu cos gamma)``,
    * worm axial = wheel tangential ``F_a1 = W (cos alpha_n cos gamma - s mu sin gamma)``,
    * radial ``F_r = W sin alpha_n``,

    with ``s = +1`` when the worm drives and ``-1`` when the wheel drives (the friction turns);
    so ``F_t1 = F_a1 tan(gamma +- phi')``, ``tan phi' = mu / cos alpha_n`` (Ozols (14.15),
    (14.18)). ``torque`` is the worm's, N m (its sign is kept on ``vector``).

    Returns
    -------
    MeshForces
        ``tangential`` F_t1, ``axial`` F_a1, ``radial`` F_r, ``normal`` W, ``radial_2`` F_r
        and ``axial_2`` the wheel's axial force F_t1; ``vector`` the force on a right-hand
        worm in the frame of :func:`worm_pair_forces`.

    Raises
    ------
    GearError
        A wheel that cannot drive its worm (``gamma <= phi'``: self-locking).

    Examples
    --------
    >>> f = worm_mesh_forces(10.0, 40.0, 5.710593, 20.0)     # tan gamma = 0.1, no friction
    >>> round(float(f.tangential), 3), round(float(f.axial), 3), round(float(f.radial), 3)
    (500.0, 5000.0, 1828.928)
    """
    t = tangential_force(torque, worm_diameter)
    g = np.radians(_array("lead_angle", lead_angle, 0.0, 90.0))
    an = np.radians(_array("normal_pressure_angle", normal_pressure_angle, 0.0, 90.0))
    mu = _array("friction", friction, 0.0, 1.0, low_open=False)
    if driving not in ("worm", "wheel"):
        raise GearError(f"driving = {driving!r}; valid are 'worm', 'wheel'")
    s = 1.0 if driving == "worm" else -1.0
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        per_w = np.cos(an) * np.sin(g) + s * mu * np.cos(g)  # F_t1 / W
        if np.any(per_w <= 0.0):
            raise GearError(
                f"friction = {float(np.max(mu)):g} with the wheel driving: the pair is "
                "self-locking (lead angle <= the friction angle); valid is a friction below "
                "tan(gamma) cos(alpha_n)"
            )
        ft = np.abs(t)
        w = ft / per_w
        fa = w * (np.cos(an) * np.cos(g) - s * mu * np.sin(g))
        fr = w * np.sin(an)
        vec = np.stack(np.broadcast_arrays(-fr, -t, np.sign(t) * fa), axis=-1)
        out = MeshForces(ft + 0.0 * fa, fr, fa, w, vec, fr, ft + 0.0 * fa)
    return _finite(out, "the worm forces")


def worm_torque_forces(
    torque: ArrayLike, wheel_torque: ArrayLike, worm_diameter: ArrayLike,
    wheel_diameter: ArrayLike, lead_angle: ArrayLike, normal_pressure_angle: ArrayLike = 20.0,
) -> MeshForces:  # fmt: skip
    """The mesh force of a right-hand cylindrical worm pair from the torques on both members:
    the force :func:`worm_mesh_forces` gives, read the other way round (from its tangential and
    axial components to W and the friction), so it holds for any efficiency, in either
    direction, and for a self-locking pair driven backwards, where the worm's torque vanishes or
    reverses and :func:`worm_mesh_forces` refuses.

    In the frame of :func:`worm_pair_forces` (origin on the worm's axis +z, x towards the
    wheel's axis, which runs along +y) the force on the worm at the pitch point is
    ``(-F_r, -F_t1, F_a1)`` with ``F_t1 = 2000 T_1 / d_1`` (``torque`` T_1 on the worm about
    +z) and ``F_a1 = 2000 T_2 / d_2`` (``wheel_torque`` T_2 on the wheel about +y, at the
    wheel's arm ``d_2 / 2``), so each member's torque balances the moment of its force. The
    normal force W and the friction mu W along the thread (:func:`worm_mesh_forces`) then
    follow from

    * ``W cos alpha_n = s (F_t1 sin gamma + F_a1 cos gamma)`` (``s = sign F_a1``),
    * ``mu W = s (F_t1 cos gamma - F_a1 sin gamma)`` (positive: the worm drives; negative:
      the wheel drives),

    and the radial force is ``F_r = W sin alpha_n`` (DIN 3996 / ISO/TR 14521; Ozols (14.15),
    (14.18): ``F_t1 = F_a1 tan(gamma +- phi')``).

    Parameters
    ----------
    torque, wheel_torque : array_like
        T_1 and T_2, N m (one of them may be 0 only if both are).
    worm_diameter : array_like
        d_1, the worm's diameter at the pitch point, mm (its reference diameter d_m1).
    wheel_diameter : array_like
        d_2, twice the wheel's arm to the pitch point, mm (``2 a - d_m1``: the wheel's
        reference diameter for an unshifted wheel, DIN 3996's d_m2).
    lead_angle, normal_pressure_angle : array_like
        gamma and alpha_n, degrees.

    Returns
    -------
    MeshForces
        ``tangential`` ``abs(F_t1)``, ``axial`` ``abs(F_a1)``, ``radial`` F_r, ``normal`` W,
        ``radial_2`` F_r, ``axial_2`` ``abs(F_t1)`` (the wheel's axial force), ``vector`` the force
        on the worm.

    Raises
    ------
    GearError
        Torques no contact can carry (W <= 0: the flank would pull), naming them.

    Examples
    --------
    The example of :func:`worm_mesh_forces` from its two torques (no friction, tan gamma =
    0.1, d_1 = 40 mm, so T_2 = 10 N m * (d_2 / d_1) / tan gamma at d_2 = 200 mm):

    >>> f = worm_torque_forces(10.0, 500.0, 40.0, 200.0, 5.710593)
    >>> round(float(f.tangential), 3), round(float(f.axial), 3), round(float(f.radial), 3)
    (500.0, 5000.0, 1828.928)
    """
    t = tangential_force(torque, worm_diameter)
    fa = tangential_force(wheel_torque, wheel_diameter)
    g = np.radians(_array("lead_angle", lead_angle, 0.0, 90.0))
    an = np.radians(_array("normal_pressure_angle", normal_pressure_angle, 0.0, 90.0))
    with np.errstate(over="ignore", invalid="ignore"):
        s = np.where(fa < 0.0, -1.0, 1.0)
        w_cos = s * (t * np.sin(g) + fa * np.cos(g))  # W cos(alpha_n)
        tiny = 1e-12 * (np.abs(t) + np.abs(fa))
        bad = ~(w_cos > tiny) & ((t != 0.0) | (fa != 0.0))
        if np.any(bad):
            t1, t2 = (np.broadcast_to(np.asarray(v, float), bad.shape)[bad].flat[0]
                      for v in (torque, wheel_torque))  # fmt: skip
            raise GearError(
                f"torque = {t1:g} N m on the worm with wheel_torque = {t2:g} N m: no contact "
                "carries them (the flank would pull); valid are torques whose forces press the "
                "flanks together, |F_a1| cos(gamma) + F_t1 sin(gamma) > 0 with F_t1 signed in "
                "the sense of F_a1"
            )
        w = np.maximum(w_cos, 0.0) / np.cos(an)
        fr = w * np.sin(an)
        vec = np.stack(np.broadcast_arrays(-fr, -t, fa), axis=-1)
        ft, fa_abs = np.abs(t) + 0.0 * fr, np.abs(fa) + 0.0 * fr
        out = MeshForces(ft, fr, fa_abs, w, vec, fr, ft)
    return _finite(out, "the worm forces")


def friction_mesh_force(
    tangential: ArrayLike, working_pressure_angle: ArrayLike, friction: ArrayLike,
    contact_pressure_angle: ArrayLike | None = None,
) -> FrictionForce:  # fmt: skip
    """The contact force with friction, Ozols (21.16)-(21.18).

    Parameters
    ----------
    tangential : array_like
        P = M_1 / r_w1, the driver's tangential force, N (>= 0).
    working_pressure_angle : array_like
        alpha_w, degrees.
    friction : array_like
        Coefficient f, 0 <= f < 1 (friction angle ``phi = atan f``).
    contact_pressure_angle : array_like, optional
        alpha_y, the driver's pressure angle at the contact point, degrees (0 <= alpha_y < 90):
        below alpha_w the approach, above it the recess. Default: the pitch point, approached
        (Ozols (21.17), the largest force).

    Returns
    -------
    FrictionForce

    Examples
    --------
    At the pitch point, alpha = 20 deg, f = 0.1 (Ozols (21.17), (21.18)):

    >>> q = friction_mesh_force(2000.0, 20.0, 0.1)
    >>> round(float(q.resultant), 2), round(float(q.radial), 2)   # P/cos(a+phi), P tan(a+phi)
    (2219.76, 962.99)
    """
    p = _array("tangential", tangential, 0.0, low_open=False)
    aw = np.radians(_array("working_pressure_angle", working_pressure_angle, 0.0, 90.0))
    f = _array("friction", friction, 0.0, 1.0, low_open=False)
    phi = np.arctan(f)
    if contact_pressure_angle is None:
        ay = aw
        approach = np.ones(np.broadcast_shapes(aw.shape, p.shape, f.shape), bool)
    else:
        ay = np.radians(_array("contact_pressure_angle", contact_pressure_angle, 0.0, 90.0,
                               low_open=False))  # fmt: skip
        approach = np.asarray(ay <= aw)
    with np.errstate(over="ignore", invalid="ignore"):
        return _finite(_leaning(p, aw, phi, ay, approach), "the contact forces")


def _leaning(p, aw, phi, ay, approach) -> FrictionForce:
    lean = np.where(approach, phi, -phi)  # towards the driver's axis before P, away after it
    # (21.16) with Theta = alpha_w - alpha_y: Q = P cos(alpha_y) / (cos alpha_w cos(alpha_y + lean))
    q = p * np.cos(ay) / (np.cos(aw) * np.cos(ay + lean))
    direction = aw + lean  # the resultant's angle from the common tangent
    approach = np.broadcast_to(approach, np.broadcast_shapes(np.shape(approach), q.shape))
    return FrictionForce(q, q * np.cos(phi), q * np.sin(phi), q * np.cos(direction),
                         q * np.sin(direction), approach)  # fmt: skip


def centrifugal_force(mass: ArrayLike, speed: ArrayLike, radius: ArrayLike) -> np.ndarray:
    """``m omega^2 rho``: the centrifugal force (N) of a mass (kg) whose centre turns at
    ``speed`` (rpm) on a circle of ``radius`` (mm) about the carrier's axis (Ozols section 11-2:
    ``J_2 = AO omega_H^2 m_2``).

    >>> round(float(centrifugal_force(1.0, 60.0 / (2 * np.pi), 1000.0)), 12)   # 1 kg, 1 rad/s, 1 m
    1.0
    """
    m = _array("mass", mass, 0.0, low_open=False)
    n = _array("speed", speed)
    r = _array("radius", radius, 0.0, low_open=False)
    with np.errstate(over="ignore", invalid="ignore"):
        return _finite(m * (n * np.pi / 30.0) ** 2 * r / 1000.0, "the centrifugal forces")


def rotate_forces(vectors: ArrayLike, angle: ArrayLike) -> np.ndarray:
    """Force vectors (``(..., 3)``) turned by ``angle`` degrees about +z: a pair's frame put
    where its line of centres lies in a train (x towards the pitch point at ``angle``).

    >>> np.round(rotate_forces([1.0, 0.0, 2.0], 90.0), 12).tolist()
    [0.0, 1.0, 2.0]
    """
    v = _array("vectors", vectors)
    if v.shape[-1:] != (3,):
        raise GearError(f"vectors has shape {v.shape}; valid is (..., 3)")
    th = np.radians(_array("angle", angle))[..., None]
    c, s = np.cos(th), np.sin(th)
    x, y, z = v[..., 0:1], v[..., 1:2], v[..., 2:3]
    with np.errstate(over="ignore", invalid="ignore"):
        out = np.concatenate(np.broadcast_arrays(c * x - s * y, s * x + c * y, z + 0.0 * c), -1)
    return _finite(out, "the turned forces")


def bearing_reactions(
    forces: ArrayLike, points: ArrayLike, bearings: ArrayLike
) -> tuple[np.ndarray, np.ndarray]:
    """The reactions of a shaft's two bearings to forces on it (statics of a beam on two
    supports): the shaft's axis is z, bearing A at ``z = bearings[0]`` takes the axial force
    (the locating bearing), B at ``z = bearings[1]`` is free to float.

    Parameters
    ----------
    forces : array_like, shape (n, 3)
        Forces on the shaft, N (the mesh forces on its gears).
    points : array_like, shape (n, 3)
        Where they act, mm (a gear's pitch point, or its centre ``(0, 0, z)`` for a force
        through the axis).
    bearings : array_like, shape (2,)
        z of bearing A and of bearing B, mm (different).

    Returns
    -------
    (reactions, torque)
        ``reactions`` of shape (2, 3): the force of each bearing on the shaft, N (A, B);
        ``torque`` the forces' moment about the axis, N m (what the shaft's coupling carries).
        The forces, the reactions and ``-torque`` about z balance.

    Examples
    --------
    A gear at mid-span with a radial load of 1000 N: each bearing takes half.

    >>> r, _ = bearing_reactions([[-1000.0, 0, 0]], [[0.0, 0, 50]], [0.0, 100.0])
    >>> np.round(r, 9).tolist()
    [[500.0, 0.0, 0.0], [500.0, 0.0, 0.0]]
    """
    f = _array("forces", forces)
    p = _array("points", points)
    zb = _array("bearings", bearings)
    if f.ndim != 2 or f.shape[1] != 3 or p.shape != f.shape:
        raise GearError(
            f"forces and points have shapes {f.shape} and {p.shape}; valid is (n, 3) each"
        )
    if zb.shape != (2,):
        raise GearError(f"bearings = {bearings!r}; valid is two axial positions (z_A, z_B), mm")
    span = zb[1] - zb[0]
    if not abs(span) > 1e-9 * max(1.0, float(np.abs(zb).max())):
        raise GearError(f"bearings = {bearings!r}: the two bearings coincide; give two positions")
    a = np.array([0.0, 0.0, zb[0]])
    with np.errstate(over="ignore", invalid="ignore"):
        moment = np.cross(p - a, f).sum(axis=0)  # N mm about bearing A
        total = f.sum(axis=0)
        # B at (0, 0, span) from A: (B - A) x R_B = (-span R_By, span R_Bx, 0) balances moment
        r_b = np.array([-moment[1] / span, moment[0] / span, 0.0])
        r_a = -total - r_b
        out = np.stack([r_a, r_b]) + 0.0, moment[2] / 1000.0
    reactions, torque = _finite(out, "the bearing reactions")
    return reactions, float(torque)


# --------------------------------------------------------------------- one pair, as a view


@dataclass(frozen=True)
class PairForces:
    """The forces of one mesh under a torque: what :meth:`gears.GearPair.forces`,
    :meth:`gears.BevelPair.forces` and :meth:`gears.WormPair.forces` return (N, N m, mm,
    degrees).

    Attributes
    ----------
    kind : str
        ``"spur"``, ``"helical"``, ``"internal"``, ``"rack"``, ``"bevel"`` or ``"worm"`` (gear 1
        the worm).
    torque : float
        The torque applied to gear 1, N m, signed about its axis (+z).
    torque_2 : float or None
        The torque that holds gear 2 in balance, N m, about its own axis (the frame's +z for
        parallel axes; for a bevel gear its axis pointing away from the apex); None for a rack.
    tangential, radial, axial, normal : (float, float)
        Magnitudes on gear 1 and gear 2.
    vectors : ndarray, shape (2, 3)
        The mesh force on gear 1 and on gear 2 in the pair's frame (:mod:`gears.forces`).
    point : ndarray, shape (3,)
        Where they act: the pitch point (bevel: the mean point).
    centres : ndarray, shape (2, 3)
        A point on each gear's axis (gear 2's is ``inf`` for a rack); ``axes`` their directions.
    axes : ndarray, shape (2, 3)
    working_pressure_angle, working_helix_angle : float
        alpha_wt and beta_w of gear 1 (bevel: alpha and 0).
    friction : float
        The friction coefficient of Ozols (21.17)/(21.18) (0: frictionless); a worm's mu.
    driving : str or None
        A worm pair's driving member, ``"worm"`` or ``"wheel"``; None for the other kinds.
    """

    kind: str
    torque: float
    torque_2: float | None
    tangential: tuple[float, float]
    radial: tuple[float, float]
    axial: tuple[float, float]
    normal: tuple[float, float]
    vectors: np.ndarray = field(repr=False)
    point: np.ndarray = field(repr=False)
    centres: np.ndarray = field(repr=False)
    axes: np.ndarray = field(repr=False)
    working_pressure_angle: float = 20.0
    working_helix_angle: float = 0.0
    friction: float = 0.0
    driving: str | None = None

    def rows(self) -> list[tuple[str, str, str]]:
        """``(quantity, gear 1, gear 2)`` text rows of the table."""
        out = []
        named = (("tangential F_t [N]", self.tangential), ("radial F_r [N]", self.radial),
                 ("axial F_a [N]", self.axial), ("normal F_n [N]", self.normal))  # fmt: skip
        for name, pair in named:
            out.append((name, f"{pair[0]:.3f}", f"{pair[1]:.3f}"))
        for i, axis in enumerate("xyz"):
            out.append((f"force {axis} [N]", f"{self.vectors[0, i]:.3f}",
                        f"{self.vectors[1, i]:.3f}"))  # fmt: skip
        t2 = "-" if self.torque_2 is None else f"{self.torque_2:.4f}"
        out.append(("torque [N m]", f"{self.torque:.4f}", t2))
        return out

    def _title(self) -> str:
        if self.kind == "worm":  # gear 1 is the worm; the angles are alpha_n and gamma
            return (f"worm mesh, the {self.driving or 'worm'} driving, torque {self.torque:g} N m "
                    f"on the worm (gear 1), alpha_n {self.working_pressure_angle:.4f} deg, lead "
                    f"angle {self.working_helix_angle:.4f} deg, friction "
                    f"{self.friction:g}")  # fmt: skip
        head = f"{self.kind} mesh, torque {self.torque:g} N m on gear 1"
        head += f", alpha_wt {self.working_pressure_angle:.4f} deg"
        if self.working_helix_angle:
            head += f", beta_w {self.working_helix_angle:.4f} deg"
        if self.friction:
            head += f", friction {self.friction:g} (Ozols (21.17))"
        return head

    def _heads(self) -> tuple[str, str]:
        return ("worm", "wheel") if self.kind == "worm" else ("gear 1", "gear 2")

    def __str__(self) -> str:
        one, two = self._heads()
        lines = [self._title(), f"{'':22s} {one:>12s} {two:>12s}"]
        lines += [f"{a:22s} {b:>12s} {c:>12s}" for a, b, c in self.rows()]
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        return html_table(["", *self._heads()], self.rows(), caption=self._title())


def _moment(point: np.ndarray, centre: np.ndarray, axis: np.ndarray, force: np.ndarray) -> float:
    """The moment of ``force`` at ``point`` about the axis through ``centre``, N m."""
    with np.errstate(over="ignore", invalid="ignore"):
        m = np.dot(np.cross(point - centre, force), axis) / 1000.0
    return float(_finite(m, "the torque on gear 2"))


def pair_forces(pair, torque, friction=0.0) -> PairForces:
    """The forces of a :class:`gears.GearPair` (spur, helical, internal or rack) under
    ``torque`` N m on gear 1 (signed about its axis), with ``friction`` at the pitch point
    (Ozols (21.17)/(21.18): the largest force; spur pairs only). The thin view behind
    :meth:`gears.GearPair.forces`."""
    t = float(_array("torque", torque))
    f = float(_array("friction", friction, 0.0, 1.0, low_open=False))
    if t == 0.0:
        raise GearError(f"torque = {torque!r}; valid is a finite non-zero number (N m)")
    g1 = pair.g1
    beta = g1.helix_angle
    if f and beta:
        raise GearError(
            f"friction = {friction!r} with helix_angle = {beta:g} deg: the friction of Ozols "
            "(21.16)-(21.18) is planar; valid is friction = 0 for a helical pair"
        )
    d1 = pair.working_diameters[0]
    awt = pair.working_pressure_angle
    m = mesh_forces(t, d1, awt, beta, g1.pressure_angle)
    vec = np.array(m.vector, float)
    if f:
        q = friction_mesh_force(float(m.tangential), awt, f)
        vec[0] = -float(q.radial)
    v1 = vec + 0.0
    v2 = -vec + 0.0
    point = np.array([d1 / 2, 0.0, 0.0])
    z = np.array([0.0, 0.0, 1.0])
    if pair.is_rack:
        kind, centre2, t2 = "rack", np.array([np.inf, 0.0, 0.0]), None
    else:
        a = pair.center_distance
        kind = "internal" if pair.internal else ("helical" if beta else "spur")
        centre2 = np.array([-a if pair.internal else a, 0.0, 0.0])
        t2 = -_moment(point, centre2, z, v2) + 0.0  # what holds gear 2
    radial = abs(float(v1[0]))
    ft = abs(v1[1])
    fa = abs(v1[2])
    fn = float(_norm(v1))
    return PairForces(
        kind, t, t2, (ft, ft), (radial, radial), (fa, fa), (fn, fn), np.stack([v1, v2]), point,
        np.stack([np.zeros(3), centre2]), np.stack([z, z]), float(awt),
        float(working_helix_angle(beta, g1.pressure_angle, awt)), f,
    )  # fmt: skip


def bevel_pair_forces(pair, torque) -> PairForces:
    """The forces of a :class:`gears.BevelPair` under ``torque`` N m on gear 1 (signed about
    its axis pointing away from the apex), at the mean cone (ISO 10300-1). The thin view behind
    :meth:`gears.BevelPair.forces`."""
    t = float(_array("torque", torque))
    if t == 0.0:
        raise GearError(f"torque = {torque!r}; valid is a finite non-zero number (N m)")
    g1 = pair.g1
    sigma = pair.shaft_angle
    d1 = pair.pitch_angles[0]
    m = bevel_mesh_forces(t, g1.mean_diameter, d1, sigma, pair.pressure_angle)
    v1 = np.array(m.vector, float) + 0.0
    v2 = -v1 + 0.0
    rm = g1.mean_diameter / 2 / np.sin(np.radians(d1))  # R_m
    point = rm * np.array([np.sin(np.radians(d1)), 0.0, np.cos(np.radians(d1))])
    s = np.radians(sigma)
    axes = np.array([[0.0, 0.0, 1.0], [np.sin(s), 0.0, np.cos(s)]])
    t2 = -_moment(point, np.zeros(3), axes[1], v2) + 0.0
    ft = float(m.tangential)
    return PairForces(
        "bevel", t, t2, (ft, ft), (float(m.radial), float(m.radial_2)),
        (float(m.axial), float(m.axial_2)), (float(m.normal), float(m.normal)),
        np.stack([v1, v2]), point, np.zeros((2, 3)), axes, float(pair.pressure_angle), 0.0, 0.0,
    )  # fmt: skip


def worm_pair_forces(pair, torque, friction=0.0, driving="worm") -> PairForces:
    """The forces of a :class:`gears.WormPair` under ``torque`` N m on the worm (signed about
    its axis), with ``friction`` mu and the ``driving`` member (:func:`worm_mesh_forces`), as
    a :class:`PairForces`. Its frame: the origin on the worm's axis (+z), x towards the wheel's
    axis, which runs along y through ``(a, 0, 0)``; a left-hand pair mirrors the axial forces.
    """
    t = float(_array("torque", torque))
    if t == 0.0:
        raise GearError(f"torque = {torque!r}; valid is a finite non-zero number (N m)")
    m = worm_mesh_forces(t, pair.worm_diameter, pair.lead_angle, pair.normal_pressure_angle,
                         friction, driving)  # fmt: skip
    v1 = np.array(m.vector, float)
    if getattr(pair, "hand", "right") == "left":
        v1[2] = -v1[2]
    v1 = v1 + 0.0
    v2 = -v1 + 0.0
    point = np.array([pair.worm_diameter / 2, 0.0, 0.0])
    centre2 = np.array([pair.center_distance, 0.0, 0.0])
    axes = np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0]])
    t2 = -_moment(point, centre2, axes[1], v2) + 0.0
    ft, fr, fa, fn = (float(x) for x in (m.tangential, m.radial, m.axial, m.normal))
    return PairForces(
        "worm", t, t2, (ft, fa), (fr, fr), (fa, ft), (fn, fn), np.stack([v1, v2]), point,
        np.stack([np.zeros(3), centre2]), axes, float(pair.normal_pressure_angle),
        float(pair.lead_angle), float(_array("friction", friction, 0.0, 1.0, low_open=False)),
        driving,
    )  # fmt: skip
