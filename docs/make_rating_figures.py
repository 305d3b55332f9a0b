"""Regenerate the figures of docs/rating.md: ``python docs/make_rating_figures.py``.

* ``rating_root.png``: the root of an external pinion (30 deg tangents) and of a ring gear
  (60 deg tangents) on their real outlines, with s_Fn, rho_F, the load at d_en and h_Fe, as
  :func:`gears.rating.root.measure_root` measures them;
* ``rating_torque.png``: S_H and S_F of both gears of a pair against the torque, from
  :func:`gears.rate_pairs` over an array of torques.
"""

import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from gears import Gear, GearPair, rate_pairs
from gears.rating.capacity import load_diameters
from gears.rating.root import measure_root

OUT = pathlib.Path(__file__).resolve().parent / "images"


def _tooth_frame(gear, pair):
    """The gear's outline turned into the tooth frame of gears.rating.root (tooth 0's centre line on
    +y, pointing to its tip) and the measured root form."""
    poly = gear.outline(tolerance=gear.module / 2000)
    ring = poly.interiors[0] if gear.internal else poly.exterior
    xy = np.asarray(ring.coords)
    x, y = (-xy[:, 1], -xy[:, 0]) if gear.internal else (-xy[:, 1], xy[:, 0])
    d_en = load_diameters(pair)[1 if gear.internal else 0]
    return x, y, measure_root(gear, d_en)


def _draw_root(ax, gear, pair, title):
    x, y, r = _tooth_frame(gear, pair)
    px, py = r.tangent_point
    lx, ly = r.load_point
    ay = r.load_axis[1]
    m = gear.module
    keep = (np.abs(x) < 2.2 * m) & (np.abs(y - py) < 3.2 * m)
    ax.plot(np.where(keep, x, np.nan), np.where(keep, y, np.nan), color="0.2", lw=1.2)
    t = math.radians(r.tangent)
    for sign in (1, -1):  # the tangents at their angle to the centre line, both flanks
        s = np.linspace(-1.2 * m, 1.2 * m, 2)
        ax.plot(sign * (px + s * math.sin(t)), py + s * math.cos(t), color="tab:red", lw=0.9)
        ax.plot([sign * px], [py], "o", color="tab:red", ms=4)
    ax.annotate("", (px, py), (-px, py), arrowprops=dict(arrowstyle="<->", color="tab:red"))
    ax.text(0, py - 0.25 * m, f"s_Fn = {r.s_Fn:.2f} mm", ha="center", va="top", color="tab:red")
    # the fillet's osculating circle: its centre lies in the space, along the normal at P
    cx, cy = px + r.rho_F * math.cos(t), py + r.rho_F * math.sin(t)
    a = np.linspace(0, 2 * math.pi, 200)
    ax.plot(cx + r.rho_F * np.cos(a), cy + r.rho_F * np.sin(a), color="tab:orange", lw=0.7,
            ls="--")  # fmt: skip
    ax.text(cx, cy, f"rho_F = {r.rho_F:.2f}", color="tab:orange", ha="center", va="center",
            fontsize=8)  # fmt: skip
    # the load at d_en along the flank normal, to the centre line
    ax.plot([lx, 0], [ly, ay], color="tab:blue", lw=1.2)
    ax.plot([lx], [ly], "o", color="tab:blue", ms=4)
    tail = (lx + 0.6 * m * math.cos(r.alpha_Fen), ly + 0.6 * m * math.sin(r.alpha_Fen))
    ax.annotate("F_n", (lx, ly), tail, arrowprops=dict(arrowstyle="->", color="tab:blue"),
                color="tab:blue")  # fmt: skip
    ax.plot([-1.9 * m, 1.9 * m], [py, py], color="0.6", lw=0.6, ls=":")
    ax.plot([-1.9 * m, 0], [ay, ay], color="0.6", lw=0.6, ls=":")
    ax.annotate("", (-1.7 * m, ay), (-1.7 * m, py), arrowprops=dict(arrowstyle="<->"))
    ax.text(-1.75 * m, (ay + py) / 2, f"h_Fe = {r.h_Fe:.2f} mm", rotation=90, ha="right",
            va="center")  # fmt: skip
    ax.axvline(0, color="0.6", lw=0.6, ls="-.")
    yf, ys, _ = r.factors(gear.module)
    ax.set_title(f"{title}\n{r.tangent:g} deg tangents: Y_F = {yf:.3f}, Y_S = {ys:.3f}", fontsize=9)
    ax.set_aspect("equal")
    ax.set_xlabel("mm (tooth frame: centre line up)")


def root_figure():
    pinion = Gear(17, 2, face_width=20)
    pair = GearPair(pinion, Gear(60, 2, face_width=20))
    ring = Gear(60, 2, internal=True, face_width=20)
    internal = GearPair(Gear(17, 2, face_width=20), ring)
    fig, (a, b) = plt.subplots(1, 2, figsize=(8, 4.4))  # readable at the page width
    _draw_root(a, pair.mounted[0], pair, "external pinion z = 17, m 2, rack-cut (exact envelope)")
    _draw_root(b, internal.mounted[1], internal, "ring z = 60, m 2, shaper-cut (exact envelope)")
    fig.tight_layout()
    return fig


def torque_figure():
    torque = np.geomspace(20, 2000, 120)
    r = rate_pairs(19, 61, 3, 30, torque, 1450, errors="mask")
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.loglog(torque, r.S_H1, label="S_H1 (pinion, pitting)", color="tab:blue")
    ax.loglog(torque, r.S_H2, label="S_H2 (wheel, pitting)", color="tab:blue", ls="--")
    ax.loglog(torque, r.S_F1, label="S_F1 (pinion, root)", color="tab:red")
    ax.loglog(torque, r.S_F2, label="S_F2 (wheel, root)", color="tab:red", ls="--")
    ax.axhline(1.0, color="tab:blue", lw=0.6, ls=":")
    ax.axhline(1.4, color="tab:red", lw=0.6, ls=":")
    ax.set_xlabel("torque on the pinion T1, N m")
    ax.set_ylabel("safety factor")
    ax.set_title("19/61, m 3, b 30, 1450 rpm, case-carburized, 20 000 h", fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    return fig


def main():
    OUT.mkdir(exist_ok=True)
    for name, fig in (("rating_root.png", root_figure()), ("rating_torque.png", torque_figure())):
        fig.savefig(OUT / name, dpi=110)
        plt.close(fig)
        print("wrote", OUT / name)


if __name__ == "__main__":
    main()
