"""Figures: the notebook drawings (SVG) of a gear, a pair and a stage, and matplotlib plots.

The names below are imported on first use (:mod:`gears.lazy`): importing one module of the
family does not load the rest.
"""

from gears.lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "display_tolerance": "gears.figures.drawing",
        "filled": "gears.figures.drawing",
        "forces_figure": "gears.figures.forces",
        "gear_svg": "gears.figures.drawing",
        "generation_figure": "gears.figures.plot",
        "outlines_figure": "gears.figures.plot",
        "outlines_svg": "gears.figures.drawing",
        "pair_figure": "gears.figures.plot",
        "pair_forces_figure": "gears.figures.forces",
        "pair_svg": "gears.figures.drawing",
        "picture": "gears.figures.drawing",
        "shown": "gears.figures.drawing",
        "tooth_figure": "gears.figures.plot",
        "LINE": "gears.figures.drawing",
        "WIDTH": "gears.figures.drawing",
    },
)
