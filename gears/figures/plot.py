"""Layer 10, consumers.

Figures (matplotlib, the ``plot`` extra): outlines, one tooth with its construction, a
meshing pair with its line of action, and the generation process with fading tool positions."""

from __future__ import annotations

import math

import numpy as np
from shapely.plotting import patch_from_polygon

from gears.cutting.generate import (
    rack_positions,
    rack_tool_polygon,
    shaper_positions,
    shaper_tool_polygon,
)
from gears.cutting.profile import ShaperProfile, ToothProfile
from gears.errors import GearError
from gears.files import pyplot
from gears.meshing import line_of_action_points

__all__ = ["generation_figure", "outlines_figure", "pair_figure", "tooth_figure"]


def _draw(ax, poly, **kw):
    for ring in (poly.exterior, *poly.interiors):
        x, y = ring.xy
        ax.plot(x, y, **kw)


def _circle(ax, r, center=(0, 0), **kw):
    t = np.linspace(0, 2 * math.pi, 721)
    ax.plot(center[0] + r * np.cos(t), center[1] + r * np.sin(t), **kw)


def outlines_figure(*outlines, ax=None):
    """All outlines, filled, equal axes, in mm."""
    plt = pyplot()
    fig, ax = (ax.figure, ax) if ax is not None else plt.subplots(figsize=(7, 7))
    for i, p in enumerate(outlines):
        polys = getattr(p, "geoms", [p])
        for q in polys:  # a patch with holes: bores and ring interiors stay unfilled
            ax.add_patch(patch_from_polygon(q, alpha=0.35, color=f"C{i}", lw=0))
            _draw(ax, q, color=f"C{i}", lw=0.6)
    ax.set_aspect("equal")
    ax.set_xlabel("mm")
    return fig


def tooth_figure(gear, tolerance: float = 1e-3, ax=None):
    """One tooth, its involute and fillet coloured, with its tip, reference, form, base and root
    circles. Every curve is named in a legend below the drawing (with the circle's diameter in
    mm), so close circles (the form and base circles of an undercut pinion) never share a
    label."""

    plt = pyplot()
    fig, ax = (ax.figure, ax) if ax is not None else plt.subplots(figsize=(5.2, 5.6))
    prof = ToothProfile(gear)
    rho, eta, kind = prof.half_space(tolerance)
    half = math.pi / gear.teeth
    parts = {0: (None, "k"), 1: ("fillet (trochoid offset)", "C3"), 2: ("involute", "C0"),
             3: (None, "k")}  # fmt: skip
    for side in (1, -1):
        th = side * (half - eta) + math.pi / 2
        x, y = rho * np.cos(th), rho * np.sin(th)
        for k, (label, colour) in parts.items():
            sel = np.flatnonzero(kind == k)
            if sel.size:
                sel = np.append(sel, min(sel[-1] + 1, len(x) - 1))
                ax.plot(x[sel], y[sel], color=colour, lw=2, label=label if side == 1 else None)
    t = np.linspace(math.pi / 2 - 1.5 * half, math.pi / 2 + 1.5 * half, 200)
    for name, d, style, colour in [
        ("tip circle d_a", gear.tip_diameter, "-", "0.55"),
        ("reference circle d", gear.reference_diameter, "--", "C2"),
        ("form circle d_Ff", gear.form_diameter, "-.", "C4"),
        ("base circle d_b", gear.base_diameter, ":", "C1"),
        ("root circle d_f", gear.root_diameter, "-", "0.55"),
    ]:  # fmt: skip
        ax.plot(d / 2 * np.cos(t), d / 2 * np.sin(t), style, color=colour, lw=1,
                label=f"{name} = {d:.3f} mm", zorder=1)  # fmt: skip
    ax.set_aspect("equal")
    ax.set_xlabel("mm")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, fontsize=8,
              frameon=False, handlelength=2.5)  # fmt: skip
    ax.set_title(f"z = {gear.teeth}, x = {gear.profile_shift:g}, m = {gear.module:g} mm")
    fig.tight_layout()
    return fig


def pair_figure(pair, angle: float = 0.0, tolerance: float = 1e-3, ax=None):
    """Both gears in mesh with the line of action and the path of contact."""
    plt = pyplot()
    p1, p2 = pair.outlines(angle, tolerance)
    fig = outlines_figure(p1, p2, ax=ax)
    ax = fig.axes[0]
    rb1 = pair.mounted[0].base_diameter / 2
    path = pair.path_of_contact

    def on_line(u):  # from N1, gear 1's base-circle tangent point, through the pitch point
        return line_of_action_points(rb1, pair.working_pressure_angle, u, pair.internal)

    ax.plot(*on_line([0.0, path.end + 0.3 * path.length]), color="k", lw=0.6,
            label="line of action")  # fmt: skip
    ax.plot(*on_line([path.start, path.end]), color="C3", lw=2.5, label="path of contact")
    _circle(ax, pair.working_diameters[0] / 2, color="0.5", lw=0.5, ls="--")
    ax.legend(loc="upper right", fontsize=8)
    ax.set_title(f"contact ratio {pair.contact_ratio:.3f}")
    plt.tight_layout()
    return fig


def generation_figure(gear, tolerance: float = 1e-2, every: int = 1, ax=None,
                      method: str = "rack", cutter=None):  # fmt: skip
    """The cutter's positions (fading away from the centre) over the cut tooth space.

    ``method='rack'``: the rack cutter over an external gear. ``method='shaper'``: the teeth of a
    shaper cutter (``cutter``, default the gear's own or
    :meth:`gears.cutting.cutter.ShaperCutter.default_for`) at their positions
    (:func:`gears.cutting.generate.shaper_positions`), for an external or an internal gear, over the
    outline that cutter leaves. ``every`` draws every n-th position.
    """
    plt = pyplot()
    if method == "rack":
        if gear.internal:
            raise GearError("a rack cutter cannot generate an internal gear; use method='shaper'")
        if cutter is not None or getattr(gear, "cutter", None) is not None:
            raise GearError("this gear is cut by a shaper cutter; use method='shaper'")
    elif method != "shaper":
        raise GearError(f"method = {method!r}; valid are 'rack', 'shaper'")
    size = (8, 5) if gear.internal else (7, 6)
    fig, ax = (ax.figure, ax) if ax is not None else plt.subplots(figsize=size)
    m = gear.module
    if method == "rack":
        prof = ToothProfile(gear)
        phis = rack_positions(prof, tolerance)[::every]
        placed = prof.tool.place(rack_tool_polygon(prof, tolerance), phis)
        name = "rack generation"
    else:
        prof = ShaperProfile(gear, cutter)
        phis = shaper_positions(prof, tolerance)[::every]
        placed = prof.tool.place(shaper_tool_polygon(prof, tolerance), phis)
        c0 = prof.cutter
        name = f"shaper generation (z0 = {c0.teeth}, x0 = {c0.shift:g})"
    big = float(np.max(np.abs(phis))) or 1.0
    for phi, xy in zip(phis, placed, strict=True):
        # the tooth polygon is closed by a chord outside the blank: left open, it is not drawn
        alpha = 0.08 + 0.6 * (1 - abs(phi) / big)
        ax.plot(xy[:, 0], xy[:, 1], color="C1", lw=0.5, alpha=alpha)
    if method == "shaper":  # the working circles of the cutting mesh, touching at the pitch point
        t = prof.tool
        _circle(ax, t.rw0, center=(0.0, t.a0), color="0.5", lw=0.6, ls="--")
        _circle(ax, t.rw, color="0.5", lw=0.6, ls="--")
    cut = prof.cutter if method == "shaper" else None
    p = gear.outline(tolerance / 10, angle=90 - 180 / gear.teeth, cutter=cut)
    _draw(ax, p, color="k", lw=1.2)
    ra, rf = prof.ra, prof.rf
    if gear.internal:
        half = min(0.45 * ra, 1.7 * math.pi * gear.transverse_module)
        ax.set_xlim(-half, half)
        ax.set_ylim(ra - 2 * m, rf + 1.5 * m)
    else:
        ax.set_xlim(-0.45 * ra, 0.45 * ra)
        ax.set_ylim(rf - 2 * m, ra + m)
    ax.set_aspect("equal")
    kind = "internal z" if gear.internal else "z"
    ax.set_title(f"{name}, {kind} = {gear.teeth}, x = {gear.profile_shift:g}: "
                 f"{len(phis)} tool positions")  # fmt: skip
    return fig
