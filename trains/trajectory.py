"""Layer 1, base.

Paths of points carried by the members of a train (gear-linkage and biplanetary trains).

A point on the last member of a chain of rotating arms (Ozols §7-3, Fig 7-10, 7-18) is the sum
of one phasor per arm: ``p = origin + sum_k l_k exp(i (phi_k + phase_k))``, where ``phi_k`` is the
absolute angle of the member that carries arm ``k``. The angles come from
:meth:`trains.willis.Motion.integrate`, so the train's Willis relations fix the path.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from trains.errors import TrainError


def point_path(
    angles: Mapping[str, Any],
    chain: Sequence[tuple[str, float] | tuple[str, float, float]],
    origin: tuple[float, float] = (0.0, 0.0),
    degrees: bool = False,
) -> tuple[np.ndarray, np.ndarray]:
    """Coordinates of a point at the end of a chain of arms turning with the members.

    Parameters
    ----------
    angles : mapping
        Absolute angle of each member (e.g. ``motion.integrate(t)``), radians unless
        ``degrees``.
    chain : sequence of (member, length) or (member, length, phase)
        The arms from the fixed origin outwards: the carrier arm (centre distance), the next
        carrier's arm, ..., and finally the point's distance from its member's axis. ``phase``
        is the arm's angle when the member's angle is zero (same unit as ``angles``).
    origin : (float, float)
        The fixed axis the first arm turns about.
    degrees : bool
        Angles and phases in degrees (the project's public convention) instead of radians.

    Returns
    -------
    x, y : ndarray

    Examples
    --------
    An epicycloid: a planet of radius 1 rolling on a fixed sun of radius 3 (the planet's
    absolute speed is 4 times the carrier's, Willis).

    >>> from trains import Train
    >>> import numpy as np
    >>> t = Train()
    >>> t.mesh("sun", "planet", teeth=(30, 10), carrier="arm")
    >>> time = np.linspace(0, 2 * np.pi, 5)
    >>> phi = t.solve(arm=np.ones_like(time), sun=0).integrate(time)
    >>> x, y = point_path(phi, [("arm", 4.0), ("planet", 1.0)])
    >>> np.round(x, 6).tolist()
    [5.0, 1.0, -3.0, 1.0, 5.0]
    """
    if not chain:
        raise TrainError("a chain needs at least one arm (member, length)")
    z: Any = complex(*origin)
    scale = np.pi / 180 if degrees else 1.0
    for arm in chain:
        if len(arm) not in (2, 3):
            raise TrainError(f"an arm is (member, length) or (member, length, phase), got {arm!r}")
        member, length = arm[0], float(arm[1])
        phase = float(arm[2]) if len(arm) == 3 else 0.0
        try:
            phi = angles[member]
        except KeyError:
            raise TrainError(f"no angle for member {member!r}") from None
        phi = np.asarray(phi, dtype=float)
        z = z + length * np.exp(1j * (phi + phase) * scale)
    z = np.asarray(z)
    return z.real.copy(), z.imag.copy()
