"""Layer 3, statics.

Statics and efficiency of gear trains: torques, mesh powers, losses, self-locking.

Every relation of a :class:`~trains.willis.Train` is a lever: its ideal reaction puts the torques
``lambda * (k_a, k_b, -(k_a + k_b))`` on its members ``a``, ``b`` and carrier ``c`` (the
coefficients of the relation, so the torques balance and do no work in the allowed motion).
Losses follow the relative-power rule (Kreines; Müller, Epicyclic Drive Trains; Ozols §14-5): in the
frame of the carrier the relation is an ordinary mesh of efficiency ``eta``; the end that supplies
power in that relative motion (``-tau_a (w_a - w_c) > 0``) drives it, and the torque at the driven
end is
``eta`` times its ideal value. Which end drives depends on the torques, so the signs are found by
iteration: start from the ideal torques, take the drivers, solve, repeat until they do not change.

This reproduces Ozols (14.26) with the corrected exponent ``k`` on the planetary efficiency, the
self-locking range (14.27), the differential formulas (14.28)/(14.29) with the general sign rule
``h = sign(M_1 (w_1 - w_H))`` (a misprint in the book corrected), the Kreines formulas (Müller) and,
for a fixed-axis train, the product of the mesh efficiencies (Ozols (14.10)).

Examples
--------
>>> from trains import power_flow, simple_planetary
>>> pf = power_flow(simple_planetary(20, 30, 80), "sun", "carrier", fixed=["ring"],
...                 mesh_efficiency=0.98)
>>> round(pf.efficiency, 6), pf.self_locking
(0.96832, False)
>>> {m: round(t, 6) for m, t in pf.torques.items()}
{'frame': 0.0, 'sun': 1.0, 'planet': 0.0, 'carrier': -4.8416, 'ring': 3.8416}
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from gears.errors import GearError
from gears.meshing import check_friction
from trains.errors import TrainError
from trains.willis import FRAME, Motion, Train


@dataclass(frozen=True)
class RelationPower:
    """Power through one relation (mesh, link or coupling).

    Attributes
    ----------
    name : str
        The relation's name.
    driver : str or None
        The end (member) that supplies power in the carrier frame; None without relative motion.
    rolling_power : float
        Power entering at the driver end in the carrier frame (Kreines' rolling power).
    power : float
        Absolute power passing through: the sum of the powers the members put into it.
    loss : float
        Power lost in it (``(1 - eta) * rolling_power``).
    efficiency : float
        The efficiency used for it.
    torques : dict
        The torque it puts on each of its members (its ends and its carrier), in the units of
        ``input_torque``: a mesh's tooth load is ``|torques[end]|`` over that gear's pitch radius
        (for a planet member declared with ``Train.set_planets``, the sum over its copies).
    """

    name: str
    driver: str | None
    rolling_power: float
    power: float
    loss: float
    efficiency: float
    torques: dict[str, float] = field(default_factory=dict)


@dataclass(frozen=True)
class PowerFlow:
    """Result of :func:`power_flow`.

    Attributes
    ----------
    speeds : Motion
        Speed of every member (floats).
    torques : dict
        External torque on every member (input drive, output load, the holding torque of fixed
        members, the housing's reaction as ``"frame"``); they sum to zero.
    powers : dict
        ``torque * speed`` per member: positive where power enters the train.
    relations : dict
        :class:`RelationPower` per relation name.
    input_power, output_power : float
        Power supplied by the input(s); power delivered at the output.
    efficiency : float
        ``output_power / input_power``; negative means self-locking.
    self_locking : bool
        True when the output cannot be driven from the input (efficiency <= 0).
    circulating_power : float
        How much the largest power through a relation exceeds the input power (0 if none does):
        the power circulating in a closed loop, as in closed differentials.
    iterations : int
        Sign iterations needed.
    """

    speeds: Motion
    torques: dict[str, float]
    powers: dict[str, float]
    relations: dict[str, RelationPower]
    input_power: float
    output_power: float
    efficiency: float
    self_locking: bool
    circulating_power: float
    iterations: int

    @property
    def mesh_power(self) -> dict[str, float]:
        """Absolute power through every relation, by name."""
        return {n: r.power for n, r in self.relations.items()}

    @property
    def loss(self) -> float:
        """Total power lost (input minus output)."""
        return self.input_power - self.output_power

    def __str__(self) -> str:
        lines = [f"{'member':<12s} {'speed':>14s} {'torque':>14s} {'power':>14s}"]
        for m in self.torques:
            w = float(self.speeds[m])
            lines.append(f"{m:<12s} {w:14.6g} {self.torques[m]:14.6g} {self.powers[m]:14.6g}")
        lines.append(f"{'relation':<16s} {'driver':>10s} {'power':>12s} {'loss':>12s}")
        for r in self.relations.values():
            lines.append(f"{r.name:<16s} {r.driver or '-':>10s} {r.power:12.6g} {r.loss:12.6g}")
        lines.append(f"efficiency {self.efficiency:.6g}" + ("  (SELF-LOCKING)" * self.self_locking))
        if self.circulating_power > 0:
            lines.append(f"circulating power {self.circulating_power:.6g}")
        return "\n".join(lines)


def _efficiencies(train: Train, mesh_efficiency: Any, friction: Any = None) -> list:
    """Efficiency of every relation: the user's value where given (a mapping entry, or the
    scalar for every mesh and link), else with ``friction`` the Ozols (14.25) estimate from a
    mesh's :class:`gears.GearPair`, or for a :class:`gears.WormPair` the pair ``(worm driving,
    wheel driving)`` of Ozols (14.15), (14.18) (the second at or below zero when it locks), else
    1 (lossless)."""
    rel = train.relations
    if friction is not None:
        try:
            friction = check_friction(friction)  # the range lives once, beside (14.25)
        except GearError as exc:
            raise TrainError(str(exc)) from None
    geometric: dict[str, float] = {}
    if friction is not None:
        for r in rel:
            if r.pair is not None:
                try:  # a worm pair gives (worm driving, wheel driving)
                    geometric[r.name] = r.pair.mesh_efficiency(friction)
                except GearError as exc:  # e.g. a tip inside its base circle: no contact
                    raise TrainError(
                        f"relation {r.name!r}: no efficiency from its gears with friction "
                        f"{friction:g}: {exc}"
                    ) from None
    if isinstance(mesh_efficiency, Mapping):
        names = {r.name for r in rel}
        for k in mesh_efficiency:
            if k not in names:
                raise TrainError(
                    f"mesh_efficiency names unknown relation {k!r}; the relations are"
                    f" {', '.join(r.name for r in rel)}"
                )
        etas = [
            mesh_efficiency[r.name]
            if r.name in mesh_efficiency
            else 1.0
            if r.kind == "couple"
            else geometric.get(r.name, 1.0)
            for r in rel
        ]
    else:
        if mesh_efficiency is None:
            mesh_efficiency = 1.0
        etas = [1.0 if r.kind == "couple" else geometric.get(r.name, mesh_efficiency) for r in rel]
    out: list = []
    for r, e in zip(rel, etas, strict=True):
        if isinstance(e, tuple):  # a worm mesh's two directions, from its geometry
            out.append(tuple(float(v) for v in e))
            continue
        if isinstance(e, bool) or not isinstance(e, numbers.Real):
            raise TrainError(f"mesh_efficiency = {e!r} for {r.name!r}; valid is a number in (0, 1]")
        e = float(e)
        if not (0.0 < e <= 1.0):
            how = (
                f" (estimated from its geometry with friction {friction:g})"
                if r.name in geometric
                and not (isinstance(mesh_efficiency, Mapping) and r.name in mesh_efficiency)
                else ""
            )
            raise TrainError(
                f"mesh_efficiency = {e:.6g} for {r.name!r}{how}; valid is a number in (0, 1]"
            )
        out.append(e)
    return out


def power_flow(
    train: Train,
    input: str | Sequence[str],
    output: str,
    fixed: Iterable[str] = (),
    mesh_efficiency: Any = None,
    input_torque: float = 1.0,
    input_speed: float | Mapping[str, float] = 1.0,
    friction: float | None = None,
) -> PowerFlow:
    """Torques, powers, losses and efficiency of a train driven at ``input``, loaded at ``output``.

    Parameters
    ----------
    train : Train
    input : str or sequence of str
        The driving member, or several (a differential driven by two members, Ozols (14.28),
        (14.29)).
    output : str
        The driven member.
    fixed : iterable of str
        Members held by the housing.
    mesh_efficiency : float or mapping, optional
        Efficiency of every mesh and link in its carrier frame, or a mapping ``relation name ->
        efficiency`` (missing relations are lossless, or estimated with ``friction``).
        Couplings are lossless. Default 1 (lossless).
    friction : float, optional
        Mesh friction coefficient f (0 <= f < 1). Every mesh built from real gears
        (:meth:`Train.mesh` with ``gears=``/``pair=``) then gets its efficiency from its own
        geometry, :meth:`gears.GearPair.mesh_efficiency` (Ozols (14.25): contact ratio, tooth
        counts, internal or external), unless ``mesh_efficiency`` names it in a mapping; a
        scalar ``mesh_efficiency`` then applies to the kinematic-only meshes and links.
        ``"gears"`` takes every real mesh's efficiency at its operating point from its gears,
        :meth:`gears.GearPair.efficiency` (ISO/TR 14179-2: its torque per planet copy, its speed
        relative to its carrier; ``input_torque`` in N m and ``input_speed`` in rpm then), and a
        callable ``(pair, torque, speed) -> efficiency`` does the same with a model of one's own
        (``lambda p, t, n: p.efficiency(t, n, viscosity=20).efficiency``); both apply to the
        meshes of spur and helical gears (:class:`gears.GearPair`), the other relations (bevel
        and worm meshes among them) are lossless or estimated with ``friction``.
    input_torque : float
        Torque on the (first) input member; the result scales with it.
    input_speed : float or mapping
        Speed of the input, or ``{member: speed}`` for several inputs.

    Returns
    -------
    PowerFlow

    Raises
    ------
    TrainError
        If the kinematics are not determined by the inputs and fixed members, the input does
        no work, or the loss signs do not settle.

    Examples
    --------
    Ozols example 14-3: the David mechanism (i_1H = 1/10000, eta_H = 0.98) is self-locking when
    driven from gear 1, and 0.5 % efficient when driven from the carrier.

    >>> from trains import stepped_planetary
    >>> t = stepped_planetary(100, 101, 100, 99, meshes=("external", "external"))
    >>> eta = {"1-2": 0.98}
    >>> pf = power_flow(t, "1", "H", fixed=["3"], mesh_efficiency=eta)
    >>> pf.self_locking, round(pf.efficiency, 2)
    (True, -203.06)
    >>> round(power_flow(t, "H", "1", fixed=["3"], mesh_efficiency=eta).efficiency, 6)
    0.004976
    """
    inputs, fixed, speeds, tq = _flow_request(train, input, output, fixed, input_speed,
                                              input_torque)  # fmt: skip
    given = {**speeds, **{f: 0 for f in fixed if f != FRAME}}
    motion = train.solve(given)
    w = {m: float(motion[m]) for m in train.members}
    if not all(math.isfinite(x) for x in w.values()):
        raise TrainError("speeds must be finite")
    model = _mesh_model(mesh_efficiency)
    if model is None:
        etas = _efficiencies(train, mesh_efficiency, friction)
        balance = _Balance(train, inputs, output, fixed, w, etas, tq)
        x, levers, drivers, iteration = balance.settle()
        return balance.flow(x, levers, drivers, iteration)
    return _operating_flow(train, inputs, output, fixed, w, tq, model, friction)


#: Fixed-point steps of the operating-point efficiencies (each mesh's efficiency depends on its
#: load, which depends on the efficiencies; the load enters as F^0.2, so a few steps settle it).
OPERATING_STEPS = 30


def _mesh_model(mesh_efficiency: Any) -> Any:
    """The operating-point model asked for: ``"gears"`` (each mesh's
    :meth:`gears.GearPair.efficiency` with its defaults), a callable ``(pair, torque, speed) ->
    efficiency``, or None for the fixed efficiencies."""
    if isinstance(mesh_efficiency, str):
        if mesh_efficiency != "gears":
            raise TrainError(
                f"mesh_efficiency = {mesh_efficiency!r}; valid is a number in (0, 1], a mapping "
                "relation -> efficiency, 'gears' or a callable (pair, torque, speed)"
            )
        return lambda pair, torque, speed: pair.efficiency(torque, speed).efficiency
    if callable(mesh_efficiency) and not isinstance(mesh_efficiency, Mapping):
        return mesh_efficiency
    return None


def _operating_flow(
    train: Train, inputs: list[str], output: str, fixed: list[str], w: dict[str, float],
    tq: float, model: Any, friction: Any,
) -> PowerFlow:  # fmt: skip
    """The power flow with every real mesh's efficiency taken from ``model`` at its own torque
    (per planet copy, on its external gear) and speed relative to its carrier, found by
    fixed-point iteration from the lossless (or ``friction``) flow."""
    from gears.pair import GearPair  # the gears' own meshes: spur and helical pairs

    base = _efficiencies(train, None, friction)
    planets = dict(getattr(train, "_planets", {}))
    meshes = [(j, r) for j, r in enumerate(train.relations)
              if isinstance(r.pair, GearPair) and r.gears]  # fmt: skip
    etas = list(base)
    flow = None
    for _ in range(OPERATING_STEPS):
        balance = _Balance(train, inputs, output, fixed, w, etas, tq)
        x, levers, drivers, iteration = balance.settle()
        flow = balance.flow(x, levers, drivers, iteration)
        new = list(etas)
        for j, r in meshes:
            m1, m2 = (r.b, r.a) if r.gears[0].internal else (r.a, r.b)
            copies = max(planets.get(m1, 1), planets.get(m2, 1))
            torque = abs(flow.relations[r.name].torques.get(m1, 0.0)) / copies
            speed = abs(w[m1] - w[r.carrier])
            if torque == 0.0 or speed == 0.0:
                new[j] = 1.0  # unloaded or not rolling: no sliding loss
                continue
            try:
                e = model(r.pair, torque, speed)
            except (GearError, TrainError) as exc:
                raise TrainError(
                    f"relation {r.name!r}: no efficiency from its gears at {torque:.6g} N m, "
                    f"{speed:.6g} rpm: {exc}"
                ) from None
            if isinstance(e, bool) or not isinstance(e, numbers.Real) or not 0.0 < e <= 1.0:
                raise TrainError(
                    f"mesh_efficiency = {e!r} for {r.name!r} at {torque:.6g} N m, {speed:.6g} "
                    "rpm; valid is a number in (0, 1]"
                )
            new[j] = float(e)
        if max(abs(np.subtract(a, b)).max() for a, b in zip(new, etas, strict=True)) <= 1e-12:
            break
        etas = new
    return flow


def _flow_request(
    train: Train, input: Any, output: str, fixed: Any, input_speed: Any, input_torque: Any
) -> tuple[list[str], list[str], dict[str, Any], float]:
    """:func:`power_flow`'s members, input speeds and torque checked: ``(inputs, fixed,
    speeds, input torque)``."""
    inputs = [input] if isinstance(input, str) else list(input)
    if not inputs:
        raise TrainError("give at least one input member")
    for m in (*inputs, output):
        train._check_member(m)
    fixed = [fixed] if isinstance(fixed, str) else list(fixed)
    for f in fixed:
        train._check_member(f)
    if output in inputs or output in fixed or set(inputs) & set(fixed):
        raise TrainError("input, output and fixed members must all differ")
    if len(set(inputs)) != len(inputs):
        raise TrainError(f"input members repeated: {inputs}")
    if isinstance(input_speed, Mapping):
        speeds = {m: input_speed[m] if m in input_speed else None for m in inputs}
        missing = [m for m, v in speeds.items() if v is None]
        if missing or set(input_speed) - set(inputs):
            raise TrainError(
                f"input_speed must give exactly the inputs {inputs}, got {list(input_speed)}"
            )
    elif len(inputs) == 1:
        speeds = {inputs[0]: input_speed}
    else:
        raise TrainError("with several inputs, give input_speed as a mapping {member: speed}")
    tq = float(input_torque)
    if not math.isfinite(tq) or tq == 0:
        raise TrainError(f"input_torque must be finite and non-zero, got {input_torque!r}")
    return inputs, fixed, speeds, tq


class _Balance:
    """The torque balance of every member of a train at its speeds ``w``: one unknown per
    relation (its force) and per reacting member (output, fixed members, frame, the inputs after
    the first), each relation's loss charged at the end that drives it in relative motion."""

    def __init__(self, train: Train, inputs: list[str], output: str, fixed: list[str],
                 w: dict[str, float], etas: list[float], tq: float) -> None:  # fmt: skip
        self.inputs, self.output, self.fixed = inputs, output, fixed
        self.w, self.etas, self.tq = w, etas, tq
        self.members = list(train.members)
        self.row = {m: i for i, m in enumerate(self.members)}
        self.rels = train.relations
        self.nr = len(self.rels)
        # unknown external torques: output, fixed members, frame, the inputs after the first
        self.reacting = [output, *[f for f in fixed if f != FRAME], FRAME, *inputs[1:]]
        self.ncol = self.nr + len(self.reacting)
        self.rhs = np.zeros(len(self.members))
        self.rhs[self.row[inputs[0]]] = -tq  # member balance: T_i + sum_j B_ji lambda_j = 0
        self.rel_u = []
        for r in self.rels:
            if r.kind == "couple":
                self.rel_u.append((0.0, 0.0))
            else:
                self.rel_u.append((w[r.a] - w[r.carrier], w[r.b] - w[r.carrier]))

    def eta(self, j: int, driver: str | None) -> float:
        """The efficiency of relation ``j`` with ``driver`` driving (a worm mesh has one for
        each end)."""
        e = self.etas[j]
        if isinstance(e, tuple):
            return e[1] if driver == self.rels[j].b else e[0]
        return e

    def lever(self, j: int, driver: str | None) -> dict[str, float]:
        r = self.rels[j]
        ka, kb = float(r.k_a), float(r.k_b)
        if driver == r.a:
            kb *= self.eta(j, driver)
        elif driver == r.b:
            ka *= self.eta(j, driver)
        if r.kind == "couple":
            return {r.a: ka, r.b: kb}
        out = {r.a: ka, r.b: kb}
        out[r.carrier] = out.get(r.carrier, 0.0) - (ka + kb)
        return out

    def solve(self, drivers: list[str | None]) -> tuple[np.ndarray, list[dict[str, float]]]:
        a = np.zeros((len(self.members), self.ncol))
        levers = [self.lever(j, d) for j, d in enumerate(drivers)]
        for j, lev in enumerate(levers):
            for m, k in lev.items():
                a[self.row[m], j] += k
        for i, m in enumerate(self.reacting):
            a[self.row[m], self.nr + i] = 1.0
        rhs, tq = self.rhs, self.tq
        x, *_ = np.linalg.lstsq(a, rhs, rcond=None)
        with np.errstate(over="ignore", invalid="ignore"):  # a torque near float's largest
            resid = np.abs(a @ x - rhs).max() if len(rhs) else 0.0
            bound = 1e-9 * max(1.0, abs(tq)) * max(1.0, np.abs(x).max())
        if np.all(np.isfinite(x)) and not np.isfinite(resid):
            raise TrainError(
                f"input_torque = {tq:g}: the train's torques overflow the floating-point range "
                "(about 1e308); valid is a smaller torque"
            )
        if not np.all(np.isfinite(x)) or resid > bound:
            raise TrainError(
                "the torques cannot balance: the train is not statically determined by the"
                f" input {self.inputs}, output {self.output!r} and fixed members {self.fixed}"
            )
        return x, levers

    def drivers_of(
        self, x: np.ndarray, levers: list[dict[str, float]], previous: list | None = None
    ) -> list[str | None]:
        """The end of every relation that supplies power in its relative motion. Where both
        ends supply it (a self-locking mesh driven backwards: a worm held by its wheel must be
        pushed round, and all the power is lost in the mesh), the end already driving stays."""
        out: list[str | None] = []
        scale = abs(self.tq) * max(1.0, max(abs(v) for v in self.w.values()))
        for j, r in enumerate(self.rels):
            if r.kind == "couple":
                out.append(None)
                continue
            ua, ub = self.rel_u[j]
            pa = -x[j] * levers[j][r.a] * ua  # relative power into the relation at end a
            pb = -x[j] * levers[j][r.b] * ub
            tol = 1e-13 * scale
            before = previous[j] if previous is not None else None
            if pa > tol and pb > tol and before in (r.a, r.b):
                out.append(before)
                continue
            out.append(r.a if pa > tol else r.b if pb > tol else None)
        return out

    def settle(self) -> tuple[np.ndarray, list[dict[str, float]], list[str | None], int]:
        """Solve, charge each loss at its relation's driving end, and solve again until the
        drivers repeat: ``(x, levers, drivers, iterations)``."""
        nr, rels = self.nr, self.rels
        drivers: list[str | None] = [None] * nr
        x, levers = self.solve(drivers)
        seen = []
        iteration = 1
        for iteration in range(1, 4 * nr + 8):  # noqa: B007 - reported below
            new = self.drivers_of(x, levers, drivers)
            if new == drivers:
                break
            if new in seen:
                raise TrainError(
                    f"the loss signs do not settle (relations {[r.name for r in rels]} alternate"
                    " drivers): the power flow is ambiguous at this operating point"
                )
            seen.append(drivers)
            drivers = new
            x, levers = self.solve(drivers)
        else:  # pragma: no cover - bounded by the number of sign patterns tried
            raise TrainError("the loss signs did not settle")
        return x, levers, drivers, iteration

    def flow(self, x: np.ndarray, levers: list[dict[str, float]], drivers: list[str | None],
             iteration: int) -> PowerFlow:  # fmt: skip
        """The :class:`PowerFlow` of the settled balance ``x``."""
        inputs, output, w, tq = self.inputs, self.output, self.w, self.tq
        members, rels, reacting, rel_u = self.members, self.rels, self.reacting, self.rel_u
        nr = self.nr
        torques = {m: 0.0 for m in members}
        torques[inputs[0]] = tq
        tiny = 1e-13 * max(abs(tq), float(np.abs(x[nr:]).max(initial=0.0)))
        for i, m in enumerate(reacting):
            torques[m] = float(x[nr + i]) if abs(x[nr + i]) > tiny else 0.0  # round-off to 0
        powers = {m: torques[m] * w[m] + 0.0 for m in members}  # no -0.0
        p_in = sum(powers[m] for m in inputs)
        if not p_in > 0:
            raise TrainError(
                f"the inputs {inputs} supply no power (input power {p_in:.6g}); reverse the input"
                " torque or choose another input"
            )
        p_out = -powers[output]
        relations: dict[str, RelationPower] = {}
        for j, r in enumerate(rels):
            lev = levers[j]
            absolute = sum(max(0.0, -x[j] * k * w[m]) for m, k in lev.items())
            d = drivers[j]
            if d is None:
                rolling = loss = 0.0
            else:
                u = rel_u[j][0] if d == r.a else rel_u[j][1]
                rolling = float(-x[j] * lev[d] * u)
                loss = (1.0 - self.eta(j, d)) * rolling
            on = {m: float(k * x[j]) + 0.0 for m, k in lev.items()}  # the relation's torque on m
            relations[r.name] = RelationPower(
                r.name, d, rolling, float(absolute), loss, self.eta(j, d), on
            )
        eff = p_out / p_in
        biggest = max((r.power for r in relations.values()), default=0.0)
        circulating = biggest - p_in if biggest > p_in * (1 + 1e-9) else 0.0
        return PowerFlow(
            speeds=Motion(w),
            torques=torques,
            powers=powers,
            relations=relations,
            input_power=p_in,
            output_power=p_out,
            efficiency=eff,
            self_locking=eff <= 0,
            circulating_power=circulating,
            iterations=iteration,
        )


# ------------------------------------------------------------------- closed forms (Ozols §14)


def series_efficiency(*efficiencies: float) -> float:
    """Efficiency of units in series, Ozols (14.10) / Joldasbekov (9.7): the product.

    Examples
    --------
    Ozols example 14-1 (hoist: two spur stages 0.95 and a drum 0.90):

    >>> round(series_efficiency(0.95, 0.95, 0.90), 5)
    0.81225
    """
    return float(np.prod([float(e) for e in efficiencies]))


def parallel_efficiency(
    efficiencies: Sequence[float],
    *,
    input_power: Sequence[float] | None = None,
    output_power: Sequence[float] | None = None,
) -> float:
    """Efficiency of branches in parallel, Ozols (14.12)/(14.13), Joldasbekov (9.8).

    Give the power of each branch either at its input (``eta = sum(eta_i nu_i)``, nu = input
    shares) or at its output (``eta = sum(N_i) / sum(N_i / eta_i)``).

    Examples
    --------
    Ozols example 14-2: branches delivering 15 hp at 0.95 and 20 hp at 0.98.

    >>> round(parallel_efficiency([0.95, 0.98], output_power=[15, 20]), 5)
    0.96691
    """
    eta = np.asarray(efficiencies, dtype=float)
    if (input_power is None) == (output_power is None):
        raise TrainError("give exactly one of input_power and output_power")
    if np.any(eta <= 0) or np.any(eta > 1):
        raise TrainError(f"efficiencies must be in (0, 1], got {list(eta)}")
    if input_power is not None:
        p = np.asarray(input_power, dtype=float)
        if p.shape != eta.shape or p.sum() <= 0:
            raise TrainError("input_power must be one non-negative power per branch")
        return float((eta * p).sum() / p.sum())
    p = np.asarray(output_power, dtype=float)
    if p.shape != eta.shape or p.sum() <= 0:
        raise TrainError("output_power must be one non-negative power per branch")
    return float(p.sum() / (p / eta).sum())


def planetary_efficiency(ratio: Any, basic_efficiency: Any, driver: str = "gear") -> Any:
    """Efficiency of a planetary train (gear 1, fixed gear n, carrier H), Ozols (14.26).

    ``i_1H eta^k = 1 - (1 - i_1H) eta_H^h`` with ``k = +1`` when gear 1 drives (``driver =
    "gear"``) and ``k = -1`` when the carrier drives; ``h = +1`` when gear 1 supplies power in
    the carrier frame (for gear 1 driving: ``i_1H < 0`` or ``i_1H > 1``), else ``-1``. The
    printed (14.26) has the exponent ``h`` on the left, a misprint: only ``k``
    follows from the derivation and reproduces example 14-3. A closed form to check
    :func:`power_flow` against; ``ratio`` and ``basic_efficiency`` broadcast (arrays give an
    array, numbers a float).

    Examples
    --------
    >>> round(planetary_efficiency(4, 0.98), 5), round(planetary_efficiency(4, 0.98, "carrier"), 5)
    (0.985, 0.98492)
    """
    try:
        i = np.asarray(ratio, float)
    except (TypeError, ValueError):
        raise TrainError(f"the planetary ratio must be a finite non-zero number, got {ratio!r}") \
            from None  # fmt: skip
    if not np.all(np.isfinite(i) & (i != 0)):
        raise TrainError(f"the planetary ratio must be finite and non-zero, got {ratio!r}")
    if driver not in ("gear", "carrier"):
        raise TrainError(f"driver must be 'gear' or 'carrier', got {driver!r}")
    k = 1 if driver == "gear" else -1
    h = np.where((0 < i) & (i < 1), -1.0, 1.0) * k
    x = (1 - (1 - i) * np.asarray(basic_efficiency, float) ** h) / i
    out = x if k == 1 else 1 / x
    return float(out) if np.ndim(out) == 0 else out


def self_locking_range(basic_efficiency: float) -> tuple[float, float]:
    """Ratios ``i_1H`` for which a planetary train locks when gear 1 drives, Ozols (14.27).

    ``1 - 1/eta_H < i_1H < 1 - eta_H``.

    Examples
    --------
    Ozols example 14-3: ``-0.0204 < i_1H < 0.02`` for eta_H = 0.98.

    >>> lo, hi = self_locking_range(0.98)
    >>> round(lo, 4), round(hi, 4)
    (-0.0204, 0.02)
    """
    e = float(basic_efficiency)
    if not 0 < e <= 1:
        raise TrainError(f"efficiency must be in (0, 1], got {basic_efficiency!r}")
    return 1 - 1 / e, 1 - e
