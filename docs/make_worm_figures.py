"""Draw the figures of docs/worm.md from the library's own worm formulas.

- ``worm_efficiency.png``: the efficiency of a worm pair over its lead angle with the worm
  driving (Ozols (14.15)) and with the wheel driving (14.18), for three friction coefficients;
  below zero the wheel cannot drive (self-locking); the best lead angles (14.16) marked;
- ``worm_flanks.png``: the four flank forms of DIN 3975 in the worm's axial section (z1 4,
  q 8, m 5: a steep lead shows the difference), as the axial half thickness less ZA's straight
  line, in micrometres.

Run: ``python docs/make_worm_figures.py [efficiency] [flanks]`` (writes ``docs/images/worm_*``;
all of them by default).
"""

from __future__ import annotations

import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from gears.worm.crossed import reduced_friction_angle
from gears.worm.flank import axial_half_thickness
from gears.worm.geometry import best_lead_angle, worm_efficiency, worm_geometry

HERE = pathlib.Path(__file__).resolve().parent
IMAGES = HERE / "images"


def efficiency_figure(out: pathlib.Path = IMAGES) -> pathlib.Path:
    gamma = np.linspace(0.5, 60.0, 600)
    fig, ax = plt.subplots(figsize=(7.0, 4.2))
    for mu, colour in ((0.03, "tab:blue"), (0.06, "tab:orange"), (0.1, "tab:red")):
        phi = float(reduced_friction_angle(mu, 20.0))
        ax.plot(gamma, worm_efficiency(gamma, phi), color=colour, label=f"worm drives, mu {mu:g}")
        ax.plot(gamma, worm_efficiency(gamma, phi, "wheel"), color=colour, ls="--",
                label=f"wheel drives, mu {mu:g}")  # fmt: skip
        g_best = float(best_lead_angle(phi))
        ax.plot([g_best], [float(worm_efficiency(g_best, phi))], "o", color=colour)
    ax.axhspan(-0.8, 0.0, color="0.9")
    ax.text(12, -0.1, "self-locking: the wheel cannot drive", ha="left", va="center")
    ax.set_ylim(-0.8, 1.0)
    ax.set_xlim(0, 60)
    ax.set_xlabel("lead angle gamma, deg")
    ax.set_ylabel("efficiency")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=2, loc="lower right", framealpha=0.95)
    fig.tight_layout()
    path = out / "worm_efficiency.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def flanks_figure(out: pathlib.Path = IMAGES) -> pathlib.Path:
    z1, m, q = 4, 5.0, 8.0
    g = worm_geometry(z1, 40, m, q)
    r = np.linspace(float(g.worm_root_diameter) / 2, float(g.worm_tip_diameter) / 2, 200)
    za = axial_half_thickness("ZA", r, z1, m, q, pressure_angle=float(g.axial_pressure_angle))
    fig, ax = plt.subplots(figsize=(6.0, 3.8))
    for flank in ("ZN", "ZI", "ZK"):
        h = axial_half_thickness(flank, r, z1, m, q)
        ax.plot(1000 * (h - za), r, label=flank)
    ax.axvline(0.0, color="k", lw=0.8, label="ZA (straight)")
    ax.axhline(float(g.worm_diameter) / 2, color="0.6", ls=":", lw=0.8)
    ax.set_xlabel("axial half thickness less ZA's, um")
    ax.set_ylabel("radius, mm")
    ax.set_title(f"z1 {z1}, q {q:g}, m_x {m:g}: gamma {float(g.lead_angle):.2f} deg", fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    path = out / "worm_flanks.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def main(out: pathlib.Path = IMAGES, which: tuple[str, ...] = ("efficiency", "flanks")) -> list:
    out.mkdir(parents=True, exist_ok=True)
    made = []
    if "efficiency" in which:
        made.append(efficiency_figure(out))
    if "flanks" in which:
        made.append(flanks_figure(out))
    return made


if __name__ == "__main__":
    print(*main(which=tuple(sys.argv[1:]) or ("efficiency", "flanks")), sep="\n")
