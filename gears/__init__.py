"""Involute gear geometry: one gear, one mesh, their checks, profiles and meshes.

The public surface (see ``docs/``)::

    from gears import BasicRack, Gear, GearPair, ShaperCutter
    from gears import BevelPair                        # straight bevel gears (docs/bevel.md)
    from gears import pair_geometry, pair_margins      # the same formulas over arrays of pairs
    from gears import search; search.pairs(...)        # design search (docs/search.md)
"""

from gears.bevel_pair import BevelGear, BevelPair
from gears.checks import GearMargins, PairMargins, gear_margins, pair_margins
from gears.cutter import ShaperCutter
from gears.errors import GearError
from gears.gear import Gear
from gears.meshing import PairGeometry, pair_geometry
from gears.pair import GearPair, Rack
from gears.rack import BasicRack
from gears.report import Finding, Report

__all__ = [
    "BasicRack",
    "BevelGear",
    "BevelPair",
    "Finding",
    "Gear",
    "GearError",
    "GearMargins",
    "GearPair",
    "PairGeometry",
    "PairMargins",
    "Rack",
    "Report",
    "ShaperCutter",
    "gear_margins",
    "pair_geometry",
    "pair_margins",
]
