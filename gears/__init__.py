"""Involute gear geometry: one gear, one mesh, their checks, profiles and meshes.

The public surface (see ``docs/``)::

    from gears import BasicRack, Gear, GearPair, ShaperCutter
    from gears import BevelPair                        # straight bevel gears (docs/bevel.md)
    from gears import WormPair                         # worm gears (docs/worm.md)
    from gears import NonCircularPair                  # non-circular gears (docs/noncircular.md)
    from gears import pair_geometry, pair_margins      # the same formulas over arrays of pairs
    from gears import search; search.pairs(...)        # design search (docs/design_search.md)
    pair.rating(torque, speed) -> Rating; rate_pairs(...)  # ISO 6336 rating (docs/rating.md)
"""

from importlib.metadata import PackageNotFoundError, version

from gears.bevel.gear import BevelGear
from gears.bevel.pair import BevelPair
from gears.checks import GearMargins, PairMargins, gear_margins, pair_margins
from gears.cutting.cutter import ShaperCutter
from gears.errors import GearError
from gears.forces import PairForces
from gears.gear import Gear
from gears.mating import Rack
from gears.meshing import PairGeometry, pair_geometry
from gears.noncircular.conjugate import conjugate, transmission_error
from gears.noncircular.pair import NonCircularPair
from gears.pair import GearPair
from gears.rack import BasicRack
from gears.rating.capacity import Rating
from gears.rating.iso6336 import PairRatings, rate_pairs
from gears.rating.materials import MATERIALS, Material
from gears.report import Finding, Report
from gears.worm.pair import WormPair

try:
    __version__ = version("geartrain")  # pyproject.toml's version, as installed
except PackageNotFoundError:  # pragma: no cover - a bare source tree, not installed
    __version__ = "unknown"

__all__ = [
    "MATERIALS",
    "BasicRack",
    "BevelGear",
    "BevelPair",
    "Finding",
    "Gear",
    "GearError",
    "GearMargins",
    "GearPair",
    "Material",
    "NonCircularPair",
    "PairForces",
    "PairGeometry",
    "PairMargins",
    "PairRatings",
    "Rack",
    "Rating",
    "Report",
    "ShaperCutter",
    "WormPair",
    "conjugate",
    "gear_margins",
    "pair_geometry",
    "pair_margins",
    "rate_pairs",
    "transmission_error",
]
