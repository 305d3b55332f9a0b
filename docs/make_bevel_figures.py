"""Draw the figures of docs/bevel.md from the library's own bevel teeth, solids and scenes.

- ``bevel_pair.png``: KHK's Gleason pair 20/40 (m 3, b 22) in mesh (``BevelPair.scene``);
- ``bevel_section.png``: the pinion's tooth space on its outer spherical section: the octoid
  (the envelope of the crown gear's plane flank), the spherical involute, and the crown gear's
  positions of the simulated cutting (``gears.bevel.crown``) in the gnomonic plane; beside it, the
  octoid minus the spherical involute along the flank of both gears, in micrometres;
- ``bevel_differential.png`` and ``bevel_differential.gif``: Ozols' car differential 16/10 with
  real teeth (``trains.Differential``), standing and turning through a corner.

Rendered by ``gears.solid.render`` (orthographic, back faces culled, flat shading) and matplotlib.
Run: ``python docs/make_bevel_figures.py [pair] [section] [differential]`` (writes
``docs/images/bevel_*``; all of them by default).
"""

from __future__ import annotations

import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from gears import BevelPair
from gears.bevel.crown import _tool, crown_positions, gnomonic
from gears.bevel.spherical import _rotate, polar
from gears.solid.render import Camera, render_image, scene_parts
from trains import Differential

HERE = pathlib.Path(__file__).resolve().parent
IMAGES = HERE / "images"
EZ = np.array([0.0, 0.0, 1.0])


def pair_picture() -> None:
    pair = BevelPair.gleason(20, 40, module=3, face_width=22)
    parts = scene_parts(pair.scene(angle=4.0, tolerance=0.02))
    render_image(IMAGES / "bevel_pair.png", parts, Camera(40.0, 160.0), size=520)


def section_picture() -> None:
    octoid = BevelPair(20, 40, module=3, face_width=22, clearance="tapered")
    invol = BevelPair(20, 40, module=3, face_width=22, clearance="tapered",
                      profile="spherical_involute")  # fmt: skip
    r_e = octoid.cone_distance
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(8, 4), gridspec_kw={"width_ratios": [1.1, 1]})
    # (a) the pinion's tooth space on the sphere R_e, gnomonic plane about the pitch generator
    tooth = octoid.g1.tooth()
    tip = math.radians(octoid.g1.face_angle)
    tool = _tool(tooth, 2e-4, tip - tooth.delta + 0.05)
    for phi in crown_positions(tooth, 0.02 / r_e, tip)[::6]:
        y = _rotate(_rotate(tool, tooth.ec, tooth.sigma * phi), EZ, -phi)
        xy = gnomonic(tooth, y) * r_e * [1, -1]  # tips up
        ax.plot(xy[:, 0], xy[:, 1], color="0.75", lw=0.5)
    for pair, style, label in ((octoid, "-", "octoid (crown gear with plane flanks)"),
                               (invol, "--", "spherical involute")):  # fmt: skip
        t = pair.g1.tooth()
        half = t.conical_half(1e-6, tip)
        xy = gnomonic(t, half.y) * r_e * [1, -1]
        both = np.concatenate([xy[::-1] * [-1, 1], xy])
        ax.plot(both[:, 0], both[:, 1], style, lw=1.6, label=label)
    az = np.linspace(-math.pi / 20, math.pi / 20, 200)
    from gears.bevel.spherical import direction

    rim = gnomonic(tooth, direction(tip, az)) * r_e * [1, -1]
    ax.plot(rim[:, 0], rim[:, 1], ":", color="k", lw=0.8, label="tip circle")
    ax.set_aspect("equal")
    ax.set_xlim(-6.5, 6.5)
    ax.set_ylim(-4.5, 6.0)
    ax.set_xlabel("along the pitch circle, mm (gnomonic, sphere R_e = 67.08 mm)")
    ax.set_ylabel("away from the pinion's axis, mm")
    ax.set_title("pinion z = 20: tooth space and crown gear positions")
    ax.legend(loc="lower center", bbox_to_anchor=(0.5, -0.36), ncol=2, fontsize=8, frameon=False)
    # (b) octoid minus spherical involute along the flank, both gears, at R_e
    for go, gs in zip(octoid.gears, invol.gears, strict=True):
        to, ts = go.tooth(), gs.tooth()
        form = max(float(polar(t.flank_points(t.form[1]))[0]) for t in (to, ts))
        theta = np.linspace(form + 1e-4, math.radians(go.face_angle), 300)
        eta_o = np.array([polar(to.flank_points(to.flank_at_polar(a)))[1] for a in theta])
        eta_s = np.array([polar(ts.flank_points(ts.flank_at_polar(a)))[1] for a in theta])
        diff = (eta_o - eta_s) * np.sin(theta) * r_e * 1000.0
        height = (theta - math.radians(go.root_angle)) * r_e
        bx.plot(height, diff, label=f"z = {go.teeth} (pitch cone at {go.dedendum:.2f} mm)")
    bx.axhline(0.0, color="k", lw=0.6)
    bx.set_xlabel("height above the root on the sphere R_e, mm")
    bx.set_ylabel("octoid - spherical involute, um (along the pitch circle)")
    bx.set_title("they touch at the pitch cone, part by 3 um at root and tip")
    bx.legend(loc="lower center", bbox_to_anchor=(0.5, -0.3), fontsize=8, frameon=False)
    fig.tight_layout()
    fig.savefig(IMAGES / "bevel_section.png", dpi=90)
    plt.close(fig)


def differential_pictures() -> None:
    diff = Differential(side=16, pinion=10, module=3, gleason=True)
    sc = diff.scene(angle=6.0, tolerance=0.02)
    render_image(IMAGES / "bevel_differential.png", scene_parts(sc), Camera(20.0, -35.0), size=480)
    diff.animate(IMAGES / "bevel_differential.gif", frames=30, left=0.8, right=1.2,
                 tolerance=0.06, fps=10, size=320)  # fmt: skip


if __name__ == "__main__":
    import sys

    IMAGES.mkdir(exist_ok=True)
    todo = set(sys.argv[1:]) or {"pair", "section", "differential"}
    if "pair" in todo:
        pair_picture()
    if "section" in todo:
        section_picture()
    if "differential" in todo:
        differential_pictures()
    print("wrote", ", ".join(sorted(p.name for p in IMAGES.glob("bevel_*"))))
