"""Tooth contact analysis: flank modifications (micro-geometry), the single-tooth compliance by
the potential-energy method, the load shared among the teeth in contact over a mesh cycle
(transmission error, mesh stiffness, load sharing, contact pattern, K_Hbeta and K_Halpha), and
the Harris map and the search for the tip relief and crowning of the least transmission error.

The names below are imported on first use (:mod:`gears.lazy`): importing one module of the
family does not load the rest.
"""

from gears.lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "best_modification": "gears.contact.result",
        "cell_stiffness": "gears.contact.analysis",
        "contact": "gears.contact.result",
        "Contact": "gears.contact.result",
        "contact_factors": "gears.contact.analysis",
        "contact_geometry": "gears.contact.result",
        "harris": "gears.contact.result",
        "harris_figure": "gears.contact.plot",
        "harris_map": "gears.contact.analysis",
        "HarrisMap": "gears.contact.result",
        "hertz_compliance": "gears.contact.compliance",
        "KINDS": "gears.contact.modification",
        "lead_relief": "gears.contact.modification",
        "loaded_contact": "gears.contact.analysis",
        "MAX_CELLS": "gears.contact.result",
        "mesh_cells": "gears.contact.analysis",
        "modified_outline": "gears.contact.flank",
        "mesh_compliance": "gears.contact.compliance",
        "Modification": "gears.contact.modification",
        "modification_grid": "gears.contact.analysis",
        "ModificationSearch": "gears.contact.result",
        "pair_gaps": "gears.contact.analysis",
        "pattern_figure": "gears.contact.plot",
        "profile_relief": "gears.contact.modification",
        "rack_short_relief": "gears.contact.flank",
        "rating_factors": "gears.contact.result",
        "share_load": "gears.contact.analysis",
        "te_figure": "gears.contact.plot",
        "tooth_compliance": "gears.contact.compliance",
    },
)
