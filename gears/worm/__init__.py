"""Worm gears and crossed-helical gears (DIN 3975 / ISO/TR 10828): the crossed-axes formulas
(axodes, crossed-helical pairs), the worm pair's geometry, efficiency and checks, its flank
forms, and ``WormPair``.

The names below are imported on first use (:mod:`gears.lazy`): importing one module of the
family does not load the rest.
"""

from gears.lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "axial_half_thickness": "gears.worm.flank",
        "Axodes": "gears.worm.crossed",
        "axodes": "gears.worm.crossed",
        "best_lead_angle": "gears.worm.geometry",
        "crossed_efficiency": "gears.worm.crossed",
        "crossed_helical": "gears.worm.crossed",
        "crossed_sliding_velocity": "gears.worm.crossed",
        "CrossedHelical": "gears.worm.crossed",
        "DRIVERS": "gears.worm.geometry",
        "FLANKS": "gears.worm.geometry",
        "plane_rack": "gears.worm.envelope",
        "rack_conjugate": "gears.worm.envelope",
        "rolled": "gears.worm.envelope",
        "reduced_friction_angle": "gears.worm.crossed",
        "self_locking": "gears.worm.geometry",
        "sliding_velocity": "gears.worm.geometry",
        "worm_efficiency": "gears.worm.geometry",
        "worm_geometry": "gears.worm.geometry",
        "worm_margins": "gears.worm.checks",
        "WormGeometry": "gears.worm.geometry",
        "WormMargins": "gears.worm.checks",
        "WormPair": "gears.worm.pair",
    },
)
