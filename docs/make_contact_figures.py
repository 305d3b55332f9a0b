"""Regenerate the figures of docs/contact.md: ``python docs/make_contact_figures.py``.

* ``contact_te.png``: the loaded and unloaded transmission error and the mesh stiffness of a
  spur pair over one mesh cycle, unmodified and with tip relief, from ``GearPair.contact``;
* ``contact_pattern.png``: the contact pattern (Hertzian pressure over the flank) of the same
  pair with a misalignment of 10 um across the face, and crowned;
* ``contact_harris.png``: the Harris map of the same pair, ``GearPair.harris``.
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


def main():
    OUT.mkdir(exist_ok=True)
    for name, make in (("contact_te.png", te), ("contact_pattern.png", pattern),
                       ("contact_harris.png", harris)):  # fmt: skip
        fig = make()
        fig.savefig(OUT / name, dpi=110)
        plt.close(fig)
        print("wrote", OUT / name)


if __name__ == "__main__":
    main()
