"""Layer 6, design and files.

Tooth-number synthesis of a planetary stage for a target ratio (lectures §4.4).

:func:`synthesize` enumerates every tooth-number set of a scheme in numpy integer arrays (exact:
ratios are compared as integer cross products, the assembly condition is an integer modulo, no
float ever decides an equality), filters them by the conditions of lectures §4.3 on zero-shift
gears (vectorised), ranks the survivors and returns the best as :class:`Candidate`\\ s, each with
its :class:`~trains.planetary.stage.Planetary` stage.

Conditions, in the order they are applied (the count each removes is kept for the explanation
of an empty result):

1. ``tooth range``: every gear has ``z_min <= z <= z_max`` (the ring too); ``z_min`` stands for
   the undercut limit of zero-shift external gears (lectures §4.3 item 5);
2. ``internal difference``: ``z_ring - z_planet >= min_internal_difference`` (8 for h_a* = 1) on
   every internal mesh, and the ring's tip above its base circle;
3. ``ratio``: exactly the target, or within the relative ``tolerance``;
4. ``coaxiality``: by construction for four schemes (the ring follows from the lectures' table);
   for the double-planet scheme the planet triangle must close with ``clearance``;
5. ``assembly``: the exact gcd form (:func:`trains.planetary.schemes.assembly_ticks`);
6. ``neighbour``: tip circles of non-meshing planets at least ``clearance`` modules apart;
7. ``mesh``: transverse contact ratio >= ``min_contact_ratio`` and no involute interference on
   internal meshes (:func:`gears.pair_geometry`, vectorised; skipped with
   ``mesh_checks="textbook"``);
8. ``shifted stage`` (``allow_shift``) and ``full checks`` (``mesh_checks="full"``): the built
   stage's :meth:`~trains.planetary.stage.Planetary.check`.

Ranking (the documented objective): smallest ring (z3), then smallest ratio error, then most
hunting-tooth meshes (gcd of the mesh's tooth counts = 1), then unshifted before shifted, then
more planets, then the tooth counts in ascending order (an explicit tiebreak).
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Callable, Iterable
from dataclasses import dataclass, replace
from fractions import Fraction
from functools import cached_property
from typing import Any

import numpy as np

from gears.meshing import contact_ratio, pair_geometry
from gears.rack import BasicRack
from gears.report import format_duration
from trains.errors import TrainError
from trains.planetary.checks import NEIGHBOUR_TOLERANCE, ring_tip_alteration
from trains.planetary.schemes import (
    _default_roles,
    assembly_ticks,
    canonical_scheme,
    coaxial_ring_teeth,
    stage_ratio,
)
from trains.planetary.stage import Planetary

__all__ = ["STAGE_FIELDS", "Candidate", "Candidates", "set_count", "stage_block", "synthesize"]

#: Tooth-count sets examined per vectorised block (bounds the memory of every search).
BLOCK = 1_000_000
#: Sets per second assumed for the size check (measured 1.2-3.4 x 10^7 on a shared core,
#: docs/performance.md); a search estimated over ``max_seconds`` is refused before any work.
SETS_PER_SECOND = 1.0e7


@dataclass(frozen=True)
class Candidate:
    """One tooth-number set that meets the request.

    Attributes
    ----------
    teeth : tuple of int
        ``(z1, z2, z2', z3)``: sun, planet on the sun, planet on the ring (outer planet of a
        double-planet stage), ring; ``z2' = z2`` for a simple stage.
    n_planets : int
    ratio : Fraction
        The achieved ratio (exact).
    ratio_error : float
        ``|ratio - target| / |target|``.
    hunting : int
        Number of meshes whose tooth counts are coprime (hunting tooth).
    shifted : bool
        The tooth counts are off the zero-shift coaxiality condition and the stage is made
        coaxial by profile shifts.
    scheme : str
    module : float
    """

    teeth: tuple[int, int, int, int]
    n_planets: int
    ratio: Fraction
    ratio_error: float
    hunting: int
    shifted: bool
    scheme: str
    module: float
    clearance: float = 0.5

    @cached_property
    def stage(self) -> Planetary:
        """The :class:`~trains.planetary.stage.Planetary` stage (made coaxial by shifts if
        needed)."""
        z1, z2, z2p, z3 = self.teeth
        planet = z2 if self.scheme == "simple" else (z2, z2p)
        if not self.shifted:
            return Planetary(z1, planet, z3, self.n_planets, self.module, scheme=self.scheme,
                             clearance=self.clearance)  # fmt: skip
        probe = Planetary(z1, planet, z3, self.n_planets, self.module, scheme=self.scheme)
        a = max(p.reference_center_distance for p in probe.meshes.values())
        return Planetary.coaxial(z1, planet, z3, self.n_planets, self.module, center_distance=a,
                                 split="proportional", scheme=self.scheme,
                                 clearance=self.clearance)  # fmt: skip

    def __str__(self) -> str:
        z1, z2, z2p, z3 = self.teeth
        planet = f"{z2}" if self.scheme == "simple" else f"{z2}/{z2p}"
        return (
            f"sun {z1}, planet {planet}, ring {z3}, {self.n_planets} planets: ratio "
            f"{self.ratio} ({float(self.ratio):.6g}, error {self.ratio_error:.2e})"
            + (", shifted" if self.shifted else "")
        )


class Candidates(list):
    """The ranked candidates (a list) with the bookkeeping of the search.

    Attributes
    ----------
    examined : int
        Tooth-number sets (times planet counts) examined.
    removed : dict
        Condition -> number of sets it removed, in the order the filters ran.
    """

    def __init__(self, items: Iterable[Candidate], examined: int, removed: dict[str, int],
                 reach: tuple[float, float] | None = None, request: str = "") -> None:  # fmt: skip
        super().__init__(items)
        self.examined = examined
        self.removed = dict(removed)
        self.reach = reach  # the ratios the sets within the tooth range reached (lo, hi)
        self.request = request  # e.g. "one simple stage with z 17 ... 200", for the reason

    @property
    def reason(self) -> str:
        """Why the result is empty (or a summary of the filtering).

        Names the condition that removed the most sets (when that is the enumeration's tooth
        range, also the condition that removed the most after it) and the last condition that
        removed any, i.e. the one that emptied the result.
        """
        if not self.removed:
            return "nothing was examined"
        worst = max(self.removed, key=self.removed.get)
        most = f"the '{worst}' condition removed the most ({self.removed[worst]})"
        others = {k: v for k, v in self.removed.items() if k != worst and v}
        if worst == "tooth range" and others:
            second = max(others, key=others.get)
            most += f", then '{second}' ({others[second]})"
        last = [k for k, v in self.removed.items() if v]
        head = "no candidate meets the request" if not self else f"{len(self)} candidates"
        counts = ", ".join(f"{k} {v}" for k, v in self.removed.items())
        tail = f"; the last sets were removed by '{last[-1]}'" if last and not self else ""
        reach = ""
        if not self and self.reach is not None and self.request and last and last[-1] == "ratio":
            lo, hi = self.reach
            if lo <= hi:
                most_ = max(abs(lo), abs(hi))
                reach = (
                    f"; {self.request} reaches ratios {lo:.4g} ... {hi:.4g}, at most about "
                    f"1:{most_:.3g}: more stages (synthesize_gearbox) or a wider tooth range "
                    "reach further"
                )
        return (
            f"{head}: of {self.examined} tooth-number sets {most}{tail}{reach}; "
            f"removed per condition: {counts}"
        )

    def table(self) -> str:
        """A ranked table, one candidate a line."""
        if not self:
            return self.reason
        lines = [f"{'#':>3} {'z1':>4} {'z2':>4} {'z2p':>4} {'z3':>4} {'k':>3} {'ratio':>12} "
                 f"{'error':>9} {'hunt':>4} shift"]  # fmt: skip
        for i, c in enumerate(self, 1):
            z1, z2, z2p, z3 = c.teeth
            lines.append(
                f"{i:>3} {z1:>4} {z2:>4} {z2p:>4} {z3:>4} {c.n_planets:>3} "
                f"{float(c.ratio):>12.6g} {c.ratio_error:>9.2e} {c.hunting:>4} "
                f"{'yes' if c.shifted else 'no'}"
            )
        return "\n".join(lines)


def _as_ratio(ratio: Any) -> Fraction:
    if isinstance(ratio, bool):
        raise TrainError(f"ratio = {ratio!r}; give a number or a fraction like '13/3'")
    if isinstance(ratio, str):
        try:
            r = Fraction(ratio.strip())
        except (ValueError, ZeroDivisionError):
            raise TrainError(
                f"ratio = {ratio!r} is not a number or a fraction like '13/3'"
            ) from None
    elif isinstance(ratio, numbers.Rational):
        r = Fraction(ratio)
    elif isinstance(ratio, numbers.Real):
        x = float(ratio)
        if not math.isfinite(x):
            raise TrainError(f"ratio = {ratio!r}; valid is a finite, non-zero number")
        r = Fraction(repr(x))  # 3.3 -> 33/10, the decimal the user typed
    else:
        raise TrainError(f"ratio = {ratio!r}; give a number or a fraction like '13/3'")
    if r == 0:
        raise TrainError(
            "ratio = 0 is impossible (the output would not turn); give a non-zero ratio"
        )
    if r.denominator > 10**12:
        r = r.limit_denominator(10**12)
    if abs(r) > 10**12 or abs(r) < Fraction(1, 10**12):
        # the exact tooth arithmetic runs in 64-bit integers; no stage comes near either end
        raise TrainError(
            f"ratio = {ratio!r}; valid is a ratio 1e-12 <= |ratio| <= 1e12 (one stage of "
            "z <= 10^6 reaches far less)"
        )
    return r


def _counts(n_planets: Any) -> list[int]:
    if isinstance(n_planets, bool):
        raise TrainError(f"n_planets = {n_planets!r}; valid is an integer >= 1 or a range")
    if isinstance(n_planets, numbers.Integral):
        ks = [int(n_planets)]
    elif isinstance(n_planets, Iterable):
        ks = []
        for k in n_planets:
            if isinstance(k, bool) or not isinstance(k, numbers.Integral):
                raise TrainError(f"n_planets contains {k!r}; valid are integers >= 1")
            ks.append(int(k))
    else:
        raise TrainError(f"n_planets = {n_planets!r}; valid is an integer >= 1 or a range")
    if not ks:
        raise TrainError("n_planets is empty; give an integer >= 1 or a non-empty range")
    bad = [k for k in ks if k < 1]
    if bad:
        raise TrainError(f"n_planets = {bad[0]}; valid is an integer >= 1")
    return sorted(set(ks))


# open intervals of the ratio for (scheme, fixed, input) with every tooth count positive
_RANGES = {
    ("simple", "ring", "sun"): (2, math.inf, "1 + z_r/z_s with z_r > z_s"),
    ("simple", "ring", "carrier"): (0, Fraction(1, 2), "1/(1 + z_r/z_s) with z_r > z_s"),
    ("simple", "sun", "ring"): (1, 2, "1 + z_s/z_r with z_s < z_r"),
    ("simple", "sun", "carrier"): (Fraction(1, 2), 1, "1/(1 + z_s/z_r)"),
    ("simple", "carrier", "sun"): (-math.inf, -1, "-z_r/z_s"),
    ("simple", "carrier", "ring"): (-1, 0, "-z_s/z_r"),
    ("stepped", "ring", "sun"): (1, math.inf, "1 + z2 z3/(z1 z2')"),
    ("stepped", "ring", "carrier"): (0, 1, "1/(1 + z2 z3/(z1 z2'))"),
    ("stepped", "sun", "ring"): (1, math.inf, "1 + z1 z2'/(z2 z3)"),
    ("stepped", "sun", "carrier"): (0, 1, "1/(1 + z1 z2'/(z2 z3))"),
    ("stepped", "carrier", "sun"): (-math.inf, 0, "-z2 z3/(z1 z2')"),
    ("stepped", "carrier", "ring"): (-math.inf, 0, "-z1 z2'/(z2 z3)"),
}


def _hunting(*pairs: tuple[np.ndarray, np.ndarray]) -> np.ndarray:
    return sum((np.gcd(a, b) == 1).astype(np.int64) for a, b in pairs)


def synthesize(
    ratio: Any,
    n_planets: Any,
    scheme: str = "simple",
    tolerance: float = 0.0,
    z_min: int = 17,
    z_max: int = 200,
    module: float | None = None,
    allow_shift: bool = False,
    *,
    fixed: str = "ring",
    input: str | None = None,
    output: str | None = None,
    clearance: float = 0.5,
    min_internal_difference: int = 8,
    min_contact_ratio: float = 1.1,
    mesh_checks: str = "geometry",
    limit: int = 20,
    progress: Callable[[int, int], object] | None = None,
    max_seconds: float = 30.0,
) -> Candidates:
    """Tooth numbers of a planetary stage that meet a target ratio under every condition.

    Parameters
    ----------
    ratio : number, Fraction or str
        Target ``w_input / w_output`` (default ring fixed, sun in, carrier out). Floats are read
        as the decimal they print as (3.3 -> 33/10).
    n_planets : int or iterable of int
        Planet count, or several (``range(3, 6)``).
    scheme : str
        ``"simple"``, ``"stepped"``, ``"external"``, ``"internal"``, ``"double-planet"``.
    tolerance : float
        Allowed relative ratio error ``|i - target| / |target|`` (0: exact).
    z_min, z_max : int
        Tooth-count range of every gear (rings included).
    module : float, optional
        Module of the returned stages (default 1: lengths in modules).
    allow_shift : bool
        Also accept sets one or two teeth off the zero-shift coaxiality condition (simple and
        stepped schemes), made coaxial by profile shifts (:meth:`Planetary.coaxial` at the
        larger reference centre distance, so no mesh is pushed together: the sun-planet shift
        sum is positive, the planet-ring one negative in DIN 3960's sign, or zero); each such
        stage must pass its checks.
    fixed, input, output : str
        Roles of ``"sun"``, ``"ring"``, ``"carrier"`` (defaults as :meth:`Planetary.ratio`).
    clearance : float
        Gap between planet tip circles (neighbour) and around a double-planet cluster, modules.
    min_internal_difference : int
        Smallest ``z_ring - z_planet`` on an internal mesh (lectures §4.3: 8 for h_a* = 1).
    min_contact_ratio : float
        Smallest transverse contact ratio of every mesh.
    mesh_checks : {"geometry", "textbook", "full"}
        ``"geometry"`` (default): the conditions above, the mesh condition on the real
        zero-shift geometry (contact ratio, involute interference of internal meshes).
        ``"textbook"``: the lectures' §4.4 rules only (z >= z_min, z_ring - z_planet >= 8, no
        mesh geometry), which reproduces their reference tables; it accepts e.g. planet 17 in
        ring 68, whose ring tip passes the planet's base tangent point (involute interference).
        ``"full"``: also every finding of each stage's ``check()``, including the undercut limit
        of ISO 53 (z = 17 is marginally undercut at x = 0) and the tip interference of internal
        meshes (a zero-shift ring's tip reaches below a rack-cut planet's form circle), which
        removes most zero-shift stages.
    limit : int
        Number of candidates returned (the best by the ranking).
    progress : callable, optional
        Called as ``progress(done, total)`` after each block of tooth-number sets is filtered
        (the command line draws its progress bar with it).
    max_seconds : float
        The search is refused before any work when its estimated time (its tooth-number sets
        at :data:`SETS_PER_SECOND`) exceeds this: the error names the estimate, the z_max that
        fits and this parameter. Sets are examined in blocks of :data:`BLOCK`, so memory does
        not grow with ``z_max``.

    Returns
    -------
    Candidates
        A list of :class:`Candidate`, best first; when empty, ``.reason`` names the condition
        that removed the most sets.

    Raises
    ------
    TrainError
        For a ratio the scheme cannot reach with the given roles (e.g. ``ratio <= 2`` for a
        simple stage, ring fixed, sun to carrier), ``n_planets < 1``, ``z_min > z_max``,
        ``z_min < 1``, a negative tolerance or an unknown option.

    Examples
    --------
    Lectures §4.4, scheme A, i = 7, three planets: the third-party course example.

    >>> best = synthesize(7, 3)[0]
    >>> best.teeth, best.ratio
    ((18, 45, 45, 108), Fraction(7, 1))
    >>> synthesize(16, 3, scheme="stepped", z_max=120, mesh_checks="textbook")[0].teeth
    (18, 54, 18, 90)

    That lectures §4.4 scheme B answer has a planet 18 in ring 90 whose nominal ring tip passes
    the planet's base tangent point; the stage relieves the ring's tip to the planet's form
    circle (``Planetary``'s ``ring_tip_relief``), so on the real geometry it stands too:

    >>> synthesize(16, 3, scheme="stepped", z_max=120)[0].teeth
    (18, 54, 18, 90)
    """
    scheme = canonical_scheme(scheme)
    target = _as_ratio(ratio)
    search, m, c = _planned_search(scheme, target, _counts(n_planets), tolerance, z_min, z_max,
                                   limit, min_internal_difference, clearance, module, fixed, input,
                                   output, allow_shift, mesh_checks, min_contact_ratio,
                                   max_seconds)  # fmt: skip
    arrays = search.run(progress)
    out, removed = _ranked(search, arrays, scheme, m, c, z_min, mesh_checks, allow_shift, limit)
    request = f"one {scheme} stage with z {z_min} ... {z_max}"
    return Candidates(out, search.examined, removed, tuple(search.reach), request)


def _planned_search(scheme, target, ks, tolerance, z_min, z_max, limit, min_internal_difference,
                    clearance, module, fixed, input, output, allow_shift, mesh_checks,
                    min_contact_ratio, max_seconds) -> tuple[_Search, float, float]:  # fmt: skip
    """:func:`synthesize`'s options checked (each refused with its value and the valid range,
    the ratio against what the scheme can reach, the work against ``max_seconds``) before any
    work; the search they ask for, the module and the clearance."""
    for name, v in (("z_min", z_min), ("z_max", z_max), ("limit", limit),
                    ("min_internal_difference", min_internal_difference)):  # fmt: skip
        if isinstance(v, bool) or not isinstance(v, numbers.Integral):
            raise TrainError(f"{name} = {v!r}; valid is an integer")
    if z_min < 1:
        raise TrainError(f"z_min = {z_min}; valid is an integer >= 1")
    if z_min > z_max:
        raise TrainError(f"z_min = {z_min} > z_max = {z_max}; give z_min <= z_max")
    if limit < 1:
        raise TrainError(f"limit = {limit}; valid is an integer >= 1")
    tol = float(tolerance) if isinstance(tolerance, numbers.Real) else math.nan
    if not (math.isfinite(tol) and tol >= 0):
        raise TrainError(f"tolerance = {tolerance!r}; valid is a relative error >= 0")
    if mesh_checks not in ("textbook", "geometry", "full"):
        raise TrainError(
            f"mesh_checks = {mesh_checks!r}; valid are 'textbook', 'geometry' and 'full'"
        )
    c = float(clearance) if isinstance(clearance, numbers.Real) else math.nan
    if not (math.isfinite(c) and c >= 0):
        raise TrainError(f"clearance = {clearance!r}; valid is a number >= 0 (modules)")
    m = 1.0 if module is None else float(module)
    if not (math.isfinite(m) and m > 0):
        raise TrainError(f"module = {module!r}; valid is a number > 0")
    fixed, input, output = _default_roles(fixed, input, output)
    key = (scheme, fixed, input)
    if key in _RANGES:
        lo, hi, form = _RANGES[key]
        tgt = float(target)
        reach_lo = lo * (1 - tol) if lo > 0 else lo * (1 + tol)
        reach_hi = hi * (1 + tol) if hi > 0 else hi * (1 - tol)
        if not (reach_lo < tgt < reach_hi):
            raise TrainError(
                f"ratio = {target} cannot be reached by a {scheme} stage with the {fixed} fixed, "
                f"{input} -> {output}: the ratio is {form}, so it must lie strictly between "
                f"{lo} and {hi}"
            )
    if allow_shift and scheme not in ("simple", "stepped"):
        raise TrainError("allow_shift applies to the simple and stepped schemes")

    budget = float(max_seconds) if isinstance(max_seconds, numbers.Real) else math.nan
    if not (budget > 0 and math.isfinite(budget)):
        raise TrainError(f"max_seconds = {max_seconds!r}; valid is a number > 0")
    _check_size(scheme, z_min, z_max, 5 if allow_shift else 1, budget)

    rack = BasicRack.iso53()
    search = _Search(scheme, target, tol, ks, z_min, z_max, c, min_internal_difference,
                     min_contact_ratio, rack.addendum, rack.pressure_angle, fixed, input,
                     output, allow_shift, mesh_checks != "textbook")  # fmt: skip
    return search, m, c


def _ranked(search, arrays, scheme, m, c, z_min, mesh_checks, allow_shift,
            limit) -> tuple[list[Candidate], dict]:  # fmt: skip
    """The best ``limit`` candidates of the sets that passed, ranked; a shifted stage or, with
    full mesh checks, any stage that fails its own check is dropped (and counted as removed)."""
    removed = search.removed
    order = np.lexsort(
        (arrays["z3"] * 0 + arrays["z2p"], arrays["z2"], arrays["z1"], -arrays["k"],
         np.abs(arrays["delta"]), -arrays["hunting"], arrays["error"], arrays["z3"])
    )  # fmt: skip
    out: list[Candidate] = []
    dropped_shift = dropped_full = 0
    for i in order:
        cand = Candidate(
            (int(arrays["z1"][i]), int(arrays["z2"][i]), int(arrays["z2p"][i]),
             int(arrays["z3"][i])),
            int(arrays["k"][i]),
            Fraction(int(arrays["num"][i]), int(arrays["den"][i])),
            float(arrays["error"][i]),
            int(arrays["hunting"][i]),
            bool(arrays["delta"][i] != 0),
            scheme, m, c,
        )  # fmt: skip
        if cand.shifted:
            try:
                report = cand.stage.check()
            except (TrainError, ValueError):
                dropped_shift += 1
                continue
            if not _rules_ok(cand.stage, report, z_min):
                dropped_shift += 1
                continue
        if mesh_checks == "full" and not cand.stage.check().ok:
            dropped_full += 1
            continue
        out.append(cand)
        if len(out) >= limit:
            break
    if allow_shift:
        removed["shifted stage"] = dropped_shift
    if mesh_checks == "full":
        removed["full checks"] = dropped_full
    return out, removed


def set_count(scheme: str, z_min: int, z_max: int) -> int:
    """Tooth-count sets :func:`synthesize` enumerates for ``scheme`` (the flat index that
    :func:`stage_block` cuts): n^2 for the simple and double-planet schemes, n^3 otherwise."""
    n = z_max - z_min + 1
    return n ** (2 if canonical_scheme(scheme) in ("simple", "double-planet") else 3)


#: the arrays of one stage block (:func:`stage_block`)
STAGE_FIELDS = ("z1", "z2", "z2p", "z3", "k", "num", "den", "hunting")


def stage_block(scheme: str, high, n_planets, z_min: int, z_max: int, first: int, last: int,
                mesh_checks: str = "geometry", min_contact_ratio: float = 1.1,
                clearance: float = 0.5) -> dict[str, np.ndarray]:  # fmt: skip
    """Every zero-shift stage of ``scheme`` (ring fixed, sun in, carrier out) with a ratio
    ``1 < r <= high`` among the tooth-count sets ``first .. last - 1`` of the flat index of
    :func:`synthesize` (:func:`set_count`), as arrays :data:`STAGE_FIELDS` (the ratio
    ``num/den`` exact, reduced). The same conditions as :func:`synthesize`; blocks of one
    scheme are independent, so a search runs them on any thread or worker.

    >>> b = stage_block("simple", 7, 3, 17, 60, 0, 44 * 44)
    >>> len(b["z1"]) > 0 and bool((b["num"] <= 7 * b["den"]).all())
    True
    """
    scheme = canonical_scheme(scheme)
    high = float(high)
    mid = _as_ratio((1 + high) / 2)
    cover = (high - 1) / (high + 1) * (1 + 1e-12)
    rack = BasicRack.iso53()
    search = _Search(scheme, mid, cover, _counts(n_planets), z_min, z_max, clearance, 8,
                     min_contact_ratio, rack.addendum, rack.pressure_angle, "ring", "sun",
                     "carrier", False, mesh_checks != "textbook")  # fmt: skip
    arrays = search.run(None, first, last)
    num, den = arrays["num"], arrays["den"]
    keep = (num > den) & (num <= high * den)
    out = {f: arrays[f][keep] for f in STAGE_FIELDS}
    if mesh_checks == "full" and len(out["z1"]):
        rows = zip(*(out[f].tolist() for f in ("z1", "z2", "z2p", "z3", "k")), strict=True)
        good = np.array([_full_check(scheme, *row, clearance) for row in rows])
        out = {f: v[good] for f, v in out.items()}
    return out


def _full_check(scheme, z1, z2, z2p, z3, k, clearance) -> bool:
    planet = z2 if scheme == "simple" else (z2, z2p)
    try:
        return bool(Planetary(z1, planet, z3, k, 1.0, scheme=scheme, clearance=clearance)
                    .check().ok)  # fmt: skip
    except ValueError:
        return False


def _check_size(scheme: str, z_min: int, z_max: int, shifts: int, budget: float) -> None:
    """Refuse a search whose estimated time exceeds ``budget`` seconds (issue 11): n^2 sets for
    a simple stage, n^3 for the three-index schemes (a double-planet search expands the planet
    grid of about n (z1, z3) survivors), n = z_max - z_min + 1, times the shift variants."""
    n = z_max - z_min + 1
    dims = 2 if scheme == "simple" else 3
    sets = n**dims * shifts
    seconds = sets / SETS_PER_SECOND
    if seconds <= budget:
        return
    fits = z_min - 1 + int((budget * SETS_PER_SECOND / shifts) ** (1 / dims))
    raise TrainError(
        f"the {scheme} search over z_min = {z_min} ... z_max = {z_max} examines about "
        f"{sets:.3g} tooth-number sets, about {format_duration(seconds)} at {SETS_PER_SECOND:.0e} "
        f"sets/s, over the budget max_seconds = {budget:g} s; lower z_max (about {fits} fits) "
        f"or raise max_seconds"
    )


def _rules_ok(stage: Planetary, report, z_min: int) -> bool:
    """The rules-mode verdict on a built stage: every finding except the fillet-contact
    (tip interference) ones and the undercut of unshifted gears with z >= z_min."""
    gears = {}
    for name, pair in stage.meshes.items():
        gears[f"{name}.g1"], gears[f"{name}.g2"] = pair.g1, pair.g2
    for name in report.failed():
        if name.endswith(("tip_interference", "tip_interference_2")):
            continue
        if name.endswith(".undercut"):
            g = gears.get(name.rsplit(".", 1)[0])
            if g is not None and g.profile_shift == 0 and g.teeth >= z_min:
                continue
        return False
    return True


class _Search:
    """The vectorised enumeration and filters of :func:`synthesize`."""

    def __init__(self, scheme, target, tol, ks, z_min, z_max, clearance, min_diff, min_eps,
                 addendum, pressure_angle, fixed, input, output, allow_shift,
                 geometry=True):  # fmt: skip
        self.scheme = scheme
        self.target = target
        self.tol = tol
        self.ks = np.array(ks, dtype=np.int64)
        self.z_min, self.z_max = int(z_min), int(z_max)
        self.c = clearance
        self.min_diff = int(min_diff)
        self.min_eps = float(min_eps)
        self.ha = float(addendum)
        self.alpha = float(pressure_angle)
        self.roles = (fixed, input, output)
        self.deltas = (0, -1, 1, -2, 2) if allow_shift else (0,)
        self.geometry = geometry
        self.removed: dict[str, int] = {}
        self.examined = 0
        self.reach = [math.inf, -math.inf]  # the ratios the sets reaching the ratio filter have

    def _count(self, name: str, before: int, after: int) -> None:
        self.removed[name] = self.removed.get(name, 0) + int(before - after)

    # --- enumeration
    def _blocks(self, first: int = 0, last: int | None = None):
        """Tooth-count sets in blocks of at most BLOCK (memory does not grow with z_max): the
        flat index over (z1, z2) or (z1, z2, z2'), in the order of a meshgrid, from ``first``
        to ``last`` (default: all, :func:`set_count`)."""
        z = np.arange(self.z_min, self.z_max + 1, dtype=np.int64)
        s = self.scheme
        dims = 2 if s in ("simple", "double-planet") else 3
        total = len(z) ** dims if last is None else min(last, len(z) ** dims)
        self.n_blocks = max(1, -(-(total - first) // BLOCK))  # for progress reports
        for start in range(first, total, BLOCK):
            idx = np.arange(start, min(start + BLOCK, total), dtype=np.int64)
            zs = [z[i] for i in np.unravel_index(idx, (len(z),) * dims)]
            if s == "simple":
                yield {"z1": zs[0], "z2": zs[1], "z2p": zs[1]}
            elif s == "double-planet":
                yield {"z1": zs[0], "z3": zs[1]}
            else:
                yield {"z1": zs[0], "z2": zs[1], "z2p": zs[2]}

    def run(self, progress=None, first: int = 0, last: int | None = None) -> dict[str, np.ndarray]:
        parts = []
        for i, block in enumerate(self._blocks(first, last), 1):
            if self.scheme == "double-planet":
                parts.append(self._double(block))
            else:
                for delta in self.deltas:
                    b = dict(block)
                    b["z3"] = coaxial_ring_teeth(self.scheme, b["z1"], b["z2"], b["z2p"]) + delta
                    b["delta"] = np.full(b["z1"].shape, delta, dtype=np.int64)
                    parts.append(self._filter(b))
            if progress is not None:
                progress(i, self.n_blocks)
        keys = ("z1", "z2", "z2p", "z3", "k", "num", "den", "error", "hunting", "delta")
        return {k: np.concatenate([p[k] for p in parts]) for k in keys}

    def _keep(self, b: dict, mask: np.ndarray, name: str, weight: int = 1) -> dict:
        """Rows of ``b`` where ``mask``; each removed row counts ``weight`` examined sets."""
        n0 = len(next(iter(b.values())))
        out = {k: v[mask] for k, v in b.items()}
        self._count(name, weight * n0, weight * int(np.count_nonzero(mask)))
        return out

    def _ratio(self, b: dict, weight: int = 1) -> dict:
        num, den = stage_ratio(self.scheme, b["z1"], b["z2"], b["z2p"], b["z3"], *self.roles)
        num, den = np.asarray(num, np.int64), np.asarray(den, np.int64)
        ok_den = den != 0
        if ok_den.any():
            r = num[ok_den] / den[ok_den]
            self.reach = [min(self.reach[0], float(r.min())), max(self.reach[1], float(r.max()))]
        a, q = self.target.numerator, self.target.denominator
        diff = np.abs(num * q - a * den)
        if self.tol == 0:
            mask = ok_den & (diff == 0)
        else:
            mask = ok_den & (diff.astype(float) <= self.tol * abs(a) * np.abs(den).astype(float))
        b = dict(b, num=num, den=den)
        b = self._keep(b, mask, "ratio", weight)
        b["error"] = np.abs(b["num"] * q - a * b["den"]).astype(float) / (
            abs(a) * np.abs(b["den"]).astype(float)
        )
        return b

    def _per_k(self, b: dict) -> dict:
        n = len(b["z1"])
        out = {k: np.repeat(v, len(self.ks)) for k, v in b.items()}
        out["k"] = np.tile(self.ks, n)
        return out

    def _filter(self, b: dict) -> dict:
        s, nk = self.scheme, len(self.ks)
        self.examined += len(b["z1"]) * nk
        z3 = b["z3"]
        b = self._keep(b, (z3 >= self.z_min) & (z3 <= self.z_max), "tooth range", nk)
        z1, z2, z2p, z3 = b["z1"], b["z2"], b["z2p"], b["z3"]
        cos_a = math.cos(math.radians(self.alpha))
        ok = np.ones(len(z1), bool)
        rings = []
        if s in ("simple", "stepped", "internal"):
            rings.append((z3, z2p))
        if s == "internal":
            rings.append((z1, z2))
        for zr, zp in rings:  # tooth difference and the ring's tip above its base circle
            ok &= (zr - zp >= self.min_diff) & (zr - 2 * self.ha > zr * cos_a)
        b = self._keep(b, ok, "internal difference", nk)
        b = self._ratio(b, nk)
        b = self._per_k(b)
        ticks = assembly_ticks(s, b["z1"], b["z2"], b["z2p"], b["z3"])
        b = self._keep(b, (ticks % b["k"]) == 0, "assembly")
        b = self._neighbour_simple(b)
        b = self._mesh(b)
        z1, z2, z2p, z3 = b["z1"], b["z2"], b["z2p"], b["z3"]
        if s == "simple":
            b["hunting"] = _hunting((z1, z2), (z2, z3))
        else:
            b["hunting"] = _hunting((z1, z2), (z2p, z3))
        return b

    def _neighbour_simple(self, b: dict) -> dict:
        z1, z2, z2p, k = b["z1"], b["z2"], b["z2p"], b["k"]
        if self.scheme == "internal":
            a = (z1 - z2) / 2.0
        else:
            a = (z1 + z2) / 2.0
        tip = np.maximum(z2, z2p) + 2 * self.ha
        with np.errstate(divide="ignore"):
            chord = np.where(k > 1, 2 * a * np.sin(np.pi / np.maximum(k, 1)), np.inf)
        return self._keep(b, chord - tip >= self.c - NEIGHBOUR_TOLERANCE, "neighbour")

    def _mesh(self, b: dict) -> dict:
        s = self.scheme
        z1, z2, z2p, z3 = b["z1"], b["z2"], b["z2p"], b["z3"]
        meshes = []
        if s == "internal":
            meshes.append((z2, z1, True))
        else:
            meshes.append((z1, z2, False))
        meshes.append((z2p, z3, s != "external"))
        ok = np.ones(len(z1), bool)
        for za, zb, internal in meshes:
            ok &= self._mesh_ok(za, zb, internal)
        return self._keep(b, ok, "mesh")

    def _mesh_ok(self, z1, z2, internal: bool) -> np.ndarray:
        if len(z1) == 0 or not self.geometry:
            return np.ones(len(z1), bool)
        g = pair_geometry(z1, z2, 1.0, 0.0, 0.0, self.alpha, 0.0, internal, self.ha)
        if not internal:
            return g.contact_ratio >= self.min_eps
        # a stage's ring has its tip relieved where it would reach the planet's fillet
        # (Planetary's ring_tip_relief): judge the ring by the tip it will have, or the filter
        # removes stages that pass (18-tooth planets, issue 26)
        rack = replace(BasicRack.iso53().with_pressure_angle(self.alpha), addendum=self.ha)
        k = ring_tip_alteration(z1, z2, 1.0, rack)
        cos_a = math.cos(math.radians(self.alpha))
        rb1, rb2 = z1 * cos_a / 2, z2 * cos_a / 2
        ra1 = g.tip_diameter_1 / 2
        ra2 = np.maximum(g.tip_diameter_2 / 2, z2 / 2 - (self.ha + k))
        tan_wt = np.tan(np.radians(g.working_pressure_angle))
        eps = contact_ratio(ra1, ra2, rb1, rb2, tan_wt, -1.0, math.pi * cos_a)
        # involute interference: z1/z2 >= 1 - tan(alpha_a2)/tan(alpha_w)
        aa2 = np.arccos(np.minimum(rb2 / ra2, 1.0))
        return (eps >= self.min_eps) & (z1 / z2 >= 1 - np.tan(aa2) / tan_wt)

    # --- double planet: ratio and assembly on (z1, z3), then the planet grid
    def _double(self, b: dict) -> dict:
        zmin, zmax, nk = self.z_min, self.z_max, len(self.ks)
        grid = (zmax - zmin + 1) ** 2  # planet pairs per (z1, z3)
        self.examined += len(b["z1"]) * nk * grid
        b["z2"] = b["z2p"] = np.zeros_like(b["z1"])
        b = self._ratio(b, nk * grid)
        b = self._per_k(b)
        b = self._keep(b, (np.abs(b["z3"] - b["z1"]) % b["k"]) == 0, "assembly", grid)
        z = np.arange(zmin, zmax + 1, dtype=np.int64)
        p1, p2 = (a.ravel() for a in np.meshgrid(z, z, indexing="ij"))
        n = len(b["z1"])
        g = {k: np.repeat(v, len(p1)) for k, v in b.items()}
        g["z2"], g["z2p"] = np.tile(p1, n), np.tile(p2, n)
        g["delta"] = np.zeros(len(g["z1"]), np.int64)
        z1, zp1, zp2, z3 = g["z1"], g["z2"], g["z2p"], g["z3"]
        ok = (z3 - zp2 >= self.min_diff) & (z3 - 2 * self.ha > z3 * math.cos(
            math.radians(self.alpha)))  # fmt: skip
        g = self._keep(g, ok, "internal difference")
        z1, zp1, zp2, z3, k = g["z1"], g["z2"], g["z2p"], g["z3"], g["k"]
        ha, c = self.ha, self.c
        a1, a2, a12 = (z1 + zp1) / 2.0, (z3 - zp2) / 2.0, (zp1 + zp2) / 2.0
        ok = (a12 > np.abs(a1 - a2)) & (a12 < a1 + a2)
        ok &= a2 - (z1 / 2 + ha) - (zp2 / 2 + ha) >= c - NEIGHBOUR_TOLERANCE
        ok &= (z3 / 2 - ha) - a1 - (zp1 / 2 + ha) >= c - NEIGHBOUR_TOLERANCE
        g = self._keep(g, ok, "coaxiality")
        z1, zp1, zp2, z3, k = g["z1"], g["z2"], g["z2p"], g["z3"], g["k"]
        a1, a2, a12 = (z1 + zp1) / 2.0, (z3 - zp2) / 2.0, (zp1 + zp2) / 2.0
        r1, r2 = zp1 / 2 + ha, zp2 / 2 + ha
        cos_psi = np.clip((a1 * a1 + a2 * a2 - a12 * a12) / (2 * a1 * a2), -1, 1)
        psi = np.arccos(cos_psi)
        th = 2 * np.pi / k
        gap = np.minimum(2 * a1 * np.sin(np.pi / k) - 2 * r1, 2 * a2 * np.sin(np.pi / k) - 2 * r2)
        for sign in (1, -1):
            d = np.sqrt(np.maximum(a1 * a1 + a2 * a2 - 2 * a1 * a2 * np.cos(psi + sign * th), 0))
            gap = np.minimum(gap, d - r1 - r2)
        gap = np.where(k > 1, gap, np.inf)
        g = self._keep(g, gap >= c - NEIGHBOUR_TOLERANCE, "neighbour")
        z1, zp1, zp2, z3 = g["z1"], g["z2"], g["z2p"], g["z3"]
        ok = (self._mesh_ok(z1, zp1, False) & self._mesh_ok(zp1, zp2, False)
              & self._mesh_ok(zp2, z3, True))  # fmt: skip
        g = self._keep(g, ok, "mesh")
        g["hunting"] = _hunting((g["z1"], g["z2"]), (g["z2"], g["z2p"]), (g["z2p"], g["z3"]))
        return g
