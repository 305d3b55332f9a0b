"""One planetary stage on real gears (``Planetary``): its conditions, placement and scene.

The names below are imported on first use (:mod:`gears.lazy`): importing one module of the
family does not load the rest.
"""

from gears.lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "Assembly": "trains.planetary.stage",
        "assembly_ticks": "trains.planetary.stage",
        "basic_ratio": "trains.planetary.stage",
        "coaxial_ring_teeth": "trains.planetary.stage",
        "NEIGHBOUR_TOLERANCE": "trains.planetary.stage",
        "phasing_class": "trains.planetary.stage",
        "Placement": "trains.planetary.stage",
        "Planetary": "trains.planetary.stage",
        "SCHEMES": "trains.planetary.stage",
        "stage_ratio": "trains.planetary.stage",
    },
)
