"""Design: tooth-number synthesis of one stage, planetary stages sized for a load, and the
multi-stage gearbox search.

The names below are imported on first use (:mod:`gears.lazy`): importing one module of the
family does not load the rest.
"""

from gears.lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "Candidate": "trains.design.synthesis",
        "Candidates": "trains.design.synthesis",
        "Gearbox": "trains.design.gearbox",
        "Gearboxes": "trains.design.gearbox",
        "MODULE_WINDOW": "trains.design.sizing",
        "ring_tip_alteration": "trains.design.sizing",
        "set_count": "trains.design.synthesis",
        "size_stages": "trains.design.sizing",
        "stage_block": "trains.design.synthesis",
        "STAGE_FIELDS": "trains.design.synthesis",
        "stage_gears": "trains.design.sizing",
        "stage_meshes": "trains.design.sizing",
        "synthesize": "trains.design.synthesis",
        "synthesize_gearbox": "trains.design.gearbox",
    },
)
