"""Draw the figures of docs/noncircular.md from the library's own non-circular and cycloidal
gearing.

- ``noncircular_pairs.png``: Litvin's elliptical pair (A 40, e 0.2, module 2) in mesh with its
  teeth cut by the rolled rack and its pitch curves; an oval pair of 2 and 3 lobes;
- ``noncircular_law.png``: the elliptical pair's ratio over a turn, and the transmission error
  of its cut teeth against the law (the arc at gear 2's pitch curve, micrometres);
- ``noncircular_cycloidal.png``: a cycloidal drive of 12 pins (disc of 11 lobes) and the force
  on each pin at 10 N m, by the equal-rigidity sharing;
- ``noncircular_pair.gif``: the elliptical pair turning, gear 2 at its varying speed.

Run: ``python docs/make_noncircular_figures.py [pairs] [law] [cycloidal] [animation]`` (writes
``docs/images/noncircular_*``; all of them by default).
"""

from __future__ import annotations

import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from gears import NonCircularPair
from trains import CycloidalDrive

HERE = pathlib.Path(__file__).resolve().parent
IMAGES = HERE / "images"


def _poly(ax, poly, **kw):
    ax.fill(*poly.exterior.xy, **kw)


def pairs_figure(out: pathlib.Path = IMAGES) -> pathlib.Path:
    fig, axes = plt.subplots(1, 2, figsize=(8.0, 3.6))  # readable at the page width
    p = NonCircularPair.elliptical(40.0, 0.2, module=2.0)
    one, two = p.outlines(30.0, 0.02)
    c1, c2 = p.pitch_curves(720, 30.0)
    ax = axes[0]
    _poly(ax, one, color="tab:blue", alpha=0.55, lw=0)
    _poly(ax, two, color="tab:orange", alpha=0.55, lw=0)
    for c in (c1, c2):
        ax.plot(*np.vstack([c, c[:1]]).T, color="k", lw=0.6, ls="--")
    ax.plot([0, p.center_distance], [0, 0], "k+", ms=10)
    ax.set_title("elliptical pair, A 40, e 0.2, 40 teeth each")
    q = NonCircularPair.lobed(40.0, 0.15, (2, 3))
    ax = axes[1]
    for phi, alpha in ((0.0, 1.0), (40.0, 0.35)):
        c1, c2 = q.pitch_curves(720, phi)
        ax.plot(*np.vstack([c1, c1[:1]]).T, color="tab:blue", alpha=alpha)
        ax.plot(*np.vstack([c2, c2[:1]]).T, color="tab:orange", alpha=alpha)
    ax.plot([0, q.center_distance], [0, 0], "k+", ms=10)
    ax.set_title(f"pitch curves of 2 and 3 lobes, a = {q.center_distance:.2f} mm")
    for ax in axes:
        ax.set_aspect("equal")
        ax.axis("off")
    fig.tight_layout()
    path = out / "noncircular_pairs.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def law_figure(out: pathlib.Path = IMAGES) -> pathlib.Path:
    p = NonCircularPair.elliptical(40.0, 0.2, module=2.0)
    phi = np.linspace(0.0, 360.0, 181)
    te = p.transmission_error(phi, tolerance=0.005)
    fig, (a, b) = plt.subplots(1, 2, figsize=(8.0, 3.2))  # readable at the page width
    a.plot(phi, p.ratio(phi), color="tab:blue")
    a.set_xlabel("input angle, deg")
    a.set_ylabel("ratio omega1/omega2")
    a.set_title("the elliptical pair's law")
    b.plot(phi, 1000 * np.radians(te) * p.radius2(phi), color="tab:red")
    b.axhline(5.0, color="k", lw=0.6, ls=":")
    b.axhline(-5.0, color="k", lw=0.6, ls=":")
    b.set_xlabel("input angle, deg")
    b.set_ylabel("transmission error, um of arc")
    b.set_title("cut teeth against the law (tolerance 5 um)")
    fig.tight_layout()
    path = out / "noncircular_law.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def cycloidal_figure(out: pathlib.Path = IMAGES) -> pathlib.Path:
    d = CycloidalDrive(pins=12, pin_radius=3.0, eccentricity=1.5, pin_circle_radius=40.0)
    angle = 20.0
    disc, pins = d.outlines(angle, 0.01)
    forces = d.contact_forces(10_000.0, angle)
    fig, ax = plt.subplots(figsize=(5.2, 5.2))
    _poly(ax, disc, color="tab:blue", alpha=0.5, lw=0)
    for pin, f in zip(pins.geoms, forces, strict=True):
        _poly(ax, pin, color="tab:gray")
        if f > 0:
            x, y = pin.centroid.x, pin.centroid.y
            t = math.radians(angle)
            px, py = d.eccentricity * d.pins * math.cos(t), d.eccentricity * d.pins * math.sin(t)
            u = np.array([x - px, y - py]) / math.hypot(x - px, y - py)
            ax.arrow(x, y, *(u * f / 20.0), width=0.3, color="tab:red")
            ax.annotate(f"{f:.0f} N", (x, y), xytext=(x + 8 * u[0], y + 8 * u[1]), fontsize=7)
    ax.set_title("12 pins, 11 lobes, 10 N m: pin forces")
    ax.set_aspect("equal")
    ax.axis("off")
    fig.tight_layout()
    path = out / "noncircular_cycloidal.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def animation(out: pathlib.Path = IMAGES) -> pathlib.Path:
    p = NonCircularPair.elliptical(40.0, 0.2, module=2.0)
    return p.animate(out / "noncircular_pair.gif", frames=48, fps=12.0, tolerance=0.05)


FIGURES = {
    "pairs": pairs_figure,
    "law": law_figure,
    "cycloidal": cycloidal_figure,
    "animation": animation,
}


def main(out: pathlib.Path = IMAGES, names=None) -> list[pathlib.Path]:
    return [FIGURES[n](out) for n in (names or FIGURES)]


if __name__ == "__main__":
    for path in main(names=sys.argv[1:] or None):
        print(path)
