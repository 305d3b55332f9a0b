"""Layer 2, kinematics.

The gear-train model and its kinematics: one Willis equation per relation, solved generically.

A :class:`Train` is a set of *members* (rigid bodies named by the user: a shaft with its gears, a
planet with its gears, a carrier; ``"frame"`` is the fixed ground) and *relations*, each one
linear and homogeneous in the member speeds:

* a mesh of ``a`` and ``b`` on carrier ``c`` (Willis, Ozols (7.6); lectures §4.5):
  ``z_a (w_a - w_c) + z_b (w_b - w_c) = 0`` for an external mesh and
  ``z_a (w_a - w_c) - z_b (w_b - w_c) = 0`` for an internal one, i.e.
  ``(w_a - w_c) / (w_b - w_c) = -z_b/z_a`` (``+z_b/z_a`` internal). This is the equality of the
  pitch-line speeds in the carrier frame; a fixed-axis mesh is the case ``c = "frame"``;
* a link ``(w_a - w_c) = ratio * (w_b - w_c)``: a bevel pair (arrow rule), a chain, a belt, a worm,
  a closing fixed-axis chain;
* a coupling ``w_a = w_b``.

There is no special code per train type (the pygeartrain idea, STYLE.md): a planetary, a
differential, a closed differential and a combined train are the same linear system with different
rows. It is solved by Gauss-Jordan elimination over :class:`fractions.Fraction`, so integer tooth
counts give exact ratios (a 1/10000 train stays 1/10000; a basic ratio near 1 loses nothing to
cancellation). The elimination is done once per set of known members and gives the linear map
from the known speeds to every speed; floats and numpy time series are then one matrix product.
The relations, the elimination and the :class:`Motion` it gives live in :mod:`trains.relations`;
the findings of :meth:`Train.check` in :mod:`trains.conditions`. :class:`Train` builds the rows,
keeps one map per set of known members, and answers.

Examples
--------
>>> t = Train()
>>> t.mesh("sun", "planet", teeth=(20, 30), carrier="arm")
>>> t.mesh("planet", "ring", teeth=(30, 80), carrier="arm", internal=True)
>>> t.ratio("sun", "arm", fixed=["ring"])
Fraction(5, 1)
>>> m = t.solve(sun=1500, ring=0)
>>> m["arm"], m.relative("planet", "arm")
(Fraction(300, 1), Fraction(-800, 1))
>>> t.mobility
2
"""

from __future__ import annotations

import math
import numbers
import operator
import warnings
from collections.abc import Iterable, Mapping
from fractions import Fraction
from typing import Any

import numpy as np

from gears import BevelPair, Finding, Gear, GearError, GearPair, Report, WormPair
from trains.conditions import (
    coaxiality_finding,
    planet_findings,
    same_gear_findings,
)
from trains.errors import TrainError
from trains.relations import (
    CONDITION_LIMIT,
    FRAME,
    IllConditionedTrainWarning,
    Motion,
    Relation,
    Structure,
    _check_overflow,
    _exact,
    _Map,
    _name,
    _ratio,
    _replace_amplification,
    _teeth,
    assemble,
    build_map,
    check_amplification,
    sensitivity,
)

# --------------------------------------------------------------------------------- the train


class Train:
    """A gear train: named members and the linear relations between their speeds.

    Members are created when first named; ``"frame"`` (the ground, speed 0) always exists.
    See the module docstring and ``docs/trains.md``.

    Examples
    --------
    A closed differential (Ozols example 7-7, the electric hoist): differential 1-2-2'-3 on the
    drum 4, closed by the fixed-axis chain 3' - idler 5 - 4.

    >>> t = Train()
    >>> t.mesh("1", "2", teeth=(24, 52), carrier="4")
    >>> t.mesh("2", "3", teeth=(21, 78), carrier="4", internal=True)
    >>> t.mesh("3", "5", teeth=(18, 30))
    >>> t.mesh("5", "4", teeth=(30, 78), internal=True)
    >>> t.ratio("1", "4")
    Fraction(2767, 63)
    """

    def __init__(self) -> None:
        self._members: list[str] = [FRAME]
        self._relations: list[Relation] = []
        self._planets: dict[str, int] = {}
        self._coaxial: list[tuple[str, ...]] = []
        self._maps: dict[tuple[str, ...], _Map] = {}
        self.name = ""
        self.run_defaults: dict[str, Any] = {}  # `[run]` table of a TOML file (CLI defaults)

    # ---- building

    def _member(self, name: Any, what: str = "member") -> str:
        name = _name(name, what)
        if name not in self._members:
            self._members.append(name)
        return name

    def _add(self, kind: str, a: Any, b: Any, carrier: Any, k_a: Any, k_b: Any, name: Any, **kw):
        a = _name(a, "first member")
        b = _name(b, "second member")
        c = FRAME if carrier is None else _name(carrier, "carrier")
        if a == b:
            raise TrainError(f"a {kind} needs two different members, got {a!r} twice")
        if kind != "couple" and c in (a, b):
            raise TrainError(
                f"the carrier {c!r} of a {kind} must differ from its members {a!r} and {b!r}"
            )
        if name is None:
            base = f"{a}={b}" if kind == "couple" else f"{a}-{b}"
            name, n = base, 1
            while any(r.name == name for r in self._relations):
                n += 1
                name = f"{base}#{n}"
        else:
            name = _name(name, "relation name")
            if any(r.name == name for r in self._relations):
                raise TrainError(f"a relation named {name!r} already exists")
        for m in (a, b) if kind == "couple" else (a, b, c):
            self._member(m)
        self._relations.append(Relation(kind, name, a, b, c, k_a, k_b, **kw))
        self._maps.clear()

    def mesh(
        self,
        a: str,
        b: str,
        teeth: tuple[int, int] | None = None,
        carrier: str | None = None,
        internal: bool | None = None,
        name: str | None = None,
        gears: tuple[Gear, Gear] | None = None,
        pair: GearPair | BevelPair | WormPair | None = None,
        opposed: bool = False,
    ) -> None:
        """Add one mesh: ``(w_a - w_c)/(w_b - w_c) = -z_b/z_a`` (``+z_b/z_a`` if internal).

        Give either tooth counts (a kinematic-only mesh) or the real gears (``gears`` or
        ``pair``): then the tooth counts and the internal flag come from the gears, and the mesh
        holds a :class:`gears.GearPair` whose findings :meth:`check` reports and whose losses
        :func:`trains.power_flow` estimates (``friction=``).

        Parameters
        ----------
        a, b : str
            The meshing members. A member meshing twice with different tooth counts is a stepped
            (compound) gear.
        teeth : (int, int), optional
            ``(z_a, z_b)``, positive integers (a worm's number of starts for a worm). With gears
            it may be given too and must agree.
        carrier : str, optional
            The member holding both axes; ``None`` means the frame (fixed axes).
        internal : bool, optional
            True when one of the two is an internal (ring) gear: the members turn the same way
            relative to the carrier. Default False; with gears it follows from them.
        name : str, optional
            Name of the mesh (default ``"a-b"``).
        gears : (Gear, Gear), optional
            The gear on ``a`` and the gear on ``b``; at most one internal (the ring may sit on
            either member).
        pair : GearPair or BevelPair, optional
            A ready pair: its ``g1`` sits on ``a`` and its ``g2`` on ``b`` (a pair keeps its own
            tip-shortening choice). A :class:`gears.BevelPair` makes a bevel mesh: with both
            speeds counted about the axes pointing away from the common apex it is an external
            mesh (``z_a w_a + z_b w_b = 0`` relative to the carrier; docs/bevel.md).
            A :class:`gears.WormPair` makes a worm mesh: the worm on ``a``, the wheel on ``b``,
            ``teeth = (z_1, z_2)`` (starts, teeth) and the sign of an external mesh (a worm pair's
            sense of rotation is a convention of its axes); :func:`trains.power_flow` with
            ``friction=`` then charges it the efficiency of the driving member, the worm's or the
            wheel's (Ozols (14.15), (14.18)), and a self-locking worm holds its load.
        opposed : bool
            Bevel meshes only: True when the speeds of ``a`` and ``b`` are counted about axes of
            opposite sense relative to the apex (both side gears of a differential about the one
            axle direction): then ``(w_a - w_c)/(w_b - w_c) = +z_b/z_a``.

        Raises
        ------
        TrainError
            For a tooth count that is not a positive integer, a carrier equal to a member, gears
            that do not form a pair (the message of :class:`gears.GearError` with the mesh
            name), or tooth counts / internal flag that contradict the gears.

        Examples
        --------
        >>> t = Train()
        >>> t.mesh("pinion", "wheel", teeth=(20, 50))
        >>> t.ratio("pinion", "wheel")
        Fraction(-5, 2)
        >>> t.mesh("wheel", "x", teeth=(20.5, 10))  # doctest: +ELLIPSIS
        Traceback (most recent call last):
        ...
        trains.errors.TrainError: first tooth count must be a positive integer, got 20.5 ...

        A mesh of real gears:

        >>> from gears import Gear
        >>> t = Train()
        >>> t.mesh("in", "out", gears=(Gear(17, 2), Gear(40, 2)))
        >>> t.ratio("in", "out"), round(t.pairs["in-out"].center_distance, 6)
        (Fraction(-40, 17), 57.0)
        """
        real, pair = self._gears_of(a, b, gears, pair, name)
        if not isinstance(opposed, bool):
            raise TrainError(f"mesh {a}-{b}: opposed = {opposed!r}; valid is True or False")
        if opposed and not isinstance(pair, BevelPair):
            raise TrainError(
                f"mesh {a}-{b}: opposed=True applies to bevel meshes (pair=BevelPair(...)); a "
                "kinematic bevel relation is Train.link(..., ratio=...)"
            )
        if isinstance(pair, WormPair):
            zg = (pair.starts, pair.wheel_teeth)
            if teeth is not None and (not isinstance(teeth, tuple | list) or tuple(teeth) != zg):
                raise TrainError(
                    f"mesh {a}-{b}: teeth = {teeth!r} contradicts the worm pair's starts and "
                    f"teeth {zg}; give one of them"
                )
            if internal:
                raise TrainError(f"mesh {a}-{b}: internal = {internal!r}; a worm pair is external")
            teeth, internal = zg, False
        if real is not None:
            zg = (real[0].teeth, real[1].teeth)
            if teeth is not None:
                if not isinstance(teeth, tuple | list) or tuple(teeth) != zg:
                    raise TrainError(
                        f"mesh {a}-{b}: teeth = {teeth!r} contradicts the gears' tooth counts"
                        f" {zg}; give one of them"
                    )
            ring = pair.internal
            if internal is not None and bool(internal) != ring:
                raise TrainError(
                    f"mesh {a}-{b}: internal = {internal!r} contradicts the gears (internal ="
                    f" {ring}); the internal flag follows from the ring gear's internal=True"
                )
            teeth, internal = zg, ring
        if teeth is None:
            raise TrainError(f"mesh {a}-{b}: give teeth=(z_a, z_b), gears=(g_a, g_b) or pair=")
        if not isinstance(teeth, tuple | list) or len(teeth) != 2:
            raise TrainError(f"teeth must be a pair (z_a, z_b), got {teeth!r}")
        za, zb = _teeth(teeth[0], "first"), _teeth(teeth[1], "second")
        internal = bool(internal)
        self._add("mesh", a, b, carrier, za, -zb if internal or opposed else zb, name,
                  teeth=(za, zb), internal=internal, gears=real, pair=pair,
                  opposed=opposed)  # fmt: skip

    @staticmethod
    def _gears_of(
        a: Any, b: Any, gears: Any, pair: Any, name: Any
    ) -> tuple[tuple[Gear, Gear] | None, GearPair | None]:
        where = f"mesh {name or f'{a}-{b}'}"
        if gears is None and pair is None:
            return None, None
        if gears is not None and pair is not None:
            raise TrainError(f"{where}: give gears=(g_a, g_b) or pair=, not both")
        if isinstance(pair, BevelPair):
            if gears is not None:
                raise TrainError(f"{where}: give gears=(g_a, g_b) or pair=, not both")
            return (pair.g1, pair.g2), pair
        if isinstance(pair, WormPair):
            if gears is not None:
                raise TrainError(f"{where}: give gears=(g_a, g_b) or pair=, not both")
            return None, pair  # a worm and its wheel: no Gear objects
        if pair is not None:
            if not isinstance(pair, GearPair):
                raise TrainError(
                    f"{where}: pair must be a gears.GearPair, gears.BevelPair or gears.WormPair, "
                    f"got {pair!r}"
                )
            if pair.is_rack:
                raise TrainError(
                    f"{where}: a pinion and rack has no second axis; use Train.link for it"
                )
            Train._geometry_exists(pair, where)
            return (pair.g1, pair.g2), pair
        if (
            not isinstance(gears, tuple | list)
            or len(gears) != 2
            or not all(isinstance(g, Gear) for g in gears)
        ):
            raise TrainError(f"{where}: gears must be two gears.Gear objects, got {gears!r}")
        ga, gb = gears
        if ga.internal and gb.internal:
            raise TrainError(f"{where}: two internal gears cannot mesh (at most one is a ring)")
        try:
            pair = GearPair(gb, ga) if ga.internal else GearPair(ga, gb)
        except GearError as exc:
            raise TrainError(f"{where}: {exc}") from None
        Train._geometry_exists(pair, where)
        return (ga, gb), pair

    @staticmethod
    def _geometry_exists(pair: GearPair, where: str) -> None:
        """Impossible gears (no working pressure angle for their shifts) raise now, not in
        :meth:`check`."""
        try:
            pair.center_distance  # noqa: B018 - computes the working geometry
            pair.tip_diameters  # noqa: B018
        except GearError as exc:
            raise TrainError(f"{where}: {exc}") from None

    def link(
        self, a: str, b: str, ratio: Any, carrier: str | None = None, name: str | None = None
    ) -> None:
        """Add any Willis relation ``(w_a - w_c) = ratio * (w_b - w_c)``.

        For bevel pairs (sign by the arrow rule), chains, belts, worms, a closing chain or any
        known ratio. ``ratio`` may be an int, a Fraction, a float or a string like ``"13/3"``.

        Examples
        --------
        The bevel (car) differential, Ozols (7.9): ``w_1 + w_2 = 2 w_H``.

        >>> t = Train()
        >>> t.link("left", "right", ratio=-1, carrier="case")
        >>> t.solve(left=0, case=100)["right"]
        Fraction(200, 1)
        """
        r = _ratio(ratio)
        self._add("link", a, b, carrier, 1, -r, name)

    def couple(self, a: str, b: str, name: str | None = None) -> None:
        """Make two members turn together (``w_a = w_b``), e.g. a shaft through two stages."""
        self._add("couple", a, b, None, 1, -1, name)

    def add_member(self, name: str) -> None:
        """Declare a member that no relation mentions yet."""
        self._member(name)
        self._maps.clear()

    def set_planets(self, member: str, count: int) -> None:
        """Declare ``count`` identical copies of planet ``member`` (for :attr:`structure`)."""
        if member not in self._members:
            raise TrainError(f"unknown member {member!r}; the members are {self._known_names()}")
        count = operator.index(count)
        if count < 1:
            raise TrainError(f"a planet count must be >= 1, got {count}")
        self._planets[member] = count

    def coaxial(self, *members: str) -> None:
        """Declare members whose axes coincide (checked by :meth:`check`).

        The input and output shafts of a reverted train, the central gears of a planetary: each
        path of real-gear meshes between two of them must close, e.g. ``a_w12 = a_w34``.

        Examples
        --------
        >>> from gears import Gear
        >>> t = Train()
        >>> t.mesh("in", "lay", gears=(Gear(17, 2), Gear(40, 2)))
        >>> t.mesh("lay", "out", gears=(Gear(20, 2), Gear(38, 2)))
        >>> t.coaxial("in", "out")
        >>> f = t.check()["coaxiality(in, out)"]
        >>> f.ok, round(f.margin, 4)    # a_w 57 mm and 58 mm
        (False, -0.99)
        """
        names = [_name(m, "coaxial member") for m in members]
        if len(names) < 2 or len(set(names)) != len(names):
            raise TrainError(f"coaxial needs two or more different members, got {members!r}")
        for m in names:
            self._check_member(m)
        self._coaxial.append(tuple(names))

    # ---- introspection

    @property
    def members(self) -> tuple[str, ...]:
        """Member names in order of creation, ``"frame"`` first."""
        return tuple(self._members)

    @property
    def relations(self) -> tuple[Relation, ...]:
        """The relations in order of creation."""
        return tuple(self._relations)

    def relation(self, name: str) -> Relation:
        """The relation called ``name``."""
        for r in self._relations:
            if r.name == name:
                return r
        names = ", ".join(r.name for r in self._relations)
        raise TrainError(f"no relation named {name!r}; the relations are {names}")

    @property
    def exact(self) -> bool:
        """True when every coefficient is an integer or a Fraction."""
        return all(_exact(r.k_a) and _exact(r.k_b) for r in self._relations)

    @property
    def mobility(self) -> int:
        """Degrees of freedom: moving members minus the rank of the relations (exact)."""
        return self._map(()).missing

    @property
    def structure(self) -> Structure:
        """Chebyshev count with identical planets, beside the algebraic mobility.

        Examples
        --------
        Ozols §21-13: a differential with three identical planets has ``k - 1 = 2`` redundant
        constraints.

        >>> from trains import simple_planetary
        >>> t = simple_planetary(20, 30, 80, n_planets=3)
        >>> s = t.structure
        >>> s.chebyshev, s.redundant, s.mobility
        (0, 2, 2)
        """
        copies = {m: self._planets.get(m, 1) for m in self._members}
        links = sum(copies[m] for m in self._members if m != FRAME)
        higher = couples = 0
        for r in self._relations:
            k = max(copies[r.a], copies[r.b])
            if r.kind == "couple":
                couples += k
            else:
                higher += k
        links -= couples  # a coupling makes two members one link
        lower = links
        cheb = 3 * links - 2 * lower - higher
        mob = self.mobility
        return Structure(links, lower, higher, cheb, mob - cheb, mob)

    @property
    def pairs(self) -> dict[str, GearPair]:
        """The :class:`gears.GearPair` of every mesh built from real gears, by mesh name."""
        return {r.name: r.pair for r in self._relations if r.pair is not None}

    @property
    def coaxial_groups(self) -> tuple[tuple[str, ...], ...]:
        """The groups of coaxial members: those declared with :meth:`coaxial`, then the
        central members of every planet declared with :meth:`set_planets` (the members it
        meshes on its carrier with real gears, which turn about the carrier's axis)."""
        groups = list(self._coaxial)
        for planet, central, _carrier in self._planet_meshes():
            # bevel meshes (intersecting axes) put their central members on one axis by design
            real = [r for r in central if isinstance(r.pair, GearPair)]
            members = tuple(dict.fromkeys(r.b if r.a == planet else r.a for r in real))
            if len(members) >= 2 and not any(set(members) <= set(g) for g in groups):
                groups.append(members)
        return tuple(groups)

    def _planet_meshes(self) -> list[tuple[str, list[Relation], str]]:
        """(planet, its meshes with central members, carrier) for each declared planet."""
        out = []
        for planet in self._planets:
            rels = [
                r
                for r in self._relations
                if r.kind == "mesh" and planet in (r.a, r.b) and r.carrier != FRAME
            ]
            central = [r for r in rels if (r.b if r.a == planet else r.a) not in self._planets]
            if central:
                out.append((planet, central, central[0].carrier))
        return out

    def check(
        self,
        tolerance: float = 0.01,
        min_contact_ratio: float = 1.1,
        min_tip_land: float = 0.2,
        clearance: float = 0.5,
    ) -> Report:
        """Every condition of a train of real gears, each a :class:`gears.Finding` with a margin.

        * every mesh's :meth:`gears.GearPair.check` findings, prefixed by the mesh name
          (``"1-2.contact_ratio"``, ``"1-2.g1.undercut"``);
        * ``coaxiality(a, b, ...)`` for every group of :attr:`coaxial_groups`: each path of
          real-gear meshes between two members of the group closes (two centre distances equal
          within ``tolerance`` mm; three or more form a closing polygon), margin in mm
          (:func:`trains.conditions.closure_margin`); coupled members share one axis;
        * ``<member>.same_gear``: a member meshing twice with gears of equal tooth count and
          module is one gear, so their profile shift, helix, pressure angle and face width agree
          (a stepped gear, two different gears on one shaft, is not flagged);
        * for a planet given ``k >= 2`` copies (:meth:`set_planets`): ``<planet>.assembly``
          (the exact gcd form, when it meshes two central members; teeth) and
          ``<planet>.neighbour`` (gap between planet tip circles minus ``clearance`` modules, mm).

        A kinematic-only mesh (tooth counts) has no geometry to check: it adds no finding, a
        planet with only such meshes gets no assembly or neighbour finding, and a coaxial group
        joined only through such meshes gets an informative note.

        Examples
        --------
        Ozols example 7-7, the electric hoist, on real gears (stage modules 1.5, 2 and 2 make
        the sun 1, the gear 3 and the drum 4 coaxial at 57 mm and 48 mm):

        >>> from gears import Gear
        >>> t = Train()
        >>> t.mesh("1", "2", gears=(Gear(24, 1.5), Gear(52, 1.5)), carrier="4")
        >>> t.mesh("2", "3", gears=(Gear(21, 2), Gear(78, 2, internal=True)), carrier="4")
        >>> t.mesh("3", "5", gears=(Gear(18, 2), Gear(30, 2)))
        >>> t.mesh("5", "4", gears=(Gear(30, 2), Gear(78, 2, internal=True)))
        >>> t.coaxial("1", "3", "4")
        >>> r = t.check()
        >>> r["coaxiality(1, 3, 4)"].ok, t.ratio("1", "4")
        (True, Fraction(2767, 63))
        """
        for value, what in ((tolerance, "tolerance"), (clearance, "clearance")):
            if (
                isinstance(value, bool)
                or not isinstance(value, numbers.Real)
                or not (math.isfinite(value) and value >= 0)
            ):
                raise TrainError(f"{what} = {value!r}; valid is a finite number >= 0")
        findings: list[Finding] = []
        for r in self._relations:
            if r.pair is not None:
                rep = r.pair.check(min_contact_ratio, min_tip_land)
                findings.extend(rep.prefixed(r.name).values())
        for group in self.coaxial_groups:
            findings.append(coaxiality_finding(group, self._members, self._relations, tolerance))
        findings.extend(same_gear_findings(self._relations))
        planets = self._planet_meshes()
        findings.extend(planet_findings(planets, self._planets, self._relations, clearance))
        return Report(findings)

    def _known_names(self) -> str:
        return ", ".join(sorted(self._members))

    def _check_member(self, name: Any) -> str:
        if not isinstance(name, str) or name not in self._members:
            raise TrainError(f"unknown member {name!r}; the members are {self._known_names()}")
        return name

    # ---- the linear map

    def _map(self, known: tuple[str, ...]) -> _Map:
        cached = self._maps.get(known)
        if cached is not None:
            return cached
        rows = [r.coefficients for r in self._relations]
        result = build_map(self._members, known, rows, self.exact)
        if not result.exact and result.determined:
            result = _replace_amplification(
                result, sensitivity(self._members, self._relations, known, result, self.exact)
            )
        self._maps[known] = result
        return result

    # ---- kinematics

    def solve(self, known: Mapping[str, Any] | None = None, /, **speeds: Any) -> Motion:
        """Speeds of every member from the given ones.

        Parameters
        ----------
        known : mapping, optional
            ``{member: speed}`` (for member names that are not Python identifiers, e.g. ``"2'"``).
        **speeds
            ``member=speed``. A fixed member is given speed 0. Speeds may be ints/Fractions
            (exact Fraction results when the train is exact), floats (float results), or numpy
            arrays of one speed per time step (array results, one matrix product).

        Returns
        -------
        Motion
            Mapping ``member -> speed`` including ``"frame"`` (0).

        Raises
        ------
        TrainError
            Unknown member; under-determined (names the free members and how many more speeds
            are needed); inconsistent or locked (names the conflicting relations); NaN or
            infinite speeds.

        Warns
        -----
        IllConditionedTrainWarning
            When float data are amplified by more than 1e8 (e.g. a float basic ratio near 1).

        Examples
        --------
        >>> from trains import simple_planetary
        >>> t = simple_planetary(20, 30, 80)
        >>> t.solve(sun=1500.0, ring=0)["carrier"]
        300.0
        >>> import numpy as np
        >>> t.solve(sun=np.array([0.0, 1500.0]), ring=0)["carrier"]
        array([  0., 300.])
        >>> t.solve(sun=1500)  # doctest: +ELLIPSIS
        Traceback (most recent call last):
        ...
        trains.errors.TrainError: under-determined: the speeds of planet, carrier, ring are ...
        """
        given: dict[str, Any] = dict(known or {})
        for k, v in speeds.items():
            if k in given:
                raise TrainError(f"speed of {k!r} given twice")
            given[k] = v
        for name in given:
            self._check_member(name)
        if FRAME in given:
            raise TrainError("'frame' is the ground; its speed is always 0 (do not give it)")
        names = tuple(sorted(given, key=self._members.index))
        mp = self._map(names)
        if mp.free:
            self._raise_free(mp)
        return Motion(self._evaluate(mp, [given[n] for n in names]))

    def _raise_free(self, mp: _Map) -> None:
        given = ", ".join(mp.known) if mp.known else "nothing"
        n = mp.missing
        raise TrainError(
            f"under-determined: the speeds of {', '.join(mp.free)} are not fixed by the given"
            f" speeds of {given}; give {n} more speed{'s' if n > 1 else ''}"
            f" (e.g. of {' and '.join(mp.choices)}; the train has mobility {self.mobility})"
        )

    def _evaluate(self, mp: _Map, values: list[Any]) -> dict[str, Any]:
        kind = "exact"
        for v in values:
            if (isinstance(v, np.ndarray) and v.ndim > 0) or isinstance(v, list | tuple):
                kind = "array"
                break
            if isinstance(v, bool) or not isinstance(v, numbers.Real):
                if isinstance(v, np.ndarray):  # 0-d
                    kind = "float"
                    continue
                raise TrainError(f"a speed must be a number or an array, got {v!r}")
            if not _exact(v):
                kind = "float"
        if kind == "exact" and not mp.exact:
            kind = "float"
        if kind == "exact":
            vals = [Fraction(v) for v in values]
            self._check_constraints(mp, vals, exact=True)
            out = {n: sum((c * w for c, w in zip(cs, vals, strict=True)), Fraction(0))
                   for n, cs in mp.determined.items()}  # fmt: skip
            return assemble(self._members, mp, dict(zip(mp.known, vals, strict=True)), out)
        if not mp.exact and mp.amplification > CONDITION_LIMIT:
            amp = mp.amplification
            digits = "all" if math.isinf(amp) else f"{math.log10(amp):.0f}"
            warnings.warn(
                f"the train's float ratios are ill-conditioned (rounding amplified {amp:.2g}"
                f" times): results may have lost {digits} of 16 digits; give the ratios as"
                " Fractions or strings like '9999/10000' for exact results",
                IllConditionedTrainWarning,
                stacklevel=3,
            )
        if kind == "float":
            vals = np.array([float(v) for v in values])
            if not np.all(np.isfinite(vals)):
                raise TrainError(
                    f"speeds must be finite, got {dict(zip(mp.known, values, strict=True))}"
                )
            with np.errstate(over="ignore", invalid="ignore"):  # overflow: refused below
                self._check_constraints(mp, vals[:, None], exact=False)
                mat = mp.matrix()
                res = mat @ vals if vals.size else np.zeros(len(mp.determined))
                _check_overflow(res, mp.known, values)
                check_amplification(mat, vals[:, None], res[:, None])
            out = {n: float(x) for n, x in zip(mp.determined, res, strict=True)}
            return assemble(
                self._members, mp, dict(zip(mp.known, map(float, vals), strict=True)), out
            )
        try:
            arrays = np.broadcast_arrays(*[np.asarray(v, dtype=float) for v in values])
        except (TypeError, ValueError):  # text, ragged lists, shapes that do not broadcast
            raise TrainError(
                f"speeds must be numbers or arrays of one shape, got "
                f"{dict(zip(mp.known, values, strict=True))}"
            ) from None
        shape = arrays[0].shape if arrays else ()
        w = np.stack([a.reshape(-1) for a in arrays]) if arrays else np.zeros((0, 1))
        if not np.all(np.isfinite(w)):
            raise TrainError("speeds must be finite; the given arrays contain NaN or infinity")
        with np.errstate(over="ignore", invalid="ignore"):  # overflow: refused below
            self._check_constraints(mp, w, exact=False)
            mat = mp.matrix()
            res = mat @ w
            _check_overflow(res, mp.known, values)
            check_amplification(mat, w, res)
        out = {n: res[i].reshape(shape) for i, n in enumerate(mp.determined)}
        known = {n: a for n, a in zip(mp.known, arrays, strict=True)}
        return assemble(self._members, mp, known, out, zero=np.zeros(shape))

    def _check_constraints(self, mp: _Map, w: Any, exact: bool) -> None:
        for cvec, rel in mp.constraints:
            if exact:
                bad = sum((c * x for c, x in zip(cvec, w, strict=True)), Fraction(0)) != 0
            else:
                c = np.array([float(x) for x in cvec])
                resid = np.abs(c @ w)
                scale = np.abs(c) @ np.abs(w)
                bad = bool(np.any(resid > 1e-9 * scale + 1e-300))
            if bad:
                self._raise_conflict(mp, cvec, rel)

    def _raise_conflict(self, mp: _Map, cvec: tuple, rel: tuple[int, ...]) -> None:
        rels = "; ".join(str(self._relations[i]) for i in rel)
        involved = [n for n, c in zip(mp.known, cvec, strict=True) if c != 0]
        if not rel:
            msg = f"inconsistent: the given speeds of {', '.join(involved)} contradict each other"
        else:
            msg = (
                f"inconsistent or locked: the relations [{rels}] cannot hold together with the"
                f" given speeds of {', '.join(involved)}"
            )
        if len(involved) > self.mobility and self.mobility >= 0:
            msg += (
                f" (the train has mobility {self.mobility} but {len(mp.known)} speeds were given)"
            )
        elif self.mobility == 0:
            msg += " (the train is locked: mobility 0)"
        raise TrainError(msg)

    def ratio(self, input: str, output: str, fixed: Iterable[str] = ()) -> Any:
        """Transmission ratio ``i = w_input / w_output`` with the ``fixed`` members held.

        Exact (a Fraction) for an exact train, a float otherwise. Ozols' convention: driver over
        driven, signed (negative = opposite directions).

        Raises
        ------
        TrainError
            If the output stands still (infinite ratio), the input cannot move, or the input and
            the fixed members do not determine the output.

        Examples
        --------
        Ozols example 7-4, the David mechanism: ``i_1H = 1/10000`` exactly.

        >>> from trains import stepped_planetary
        >>> t = stepped_planetary(100, 101, 100, 99, meshes=("external", "external"))
        >>> t.ratio("1", "H", fixed=["3"])
        Fraction(1, 10000)
        """
        self._check_member(input)
        self._check_member(output)
        fixed = [fixed] if isinstance(fixed, str) else list(fixed)
        for f in fixed:
            self._check_member(f)
        if input in fixed or output in fixed:
            raise TrainError(f"the input {input!r} and output {output!r} must not be fixed")
        one = Fraction(1) if self.exact else 1.0
        given = {f: 0 for f in fixed if f != FRAME}
        speeds = self._partial({input: one, **given}, output)
        if speeds is None:  # the input cannot move: maybe the output drives it (i = 0)
            back = self._partial({output: one, **given}, input)
            if back is not None and back == 0:
                return back * 0
            raise TrainError(
                f"{input} cannot turn with {', '.join(fixed) or 'nothing'} fixed: it is locked"
            )
        if speeds == 0:
            raise TrainError(
                f"{output} stands still when {input} turns with {', '.join(fixed) or 'nothing'}"
                " fixed: the ratio is infinite"
            )
        return one / speeds

    def _partial(self, given: dict[str, Any], want: str) -> Any:
        """Speed of ``want`` (None if the given speeds are inconsistent); raise if it is free."""
        names = tuple(sorted(given, key=self._members.index))
        if want in given:
            return given[want]
        mp = self._map(names)
        vals = [given[n] for n in names]
        try:
            self._check_constraints(mp, vals if mp.exact else np.array(vals, float)[:, None],
                                    exact=mp.exact)  # fmt: skip
        except TrainError:
            return None
        if want not in mp.determined:
            self._raise_free(mp)
        cs = mp.determined[want]
        if mp.exact:
            return sum((c * Fraction(v) for c, v in zip(cs, vals, strict=True)), Fraction(0))
        return float(sum(float(c) * float(v) for c, v in zip(cs, vals, strict=True)))

    def __repr__(self) -> str:
        moving = [m for m in self._members if m != FRAME]
        return f"Train(members={moving}, relations={[r.name for r in self._relations]})"

    def describe(self) -> str:
        """One line per relation, readable."""
        lines = [self.name] if self.name else []
        lines += [str(r) for r in self._relations]
        return "\n".join(lines)
