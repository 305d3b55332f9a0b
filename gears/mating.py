"""Layer 3, mates: the parts of a mesh that are not a :class:`gears.Gear`: :class:`Rack`, the
pinion's mate of infinitely many teeth, and :class:`PathOfContact`, the positions on the line of
action (both used by :class:`gears.GearPair`).
"""

from __future__ import annotations

from dataclasses import dataclass

from gears.arguments import check_module, check_positive, check_pressure_angle
from gears.geometry import check_real

__all__ = ["PathOfContact", "Rack"]


@dataclass(frozen=True)
class Rack:
    """A gear rack (z -> infinity) to mesh with a pinion.

    Parameters
    ----------
    module : float
        Normal module; must equal the pinion's.
    pressure_angle : float
        Normal pressure angle in degrees (defaults to 20).
    helix_angle : float
        Helix angle of the rack teeth in degrees; the pinion's is its negative.
    face_width : float or None
        For the overlap ratio.
    addendum : float
        Rack addendum coefficient h_aP* (1.0 for ISO 53).
    """

    module: float
    pressure_angle: float = 20.0
    helix_angle: float = 0.0
    face_width: float | None = None
    addendum: float = 1.0

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        set_(self, "module", check_module(self.module, "rack module"))
        set_(
            self, "pressure_angle", check_pressure_angle(self.pressure_angle, "rack pressure_angle")
        )
        set_(self, "helix_angle", check_real("rack helix_angle", self.helix_angle, -60.0, 60.0))
        if self.face_width is not None:
            set_(self, "face_width", check_positive("rack face_width", self.face_width))
        set_(self, "addendum", check_real("rack addendum", self.addendum, 0.0, 10.0))


@dataclass(frozen=True)
class PathOfContact:
    """Positions on the line of action, in mm from N1 (gear 1's base-circle tangent point).

    ``start`` (A, gear 2's tip when gear 1 drives), ``end`` (E, gear 1's tip), ``pitch_point``
    (C), ``n2`` (N2, gear 2's tangent point; for a rack, ``inf``), ``base_pitch`` p_bt, and the
    single-contact zone ``[single_start, single_end] = [E - p_bt, A + p_bt]`` (empty when the
    contact ratio reaches 2).
    """

    start: float
    end: float
    pitch_point: float
    n2: float
    base_pitch: float

    @property
    def length(self) -> float:
        """g_alpha = AE."""
        return self.end - self.start

    @property
    def single_start(self) -> float:
        return self.end - self.base_pitch

    @property
    def single_end(self) -> float:
        return self.start + self.base_pitch

    @property
    def single_contact(self) -> tuple[float, float] | None:
        """The single-tooth contact zone on the line, or None when two pairs always mesh."""
        lo, hi = self.single_start, self.single_end
        return (lo, hi) if hi > lo else None
