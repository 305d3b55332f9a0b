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
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import numpy as np

from gears import BevelPair, Finding, Gear, GearError, GearPair, Report
from trains.conditions import (
    assembly_number,
    bevel_neighbour_gap,
    closure_margin,
    neighbour_gap,
)
from trains.errors import TrainError

FRAME = "frame"

#: Above this amplification of the rounding of float inputs, a float result is flagged.
CONDITION_LIMIT = 1e8


class IllConditionedTrainWarning(UserWarning):
    """A float computation through the train amplifies rounding errors by more than 1e8.

    Give the tooth counts and ratios as integers or :class:`fractions.Fraction` (and the speeds
    as integers or Fractions) to get the exact answer.
    """


# --------------------------------------------------------------------------------- relations


@dataclass(frozen=True)
class Relation:
    """One linear relation ``k_a (w_a - w_c) + k_b (w_b - w_c) = 0`` between member speeds.

    Parameters
    ----------
    kind : {"mesh", "link", "couple"}
    name : str
        Unique name in its train (``"sun-planet"`` by default); used in messages and as the key
        of per-mesh efficiencies and powers.
    a, b : str
        The two members whose relative speeds the relation ties.
    carrier : str
        The member holding both axes (``"frame"`` for fixed axes; irrelevant for a coupling).
    k_a, k_b : int, Fraction or float
        The coefficients: ``(z_a, z_b)`` for an external mesh, ``(z_a, -z_b)`` internal,
        ``(1, -ratio)`` for a link, ``(1, -1)`` for a coupling.
    teeth : tuple of int or None
        ``(z_a, z_b)`` for a mesh.
    internal : bool
        True for an internal mesh.
    gears : (Gear, Gear) or None
        The real gears on ``a`` and ``b`` of a mesh built from gears (None: kinematic only).
    pair : GearPair or BevelPair or None
        Their :class:`gears.GearPair` (the external gear is its ``g1``) or
        :class:`gears.BevelPair`.
    opposed : bool
        A bevel mesh whose members' speeds are counted about axes of opposite sense relative
        to the common apex (the sign of ``k_b`` is turned, as for an internal mesh).
    """

    kind: str
    name: str
    a: str
    b: str
    carrier: str
    k_a: Any
    k_b: Any
    teeth: tuple[int, int] | None = None
    internal: bool = False
    gears: tuple[Gear, Gear] | None = field(default=None, compare=False, repr=False)
    pair: GearPair | BevelPair | None = field(default=None, compare=False, repr=False)
    opposed: bool = False

    def gear_of(self, member: str) -> tuple[Gear, float] | None:
        """The gear on ``member`` in this mesh and its tip diameter as mounted (with the pair's
        tip shortening), or None for a kinematic-only relation."""
        if self.pair is None or member not in (self.a, self.b):
            return None
        on_a = member == self.a
        gear = self.gears[0] if on_a else self.gears[1]
        d1, d2 = self.pair.tip_diameters
        first = on_a != self.gears[0].internal  # the external gear is the pair's g1
        return gear, float(d1 if first else d2)

    @property
    def coefficients(self) -> dict[str, Any]:
        """Coefficient of each member's speed in the relation (they sum to zero)."""
        out: dict[str, Any] = {}
        for member, k in ((self.a, self.k_a), (self.b, self.k_b)):
            out[member] = out.get(member, 0) + k
        if self.kind != "couple":
            out[self.carrier] = out.get(self.carrier, 0) - (self.k_a + self.k_b)
        return {m: k for m, k in out.items() if k != 0}

    @property
    def basic_ratio(self) -> Any:
        """``(w_a - w_c) / (w_b - w_c)`` with the carrier held: ``-k_b / k_a``."""
        return -_div(self.k_b, self.k_a)

    def __str__(self) -> str:
        if self.kind == "mesh":
            kind = "internal mesh" if self.internal else "mesh"
            where = "" if self.carrier == FRAME else f" on carrier {self.carrier}"
            return (
                f"{kind} {self.name!r} ({self.a} {self.teeth[0]} / {self.b} {self.teeth[1]}{where})"
            )
        if self.kind == "link":
            where = "" if self.carrier == FRAME else f" on carrier {self.carrier}"
            return f"link {self.name!r} ({self.a} = {self.basic_ratio} x {self.b}{where})"
        return f"coupling {self.name!r} ({self.a} = {self.b})"


def _div(x: Any, y: Any) -> Any:
    if isinstance(x, float) or isinstance(y, float):
        return x / y
    return Fraction(x) / Fraction(y)


def _exact(x: Any) -> bool:
    return isinstance(x, numbers.Rational) and not isinstance(x, bool)


def _teeth(value: Any, which: str) -> int:
    if isinstance(value, bool):
        raise TrainError(f"{which} tooth count must be a positive integer, got {value!r}")
    try:
        z = operator.index(value)
    except TypeError:
        if isinstance(value, Fraction) and value.denominator == 1:
            z = int(value)
        else:
            raise TrainError(
                f"{which} tooth count must be a positive integer, got {value!r}"
                " (for a ratio that is not a tooth count use Train.link)"
            ) from None
    if z < 1:
        raise TrainError(f"{which} tooth count must be a positive integer (>= 1), got {z}")
    return z


def _ratio(value: Any) -> Fraction | float:
    if isinstance(value, bool):
        raise TrainError(f"ratio must be a number, got {value!r}")
    if isinstance(value, str):
        try:
            r = Fraction(value)
        except ValueError:
            raise TrainError(f"ratio {value!r} is not a number or a fraction like '13/3'") from None
        except ZeroDivisionError:
            raise TrainError(f"ratio {value!r} divides by zero; give a finite ratio") from None
        return r
    if _exact(value):
        return Fraction(value)
    if isinstance(value, numbers.Real):
        x = float(value)
        if not math.isfinite(x):
            raise TrainError(f"ratio must be finite, got {value!r}")
        return x
    raise TrainError(f"ratio must be a number, got {value!r}")


def _name(value: Any, what: str) -> str:
    if not isinstance(value, str) or not value:
        raise TrainError(f"{what} must be a non-empty string (a member name), got {value!r}")
    return value


# --------------------------------------------------------------------------------- elimination


@dataclass(frozen=True)
class _Map:
    """Result of one elimination for a given set of known members."""

    known: tuple[str, ...]
    determined: dict[str, tuple[Fraction, ...]]  # member -> coefficients over known
    free: tuple[str, ...]  # unknown members not fixed by the known ones
    choices: tuple[str, ...]  # members whose speeds would each remove one freedom
    missing: int  # how many more independent speeds are needed
    constraints: tuple[tuple[tuple[Fraction, ...], tuple[int, ...]], ...]  # (c, relation ids)
    exact: bool  # all coefficients exact
    amplification: float = 1.0  # relative change of the map per relative change of float data

    def matrix(self) -> np.ndarray:
        names = list(self.determined)
        out = np.empty((len(names), len(self.known)))
        for i, n in enumerate(names):
            out[i] = [float(c) for c in self.determined[n]]
        return out


def _eliminate(
    rows: list[dict[str, Any]], unknown: list[str], known: list[str]
) -> tuple[list[list[Fraction]], list[int]]:
    """Gauss-Jordan on ``[A_U | A_K | I]`` over Fractions, pivoting on the unknown columns only.

    Returns the reduced rows and the pivot column of each row (-1 for a row with no pivot).
    """
    nu, nk, m = len(unknown), len(known), len(rows)
    col = {n: i for i, n in enumerate(unknown)}
    col.update({n: nu + i for i, n in enumerate(known)})
    width = nu + nk + m
    mat: list[list[Fraction]] = []
    for r, coeffs in enumerate(rows):
        row = [Fraction(0)] * width
        for member, k in coeffs.items():
            if member in col:  # the frame column is dropped: its speed is 0
                row[col[member]] += Fraction(k)
        row[nu + nk + r] = Fraction(1)
        mat.append(row)
    pivots = [-1] * m
    r = 0
    for c in range(nu):
        p = next((i for i in range(r, m) if mat[i][c] != 0), None)
        if p is None:
            continue
        mat[r], mat[p] = mat[p], mat[r]
        piv = mat[r][c]
        if piv != 1:
            mat[r] = [x / piv for x in mat[r]]
        prow = mat[r]
        nz = [j for j in range(width) if prow[j] != 0]
        for i in range(m):
            if i != r and mat[i][c] != 0:
                f = mat[i][c]
                row = mat[i]
                for j in nz:
                    row[j] -= f * prow[j]
        pivots[r] = c
        r += 1
        if r == m:
            break
    return mat, pivots


def _replace_amplification(mp: _Map, amplification: float) -> _Map:
    from dataclasses import replace

    return replace(mp, amplification=amplification)


# --------------------------------------------------------------------------------- motion


class Motion(Mapping[str, Any]):
    """The speed of every member of a train: a read-only mapping ``member -> speed``.

    Speeds are :class:`~fractions.Fraction` when everything given was exact, floats for float
    input, and numpy arrays (one value per time step) for array input. ``"frame"`` is included
    with speed 0.

    Examples
    --------
    >>> from trains import simple_planetary
    >>> m = simple_planetary(20, 30, 80).solve(sun=1500, ring=0)
    >>> m["carrier"], m.relative("planet", "carrier"), m.ratio("sun", "carrier")
    (Fraction(300, 1), Fraction(-800, 1), Fraction(5, 1))
    """

    def __init__(self, speeds: Mapping[str, Any]) -> None:
        self._speeds = dict(speeds)

    def __getitem__(self, member: str) -> Any:
        try:
            return self._speeds[member]
        except KeyError:
            raise TrainError(
                f"unknown member {member!r}; the members are {', '.join(sorted(self._speeds))}"
            ) from None

    def __iter__(self) -> Iterator[str]:
        return iter(self._speeds)

    def __len__(self) -> int:
        return len(self._speeds)

    def relative(self, member: str, carrier: str) -> Any:
        """Speed of ``member`` relative to ``carrier``, ``w_member - w_carrier`` (bearings)."""
        return self[member] - self[carrier]

    def ratio(self, a: str, b: str) -> Any:
        """``w_a / w_b`` (Ozols' ``i_ab``, driver over driven).

        Raises
        ------
        TrainError
            If ``b`` stands still.
        """
        wa, wb = self[a], self[b]
        if np.any(np.asarray(wb) == 0):
            raise TrainError(f"{b} stands still, so the ratio {a}/{b} is infinite")
        return _div(wa, wb) if np.ndim(wa) == 0 and np.ndim(wb) == 0 else wa / wb

    def integrate(self, t: Any, initial: Mapping[str, Any] | None = None) -> Motion:
        """Angles over time: the integral of the speeds from ``t[0]`` (or from 0 for scalars).

        Parameters
        ----------
        t : number or array
            Time. For scalar (constant) speeds, ``angle = initial + speed * t``; for array speeds
            ``t`` is the array of time steps and the integral is the trapezoid rule (exact for
            speeds linear between steps).
        initial : mapping, optional
            Angle of each member at ``t[0]`` (default 0).

        Returns
        -------
        Motion
            A mapping ``member -> angle`` in the unit of speed times time (rad/s x s = rad).

        Examples
        --------
        Ozols example 7-6, the summator: turn shaft 1 by +60 degrees and shaft 3 by -60 degrees.

        >>> from trains import stepped_planetary
        >>> t = stepped_planetary(100, 50, 100, 50, meshes=("external", "external"))
        >>> t.solve({"1": 60, "3": -60}).integrate(1)["H"]
        Fraction(100, 1)
        """
        initial = dict(initial or {})
        for name in initial:
            self[name]  # raises for an unknown member
        out: dict[str, Any] = {}
        if all(np.ndim(v) == 0 for v in self._speeds.values()):
            for n, w in self._speeds.items():
                out[n] = initial.get(n, 0) + w * t
            return Motion(out)
        from scipy.integrate import cumulative_trapezoid

        t = np.asarray(t, dtype=float)
        for n, w in self._speeds.items():
            w = np.broadcast_to(np.asarray(w, dtype=float), t.shape)
            out[n] = initial.get(n, 0.0) + cumulative_trapezoid(w, t, initial=0.0)
        return Motion(out)

    def __repr__(self) -> str:
        body = ", ".join(
            f"{n}={v!s}" if np.ndim(v) == 0 else f"{n}=<array>" for n, v in self.items()
        )
        return f"Motion({body})"


# --------------------------------------------------------------------------------- structure


@dataclass(frozen=True)
class Structure:
    """Structural (Chebyshev) count beside the algebraic mobility (Ozols §2.4, (3.12), (2.8)).

    Each moving link has one revolute bearing (``lower_pairs == links``); each mesh or link
    relation is one higher pair; identical planets are counted ``k`` times with their meshes.
    ``chebyshev = 3 links - 2 lower_pairs - higher_pairs``; ``redundant`` is the number of
    redundant (passive) constraints, ``mobility - chebyshev`` (``k - 1`` for ``k`` planets,
    Ozols §21-13; lectures §2.3 [P] 697).
    """

    links: int
    lower_pairs: int
    higher_pairs: int
    chebyshev: int
    redundant: int
    mobility: int


# --------------------------------------------------------------------------------- the train


def _check_overflow(res: np.ndarray, names, values) -> None:
    """Refuse float speeds whose solved speeds leave float64's range (|w| > 1.8e308)."""
    if not np.all(np.isfinite(res)):
        given = ", ".join(f"|{n}| up to {np.max(np.abs(np.asarray(v, dtype=float))):.3g}"
                          for n, v in zip(names, values, strict=True))  # fmt: skip
        raise TrainError(
            f"speeds {given} overflow float64 through this train (a solved speed passes"
            " 1.8e308); scale them down, or give integers or Fractions for exact results"
        )


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
        pair: GearPair | BevelPair | None = None,
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
        if pair is not None:
            if not isinstance(pair, GearPair):
                raise TrainError(
                    f"{where}: pair must be a gears.GearPair or gears.BevelPair, got {pair!r}"
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
            findings.append(self._coaxiality(group, tolerance))
        findings.extend(self._same_gear())
        findings.extend(self._planet_findings(clearance))
        return Report(findings)

    def _coaxiality(self, group: tuple[str, ...], tolerance: float) -> Finding:
        name = f"coaxiality({', '.join(group)})"
        shaft = {m: m for m in self._members}  # coupled members turn on one shaft: one axis

        def axis(m: str) -> str:
            while shaft[m] != m:
                m = shaft[m]
            return m

        for r in self._relations:
            if r.kind == "couple":
                shaft[axis(r.a)] = axis(r.b)
        edges: dict[str, list[tuple[str, Relation]]] = {}
        for r in self._relations:
            a, b = axis(r.a), axis(r.b)
            if r.kind == "mesh" and isinstance(r.pair, GearPair) and a != b:
                edges.setdefault(a, []).append((b, r))
                edges.setdefault(b, []).append((a, r))
        axes = list(dict.fromkeys(axis(m) for m in group))
        inside = set(axes)
        paths: list[tuple[str, list[Relation]]] = []
        for start in axes:
            stack = [(start, [start], [])]
            while stack and len(paths) < 1000:
                node, seen, rels = stack.pop()
                for nxt, r in edges.get(node, ()):
                    if nxt in seen or len(rels) >= 8:
                        continue
                    if nxt in inside:
                        if axes.index(nxt) > axes.index(start):
                            paths.append((" - ".join([*seen, nxt]), [*rels, r]))
                        continue
                    stack.append((nxt, [*seen, nxt], [*rels, r]))
        if not paths:
            return Finding(
                name, 0.0,
                f"no chain of real-gear meshes joins {', '.join(group)}: coaxiality not checked"
                " (give the meshes gears=)", ok=True,
            )  # fmt: skip
        worst, text = math.inf, []
        for label, rels in paths:
            dist = [r.pair.center_distance for r in rels]
            margin = float(closure_margin(dist, tolerance))
            worst = min(worst, margin)
            text.append(f"{label}: a_w {' / '.join(f'{d:.4f}' for d in dist)} mm")
        rule = f"equal within {tolerance:g} mm; chains of 3+ close as a polygon"
        return Finding(name, worst, f"{'; '.join(text)} ({rule})")

    def _same_gear(self) -> list[Finding]:
        seen: dict[tuple[str, int, float], tuple[str, Gear]] = {}
        out: list[Finding] = []
        for r in self._relations:
            if r.pair is None:
                continue
            for member, gear in ((r.a, r.gears[0]), (r.b, r.gears[1])):
                key = (member, gear.teeth, gear.module)
                if key not in seen:
                    seen[key] = (r.name, gear)
                    continue
                first, g0 = seen[key]
                diffs = []
                for attr, unit in (("profile_shift", ""), ("helix_angle", " deg"),
                                   ("pressure_angle", " deg"), ("face_width", " mm")):  # fmt: skip
                    x, y = getattr(g0, attr), getattr(gear, attr)
                    if x is not None and y is not None and not math.isclose(x, y, abs_tol=1e-12):
                        diffs.append((attr, x, y, unit))
                name = f"{member}.same_gear"
                if any(f.name == name for f in out):
                    continue
                if diffs:
                    unit = {"profile_shift": "module"}.get(diffs[0][0], diffs[0][3].strip())
                    d = abs(diffs[0][1] - diffs[0][2])
                    what = ", ".join(f"{a} {x:g}{u} vs {y:g}{u}" for a, x, y, u in diffs)
                    out.append(Finding(
                        name, -d,
                        f"{member} meshes in {first} and {r.name} with one gear of {gear.teeth}"
                        f" teeth, module {gear.module:g}, but the two descriptions differ:"
                        f" {what} (a stepped gear needs another tooth count or module)",
                        unit=unit,
                    ))  # fmt: skip
        return out

    def _planet_findings(self, clearance: float) -> list[Finding]:
        out: list[Finding] = []
        for planet, central, _carrier in self._planet_meshes():
            k = self._planets[planet]
            if k < 2:
                continue
            real = [r for r in central if r.pair is not None]
            if not real:
                continue  # a kinematic-only planet: nothing to check
            if len(central) == 2:
                z, internal = [], []
                for r in central:
                    on_a = r.a == planet
                    z.append(
                        (r.teeth[1] if on_a else r.teeth[0], r.teeth[0] if on_a else r.teeth[1])
                    )
                    internal.append(r.internal or r.opposed)
                (za, zc), (zb, zd) = z
                t = int(assembly_number(za, zc, zd, zb, internal[0], internal[1]))
                rem = t % k if t else 0
                ok = rem == 0
                names = " and ".join(r.name for r in central)
                out.append(Finding(
                    f"{planet}.assembly", -float(min(rem, k - rem)) + 0.0,
                    f"{k} equally spaced planets {planet} ({names}): assembly number T = {t}"
                    f" {'is' if ok else 'is not'} a multiple of {k} (lectures §4.3)",
                    unit="teeth", ok=ok,
                ))  # fmt: skip
            tips, modules = [], []
            for r in self._relations:
                got = r.gear_of(planet) if r.kind == "mesh" else None
                if got is not None:
                    tips.append(got[1])
                    modules.append(got[0].module)
            if isinstance(real[0].pair, BevelPair):
                out.append(self._bevel_neighbour(planet, real[0], k, clearance))
                continue
            tips_by_gear = max(tips)
            a = real[0].pair.center_distance
            gap = float(neighbour_gap(a, tips_by_gear, k))
            need = clearance * max(modules)
            out.append(Finding(
                f"{planet}.neighbour", gap - need,
                f"{k} planets {planet} at a_w = {a:.4f} mm: gap between tip circles (d_a ="
                f" {tips_by_gear:.4f} mm) {gap:.4f} mm vs clearance {need:.4f} mm",
            ))  # fmt: skip
        return out

    @staticmethod
    def _bevel_neighbour(planet: str, r: Relation, k: int, clearance: float) -> Finding:
        """``k`` bevel planets on a common apex, their axes 360/k deg apart (a differential's
        pinions): the gap between their face cones at the outer tips
        (:func:`trains.conditions.bevel_neighbour_gap`) against ``clearance`` modules."""
        gear = r.gears[0] if r.a == planet else r.gears[1]
        reach = math.hypot(gear.cone_distance, gear.addendum)
        gap = float(bevel_neighbour_gap(gear.face_angle, reach, k))
        need = clearance * gear.module
        return Finding(
            f"{planet}.neighbour", gap - need,
            f"{k} bevel planets {planet} (face cone {gear.face_angle:.4f} deg, outer tips "
            f"{reach:.4f} mm from the apex): gap between neighbours {gap:.4f} mm vs clearance "
            f"{need:.4f} mm",
        )  # fmt: skip

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
        result = self._build_map(known, rows)
        if not result.exact and result.determined:
            result = _replace_amplification(result, self._sensitivity(known, result))
        self._maps[known] = result
        return result

    def _build_map(self, known: tuple[str, ...], rows: list[dict[str, Any]]) -> _Map:
        unknown = [m for m in self._members if m != FRAME and m not in known]
        mat, pivots = _eliminate(rows, unknown, list(known))
        nu, nk = len(unknown), len(known)
        pivot_cols = {c for c in pivots if c >= 0}
        free_cols = [c for c in range(nu) if c not in pivot_cols]
        determined: dict[str, tuple[Fraction, ...]] = {}
        free = [unknown[c] for c in free_cols]
        constraints = []
        for row, c in zip(mat, pivots, strict=True):
            if c >= 0:
                if any(row[f] != 0 for f in free_cols):
                    free.append(unknown[c])
                else:
                    determined[unknown[c]] = tuple(-row[nu + j] for j in range(nk))
            else:
                cvec = tuple(row[nu : nu + nk])
                if any(x != 0 for x in cvec):
                    rel = tuple(i for i, y in enumerate(row[nu + nk :]) if y != 0)
                    constraints.append((cvec, rel))
        order = {n: i for i, n in enumerate(self._members)}
        determined = dict(sorted(determined.items(), key=lambda kv: order[kv[0]]))
        return _Map(
            known=known,
            determined=determined,
            free=tuple(sorted(free, key=order.__getitem__)),
            choices=tuple(unknown[c] for c in free_cols),
            missing=len(free_cols),
            constraints=tuple(constraints),
            exact=self.exact,
        )

    def _sensitivity(self, known: tuple[str, ...], base: _Map) -> float:
        """Relative change of the speed map per relative change of the float coefficients.

        Float ratios carry a relative rounding of about 1e-16; a map that amplifies it by more
        than ``CONDITION_LIMIT`` (a float basic ratio near 1) gives results with few correct
        digits. Measured by perturbing every float coefficient by 2^-30 (two sign patterns).
        """
        delta = Fraction(1, 2**30)
        worst = 0.0
        for pattern in (1, -1):
            rows = []
            for j, r in enumerate(self._relations):
                ka, kb = r.k_a, r.k_b
                if not _exact(kb):
                    kb = Fraction(kb) * (1 + delta * (pattern if j % 2 else 1))
                if not _exact(ka):
                    ka = Fraction(ka) * (1 + delta)
                rows.append(Relation(r.kind, r.name, r.a, r.b, r.carrier, ka, kb).coefficients)
            pert = self._build_map(known, rows)
            for name, cs in base.determined.items():
                cp = pert.determined.get(name)
                if cp is None:  # a perturbation changes the rank: singular to working precision
                    return math.inf
                for a, b in zip(cs, cp, strict=True):  # entry-wise relative change
                    if a != 0:
                        worst = max(worst, float(abs(b - a) / abs(a) / delta))
                    elif b != 0:
                        return math.inf
        return worst

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
            return self._assemble(mp, dict(zip(mp.known, vals, strict=True)), out)
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
                self._check_amplification(mat, vals[:, None], res[:, None])
            out = {n: float(x) for n, x in zip(mp.determined, res, strict=True)}
            return self._assemble(mp, dict(zip(mp.known, map(float, vals), strict=True)), out)
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
            self._check_amplification(mat, w, res)
        out = {n: res[i].reshape(shape) for i, n in enumerate(mp.determined)}
        known = {n: a for n, a in zip(mp.known, arrays, strict=True)}
        return self._assemble(mp, known, out, zero=np.zeros(shape))

    def _assemble(self, mp: _Map, known: dict, out: dict, zero: Any = None) -> dict[str, Any]:
        if zero is None:
            exact = all(isinstance(v, Fraction) for v in (*known.values(), *out.values()))
            zero = Fraction(0) if exact else 0.0
        speeds: dict[str, Any] = {}
        for m in self._members:
            speeds[m] = zero if m == FRAME else known[m] if m in known else out[m]
        return speeds

    def _check_amplification(self, mat: np.ndarray, w: np.ndarray, res: np.ndarray) -> None:
        if mat.size == 0 or np.abs(mat).sum(axis=1).max() <= CONDITION_LIMIT * 1e-3:
            return  # the train cannot amplify rounding much: skip the extra product
        scale = np.abs(mat) @ np.abs(w)
        bound = np.maximum(np.abs(res), np.abs(w).max(axis=0, initial=0.0))
        if np.any(scale > CONDITION_LIMIT * bound):
            warnings.warn(
                "float speeds through this train cancel: rounding is amplified by more than"
                f" {CONDITION_LIMIT:.0e}; give integer or Fraction speeds for exact results",
                IllConditionedTrainWarning,
                stacklevel=4,
            )

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
