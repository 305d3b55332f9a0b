"""Involute gear geometry: one gear, one mesh, their checks, profiles and meshes.

The public surface (see ``docs/``)::

    from gears import BasicRack, Gear, GearPair
"""

from gears.errors import GearError
from gears.rack import BasicRack
from gears.report import Finding, Report

__all__ = ["BasicRack", "Finding", "GearError", "Report"]
