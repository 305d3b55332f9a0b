"""Generate the figure of ``docs/trains.md``: the reverted reducer on real gears.

Usage: ``python docs/make_train_figures.py [output_dir]`` (default: ``docs/images``).
Draws both stages of the 17/40 + 20/38, m = 2 reverted reducer with their real tooth outlines
(:meth:`gears.GearPair.outlines`) at their working centre distances: the input and output gears
on one axis, the layshaft at a_w = 58 mm for both stages after
:func:`trains.coaxial_shifts` shifted the 17/40 stage (its zero-shift a = 57 mm).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

from shapely.affinity import scale

from gears import Gear
from trains import coaxial_shifts

FIGURES = ("train_reverted_reducer.png",)


def _fill(ax, poly, **kw) -> None:
    from matplotlib.patches import PathPatch
    from matplotlib.path import Path as MPath

    polys = getattr(poly, "geoms", [poly])
    for p in polys:
        rings = [p.exterior, *p.interiors]
        verts, codes = [], []
        for ring in rings:
            xy = list(ring.coords)
            verts += xy
            codes += [MPath.MOVETO] + [MPath.LINETO] * (len(xy) - 2) + [MPath.CLOSEPOLY]
        ax.add_patch(PathPatch(MPath(verts, codes), **kw))


def reverted_reducer(path: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle

    m = 2.0
    p12, p34 = coaxial_shifts([(Gear(17, m), Gear(40, m)), (Gear(20, m), Gear(38, m))])
    fig, axes = plt.subplots(1, 2, figsize=(8, 4))  # readable at the page width
    stages = (
        (p12, "stage 1: input 17 / layshaft 40", ("in", "lay")),
        (p34, "stage 2: layshaft 20 / output 38", ("lay", "out")),
    )
    for ax, (pair, title, names) in zip(axes, stages, strict=True):
        a = pair.center_distance
        # outlines: gear 1 at the origin, gear 2 at (a_w, 0); stage 2's output (its gear 2)
        # sits on the input axis, so that stage is drawn mirrored
        o1, o2 = pair.outlines(angle=0.0, tolerance=0.01)
        if names[1] == "out":  # mirror about x = a/2: gear 2 to the origin, gear 1 to +a_w
            o1, o2 = (scale(o, -1.0, 1.0, origin=(a / 2, 0.0)) for o in (o1, o2))
        _fill(ax, o1, facecolor="tab:blue", alpha=0.55, edgecolor="tab:blue", lw=0.6)
        _fill(ax, o2, facecolor="tab:orange", alpha=0.55, edgecolor="tab:orange", lw=0.6)
        dw1, dw2 = pair.working_diameters
        centres = (0.0, a) if names[1] != "out" else (a, 0.0)
        for c, d in zip(centres, (dw1, dw2), strict=True):
            ax.add_patch(Circle((c, 0.0), d / 2, fill=False, ls="--", lw=0.8, color="0.3"))
            ax.plot([c], [0.0], "k+", ms=10)
        ax.annotate("", (0.0, -48), (a, -48),
                    arrowprops={"arrowstyle": "<->", "color": "tab:red"})  # fmt: skip
        x1, x2 = pair.g1.profile_shift, pair.g2.profile_shift
        ax.text(a / 2, -52, f"a_w = {a:.4f} mm", ha="center", va="top", color="tab:red")
        ax.text(0.0, 44, "input / output axis", ha="center", fontsize=8)
        ax.text(a, 44, "layshaft", ha="center", fontsize=8)
        ax.set_title(f"{title}\nx = {x1:+.4f} / {x2:+.4f}, contact ratio "
                     f"{pair.contact_ratio:.3f}", fontsize=10)  # fmt: skip
        ax.set_xlim(-45, a + 45)
        ax.set_ylim(-60, 50)
        ax.set_aspect("equal")
        ax.set_xlabel("mm")
    assert math.isclose(p12.center_distance, p34.center_distance, abs_tol=1e-9)
    fig.suptitle("reverted reducer 17/40 + 20/38, m = 2: the 17/40 stage shifted to the "
                 "20/38 stage's 58 mm (real tooth outlines, working pitch circles dashed)",
                 fontsize=10)  # fmt: skip
    fig.tight_layout()
    fig.savefig(path, dpi=100, metadata={"Software": None})
    plt.close(fig)
    return path


def main(out: Path) -> list[Path]:
    out.mkdir(parents=True, exist_ok=True)
    return [reverted_reducer(out / FIGURES[0])]


if __name__ == "__main__":
    target = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).parent / "images"
    for p in main(target):
        print(p)
