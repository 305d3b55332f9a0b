"""Regenerate the figures of docs/contact.md: ``python docs/make_contact_figures.py``.

* ``contact_te.png``: the loaded and unloaded transmission error and the mesh stiffness of a
  spur pair over one mesh cycle, unmodified and with tip relief, from ``GearPair.contact``;
* ``contact_pattern.png``: the contact pattern (Hertzian pressure over the flank) of the same
  pair with a misalignment of 10 um across the face, and crowned;
* ``contact_harris.png``: the Harris map of the same pair, ``GearPair.harris``;
* ``contact_planetary.png``: a planetary stage's sun-planet transmission error, one mesh and the
  three planets' net, sequentially phased (as the stage is) and in phase, with its harmonics
  (``Planetary.contact``, ``trains.planetary.contact.phased_sum``);
* ``contact_best.png``: the design search's peak to peak and K_Hbeta over tip relief and
  crowning under a tilt (``GearPair.best_modification``).
"""

import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from gears import Gear, GearPair
from gears.contact.modification import Modification
from gears.contact.plot import pattern_figure, te_figure

OUT = pathlib.Path(__file__).resolve().parent / "images"


def pair(modification=None):
    return GearPair(Gear(20, 3, face_width=30, modification=modification),
                    Gear(50, 3, face_width=30, modification=modification))  # fmt: skip


def te():
    fig, axes = plt.subplots(2, 1, figsize=(7.5, 7.5), sharex=True)
    te_figure(pair().contact(300), ax=axes[0])
    te_figure(pair(Modification(tip_relief=0.017)).contact(300), ax=axes[1])
    axes[0].set_title("unmodified: " + axes[0].get_title(), fontsize=8)
    axes[1].set_title("tip relief 17 um: " + axes[1].get_title(), fontsize=8)
    fig.tight_layout()
    return fig


def pattern():
    fig, axes = plt.subplots(2, 1, figsize=(7, 8))
    pattern_figure(pair().contact(300, misalignment=0.01), ax=axes[0])
    crowned = GearPair(Gear(20, 3, face_width=30, modification=Modification(crowning=0.01)),
                       Gear(50, 3, face_width=30))  # fmt: skip
    pattern_figure(crowned.contact(300, misalignment=0.01), ax=axes[1])
    axes[0].set_title("misaligned 10 um: " + axes[0].get_title(), fontsize=8)
    axes[1].set_title("and crowned 10 um: " + axes[1].get_title(), fontsize=8)
    fig.tight_layout()
    return fig


def harris():
    return pair().harris(np.linspace(20, 500, 25), np.linspace(0, 0.04, 41)).plot()


def planetary():
    from trains import Planetary
    from trains.planetary.contact import harmonic_amplitudes, phased_sum

    c = Planetary(19, 29, 77, n_planets=3, module=2).contact(40, face_width=20)
    mesh = c.meshes["sun-planet"]
    single = mesh.transmission_error
    cycle = np.arange(single.size) / single.size
    sequential = c.net_transmission_error("sun-planet")
    in_phase = phased_sum(single, np.zeros(3))
    fig, axes = plt.subplots(1, 2, figsize=(8, 3.4))
    axes[0].plot(cycle, single, label="one sun-planet mesh")
    axes[0].plot(cycle, sequential, label="net, sequential (as built: 19 / 3)")
    axes[0].plot(cycle, in_phase, "--", label="net, in phase")
    axes[0].set_xlabel("mesh cycle")
    axes[0].set_ylabel("transmission error, um")
    axes[0].legend(fontsize=7)
    orders = np.arange(1, 7)
    width = 0.27
    for k, (label, values) in enumerate((("one mesh", single), ("net, sequential", sequential),
                                         ("net, in phase", in_phase))):  # fmt: skip
        axes[1].bar(orders + (k - 1) * width, harmonic_amplitudes(values, orders), width,
                    label=label)  # fmt: skip
    axes[1].set_xlabel("mesh order")
    axes[1].set_ylabel("amplitude, um")
    axes[1].legend(fontsize=7)
    fig.suptitle("Planetary(19, 29, 77, n_planets=3, module=2), 40 N m on the sun, b 20 mm",
                 fontsize=9)  # fmt: skip
    fig.tight_layout()
    return fig


def best():
    s = pair().best_modification(300, misalignment=0.02, tip_reliefs=np.linspace(0, 0.04, 41),
                                 crownings=np.linspace(0, 0.03, 16), max_K_Hbeta=1.3)  # fmt: skip
    fig, ax = plt.subplots(figsize=(7, 4.5))
    extent = (0, 30, 0, 40)
    im = ax.imshow(s.peak_to_peak, origin="lower", aspect="auto", extent=extent, cmap="viridis")
    fig.colorbar(im, ax=ax, label="transmission error peak to peak, um")
    cs = ax.contour(np.linspace(0, 30, 16), np.linspace(0, 40, 41), s.K_Hbeta, colors="w",
                    linewidths=0.8)  # fmt: skip
    ax.clabel(cs, fontsize=7, fmt="K_Hbeta %.2f")
    ax.plot(s.crowning * 1000, s.tip_relief * 1000, "r*", markersize=12,
            label="best with K_Hbeta <= 1.3")  # fmt: skip
    ax.set_xlabel("crowning C_b on gear 1, um")
    ax.set_ylabel("tip relief C_a on both gears, um")
    ax.set_title("spur 20/50 m 3 b 30, 300 N m, tilt 20 um", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def main():
    OUT.mkdir(exist_ok=True)
    for name, make in (("contact_te.png", te), ("contact_pattern.png", pattern),
                       ("contact_harris.png", harris), ("contact_planetary.png", planetary),
                       ("contact_best.png", best)):  # fmt: skip
        fig = make()
        fig.savefig(OUT / name, dpi=110)
        plt.close(fig)
        print("wrote", OUT / name)


if __name__ == "__main__":
    main()
