"""Layer 4, planetary: a stage's loaded tooth contact, mesh by mesh, and its net transmission
error with the planets' mesh phasing (:class:`StageContact`).

Each mesh of the stage (sun-planet, planet-ring, ...) is analysed once by
:meth:`gears.GearPair.contact` under the torque one planet's mesh carries (the power flow of
the stage's :class:`~trains.willis.Train`, shared by the planets, times the load-sharing
factor K_gamma); the planets' meshes of one kind are copies of it, each running at its own
*mesh phase*. With the planets at the angles psi_i of the stage's
:meth:`~trains.planetary.stage.Planetary.placement`, a central gear of z teeth meets planet i
``gamma_i = z psi_i / 360`` mesh cycles after planet 0 (the sun's meshes; the ring's run the
other way, ``-z psi_i / 360``): Parker and Lin (2004), "Mesh phasing relationships in planetary
and epicyclic gears", J. Mech. Des. 126, eqs. 9-10.

The net transmission error of a mesh kind is the sum over the planets of each copy's
transmission error at its phase, the stage's excitation at that mesh: its harmonic of mesh
order h is the single mesh's times ``sum_i exp(2 pi j h gamma_i)``. With equally spaced
planets that sum is n when h z / n is an integer (the meshes in phase) and 0 otherwise
(sequential phasing cancels the harmonic; Parker and Lin 2004, Kahraman 1994). The shift by a
fraction of a mesh cycle is exact on the sampled cycle (a phase factor on its Fourier series).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from gears import GearPair
from gears.errors import GearError
from trains.errors import TrainError
from trains.planetary.schemes import _MESHES, _default_roles
from trains.power import power_flow

__all__ = ["StageContact", "mesh_phases", "phased_sum", "stage_contact"]


def mesh_phases(teeth, angles, ring: bool = False):
    """Mesh phase of each planet, in mesh cycles (0 ... 1) after the planet at angle 0:
    ``z psi / 360`` for a sun, ``-z psi / 360`` for a ring (Parker and Lin 2004, eqs. 9-10);
    ``angles`` in degrees (arrays broadcast).

    >>> [round(float(g), 6) for g in mesh_phases(19, [0.0, 120.0, 240.0])]
    [0.0, 0.333333, 0.666667]
    """
    sign = -1.0 if ring else 1.0
    return np.mod(sign * np.asarray(teeth, float) * np.asarray(angles, float) / 360.0, 1.0)


def phased_sum(values, phases):
    """The sum of copies of a periodic sampled signal ``values`` (one period over the last
    axis), copy i delayed by ``phases[i]`` periods: exact on the samples (each Fourier
    harmonic h times ``sum_i exp(-2 pi j h gamma_i)``).

    >>> np.round(phased_sum(np.cos(2 * np.pi * np.arange(8) / 8), [0.0, 0.5]), 12) + 0.0
    array([0., 0., 0., 0., 0., 0., 0., 0.])
    """
    values = np.asarray(values, float)
    n = values.shape[-1]
    h = np.arange(n // 2 + 1)
    factor = np.exp(-2j * np.pi * np.outer(np.asarray(phases, float), h)).sum(axis=0)
    return np.fft.irfft(np.fft.rfft(values, axis=-1) * factor, n=n, axis=-1)


def harmonic_amplitudes(values, orders):
    """Amplitude of the harmonics ``orders`` (per period) of a periodic sampled signal."""
    values = np.asarray(values, float)
    spectrum = np.fft.rfft(values, axis=-1) / values.shape[-1]
    orders = np.asarray(orders, int)
    scale = np.where((orders == 0) | (2 * orders == values.shape[-1]), 1.0, 2.0)
    return np.abs(spectrum[..., orders]) * scale


@dataclass(frozen=True)
class StageContact:
    """The loaded tooth contact of every mesh of a planetary stage.

    Attributes
    ----------
    meshes : dict
        Mesh name (``"sun-planet"``, ``"planet-ring"``, ...) -> :class:`gears.Contact` of one
        planet's mesh.
    torques : dict
        Mesh name -> torque on the mesh's gear 1 per planet, N m (times K_gamma).
    phases : dict
        Mesh name -> each planet's mesh phase in mesh cycles (:func:`mesh_phases`); None for a
        mesh between two planets (no central gear).
    n_planets : int
    """

    meshes: dict
    torques: dict
    phases: dict
    n_planets: int
    settings: dict = field(default_factory=dict, repr=False)

    def _phases(self, mesh: str) -> np.ndarray:
        if mesh not in self.meshes:
            raise TrainError(f"mesh = {mesh!r}; valid are {', '.join(self.meshes)}")
        if self.phases[mesh] is None:
            raise TrainError(f"mesh {mesh!r} joins two planets: it has no central gear's phase")
        return np.asarray(self.phases[mesh], float)

    def in_phase(self, mesh: str, order: int = 1) -> bool:
        """True when every planet's mesh of this kind is at the same phase for the mesh
        harmonic ``order`` (h gamma_i an integer for every planet)."""
        g = self._phases(mesh) * order
        return bool(np.all(np.abs(g - np.round(g)) < 1e-9))

    def net_transmission_error(self, mesh: str) -> np.ndarray:
        """The sum over the planets of the mesh's loaded transmission error, each at its mesh
        phase, um along the line of action, at the mesh's positions over one mesh cycle."""
        te = self.meshes[mesh].transmission_error if mesh in self.meshes else None
        return phased_sum(te, self._phases(mesh))

    def harmonics(self, mesh: str, orders: Sequence[int] = (1, 2, 3)) -> dict[str, np.ndarray]:
        """Amplitudes (um) of the mesh-order harmonics ``orders`` of one mesh's transmission
        error (``"single"``) and of the stage's net (``"net"``)."""
        net = self.net_transmission_error(mesh)
        orders = np.asarray(orders, int)
        positions = net.shape[-1]
        if orders.size == 0 or orders.min() < 1 or orders.max() > positions // 2:
            raise TrainError(
                f"orders = {orders.tolist()}; valid are mesh orders 1 ... {positions // 2} "
                f"(half the {positions} positions)"
            )
        single = self.meshes[mesh].transmission_error
        return {"single": harmonic_amplitudes(single, orders),
                "net": harmonic_amplitudes(net, orders)}  # fmt: skip

    def __repr__(self) -> str:
        parts = ", ".join(f"{k}: {c.peak_to_peak:.4g} um" for k, c in self.meshes.items())
        return f"StageContact(n_planets={self.n_planets}, peak_to_peak {{{parts}}})"


def _mesh_torques(stage, torque, fixed, input, output) -> dict[str, float]:
    """Torque on each mesh's gear 1 per planet, N m: the stage's power flow as
    :func:`trains.capacity.rating` reads it."""
    fixed, input, output = _default_roles(
        stage._member(fixed),
        None if input is None else stage._member(input),
        None if output is None else stage._member(output),
    )
    name = {"sun": "sun", "ring": "ring", "carrier": stage.carrier}
    train = stage.train
    flow = power_flow(train, name[input], name[output], fixed=[name[fixed]],
                      input_torque=float(torque), input_speed=1.0)  # fmt: skip
    planets = dict(getattr(train, "_planets", {}))
    out = {}
    for r in train.relations:
        rp = flow.relations[r.name]
        m1 = r.b if r.gears[0].internal else r.a  # the pair's g1 is the external gear
        m2 = r.a if m1 == r.b else r.b
        copies = max(planets.get(m1, 1), planets.get(m2, 1))
        out[r.name] = abs(rp.torques.get(m1, 0.0)) / copies
    return out


def stage_contact(
    stage, torque: float, *, fixed: str = "ring", input: str | None = None,
    output: str | None = None, load_sharing_factor: float = 1.0,
    face_width: float | None = None, angles=None, **options: Any,
) -> StageContact:  # fmt: skip
    """Every mesh of ``stage`` under ``torque`` (N m on the input member), see
    :meth:`trains.Planetary.contact`."""
    for label, value in (("torque", torque), ("load_sharing_factor", load_sharing_factor)):
        if (
            isinstance(value, bool)
            or not isinstance(value, int | float)
            or not (math.isfinite(value) and value > 0)
        ):
            raise TrainError(f"{label} = {value!r}; valid is a finite number > 0")
    if load_sharing_factor < 1.0:
        raise TrainError(f"load_sharing_factor = {load_sharing_factor!r}; valid is >= 1")
    torques = _mesh_torques(stage, torque, fixed, input, output)
    placement = stage.placement(angles)
    z_sun, _, _, z_ring = stage.teeth
    meshes, phases, carried = {}, {}, {}
    for name, k1, k2 in _MESHES[stage.scheme]:
        pair = stage.meshes[name]
        if face_width is not None:
            pair = GearPair(pair.g1.with_(face_width=face_width),
                            pair.g2.with_(face_width=face_width))  # fmt: skip
        t1 = torques[name] * load_sharing_factor
        try:
            meshes[name] = pair.contact(t1, **options)
        except GearError as exc:
            raise TrainError(f"mesh {name}: {exc}") from None
        carried[name] = t1
        keys = (k1, k2)
        psi = placement.planet2_angles if "planet2" in keys else placement.planet_angles
        if "sun" in keys:
            phases[name] = tuple(mesh_phases(z_sun, psi, ring=False).tolist())
        elif "ring" in keys:
            phases[name] = tuple(mesh_phases(z_ring, psi, ring=True).tolist())
        else:
            phases[name] = None
    settings = {"torque": float(torque), "fixed": fixed, "input": input, "output": output,
                "load_sharing_factor": float(load_sharing_factor)}  # fmt: skip
    return StageContact(meshes, carried, phases, stage.n_planets, settings)
