"""Layer 1, base.

Reduced (equivalent) inertia of a geared drive, Ozols (13.10), with speeds from the solver."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

from trains.errors import TrainError


def reduced_inertia(
    speeds: Mapping[str, Any],
    reference: str,
    inertias: Mapping[str, Any],
    translating: Iterable[tuple[Any, Any]] = (),
) -> Any:
    """Moment of inertia reduced to ``reference``: Ozols (13.10).

    ``I_r = sum I_j (w_j / w_ref)^2 + sum m_k (v_k / w_ref)^2``.

    Parameters
    ----------
    speeds : mapping
        Member speeds, e.g. a :class:`~trains.willis.Motion` (exact speeds give an exact result
        when the inertias are exact).
    reference : str
        The member the inertia is reduced to (usually the motor shaft).
    inertias : mapping
        ``member -> moment of inertia`` of the rotating members.
    translating : iterable of (mass, velocity)
        Translating masses with their velocities in the same motion.

    Examples
    --------
    Ozols example 13-1 (hoist; z3 = 72, the value the printed 0.0045 requires):

    >>> from trains import Train
    >>> t = Train()
    >>> t.mesh("worm", "wheel", teeth=(1, 37))
    >>> t.mesh("wheel", "drum", teeth=(12, 72))
    >>> m = t.solve(worm=1)
    >>> v = m["drum"] * 0.2 / 2                   # two-fall block, drum radius 0.2 m
    >>> I = reduced_inertia(m, "worm", {"worm": 0.7, "wheel": 1.8, "drum": 107},
    ...                     translating=[(80, v), (44000, v)])
    >>> round(I + 2 * float(m["drum"] / 2) ** 2, 5)  # the block (I4 = 2) turns at w3/2
    0.71244
    """
    try:
        w_ref = speeds[reference]
    except KeyError:
        raise TrainError(f"unknown reference member {reference!r}") from None
    if w_ref == 0:
        raise TrainError(f"the reference member {reference!r} stands still")
    total: Any = 0
    for member, inertia in inertias.items():
        try:
            w = speeds[member]
        except KeyError:
            raise TrainError(f"unknown member {member!r} in inertias") from None
        total = total + inertia * (w / w_ref) ** 2
    for mass, v in translating:
        total = total + mass * (v / w_ref) ** 2
    return total
