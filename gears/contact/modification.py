"""Layer 2, micro-geometry: tooth flank modifications (:class:`Modification`) and the relief
they remove, as vectorised functions of the roll distance and the face position.

Symbols follow ISO 21771 (clause 7, flank modifications): tip relief C_a over the length L_Ca,
root relief C_f over L_Cf (both measured along the path of contact, that is as roll length on
the line of action), crowning C_b, end relief C_I over L_CI at each end of the face, and the
helix slope deviation f_Hbeta (the flank turned about the face centre). A relief is material
taken off the flank, so it opens a gap between the mating flanks; every amount is in mm and is
>= 0 (a helix slope may have either sign).

Examples
--------
>>> m = Modification(tip_relief=0.02, tip_relief_length=4.0)
>>> float(profile_relief(13.0, 10.0, 15.0, m.tip_relief, m.tip_relief_length, 0.0, 0.0))
0.01
>>> float(lead_relief(0.0, 20.0, crowning=0.01))   # the face centre keeps its material
0.0
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from gears.arguments import check_choice, check_real
from gears.errors import GearError

__all__ = ["KINDS", "Modification", "lead_relief", "profile_relief", "relief_shape"]

#: How a relief grows from its start to the tip (or root, or face end): ``"linear"`` (a straight
#: ramp, ISO 21771 linear tip relief) or ``"parabolic"`` (a quadratic, tangent at its start).
KINDS = ("linear", "parabolic")

#: The largest relief amount accepted, mm (the deepest modifications ground are tenths of a mm).
MAX_RELIEF = 1.0


def relief_shape(fraction, kind: str = "linear"):
    """The relief's shape over its length: 0 at its start, 1 at the tip (or root, or face end);
    ``fraction`` is the distance into the relieved zone over its length (clipped to 0 ... 1).

    >>> [float(relief_shape(f, "parabolic")) for f in (-1.0, 0.5, 2.0)]
    [0.0, 0.25, 1.0]
    """
    f = np.clip(np.asarray(fraction, float), 0.0, 1.0)
    return f * f if kind == "parabolic" else f


def profile_relief(u, root, tip, tip_relief, tip_length, root_relief, root_length, kind="linear"):
    """Profile relief (mm) at the roll positions ``u`` of a flank whose active profile runs from
    ``root`` to ``tip`` (positions on the line of action in mm, either order: the tip is the end
    named ``tip``): C_a over the last ``tip_length`` before the tip, C_f over the first
    ``root_length`` after the root (ISO 21771, profile modifications). Arrays broadcast.
    """
    u = np.asarray(u, float)
    toward_tip = np.sign(tip - root)  # +1 when the tip lies at the larger roll position
    into_tip = (u - (tip - toward_tip * tip_length)) * toward_tip
    into_root = ((root + toward_tip * root_length) - u) * toward_tip
    out = np.zeros(np.broadcast(u, tip, root).shape)
    for amount, length, into in ((tip_relief, tip_length, into_tip),
                                 (root_relief, root_length, into_root)):  # fmt: skip
        if np.any(np.asarray(amount) > 0):
            safe = np.where(np.asarray(length) > 0, length, 1.0)
            with np.errstate(over="ignore"):  # a tiny length: a step, clipped to 1
                ramp = relief_shape(into / safe, kind)
            out = out + np.where(np.asarray(length) > 0, amount * ramp, 0.0)
    return out


def lead_relief(y, face_width, crowning=0.0, end_relief=0.0, end_length=0.0, helix_slope=0.0,
                kind="linear"):  # fmt: skip
    """Lead relief (mm) at the face positions ``y`` (mm from the face centre, -b/2 ... b/2):
    crowning C_b (a parabola, C_b at each end), end relief C_I over ``end_length`` at each end
    (``kind`` shaped), and the helix slope f_Hbeta (a straight line through the face centre,
    +f_Hbeta/2 at y = b/2). The slope may open a negative gap at one end: the contact analysis
    measures gaps from the first point to touch, so only differences count.
    """
    y = np.asarray(y, float)
    half = face_width / 2.0
    out = crowning * (y / half) ** 2 + helix_slope * (y / face_width)
    if end_relief > 0 and end_length > 0:
        with np.errstate(over="ignore"):  # a tiny length: a step, clipped to 1
            into_end = (np.abs(y) - (half - end_length)) / end_length
        out = out + end_relief * relief_shape(into_end, kind)
    return out


@dataclass(frozen=True)
class Modification:
    """Flank modifications of one gear (ISO 21771 clause 7); immutable, lengths in mm.

    Parameters
    ----------
    tip_relief, root_relief : float
        C_a and C_f, the material taken off at the tip and at the start of the active profile
        (the root), mm >= 0.
    tip_relief_length, root_relief_length : float or None
        L_Ca and L_Cf along the path of contact, mm (roll length on the line of action). None:
        the "short" relief of the mesh it works in, from the tip (root) to the nearest point of
        single contact, (eps_alpha - 1) p_bt.
    crowning : float
        C_b, the parabolic lead crowning at each end of the face, mm >= 0.
    end_relief, end_relief_length : float
        C_I at each end of the face, over L_CI mm (None: a sixth of the face width).
    helix_slope : float
        f_Hbeta, mm over the face width (either sign).
    kind : str
        ``"linear"`` or ``"parabolic"`` reliefs (:data:`KINDS`).

    Raises
    ------
    GearError
        An amount that is negative, not finite or above :data:`MAX_RELIEF`, naming it.

    Examples
    --------
    >>> Modification(tip_relief=0.015, kind="parabolic").tip_relief
    0.015
    >>> Modification(tip_relief=-0.01)
    Traceback (most recent call last):
    ...
    gears.errors.GearError: tip_relief = -0.01; valid is tip_relief >= 0 and <= 1
    """

    tip_relief: float = 0.0
    tip_relief_length: float | None = None
    root_relief: float = 0.0
    root_relief_length: float | None = None
    crowning: float = 0.0
    end_relief: float = 0.0
    end_relief_length: float | None = None
    helix_slope: float = 0.0
    kind: str = "linear"

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        for name in ("tip_relief", "root_relief", "crowning", "end_relief"):
            value = check_real(name, getattr(self, name), 0.0, MAX_RELIEF, False, False)
            set_(self, name, value)
        for name in ("tip_relief_length", "root_relief_length", "end_relief_length"):
            if getattr(self, name) is not None:
                set_(self, name, check_real(name, getattr(self, name), 0.0, 1e6))
        set_(self, "helix_slope", check_real("helix_slope", self.helix_slope, -1.0, 1.0))
        set_(self, "kind", check_choice("kind", self.kind, KINDS))

    @property
    def is_none(self) -> bool:
        """True when nothing is taken off (every amount is 0)."""
        amounts = (self.tip_relief, self.root_relief, self.crowning, self.end_relief)
        return not any(amounts) and self.helix_slope == 0.0

    def lengths(self, short: float, face_width: float) -> tuple[float, float, float]:
        """``(L_Ca, L_Cf, L_CI)`` in mm with their defaults filled in: ``short`` is the short
        relief of the mesh, (eps_alpha - 1) p_bt, and ``face_width`` the face's b."""
        la = short if self.tip_relief_length is None else self.tip_relief_length
        lf = short if self.root_relief_length is None else self.root_relief_length
        li = face_width / 6.0 if self.end_relief_length is None else self.end_relief_length
        if li > face_width / 2.0:
            raise GearError(
                f"end_relief_length = {li:g} mm; valid is at most half the face width "
                f"({face_width / 2:g} mm)"
            )
        return max(la, 0.0), max(lf, 0.0), li
