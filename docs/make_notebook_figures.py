"""Write the pictures of docs/notebooks.md: what a notebook shows of gears, pairs and stages.

Each file is the object's own ``_repr_svg_()`` text, the very SVG Jupyter displays.

Run: ``python docs/make_notebook_figures.py [out_dir]`` (default ``docs/images``; writes
``notebook_gear.svg``, ``notebook_pair.svg``, ``notebook_ring_pair.svg``,
``notebook_stage.svg``, ``notebook_bevel.svg``, ``notebook_differential.svg``).
"""

from __future__ import annotations

import pathlib
import sys

from gears import BevelPair, Gear, GearPair
from trains import Differential, Planetary

HERE = pathlib.Path(__file__).resolve().parent


def main(out: pathlib.Path) -> list[pathlib.Path]:
    pinion = Gear(12, 3, profile_shift=0.6)
    shown = {
        "gear": pinion,
        "pair": GearPair(pinion, Gear(24, 3, profile_shift=0.36)),
        "ring_pair": GearPair(
            Gear(20, 2, profile_shift=0.3), Gear(80, 2, internal=True, profile_shift=-0.5)
        ),
        "stage": Planetary(18, 45, 108, n_planets=3, module=2),
        "bevel": BevelPair(20, 40, module=3, face_width=20),
        "differential": Differential(16, 10, module=3, gleason=True),
    }
    written = []
    for name, obj in shown.items():
        path = out / f"notebook_{name}.svg"
        path.write_text(obj._repr_svg_())
        written.append(path)
    return written


if __name__ == "__main__":
    folder = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else HERE / "images"
    for path in main(folder):
        print(f"wrote {path}")
