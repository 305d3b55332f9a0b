"""Layer 2, formulas: the vectorised formulas of a meshing pair (ISO 21771 / DIN 3960 / KHK).


Formulas (ISO 21771 / DIN 3960 / KHK Gear Technical Reference; Ozols §21-3...21-8;
Joldasbekov §11). Positions on the line of action are measured in mm from N1, the point where
the line of action touches gear 1's base circle, towards the pitch point C:

* ``u_C = r_b1 tan alpha_wt``, ``u_N2 = r_b1 tan alpha_wt + sigma r_b2 tan alpha_wt``
  (sigma = +1 external, -1 internal: N2 lies beyond N1 for a ring);
* contact starts where gear 2's tip circle cuts the line
  (``u_A = u_N2 - sigma sqrt(r_a2^2 - r_b2^2)``) and ends where gear 1's tip circle cuts it
  (``u_E = sqrt(r_a1^2 - r_b1^2)``) when gear 1 drives;
* ``contact_ratio = (u_E - u_A) / p_bt``.

All formulas are numpy functions over arrays (:func:`pair_geometry` evaluates 10^6 pairs at once);
:class:`gears.GearPair` calls them for one pair; this module imports no class.
"""

from __future__ import annotations

import itertools
import math
import os
from concurrent.futures import ThreadPoolExecutor
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from gears.arguments import common_shape
from gears.errors import GearError
from gears.involute import inv, inv_inverse
from gears.namespace import of

__all__ = [
    "InternalInterference",
    "PairGeometry",
    "center_distance_shift_sum",
    "check_friction",
    "contact_ratio",
    "default_threads",
    "internal_interference",
    "line_of_action_points",
    "line_positions",
    "mesh_efficiency",
    "pair_geometry",
    "specific_sliding",
]


class PairGeometry(NamedTuple):
    """Arrays returned by :func:`pair_geometry` (mm and degrees)."""

    working_pressure_angle: np.ndarray
    center_distance: np.ndarray
    center_distance_modification: np.ndarray
    tip_alteration: np.ndarray
    tip_diameter_1: np.ndarray
    tip_diameter_2: np.ndarray
    working_diameter_1: np.ndarray
    working_diameter_2: np.ndarray
    contact_ratio: np.ndarray


def _sigma(internal):
    return np.where(np.asarray(internal, bool), -1.0, 1.0)


def pair_geometry(
    z1: ArrayLike, z2: ArrayLike, module: ArrayLike, x1: ArrayLike = 0.0, x2: ArrayLike = 0.0,
    pressure_angle: ArrayLike = 20.0, helix_angle: ArrayLike = 0.0, internal: ArrayLike = False,
    addendum: ArrayLike = 1.0, tip_shortening: ArrayLike = True, threads: int | None = None,
) -> PairGeometry:  # fmt: skip
    """Geometry of many pairs at once (all arguments broadcast; angles in degrees).

    ``z2`` is gear 2's own (positive) tooth count and ``x2`` its shift (a ring's in the sign of DIN
    3960 / ISO 21771: positive thickens its teeth); ``internal`` marks gear 2 as a ring.
    ``helix_angle`` is gear 1's (gear 2 has the opposite hand externally, the same internally). Tip
    shortening (DIN 3960: k = y - (x1 + x2), applied when negative) is for external pairs only;
    internal pairs keep their tips. Arrays of 65536 pairs or more run in blocks on ``threads``
    threads (default :func:`default_threads`).

    Returns
    -------
    PairGeometry
        Working transverse pressure angle alpha_wt (deg), centre distance a_w, y, k, tip
        diameters, working pitch diameters, transverse contact ratio. Tips inside the base
        circle, or tips too short to reach each other's flanks, give a contact ratio of 0 (no
        involute contact); use :class:`GearPair` for a
        checked single pair.

    Examples
    --------
    >>> g = pair_geometry(12, 28, 1.0, 0.3, 0.2)   # Joldasbekov §5.4, row 3
    >>> round(float(g.working_pressure_angle), 5), round(float(g.center_distance), 5)
    (23.29917, 20.46253)
    >>> round(float(g.contact_ratio), 5)
    1.36264
    """
    names = ("z1", "z2", "module", "x1", "x2", "pressure_angle", "helix_angle", "addendum")
    values = (z1, z2, module, x1, x2, pressure_angle, helix_angle, addendum)
    args = [_floats(name, v) for name, v in zip(names, values, strict=True)]
    args.append(np.asarray(internal, bool))
    args.append(_flags("tip_shortening", tip_shortening))
    shape = common_shape(
        dict(zip((*names, "internal", "tip_shortening"), (v.shape for v in args), strict=True))
    )
    n = math.prod(shape)
    if threads is None:
        threads = default_threads()
    elif isinstance(threads, bool) or not isinstance(threads, int) or threads < 1:
        raise GearError(f"threads = {threads!r}; valid is an integer >= 1")
    if n < 2 * _CHUNK:
        _check_rows(args, shape, 0)
        # every argument at the full shape: the block's in-place steps (inv_wt *= 2 tan) need
        # their first operand as large as the result (a scalar z1 with arrays of pressure angle)
        full = [np.broadcast_to(v, shape) for v in args]
        return PairGeometry(*_pair_geometry_block(*full))
    # Large arrays: blocks of _CHUNK pairs, whose temporaries stay in cache, shared by the
    # threads (numpy ufuncs release the GIL). Measured in docs/performance.md.
    flat = [v if v.ndim == 0 else np.broadcast_to(v, shape).ravel() for v in args]
    out = np.empty((len(PairGeometry._fields), n))

    def work(bounds: tuple[int, int]) -> None:
        i0, i1 = bounds
        part = [v if v.ndim == 0 else v[i0:i1] for v in flat]
        _check_rows(part, (i1 - i0,), i0)
        for row, value in zip(out, _pair_geometry_block(*part), strict=True):
            row[i0:i1] = value

    blocks = list(itertools.pairwise([*range(0, n, _CHUNK), n]))
    if threads == 1:
        for b in blocks:
            work(b)
    else:
        for _ in _pool(threads).map(work, blocks):  # re-raises a GearError from any block
            pass
    return PairGeometry(*(row.reshape(shape) for row in out))


_ROWS = (
    ("z1", lambda a: (a[0] >= 1) & (a[0] < 1e9), "a tooth count 1 <= z1 < 1e9"),
    ("z2", lambda a: (a[1] >= 1) & (a[1] < 1e9), "a tooth count 1 <= z2 < 1e9"),
    ("module", lambda a: (a[2] > 0) & (a[2] < 1e6), "0 < module (mm)"),
    ("x1", lambda a: np.abs(a[3]) < 1e3, "a finite shift"),
    ("x2", lambda a: np.abs(a[4]) < 1e3, "a finite shift"),
    ("pressure_angle", lambda a: (a[5] >= 1) & (a[5] < 45), "1 <= pressure_angle < 45 deg"),
    ("helix_angle", lambda a: np.abs(a[6]) < 60, "-60 < helix_angle < 60 deg"),
    ("addendum", lambda a: (a[7] > 0) & (a[7] < 10), "0 < addendum < 10 (module units)"),
    ("z2", lambda a: ~a[8] | (a[1] > a[0]), "z2 > z1 for a ring (internal)"),
)


def _floats(name: str, value) -> np.ndarray:
    """``value`` as a float array, or a GearError where it is no number in float range."""
    if type(value) is float:
        return np.asarray(value)
    try:
        a = np.asarray(value, float)
    except OverflowError:
        raise GearError(f"{name}: a value beyond the range of floats (10**400?)") from None
    except (TypeError, ValueError):
        raise GearError(f"{name} = {value!r}; valid is a number or an array of numbers") from None
    return a


def _flags(name: str, value) -> np.ndarray:
    """``value`` as a bool array (True/False or an array of them), or a GearError naming it."""
    a = np.asarray(value)
    if a.dtype != bool and not (a.dtype.kind in "iu" and np.all((a == 0) | (a == 1))):
        raise GearError(f"{name} = {value!r}; valid is True, False or an array of them")
    return a.astype(bool)


def _check_rows(args, shape, offset: int) -> None:
    """Refuse rows that describe no real pair, naming the first bad index and its value, the
    way :class:`gears.Gear` refuses one bad value (NaN fails every test)."""
    for name, test, valid in _ROWS:
        ok = test(args)
        if not np.all(ok):
            bad = np.broadcast_to(~ok, shape)
            index = np.unravel_index(int(np.argmax(bad)), shape)
            i = tuple(int(j) for j in index)
            where = "" if not i else (f" at row {offset + i[0]}" if len(i) == 1 else f" at {i}")
            values = {k: args[j] for j, k in enumerate(("z1", "z2", "module", "x1", "x2"))}
            values.update(pressure_angle=args[5], helix_angle=args[6], addendum=args[7])
            v = np.broadcast_to(values[name], shape)[index]
            raise GearError(f"{name} = {float(v):g}{where}; valid is {valid}")


_CHUNK = 1 << 15  # pairs per block: 32768 beat 16384 and 65536 (docs/performance.md)
_PARALLEL_MIN = _CHUNK  # arrays of at least 2 blocks take the blocked, threaded path
_MAX_THREADS = 4  # blocks are memory-bound: past 4 threads they got slower (docs/performance.md)
_POOLS: dict[int, ThreadPoolExecutor] = {}


def default_threads() -> int:
    """Threads for the blocked paths: the cores this process may run on, at most 4.

    ``GEARTRAIN_THREADS`` (an integer >= 1) overrides it; so does ``threads=`` on the call.
    """
    env = os.environ.get("GEARTRAIN_THREADS", "").strip()
    if env:
        if not env.isdigit() or int(env) < 1:
            raise GearError(f"GEARTRAIN_THREADS = {env!r}; valid is an integer >= 1")
        return int(env)
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        cores = os.cpu_count() or 1
    return max(1, min(cores, _MAX_THREADS))


def _pool(threads: int) -> ThreadPoolExecutor:
    if threads not in _POOLS:
        _POOLS[threads] = ThreadPoolExecutor(threads, thread_name_prefix="pair_geometry")
    return _POOLS[threads]


def _pair_geometry_block(z1, z2, m, x1, x2, pressure_angle, helix_angle, addendum, internal,
                         tip_shortening):  # fmt: skip
    """The formulas of :func:`pair_geometry` on one block of (broadcastable) arrays."""
    external = not internal.any()
    s = 1.0 if external else _sigma(internal)
    an = np.radians(pressure_angle)
    tan_an = np.tan(an)
    cos_b = np.cos(np.radians(helix_angle))
    at = np.arctan(tan_an / cos_b)
    cos_at = np.cos(at)
    z2s = z2 if external else s * z2  # signed tooth count of gear 2
    zs = z1 + z2s
    xs = x1 + x2  # DIN 3960: inv alpha_wt = 2 tan alpha_n (x1 + x2) / (z1 + z2), z2 < 0 a ring
    inv_wt = xs / zs
    inv_wt *= 2.0 * tan_an
    inv_wt += inv(at)
    if not np.all(inv_wt >= 0.0):
        bad = ~(inv_wt >= 0.0)
        # the limit sum -(z1 + z2) inv alpha_t / (2 tan alpha_n): a floor externally, a ceiling
        # for a ring (z1 + z2 < 0)
        limit = np.broadcast_to(-inv(at) * zs / (2.0 * tan_an), bad.shape)[bad]
        given = np.broadcast_to(xs, bad.shape)[bad][:3].tolist()
        ring = bool(np.broadcast_to(zs < 0, bad.shape)[bad][0])
        too, side = ("large for an internal pair", "below") if ring else ("negative", "above")
        raise GearError(
            f"shift sum x1 + x2 = {given} is too {too}: a working pressure angle exists "
            f"only {side} {np.ravel(limit)[:3].tolist()} (inv alpha_wt >= 0)"
        )
    awt = inv_inverse(inv_wt)
    cos_wt = np.cos(awt)
    tan_wt = np.tan(awt)
    ratio = cos_at / cos_wt
    half = np.abs(zs) / (2.0 * cos_b)
    a = half * ratio * m
    y = ratio - 1.0
    y *= half
    # k = y - (x1 + x2) when negative (DIN 3960), external pairs only
    k = np.minimum(y - xs, 0.0) if external else np.where(s > 0, np.minimum(y - xs, 0.0), 0.0)
    if not np.all(tip_shortening):
        k = np.where(tip_shortening, k, 0.0)
    mt = m / cos_b
    d1 = z1 * mt
    d2 = z2 * mt
    da1 = addendum + x1
    da1 += k
    da1 *= 2.0 * m
    da1 += d1
    da2 = addendum + x2
    da2 += k
    da2 *= 2.0 * m if external else 2.0 * s * m
    da2 += d2
    rb1 = d1 * (cos_at / 2.0)
    rb2 = d2 * (cos_at / 2.0)
    eps = contact_ratio(da1 / 2, da2 / 2, rb1, rb2, tan_wt, s, np.pi * mt * cos_at)
    two_over_cos_wt = 2.0 / cos_wt
    return (np.degrees(awt), a, y, k, da1, da2, rb1 * two_over_cos_wt, rb2 * two_over_cos_wt, eps)


def line_positions(ra1, ra2, rb1, rb2, tan_wt, sigma):
    """(u_A, u_E, u_N2) on the line of action, measured from N1 (see the module docstring)."""
    xp = of(ra1, ra2, rb1, rb2, tan_wt, sigma)
    u_n2 = rb1 * tan_wt + sigma * rb2 * tan_wt
    u_e = xp.sqrt(xp.maximum(ra1 * ra1 - rb1 * rb1, 0.0))
    u_a = u_n2 - sigma * xp.sqrt(xp.maximum(ra2 * ra2 - rb2 * rb2, 0.0))
    return u_a, u_e, u_n2


def line_of_action_points(rb1, working_pressure_angle, u, internal=False):
    """``(x, y)`` of the points at ``u`` mm from N1 on the line of action, in the frame of
    :func:`gears.cutting.outline.pair_placement` (gear 1 at the origin, gear 2 on +x, a ring's
    centre on
    -x): N1 = r_b1 (cos alpha_wt, sigma sin alpha_wt), the line running along
    (sin alpha_wt, -sigma cos alpha_wt) through the pitch point C = (r_w1, 0) at u_C = r_b1 tan
    alpha_wt (sigma = +1 external, -1 internal). ``working_pressure_angle`` in degrees.

    >>> x, y = line_of_action_points(10.0, 20.0, 10.0 * np.tan(np.radians(20.0)))
    >>> round(float(x), 6), abs(round(float(y), 6))   # the pitch point r_w1 = r_b1 / cos alpha_wt
    (10.641778, 0.0)
    """
    aw = np.radians(working_pressure_angle)
    s = _sigma(internal)
    u = np.asarray(u, float)
    return rb1 * np.cos(aw) + u * np.sin(aw), s * (rb1 * np.sin(aw) - u * np.cos(aw))


def contact_ratio(ra1, ra2, rb1, rb2, tan_wt, sigma, base_pitch):
    """Transverse contact ratio ``(u_E - u_A) / p_bt`` (see the module docstring), 0 where the
    tips do not reach each other's flanks or a tip lies inside its base circle (arrays)."""
    u_a, u_e, _ = line_positions(ra1, ra2, rb1, rb2, tan_wt, sigma)
    valid = (ra1 >= rb1) & (ra2 >= rb2)
    xp = of(u_a, u_e, base_pitch, valid)
    # tips that do not reach each other's flanks give no contact: 0, never a negative ratio
    return xp.where(valid, xp.maximum(u_e - u_a, 0.0) / base_pitch, 0.0)


def center_distance_shift_sum(
    z1, z2, module, center_distance, pressure_angle=20.0, helix_angle=0.0, internal=False
):
    """Sum of shifts x1 + x2 that gives ``center_distance`` (ISO 21771, the inverse problem;
    a ring's x2 in the sign of DIN 3960): cos alpha_wt = a_d cos alpha_t / a_w, then
    x1 + x2 = (z1 +- z2)(inv alpha_wt - inv alpha_t) / (2 tan alpha_n) (- internal: the sum
    falls as the centre distance grows).

    Raises
    ------
    GearError
        If no shift reaches ``center_distance`` (a_w <= a_d cos alpha_t).
    """
    s = _sigma(internal)
    z1 = np.asarray(z1, float)
    z2 = np.asarray(z2, float)
    a_w = np.asarray(center_distance, float)
    if not np.all((a_w > 0) & (a_w < np.inf)):
        bad = np.ravel(a_w)[np.argmax(~np.ravel((a_w > 0) & (a_w < np.inf)))]
        raise GearError(f"center_distance = {float(bad):g} mm; valid is a finite distance > 0")
    an = np.radians(pressure_angle)
    cos_b = np.cos(np.radians(helix_angle))
    at = np.arctan(np.tan(an) / cos_b)
    zsum = np.abs(z1 + s * z2)
    a_d = zsum * np.asarray(module) / (2 * cos_b)
    c = a_d * np.cos(at) / a_w
    # alpha_wt = 0 is the limit pair_geometry accepts (inv alpha_wt >= 0); rounding may put a
    # distance computed from such a pair a few ulps below a_d cos(alpha_t): the same boundary
    if np.any(~(c <= 1.0 + 4 * np.finfo(float).eps)):
        lowest = np.min(a_d * np.cos(at))
        raise GearError(
            f"center_distance = {np.ravel(center_distance)[0]:g} mm cannot be reached by profile "
            f"shift: it must be at least a_d cos(alpha_t) = {lowest:.6f} mm (working pressure "
            "angle 0)"
        )
    c = np.minimum(c, 1.0)
    awt = np.arccos(c)
    out = (z1 + s * z2) * (inv(awt) - inv(at)) / (2 * np.tan(an))
    return out[()] if np.ndim(out) == 0 else out


def specific_sliding(u, rb1, rb2, tan_wt, ratio, internal=False):
    """Specific sliding of both flanks at positions ``u`` on the line of action (from N1).

    zeta_1 = 1 - rho_2 / (u rho_1) and zeta_2 = 1 - u rho_1 / rho_2 with the flank radii of
    curvature rho_1 = u and rho_2 = sigma (u_N2 - u), u = z2/z1 (Ozols §21-4 (2)-(3) with the
    lost page restored; Joldasbekov §5.6). Both are 0 at the pitch point; at N1 (rho_1 = 0)
    zeta_1 is -inf, which is why a pair whose contact reaches N1 is interfering.
    """
    s = _sigma(internal)
    u = np.asarray(u, float)
    u_n2 = rb1 * tan_wt + s * rb2 * tan_wt
    rho1 = u
    rho2 = s * (u_n2 - u)
    with np.errstate(divide="ignore", invalid="ignore"):
        z1_ = 1.0 - rho2 / (ratio * rho1)
        z2_ = 1.0 - ratio * rho1 / rho2
    return z1_, z2_


def check_friction(friction) -> float:
    """``friction`` as a float, or a :class:`GearError` naming the valid range 0 <= f < 1."""
    if isinstance(friction, bool) or not isinstance(friction, int | float | np.floating):
        raise GearError(f"friction = {friction!r}; valid is a number 0 <= friction < 1")
    f = float(friction)
    if not 0.0 <= f < 1.0:  # NaN fails too
        raise GearError(f"friction = {friction!r}; valid is 0 <= friction < 1")
    return f


def mesh_efficiency(z1, z2, contact_ratio, friction=0.1, internal=False):
    """Mesh efficiency estimate, Ozols (14.25) after Reshetov:
    eta = 1 - (pi f eps / 2)(1/z1 +- 1/z2), + external, - internal.

    ``friction`` is the coefficient of sliding friction, 0 <= f < 1.

    >>> round(float(mesh_efficiency(20, 40, 1.6, 0.1)), 6)   # Ozols (14.25), derived case
    0.98115
    """
    check_friction(friction)
    s = _sigma(internal)
    return 1.0 - np.pi * friction * contact_ratio / 2.0 * (1.0 / z1 + s / np.asarray(z2, float))


class InternalInterference(NamedTuple):
    """Signed margins of :func:`internal_interference` (positive = satisfied)."""

    involute: np.ndarray  # dimensionless
    trochoid: np.ndarray  # rad
    radial: np.ndarray  # rad


def internal_interference(z1, z2, center_distance, ra1, ra2, rb1, rb2, working_pressure_angle):
    """The internal-gear interference checks of the KHK Gear Technical Reference as signed margins.

    Arguments broadcast; radii and the centre distance in mm, ``working_pressure_angle``
    alpha_wt in degrees. Tips must lie outside their base circles (``ra > rb``).

    * involute: the ring's tip must not pass N1: ``z1/z2 - (1 - tan alpha_a2 / tan alpha_wt)``;
    * trochoid: the tips clear each other leaving mesh:
      ``theta1 z1/z2 + inv alpha_wt - inv alpha_a2 - theta2`` (rad), with
      ``cos theta1 = (r_a2^2 - r_a1^2 - a^2) / (2 a r_a1)`` (+ inv alpha_a1 - inv alpha_wt) and
      ``cos theta2 = (a^2 + r_a2^2 - r_a1^2) / (2 a r_a2)``; ``pi / z2`` when the ring's tip
      circle encloses the pinion's (the tips never meet), and at most ``(a + r_a2 - r_a1)/r_a2``
      when it lies inside the pinion's (the tips foul);
    * radial: the pinion can be moved in radially (trimming):
      ``(theta1' + inv alpha_a1 - inv alpha_wt) - (z2/z1)(theta2' + inv alpha_a2 - inv alpha_wt)``
      with ``sin^2 theta1' = (1 - (cos alpha_a1/cos alpha_a2)^2) / (1 - (z1/z2)^2)`` and
      ``sin^2 theta2' = ((cos alpha_a2/cos alpha_a1)^2 - 1) / ((z2/z1)^2 - 1)``, clamped to
      [0, 1] so the margin stays continuous across both edges of the formula's domain; at most
      ``(r_a2 - r_a1)/r_a1`` when the pinion's tip circle exceeds the ring's.

    Returns
    -------
    InternalInterference
        ``(involute, trochoid, radial)`` arrays (0-d for scalar input).

    Examples
    --------
    Standard z1 = 20 pinion (x = 0, m = 1) in rings of z2 = 30 ... 79 teeth (a scan of
    the same conditions by an independent script): the involute check first passes at z2 = 64, the
    radial one at z2 = 37.

    >>> z2 = np.arange(30, 80)
    >>> c = np.cos(np.radians(20.0))
    >>> ra2, rb2 = (z2 - 2) / 2, z2 / 2 * c
    >>> m = internal_interference(20, z2, (z2 - 20) / 2, 11.0, ra2, 10 * c, rb2, 20.0)
    >>> int(z2[m.involute >= 0].min()), int(z2[m.radial >= 0].min())
    (64, 37)
    """
    z1 = np.asarray(z1, float)
    z2 = np.asarray(z2, float)
    a = np.asarray(center_distance, float)
    ra1, ra2, rb1, rb2 = (np.asarray(v, float) for v in (ra1, ra2, rb1, rb2))
    awt = np.radians(working_pressure_angle)
    aa1 = np.arccos(np.clip(rb1 / ra1, -1.0, 1.0))
    aa2 = np.arccos(np.clip(rb2 / ra2, -1.0, 1.0))
    inv_w, inv_a1, inv_a2 = inv(awt), inv(aa1), inv(aa2)
    tan_w = np.maximum(np.tan(awt), 1e-300)  # alpha_wt -> 0: the ring tip is far from N1
    involute = z1 / z2 - (1.0 - np.tan(aa2) / tan_w)
    a_safe = np.maximum(a, 1e-300)
    c1 = (ra2 * ra2 - ra1 * ra1 - a * a) / (2.0 * a_safe * ra1)
    c2 = (a * a + ra2 * ra2 - ra1 * ra1) / (2.0 * a_safe * ra2)
    th1 = np.arccos(np.clip(c1, -1.0, 1.0)) + inv_a1 - inv_w
    th2 = np.arccos(np.clip(c2, -1.0, 1.0))
    trochoid = th1 * z1 / z2 + inv_w - inv_a2 - th2
    trochoid = np.where(ra1 >= a + ra2, np.minimum(trochoid, (a + ra2 - ra1) / ra2), trochoid)
    trochoid = np.where(ra2 >= a + ra1, np.pi / z2, trochoid)
    with np.errstate(divide="ignore", invalid="ignore"):
        q1 = (1.0 - (np.cos(aa1) / np.cos(aa2)) ** 2) / (1.0 - (z1 / z2) ** 2)
        q2 = ((np.cos(aa2) / np.cos(aa1)) ** 2 - 1.0) / ((z2 / z1) ** 2 - 1.0)
    # z1 = z2 leaves 0/0: no radial entry is possible, the clamp takes q = 1 (theta' = pi/2)
    q1 = np.where(np.isfinite(q1), q1, 1.0)
    q2 = np.where(np.isfinite(q2), q2, 1.0)
    t1 = np.arcsin(np.sqrt(np.clip(q1, 0.0, 1.0)))
    t2 = np.arcsin(np.sqrt(np.clip(q2, 0.0, 1.0)))
    radial = (t1 + inv_a1 - inv_w) - (z2 / z1) * (t2 + inv_a2 - inv_w)
    radial = np.where(ra1 > ra2, np.minimum(radial, (ra2 - ra1) / ra1), radial)
    return InternalInterference(
        *(v[()] if v.ndim == 0 else v for v in (involute, trochoid, radial))
    )
