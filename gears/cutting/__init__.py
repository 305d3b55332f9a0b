"""Cutting: the generating tools' exact envelopes and the simulated cutting that make a gear's
outline
(rack and shaper cutter), measurements on any outline, a pair's outlines in mesh.

The names below are imported on first use (:mod:`gears.lazy`): importing one module of the
family does not load the rest.
"""

from gears.lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "assemble": "gears.cutting.sampling",
        "check_backlash": "gears.cutting.sampling",
        "check_blank": "gears.cutting.sampling",
        "check_tolerance": "gears.cutting.profile",
        "form_diameter_on": "gears.cutting.measure",
        "gear_outline": "gears.cutting.outline",
        "MAX_OUTLINE_VERTICES": "gears.cutting.sampling",
        "METHODS": "gears.cutting.outline",
        "MIN_TOLERANCE": "gears.cutting.profile",
        "one_sided": "gears.cutting.sampling",
        "outline": "gears.cutting.profile",
        "outline_vertices": "gears.cutting.outline",
        "pair_outlines": "gears.cutting.outline",
        "pair_placement": "gears.cutting.outline",
        "profile_of": "gears.cutting.profile",
        "rack_outline": "gears.cutting.generate",
        "rack_positions": "gears.cutting.generate",
        "rack_tool_polygon": "gears.cutting.generate",
        "shaper_outline": "gears.cutting.generate",
        "shaper_positions": "gears.cutting.generate",
        "shaper_tool_polygon": "gears.cutting.generate",
        "ShaperCutter": "gears.cutting.cutter",
        "ShaperProfile": "gears.cutting.profile",
        "ShaperTool": "gears.cutting.cutter",
        "thickness_on": "gears.cutting.measure",
        "tooth_profile": "gears.cutting.profile",
        "ToothProfile": "gears.cutting.profile",
        "undercut_depth": "gears.cutting.measure",
        "undercut_form_diameter": "gears.cutting.profile",
    },
)
