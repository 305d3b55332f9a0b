"""Gear trains: the Willis formula per carrier, solved generically (see docs/trains.md)."""

from trains.errors import TrainError

__all__ = ["TrainError"]
