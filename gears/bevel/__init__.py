"""Straight bevel gears (ISO 23509): the cone formulas, the tooth on its spherical sections (octoid
or spherical involute) cut by the crown gear, its solids, and ``BevelPair`` / ``BevelGear``.

The names below are imported on first use (:mod:`gears.lazy`): importing one module of the
family does not load the rest.
"""

from gears.lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "ANIMATION_BUDGET_3D": "gears.bevel.pair",
        "axial_section": "gears.bevel.cone",
        "bevel_geometry": "gears.bevel.cone",
        "bevel_pair_svg": "gears.bevel.drawing",
        "bevel_placement": "gears.bevel.solid",
        "bevel_svg": "gears.bevel.drawing",
        "bevel_solid": "gears.bevel.solid",
        "BevelBlank": "gears.bevel.solid",
        "BevelGear": "gears.bevel.gear",
        "BevelGeometry": "gears.bevel.cone",
        "BevelPair": "gears.bevel.pair",
        "check_shaft_angle": "gears.bevel.cone",
        "CLEARANCES": "gears.bevel.cone",
        "CROWN_TOLERANCE": "gears.bevel.cone",
        "cone_distance": "gears.bevel.cone",
        "crown_positions": "gears.bevel.crown",
        "crown_space": "gears.bevel.crown",
        "direction": "gears.bevel.spherical",
        "DRAWN_PER_VERTEX": "gears.bevel.pair",
        "face_width_margins": "gears.bevel.cone",
        "full_round_radius": "gears.bevel.cone",
        "gleason_coefficients": "gears.bevel.cone",
        "gnomonic": "gears.bevel.crown",
        "great_circle_deviation": "gears.bevel.spherical",
        "is_crown": "gears.bevel.cone",
        "KINDS": "gears.bevel.spherical",
        "max_face_width": "gears.bevel.cone",
        "pitch_angles": "gears.bevel.cone",
        "polar": "gears.bevel.spherical",
        "PROFILES": "gears.bevel.pair",
        "rotation": "gears.bevel.solid",
        "solid_estimate": "gears.bevel.solid",
        "spherical_involute": "gears.bevel.spherical",
        "SphericalTooth": "gears.bevel.spherical",
        "virtual_teeth": "gears.bevel.cone",
        "VirtualGear": "gears.bevel.gear",
    },
)
