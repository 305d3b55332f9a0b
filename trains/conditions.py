"""Layer 1, base.

The geometric conditions of a train of real gears, as vectorised numpy functions.

Pure formulas (no classes, no trains): :class:`trains.willis.Train` (``Train.check``) and
:class:`trains.planetary.stage.Planetary` both evaluate them.

* assembly number of identical planets between two central gears (lectures §4.3,
  standards.md §4): ``T = |z_b z_c - s_a s_b z_a z_d| / gcd(z_c, z_d)``, s = -1 for an external
  mesh and +1 for an internal one; ``k`` equally spaced planets assemble iff ``T % k == 0``;
* neighbour gap of ``k`` planets in one row: ``2 a_w sin(pi/k) - d_a`` (Ozols §21-13), and of
  ``k`` bevel planets on a common apex (a differential's pinions);
* closure of a chain of centre distances between two coaxial axes: two distances must be equal
  (the reverted-train and planetary coaxiality condition ``a_w12 = a_w34``), three or more form
  a polygon that closes iff the longest side does not exceed the sum of the others.

Examples
--------
>>> int(assembly_number(18, 45, 45, 108, internal_b=True))   # lectures §4.3: z_s + z_r
126
>>> round(float(neighbour_gap(63.0, 94.0, 3)), 4)   # 2 x 63 sin 60 deg - 94
15.1192
>>> float(closure_margin([57.0, 58.0], tolerance=0.01))
-0.99
"""

from __future__ import annotations

import numpy as np

__all__ = ["assembly_number", "bevel_neighbour_gap", "closure_margin", "neighbour_gap"]


def assembly_number(z_a, z_c, z_d, z_b, internal_a=False, internal_b=False):
    """Assembly number T of planets between central gears a and b (integer arithmetic).

    Parameters
    ----------
    z_a, z_b : int or array
        Tooth counts of the two central gears.
    z_c, z_d : int or array
        Tooth counts of the planet's gears meshing a and b (equal for a simple planet).
    internal_a, internal_b : bool or array
        True where the mesh with that central gear is internal.

    Returns
    -------
    int or array
        ``|z_b z_c - s_a s_b z_a z_d| // gcd(z_c, z_d)``: planet positions per turn.
    """
    z_a, z_c, z_d, z_b = (np.asarray(v, dtype=np.int64) for v in (z_a, z_c, z_d, z_b))
    s = np.where(np.asarray(internal_a, bool), 1, -1) * np.where(
        np.asarray(internal_b, bool), 1, -1
    )
    out = np.abs(z_b * z_c - s * z_a * z_d) // np.gcd(z_c, z_d)
    return out[()] if out.ndim == 0 else out


def neighbour_gap(center_distance, tip_diameter, n):
    """Gap between the tip circles of ``n`` equally spaced planets at ``center_distance`` (mm).

    ``2 a_w sin(pi/n) - d_a``; infinite for one planet.
    """
    a = np.asarray(center_distance, float)
    d = np.asarray(tip_diameter, float)
    n = np.asarray(n, float)
    with np.errstate(divide="ignore"):
        out = np.where(n >= 2, 2.0 * a * np.sin(np.pi / np.maximum(n, 1.0)) - d, np.inf)
    return out[()] if out.ndim == 0 else out


def bevel_neighbour_gap(face_angle, reach, n):
    """Gap between ``n`` equally spaced bevel planets on a common apex (the pinions of a
    differential), mm: their axes are ``360/n`` deg apart and each face cone (half angle
    ``face_angle`` deg) reaches ``reach`` mm from the apex at its outer tips, so the cones clear
    each other by ``reach (2 pi / n - 2 delta_a)`` (an arc at the outer tips); infinite for one.

    >>> round(float(bevel_neighbour_gap(36.0, 30.0, 4)), 4)   # 30 mm x (90 - 72) deg
    9.4248
    """
    da = np.radians(np.asarray(face_angle, float))
    r = np.asarray(reach, float)
    n = np.asarray(n, float)
    with np.errstate(divide="ignore"):
        out = np.where(n >= 2, r * (2.0 * np.pi / np.maximum(n, 1.0) - 2.0 * da), np.inf)
    return out[()] if out.ndim == 0 else out


def closure_margin(distances, tolerance=0.0):
    """Signed margin (mm) for a chain of centre distances to join two coaxial axes.

    One distance: the axes cannot coincide (margin ``tolerance - a``). Two distances (one
    intermediate shaft: a reverted train, sun-planet-ring): ``tolerance - |a_1 - a_2|``. Three
    or more: the polygon of the distances closes, ``sum - 2 max`` (>= 0). ``distances`` runs
    over the last axis, so many chains of equal length evaluate at once.
    """
    d = np.asarray(distances, float)
    if d.shape[-1] == 1:
        out = tolerance - d[..., 0]
    elif d.shape[-1] == 2:
        out = tolerance - np.abs(d[..., 0] - d[..., 1])
    else:
        out = d.sum(axis=-1) - 2.0 * d.max(axis=-1)
    return out[()] if np.ndim(out) == 0 else out
