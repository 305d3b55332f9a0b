"""Load capacity: ISO 6336 over arrays and for one mesh (``Rating``), the root measured on the real
tooth, materials and their life curves (ISO 6336-5), sizing for a load.

The names below are imported on first use (:mod:`gears.lazy`): importing one module of the
family does not load the rest.
"""

from gears.lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "bending_life_factor": "gears.rating.materials",
        "contact_ratio_factor": "gears.rating.iso6336",
        "dynamic_factor": "gears.rating.iso6336",
        "elasticity_factor": "gears.rating.iso6336",
        "face_load_factor": "gears.rating.iso6336",
        "FACTORS": "gears.rating.iso6336",
        "form_factors": "gears.rating.iso6336",
        "gear_volume": "gears.rating.sizing",
        "internal_root_form": "gears.rating.iso6336",
        "ISO54": "gears.rating.sizing",
        "ISO54_SECOND": "gears.rating.sizing",
        "kind_code": "gears.rating.materials",
        "KINDS": "gears.rating.materials",
        "Load": "gears.rating.sizing",
        "load_case": "gears.rating.sizing",
        "load_diameters": "gears.rating.capacity",
        "load_point": "gears.rating.iso6336",
        "lubrication_factors": "gears.rating.iso6336",
        "Material": "gears.rating.materials",
        "material": "gears.rating.materials",
        "MATERIALS": "gears.rating.materials",
        "measure_root": "gears.rating.root",
        "mesh_stiffness": "gears.rating.iso6336",
        "MIN_SAFETY": "gears.rating.sizing",
        "pair_volume": "gears.rating.sizing",
        "PairRatings": "gears.rating.iso6336",
        "pitting_life_factor": "gears.rating.materials",
        "QUANTITIES": "gears.rating.iso6336",
        "rate": "gears.rating.sizing",
        "rate_pair": "gears.rating.capacity",
        "rate_pairs": "gears.rating.iso6336",
        "Rating": "gears.rating.capacity",
        "RATING_OPTIONS": "gears.rating.sizing",
        "REASONS": "gears.rating.iso6336",
        "RING_RIM": "gears.rating.sizing",
        "root_form": "gears.rating.iso6336",
        "ROOT_ROUTES": "gears.rating.capacity",
        "RootForm": "gears.rating.root",
        "roughness_factor": "gears.rating.iso6336",
        "single_pair_factors": "gears.rating.iso6336",
        "single_stiffness": "gears.rating.iso6336",
        "smallest_width": "gears.rating.sizing",
        "tolerances": "gears.rating.iso6336",
        "transverse_load_factors": "gears.rating.iso6336",
        "virtual_gear": "gears.rating.root",
        "zone_factor": "gears.rating.iso6336",
    },
)
