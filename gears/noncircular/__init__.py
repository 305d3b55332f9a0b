"""Non-circular gears: centrodes from a motion law (Ozols section 19-1), their checks, teeth cut
by a rack rolled on any pitch curve, conjugate profiles and the transmission error of any two
outlines (Ozols 19-2), and ``NonCircularPair``.

The names below are imported on first use (:mod:`gears.lazy`): importing one module of the
family does not load the rest.
"""

from gears.lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "center_distance_for_lobes": "gears.noncircular.centrode",
        "conjugate": "gears.noncircular.conjugate",
        "cut_outline": "gears.noncircular.teeth",
        "cycloidal_gear_outline": "gears.noncircular.cycloid",
        "cycloidal_tooth_flank": "gears.noncircular.cycloid",
        "disc_profile": "gears.noncircular.cycloid",
        "epicycloid": "gears.noncircular.cycloid",
        "hypocycloid": "gears.noncircular.cycloid",
        "pin_path": "gears.noncircular.cycloid",
        "normal_miss": "gears.noncircular.conjugate",
        "rack_tooth": "gears.noncircular.teeth",
        "RackCutter": "gears.noncircular.teeth",
        "transmission_error": "gears.noncircular.conjugate",
        "eccentric_radius": "gears.noncircular.centrode",
        "elliptical_radius": "gears.noncircular.centrode",
        "equivalent_teeth": "gears.noncircular.checks",
        "KINDS": "gears.noncircular.centrode",
        "MotionLaw": "gears.noncircular.centrode",
        "NonCircularPair": "gears.noncircular.pair",
        "polar_arc_length": "gears.noncircular.centrode",
        "polar_curvature": "gears.noncircular.centrode",
        "pole_radii": "gears.noncircular.centrode",
        "pole_radius": "gears.noncircular.centrode",
        "rack_centrode": "gears.noncircular.centrode",
        "tooth_margins": "gears.noncircular.checks",
    },
)
