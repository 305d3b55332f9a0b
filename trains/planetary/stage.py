"""Layer 5, stages and catalog.

One planetary (2K-H) stage on real gears: ratios, coaxiality, assembly, neighbours, phasing.

A stage has two central gears, called ``sun`` (central gear *a*, lectures' link 1) and ``ring``
(central gear *b*, link 3) whatever their kind, a carrier, and ``n_planets`` identical planets
(or planet pairs). The mesh topology is the ``scheme`` (lectures §4.2 / standards.md §4; the
letters differ between authors, so the code names schemes by topology and keeps the letters as
aliases):

==================  ===================================  =========================  ==========
scheme              meshes                               basic ratio i0 = i_13^(H)  alias
==================  ===================================  =========================  ==========
``simple``          sun-planet ext, planet-ring int      -z3/z1                     A, james
``stepped``         sun-planet ext, planet'-ring int     -z2 z3 / (z1 z2')          B
``external``        sun-planet ext, planet'-ring ext     +z2 z3 / (z1 z2')          C, david
``internal``        sun(ring)-planet int, planet'-ring   +z2 z3 / (z1 z2')          D
``double-planet``   sun-planet ext, planet-planet2 ext,  +z3/z1
                    planet2-ring int
==================  ===================================  =========================  ==========

Ratios follow from the Willis relation ``w_sun - i0 w_ring - (1 - i0) w_carrier = 0``
(Ozols (7.6), (7.7)) and are exact :class:`fractions.Fraction`\\ s.

The three textbook conditions are evaluated on the real gears (profile shifts, tip shortening,
helix), each with a signed margin (Ozols §21-13; lectures §4.3; standards.md §4):

* coaxiality: the working centre distances of the meshes agree (each a_w from its own working
  pressure angle), or for the double-planet scheme the planet triangle closes with clearance;
* assembly: the exact gcd form ``N / (k gcd(z_c, z_d)) in Z`` with
  ``N = |z_b z_c - s_a s_b z_a z_d|`` (s = -1 external, +1 internal mesh; lectures §4.3,
  standards.md §4), and the textbook sufficient form ``(z_a i_aH / k)(1 + k p) in Z`` reported
  beside it; both in integer arithmetic;
* neighbour: the smallest gap between the tip circles of planets that do not mesh, against a
  clearance (``2 a_w sin(pi/k) - d_a`` for one planet row).
"""

from __future__ import annotations

import math
import numbers
import operator
import os
import pathlib
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from fractions import Fraction
from functools import cached_property
from typing import TYPE_CHECKING, Any

import numpy as np

from gears import Gear, GearPair
from gears.arguments import (
    check_angle,
    check_callback,
    check_flag,
    check_fps,
    check_frames,
    check_length,
    check_positive,
    check_real,
    check_tolerance,
)
from gears.budget import check_budget
from gears.cutting.outline import outline_vertices
from gears.errors import GearError
from gears.figures.drawing import display_tolerance, outlines_svg
from gears.files import check_output
from gears.report import Finding, Report
from gears.solid.animate import FORMATS, write_animation
from gears.solid.mesh import COLOURS, gear_solid, helix_twist, scene, transform
from trains.capacity import rating as rate_train
from trains.conditions import assembly_number
from trains.errors import TrainError
from trains.power import power_flow
from trains.willis import Train

if TYPE_CHECKING:
    import trimesh

__all__ = [
    "NEIGHBOUR_TOLERANCE",
    "SCHEMES",
    "Assembly",
    "Placement",
    "Planetary",
    "assembly_ticks",
    "basic_ratio",
    "coaxial_ring_teeth",
    "phasing_class",
    "stage_ratio",
]

#: The stage schemes a :class:`Planetary` takes (``scheme=``).
SCHEMES = ("simple", "stepped", "external", "internal", "double-planet")
_ALIASES = {
    "a": "simple", "james": "simple", "sun-planet-ring": "simple",
    "b": "stepped", "compound": "stepped", "ext-int": "stepped",
    "c": "external", "david": "external", "ext-ext": "external",
    "d": "internal", "int-int": "internal",
    "double": "double-planet", "double_planet": "double-planet",
}  # fmt: skip
_MEMBERS = ("sun", "ring", "carrier")


def canonical_scheme(scheme: Any) -> str:
    """The scheme name for ``scheme`` or one of its aliases (``"A"`` ... ``"D"``, ``"james"``).

    Raises
    ------
    TrainError
        For an unknown scheme.
    """
    if isinstance(scheme, str):
        s = scheme.strip().lower()
        if s in SCHEMES:
            return s
        if s in _ALIASES:
            return _ALIASES[s]
    raise TrainError(
        f"scheme = {scheme!r}; valid are {', '.join(SCHEMES)} (aliases A, B, C, D, james, david)"
    )


# --------------------------------------------------------------------------------- integer core
# Vectorised over numpy integer arrays (or Python ints); exact: no floats anywhere.


def basic_ratio(scheme: str, z1, z2, z2p, z3):
    """Basic (carrier-fixed) ratio i0 = i_13^(H) as an integer pair ``(numerator, denominator)``.

    ``z1`` sun (central gear a), ``z2`` the planet gear meshing it, ``z2p`` the planet gear meshing
    the ring (``z2p = z2`` for one row; the outer planet of a double-planet stage), ``z3`` ring
    (lectures §4.2 table). Arrays broadcast.

    Examples
    --------
    >>> basic_ratio("stepped", 20, 40, 20, 80)   # standards.md §4: -(40 80)/(20 20)
    (-3200, 400)
    """
    scheme = canonical_scheme(scheme)
    if scheme == "double-planet":
        return z3, z1
    sign = -1 if scheme in ("simple", "stepped") else 1
    return sign * z2 * z3, z1 * z2p


def _coefficients(num, den):
    """Willis coefficients of (sun, ring, carrier): den w_s - num w_r + (num - den) w_H = 0."""
    return {"sun": den, "ring": -num, "carrier": num - den}


def stage_ratio(scheme: str, z1, z2, z2p, z3, fixed="ring", input="sun", output="carrier"):
    """Exact ratio ``w_input / w_output`` with ``fixed`` held, as ``(numerator, denominator)``.

    From ``w_s - i0 w_r - (1 - i0) w_H = 0`` (Ozols (7.6)): with one member fixed the ratio is
    ``-c_output / c_input`` of the Willis coefficients, reduced, with a positive denominator. A
    zero denominator means the input is locked, a zero numerator that the output stands still.

    Examples
    --------
    >>> stage_ratio("simple", 20, 30, 30, 80)   # Ozols derived case: i_1H = 5
    (5, 1)
    >>> stage_ratio("simple", 20, 30, 30, 80, fixed="sun", input="ring")   # 1 - 1/i0 = 5/4
    (5, 4)
    """
    fixed, input, output = _roles(fixed, input, output)
    c = _coefficients(*basic_ratio(scheme, z1, z2, z2p, z3))
    num, den = -c[output], c[input]
    g = np.gcd(num, den)
    g = np.where(g == 0, 1, g) * np.where(den < 0, -1, 1)
    num, den = num // g, den // g
    if np.ndim(num) == 0:
        return int(num), int(den)
    return num, den


def _roles(fixed: Any, input: Any, output: Any) -> tuple[str, str, str]:
    names = []
    for what, v in (("fixed", fixed), ("input", input), ("output", output)):
        if v not in _MEMBERS:
            raise TrainError(f"{what} = {v!r}; valid are 'sun', 'ring', 'carrier'")
        names.append(v)
    if len(set(names)) != 3:
        raise TrainError(
            f"fixed = {fixed!r}, input = {input!r}, output = {output!r} must be three different"
            " members of 'sun', 'ring', 'carrier'"
        )
    return names[0], names[1], names[2]


def _default_roles(fixed: str, input: str | None, output: str | None) -> tuple[str, str, str]:
    if fixed not in _MEMBERS:
        raise TrainError(f"fixed = {fixed!r}; valid are 'sun', 'ring', 'carrier'")
    free = [m for m in _MEMBERS if m != fixed]
    if input is None:
        input = free[0] if output != free[0] else free[1]
    if output is None:
        output = next(m for m in free if m != input)
    return _roles(fixed, input, output)


def assembly_ticks(scheme: str, z1, z2, z2p, z3):
    """Assembly number T = N / gcd(z_c, z_d): planet positions per turn (tick 2 pi / T).

    ``N = |z_b z_c - s_a s_b z_a z_d|`` (lectures §4.3, standards.md §4); for one row this is
    ``z_s + z_r`` (Ozols §21-13). Identical planets assemble equally spaced iff ``T % k == 0``.
    For the double-planet scheme the rigid cluster behaves as one planet with the sun-side tooth
    count on both sides and a sign reversal, giving ``T = |z_r - z_s|``. Integer arithmetic.

    Examples
    --------
    >>> int(assembly_ticks("simple", 18, 45, 45, 108))   # 126 = 3 x 42: three planets fit
    126
    >>> int(assembly_ticks("stepped", 26, 70, 21, 117))  # (26 21 + 117 70) / 7 = 1248
    1248
    """
    scheme = canonical_scheme(scheme)
    if scheme == "double-planet":
        return np.abs(np.asarray(z3) - np.asarray(z1))
    internal_a = scheme == "internal"  # the sun of scheme D is a ring
    internal_b = scheme != "external"
    return assembly_number(z1, z2, z2p, z3, internal_a, internal_b)


def textbook_assembly(z_a: int, ratio_aH: Fraction, k: int) -> bool:
    """Textbook (sufficient) form: ``(z_a i_aH / k)(1 + k p)`` is an integer for some p >= 0.

    Exact: with ``z_a |i_aH| / k = u / v`` in lowest terms, ``v`` must divide ``1 + k p`` for some
    p, which is decided by p in ``range(v)``.
    """
    x = Fraction(z_a) * abs(Fraction(ratio_aH)) / k
    v = x.denominator
    return any((1 + k * p) % v == 0 for p in range(v))


def phasing_class(z_central: int, k: int) -> str:
    """Mesh phasing of k equally spaced planets on a central gear of ``z_central`` teeth.

    ``z mod k`` is 0: in-phase (tooth forces add, radial forces cancel); 1 or k - 1: sequential;
    otherwise counter-phase (standards.md §4, after drivetrainhub).
    """
    r = int(z_central) % int(k)
    if r == 0:
        return "in-phase"
    if r in (1, k - 1):
        return "sequential"
    return "counter-phase"


def coaxial_ring_teeth(scheme: str, z1, z2, z2p):
    """z3 from the zero-shift, one-module coaxiality condition (lectures §4.2 table).

    simple ``z1 + 2 z2``; stepped ``z1 + z2 + z2'``; external ``z1 + z2 - z2'``; internal
    ``z1 - z2 + z2'``. The double-planet scheme has no such equation (its planet triangle closes
    for a range of tooth counts).
    """
    scheme = canonical_scheme(scheme)
    if scheme == "simple":
        return z1 + 2 * z2
    if scheme == "stepped":
        return z1 + z2 + z2p
    if scheme == "external":
        return z1 + z2 - z2p
    if scheme == "internal":
        return z1 - z2 + z2p
    raise TrainError("the double-planet scheme has no tooth-count coaxiality equation")


# --------------------------------------------------------------------------------- results


@dataclass(frozen=True)
class Assembly:
    """The assembly condition of a stage (see :meth:`Planetary.assembly`).

    Attributes
    ----------
    n_planets : int
    ticks : int
        Assembly number T: positions per turn at which a planet fits (tick angle 360/T deg).
    exact : bool
        T is a multiple of n_planets (necessary and sufficient for identical planets with the
        same tooth phase on both steps).
    textbook : bool
        The sufficient textbook form ``(z_a i_aH / k)(1 + k p) in Z``.
    tick_angle : float
        360 / T degrees.
    spacing : tuple of float
        Planet centre angles in degrees: equal when ``exact``, otherwise the feasible unequal
        spacing closest to equal (each angle a multiple of the tick).
    max_deviation : float
        Largest deviation of ``spacing`` from equal spacing, degrees.
    nearest_counts : tuple of int
        The assemblable counts (divisors of T) nearest below and above n_planets.
    """

    n_planets: int
    ticks: int
    exact: bool
    textbook: bool
    tick_angle: float
    spacing: tuple[float, ...]
    max_deviation: float
    nearest_counts: tuple[int, ...]


@dataclass(frozen=True)
class Placement:
    """Where each planet sits and how every gear is turned at assembly (degrees).

    A gear's *rotation* is the direction of the centre line of its tooth 0 in the stage frame
    (external gear: a tooth; ring: a ring tooth); the sun is at rotation 0. Every mesh is in
    phase: at each line of centres a tooth of one gear faces a space of the other. Stepped
    planets carry both steps with their tooth 0 on the same centre line.

    Attributes
    ----------
    planet_angles : tuple of float
        Centre angle of each planet (the sun-side planet of a double-planet cluster).
    planet_radius : float
        Distance from the stage axis to the planet centres, mm.
    planet_rotations : tuple of float
    planet2_angles, planet2_radius, planet2_rotations
        The outer planets of a double-planet stage (empty otherwise).
    sun_rotation, ring_rotation : float
    residual : float
        Largest mesh phase error in teeth (0 up to rounding when the stage assembles).
    """

    planet_angles: tuple[float, ...]
    planet_radius: float
    planet_rotations: tuple[float, ...]
    sun_rotation: float
    ring_rotation: float
    planet2_angles: tuple[float, ...] = ()
    planet2_radius: float = 0.0
    planet2_rotations: tuple[float, ...] = ()
    residual: float = 0.0


# --------------------------------------------------------------------------------- the stage


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


# mesh table: (name, gear key 1, gear key 2); the GearPair takes the first as g1 (external)
_MESHES = {
    "simple": (("sun-planet", "sun", "planet"), ("planet-ring", "planet", "ring")),
    "stepped": (("sun-planet", "sun", "planet"), ("planet-ring", "planet'", "ring")),
    "external": (("sun-planet", "sun", "planet"), ("planet-ring", "planet'", "ring")),
    "internal": (("sun-planet", "planet", "sun"), ("planet-ring", "planet'", "ring")),
    "double-planet": (
        ("sun-planet", "sun", "planet"),
        ("planet-planet2", "planet", "planet2"),
        ("planet2-ring", "planet2", "ring"),
    ),
}
# (gear key, internal?, helix sign relative to the sun's helix)
_GEARS = {
    "simple": (("sun", False, 1), ("planet", False, -1), ("ring", True, -1)),
    "stepped": (("sun", False, 1), ("planet", False, -1), ("planet'", False, -1),
                ("ring", True, -1)),
    "external": (("sun", False, 1), ("planet", False, -1), ("planet'", False, -1),
                 ("ring", False, 1)),
    "internal": (("sun", True, -1), ("planet", False, -1), ("planet'", False, -1),
                 ("ring", True, -1)),
    "double-planet": (("sun", False, 1), ("planet", False, -1), ("planet2", False, 1),
                      ("ring", True, 1)),
}  # fmt: skip
_TRAIN_MEMBER = {"sun": "sun", "planet": "planet", "planet'": "planet", "planet2": "planet2",
                 "ring": "ring"}  # fmt: skip


#: How far (in modules) a gap between planet tip circles may fall short of the clearance and
#: still pass: the rounding of ``2 a_w sin(pi / k)`` (six planets at clearance 0 touch exactly,
#: and land 1.8e-15 mm short). :func:`trains.synthesize` filters with the same tolerance, so its
#: candidates pass their own stage's check.
NEIGHBOUR_TOLERANCE = 1e-9


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
        if (
            isinstance(module, bool)
            or not isinstance(module, numbers.Real)
            or not (math.isfinite(float(module)) and float(module) > 0)
        ):
            raise TrainError(f"module = {module!r}; valid is a number > 0 (mm)")
        self.module = float(module)
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
        # internal: d_a2 = d2 - 2 m_n (h_a - x + k)  ->  k for d_a2 = target
        k = (ring.reference_diameter - target) / (2 * ring.module) - ring.rack.addendum
        k += ring.profile_shift
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

        The sun-planet pair gets the shift sum and the planet-ring pair the shift difference
        (standards.md §4: cos alpha_w = a_d cos alpha / a_w; x_s + x_p and x_r - x_p from the
        involute function) for the common centre distance ``center_distance``; ``split``
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
        scheme = canonical_scheme(scheme)
        if scheme not in ("simple", "stepped"):
            raise TrainError(
                f"Planetary.coaxial handles the simple and stepped schemes, not {scheme}"
            )
        base = cls(sun, planet, ring, n_planets, module, scheme=scheme, **kwargs)
        g = base._gears_in
        sun_g, p1, p2, ring_g = g["sun"], g["planet"], g["planet'"], g["ring"]
        a1 = base._pairs["sun-planet"].reference_center_distance
        a2 = base._pairs["planet-ring"].reference_center_distance

        def build(a: float) -> Planetary:
            try:
                sp = GearPair.at_center_distance(sun_g, p1, a, split=split)
                p2x = sp.g2 if scheme == "simple" else p2
                pr = GearPair.at_center_distance(p2x, ring_g, a, split="keep")
            except GearError as exc:
                raise TrainError(f"centre distance {a:.6g} mm: {exc}") from None
            planet_arg = sp.g2 if scheme == "simple" else (sp.g2, pr.g1)
            return cls(sp.g1, planet_arg, pr.g2, n_planets, base.module, scheme=scheme, **kwargs)

        if center_distance is not None:
            try:
                return build(check_real("center_distance", center_distance, 0.0))
            except GearError as exc:
                raise TrainError(str(exc)) from None
        m = base.module
        mean = (a1 + a2) / 2
        steps = np.arange(-150, 151) * 0.01 * m
        grid = mean + steps[np.argsort(np.abs(steps), kind="stable")]
        best, best_key = None, None
        for a in grid:
            try:
                stage = build(float(a))
                report = stage.check()
            except (TrainError, GearError):
                continue
            fails = [n for n in report.failed() if n not in ("assembly",)]
            if not fails:
                return stage
            key = (len(fails), abs(a - mean))
            if best_key is None or key < best_key:
                best, best_key = stage, key
        if best is None:
            raise TrainError(
                f"no working centre distance within 1.5 modules of {mean:.4f} mm makes sun "
                f"{sun_g.teeth}, planet {p1.teeth}/{p2.teeth}, ring {ring_g.teeth} coaxial"
            )
        return best

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
        mesh_efficiency: float | None = None,
        friction: float = 0.1,
    ) -> float:
        """Efficiency input -> output by the relative-power (Kreines/Müller) method.

        Solved by :func:`trains.power_flow` on :attr:`train`: in the carrier frame each
        mesh has efficiency ``mesh_efficiency`` (or its GearPair's Ozols (14.25) value with
        ``friction``), lost at whichever end drives in relative motion (standards.md §4; Ozols
        (14.26)). A negative value means self-locking in that direction.

        Examples
        --------
        standards.md §4: i0 = -4, eta0 = 0.97 gives eta_1H = 0.976.

        >>> p = Planetary(20, 30, 80, n_planets=2)
        >>> round(p.efficiency(mesh_efficiency=0.97 ** 0.5), 6)
        0.976
        """
        fixed, input, output = _default_roles(
            self._member(fixed),
            None if input is None else self._member(input),
            None if output is None else self._member(output),
        )
        etas = {} if mesh_efficiency is None else {n: mesh_efficiency for n in self._pairs}
        name = {"sun": "sun", "ring": "ring", "carrier": self.carrier}
        flow = power_flow(self.train, name[input], name[output], fixed=[name[fixed]],
                          mesh_efficiency=etas,
                          friction=friction if mesh_efficiency is None else None)  # fmt: skip
        return float(flow.efficiency)

    def rating(
        self,
        torque: float,
        speed: float,
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
        """
        fixed, input, output = _default_roles(
            self._member(fixed),
            None if input is None else self._member(input),
            None if output is None else self._member(output),
        )
        name = {"sun": "sun", "ring": "ring", "carrier": self.carrier}
        return rate_train(self.train, name[input], name[output], fixed=[name[fixed]],
                          torque=torque, speed=speed, material=material, face_width=face_width,
                          load_sharing_factor=load_sharing_factor, **options)  # fmt: skip

    # ---- conditions ------------------------------------------------------------------------
    def _planet_tips(self) -> tuple[float, ...]:
        return tuple(g.tip_diameter for g in self.planet_gears)

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
        z1, z2, z2p, z3 = self._z()
        k = self.n_planets
        t = int(assembly_ticks(self.scheme, z1, z2, z2p, z3))
        exact = t % k == 0 if t else True
        r = Fraction(*map(int, stage_ratio(self.scheme, z1, z2, z2p, z3)))  # i_aH, ring fixed
        textbook = textbook_assembly(z1, r, k) if r != 0 else exact
        if t == 0:  # i0 = 1: any position (the stage turns as a block)
            return Assembly(k, 0, True, textbook, 0.0, tuple(360.0 * j / k for j in range(k)),
                            0.0, (k,))  # fmt: skip
        ticks = [round(Fraction(j * t, k)) for j in range(k)]
        spacing = tuple(360.0 * x / t for x in ticks)
        dev = max(abs(s - 360.0 * j / k) for j, s in enumerate(spacing))
        divisors = [d for d in range(1, t + 1) if t % d == 0]
        below = [d for d in divisors if d < k]
        above = [d for d in divisors if d > k]
        near = tuple(x for x in ((below[-1] if below else None), (above[0] if above else None))
                     if x is not None)  # fmt: skip
        if exact:
            near = (k,)
        return Assembly(k, t, exact, textbook, 360.0 / t, spacing, dev, near)

    def _centres(self, n: int) -> list[tuple[np.ndarray, float]]:
        """Planet centres (k x 2 arrays) with their tip radii, for ``n`` equal positions."""
        th = 2 * np.pi * np.arange(n) / n
        out = []
        tips = self._planet_tips()
        if self.scheme == "double-planet":
            a1 = self._pairs["sun-planet"].center_distance
            a12 = self._pairs["planet-planet2"].center_distance
            a2 = self._pairs["planet2-ring"].center_distance
            cos_psi = (a1 * a1 + a2 * a2 - a12 * a12) / (2 * a1 * a2)
            psi = math.acos(min(1.0, max(-1.0, cos_psi)))
            out.append((a1 * np.stack([np.cos(th), np.sin(th)], 1), tips[0] / 2))
            out.append((a2 * np.stack([np.cos(th + psi), np.sin(th + psi)], 1), tips[1] / 2))
        else:
            a = self._pairs["sun-planet"].center_distance
            out.append((a * np.stack([np.cos(th), np.sin(th)], 1), max(tips) / 2))
        return out

    def _neighbour_gap(self, n: int) -> float:
        """Smallest tip-circle gap between planets that do not mesh, n planets (mm)."""
        if n < 2:
            return math.inf
        groups = self._centres(n)
        gaps = []
        for gi, (ci, ri) in enumerate(groups):
            for gj, (cj, rj) in enumerate(groups):
                if gj < gi:
                    continue
                d = np.linalg.norm(ci[:, None, :] - cj[None, :, :], axis=2)
                mask = np.ones_like(d, bool)
                if gi == gj:
                    mask &= ~np.eye(n, dtype=bool)
                else:
                    mask &= ~np.eye(n, dtype=bool)  # cluster j's own planets mesh
                gaps.append(float(np.min(np.where(mask, d - ri - rj, np.inf))))
        return min(gaps)

    @property
    def max_planets(self) -> int:
        """The largest planet count that passes the neighbour condition (>= 1)."""
        need = (self.clearance - NEIGHBOUR_TOLERANCE) * self.module
        n = 1
        while n < 10_000 and self._neighbour_gap(n + 1) >= need:
            n += 1
        return n

    def _coaxiality(self, tolerance: float) -> Finding:
        pairs = self._pairs
        if self.scheme == "double-planet":
            a1 = pairs["sun-planet"].center_distance
            a12 = pairs["planet-planet2"].center_distance
            a2 = pairs["planet2-ring"].center_distance
            c = self.clearance * self.module
            ra_s = self.sun.tip_diameter / 2
            ra_p1, ra_p2 = (g.tip_diameter / 2 for g in self.planet_gears)
            ra_r = self.ring.tip_diameter / 2
            margins = {
                "planet triangle closes (a12 > |a1 - a2|)": a12 - abs(a1 - a2),
                "planet triangle closes (a12 < a1 + a2)": a1 + a2 - a12,
                "outer planet clears the sun": a2 - ra_s - ra_p2 - c,
                "inner planet clears the ring": ra_r - a1 - ra_p1 - c,
            }
            worst = min(margins, key=margins.get)
            return Finding(
                "coaxiality", margins[worst],
                f"double-planet closure: a_sun-planet {a1:.4f}, a_planet-planet2 {a12:.4f}, "
                f"a_planet2-ring {a2:.4f} mm; tightest: {worst} by {margins[worst]:+.4f} mm",
                ok=margins[worst] >= -NEIGHBOUR_TOLERANCE * self.module,  # as the search
            )  # fmt: skip
        a = [p.center_distance for p in pairs.values()]
        spread = max(a) - min(a)
        names = list(pairs)
        if all(p.g1.profile_shift == 0 and p.g2.profile_shift == 0 for p in pairs.values()):
            how = "zero shifts: the tooth-count condition"
        else:
            how = "with shifts, each a_w from its working pressure angle"
        return Finding(
            "coaxiality", tolerance - spread,
            f"working centre distances {names[0]} {a[0]:.4f} mm and {names[1]} {a[1]:.4f} mm "
            f"differ by {spread:.4f} mm (tolerance {tolerance:g} mm; {how})",
        )  # fmt: skip

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
        k = self.n_planets
        findings = [self._coaxiality(tolerance)]
        asm = self.assembly()
        r = asm.ticks % k if asm.ticks else 0
        if asm.exact:
            msg = (
                f"{k} equally spaced planets assemble: assembly number T = {asm.ticks} is a "
                f"multiple of {k} ({asm.ticks // k if k else 0} ticks apart; tick "
                f"{asm.tick_angle:.4f} deg)"
            )
        else:
            spacing = ", ".join(f"{s:.3f}" for s in asm.spacing)
            near = " or ".join(map(str, asm.nearest_counts))
            msg = (
                f"{k} equally spaced planets do not assemble: T = {asm.ticks} is not a multiple "
                f"of {k}; feasible unequal spacing on the tick {asm.tick_angle:.4f} deg: "
                f"[{spacing}] deg (max {asm.max_deviation:.3f} deg from equal); nearest "
                f"assemblable counts: {near}"
            )
        findings.append(Finding("assembly", -float(min(r, k - r)) or 0.0, msg, unit="teeth",
                                ok=asm.exact))  # fmt: skip
        tb = "accepts" if asm.textbook else "rejects"
        findings.append(
            Finding(
                "assembly_textbook", 0.0 if asm.textbook else -1.0,
                f"the textbook sufficient form (z_a i_aH / k)(1 + k p) in Z {tb} {k} planets "
                f"(informative; the exact gcd form decides)", unit="", ok=True,
            )
        )  # fmt: skip
        gap = self._neighbour_gap(k)
        need = self.clearance * self.module
        tips = self._planet_tips()
        if math.isinf(gap):
            nb = Finding("neighbour", 0.0, f"one planet: no neighbours (up to "
                         f"{self.max_planets} fit)", ok=True)  # fmt: skip
        else:
            nb = Finding(
                "neighbour", gap - need,
                f"smallest gap between planet tip circles {gap:.4f} mm (largest planet tip "
                f"d_a = {max(tips):.4f} mm after tip shortening) vs clearance {need:.4f} mm; "
                f"the largest planet count that fits is {self.max_planets}",
                ok=gap - need >= -NEIGHBOUR_TOLERANCE * self.module,
            )  # fmt: skip
        findings.append(nb)
        findings.append(
            Finding(
                "redundant_constraints", float(k - 1),
                f"{k} planets add q = {k - 1} redundant (passive) constraints (Ozols §21-13); "
                "equal load sharing needs a floating sun or ring, or flexible pins",
                unit="", ok=True,
            )
        )  # fmt: skip
        for key, (nominal, relieved) in self._relief.items():
            findings.append(
                Finding(
                    f"{key}_tip_relief", (relieved - nominal) / 2,
                    f"{key} tip diameter enlarged from {nominal:.4f} to {relieved:.4f} mm so its "
                    "tip stays on the planet's involute (above the planet's form circle); make the "
                    "ring blank to this diameter", ok=True,
                )
            )  # fmt: skip
        for name, pair in self._pairs.items():
            findings.extend(pair.check(min_contact_ratio, min_tip_land).prefixed(name).values())
        return Report(findings)

    # ---- placement and phasing ------------------------------------------------------------
    @property
    def phasing(self) -> dict[str, str]:
        """Mesh phasing class of each central-gear mesh (:func:`phasing_class`)."""
        z1, _, _, z3 = self._z()
        names = list(self._pairs)
        return {names[0]: phasing_class(z1, self.n_planets),
                names[-1]: phasing_class(z3, self.n_planets)}  # fmt: skip

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
        if angles is None:
            asm = self.assembly()
            th = [s / 360.0 for s in asm.spacing]
        else:
            th = _planet_turns(angles, self.n_planets)
        z1, zc, zd, z3 = self._z()
        pairs = self._pairs
        first = next(iter(pairs.values()))
        a1 = first.center_distance
        sun_internal = self.scheme == "internal"
        ring_internal = self.scheme != "external"
        # phases in teeth; angles in turns. External pair: p1 + p2 = 1/2; internal: p_r - p_p = 1/2
        rot_p, rot_p2, th2 = [], [], []
        ring_rot = None
        resid = 0.0
        a2 = 0.0
        psi = 0.0
        if self.scheme == "double-planet":
            a12 = pairs["planet-planet2"].center_distance
            a2 = pairs["planet2-ring"].center_distance
            cos_psi = (a1 * a1 + a2 * a2 - a12 * a12) / (2 * a1 * a2)
            psi = math.acos(min(1.0, max(-1.0, cos_psi))) / (2 * math.pi)
            # direction from inner to outer planet centre, relative to the inner planet's angle
            dx = a2 * math.cos(2 * math.pi * psi) - a1
            dy = a2 * math.sin(2 * math.pi * psi)
            beta = math.atan2(dy, dx) / (2 * math.pi)
        for t in th:
            p_sun = z1 * t  # sun phase at direction t (sun rotation 0)
            best = None
            for n in range(zc):
                if sun_internal:  # planet inside the sun ring: p_s - p_p = 1/2 at direction t
                    phi = t - (p_sun - 0.5 - n) / zc
                else:  # planet phase at direction t + 1/2: z_c (t + 1/2 - phi)
                    phi = t + 0.5 - (0.5 - p_sun + n) / zc
                if self.scheme == "double-planet":
                    b = t + beta
                    p_in = zc * (b - phi)
                    phi2 = b + 0.5 - (0.5 - p_in) / zd
                    t2 = t + psi
                    p_out = zd * (t2 - phi2)
                    direction, phase = t2, p_out
                else:
                    phi2 = phi
                    direction = t
                    # ring-side planet phase towards the ring mesh
                    phase = zd * (t - phi) if ring_internal else zd * (t + 0.5 - phi)
                if ring_internal:  # p_r - p_d = 1/2 with p_r = z3 (direction - rho)
                    target = lambda rho, d=direction, ph=phase: z3 * (d - rho) - ph - 0.5  # noqa: E731
                else:  # external ring at the axis: p_r + p_d = 1/2 with p_r = z3 (direction - rho)
                    target = lambda rho, d=direction, ph=phase: z3 * (d - rho) + ph - 0.5  # noqa: E731
                if ring_rot is None:
                    ring_rot = direction - (phase + 0.5) / z3 if ring_internal else (
                        direction - (0.5 - phase) / z3)  # fmt: skip
                err = target(ring_rot)
                err = abs(err - round(err))
                if best is None or err < best[0] - 1e-12:
                    best = (err, phi, phi2)
                if err < 1e-9:
                    break
            resid = max(resid, best[0])
            rot_p.append(360.0 * (best[1] % 1.0))
            if self.scheme == "double-planet":
                rot_p2.append(360.0 * (best[2] % 1.0))
                th2.append(360.0 * ((t + psi) % 1.0))
        return Placement(
            planet_angles=tuple(360.0 * (t % 1.0) for t in th),
            planet_radius=a1,
            planet_rotations=tuple(rot_p),
            sun_rotation=0.0,
            ring_rotation=360.0 * (ring_rot % 1.0) if ring_rot is not None else 0.0,
            planet2_angles=tuple(th2),
            planet2_radius=a2,
            planet2_rotations=tuple(rot_p2),
            residual=resid,
        )

    # ---- outlines, 3D scene and animation (gears.solid.mesh, gears.solid.animate)
    # -----------------------
    def _layout(self, angle: float = 0.0, fixed: str = "ring") -> list[tuple]:
        """``(name, key, gear, centre, rotation, z)`` of every gear with the carrier turned by
        ``angle`` degrees (the sun when the carrier is ``fixed``): phases from
        :meth:`placement`, rotations from the Willis solution of :attr:`train`. ``z`` is the
        mid-plane in face widths (the ring side of a stepped planet sits above the sun side)."""
        fixed = self._member(fixed)
        if fixed not in ("sun", "ring", "carrier"):
            raise TrainError(f"fixed = {fixed!r}; valid are 'sun', 'ring', 'carrier'")
        try:
            a = check_angle("angle", angle)
        except GearError as exc:
            raise TrainError(str(exc)) from None
        name = {"sun": "sun", "ring": "ring", "carrier": self.carrier}
        drive = "sun" if fixed == "carrier" else "carrier"
        motion = self.train.solve({name[drive]: 1, name[fixed]: 0})

        def turned(member: str) -> float:
            return float(motion[member]) * a

        pl = self.placement()
        stepped = self.scheme in ("stepped", "external", "internal")
        lo, hi = (-0.5, 0.5) if stepped else (0.0, 0.0)
        c = turned(self.carrier)
        origin = (0.0, 0.0)
        out = [("ring", "ring", self.ring, origin, pl.ring_rotation + turned("ring"), hi),
               ("sun", "sun", self.sun, origin, pl.sun_rotation + turned("sun"), lo)]  # fmt: skip
        steps = self.planet_gears
        for i, (phi, rot) in enumerate(zip(pl.planet_angles, pl.planet_rotations, strict=True)):
            t = math.radians(phi + c)
            centre = (pl.planet_radius * math.cos(t), pl.planet_radius * math.sin(t))
            r = rot + turned("planet")
            out.append((f"planet{i + 1}", "planet", steps[0], centre, r, lo))
            if stepped:
                out.append((f"planet{i + 1}'", "planet'", steps[1], centre, r, hi))
        for i, (phi, rot) in enumerate(zip(pl.planet2_angles, pl.planet2_rotations, strict=True)):
            t = math.radians(phi + c)
            centre = (pl.planet2_radius * math.cos(t), pl.planet2_radius * math.sin(t))
            out.append((f"outer{i + 1}", "planet2", steps[1], centre,
                        rot + turned("planet2"), 0.0))  # fmt: skip
        return out

    def _placed(self, angle: float, tolerance: float, fixed: str, cache: dict) -> list[tuple]:
        from shapely import affinity

        out = []
        for name, key, gear, centre, rot, _ in self._layout(angle, fixed):
            if key not in cache:
                try:
                    cache[key] = gear.outline(tolerance)
                except GearError as exc:
                    raise TrainError(f"{key}: {exc}") from None
            shape = affinity.rotate(cache[key], rot, origin=(0.0, 0.0))
            out.append((name, key, affinity.translate(shape, *centre)))
        return out

    def _tolerance(self, tolerance) -> float:
        try:
            return check_tolerance(tolerance, module=self.module)
        except GearError as exc:
            raise TrainError(str(exc)) from None

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
        tolerance = self._tolerance(tolerance)
        return {name: p for name, _, p in self._placed(angle, tolerance, fixed, {})}

    def scene(self, angle: float = 0.0, face_width: float | None = None,
              tolerance: float = 0.01, fixed: str = "ring", herringbone: bool = False,
              progress: Callable[[int, int], object] | None = None) -> trimesh.Scene:  # fmt: skip
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

        Examples
        --------
        >>> s = Planetary(18, 45, 108, n_planets=3, module=2).scene(tolerance=0.1)
        >>> len(s.geometry), len(s.graph.nodes_geometry)
        (3, 5)
        """
        try:
            tol = check_tolerance(tolerance, module=self.module)
            herringbone = check_flag("herringbone", herringbone)
            check_callback("progress", progress)
            b = face_width
            if b is None:
                b = self.sun.face_width or 10.0 * self.module
            b = check_positive("face_width", b)
        except GearError as exc:
            raise TrainError(str(exc)) from None
        layout = self._layout(angle, fixed)
        distinct = {key: gear for _, key, gear, *_ in reversed(layout)}
        twists = {}
        try:
            for key, gear in distinct.items():
                check_length("face_width", b, gear.solid_radius(), f"the {key}'s radius")
                twists[key] = helix_twist(b, gear.helix_angle, gear.reference_diameter)
            check_budget(
                "mesh", f"the scene of {self!r}",
                lambda t: sum(g.solid_vertices(t, twists[k], herringbone=herringbone)
                              for k, g in distinct.items()), tol,
            )  # fmt: skip
        except GearError as exc:
            raise TrainError(str(exc)) from None
        solids = {}
        parts = []
        for name, key, gear, centre, rot, z in layout:
            if key not in solids:
                try:
                    solids[key] = gear_solid(gear.outline(tol), b, twists[key], tol,
                                             herringbone=herringbone)  # fmt: skip
                except GearError as exc:
                    raise TrainError(f"{key}: {exc}") from None
                solids[key].metadata["name"] = key
                if progress is not None:
                    progress(len(solids), len(distinct))
            colour = COLOURS.get(key.rstrip("'"), COLOURS["planet"])
            parts.append((name, solids[key], transform(rot, centre, z * b), colour))
        return scene(parts)

    def animate(self, path: str | os.PathLike[str], frames: int = 48, fps: float = 20.0,
                turn: float | None = None, tolerance: float = 0.02, fixed: str = "ring",
                progress: Callable[[int, int], object] | None = None) -> pathlib.Path:  # fmt: skip
        """Write a GIF (or MP4 with ffmpeg) of the stage's outlines in mesh while it turns.

        ``turn`` is the carrier rotation covered, degrees (the sun's when the carrier is
        ``fixed``); default one mesh cycle, ``360 / (z_sun |w_sun - w_carrier|)`` per unit
        carrier speed, after which the picture repeats. Phasing from :meth:`placement`,
        speeds from the Willis solver; frames are written by
        :func:`gears.solid.animate.write_animation` (``progress(i, n)`` after each frame). Every
        argument (the file's folder too) is checked and the drawing's size (frames times the
        outline vertices of every gear drawn) estimated before any work: over the animation
        budget it is refused with the tolerance that fits.
        """
        try:
            path = check_output(path, FORMATS)
            n = check_frames(frames)
            check_fps(fps)
            tol = check_tolerance(tolerance, module=self.module)
            check_callback("progress", progress)
            if turn is not None:
                turn = check_angle("turn", turn)
        except GearError as exc:
            raise TrainError(str(exc)) from None
        if turn is None:
            turn = self.mesh_cycle(fixed)
        layout = self._layout(0.0, fixed)
        try:
            check_budget(
                "animation", f"{n} frames of {self!r}",
                lambda t: n * sum(outline_vertices(g, t) for _, _, g, *_ in layout), tol,
                hint="fewer frames",
            )  # fmt: skip
        except GearError as exc:
            raise TrainError(str(exc)) from None
        step = turn / n
        cache: dict = {}

        def frame(i: int) -> list:
            placed = self._placed(i * step, tol, fixed, cache)
            return [(p, np.asarray(COLOURS[key.rstrip("'")]) / 255.0) for _, key, p in placed]

        try:
            return write_animation(path, frame, fps=fps, n_frames=n, progress=progress,
                                   title=repr(self))  # fmt: skip
        except GearError as exc:
            raise TrainError(str(exc)) from None

    def mesh_cycle(self, fixed: str = "ring") -> float:
        """Carrier rotation (degrees; the sun's when the carrier is fixed) over which every
        tooth mesh advances by one pitch, so the stage looks the same again."""
        fixed = self._member(fixed)
        name = {"sun": "sun", "ring": "ring", "carrier": self.carrier}
        drive = "sun" if fixed == "carrier" else "carrier"
        motion = self.train.solve({name.get(drive, drive): 1, name.get(fixed, fixed): 0})
        rel = abs(float(motion["sun"]) - float(motion[self.carrier]))
        return 360.0 / (self.sun.teeth * rel)

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

        def parts() -> list:
            tolerance = display_tolerance(max(self.ring.root_diameter, self.ring.tip_diameter))
            placed = self._placed(0.0, tolerance, "ring", {})
            return [(p, COLOURS[key.rstrip("'")]) for _, key, p in placed]

        return outlines_svg(parts, "this stage", title=repr(self))

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


def _planet_turns(angles: Any, n_planets: int) -> list[float]:
    """Planet centre angles (degrees) as fractions of a turn, refused unless there is one
    finite angle per planet and no two planets share a place."""
    try:
        values = [float(a) for a in angles]
    except (TypeError, ValueError):
        raise TrainError(f"angles = {angles!r}; valid is one angle in degrees per planet") from None
    if len(values) != n_planets or not all(math.isfinite(a) for a in values):
        raise TrainError(f"angles = {values}; valid is {n_planets} finite planet angles in degrees")
    turns = sorted(a / 360.0 % 1.0 for a in values)
    gaps = [b - a for a, b in zip(turns, [*turns[1:], turns[0] + 1.0], strict=True)]
    if n_planets > 1 and min(gaps) < 1e-9:
        raise TrainError(
            f"angles = {values}: two planets would sit at the same place; valid is "
            f"{n_planets} distinct angles (mod 360 deg)"
        )
    return [a / 360.0 for a in values]


def _count(n_planets: Any) -> int:
    if isinstance(n_planets, bool):
        raise TrainError(f"n_planets = {n_planets!r}; valid is an integer >= 1")
    try:
        k = operator.index(n_planets)
    except TypeError:
        raise TrainError(f"n_planets = {n_planets!r}; valid is an integer >= 1") from None
    if k < 1:
        raise TrainError(f"n_planets = {k}; valid is an integer >= 1")
    return k
