"""Generate the figure of ``docs/design_search.md``, "Design to a load": safety against volume.

Usage: ``python docs/make_search_figures.py [output_dir]`` (default: ``docs/images``).
Every pair of a 3.2:1 (+- 2 %) search that carries 60 N m at 1500 rpm for 20 000 h with
S_H >= 1.1 and S_F >= 1.5 (modules 1.5 ... 3 mm, each face width of 8 ... 40 mm a candidate of
its own) as grey points, and the Pareto fronts of (volume, -S_H) and (volume, -S_F) drawn over
them (:func:`gears.search.pairs` with two objectives).
"""

from __future__ import annotations

import sys
from pathlib import Path

from gears import search

FIGURES = ("search_load_front.png",)

SPACE = dict(
    ratio=3.2, ratio_tolerance=0.02, module=[1.5, 2, 2.5, 3], teeth=(14, 100),
    shifts=(-0.2, 0.8, 0.2), torque=60, speed=1500, life=20000, face_width=(8, 40, 4),
    min_safety={"pitting": 1.1, "bending": 1.5}, smallest_width=False, progress=False,
)  # fmt: skip


def load_front(path: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    every = search.pairs(**SPACE, objective="volume", top=None)
    fig, axes = plt.subplots(2, 1, figsize=(7, 8), sharex=True)  # readable at page width
    for ax, name, label, low in ((axes[0], "S_H", "pitting", 1.1),
                                 (axes[1], "S_F", "bending", 1.5)):  # fmt: skip
        front = search.pairs(**SPACE, objective=("volume", f"-{name}"), top=None)
        ax.scatter(every["volume"] / 1e3, every[name], s=3, color="0.75", rasterized=True,
                   label=f"{every.feasible} pairs that carry the load")  # fmt: skip
        ax.step(front["volume"] / 1e3, front[name], where="post", color="tab:red", lw=1.2)
        ax.plot(front["volume"] / 1e3, front[name], "o", color="tab:red", ms=3,
                label=f"Pareto front ({len(front)} pairs)")  # fmt: skip
        ax.axhline(low, color="tab:blue", ls="--", lw=0.8, label=f"required {name} = {low:g}")
        b = front.table[0]
        ax.annotate(f"{int(b['z1'])}/{int(b['z2'])}, m = {b['module']:g}, "
                    f"b = {b['face_width']:g} mm", (b["volume"] / 1e3, b[name]),
                    (12, 12), textcoords="offset points", fontsize=8,
                    arrowprops={"arrowstyle": "->", "lw": 0.6})  # fmt: skip
        ax.set_xlabel("volume of both gears, cm^3 (pitch cylinders)")
        ax.set_ylabel(f"smaller safety against {label}, {name}")
        ax.legend(fontsize=8, loc="lower right")
        ax.grid(alpha=0.3)
    fig.suptitle("3.2:1 pairs for 60 N m at 1500 rpm, 20 000 h (ISO 6336 method B):\n"
                 "safety against volume", fontsize=11)  # fmt: skip
    fig.tight_layout()
    fig.savefig(path, dpi=100, metadata={"Software": None})
    plt.close(fig)
    return path


def main(out: Path) -> list[Path]:
    out.mkdir(parents=True, exist_ok=True)
    return [load_front(out / FIGURES[0])]


if __name__ == "__main__":
    target = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).parent / "images"
    for p in main(target):
        print(p)
