"""Layer 1, kinematics: the relations of a train and their exact solution.

Each relation of a :class:`~trains.willis.Train` is one linear, homogeneous equation in the
member speeds (:class:`Relation`: a mesh ``k_a (w_a - w_c) + k_b (w_b - w_c) = 0``, a link, a
coupling). This module holds the rows and what solves them: Gauss-Jordan elimination over
:class:`fractions.Fraction` (exact for integer tooth counts), the linear map from the known speeds
to every speed it gives (one matrix product for floats and time series), the solution
(:class:`Motion`) and the structural count beside the algebraic mobility (:class:`Structure`).
The train that builds the rows and asks the questions is :mod:`trains.willis`.
"""

from __future__ import annotations

import math
import numbers
import operator
import warnings
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import numpy as np

from gears import BevelPair, Gear, GearPair, WormPair
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
    pair: GearPair | BevelPair | WormPair | None = field(default=None, compare=False, repr=False)
    opposed: bool = False

    def gear_of(self, member: str) -> tuple[Gear, float] | None:
        """The gear on ``member`` in this mesh and its tip diameter as mounted (with the pair's
        tip shortening), or None for a kinematic-only relation."""
        if self.pair is None or self.gears is None or member not in (self.a, self.b):
            return None  # kinematic, or a worm mesh (no Gear objects)
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


def _check_overflow(res: np.ndarray, names, values) -> None:
    """Refuse float speeds whose solved speeds leave float64's range (``abs(w) > 1.8e308``)."""
    if not np.all(np.isfinite(res)):
        given = ", ".join(f"|{n}| up to {np.max(np.abs(np.asarray(v, dtype=float))):.3g}"
                          for n, v in zip(names, values, strict=True))  # fmt: skip
        raise TrainError(
            f"speeds {given} overflow float64 through this train (a solved speed passes"
            " 1.8e308); scale them down, or give integers or Fractions for exact results"
        )


def build_map(
    members: list[str], known: tuple[str, ...], rows: list[dict[str, Any]], exact: bool
) -> _Map:
    """The linear map from the speeds of ``known`` to every other member's, from the relations'
    coefficient ``rows`` (``members`` in the train's order; ``exact``: every coefficient is)."""
    unknown = [m for m in members if m != FRAME and m not in known]
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
    order = {n: i for i, n in enumerate(members)}
    determined = dict(sorted(determined.items(), key=lambda kv: order[kv[0]]))
    return _Map(
        known=known,
        determined=determined,
        free=tuple(sorted(free, key=order.__getitem__)),
        choices=tuple(unknown[c] for c in free_cols),
        missing=len(free_cols),
        constraints=tuple(constraints),
        exact=exact,
    )


def assemble(
    members: list[str], mp: _Map, known: dict, out: dict, zero: Any = None
) -> dict[str, Any]:
    """Every member's speed in ``members`` order: the known ones, the solved ones, the frame 0."""
    if zero is None:
        exact = all(isinstance(v, Fraction) for v in (*known.values(), *out.values()))
        zero = Fraction(0) if exact else 0.0
    speeds: dict[str, Any] = {}
    for m in members:
        speeds[m] = zero if m == FRAME else known[m] if m in known else out[m]
    return speeds


def check_amplification(mat: np.ndarray, w: np.ndarray, res: np.ndarray) -> None:
    """Warn when float speeds through the map ``mat`` cancel by more than ``CONDITION_LIMIT``."""
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


def sensitivity(
    members: list[str], relations: list[Relation], known: tuple[str, ...], base: _Map, exact: bool
) -> float:
    """Relative change of the speed map per relative change of the float coefficients.

    Float ratios carry a relative rounding of about 1e-16; a map that amplifies it by more
    than ``CONDITION_LIMIT`` (a float basic ratio near 1) gives results with few correct
    digits. Measured by perturbing every float coefficient by 2^-30 (two sign patterns).
    """
    delta = Fraction(1, 2**30)
    worst = 0.0
    for pattern in (1, -1):
        rows = []
        for j, r in enumerate(relations):
            ka, kb = r.k_a, r.k_b
            if not _exact(kb):
                kb = Fraction(kb) * (1 + delta * (pattern if j % 2 else 1))
            if not _exact(ka):
                ka = Fraction(ka) * (1 + delta)
            rows.append(Relation(r.kind, r.name, r.a, r.b, r.carrier, ka, kb).coefficients)
        pert = build_map(members, known, rows, exact)
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
