"""Layer 10, consumers.

Blocking contour: every limit of an external pair as a signed margin field over (x1, x2).

The blocking contour (Kolchin & Movnin; Ozols §21-7, Fig. 21-13; GOST 16532-70) maps every
profile-shifted pair of two tooth counts to a point (x1, x2). The origin is the zero-shift pair,
the line x1 + x2 = 0 holds the equal-and-opposite ("KO", V-zero) pairs, and each line
x1 + x2 = const is a constant centre distance. Each limit splits the plane; the region where all
of them hold is the set of usable designs.

:func:`blocking_contour` evaluates every limit on a grid with the vectorised formulas of
:mod:`gears.gear` and :mod:`gears.pair` (one numpy call per field, no loop over grid points).
Each field is a signed margin, positive where the condition holds, zero on the limit line:

``undercut_1``, ``undercut_2``
    x - x_min (modules): undercut by the rack-type tool (ISO 53 tool, Ozols 21.27).
``pointed_tip_1``, ``pointed_tip_2``
    normal tip land s_an / m_n (after tip shortening): the tooth is pointed where it is 0
    (ISO 21771, tooth thickness).
``tip_land_1``, ``tip_land_2``
    s_an / m_n - ``min_tip_land`` (DIN 3960 / Niemann rule of thumb, 0.2 m_n by default).
``contact_ratio``
    epsilon_alpha - ``min_contact_ratio`` (Ozols line 5 is epsilon_alpha = 1).
``tip_interference_1``
    how far (in modules, along the line of action) gear 2's tip meets gear 1's flank above
    gear 1's form circle (Ozols lines 3-4); the same margin as
    :meth:`gears.pair.GearPair.check` ``tip_interference`` divided by m_n.
``tip_interference_2``
    the same for gear 1's tip on gear 2's flank (Ozols lines 1-2; ``tip_interference_2``).

Where a gear is undercut (``undercut_*`` < 0) its form circle is taken as the base circle, the
involute's own limit (the vectorised :func:`gears.geometry.form_diameter`); the exact trochoid
crossing (:func:`gears.cutting.profile.undercut_form_diameter`) is a per-gear root-find and is not
needed
to draw the contour, because the undercut limit already excludes that region.

Margins are made dimensionless (divided by the normal module) so a plot at any module is the
same figure.
"""

from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType

import numpy as np

from gears.errors import GearError
from gears.geometry import (
    check_teeth,
    form_diameter,
    min_profile_shift,
    reference_diameter,
    tooth_thickness,
    transverse_pressure_angle,
)
from gears.involute import inv
from gears.meshing import line_positions, pair_geometry
from gears.rack import BasicRack

__all__ = ["LIMITS", "BlockingContour", "blocking_contour", "plot_blocking_contour"]

LIMITS = (
    "undercut_1",
    "undercut_2",
    "pointed_tip_1",
    "pointed_tip_2",
    "tip_land_1",
    "tip_land_2",
    "contact_ratio",
    "tip_interference_1",
    "tip_interference_2",
)
"""Names of the margin fields, in the order they are computed and plotted."""


@dataclass(frozen=True, eq=False)
class BlockingContour:
    """Margin fields of an external pair over a grid of profile shifts (read-only arrays).

    Arrays on the grid have shape ``(len(x2), len(x1))``: rows follow x2, columns x1 (the
    ``np.meshgrid`` "xy" layout, so ``ax.contour(x1, x2, field)`` draws them directly).

    Attributes
    ----------
    z1, z2 : int
        Tooth counts.
    module, pressure_angle, helix_angle : float
        Normal module (mm), normal pressure angle and helix angle (degrees).
    min_contact_ratio, min_tip_land : float
        The thresholds used for ``contact_ratio`` and ``tip_land_*``.
    x1, x2 : ndarray
        The 1-D grids of shift coefficients.
    margins : Mapping[str, ndarray]
        Signed margin field per limit name (:data:`LIMITS`); >= 0 where the limit holds.
    feasible : ndarray of bool
        True where every margin is >= 0.
    contact_ratio : ndarray
        Transverse contact ratio epsilon_alpha.
    center_distance : ndarray
        Working centre distance a_w (mm); constant on the lines x1 + x2 = const.
    working_pressure_angle : ndarray
        alpha_wt in degrees.
    """

    z1: int
    z2: int
    module: float
    pressure_angle: float
    helix_angle: float
    min_contact_ratio: float
    min_tip_land: float
    x1: np.ndarray
    x2: np.ndarray
    margins: MappingProxyType
    feasible: np.ndarray
    contact_ratio: np.ndarray
    center_distance: np.ndarray
    working_pressure_angle: np.ndarray

    def failing(self, x1: float, x2: float) -> list[str]:
        """Names of the limits violated at the grid point nearest to (x1, x2)."""
        j = int(np.argmin(np.abs(self.x1 - x1)))
        i = int(np.argmin(np.abs(self.x2 - x2)))
        return [name for name, f in self.margins.items() if f[i, j] < 0]


def _readonly(a) -> np.ndarray:
    a = np.array(a, dtype=a.dtype if isinstance(a, np.ndarray) else float)
    a.setflags(write=False)
    return a


def _grid(values, name: str) -> np.ndarray:
    g = np.atleast_1d(np.asarray(values, dtype=float))
    if g.ndim != 1 or g.size == 0 or not np.all(np.isfinite(g)):
        raise GearError(f"{name} must be a non-empty 1-D sequence of finite shifts; got {values!r}")
    return g


def _tip_lands(z1, z2, X1, X2, g, m, at, pressure_angle, helix_angle) -> list[np.ndarray]:
    """Both gears' normal tip land in modules over the grid (``g``: its :func:`pair_geometry`);
    a tip inside the base circle has no land: its (negative) depth below d_b instead."""
    lands = []
    for z, x, da, beta in ((z1, X1, g.tip_diameter_1, helix_angle),
                           (z2, X2, g.tip_diameter_2, -helix_angle)):  # fmt: skip
        d = float(reference_diameter(z, m, beta))
        db = d * np.cos(at)
        above = da >= db
        s_at = tooth_thickness(np.where(above, da, db), z, m, x, pressure_angle, beta, signed=True)
        cos_ba = np.cos(np.arctan(np.tan(np.radians(beta)) * da / d))
        # a tip inside the base circle has no land: its (negative) depth below d_b instead
        lands.append(np.where(above, s_at * cos_ba, (da - db) / 2.0) / m)
    return lands


def _tip_interference(
    z1, z2, X1, X2, g, m, at, pressure_angle, helix_angle, depth
) -> tuple[np.ndarray, np.ndarray]:
    """Tip interference on both flanks over the grid, in modules: the same margins as
    ``GearPair.check`` (each tip meets its mate's flank at or above the mate's form circle)."""
    rb1 = float(reference_diameter(z1, m, helix_angle)) * np.cos(at) / 2.0
    rb2 = float(reference_diameter(z2, m, -helix_angle)) * np.cos(at) / 2.0
    tan_wt = np.tan(np.radians(g.working_pressure_angle))
    u_a, u_e, u_n2 = line_positions(
        g.tip_diameter_1 / 2, g.tip_diameter_2 / 2, rb1, rb2, tan_wt, 1.0
    )
    rf1 = form_diameter(z1, m, X1, pressure_angle, helix_angle, depth) / 2.0
    rf2 = form_diameter(z2, m, X2, pressure_angle, -helix_angle, depth) / 2.0
    u_f1 = np.sqrt(np.maximum(rf1 * rf1 - rb1 * rb1, 0.0))
    l_f2 = np.sqrt(np.maximum(rf2 * rf2 - rb2 * rb2, 0.0))
    return (u_a - u_f1) / m, ((u_n2 - u_e) - l_f2) / m


def blocking_contour(
    z1: int, z2: int, x1=None, x2=None, module: float = 1.0, pressure_angle: float = 20.0,
    min_contact_ratio: float = 1.0, min_tip_land: float = 0.2, helix_angle: float = 0.0,
    rack: BasicRack | None = None, tip_shortening: bool = True, n: int = 201,
) -> BlockingContour:  # fmt: skip
    """Every limit of the external pair z1/z2 as a margin field on a grid of (x1, x2).

    Parameters
    ----------
    z1, z2 : int
        Tooth counts of the two external gears.
    x1, x2 : array_like, optional
        1-D grids of profile-shift coefficients. Default: ``n`` values from -0.5 (or just
        above half the smallest shift sum that still has a working pressure angle) to 1.5.
    module : float
        Normal module m_n in mm (the margins are in modules, so it only scales
        ``center_distance``).
    pressure_angle : float
        Normal pressure angle in degrees (re-angles ``rack``).
    min_contact_ratio : float
        Threshold for the ``contact_ratio`` field (Ozols' line 5 is 1.0).
    min_tip_land : float
        Required normal tip land in modules for ``tip_land_*`` (0.2, as :meth:`Gear.check`).
    helix_angle : float
        Helix angle of gear 1 in degrees (gear 2 has the opposite hand).
    rack : BasicRack, optional
        Basic rack (ISO 53 A by default): its addendum sets the tips, its straight-flank depth
        the undercut limit and the form circles.
    tip_shortening : bool
        Apply DIN 3960 tip shortening, as :class:`~gears.pair.GearPair` does by default.
    n : int
        Number of grid values per axis when ``x1`` / ``x2`` are not given.

    Returns
    -------
    BlockingContour

    Raises
    ------
    GearError
        For invalid tooth counts, or a grid reaching a shift sum so negative that no working
        pressure angle exists (inv alpha_wt < 0).

    Examples
    --------
    >>> bc = blocking_contour(12, 28, x1=[0.0, 0.4], x2=[0.0, 0.2])
    >>> bc.feasible.tolist()      # the zero-shift 12-tooth pinion is undercut
    [[False, True], [False, True]]
    >>> bc.failing(0.0, 0.0)
    ['undercut_1', 'tip_interference_1']
    """
    z1 = check_teeth("z1", z1)
    z2 = check_teeth("z2", z2)
    rack = BasicRack.iso53("A") if rack is None else rack
    if rack.pressure_angle != pressure_angle:
        rack = rack.with_pressure_angle(pressure_angle)
    m = float(module)
    if not m > 0:
        raise GearError(f"module = {module}; valid is module > 0")
    at = float(transverse_pressure_angle(pressure_angle, helix_angle))
    tan_an = np.tan(np.radians(pressure_angle))
    # inv alpha_wt >= 0  <=>  x1 + x2 >= -(z1 + z2) inv(alpha_t) / (2 tan alpha_n)
    sum_min = -(z1 + z2) * float(inv(at)) / (2.0 * tan_an)
    if x1 is None or x2 is None:
        low = max(-0.5, 0.45 * sum_min)
        default = np.linspace(low, 1.5, n)
        x1 = default if x1 is None else x1
        x2 = default if x2 is None else x2
    x1 = _grid(x1, "x1")
    x2 = _grid(x2, "x2")
    if x1.min() + x2.min() <= sum_min:
        raise GearError(
            f"the grid reaches x1 + x2 = {x1.min() + x2.min():.4f}; a working pressure angle "
            f"exists only for x1 + x2 > {sum_min:.4f} (z1 = {z1}, z2 = {z2})"
        )
    X1, X2 = np.meshgrid(x1, x2)
    g = pair_geometry(
        z1, z2, m, X1, X2, pressure_angle, helix_angle, False, rack.addendum, tip_shortening
    )
    depth = rack.straight_flank_depth
    margins = {
        "undercut_1": X1 - min_profile_shift(z1, pressure_angle, helix_angle, depth),
        "undercut_2": X2 - min_profile_shift(z2, pressure_angle, -helix_angle, depth),
    }
    lands = _tip_lands(z1, z2, X1, X2, g, m, at, pressure_angle, helix_angle)
    margins["pointed_tip_1"], margins["pointed_tip_2"] = lands
    margins["tip_land_1"] = lands[0] - min_tip_land
    margins["tip_land_2"] = lands[1] - min_tip_land
    margins["contact_ratio"] = g.contact_ratio - min_contact_ratio
    margins["tip_interference_1"], margins["tip_interference_2"] = _tip_interference(
        z1, z2, X1, X2, g, m, at, pressure_angle, helix_angle, depth
    )
    margins = {name: _readonly(margins[name]) for name in LIMITS}
    feasible = np.logical_and.reduce([f >= 0.0 for f in margins.values()])
    for name, f in margins.items():
        if not np.all(np.isfinite(f)):
            raise GearError(f"blocking contour field {name} is not finite on this grid")
    return BlockingContour(
        z1, z2, m, float(pressure_angle), float(helix_angle), float(min_contact_ratio),
        float(min_tip_land), _readonly(x1), _readonly(x2), MappingProxyType(margins),
        _readonly(feasible), _readonly(g.contact_ratio), _readonly(g.center_distance),
        _readonly(g.working_pressure_angle),
    )  # fmt: skip


_LABELS = {
    "undercut_1": "$x_{1,min}$ (undercut 1)",
    "undercut_2": "$x_{2,min}$ (undercut 2)",
    "pointed_tip_1": "$s_{a1} = 0$",
    "pointed_tip_2": "$s_{a2} = 0$",
    "tip_land_1": "$s_{a1} = $ land",
    "tip_land_2": "$s_{a2} = $ land",
    "contact_ratio": r"$\varepsilon_\alpha = $ min",
    "tip_interference_1": "interference on 1",
    "tip_interference_2": "interference on 2",
}


def plot_blocking_contour(result: BlockingContour, ax=None, contact_levels=None, n_center=7):
    """Draw the blocking contour (Ozols Fig. 21-13): each limit line labelled, the infeasible
    region hatched, iso-lines of contact ratio and of centre distance (x1 + x2 = const).

    Parameters
    ----------
    result : BlockingContour
    ax : matplotlib Axes, optional
        Drawn into a new figure when omitted.
    contact_levels : sequence of float, optional
        Iso-lines of epsilon_alpha (default: 1.1 ... 1.7 by 0.1 where present).
    n_center : int
        Number of centre-distance iso-lines.

    Returns
    -------
    matplotlib Axes

    Raises
    ------
    ImportError
        If matplotlib is not installed (``pip install geartrain[plot]``).
    """
    try:
        import matplotlib.pyplot as plt
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise ImportError(
            "plot_blocking_contour needs matplotlib: install the 'plot' extra "
            "(pip install 'geartrain[plot]')"
        ) from exc
    if ax is None:
        _, ax = plt.subplots(figsize=(7.5, 7.0))
    x1, x2 = result.x1, result.x2
    with plt.rc_context({"hatch.color": "0.6", "hatch.linewidth": 0.6}):
        ax.contourf(
            x1, x2, (~result.feasible).astype(float), levels=[0.5, 1.5], colors=["0.9"],
            hatches=["///"], alpha=0.6,
        )  # fmt: skip
    labels = []  # every contour label on a white box: readable over the hatching
    colors = ["tab:red", "tab:orange", "tab:green", "tab:olive", "tab:purple", "tab:pink",
              "black", "tab:brown", "tab:cyan"]  # fmt: skip
    for i, name in enumerate(LIMITS):
        field = result.margins[name]
        if not (field.min() < 0.0 < field.max()):
            continue  # this limit does not cross the drawn region
        cs = ax.contour(x1, x2, field, levels=[0.0], colors=[colors[i]], linewidths=1.8)
        labels += ax.clabel(cs, fmt={0.0: _LABELS[name]}, fontsize=8, inline=True)
    eps = result.contact_ratio
    levels = contact_levels
    if levels is None:
        levels = [v for v in np.arange(1.1, 2.0, 0.1) if eps.min() < v < eps.max()]
    if len(levels):
        cs = ax.contour(x1, x2, eps, levels=levels, colors="0.35", linewidths=0.7, linestyles=":")
        labels += ax.clabel(cs, fmt=lambda v: f"ε={v:.1f}", fontsize=7)
    a = result.center_distance
    a_levels = np.linspace(a.min(), a.max(), n_center + 2)[1:-1]
    cs = ax.contour(x1, x2, a, levels=a_levels, colors="tab:blue", linewidths=0.6, linestyles="--")
    labels += ax.clabel(cs, fmt=lambda v: f"a={v:.2f}", fontsize=7)
    for text in labels:
        text.set_bbox({"facecolor": "white", "edgecolor": "none", "alpha": 0.85, "pad": 1.0})
    ax.axhline(0.0, color="k", linewidth=0.5)
    ax.axvline(0.0, color="k", linewidth=0.5)
    ax.set_xlabel("$x_1$")
    ax.set_ylabel("$x_2$")
    ax.set_title(
        f"Blocking contour z1 = {result.z1}, z2 = {result.z2}, "
        f"α = {result.pressure_angle:g}°, m = {result.module:g} mm "
        "(hatched: infeasible)"
    )
    ax.set_aspect("equal")
    return ax
