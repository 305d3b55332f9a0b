"""Layer 6, noncircular teeth: teeth cut on any pitch curve by a rack rolled along it.

The rack's pitch line rolls without slipping on the pitch curve (the generation of
:mod:`gears.cutting.generate` with the circle replaced by any centrode; Litvin, *Gear Geometry
and Applied Theory*, the generation of non-circular gears by a rack cutter): at each pole
position the line is the centrodes' common tangent, and the rack's point at the pole is the one
whose distance along the line equals the arc rolled. Gear 1's cutter has its teeth towards
O1, gear 2's cutter is the complementary rack (its teeth towards O2, half a pitch along): both
gears are conjugate to one rack, so to each other. Each cutter position is subtracted from the
blank (the pitch curve offset by the addendum) with shapely, all positions at once.

Accuracy from ``tolerance`` (mm), by the scallop rules of simulated cutting on a circle, with
the pitch curve's largest curvature kappa for 1/r:

* the flank scallop between two positions, h = sin(alpha) ds^2 kappa / 8;
* the tip round's scallop, h = (kappa reach ds)^2 / (8 rho_aP0), ``reach`` the farthest a cutter
  tooth works from the pole;
* the tool's round sampled to a chord sag of ``tolerance / 4``; the pitch curve's blank too.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import shapely

from gears.budget import check_budget
from gears.cutting.sampling import chord_angle
from gears.errors import GearError

__all__ = [
    "RackCutter",
    "check_cut_budget",
    "cut_outline",
    "rack_frames",
    "rack_tooth",
    "roll_step",
]


@dataclass(frozen=True)
class RackCutter:
    """A rack cutter's tooth (the basic rack's mirror image, ISO 53): module (the pitch curve's
    fitted one), pressure angle (degrees), the gear's addendum and dedendum and the tool's tip
    round, in modules."""

    module: float
    pressure_angle: float = 20.0
    addendum: float = 1.0
    dedendum: float = 1.25
    tip_round: float = 0.38

    @property
    def pitch(self) -> float:
        return math.pi * self.module

    @property
    def reach(self) -> float:
        """The farthest (mm along the pitch line) from the pole at which a cutter tooth still
        touches the blank: its whole depth along the flank, plus a pitch."""
        depth = (self.addendum + self.dedendum) * self.module
        return depth / math.tan(math.radians(self.pressure_angle)) + self.pitch


def _arc_points(radius: float, start: float, stop: float, sag: float) -> np.ndarray:
    """Points of an arc of ``radius`` (centre at the origin) from ``start`` to ``stop`` (rad),
    chords sagging at most ``sag``."""
    if radius <= 0:
        return np.zeros((1, 2))
    n = max(1, math.ceil(abs(stop - start) / max(chord_angle(radius, sag), 1e-9)))
    t = np.linspace(start, stop, n + 1)
    return np.stack([radius * np.cos(t), radius * np.sin(t)], axis=-1)


def rack_tooth(cutter: RackCutter, tolerance: float) -> np.ndarray:
    """One cutter tooth as (u, v) vertices, counter-clockwise: u along the pitch line (the
    tooth centred at u = 0), v away from the gear being cut; its tip (which cuts the gear's
    root) at v = -dedendum m, its flanks u = +-(p/4 + v tan alpha), reaching past the gear's
    tip to v = (addendum + 0.75) m."""
    m = cutter.module
    tan_a = math.tan(math.radians(cutter.pressure_angle))
    cos_a = math.cos(math.radians(cutter.pressure_angle))
    h = cutter.dedendum * m
    rho = cutter.tip_round * m
    top = (cutter.addendum + 0.75) * m
    vc = -h + rho
    uc = cutter.pitch / 4 + vc * tan_a - rho / cos_a
    if uc < 0:
        raise GearError(
            f"tip_round = {cutter.tip_round:g} m does not fit the cutter's tip land at "
            f"{cutter.pressure_angle:g} deg; valid is a round whose centre lies inside the tip"
        )
    alpha = math.radians(cutter.pressure_angle)
    arc = _arc_points(rho, -math.pi / 2, -alpha, tolerance / 4) + np.array([uc, vc])
    right = np.vstack([arc, [[cutter.pitch / 4 + top * tan_a, top]]])
    left = right[::-1] * [-1.0, 1.0]
    return np.vstack([left[:-1] if uc == 0 else left, right])


def roll_step(cutter: RackCutter, curvature: float, tolerance: float) -> float:
    """The arc length between two cutter positions (mm) for ``tolerance`` on a pitch curve
    whose largest curvature is ``curvature`` (1/mm): the smaller of the flank's and the tip
    round's scallop rules (module docstring), at most a quarter pitch."""
    k = max(abs(curvature), 1e-12)
    sin_a = math.sin(math.radians(cutter.pressure_angle))
    flank = math.sqrt(8.0 * tolerance / (k * sin_a))
    rho = max(cutter.tip_round * cutter.module, tolerance)
    fillet = math.sqrt(8.0 * rho * tolerance) / (k * cutter.reach)
    return min(flank, fillet, cutter.pitch / 4)


def rack_frames(r, dr):
    """The rack's pitch line at the pole in the fixed frame for gear 1's pole radius ``r`` and
    its derivative ``dr`` = d r1/d phi (arrays): the unit tangent ``t = (r', -r)/|.|`` (the way
    the pole runs along gear 1's pitch curve as phi grows) and the unit normal
    ``n = (r, r')/|.|`` (towards gear 2)."""
    r, dr = np.asarray(r, float), np.asarray(dr, float)
    h = np.hypot(r, dr)
    t = np.stack([dr / h, -r / h], axis=-1)
    n = np.stack([r / h, dr / h], axis=-1)
    return t, n


def cut_outline(
    blank: shapely.Polygon, tooth: np.ndarray, pitch: float, reach: float, pole: np.ndarray,
    tangent: np.ndarray, normal: np.ndarray, rolled: np.ndarray, rotation: np.ndarray,
    center: tuple[float, float], second: bool, tolerance: float,
    progress: Callable | None = None,
) -> shapely.Polygon:  # fmt: skip
    """``blank`` minus the rack cutter at every position: the pole (N, 2), the pitch line's
    tangent and normal (N, 2) and the arc rolled (N,) in the fixed frame; the gear's own frame
    is the fixed one turned by ``rotation`` (N,) radians about ``center``. ``second``: the
    complementary cutter of gear 2 (teeth towards +n, half a pitch along)."""
    tool = tooth * [1.0, -1.0] if second else tooth
    shift = pitch / 2 if second else 0.0
    span = math.ceil(reach / pitch) + 1
    offsets = np.arange(-span, span + 1)
    # the cutter teeth near each position: centres u_j = j p + shift within reach of the pole
    j0 = np.round((rolled - shift) / pitch)
    u = (j0[:, None] + offsets[None, :]) * pitch + shift - rolled[:, None]  # (N, J) along t
    keep = np.abs(u) <= reach + pitch
    pu = u[:, :, None] + tool[None, None, :, 0]  # (N, J, K)
    pv = np.broadcast_to(tool[None, None, :, 1], pu.shape)
    pts = (
        pole[:, None, None, :]
        + pu[..., None] * tangent[:, None, None, :]
        + pv[..., None] * normal[:, None, None, :]
    )
    c, s_ = np.cos(rotation)[:, None, None], np.sin(rotation)[:, None, None]
    x, y = pts[..., 0] - center[0], pts[..., 1] - center[1]
    pts = np.stack([c * x - s_ * y, s_ * x + c * y], axis=-1)
    polys = shapely.polygons(pts[keep])
    if progress is not None:
        progress(1, 3)
    cut = shapely.union_all(polys, grid_size=None)
    if progress is not None:
        progress(2, 3)
    out = shapely.difference(blank, cut)
    if isinstance(out, shapely.MultiPolygon):  # slivers of the blank cut loose at the tips
        out = max(out.geoms, key=lambda g: g.area)
    out = shapely.simplify(out, tolerance / 4)
    if progress is not None:
        progress(3, 3)
    return out


def check_cut_budget(positions: int, teeth: int, vertices: int, tolerance: float, what: str):
    """Refuse a cut over the simulation budget before any work (vertex operations of the
    union: positions x cutter teeth x tool vertices, falling as 1/tolerance)."""
    n = float(positions) * teeth * vertices
    check_budget("simulation", what, lambda t: n * tolerance / t, tolerance)
