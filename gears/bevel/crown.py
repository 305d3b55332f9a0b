"""Layer 5, simulated cutting on the sphere: a bevel gear's tooth space cut by its generating
crown gear, position by position, as :mod:`gears.cutting.generate` cuts a spur gear with a rack.

On a spherical section the crown gear's plane flanks are great circles; the *gnomonic*
projection from the apex onto the plane tangent to the sphere at the pitch generator g maps
great circles to straight lines, so there each position of the crown tooth is a plain polygon
(its flanks exact straight edges, its tip land and rounds sampled at a quarter of the
tolerance) and shapely unites them. The positions turn the crown by ``sin(delta) phi`` and the
gear by phi (the generating roll, :mod:`gears.bevel.spherical`), spaced so that the scallops between
them stay within a third of the tolerance. The union, clipped by the tip circle, is the tooth
space that a straight-bevel generator with plane-flanked tools leaves: the octoid with its root
fillet and any undercut. It agrees with the closed-form envelope of
:class:`gears.bevel.spherical.SphericalTooth` within the tolerance (tests/gears/test_bevel_mesh.py).
Angles in radians; the gnomonic coordinates are tangents of angles (near g, angles).
"""

from __future__ import annotations

import math

import numpy as np
import shapely

from gears.bevel.spherical import SphericalTooth, _adaptive, _rotate, direction
from gears.budget import check_budget
from gears.errors import GearError

__all__ = ["crown_positions", "crown_space", "gnomonic"]

_EZ = np.array([0.0, 0.0, 1.0])


def gnomonic(tooth: SphericalTooth, y) -> np.ndarray:
    """Unit vectors ``y`` in the gnomonic plane tangent at the pitch generator g: coordinates
    ``(y . e_y, y . e_c) / (y . g)`` (azimuth-wise, and towards the gear's axis)."""
    y = np.asarray(y, float)
    w = y @ tooth.g
    if np.any(w <= 0):
        raise GearError("a point lies 90 deg or more from the pitch generator")
    return np.stack([y @ tooth.ey, y @ tooth.ec], axis=-1) / w[..., None]


def _tool(tooth: SphericalTooth, eps: float, depth: float) -> np.ndarray:
    """The crown tooth on the sphere (crown frame, unit vectors), closed, counter-clockwise
    in the gnomonic plane: tip land, rounds, flanks down to latitude ``-depth``."""
    quarter = eps / 4.0
    lat = tooth.eta_t
    land = _adaptive(
        lambda p: math.cos(lat) * (np.cos(p)[..., None] * tooth.g + np.sin(p)[..., None] * tooth.ey)
        + math.sin(lat) * tooth.ec,
        0.0, max(tooth.psi_c, 1e-12), quarter,
    )  # fmt: skip
    tip = math.cos(lat) * (np.cos(land)[:, None] * tooth.g + np.sin(land)[:, None] * tooth.ey)
    tip = tip + math.sin(lat) * tooth.ec
    gam = _adaptive(lambda g: tooth.round_points(g)[0], 0.0, tooth.gamma_flank, quarter)
    rnd = tooth.round_points(gam)[0]
    s_lo = -(depth + 0.1) / max(math.cos(tooth.alpha), 0.2)
    s = _adaptive(lambda t: tooth.flank(t)[0], tooth.s_form, s_lo, quarter)
    flank = tooth.flank(s)[0]
    right = np.concatenate([tip, rnd[1:], flank[1:]])
    left = _mirror(tooth, right)[::-1]
    return np.concatenate([left[:-1], right])


def _mirror(tooth: SphericalTooth, y: np.ndarray) -> np.ndarray:
    """Mirror in the crown's tooth-centre plane (the plane of g and e_c): e_y -> -e_y."""
    return y - 2.0 * (y @ tooth.ey)[:, None] * tooth.ey[None, :]


def crown_positions(tooth: SphericalTooth, eps: float, theta_tip: float) -> np.ndarray:
    """Gear rotations phi of the simulated positions: symmetric, through 0, spaced for scallops
    of a third of ``eps`` on the flank (curvature radius below 1 on the unit sphere) and on the
    fillet (the round's radius r, its centre turning about g at the rate cos delta), over the
    roll that brings the flank's contact to the tip circle ``theta_tip``, and one step more."""
    e = eps / 3.0
    s_tip = tooth.flank_at_polar(theta_tip)
    x, t = tooth.flank(np.array([s_tip, tooth.s_form]))
    beta = np.arctan2(-(t @ tooth.g), t @ tooth.ey)
    own = tooth.longitude(x)
    beta = beta + np.pi * np.round((own - beta) / np.pi)
    reach = float(np.max(np.abs(beta))) / tooth.sigma
    d_c = 2.0 * (tooth.eta_t + tooth.r + abs(tooth.psi_c)) * math.cos(tooth.delta)
    step = math.sqrt(8.0 * e)
    if tooth.r > 0 and d_c > 0:
        step = min(step, math.sqrt(8.0 * e * tooth.r) / d_c)
    n = math.ceil(reach / step) + 2
    half = step * np.arange(n + 1)
    return np.concatenate([-half[:0:-1], half])


def crown_space(tooth: SphericalTooth, tolerance: float, distance: float,
                theta_tip: float) -> shapely.Geometry:  # fmt: skip
    """One tooth space cut by the crown gear (centred on azimuth 0) on the sphere of radius
    ``distance`` (mm) about the apex, to ``tolerance`` (mm), as a shapely geometry in the
    gnomonic plane of :func:`gnomonic` (unit sphere), clipped by the tip circle ``theta_tip``.

    Raises
    ------
    GearError
        When the simulation would place more tool vertices than the simulation budget of
        :mod:`gears.budget`; the message names the size and the coarsest tolerance that fits.
    """
    depth = theta_tip - tooth.delta + 0.05

    def placed(tol: float) -> float:
        e = tol / distance
        return len(_tool(tooth, e, depth)) * len(crown_positions(tooth, e, theta_tip))

    check_budget("simulation", f"the crown simulation of z = {tooth.z}", placed, tolerance)
    eps = tolerance / distance
    tool = _tool(tooth, eps, depth)
    phis = crown_positions(tooth, eps, theta_tip)
    polys = []
    for phi in phis:
        y = _rotate(tool, tooth.ec, tooth.sigma * phi)
        y = _rotate(y, _EZ, -phi)
        polys.append(gnomonic(tooth, y))
    space = shapely.union_all(shapely.polygons(polys))
    az = np.linspace(-math.pi / tooth.z, math.pi / tooth.z, 721)
    rim = gnomonic(tooth, direction(theta_tip, az))
    axis_side = gnomonic(tooth, direction(max(tooth.delta - 0.5, 0.01), az[::-1]))
    blank = shapely.Polygon(np.concatenate([rim, axis_side]))
    return space.intersection(blank)
