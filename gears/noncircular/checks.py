"""Layer 5, noncircular checks: the margins of a non-circular pair's teeth, per tooth, as
vectorised functions.

A tooth cut by a rack on a non-circular pitch curve is, locally, a tooth of the circular gear
whose pitch radius is the curve's radius of curvature rho there (Litvin, *Gear Geometry and
Applied Theory*, the elliptical gears' chapter: the equivalent gear of z_eq = 2 rho / m teeth).
Its undercut and its tip land follow from the circular gear's ISO 21771 formulas at that tooth
count (:func:`gears.geometry.min_profile_shift`, :func:`gears.checks.pointed_tip_margin`); a
concave stretch of pitch curve (rho < 0) cannot be cut by a rack or hob at all.
"""

from __future__ import annotations

import numpy as np

from gears.checks import pointed_tip_margin
from gears.geometry import min_profile_shift, tip_diameter

__all__ = ["equivalent_teeth", "tooth_margins"]


def equivalent_teeth(radius_of_curvature, module):
    """z_eq = 2 rho / m: the teeth of the circular gear whose pitch circle osculates the pitch
    curve (arrays broadcast; negative on a concave stretch)."""
    return 2.0 * np.asarray(radius_of_curvature, float) / np.asarray(module, float)


def tooth_margins(curvature, module, pressure_angle=20.0, addendum=1.0, min_tip_land=0.2):
    """(undercut, pointed_tip, convexity) margins at each tooth from the pitch curve's signed
    curvature there (1/mm, positive convex), arrays broadcast.

    * undercut, modules: -x_min(z_eq), the shift the equivalent gear would need (ISO 21771
      x_min = h_a* - z sin^2(alpha) / 2), negative where the rack undercuts the tooth;
    * pointed_tip, mm: the equivalent gear's normal tip land minus ``min_tip_land`` m;
    * convexity, 1/mm: the curvature itself, negative on a concave stretch (no rack can cut it).

    On a concave or straight stretch the equivalent gear is taken as the rack (z_eq -> inf: no
    undercut, the rack's own tip land), so the first two margins stay finite.
    """
    k = np.asarray(curvature, float)
    m = np.asarray(module, float)
    convex = k > 0
    big = 1e6  # teeth: the rack limit, where every margin has reached its limit value
    z = np.where(convex, np.minimum(equivalent_teeth(1.0 / np.where(convex, k, 1.0), m), big), big)
    undercut = -min_profile_shift(z, pressure_angle, 0.0, addendum)
    da = tip_diameter(z, m, 0.0, 0.0, addendum)
    tip = pointed_tip_margin(z, m, 0.0, pressure_angle, 0.0, False, da, min_tip_land)
    return undercut, tip, k
