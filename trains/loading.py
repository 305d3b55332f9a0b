"""Layer 4, statics: the force of every mesh and the load on every bearing of a train.

:func:`loads` runs :func:`trains.power.power_flow` (torques with losses, the direction of power)
and turns each member's mesh torques into forces (:func:`gears.forces.mesh_forces`: Ozols
(11.8), ISO 6336-1 (1)): every mesh of parallel axes gets its tangential, radial and axial
force, and every member the resultant on its bearings as a vector, so that its forces and
torques balance: an idler's bearing carries ``2 R cos alpha`` (Ozols (11.9)), a two-stage shaft
carries ``R_12`` and ``R_23 = R_12 r_2 / r_2'`` (Ozols (11.10)), a planet's pin the sum of its two
mesh forces, the carrier the pins of all planets (Ozols (11.11)).

The drawing plane: members lie in one plane of parallel axes (z out of it). Coaxial members
(couplings, :meth:`~trains.Train.coaxial`, the central members of a carrier and the carrier
itself) share an axis; each mesh sets the distance of its two axes (its working centre
distance). The first member sits at the origin; a member reached by one mesh lies in the
direction ``angles[mesh]`` (degrees, default 0: the textbooks' collinear trains) from its mate,
one reached by two meshes where both distances put it (the planet triangle of a double-planet
stage). A mesh's direction is then the direction from its external gear's axis to the pitch
point. Planets declared with :meth:`~trains.Train.set_planets` are spread evenly about their
carrier's axis (``360 k / n`` degrees), each carrying ``1/n`` of the mesh's torque, times a
load-sharing factor per mesh when given.

With losses (``mesh_efficiency`` or ``friction``) the two gears of a mesh carry different
torques; each gear's force follows from its own torque, so every member balances exactly and
the two forces of one mesh differ by the loss (Newton's third law holds to ``1 - eta``).

Meshes of kinematic-only relations (tooth counts, no gears) get their diameters from
``module=`` (``d = m z``, spur); links (bevel pairs by the arrow rule, chains, worms by ratio)
carry no force. Bevel meshes (:class:`gears.BevelPair`) report their forces per mesh, in the
pair's frame, left out of the members' resultants. A worm mesh (:class:`gears.WormPair`) is in
3D (:mod:`trains.crossing`): the worm's axis crosses the plane in the wheel's mid-plane, its
force (from both members' torques, the friction set by the member that drives) loads the
wheel and the worm, whose bearings carry it along and across the worm's own axis.
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from gears import MATERIALS, BevelPair, Gear, GearError
from gears.display import html_table
from gears.forces import bevel_pair_forces, centrifugal_force, mesh_forces
from trains.crossing import axis_reactions, moment_about, place_worms, worm_mesh, worm_relations
from trains.errors import TrainError
from trains.layout import Axes, Mesh, direction, mesh_geometry, place, shared_axes, turn
from trains.power import PowerFlow, power_flow
from trains.relations import FRAME, Relation
from trains.willis import Train

#: The most copies of one planet :func:`loads` places (the work is one force per copy and mesh).
MAX_COPIES = 1000

__all__ = ["MemberLoad", "MeshLoad", "TrainLoads", "loads", "planetary_loads", "solid_mass"]


@dataclass(frozen=True)
class MeshLoad:
    """The forces of one mesh (N), per planet copy.

    Attributes
    ----------
    name : str
    members : (str, str)
        The relation's members ``(a, b)``.
    kind : str
        ``"spur"``, ``"helical"``, ``"internal"``, ``"bevel"``, ``"worm"`` or ``"link"`` (no
        force).
    copies : int
        How many copies carry it (the planet count), each at ``angles[k]`` degrees.
    tangential, radial, axial, normal : (float, float)
        Magnitudes on the gear of ``a`` and of ``b``, per copy (a worm mesh: the worm's axial
        force is the wheel's tangential force and the other way round; ``normal`` is W).
    forces : dict
        Member -> the force on its gear, shape ``(copies, 3)``, in the drawing's frame.
    points : dict
        Member -> where the force acts (the pitch point), shape ``(copies, 3)``, mm.
    angles : tuple of float
        The direction of each copy's line of centres (from the external gear's axis; a worm
        mesh: from the wheel's axis to the worm's), degrees.
    driver : str or None
        The member that drives the mesh in its relative motion in the power flow (the friction
        acts against its flank's sliding); None without relative motion.
    """

    name: str
    members: tuple[str, str]
    kind: str
    copies: int
    tangential: tuple[float, float]
    radial: tuple[float, float]
    axial: tuple[float, float]
    normal: tuple[float, float]
    forces: dict[str, np.ndarray] = field(repr=False)
    points: dict[str, np.ndarray] = field(repr=False)
    angles: tuple[float, ...] = ()
    driver: str | None = None


@dataclass(frozen=True)
class MemberLoad:
    """The loads on one member (N, N m, mm).

    Attributes
    ----------
    name : str
    torque : float
        The external torque on it from the power flow (input, output, holding; 0 for an idler
        or a planet).
    force : ndarray, shape (3,)
        The resultant of the mesh forces on it (a planet: on one copy, with its centrifugal
        force when given; a carrier: the pins of all its planets).
    bearing : ndarray, shape (3,)
        The force of its bearings on it: ``-force`` (a planet: its pin's).
    moment : float
        The moment of those forces about its axis, N m: ``moment + torque = 0``.
    position : ndarray, shape (3,)
        A point of its axis in the drawing (a planet: copy 0's; a worm: where its axis crosses
        the line of centres).
    copies : int
    carried_by : str
        Where its bearings sit: ``"frame"``, or the carrier of a planet.
    reactions : ndarray or None
        With ``bearings=``: the force of each of its two bearings, shape (2, 3).
    axis : ndarray, shape (3,)
        The direction of its axis: +z, or across the plane for a worm (and what turns with it).
    """

    name: str
    torque: float
    force: np.ndarray
    bearing: np.ndarray
    moment: float
    position: np.ndarray
    copies: int = 1
    carried_by: str = FRAME
    reactions: np.ndarray | None = None
    axis: np.ndarray = field(default_factory=lambda: np.array([0.0, 0.0, 1.0]), repr=False)

    @property
    def radial_load(self) -> float:
        """``|bearing|`` across its axis (the radial bearing load), N."""
        b = self.bearing - self.axial_force * self.axis
        return float(math.hypot(math.hypot(b[0], b[1]), b[2]))

    @property
    def axial_force(self) -> float:
        """The bearing force along its axis (signed; the axial bearing load is its size), N."""
        return float(np.dot(self.bearing, self.axis))


@dataclass(frozen=True)
class TrainLoads:
    """What :func:`loads` returns; ``print`` shows its tables, a notebook its HTML.

    Attributes
    ----------
    flow : PowerFlow
        The power flow the forces come from (torques with losses).
    meshes : dict
        :class:`MeshLoad` per relation name (links and couplings with zero forces).
    members : dict
        :class:`MemberLoad` per member (the frame left out).
    notes : dict
        A planetary stage's figures (:meth:`trains.Planetary.loads`): planet mass, radius and
        centrifugal force, carrier speed and torque, the balancing moment, the net radial force
        on the sun and the carrier; empty for a train.
    """

    flow: PowerFlow
    meshes: dict[str, MeshLoad]
    members: dict[str, MemberLoad]
    notes: dict[str, float] = field(default_factory=dict)

    def rows(self) -> tuple[list[tuple], list[tuple]]:
        """Text rows of the two tables: meshes, then members."""
        meshes = [
            (
                m.name,
                m.kind,
                m.copies,
                *(f"{v[0]:.2f}" for v in (m.tangential, m.radial, m.axial, m.normal)),
            )
            for m in self.meshes.values()
        ]
        members = [
            (
                b.name,
                f"{round(b.torque, 4) + 0.0:.4f}",
                f"{b.radial_load:.2f}",
                f"{abs(b.axial_force):.2f}",
                f"{round(b.moment, 4) + 0.0:.4f}",
                b.carried_by if b.copies == 1 else f"{b.carried_by} x{b.copies}",
            )
            for b in self.members.values()
        ]
        return meshes, members

    MESH_COLUMNS = ("mesh", "kind", "copies", "F_t [N]", "F_r [N]", "F_a [N]", "F_n [N]")
    MEMBER_COLUMNS = (
        "member",
        "torque [N m]",
        "radial [N]",
        "axial [N]",
        "moment [N m]",
        "bearing on",
    )

    def __str__(self) -> str:
        meshes, members = self.rows()
        out = []
        for cols, rows in ((self.MESH_COLUMNS, meshes), (self.MEMBER_COLUMNS, members)):
            width = [max(len(str(c)), *(len(str(r[i])) for r in rows)) for i, c in enumerate(cols)]
            out.append("  ".join(f"{c:>{w}s}" for c, w in zip(cols, width, strict=True)))
            out += ["  ".join(f"{v!s:>{w}s}" for v, w in zip(r, width, strict=True)) for r in rows]
            out.append("")
        out += [f"{k}: {v:.6g}" for k, v in self.notes.items()]
        return "\n".join(out if self.notes else out[:-1])

    def _repr_html_(self) -> str:
        meshes, members = self.rows()
        return (
            html_table(self.MESH_COLUMNS, meshes, caption="mesh forces (per planet copy)")
            + "\n"
            + html_table(self.MEMBER_COLUMNS, members, caption="bearing loads")
            + (
                html_table(
                    ["", ""], [(k, f"{v:.6g}") for k, v in self.notes.items()], caption="stage"
                )
                if self.notes
                else ""
            )
        )

    def figure(self, outlines: Iterable[Any] = (), ax: Any = None) -> Any:
        """The mesh force on each mesh's first member at every pitch point (red) and every
        member's bearing reaction at its axis (blue; a planet's pin at its first copy), drawn
        on ``outlines`` (shapely polygons in the same frame, e.g. ``Planetary.outlines()``
        values) with :func:`gears.figures.forces.forces_figure`; a matplotlib Figure."""
        from gears.figures.forces import forces_figure

        arrows = []
        for mesh in self.meshes.values():
            if not mesh.forces:
                continue
            first = mesh.members[0]
            for f, p in zip(mesh.forces[first], mesh.points[first], strict=True):
                arrows.append((p[0], p[1], f[0], f[1], mesh.name, "mesh"))
        for m in self.members.values():
            b, at = m.bearing, m.position
            if math.hypot(b[0], b[1]) > 1e-9 * max(1.0, *(abs(x) for x in b)):
                kind = "pin" if m.carried_by != FRAME else "bearing"
                arrows.append((at[0], at[1], b[0], b[1], f"{m.name} {m.radial_load:.0f} N", kind))
        if isinstance(outlines, Mapping):
            outlines = list(outlines.values())
        return forces_figure(
            outlines, arrows, ax, "mesh forces (red), bearings (blue), pins (green)"
        )


def _planets(train: Train, flow: PowerFlow) -> dict[str, tuple[str, int]]:
    """Planet member -> (its carrier, copies): those declared with ``set_planets``, else the
    members that mesh only on one moving carrier and carry no external torque."""
    declared = dict(getattr(train, "_planets", {}))
    out: dict[str, tuple[str, int]] = {}
    for m in train.members:
        rels = [r for r in train.relations if m in (r.a, r.b)]
        carriers = {r.carrier for r in rels if r.kind == "mesh"}
        on_carrier = rels and all(r.kind == "mesh" for r in rels) and len(carriers) == 1
        c = next(iter(carriers)) if carriers else FRAME
        if m in declared and c != FRAME:
            out[m] = (c, int(declared[m]))
        elif on_carrier and c != FRAME and abs(flow.torques.get(m, 0.0)) == 0.0:
            out[m] = (c, 1)
    return out


# --------------------------------------------------------------------------------- the loads


def _mapping(name: str, value: Any, keys: Iterable[str], what: str) -> dict[str, Any]:
    if value is None:
        return {}
    if not isinstance(value, Mapping):
        raise TrainError(f"{name} = {value!r}; valid is a mapping {what}")
    keys = set(keys)
    for k in value:
        if k not in keys:
            raise TrainError(f"{name} names {k!r}; valid names are {', '.join(sorted(keys))}")
    return dict(value)


def _real(name: str, value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TrainError(f"{name} = {value!r}; valid is a finite number")
    v = float(value)
    if not math.isfinite(v):
        raise TrainError(f"{name} = {value!r}; valid is a finite number")
    return v


def loads(
    train: Train,
    input: str | Sequence[str],
    output: str,
    fixed: Iterable[str] = (),
    torque: float = 1.0,
    speed: float | Mapping[str, float] = 1.0,
    mesh_efficiency: float | Mapping[str, float] | None = None,
    friction: float | None = None,
    module: float | None = None,
    pressure_angle: float = 20.0,
    angles: Mapping[str, float] | None = None,
    axial: Mapping[str, float] | None = None,
    bearings: Mapping[str, tuple[float, float]] | None = None,
    centrifugal: Mapping[str, float] | None = None,
    planet_angles: Mapping[str, Sequence[float]] | None = None,
    load_sharing: Mapping[str, float] | None = None,
) -> TrainLoads:
    """The force of every mesh and the load on every member's bearings (module docstring).

    Parameters
    ----------
    train, input, output, fixed, mesh_efficiency, friction
        As for :func:`trains.power_flow`.
    torque : float
        Torque on the (first) input member, N m.
    speed : float or mapping
        Speed of the input(s) (any unit: the forces do not depend on it).
    module : float or mapping, optional
        Module (mm) of meshes given by tooth counts only (pitch diameters ``m z``), or a
        mapping mesh name -> module (a stepped planet's two meshes close at different modules).
    pressure_angle : float
        Their pressure angle, degrees (default 20).
    angles : mapping, optional
        Mesh name -> direction (degrees) in which it places the member it reaches (default 0;
        a worm mesh places the worm's axis).
    axial : mapping, optional
        Mesh name -> axial position (mm) of its mid-plane, for ``bearings`` (default 0).
    bearings : mapping, optional
        Member -> ``(z_A, z_B)``: the axial positions (mm) of its two bearings along its axis
        (a worm's from its :attr:`MemberLoad.position`, along :attr:`MemberLoad.axis`); A
        locates axially. Fills :attr:`MemberLoad.reactions` (:mod:`gears.forces`).
    centrifugal : mapping, optional
        Planet member -> its centrifugal force, N (outwards from its carrier's axis; the pin
        carries it).
    planet_angles : mapping, optional
        Planet member -> the angle of each copy about its carrier's axis, degrees (unequal
        spacing; default ``360 k / n``). Only the differences count: copy 0 lies where the
        meshes place it.
    load_sharing : mapping, optional
        Planet member -> the load-sharing factor K_gamma (1 <= K_gamma <= n): copy 0 carries
        ``K_gamma / n`` of its meshes' torque and the others share the rest equally (ISO
        6336-1 K_gamma; the unequal shares load the sun's and the carrier's bearings).

    Returns
    -------
    TrainLoads

    Raises
    ------
    TrainError
        What :func:`trains.power_flow` refuses, a kinematic mesh without ``module``, unknown
        names in the mappings, bad numbers, a worm axis it cannot place (:mod:`trains.crossing`).

    Examples
    --------
    Ozols section 11-2 (11.9): an idler between two gears, all centres on one line,
    M_1 = 100 N m, r_1 = 50 mm, alpha = 20 deg: the idler's bearing carries 2 R cos alpha.

    >>> t = Train()
    >>> t.mesh("1", "2", teeth=(20, 30)); t.mesh("2", "3", teeth=(30, 40))
    >>> ld = loads(t, "1", "3", torque=100, module=5)
    >>> round(ld.members["2"].radial_load, 6)
    4000.0
    """
    torque = _real("torque", torque)
    pressure_angle = _real("pressure_angle", pressure_angle)
    if not 0.0 < pressure_angle < 90.0:
        raise TrainError(f"pressure_angle = {pressure_angle:g}; valid is 0 < pressure_angle < 90")
    names = [r.name for r in train.relations]
    if isinstance(module, Mapping):
        modules = _mapping("module", module, names, "mesh name -> mm")
    else:
        modules = {} if module is None else dict.fromkeys(names, module)
    for k, v in modules.items():
        if not _real(f"module[{k!r}]", v) > 0:
            raise TrainError(f"module = {v!r} for mesh {k!r}; valid is a number > 0 (mm)")
    angles = {
        k: _real(f"angles[{k!r}]", v)
        for k, v in _mapping("angles", angles, names, "mesh name -> degrees").items()
    }
    axial = {
        k: _real(f"axial[{k!r}]", v)
        for k, v in _mapping("axial", axial, names, "mesh name -> mm").items()
    }
    bearings = _mapping("bearings", bearings, train.members, "member -> (z_A, z_B)")
    flow = power_flow(train, input, output, fixed, mesh_efficiency, torque, speed, friction)
    planets = _planets(train, flow)
    centrifugal = {
        k: _real(f"centrifugal[{k!r}]", v)
        for k, v in _mapping("centrifugal", centrifugal, planets, "planet -> N").items()
    }
    spread = _spread(planets, planet_angles, load_sharing)
    geo = [
        g for r in train.relations if (g := mesh_geometry(r, modules, pressure_angle)) is not None
    ]
    for r in train.relations:
        if r.kind == "mesh" and r.carrier in planets:
            raise TrainError(
                f"mesh {r.name!r} rides on {r.carrier!r}, itself a planet of "
                f"{planets[r.carrier][0]!r}: "
                "loads does not place carriers on carriers (a biplanetary train); its torques "
                "are in trains.power_flow"
            )
    axes = shared_axes(train, planets)
    pos = place(train, geo, axes, angles)
    parallel = [g for m in geo for g in (m.g1, m.g2)]
    worms = place_worms(worm_relations(train), axes.find, train.members, parallel, pos, angles,
                        axial)  # fmt: skip
    meshes = {}
    on: dict[str, list[tuple[int, np.ndarray, np.ndarray]]] = {m: [] for m in train.members}
    for m in geo:
        meshes[m.relation.name] = _mesh_load(m, flow, spread, pos, axes, angles, axial, on)
    for name, w in worms.items():  # a force across the plane (trains.crossing)
        fields, v, point = worm_mesh(w, flow.relations[name])
        on[w.worm].append((0, v, point - w.position, point))
        on[w.wheel].append((0, -v + 0.0, point - [*pos[axes.find(w.wheel)], 0.0], point))
        meshes[name] = MeshLoad(**fields)
    for r in train.relations:
        if r.name not in meshes:
            meshes[r.name] = _link_load(r, flow, spread)
    crossed = {axes.find(w.worm): (w.position, w.axis) for w in worms.values()}
    geometric = {m.relation.name for m in geo} | set(worms)
    members = _members(train, flow, (planets, spread), pos, axes, on, bearings, centrifugal,
                       geometric, crossed)  # fmt: skip
    return TrainLoads(flow, meshes, members)


def _frame(v: np.ndarray, e: np.ndarray) -> np.ndarray:
    """A force ``v`` of a mesh's frame (x along ``e``) in the drawing's frame."""
    return np.array([v[0] * e[0] - v[1] * e[1], v[0] * e[1] + v[1] * e[0], v[2]])


def _mesh_load(
    m: Mesh, flow: PowerFlow, spread, pos, axes: Axes, angles, axial, on: dict[str, list]
) -> MeshLoad:
    """The forces of one mesh of parallel axes on each copy; records them per member in
    ``on[member]`` as ``(copy, force, point from the member's axis, pitch point)``."""
    r = m.relation
    rp = flow.relations[r.name]
    turns, shares = _copies(spread, m.g1, m.g2)
    centre = pos[axes.find(r.carrier)] if r.carrier != FRAME else np.zeros(2)
    e0 = direction(m, pos, axes, angles.get(r.name, 0.0))
    s_a = -m.distance if m.internal else m.distance  # gear 2's axis at (s_a, 0)
    tau1 = 1000.0 * rp.torques.get(m.g1, 0.0)  # N mm, the mesh's torques (all copies)
    tau2 = 1000.0 * rp.torques.get(m.g2, 0.0)
    # one force along the line of action: its tangential part from both torques, its line
    # through x = tau1 / F_y (the pitch point without losses; shifted by the loss)
    fy = (tau1 + tau2) / s_a if s_a else 0.0
    try:
        whole = mesh_forces(-fy * m.d1 / 2000.0, m.d1, m.alpha, m.beta, m.alpha_n)
    except GearError as exc:
        raise TrainError(f"mesh {r.name!r}: {exc}") from None
    x = tau1 / fy if abs(fy) > 1e-300 else m.d1 / 2
    z = 0.0 if m.relation.name not in axial else axial[m.relation.name]
    forces: dict[str, list] = {m.g1: [], m.g2: []}
    points: dict[str, list] = {m.g1: [], m.g2: []}
    angles_out = []
    for k, (th, share) in enumerate(zip(turns, shares, strict=True)):
        e = turn(e0, th)
        o1 = centre + turn(pos[axes.find(m.g1)] - centre, th)
        point = np.array([*(o1 + x * e), z])
        f = _frame(np.asarray(whole.vector, float) * share, e)
        for member, v, rel in ((m.g1, f, x * e), (m.g2, -f, (x - s_a) * e)):
            forces[member].append(v + 0.0)
            points[member].append(point)
            on[member].append((k, v + 0.0, np.array([*rel, z]), point))
        angles_out.append(math.degrees(math.atan2(e[1], e[0])))
    pick = (lambda t: t) if m.g1 == r.a else (lambda t: (t[1], t[0]))
    mags = [(float(whole[i]) * shares[0],) * 2 for i in range(4)]  # copy 0: the most loaded
    return MeshLoad(
        r.name,
        (r.a, r.b),
        "internal" if m.internal else ("helical" if m.beta else "spur"),
        len(turns),
        *(pick(x) for x in mags),
        {k: np.array(v) for k, v in forces.items()},
        {k: np.array(v) for k, v in points.items()},
        tuple(angles_out),
        rp.driver,
    )


def _spread(planets, planet_angles, load_sharing) -> dict[str, tuple[list[float], list[float]]]:
    """Planet -> (turn of each copy about its carrier's axis, rad; share of the torque)."""
    angles = _mapping("planet_angles", planet_angles, planets, "planet -> degrees per copy")
    sharing = _mapping("load_sharing", load_sharing, planets, "planet -> K_gamma")
    out = {}
    for p, (_, n) in planets.items():
        if n > MAX_COPIES:
            raise TrainError(
                f"planet {p!r} has {n} copies; loads places at most {MAX_COPIES} copies of a "
                "planet (each is a force of its own)"
            )
        turns = [2 * math.pi * k / n for k in range(n)]
        if p in angles:
            a = angles[p]
            if isinstance(a, str) or not hasattr(a, "__len__") or len(a) != n:
                raise TrainError(f"planet_angles[{p!r}] = {a!r}; valid is {n} angles (degrees)")
            deg = [_real(f"planet_angles[{p!r}]", v) for v in a]
            turns = [math.radians(v - deg[0]) for v in deg]
        shares = [1.0 / n] * n
        if p in sharing:
            k = _real(f"load_sharing[{p!r}]", sharing[p])
            if not 1.0 <= k <= n:
                raise TrainError(f"load_sharing[{p!r}] = {k:g}; valid is 1 <= K_gamma <= {n}")
            if n > 1:
                shares = [k / n] + [(n - k) / (n * (n - 1))] * (n - 1)
        out[p] = (turns, shares)
    return out


def _copies(spread, *members: str) -> tuple[list[float], list[float]]:
    """The copies of a mesh or link: those of its planet member (one copy if none)."""
    for m in members:
        if m in spread:
            return spread[m]
    return [0.0], [1.0]


def _link_load(r: Relation, flow: PowerFlow, spread) -> MeshLoad:
    """A relation with no force in the plane: a link, a coupling, or a bevel mesh (its forces
    per copy from :func:`gears.forces.bevel_pair_forces`, in the pair's own frame)."""
    zero = (0.0, 0.0)
    if r.kind == "mesh" and isinstance(r.pair, BevelPair):
        turns, shares = _copies(spread, r.a, r.b)
        copies = len(turns)
        t1 = -flow.relations[r.name].torques.get(r.a, 0.0) * shares[0]
        if t1 != 0.0:
            f = bevel_pair_forces(r.pair, t1)
            return MeshLoad(
                r.name,
                (r.a, r.b),
                "bevel",
                copies,
                f.tangential,
                f.radial,
                f.axial,
                f.normal,
                {},
                {},
            )
        return MeshLoad(r.name, (r.a, r.b), "bevel", copies, zero, zero, zero, zero, {}, {})
    kind = "link" if r.kind == "mesh" else r.kind
    return MeshLoad(r.name, (r.a, r.b), kind, 1, zero, zero, zero, zero, {}, {})


def _members(
    train: Train,
    flow: PowerFlow,
    planets,
    pos,
    axes: Axes,
    on,
    bearings,
    centrifugal,
    geometric: set[str],
    crossed: Mapping[str, tuple[np.ndarray, np.ndarray]],
) -> dict[str, MemberLoad]:
    """Every member's resultant, bearing force and moment (module docstring); ``crossed``
    maps a worm's axis group to its point and direction."""
    planets, spread = planets
    # torques no force in the drawing carries: links, couplings, bevel meshes, and the carrier's
    # share of a mesh on a moving carrier that holds no planet (a strain-wave generator)
    forceless = [r for r in train.relations if r.name not in geometric]
    pinless = {
        r.name: r.carrier
        for r in train.relations
        if r.name in geometric and r.carrier != FRAME and r.a not in planets and r.b not in planets
    }
    out = {}
    for name in train.members:
        if name == FRAME:
            continue
        carrier, n = planets.get(name, (FRAME, 1))
        share = spread[name][1][0] if name in spread else 1.0  # copy 0's share
        recs = [x for x in on[name] if x[0] == 0] if name in planets else on[name]
        forces = [f for _, f, _, _ in recs]
        points = [p for _, _, p, _ in recs]
        here = pos[axes.find(name)]
        if name in planets and name in centrifugal:
            out_dir = here - (pos[axes.find(carrier)])
            norm = float(np.linalg.norm(out_dir))
            unit = out_dir / norm if norm > 0 else np.array([1.0, 0.0])
            forces.append(np.array([*(centrifugal[name] * unit), 0.0]))
            points.append(np.array([0.0, 0.0, _mid(points)]))
        for planet, (c, _) in planets.items():
            if c == name:
                _pins(
                    planet,
                    spread[planet][0],
                    here,
                    pos[axes.find(planet)],
                    on[planet],
                    centrifugal.get(planet, 0.0),
                    forces,
                    points,
                )
        f = np.sum(forces, axis=0) if forces else np.zeros(3)
        at, axis = crossed.get(axes.find(name), (np.array([*here, 0.0]), np.array([0.0, 0, 1])))
        moment = sum(moment_about(p, v, axis) for p, v in zip(points, forces, strict=True))
        other = (
            flow.torques.get(name, 0.0)
            + sum(flow.relations[r.name].torques.get(name, 0.0) for r in forceless)
            + sum(flow.relations[k].torques.get(name, 0.0) for k, c in pinless.items() if c == name)
        )
        reactions = None
        if name in bearings:
            try:
                reactions = axis_reactions(
                    np.reshape(forces, (-1, 3)), np.reshape(points, (-1, 3)), bearings[name], axis
                )
            except GearError as exc:
                raise TrainError(f"bearings[{name!r}]: {exc}") from None
        out[name] = MemberLoad(
            name,
            other * share,
            f + 0.0,
            -f + 0.0,
            moment / 1000.0 + 0.0,
            at + 0.0,
            n,
            carrier,
            reactions,
            axis + 0.0,
        )
    return out


def _mid(points: list[np.ndarray]) -> float:
    return float(np.mean([p[2] for p in points])) if points else 0.0


def _pins(
    planet: str,
    turns: list[float],
    centre: np.ndarray,
    at: np.ndarray,
    recs: list,
    centrifugal: float,
    forces: list,
    points: list,
) -> None:
    """Append the pin force of every copy of ``planet`` (its mesh forces and centrifugal force)
    to a carrier's ``forces`` at its ``points`` (from the carrier's axis)."""
    for k, th in enumerate(turns):
        rel = turn(at - centre, th)
        mine = [(f, p) for j, f, p, _ in recs if j == k]
        pin = np.sum([f for f, _ in mine], axis=0) if mine else np.zeros(3)
        norm = float(np.linalg.norm(rel))
        if centrifugal and norm > 0:
            pin = pin + np.array([*(centrifugal * rel / norm), 0.0])
        forces.append(pin)
        points.append(np.array([*rel, _mid([p for _, p in mine])]))


# ------------------------------------------------------------------------ a planetary stage


def solid_mass(
    gear: Gear, face_width: float | None, density: float, tolerance: float | None = None
) -> float:
    """The mass (kg) of a gear's solid: the area of its outline (:meth:`gears.Gear.outline`,
    the real teeth, mm^2) times its face width (mm; default the gear's own, else 10 modules,
    as :meth:`gears.Gear.mesh`, whose solid is that outline swept along the helix, with the same
    volume) times ``density`` (kg/mm^3); ``tolerance`` defaults to a hundredth of the module."""
    tol = gear.module / 100 if tolerance is None else tolerance
    width = face_width if face_width is not None else (gear.face_width or 10 * gear.module)
    try:
        area = float(gear.outline(tolerance=tol).area)
    except GearError as exc:
        raise TrainError(f"the planet's solid: {exc}") from None
    return area * _real("face_width", width) * _real("density", density)


def planetary_loads(
    stage: Any,
    input: str,
    output: str,
    fixed: str,
    torque: float,
    speed: float,
    load_sharing_factor: float,
    face_width: float | None = None,
    material: Any = "case-carburized",
    planet_mass: float | Mapping[str, float] | None = None,
    mesh_efficiency: float | None = None,
    friction: float | None = None,
    unequal_sharing: bool = False,
) -> TrainLoads:
    """The loads of a :class:`trains.Planetary` (the view behind :meth:`trains.Planetary.loads`):
    :func:`loads` on its train with its planets where :meth:`~trains.Planetary.placement` puts
    them (unequal spacing too) and the planets' centrifugal force ``m omega_H^2 rho`` (Ozols
    section 11-2) from their solids' mass (:func:`solid_mass`, or ``planet_mass`` in kg) at the
    carrier's speed.

    ``material`` (a name of :data:`gears.MATERIALS` or a :class:`gears.Material`) gives the
    density. The planets share the load equally in the statics (so symmetric planets leave the
    sun and the carrier unloaded); the most loaded planet's mesh forces and pin load with
    ``load_sharing_factor`` K_gamma are in the notes. With ``unequal_sharing`` the statics
    themselves load planet 0 with ``K_gamma / n`` and the others with the rest, which loads the
    sun's and the carrier's bearings.

    ``input``, ``output``, ``fixed`` are member names of ``stage.train``; ``speed`` is the
    input's, rpm. The notes also give the carrier torque, the output's balancing moment (Ozols
    (11.7)), the planets' mass, radius and centrifugal force, and the net radial force on the
    sun's and the carrier's bearings.
    """
    speed = _real("speed", speed)
    if not isinstance(unequal_sharing, bool):
        raise TrainError(f"unequal_sharing = {unequal_sharing!r}; valid is True or False")
    if isinstance(material, str) and material not in MATERIALS:
        raise TrainError(f"material = {material!r}; valid are {', '.join(MATERIALS)}")
    density = getattr(MATERIALS[material] if isinstance(material, str) else material, "density",
                      None)  # fmt: skip
    if density is None:
        raise TrainError(f"material = {material!r}; valid is a name of gears.MATERIALS or a "
                         "gears.Material")  # fmt: skip
    train = stage.train
    place = stage.placement()
    members = ["planet", "planet2"] if stage.scheme == "double-planet" else ["planet"]
    gears = stage.planet_gears if stage.scheme == "double-planet" else (stage.planet_gears,)
    radii = [place.planet_radius, place.planet2_radius]
    spacing = [place.planet_angles, place.planet2_angles]
    motion = train.solve({input: speed, fixed: 0})
    n_h = float(motion[stage.carrier])
    given = planet_mass if isinstance(planet_mass, Mapping) else dict.fromkeys(members, planet_mass)
    given = _mapping("planet_mass", given, members, "planet -> kg")
    notes: dict[str, float] = {
        "planets": stage.n_planets,
        "K_gamma": load_sharing_factor,
        "carrier speed [rpm]": n_h,
    }
    centrifugal = {}
    for i, member in enumerate(members):
        own = gears[i] if isinstance(gears[i], tuple) else (gears[i],)
        if given.get(member) is None:
            mass = sum(solid_mass(g, face_width, density) for g in dict.fromkeys(own))
        else:
            mass = _real(f"planet_mass[{member!r}]", given[member])
            if mass < 0:
                raise TrainError(f"planet_mass = {mass:g} for {member!r}; valid is >= 0 (kg)")
        centrifugal[member] = float(centrifugal_force(mass, n_h, radii[i]))
        suffix = "" if len(members) == 1 else f" ({member})"
        notes[f"planet mass [kg]{suffix}"] = mass
        notes[f"planet radius [mm]{suffix}"] = radii[i]
        notes[f"centrifugal force [N]{suffix}"] = centrifugal[member]
    ld = loads(
        train,
        input,
        output,
        [fixed],
        torque,
        speed,
        mesh_efficiency,
        friction,
        planet_angles={m: spacing[i] for i, m in enumerate(members)},
        load_sharing=dict.fromkeys(members, load_sharing_factor) if unequal_sharing else None,
        centrifugal=centrifugal,
    )
    k = 1.0 if unequal_sharing else load_sharing_factor  # planet 0's loads times k
    for name, mesh in ld.meshes.items():
        if mesh.copies > 1 or any(m in members for m in mesh.members):
            notes[f"most loaded planet: {name} F_n [N]"] = k * mesh.normal[0]
    for member in members:
        p = ld.members[member]
        out = p.position[:2] - ld.members[stage.carrier].position[:2]
        norm = float(np.hypot(*out))
        j = centrifugal[member] * (out / norm if norm > 0 else np.zeros(2))
        pin = k * (p.force[:2] - j) + j
        suffix = "" if len(members) == 1 else f" ({member})"
        notes[f"most loaded planet: pin load [N]{suffix}"] = float(np.hypot(*pin))
    notes["carrier torque [N m]"] = ld.flow.torques[stage.carrier]
    notes["output torque (balancing moment) [N m]"] = ld.flow.torques[output]
    tiny = 1e-9 * max((m.normal[0] * m.copies for m in ld.meshes.values()), default=0.0)
    for member in ("sun", stage.carrier):
        net = ld.members[member].radial_load
        notes[f"net radial force on {member} [N]"] = net if net > tiny else 0.0  # round-off
    return TrainLoads(ld.flow, ld.meshes, ld.members, notes)
