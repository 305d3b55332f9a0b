"""Generate the figure of ``docs/forces.md``: the forces of a pair and of a planetary stage.

Usage: ``python docs/make_forces_figures.py [output_dir]`` (default: ``docs/images``).
Left: the 20/40, m = 5 pair of Ozols section 11-2 under 100 N m on the pinion
(:func:`gears.figures.forces.pair_forces_figure`). Right: the 20/31/82 stage with four
unequally spaced planets under 120 N m at 1500 rpm on the sun (:meth:`trains.Planetary.loads`,
:meth:`trains.TrainLoads.figure` on :meth:`trains.Planetary.outlines`).
"""

from __future__ import annotations

import sys
from pathlib import Path

from gears import Gear, GearPair
from gears.figures.forces import pair_forces_figure
from trains import Planetary

FIGURES = ("forces.png",)


def main(out: Path) -> list[Path]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out.mkdir(parents=True, exist_ok=True)
    fig, (left, right) = plt.subplots(1, 2, figsize=(8, 4.2))  # readable at the page width
    pair = GearPair(Gear(20, 5), Gear(40, 5))
    pair_forces_figure(pair.forces(100.0), pair.outlines(tolerance=0.05), ax=left)
    stage = Planetary(20, 31, 82, n_planets=4, module=2)
    loads = stage.loads(120.0, 1500.0, face_width=20, load_sharing_factor=1.0)
    loads.figure(stage.outlines(tolerance=0.05), ax=right)
    fig.tight_layout()
    path = out / FIGURES[0]
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return [path]


if __name__ == "__main__":
    target = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).with_name("images")
    for p in main(target):
        print(p)
