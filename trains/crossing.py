"""Layer 3, statics: a train's worm meshes, whose axes cross the plane of its other axes.

The drawing of :func:`trains.loads` lays the parallel axes of a train along z. A worm mesh
(:meth:`trains.Train.mesh` with a :class:`gears.WormPair`) joins two axes crossed at 90 degrees:
the wheel's axis is one of the train's axes; the worm's axis lies in the wheel's mid-plane
(``z = axial[mesh]``), at the centre distance ``a`` from the wheel's axis in the direction
``e`` at ``angles[mesh]`` degrees (default 0), and runs along ``h (z x e)``, where ``h = +1``
for a right-hand pair and ``-1`` for a left-hand one. With that direction the train's sign of
an external mesh, ``w_wheel = -(z_1 / z_2) w_worm``, is the pair's own kinematics (the thread
of a right-hand worm turning about ``z x e`` carries the wheel's pitch point along
``-(z x e)``). The frame of :func:`gears.forces.worm_pair_forces` (x from the worm's axis
towards the wheel's, y the wheel's axis, z the worm's) maps onto the drawing by
``x -> -e``, ``y -> h z``, ``z -> h (z x e)``.

The force comes from the power flow's torques on both members
(:func:`gears.forces.worm_torque_forces`): the worm's at its reference diameter ``d_m1``, the
wheel's at its arm ``a - d_m1 / 2`` (DIN 3996's ``d_m2 = 2 a - d_m1``, the reference diameter
of an unshifted wheel). So both members balance the power flow exactly whichever member
drives, the friction lies along the thread against the sliding of the driver's flank, and a
self-locking worm driven backwards (a hoist lowering its load while the motor pushes the worm
round) has its force too.

A member that turns with a worm shares its axis (a motor coupled to it). A placement this
drawing cannot make is refused, naming it: a worm mesh on a moving carrier, a worm whose
axis also carries a gear of a parallel mesh or the wheel of another worm mesh (a worm
reducer after a worm reducer turns the second worm's axis out of the plane), a worm on its
own wheel's axis.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass

import numpy as np

from gears import GearError, WormPair
from gears.forces import MeshForces, bearing_reactions, worm_torque_forces
from trains.errors import TrainError
from trains.relations import FRAME, Relation

__all__ = [
    "WormAxis",
    "axis_reactions",
    "moment_about",
    "place_worms",
    "worm_force",
    "worm_mesh",
    "worm_relations",
]

Z = np.array([0.0, 0.0, 1.0])


@dataclass(frozen=True)
class WormAxis:
    """Where one worm mesh puts its worm in the drawing (mm, unit vectors)."""

    relation: Relation
    worm: str
    wheel: str
    position: np.ndarray  # where the worm's axis crosses the line of centres, shape (3,)
    axis: np.ndarray  # the worm's axis, h (z x e)
    e: np.ndarray  # from the wheel's axis towards the worm's, (cos, sin, 0)
    hand: float  # +1 right, -1 left
    worm_arm: float  # d_m1 / 2
    wheel_arm: float  # a - d_m1 / 2

    @property
    def point(self) -> np.ndarray:
        """The pitch point, where the force acts."""
        return self.position - self.worm_arm * self.e


def worm_relations(train) -> list[Relation]:
    """The worm meshes of ``train`` (built from a :class:`gears.WormPair`)."""
    return [r for r in train.relations if r.kind == "mesh" and isinstance(r.pair, WormPair)]


def place_worms(
    worms: Iterable[Relation],
    find: Callable[[str], str],
    members: Iterable[str],
    parallel: Iterable[str],
    pos: dict[str, np.ndarray],
    angles: Mapping[str, float],
    axial: Mapping[str, float],
) -> dict[str, WormAxis]:
    """Place every worm's axis group beside its wheel (module docstring) and return each worm
    mesh's :class:`WormAxis` by name. ``find`` maps a member to its axis group, ``members`` are
    the train's members, ``parallel`` the members of its parallel meshes, ``pos`` the groups'
    plane positions (updated for the worms)."""
    worms = list(worms)
    members = list(members)
    wheels = {find(r.b): r.b for r in worms}
    on_plane = {find(m): m for m in parallel}
    seen: dict[str, str] = {}
    out = {}
    for r in worms:
        if r.carrier != FRAME:
            raise TrainError(
                f"worm mesh {r.name!r} rides on the carrier {r.carrier!r}: loads places worm "
                "meshes on the frame only; its torques are in trains.power_flow"
            )
        g = find(r.a)
        clash = (
            f"the wheel {r.b!r} of its own mesh"
            if g == find(r.b)
            else f"{on_plane[g]!r}, a gear of a parallel mesh"
            if g in on_plane
            else f"{wheels[g]!r}, the wheel of another worm mesh"
            if g in wheels
            else f"the worm of mesh {seen[g]!r}"
            if g in seen
            else None
        )
        if clash is not None:
            with_worm = [m for m in members if find(m) == g]
            raise TrainError(
                f"worm mesh {r.name!r}: the worm {r.a!r} turns about one axis with {clash} "
                f"(members {', '.join(repr(m) for m in with_worm)}); loads lays a worm's axis "
                "across the plane of the parallel axes beside its one wheel and cannot place "
                "that axis for both: the placement is ambiguous. Its torques are in "
                "trains.power_flow"
            )
        seen[g] = r.name
        pair: WormPair = r.pair
        th = np.radians(float(angles.get(r.name, 0.0)))
        e = np.array([np.cos(th), np.sin(th), 0.0])
        hand = 1.0 if pair.hand == "right" else -1.0
        a = float(pair.center_distance)
        wheel_xy = pos[find(r.b)]
        pos[g] = wheel_xy + a * e[:2]
        z = float(axial.get(r.name, 0.0))
        out[r.name] = WormAxis(
            r,
            r.a,
            r.b,
            np.array([*pos[g], z]),
            hand * np.cross(Z, e),
            e,
            hand,
            pair.worm_diameter / 2.0,
            a - pair.worm_diameter / 2.0,
        )
    return out


def worm_force(
    w: WormAxis, worm_torque: float, wheel_torque: float
) -> tuple[MeshForces, np.ndarray]:
    """The worm mesh's forces from the torques it puts on the worm (about ``w.axis``) and on
    the wheel (about +z), N m (a relation's torques in :func:`trains.power_flow`): the
    :class:`gears.forces.MeshForces` of :func:`gears.forces.worm_torque_forces` and the force on
    the worm in the drawing (N, shape (3,)); the wheel carries its opposite."""
    pair: WormPair = w.relation.pair
    # the torques that hold the members, in the pair's frame (y = h z); a left-hand pair is
    # the mirror image of a right-hand one in its worm's axial direction
    try:
        f = worm_torque_forces(-worm_torque, -wheel_torque, 2 * w.worm_arm, 2 * w.wheel_arm,
                               pair.lead_angle, pair.normal_pressure_angle)  # fmt: skip
    except GearError as exc:
        raise TrainError(f"worm mesh {w.relation.name!r}: {exc}") from None
    v = np.array(f.vector, float)
    v[2] *= w.hand
    frame = np.column_stack([-w.e, w.hand * Z, w.axis])  # the pair's x, y, z in the drawing
    return f, frame @ v + 0.0


def worm_mesh(w: WormAxis, flow) -> tuple[dict, np.ndarray, np.ndarray]:
    """A worm mesh's load from its relation's power flow ``flow``
    (:class:`trains.power.RelationPower`): the fields of its :class:`trains.loading.MeshLoad`
    (magnitudes on the worm and on the wheel: the worm's axial force is the wheel's tangential
    force), the force on the worm in the drawing and the pitch point."""
    f, v = worm_force(w, flow.torques.get(w.worm, 0.0), flow.torques.get(w.wheel, 0.0))
    ft, fa, fr, fn = (float(x) for x in (f.tangential, f.axial, f.radial, f.normal))
    point = w.point
    fields = {
        "name": w.relation.name,
        "members": (w.worm, w.wheel),
        "kind": "worm",
        "copies": 1,
        "tangential": (ft, fa),
        "radial": (fr, fr),
        "axial": (fa, ft),
        "normal": (fn, fn),
        "forces": {w.worm: v[None, :], w.wheel: -v[None, :] + 0.0},
        "points": {w.worm: point[None, :], w.wheel: point[None, :]},
        "angles": (float(np.degrees(np.arctan2(w.e[1], w.e[0]))),),
        "driver": flow.driver,
    }
    return fields, v, point


def axis_reactions(
    forces: np.ndarray, points: np.ndarray, bearings, axis: np.ndarray
) -> np.ndarray:
    """:func:`gears.forces.bearing_reactions` of a shaft along the unit vector ``axis`` (its
    bearings at ``bearings`` mm along it from the shaft's point where ``points`` start): the
    reactions (2, 3) in the drawing."""
    if axis[2] == 1.0:
        return bearing_reactions(forces, points, bearings)[0]
    x = np.cross(axis, Z)
    x /= np.linalg.norm(x)
    frame = np.column_stack([x, np.cross(axis, x), axis])  # the shaft's x, y, z
    local, _ = bearing_reactions(np.asarray(forces) @ frame, np.asarray(points) @ frame, bearings)
    return local @ frame.T + 0.0


def moment_about(point: np.ndarray, force: np.ndarray, axis: np.ndarray) -> float:
    """The moment of ``force`` (N) at ``point`` (mm, from a point of the axis) about the unit
    vector ``axis``, N mm; a TrainError where it passes float's range."""
    p, v = point, force
    with np.errstate(over="ignore", invalid="ignore"):
        m = float(p[0] * v[1] - p[1] * v[0] if axis[2] == 1.0 else np.cross(p, v) @ axis)
    if not np.isfinite(m):
        size, arm = float(np.max(np.abs(v))), float(np.max(np.abs(p)))
        raise TrainError(
            f"a mesh force of {size:.3g} N at {arm:.3g} mm: its moment overflows the "
            "floating-point range (about 1e308 N mm); valid are forces and positions whose "
            "moments stay finite (a smaller torque)"
        )
    return m
