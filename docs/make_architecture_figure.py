"""Generate the figure of ``docs/architecture.md``: the families and layers of both packages.

Usage: ``python docs/make_architecture_figure.py [output_dir]`` (default: ``docs/images``).
The figure is drawn from the layer tables of ``docs/architecture.md`` itself (the tables that
``tests/test_layers.py`` holds the code to): one column per family, one row per layer, each
module a box in its family's column; the packages side by side, ``trains`` importing ``gears``.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
FIGURES = ("architecture.png",)


def layer_tables(text: str) -> dict[str, list[list[str]]]:
    """``{package: [[module, ...] per layer]}`` from the layer tables of architecture.md."""
    out = {}
    for package in ("gears", "trains"):
        section = text.split(f"## `{package}`", 1)[1].split("\n## ", 1)[0]
        rows = re.findall(r"^\|\s*(\d+)\s*\|([^|]*)\|", section, flags=re.M)
        out[package] = [re.findall(r"`([\w.*]+)`", names) for _, names in rows]
    return out


def _family(module: str) -> str:
    return module.split(".", 1)[0] if "." in module else "core"


def main(out_dir: Path | str = HERE / "images") -> list[Path]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    tables = layer_tables((HERE / "architecture.md").read_text())
    fig, axes = plt.subplots(
        1, 2, figsize=(13, 7.2), gridspec_kw={"width_ratios": [7, 4]}, layout="constrained"
    )
    colours = plt.get_cmap("tab10").colors
    for ax, (package, layers) in zip(axes, tables.items(), strict=True):
        families = [
            "core",
            *sorted(
                {_family(m) for layer in layers for m in layer} - {"core"},
                key=lambda f: min(
                    i for i, layer in enumerate(layers) for m in layer if _family(m) == f
                ),
            ),
        ]
        for i, layer in enumerate(layers):
            ax.axhline(i - 0.5, color="0.9", lw=0.6, zorder=0)
            by_family: dict[str, list[str]] = {}
            for m in layer:
                by_family.setdefault(_family(m), []).append(m.split(".", 1)[-1])
            for f, names in by_family.items():
                j = families.index(f)
                label = "\n".join(", ".join(names[k : k + 2]) for k in range(0, len(names), 2))
                ax.text(
                    j, i, label, ha="center", va="center", fontsize=7.5,
                    bbox={"boxstyle": "round,pad=0.25", "fc": colours[j % 10], "alpha": 0.25,
                          "ec": colours[j % 10]},
                )  # fmt: skip
        ax.set_xticks(range(len(families)), [f if f == "core" else f + "/" for f in families])
        ax.set_yticks(range(len(layers)), [f"layer {i}" for i in range(len(layers))])
        ax.set_xlim(-0.6, len(families) - 0.4)
        ax.set_ylim(-0.6, len(layers) - 0.4)
        ax.tick_params(length=0, labelsize=9)
        ax.xaxis.tick_top()
        for side in ax.spines.values():
            side.set_visible(False)
        ax.set_title(f"{package}/  (imports point down)", fontsize=11, pad=22)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    path = out / FIGURES[0]
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return [path]


if __name__ == "__main__":
    print(*main(*sys.argv[1:2]), sep="\n")
