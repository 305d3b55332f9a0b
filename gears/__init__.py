"""Involute gear geometry: one gear, one mesh, their checks, profiles and meshes.

The public surface (see ``docs/``)::

    from gears import BasicRack, Gear, GearPair, ShaperCutter
"""

from gears.cutter import ShaperCutter
from gears.errors import GearError
from gears.gear import Gear
from gears.meshing import PairGeometry, pair_geometry
from gears.pair import GearPair, Rack
from gears.rack import BasicRack
from gears.report import Finding, Report

__all__ = [
    "BasicRack",
    "Finding",
    "Gear",
    "GearError",
    "GearPair",
    "PairGeometry",
    "Rack",
    "Report",
    "ShaperCutter",
    "pair_geometry",
]
