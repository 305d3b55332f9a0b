"""One planetary stage on real gears (``Planetary``): its conditions, placement, scene
and loaded tooth contact.

The names below are imported on first use (:mod:`gears.lazy`): importing one module of the
family does not load the rest.
"""

from gears.lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "Assembly": "trains.planetary.checks",
        "assembly_ticks": "trains.planetary.schemes",
        "basic_ratio": "trains.planetary.schemes",
        "canonical_scheme": "trains.planetary.schemes",
        "coaxial_ring_teeth": "trains.planetary.schemes",
        "mesh_phases": "trains.planetary.contact",
        "NEIGHBOUR_TOLERANCE": "trains.planetary.checks",
        "phasing_class": "trains.planetary.schemes",
        "Placement": "trains.planetary.placement",
        "phased_sum": "trains.planetary.contact",
        "Planetary": "trains.planetary.stage",
        "SCHEMES": "trains.planetary.schemes",
        "stage_contact": "trains.planetary.contact",
        "StageContact": "trains.planetary.contact",
        "stage_ratio": "trains.planetary.schemes",
        "textbook_assembly": "trains.planetary.schemes",
    },
)
