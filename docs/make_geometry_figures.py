"""Generate the figures of ``docs/geometry.md``.

Usage: ``python docs/make_geometry_figures.py [output_dir]`` (default: ``docs/images``). The test
suite runs it into a temporary directory, so the committed images are the ones this script makes.
"""

from __future__ import annotations

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt

from gears.shift import blocking_contour, plot_blocking_contour

FIGURES = ("blocking_contour_12_28.png",)


def blocking_contour_12_28(path: Path) -> Path:
    """Ozols Fig. 21-13 for z1 = 12, z2 = 28, ISO 53 A, alpha = 20 deg, epsilon_alpha >= 1."""
    result = blocking_contour(12, 28, n=241)
    fig, ax = plt.subplots(figsize=(8, 7.5))
    plot_blocking_contour(result, ax=ax)
    fig.tight_layout()
    # fixed metadata so that re-running the script gives the same bytes
    fig.savefig(path, dpi=110, metadata={"Software": None})
    plt.close(fig)
    return path


def main(out_dir: str | Path = Path(__file__).parent / "images") -> list[Path]:
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    return [blocking_contour_12_28(out / FIGURES[0])]


if __name__ == "__main__":
    for p in main(*sys.argv[1:2]):
        print(p)
