"""Regenerate the figures of docs/profiles.md: ``python docs/make_profile_figures.py``.

(The speed-versus-accuracy chart comes from ``tests/benchmarks/bench_profile.py``.)
"""

import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

from gears import Gear, GearPair
from gears.cutting.cutter import ShaperCutter
from gears.figures.plot import generation_figure, pair_figure, tooth_figure

OUT = pathlib.Path(__file__).resolve().parent / "images"


def main():
    OUT.mkdir(exist_ok=True)
    figures = {
        "profile_generation.png": generation_figure(Gear(8, 1), 1e-2),
        "profile_tooth_undercut.png": tooth_figure(Gear(8, 1)),
        "profile_tooth_shifted.png": tooth_figure(Gear(12, 3, profile_shift=0.6)),
        "profile_pair.png": pair_figure(
            GearPair(Gear(12, 3, profile_shift=0.6), Gear(24, 3, profile_shift=0.36))
        ),
        "profile_internal_pair.png": pair_figure(
            GearPair(Gear(20, 2, profile_shift=0.5), Gear(80, 2, internal=True, profile_shift=-0.5))
        ),
        "profile_shaper_internal.png": generation_figure(
            Gear(40, 1, internal=True, profile_shift=-0.3),
            1e-2,
            method="shaper",
            cutter=ShaperCutter(20),
        ),
    }
    for name, fig in figures.items():
        fig.savefig(OUT / name, dpi=110, bbox_inches="tight")  # no empty margins
        plt.close(fig)
        print("wrote", OUT / name)


if __name__ == "__main__":
    main()
