"""Generate the figure of ``docs/planetary.md``: the three conditions of a planetary stage.

Usage: ``python docs/make_planetary_figures.py [output_dir]`` (default: ``docs/images``).
Draws the course example 18/45/108 with three planets (lectures §4.3): working pitch circles
(coaxiality), planet tip circles and the neighbour gap (neighbour), and the assembly ticks
360/(z_s + z_r) with the planet positions on them (assembly).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

from trains import Planetary

FIGURES = ("planetary_conditions.png",)


def planetary_conditions(path: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle

    stage = Planetary(18, 45, 108, n_planets=3, module=2)
    place = stage.placement()
    asm = stage.assembly()
    sp = stage.meshes["sun-planet"]
    a = sp.center_distance
    d_sun, d_planet = sp.working_diameters
    tip = stage.planet.tip_diameter
    ring_tip = stage.ring.tip_diameter
    fig, ax = plt.subplots(figsize=(7.5, 7.5))
    ax.add_patch(Circle((0, 0), d_sun / 2, fill=False, color="tab:blue", lw=1.5,
                        label="working pitch circles (coaxiality: a_w equal)"))  # fmt: skip
    ax.add_patch(Circle((0, 0), a + d_planet / 2, fill=False, color="tab:blue", lw=1.5))
    ax.add_patch(Circle((0, 0), ring_tip / 2, fill=False, color="0.5", ls=":", lw=1))
    centres = []
    for i, th in enumerate(place.planet_angles):
        t = math.radians(th)
        cx, cy = a * math.cos(t), a * math.sin(t)
        centres.append((cx, cy))
        ax.add_patch(Circle((cx, cy), d_planet / 2, fill=False, color="tab:blue", lw=1.5))
        label = "planet tip circles (neighbour)" if i == 0 else None
        ax.add_patch(Circle((cx, cy), tip / 2, fill=False, color="tab:red", ls="--", lw=1.2,
                            label=label))  # fmt: skip
        ax.plot([0, cx], [0, cy], color="0.3", lw=0.8)
    (x0, y0), (x1, y1) = centres[0], centres[1]
    ax.plot([x0, x1], [y0, y1], color="tab:red", lw=1)
    gap = stage.check()["neighbour"]
    ax.annotate(f"2 a_w sin(pi/3) = {math.dist(centres[0], centres[1]):.1f} mm\n"
                f"vs d_a = {tip:.1f} mm (+ clearance): margin {gap.margin:+.1f} mm",
                ((x0 + x1) / 2, (y0 + y1) / 2), xytext=(0.98, 0.02), textcoords="axes fraction",
                ha="right", va="bottom", fontsize=8, color="tab:red",
                bbox={"boxstyle": "round", "fc": "white", "ec": "tab:red", "alpha": 0.95},
                arrowprops={"arrowstyle": "->", "color": "tab:red"})  # fmt: skip
    r_tick = ring_tip / 2 + 10
    for j in range(asm.ticks):
        t = 2 * math.pi * j / asm.ticks
        ax.plot([r_tick * math.cos(t), (r_tick + 4) * math.cos(t)],
                [r_tick * math.sin(t), (r_tick + 4) * math.sin(t)], color="tab:green", lw=0.6,
                label="assembly ticks 360/(z_s + z_r)" if j == 0 else None)  # fmt: skip
    for th in place.planet_angles:
        t = math.radians(th)
        ax.plot(
            [r_tick * math.cos(t), (r_tick + 12) * math.cos(t)],
            [r_tick * math.sin(t), (r_tick + 12) * math.sin(t)],
            color="tab:green",
            lw=2.5,
        )
    ax.set_title(f"sun 18, planet 45, ring 108, m = 2, 3 planets: T = {asm.ticks} ticks, "
                 f"{asm.ticks // 3} per planet", fontsize=10)  # fmt: skip
    lim = r_tick + 16
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_aspect("equal")
    ax.legend(loc="lower left", fontsize=8)
    ax.set_xlabel("mm")
    fig.tight_layout()
    fig.savefig(path, dpi=100, metadata={"Software": None})
    plt.close(fig)
    return path


def main(out: Path) -> list[Path]:
    out.mkdir(parents=True, exist_ok=True)
    return [planetary_conditions(out / FIGURES[0])]


if __name__ == "__main__":
    target = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).parent / "images"
    for p in main(target):
        print(p)
