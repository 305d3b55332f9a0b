"""Layer 3, cycle: a train with one non-circular pair, over one cycle of its law.

A non-circular pair's ratio varies with its input angle, so the train's speeds do too. At each
angle phi of the pair's gear 1 the train is solved with the pair entered as the Willis link of
its instantaneous ratio (:meth:`trains.Train.link`; ratio -i(phi) for an external pair, +i for an
internal one), the input member turning at unit speed and the ``fixed`` members held. The
input's angle follows from the driver's speed ratio g = w_driver / w_input as
theta(phi) = integral(d phi / g), the output's as integral((w_output / w_input) d theta), and the
output's acceleration at a constant input speed w is w^2 d(w_output/w_input)/d theta.
"""

from __future__ import annotations

import copy
import math
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np
from scipy.integrate import cumulative_simpson

from gears import GearError, NonCircularPair
from gears.arguments import check_integer
from trains.errors import TrainError
from trains.willis import Train

__all__ = ["Cycle", "noncircular_cycle"]


@dataclass(frozen=True)
class Cycle:
    """A train's motion over one cycle of its non-circular pair, at unit input speed: arrays
    over the samples (degrees; speeds per unit input speed; accelerations per unit input speed
    squared, per radian)."""

    pair_angle: np.ndarray
    input_angle: np.ndarray
    output_angle: np.ndarray
    output_speed: np.ndarray
    output_acceleration: np.ndarray

    @property
    def speed_range(self) -> tuple[float, float]:
        """The least and greatest output speed over the cycle (per unit input speed)."""
        return float(np.min(self.output_speed)), float(np.max(self.output_speed))


def noncircular_cycle(
    train: Train, pair: NonCircularPair, driver: str, driven: str, input: str, output: str,
    fixed: Iterable[str] = (), samples: int = 361,
) -> Cycle:  # fmt: skip
    """The motion of ``train`` with ``pair`` meshing ``driver`` (its gear 1) and ``driven``
    (its gear 2), over one period of the pair's law, ``samples`` angles (odd, >= 5).

    ``train`` holds every other relation; it is not changed. Raises a :class:`TrainError`
    for a train that the link does not determine, or a driver that stands still.
    """
    if not isinstance(train, Train):
        raise TrainError(f"train = {train!r}; valid is a trains.Train")
    if not isinstance(pair, NonCircularPair):
        raise TrainError(f"pair = {pair!r}; valid is a gears.NonCircularPair")
    n = check_integer("samples", samples, 5, 100_001)
    n += 1 - n % 2  # Simpson wants an odd count
    fixed = list(fixed)
    phi = np.linspace(0.0, math.degrees(pair.law.period), n)
    sign = -1.0 if pair.kind == "external" else 1.0
    ratio = pair.ratio(phi)
    g = np.empty(n)
    w_out = np.empty(n)
    for k, i in enumerate(ratio):
        t = copy.deepcopy(train)
        t.link(driver, driven, ratio=float(sign * i), name="non-circular pair")
        try:
            m = t.solve({input: 1.0, **{f: 0.0 for f in fixed}})
        except GearError as exc:  # pragma: no cover - the solver raises TrainError
            raise TrainError(str(exc)) from None
        g[k], w_out[k] = float(m[driver]), float(m[output])
    if not np.all(np.abs(g) > 1e-12):
        raise TrainError(
            f"the driver {driver!r} stands still for a turning input {input!r}: the pair's "
            "angle does not follow the input"
        )
    rad = np.radians(phi)
    theta = cumulative_simpson(1.0 / g, x=rad, initial=0.0)
    out = cumulative_simpson(w_out / g, x=rad, initial=0.0)
    accel = np.gradient(w_out, rad, edge_order=2) * g  # d w_out / d theta = (d/d phi) g
    return Cycle(phi, np.degrees(theta), np.degrees(out), w_out, accel)
