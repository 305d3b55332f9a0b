"""Involute gear geometry: one gear, one mesh, their checks, profiles and meshes.

The public surface (see ``docs/``)::

    from gears import BasicRack, Gear, GearPair, ShaperCutter
    from gears import BevelPair                        # straight bevel gears (docs/bevel.md)
    from gears import WormPair                         # worm gears (docs/worm.md)
    from gears import NonCircularPair                  # non-circular gears (docs/noncircular.md)
    from gears import pair_geometry, pair_margins      # the same formulas over arrays of pairs
    from gears import search; search.pairs(...)        # design search (docs/design_search.md)
    pair.rating(torque, speed) -> Rating; rate_pairs(...)  # ISO 6336 rating (docs/rating.md)
    pair.contact(torque) -> Contact; Gear(..., modification=Modification(...))  # docs/contact.md

The names are imported on first use (:mod:`gears.lazy`): ``from gears.errors import GearError``
or a command that needs one class loads that class's modules, not the whole library.
"""

from gears.lazy import attach

_getattr, __dir__, __all__ = attach(
    __name__,
    {
        "BasicRack": "gears.rack",
        "BevelGear": "gears.bevel.gear",
        "BevelPair": "gears.bevel.pair",
        "BevelRating": "gears.bevel.rating",
        "conjugate": "gears.noncircular.conjugate",
        "Contact": "gears.contact.result",
        "Finding": "gears.report",
        "Gear": "gears.gear",
        "gear_margins": "gears.checks",
        "GearError": "gears.errors",
        "GearMargins": "gears.checks",
        "GearPair": "gears.pair",
        "HarrisMap": "gears.contact.result",
        "Material": "gears.rating.materials",
        "MATERIALS": "gears.rating.materials",
        "Modification": "gears.contact.modification",
        "ModificationSearch": "gears.contact.result",
        "NonCircularPair": "gears.noncircular.pair",
        "Oil": "gears.rating.scuffing",
        "pair_geometry": "gears.meshing",
        "pair_margins": "gears.checks",
        "PairForces": "gears.forces",
        "PairGeometry": "gears.meshing",
        "PairMargins": "gears.checks",
        "PairRatings": "gears.rating.iso6336",
        "Rack": "gears.mating",
        "rate_pairs": "gears.rating.iso6336",
        "Rating": "gears.rating.capacity",
        "Report": "gears.report",
        "ShaperCutter": "gears.cutting.cutter",
        "transmission_error": "gears.noncircular.conjugate",
        "WormPair": "gears.worm.pair",
    },
)


def __getattr__(name: str) -> object:
    if name == "__version__":  # pyproject.toml's version, as installed (importlib.metadata is slow)
        from importlib.metadata import PackageNotFoundError, version

        try:
            value = version("geartrain")
        except PackageNotFoundError:  # pragma: no cover - a bare source tree, not installed
            value = "unknown"
        globals()["__version__"] = value
        return value
    return _getattr(name)
