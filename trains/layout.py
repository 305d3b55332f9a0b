"""Layer 3, statics: the plane layout of a train's axes, for its forces.

Members lie in one plane of parallel axes (z out of it). Coaxial members (couplings between
members that are not planets, :meth:`~trains.Train.coaxial`, the central members of a carrier
and the carrier itself) share an axis; each mesh of parallel axes sets the distance of its two
axes (its working centre distance, or ``m (z2 +- z1) / 2`` for tooth counts). The first member
sits at the origin; a member reached by one mesh lies in the direction ``angles[mesh]``
(degrees, default 0) from its mate, one reached by two meshes where both distances put it (the
planet triangle of a double-planet stage). A train whose distances cannot all hold is refused.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from gears import BevelPair
from trains.errors import TrainError
from trains.relations import FRAME, Relation

__all__ = ["Mesh", "direction", "mesh_geometry", "place", "shared_axes", "turn"]


@dataclass(frozen=True)
class Mesh:
    """One mesh's plane geometry: its external gear's member ``g1`` and the other ``g2``."""

    relation: Relation
    g1: str
    g2: str
    d1: float  # working pitch diameters, mm
    d2: float
    alpha: float  # working transverse pressure angle, deg
    beta: float  # gear 1's helix angle, deg
    alpha_n: float
    internal: bool
    distance: float  # centre distance, mm


def mesh_geometry(r: Relation, modules: Mapping[str, float], pressure_angle: float) -> Mesh | None:
    """The plane geometry of a mesh relation, or None for a link, coupling, bevel or worm mesh."""
    if r.kind != "mesh" or isinstance(r.pair, BevelPair):
        return None
    if r.pair is not None and r.gears is None:
        return None  # a worm mesh: crossed axes, not in the plane
    if r.pair is not None:
        p = r.pair
        first_on_a = not r.gears[0].internal  # the external gear is the pair's g1
        g1, g2 = (r.a, r.b) if first_on_a else (r.b, r.a)
        d1, d2 = p.working_diameters
        return Mesh(
            r,
            g1,
            g2,
            d1,
            d2,
            p.working_pressure_angle,
            p.g1.helix_angle,
            p.g1.pressure_angle,
            p.internal,
            p.center_distance,
        )
    if r.name not in modules:
        raise TrainError(
            f"mesh {r.name!r} has tooth counts but no gears: give module= (mm, or a mapping "
            "mesh name -> mm) for its pitch diameters m z, or build it from gears "
            "(Train.mesh(..., gears=...))"
        )
    module = modules[r.name]
    za, zb = r.teeth
    ring_is_a = r.internal and za > zb  # a ring has more teeth than its pinion
    g1, g2 = (r.b, r.a) if ring_is_a else (r.a, r.b)
    z1, z2 = (zb, za) if ring_is_a else (za, zb)
    d1, d2 = module * z1, module * z2
    dist = abs(d2 - d1) / 2 if r.internal else (d1 + d2) / 2
    return Mesh(r, g1, g2, d1, d2, pressure_angle, 0.0, pressure_angle, r.internal, dist)


class Axes:
    """Union of members that share an axis."""

    def __init__(self, members: Iterable[str]) -> None:
        self.parent = {m: m for m in members}

    def find(self, m: str) -> str:
        while self.parent[m] != m:
            self.parent[m] = self.parent[self.parent[m]]
            m = self.parent[m]
        return m

    def join(self, a: str, b: str) -> None:
        self.parent[self.find(a)] = self.find(b)


def shared_axes(train, planets: Mapping[str, tuple[str, int]]) -> Axes:
    """The members of ``train`` grouped by the axis they turn about: shafts coupled through two
    stages, the central members of a carrier with the carrier, declared coaxial groups (the
    ``planets`` turn about axes of their own)."""
    axes = Axes(train.members)
    for r in train.relations:
        if r.kind == "couple" and r.a not in planets and r.b not in planets:
            axes.join(r.a, r.b)  # a shaft through two stages (a planet's coupling is parallel)
        elif r.carrier != FRAME:
            for m in (r.a, r.b):
                if m not in planets:
                    axes.join(m, r.carrier)  # a central member turns about the carrier's axis
    for group in train.coaxial_groups:
        for m in group[1:]:
            axes.join(group[0], m)
    return axes


def place(
    train, meshes: Sequence[Mesh], axes: Axes, angles: Mapping[str, float]
) -> dict[str, np.ndarray]:
    """Axis position (x, y) of every axis group: the first at the origin, then by meshes."""
    links = [(axes.find(m.g1), axes.find(m.g2), m) for m in meshes]
    groups = list(dict.fromkeys(axes.find(m) for m in train.members if m != FRAME))
    pos: dict[str, np.ndarray] = {}
    pending = [g for g in groups if any(g in (a, b) for a, b, _ in links)]
    while pending:
        if not pos:
            pos[pending.pop(0)] = np.zeros(2)
            continue
        placed = False
        for g in pending:  # two placed mates fix a member (a planet triangle)
            known = [
                (b if a == g else a, m)
                for a, b, m in links
                if g in (a, b) and (b if a == g else a) in pos
            ]
            if len({k for k, _ in known}) >= 2:
                (p, m1), (q, m2) = known[0], next(k for k in known if k[0] != known[0][0])
                pos[g] = triangle(pos[p], m1.distance, pos[q], m2.distance)
                pending.remove(g)
                placed = True
                break
        if placed:
            continue
        for g in pending:
            known = [(a, b, m) for a, b, m in links if g in (a, b) and (b if a == g else a) in pos]
            if known:
                a, b, m = known[0]
                th = math.radians(float(angles.get(m.relation.name, 0.0)))
                step = m.distance * np.array([math.cos(th), math.sin(th)])
                # external: g2's axis at +a from g1's; internal: the ring's at -a from the pinion's
                step = -step if m.internal else step
                pos[g] = pos[a] + step if g == b else pos[b] - step
                pending.remove(g)
                break
        else:  # a group no mesh reaches from the placed ones: start it at the origin
            pos[pending.pop(0)] = np.zeros(2)
    for g in groups:
        pos.setdefault(g, np.zeros(2))
    for a, b, m in links:
        gap = float(np.linalg.norm(pos[a] - pos[b]))
        if a != b and abs(gap - m.distance) > 1e-9 * max(1.0, m.distance):
            raise TrainError(
                f"mesh {m.relation.name!r}: its centre distance is {m.distance:.6g} mm but the "
                f"other meshes put its axes {gap:.6g} mm apart: the train does not close (give "
                "module= per mesh, or gears whose centre distances agree)"
            )
    return pos


def triangle(p: np.ndarray, rp: float, q: np.ndarray, rq: float) -> np.ndarray:
    """The point at distance rp from p and rq from q, to the left of p -> q (or on the line)."""
    d = float(np.linalg.norm(q - p))
    if d == 0.0:
        return p + np.array([rp, 0.0])
    x = (d * d + rp * rp - rq * rq) / (2 * d)
    h = math.sqrt(max(rp * rp - x * x, 0.0))
    e = (q - p) / d
    return p + x * e + h * np.array([-e[1], e[0]])


def direction(m: Mesh, pos: Mapping[str, np.ndarray], axes: Axes, angle: float) -> np.ndarray:
    """Unit vector from the external gear's axis towards the pitch point."""
    p1, p2 = pos[axes.find(m.g1)], pos[axes.find(m.g2)]
    v = (p1 - p2) if m.internal else (p2 - p1)
    n = float(np.linalg.norm(v))
    if n > 1e-9 * max(1.0, m.distance):
        return v / n
    th = math.radians(angle)
    return np.array([math.cos(th), math.sin(th)])


def turn(v: np.ndarray, th: float) -> np.ndarray:
    """The plane vector ``v`` turned by ``th`` radians (counter-clockwise)."""
    c, s = math.cos(th), math.sin(th)
    return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])
