"""Layer 5, planetary: one planetary (2K-H) stage on real gears, :class:`Planetary`.

A stage has two central gears, called ``sun`` (central gear *a*, lectures' link 1) and ``ring``
(central gear *b*, link 3) whatever their kind, a carrier, and ``n_planets`` identical planets
(or planet pairs), meshing in one of the schemes of :mod:`trains.planetary.schemes`. The class is
a thin view: its ratios, efficiency and rating come from the generic Willis solver of its
:attr:`~Planetary.train` (:mod:`trains.willis`, :mod:`trains.power`, :mod:`trains.capacity`), its
conditions from :mod:`trains.planetary.checks`, its placement from
:mod:`trains.planetary.placement`, and its outlines, scene and animation from
:mod:`trains.planetary.scene`.
"""

from __future__ import annotations

import math
import numbers
import operator
import os
import pathlib
from collections.abc import Callable, Iterable
from fractions import Fraction
from functools import cached_property
from typing import TYPE_CHECKING, Any

from gears import Gear, GearPair
from gears.arguments import check_angle, check_integer, check_module
from gears.errors import GearError
from gears.report import Report
from trains.capacity import load_sharing
from trains.capacity import rating as rate_train
from trains.errors import TrainError
from trains.loading import TrainLoads, planetary_loads
from trains.planetary import checks, placement, scene
from trains.planetary.checks import MAX_PLANETS, Assembly
from trains.planetary.contact import StageContact, stage_contact
from trains.planetary.placement import Placement
from trains.planetary.schemes import (
    _GEARS,
    _MESHES,
    _TRAIN_MEMBER,
    _default_roles,
    basic_ratio,
    canonical_scheme,
)
from trains.power import power_flow
from trains.willis import Train

if TYPE_CHECKING:
    import trimesh

__all__ = ["Planetary"]


def _is_pair(value: Any) -> bool:
    return isinstance(value, tuple | list) and len(value) == 2


def _teeth_or_gear(value: Any, which: str) -> Any:
    if isinstance(value, Gear):
        return value
    if isinstance(value, bool) or not isinstance(value, numbers.Integral | Fraction | float):
        raise TrainError(f"{which} must be a tooth count (integer >= 1) or a Gear; got {value!r}")
    try:
        z = operator.index(value) if not isinstance(value, Fraction | float) else value
        if isinstance(z, Fraction | float):
            if not (math.isfinite(float(z)) and float(z) == int(z)):
                raise TypeError
            z = int(z)
    except TypeError:
        raise TrainError(f"{which} = {value!r} is not a whole number of teeth") from None
    if z < 1:
        raise TrainError(f"{which} = {z}; valid is an integer >= 1")
    return z


class Planetary:
    """A planetary stage with ``n_planets`` identical, equally spaced planets.

    Parameters
    ----------
    sun, ring : int or Gear
        Tooth counts (then ``module``, ``pressure_angle`` and ``helix_angle`` make the gears, with
        zero shift) or :class:`gears.Gear` objects carrying their shift, helix and rack. The
        ``ring`` of the ``external`` scheme is an external gear; the ``sun`` of the ``internal``
        scheme is a ring.
    planet : int, Gear or pair
        The planet; a pair ``(meshing sun, meshing ring)`` for a stepped planet (schemes
        ``stepped``, ``external``, ``internal``) or ``(inner, outer)`` planets of a
        ``double-planet`` stage.
    n_planets : int
        Number of identical planets (clusters), >= 1.
    module : float, optional
        Normal module for tooth-count input (default 1: lengths then read in modules). Must match
        the gears' when Gears are given.
    carrier : str
        Name of the carrier member in :attr:`train`.
    scheme : str
        ``"simple"``, ``"stepped"``, ``"external"``, ``"internal"`` or ``"double-planet"``
        (aliases ``"A"`` ... ``"D"``; see the module docstring).
    clearance : float
        Neighbour clearance between planet tip circles, in modules (default 0.5).
    pressure_angle, helix_angle : float
        For tooth-count input (degrees; helix is the sun's, the mates get the matching hands).
    tip_shortening : bool
        Apply DIN 3960 tip shortening on external meshes (see :class:`gears.GearPair`).
    ring_tip_relief : bool
        Relieve the tip of a ring whose nominal tip (d_a2 = d2 - 2 m (h_a - x)) would reach below
        its planet's form circle, i.e. onto the planet's fillet: a ring tip circle cuts the line
        of action deeper than a rack's tip line, so with an ISO 53 A tool every zero-shift
        internal mesh does this (by about 0.25 m at 45/108). The ring's tip diameter is enlarged
        to :attr:`gears.GearPair.tip_diameter_limits` (rounded up to 1 um), which DIN 3960 style
        checks require (active root diameter >= form diameter); the amount is reported as the
        ``ring_tip_relief`` finding. Rings given as Gears with their own ``tip_alteration`` are
        left as they are.

    Raises
    ------
    TrainError
        For an unknown scheme, a planet count < 1, a tooth count that is not a positive integer,
        a gear of the wrong kind (internal/external) for its place, or mismatched modules.

    Examples
    --------
    The third-party course example (lectures §4.3): u = 7 with 18/45/108 and three planets.

    >>> p = Planetary(sun=18, planet=45, ring=108, n_planets=3, module=2)
    >>> p.ratio()
    Fraction(7, 1)
    >>> p.check()["assembly"].ok, p.max_planets
    (True, 3)
    """

    def __init__(
        self,
        sun: Any,
        planet: Any,
        ring: Any,
        n_planets: int,
        module: float | None = None,
        carrier: str = "arm",
        scheme: str = "simple",
        clearance: float = 0.5,
        pressure_angle: float | None = None,
        helix_angle: float = 0.0,
        tip_shortening: bool = True,
        ring_tip_relief: bool = True,
    ) -> None:
        self.scheme = canonical_scheme(scheme)
        self.n_planets = _count(n_planets)
        if not isinstance(carrier, str) or not carrier or carrier in ("sun", "ring", "planet"):
            raise TrainError(
                f"carrier = {carrier!r}; give a non-empty member name other than sun/ring/planet"
            )
        self.carrier = carrier
        c = float(clearance) if isinstance(clearance, numbers.Real) else math.nan
        if not (math.isfinite(c) and c >= 0):
            raise TrainError(f"clearance = {clearance!r}; valid is a number >= 0 (modules)")
        self.clearance = c
        self.tip_shortening = bool(tip_shortening)
        self.ring_tip_relief = bool(ring_tip_relief)
        self._relief: dict[str, tuple[float, float]] = {}  # ring key -> (nominal, relieved d_a)
        two_planets = self.scheme != "simple"
        if _is_pair(planet):
            p1, p2 = planet
            if not two_planets:
                z = [g.teeth if isinstance(g, Gear) else g for g in planet]
                if z[0] != z[1]:
                    raise TrainError(
                        f"planet = {planet!r} is a stepped planet; use scheme='stepped' (or give"
                        " one tooth count for a simple planet)"
                    )
                planet = p1
        else:
            p1 = p2 = planet
        given = {"sun": sun, "planet": planet if not two_planets else p1, "ring": ring}
        if two_planets:
            given["planet2" if self.scheme == "double-planet" else "planet'"] = p2
        given = {k: _teeth_or_gear(v, k) for k, v in given.items()}
        gears_in = [g for g in given.values() if isinstance(g, Gear)]
        if module is None:
            module = gears_in[0].module if gears_in else 1.0
        try:
            self.module = check_module(module)
        except GearError as exc:
            raise TrainError(str(exc)) from None
        ref = gears_in[0] if gears_in else None
        if ref is not None:
            sign0 = dict((k, h) for k, _, h in _GEARS[self.scheme])
            key0 = next(k for k, v in given.items() if v is ref)
            helix = ref.helix_angle * sign0[key0]
            pa = ref.pressure_angle
        else:
            try:
                helix, pa = check_angle("helix_angle", helix_angle), pressure_angle
            except GearError as exc:
                raise TrainError(str(exc)) from None
        gears: dict[str, Gear] = {}
        for key, internal, hsign in _GEARS[self.scheme]:
            v = given[key]
            if isinstance(v, Gear):
                if v.internal != internal:
                    want = "an internal" if internal else "an external"
                    raise TrainError(
                        f"{key} must be {want} gear in the {self.scheme} scheme; got a Gear with"
                        f" internal={v.internal}"
                    )
                if not math.isclose(v.module, self.module, rel_tol=1e-12):
                    raise TrainError(
                        f"{key} has module {v.module:g} but the stage has module {self.module:g};"
                        " every gear of a stage needs the same module"
                    )
                gears[key] = v
            else:
                try:
                    gears[key] = Gear(v, self.module, pa, hsign * helix, internal=internal)
                except GearError as exc:
                    raise TrainError(f"{key}: {exc}") from None
        if self.scheme == "simple":
            gears["planet'"] = gears["planet"]
        self._gears_in = gears
        pairs: dict[str, GearPair] = {}
        for name, k1, k2 in _MESHES[self.scheme]:
            try:
                pairs[name] = GearPair(gears[k1], gears[k2], self.tip_shortening)
            except GearError as exc:
                raise TrainError(f"mesh {name}: {exc}") from None
            if ring_tip_relief and pairs[name].internal:
                pairs[name] = self._relieve_ring_tip(pairs[name], gears, k2)
        self._pairs = pairs

    def _relieve_ring_tip(self, pair: GearPair, gears: dict[str, Gear], key: str) -> GearPair:
        """The pair with its ring's tip enlarged to clear the planet's fillet (if it reaches it)."""
        ring = pair.g2
        if ring.tip_alteration != 0.0:
            return pair
        try:
            limit = pair.tip_diameter_limits[1]
        except GearError:
            return pair  # no contact geometry: the pair's own findings report why
        if ring.tip_diameter >= limit:
            return pair
        target = math.ceil(limit * 1000.0) / 1000.0
        # internal: d_a2 = d2 - 2 m_n (h_a + x + k) (DIN 3960)  ->  k for d_a2 = target
        k = (ring.reference_diameter - target) / (2 * ring.module) - ring.rack.addendum
        k -= ring.profile_shift
        relieved = ring.with_(tip_alteration=k)
        gears[key] = relieved
        self._relief[key] = (ring.tip_diameter, target)
        return GearPair(pair.g1, relieved, self.tip_shortening)

    # ---- construction by centre distance --------------------------------------------------
    @classmethod
    def coaxial(
        cls,
        sun: Any,
        planet: Any,
        ring: Any,
        n_planets: int,
        module: float | None = None,
        center_distance: float | None = None,
        split: str = "equal_sliding",
        scheme: str = "simple",
        **kwargs: Any,
    ) -> Planetary:
        """A stage made coaxial by profile shifts at one working centre distance.

        Each pair gets the shift sum its centre distance needs (ISO 21771: cos alpha_w = a_d
        cos alpha / a_w; x_s + x_p and x_p + x_r from the involute function, the ring's x_r in
        the sign of DIN 3960) for the common centre distance ``center_distance``; ``split``
        (:meth:`gears.GearPair.at_center_distance`) shares the sun-planet sum, and the ring takes
        the rest of its pair with the planet's shift kept. Without ``center_distance`` the
        distance nearest the mean of the two reference centre distances whose stage passes every
        coaxiality, neighbour and mesh check is chosen (on a 0.01 module grid); if none passes,
        the one with the fewest failing findings.

        Parameters
        ----------
        sun, planet, ring, n_planets, module, scheme
            As for :class:`Planetary` (simple or stepped schemes; Gears keep their other data).
        center_distance : float, optional
            Working centre distance a_w in mm.
        split : str
            ``"equal_sliding"``, ``"proportional"`` or ``"keep"`` for the sun-planet pair.

        Raises
        ------
        TrainError
            For a scheme other than simple/stepped, or a centre distance no shift can reach.

        Examples
        --------
        Sun 21, planet 43, ring 108 (lectures §4.3: 21 + 2 x 43 = 107, one tooth short of
        coaxial) made coaxial with shifts:

        >>> p = Planetary.coaxial(21, 43, 108, n_planets=3, module=1)
        >>> bool(p.check()["coaxiality"].ok)
        True
        """
        from trains.planetary.shifts import coaxial_stage

        return coaxial_stage(cls, sun, planet, ring, n_planets, module, center_distance, split,
                             scheme, **kwargs)  # fmt: skip

    # ---- gears and meshes ------------------------------------------------------------------
    @property
    def meshes(self) -> dict[str, GearPair]:
        """The meshes by name (``"sun-planet"``, ``"planet-ring"``, ...) as GearPairs."""
        return dict(self._pairs)

    def _mounted(self, key: str) -> Gear:
        """A gear as made: with the most negative tip alteration of its external meshes."""
        gear = self._gears_in[key]
        k = 0.0
        for name, k1, k2 in _MESHES[self.scheme]:
            if key in (k1, k2) and not self._pairs[name].internal:
                k = min(k, self._pairs[name].tip_alteration)
        return gear.with_(tip_alteration=k) if k != 0.0 else gear

    @cached_property
    def sun(self) -> Gear:
        """Central gear a (a ring in the ``internal`` scheme), with its tip shortening."""
        return self._mounted("sun")

    @cached_property
    def planet(self) -> Gear:
        """The planet gear meshing the sun (the inner planet of a double-planet stage)."""
        return self._mounted("planet")

    @cached_property
    def planet_gears(self) -> tuple[Gear, ...]:
        """Every distinct planet gear: ``(planet,)``, ``(sun side, ring side)`` or
        ``(inner, outer)``."""
        if self.scheme == "simple":
            return (self.planet,)
        other = "planet2" if self.scheme == "double-planet" else "planet'"
        return (self.planet, self._mounted(other))

    @cached_property
    def ring(self) -> Gear:
        """Central gear b (an external gear in the ``external`` scheme)."""
        return self._mounted("ring")

    @property
    def teeth(self) -> tuple[int, int, int, int]:
        """``(z1, z2, z2', z3)``: sun, planet on the sun, planet on the ring, ring."""
        z = {k: g.teeth for k, g in self._gears_in.items()}
        zr = z.get("planet2", z.get("planet'"))
        return z["sun"], z["planet"], zr, z["ring"]

    def _z(self) -> tuple[int, int, int, int]:
        return self.teeth

    # ---- kinematics ------------------------------------------------------------------------
    @cached_property
    def train(self) -> Train:
        """The stage as a :class:`trains.Train` (members sun, planet[, planet2], ring, carrier)."""
        t = Train()
        internal_keys = {k for k, internal, _ in _GEARS[self.scheme] if internal}
        for name, k1, k2 in _MESHES[self.scheme]:
            # Willis mesh from the member nearer the sun to the one nearer the ring
            a, b = (k2, k1) if (self.scheme == "internal" and name == "sun-planet") else (k1, k2)
            internal = k1 in internal_keys or k2 in internal_keys
            za, zb = self._gears_in[a].teeth, self._gears_in[b].teeth
            pair = self._pairs[name]  # the real gears: Train.check and friction= work on it
            real = {"pair": pair} if a == k1 else {"gears": (pair.g2, pair.g1)}
            t.mesh(_TRAIN_MEMBER[a], _TRAIN_MEMBER[b], teeth=(za, zb), carrier=self.carrier,
                   internal=internal, name=name, **real)  # fmt: skip
        try:
            t.set_planets("planet", self.n_planets)
            if self.scheme == "double-planet":
                t.set_planets("planet2", self.n_planets)
        except (AttributeError, TrainError):  # pragma: no cover - older Train
            pass
        return t

    @property
    def basic_ratio(self) -> Fraction:
        """i0 = i_13^(H), the ratio sun/ring with the carrier held (exact)."""
        n, d = basic_ratio(self.scheme, *self._z())
        return Fraction(int(n), int(d))

    def _member(self, name: str) -> str:
        return "carrier" if name in ("carrier", self.carrier) else name

    def ratio(
        self, fixed: str = "ring", input: str | None = None, output: str | None = None
    ) -> Fraction:
        """Exact ratio ``w_input / w_output`` with ``fixed`` held (Ozols' i, signed).

        Defaults: ring fixed -> sun to carrier; sun fixed -> ring to carrier; carrier fixed ->
        sun to ring. Members are ``"sun"``, ``"ring"``, ``"carrier"`` (or the carrier's name).
        Solved by :attr:`train` (the generic Willis solver).

        Raises
        ------
        TrainError
            For an unknown member, or a locked input / standing output (infinite ratio).

        Examples
        --------
        >>> p = Planetary(20, 30, 80, n_planets=2)    # Ozols derived case (7.7)
        >>> p.ratio(), p.ratio(fixed="sun"), p.ratio(fixed="carrier")
        (Fraction(5, 1), Fraction(5, 4), Fraction(-4, 1))
        """
        fixed, input, output = _default_roles(
            self._member(fixed),
            None if input is None else self._member(input),
            None if output is None else self._member(output),
        )
        name = {"sun": "sun", "ring": "ring", "carrier": self.carrier}
        return self.train.ratio(name[input], name[output], fixed=[name[fixed]])

    def planet_speed(self, fixed: str = "ring", input: str | None = None) -> dict[str, Fraction]:
        """Speed of each planet relative to the carrier per unit input speed (bearing speed).

        Lectures §2.3 [P] 683: ``w_2 - w_H = (w_1 - w_H)(-z_1/z_2)`` for an external sun mesh.

        Examples
        --------
        >>> Planetary(20, 30, 80, n_planets=2).planet_speed()   # 1500 rpm in -> -800 rpm
        {'planet': Fraction(-8, 15)}
        """
        fixed, input, _ = _default_roles(
            self._member(fixed), None if input is None else self._member(input), None
        )
        name = {"sun": "sun", "ring": "ring", "carrier": self.carrier}
        motion = self.train.solve({name[input]: 1, name[fixed]: 0})
        planets = ["planet", "planet2"] if self.scheme == "double-planet" else ["planet"]
        return {pl: motion.relative(pl, self.carrier) for pl in planets}

    def efficiency(
        self,
        fixed: str = "ring",
        input: str | None = None,
        output: str | None = None,
        mesh_efficiency: Any = None,
        friction: float = 0.1,
        *,
        torque: float | None = None,
        speed: float | None = None,
    ) -> float:
        """Efficiency input -> output by the relative-power (Kreines/Müller) method.

        Solved by :func:`trains.power_flow` on :attr:`train`: in the carrier frame each
        mesh has efficiency ``mesh_efficiency`` (or its GearPair's Ozols (14.25) value with
        ``friction``), lost at whichever end drives in relative motion (Kreines / Müller; Ozols
        (14.26)). A negative value means self-locking in that direction.

        ``mesh_efficiency="gears"`` (or a callable ``(pair, torque, speed) -> efficiency``)
        takes each mesh's efficiency from its gears at the operating point,
        :meth:`gears.GearPair.efficiency` (ISO/TR 14179-2), which needs the input's ``torque``
        (N m) and ``speed`` (rpm).

        Examples
        --------
        Müller's relative-power rule: i0 = -4, eta0 = 0.97 gives eta_1H = 0.976.

        >>> p = Planetary(20, 30, 80, n_planets=2)
        >>> round(p.efficiency(mesh_efficiency=0.97 ** 0.5), 6)
        0.976
        >>> from gears import Gear
        >>> p = Planetary(Gear(20, 2, face_width=20), Gear(31, 2, face_width=20),
        ...               Gear(82, 2, internal=True, face_width=20), n_planets=3)
        >>> round(p.efficiency(mesh_efficiency="gears", torque=60, speed=1500), 4)
        0.9894
        """
        fixed, input, output = _default_roles(
            self._member(fixed),
            None if input is None else self._member(input),
            None if output is None else self._member(output),
        )
        name = {"sun": "sun", "ring": "ring", "carrier": self.carrier}
        operating = isinstance(mesh_efficiency, str) or (
            callable(mesh_efficiency) and not isinstance(mesh_efficiency, dict)
        )
        if operating:
            if torque is None or speed is None:
                raise TrainError(
                    f"mesh_efficiency = {mesh_efficiency!r} needs the input's torque (N m) and "
                    "speed (rpm): give torque= and speed="
                )
            for what, value in (("torque", torque), ("speed", speed)):
                if (isinstance(value, bool) or not isinstance(value, int | float)
                        or not (math.isfinite(value) and value > 0)):  # fmt: skip
                    raise TrainError(f"{what} = {value!r}; valid is a finite number > 0")
            flow = power_flow(self.train, name[input], name[output], fixed=[name[fixed]],
                              mesh_efficiency=mesh_efficiency, input_torque=float(torque),
                              input_speed=float(speed))  # fmt: skip
            return float(flow.efficiency)
        etas = {} if mesh_efficiency is None else {n: mesh_efficiency for n in self._pairs}
        flow = power_flow(self.train, name[input], name[output], fixed=[name[fixed]],
                          mesh_efficiency=etas,
                          friction=friction if mesh_efficiency is None else None)  # fmt: skip
        return float(flow.efficiency)

    def rating(
        self,
        torque: float | None = None,
        speed: float | None = None,
        face_width: float | dict | None = None,
        material: Any = "case-carburized",
        fixed: str = "ring",
        input: str | None = None,
        output: str | None = None,
        load_sharing_factor: float | dict | None = None,
        **options: Any,
    ) -> dict:
        """ISO 6336 rating of every mesh of the stage (docs/rating.md), by
        :func:`trains.rating` on :attr:`train`.

        ``torque`` (N m) and ``speed`` (rpm) are the input member's; the roles default as in
        :meth:`ratio` (ring fixed: sun in, carrier out). Each mesh carries its share of the
        torque per planet, times the load-sharing factor K_gamma (default
        :func:`trains.load_sharing` of ``n_planets``, or ``load_sharing_factor``), at its speed
        relative to the carrier; a central gear counts one load cycle per planet and turn, a
        planet is an idler (Y_M). ``face_width`` (mm, or per mesh name) defaults to the gears'
        own; ``options`` go to :meth:`gears.GearPair.rating` (``life``, ``quality``, factors).

        Returns
        -------
        dict
            Mesh name (``"sun-planet"``, ``"planet-ring"``, ...) -> :class:`gears.Rating`.

        Examples
        --------
        >>> p = Planetary(sun=21, planet=36, ring=93, n_planets=3, module=2)
        >>> r = p.rating(torque=120, speed=1500, face_width=20)
        >>> {k: round(min(v.safety_pitting), 2) for k, v in r.items()}
        {'sun-planet': 1.07, 'planet-ring': 2.21}

        A load spectrum (ISO 6336-6: ``(torque, speed, hours)`` bins on the input) instead:

        >>> r = p.rating(spectrum=[(120, 1500, 5000), (200, 1500, 200)], face_width=20)
        >>> {k: round(min(v.safety_pitting), 2) for k, v in r.items()}
        {'sun-planet': 1.03, 'planet-ring': 2.27}
        """
        fixed, input, output = _default_roles(
            self._member(fixed),
            None if input is None else self._member(input),
            None if output is None else self._member(output),
        )
        name = {"sun": "sun", "ring": "ring", "carrier": self.carrier}
        if options.get("spectrum") is not None:
            if torque is not None or speed is not None:
                raise TrainError("give either torque and speed or spectrum=, not both")
            torque = speed = 1.0  # the spectrum's bins give them
        elif torque is None or speed is None:
            raise TrainError("rating needs torque (N m) and speed (rpm), or spectrum=")
        return rate_train(self.train, name[input], name[output], fixed=[name[fixed]],
                          torque=torque, speed=speed, material=material, face_width=face_width,
                          load_sharing_factor=load_sharing_factor, **options)  # fmt: skip

    def loads(self, torque: float, speed: float, fixed: str = "ring", input: str | None = None,
              output: str | None = None, load_sharing_factor: float | None = None,
              **options: Any) -> TrainLoads:  # fmt: skip
        """Every force of the stage, :func:`trains.loading.planetary_loads` (``options``:
        ``face_width``, ``material``, ``planet_mass``, ``unequal_sharing``, ...) with the roles
        of :meth:`ratio`, K_gamma by default :func:`trains.load_sharing`; ``torque`` (N m) and
        ``speed`` (rpm) are the input's. Ozols (11.11): M_H = M1 (1 + r3/r1).

        >>> ld = Planetary(21, 36, 93, n_planets=3, module=2).loads(100, 1500, planet_mass=0.6)
        >>> round(ld.notes["carrier torque [N m]"], 6), round(ld.members["sun"].radial_load, 6)
        (-542.857143, 0.0)
        """
        roles = _default_roles(self._member(fixed), input and self._member(input),
                               output and self._member(output))  # fmt: skip
        fixed, input, output = ({"carrier": self.carrier}.get(r, r) for r in roles)
        k = load_sharing(self.n_planets) if load_sharing_factor is None else load_sharing_factor
        return planetary_loads(self, input, output, fixed, torque, speed, k, **options)

    def contact(self, torque: float, *, fixed: str = "ring", input: str | None = None,
                output: str | None = None, load_sharing_factor: float = 1.0,
                face_width: float | None = None, angles: Iterable[float] | None = None,
                **options: Any) -> StageContact:  # fmt: skip
        """Loaded tooth contact of every mesh (:class:`trains.planetary.contact.StageContact`):
        one planet's mesh of each kind by :meth:`gears.GearPair.contact` under its torque share
        (``torque`` N m on the input, roles as in :meth:`ratio`, times ``load_sharing_factor``),
        the planets' mesh phases from :meth:`placement` (``angles``), and the net transmission
        error. ``face_width`` (mm) replaces the gears' own; ``options`` go to the contact.

        >>> c = Planetary(19, 29, 77, n_planets=3, module=2).contact(40, face_width=20,
        ...                                                          positions=32, slices=1)
        >>> [round(g, 4) for g in c.phases["sun-planet"]], c.in_phase("sun-planet")
        ([0.0, 0.3333, 0.6667], False)
        """
        return stage_contact(self, torque, fixed=fixed, input=input, output=output,
                             load_sharing_factor=load_sharing_factor, face_width=face_width,
                             angles=angles, **options)  # fmt: skip

    # ---- conditions (trains.planetary.checks) ---------------------------------------------
    def assembly(self) -> Assembly:
        """The exact and textbook assembly conditions, unequal spacing and nearest counts.

        Examples
        --------
        The compound planet the textbook form rejects (lectures §4.3, scheme B, i = 16):

        >>> a = Planetary(26, (70, 21), 117, n_planets=3, scheme="stepped").assembly()
        >>> a.exact, a.textbook, a.ticks
        (True, False, 1248)
        >>> Planetary(19, 30, 80, n_planets=4).assembly().nearest_counts  # 99 ticks
        (3, 9)
        """
        return checks.assembly(self)

    @property
    def max_planets(self) -> int:
        """The largest planet count that passes the neighbour condition (>= 1)."""
        return checks.max_planets(self)

    def check(
        self,
        tolerance: float = 0.01,
        min_contact_ratio: float = 1.1,
        min_tip_land: float = 0.2,
    ) -> Report:
        """Every condition of the stage, each a :class:`gears.report.Finding` with a margin.

        Findings: ``coaxiality`` (mm, tolerance ``tolerance``), ``assembly`` (ticks; the exact
        gcd form), ``assembly_textbook`` (informative: the sufficient textbook form),
        ``neighbour`` (mm), ``redundant_constraints`` (informative note), and every mesh's own
        :meth:`gears.GearPair.check` findings prefixed by the mesh name (``"sun-planet."``...).

        Examples
        --------
        Ozols §21-13 derived case: 20/30/80 assembles with 2 and 4 planets, not 3.

        >>> Planetary(20, 30, 80, n_planets=3).check()["assembly"].ok
        False
        """
        return checks.check(self, tolerance, min_contact_ratio, min_tip_land)

    # ---- placement and phasing (trains.planetary.placement) --------------------------------
    @property
    def phasing(self) -> dict[str, str]:
        """Mesh phasing class of each central-gear mesh (:func:`phasing_class`)."""
        return placement.phasing(self)

    def placement(self, angles: Iterable[float] | None = None) -> Placement:
        """Planet positions and the rotation of every gear at assembly (all meshes in phase).

        Parameters
        ----------
        angles : iterable of float, optional
            Planet centre angles in degrees; default: equal spacing when the stage assembles,
            otherwise the feasible unequal spacing of :meth:`assembly`.

        Returns
        -------
        Placement
            Its ``residual`` is the largest tooth-phase error (0 when every planet fits).

        Examples
        --------
        >>> pl = Planetary(18, 45, 108, n_planets=3, module=2).placement()
        >>> pl.planet_angles, round(pl.residual, 12)
        ((0.0, 120.0, 240.0), 0.0)
        """
        return placement.placement(self, angles)

    # ---- outlines, 3D scene and animation (trains.planetary.scene) -------------------------
    def outlines(self, angle: float = 0.0, tolerance: float = 0.01, fixed: str = "ring") -> dict:
        """Every gear's 2D outline placed in mesh with the carrier turned by ``angle`` degrees
        (see :meth:`scene`): ``{"ring": ..., "sun": ..., "planet1": ..., ...}`` (shapely
        Polygons; the ring with its default rim). A stepped planet's ring-side step is
        ``planet1'`` ..., the outer planets of a double-planet stage ``outer1`` ....

        Examples
        --------
        >>> o = Planetary(18, 45, 108, n_planets=3, module=2).outlines(tolerance=0.01)
        >>> sorted(o), o["ring"].intersection(o["planet1"]).area < 0.01   # mm^2: chords only
        (['planet1', 'planet2', 'planet3', 'ring', 'sun'], True)
        """
        return scene.outlines(self, angle, tolerance, fixed)

    def scene(self, angle: float = 0.0, face_width: float | None = None,
              tolerance: float = 0.01, fixed: str = "ring", herringbone: bool = False,
              progress: Callable[[int, int], object] | None = None,
              check: bool = True) -> trimesh.Scene:  # fmt: skip
        """The stage as a ``trimesh.Scene`` with real teeth, every mesh engaged.

        Sun, ring and every planet sit at the real centre distances, turned to their phase from
        :meth:`placement`; the carrier turns by ``angle`` degrees (the sun, when ``fixed`` is the
        carrier) and every member by the Willis speeds of :attr:`train`, so a sequence of angles
        animates the stage. Identical planets share one geometry (instanced by node
        transforms), so a GLB holds one planet mesh. The ring side of a stepped planet stands
        on the sun side (mid-planes at -b/2 and +b/2). ``face_width`` defaults to the gears'
        own or 10 modules; ``tolerance`` (mm) applies to each gear
        (:func:`gears.solid.mesh.gear_solid`);
        ``progress(done, total)`` is called after each distinct solid. Every argument is
        checked and the scene's size (its distinct solids) estimated before any work: over the
        mesh budget it is refused with the tolerance that fits (:data:`gears.budget.BUDGETS`).
        A stage that fails :meth:`check` (planets that collide, teeth that interfere) is
        refused unless ``check=False``.

        Examples
        --------
        >>> s = Planetary(18, 45, 108, n_planets=3, module=2).scene(tolerance=0.1)
        >>> len(s.geometry), len(s.graph.nodes_geometry)
        (3, 5)
        """
        return scene.scene(self, angle, face_width, tolerance, fixed, herringbone, progress,
                           check)  # fmt: skip

    def animate(self, path: str | os.PathLike[str], frames: int = 48, fps: float = 20.0,
                turn: float | None = None, tolerance: float = 0.02, fixed: str = "ring",
                progress: Callable[[int, int], object] | None = None,
                check: bool = True) -> pathlib.Path:  # fmt: skip
        """Write a GIF (or MP4 with ffmpeg) of the stage's outlines in mesh while it turns.

        ``turn`` is the carrier rotation covered, degrees (the sun's when the carrier is
        ``fixed``); default one mesh cycle, ``360 / (z_sun |w_sun - w_carrier|)`` per unit
        carrier speed, after which the picture repeats. Phasing from :meth:`placement`,
        speeds from the Willis solver; frames are written by
        :func:`gears.solid.animate.write_animation` (``progress(i, n)`` after each frame). Every
        argument (the file's folder too) is checked and the drawing's size (frames times the
        outline vertices of every gear drawn) estimated before any work: over the animation
        budget it is refused with the tolerance that fits. A stage that fails :meth:`check` is
        refused unless ``check=False`` (:meth:`scene`).
        """
        return scene.animate(self, path, frames, fps, turn, tolerance, fixed, progress, check)

    def mesh_cycle(self, fixed: str = "ring") -> float:
        """Carrier rotation (degrees; the sun's when the carrier is fixed) over which every
        tooth mesh advances by one pitch, so the stage looks the same again."""
        return scene.mesh_cycle(self, fixed)

    def __repr__(self) -> str:
        z1, z2, z2p, z3 = self._z()
        planet = f"{z2}" if self.scheme == "simple" else f"({z2}, {z2p})"
        return (
            f"Planetary(sun={z1}, planet={planet}, ring={z3}, n_planets={self.n_planets}, "
            f"module={self.module:g}, scheme={self.scheme!r})"
        )

    def _repr_svg_(self) -> str:
        """The stage in mesh, planets phased (:meth:`outlines`), as an SVG picture: what a
        notebook shows (:func:`gears.figures.drawing.outlines_svg`; a text when it cannot be
        drawn)."""
        return scene.svg(self)

    def describe(self) -> str:
        """A readable summary: teeth, ratio, planet speed, placement, phasing and the report."""
        lines = [repr(self)]
        try:
            lines.append(f"ratio (ring fixed, sun -> carrier): {self.ratio()} "
                         f"= {float(self.ratio()):.6g}")  # fmt: skip
            speeds = ", ".join(f"{k} {v} ({float(v):+.6g})" for k, v in self.planet_speed().items())
            lines.append(f"planet speed relative to the carrier per unit input: {speeds}")
            lines.append(f"efficiency sun -> carrier (friction 0.1): {self.efficiency():.5f}")
        except TrainError as exc:
            lines.append(f"ratio (ring fixed): {exc}")
        for name, pair in self._pairs.items():
            g1, g2 = pair.mounted
            lines.append(
                f"{name}: z {g1.teeth}/{g2.teeth}, x {g1.profile_shift:+.4f}/"
                f"{g2.profile_shift:+.4f}, a_w {pair.center_distance:.4f} mm, alpha_w "
                f"{pair.working_pressure_angle:.4f} deg, eps_alpha {pair.contact_ratio:.4f}"
            )
        lines.append("phasing: " + ", ".join(f"{k} {v}" for k, v in self.phasing.items()))
        pl = self.placement()
        lines.append("planet angles (deg): " + ", ".join(f"{a:.3f}" for a in pl.planet_angles))
        lines.append(str(self.check()))
        return "\n".join(lines)


def _count(n_planets: Any) -> int:
    """An integer 1 ... MAX_PLANETS (:data:`trains.planetary.checks.MAX_PLANETS`)."""
    valid = f"valid is an integer 1 ... {MAX_PLANETS}"
    if isinstance(n_planets, bool):
        raise TrainError(f"n_planets = {n_planets!r}; {valid}")
    try:
        k = operator.index(n_planets)
    except TypeError:
        raise TrainError(f"n_planets = {n_planets!r}; {valid}") from None
    try:
        return check_integer("n_planets", k, 1, MAX_PLANETS)
    except GearError as exc:
        raise TrainError(str(exc)) from None
