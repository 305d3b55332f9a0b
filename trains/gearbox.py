"""Layer 7, design: multi-stage planetary gearbox search (issue 13).

:func:`synthesize_gearbox` finds ``stages`` planetary stages in series (any of the five
schemes each, ring fixed, sun in, carrier out by default) whose ratios multiply to a target.

1. **Stage sets, once.** Every single stage a scheme allows with a reduction ratio
   ``1 < r <= R`` comes from one :func:`trains.synthesize` call per scheme (exact Fractions,
   the assembly, neighbour, coaxiality and mesh conditions; vectorised). The calls run on local
   threads, or as Dask tasks with ``client=``.
2. **Prune on the exact ratio, in integers.** Stages are grouped by their ratio ``a/b``; for
   k = 2 the second ratio must be exactly ``R b / a`` (one dictionary look-up of a reduced
   integer pair); for k = 3 the first two are paired and the third looked up the same way.
   With ``tolerance > 0`` a sorted float window preselects and ``Fraction`` decides.
3. **Combine, not recompute.** The objectives are separable (the largest ring, the sum of
   the tooth counts, the product of the stage efficiencies), so the best gearboxes of a ratio
   tuple combine the best stages of each ratio: only the ``top`` best per ratio are combined.
4. **Full checks, lazily.** Walking the ranking, each stage is built and checked once with
   :meth:`trains.planetary.Planetary.check` (cached); a gearbox with a failing stage is
   skipped, until ``top`` are found.

Stages are listed input first, in non-decreasing ratio (any order gives the same product).
"""

from __future__ import annotations

import bisect
import heapq
import itertools
import math
import numbers
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import numpy as np

from gears.errors import GearError
from gears.search import dask_client, dask_results, progress_callback
from trains.errors import TrainError
from trains.planetary import canonical_scheme
from trains.synthesis import Candidate, _as_ratio, synthesize

__all__ = ["Gearbox", "Gearboxes", "synthesize_gearbox"]

_OBJECTIVES = ("ring", "teeth", "efficiency")
_MIN_RATIO = {"simple": 2.0}
#: combinations of stage ratios examined without client= before the search is refused
MAX_LOCAL_PAIRS = 5 * 10**7


@dataclass(frozen=True)
class Gearbox:
    """Planetary stages in series.

    Attributes
    ----------
    stages : tuple of Candidate
        The stages, input first (each with its ``stage``: a :class:`Planetary`).
    ratio : Fraction
        The product of the stage ratios (exact).
    ratio_error : float
    ring : float
        Largest ring reference diameter, mm (z3 m).
    teeth : int
        Total of the tooth counts of all stages.
    efficiency : float
        Product of the stage efficiencies (:meth:`Planetary.efficiency`, Ozols (14.25)
        meshes with friction 0.1).
    """

    stages: tuple[Candidate, ...]
    ratio: Fraction
    ratio_error: float
    ring: float
    teeth: int
    efficiency: float

    def __str__(self) -> str:
        parts = " | ".join(
            f"{c.scheme} {'/'.join(str(z) for z in _distinct(c))} x{c.n_planets} ({c.ratio})"
            for c in self.stages
        )
        return (f"ratio {self.ratio} (error {self.ratio_error:.2e}), ring {self.ring:g} mm, "
                f"{self.teeth} teeth, efficiency {self.efficiency:.4f}: {parts}")  # fmt: skip


def _distinct(c: Candidate) -> tuple[int, ...]:
    z1, z2, z2p, z3 = c.teeth
    return (z1, z2, z3) if c.scheme == "simple" else (z1, z2, z2p, z3)


def _teeth_total(c: Candidate) -> int:
    return sum(_distinct(c))


class Gearboxes(list):
    """The ranked gearboxes (a list) with the bookkeeping of the search.

    Attributes
    ----------
    stage_sets : dict
        Scheme -> single stages found for it.
    ratio_tuples : int
        Combinations of stage ratios whose product meets the target.
    checked : int
        Distinct stages checked in full (:meth:`Planetary.check`).
    seconds : float
    """

    def __init__(self, items, stage_sets, ratio_tuples, checked, seconds):
        super().__init__(items)
        self.stage_sets = dict(stage_sets)
        self.ratio_tuples = int(ratio_tuples)
        self.checked = int(checked)
        self.seconds = float(seconds)

    def table(self) -> str:
        """One line per gearbox, ranked."""
        if not self:
            return (f"no gearbox meets the request ({self.ratio_tuples} ratio combinations; "
                    f"stage sets: {self.stage_sets})")  # fmt: skip
        return "\n".join(f"{i:3d}. {g}" for i, g in enumerate(self, 1))

    def to_array(self) -> np.ndarray:
        """A numpy structured array: rank, ratio, error, ring, teeth, efficiency and, per stage
        ``s``, ``s_scheme``, ``s_z1``, ``s_z2``, ``s_z2p``, ``s_z3``, ``s_planets``."""
        k = len(self[0].stages) if self else 0
        fields = [("rank", int), ("ratio", float), ("ratio_error", float), ("ring", float),
                  ("teeth", int), ("efficiency", float)]  # fmt: skip
        for s in range(1, k + 1):
            fields += [(f"{s}_scheme", "U13"), (f"{s}_z1", int), (f"{s}_z2", int),
                       (f"{s}_z2p", int), (f"{s}_z3", int), (f"{s}_planets", int)]  # fmt: skip
        out = np.zeros(len(self), fields)
        for i, g in enumerate(self):
            row = [i + 1, float(g.ratio), g.ratio_error, g.ring, g.teeth, g.efficiency]
            for c in g.stages:
                row += [c.scheme, *c.teeth, c.n_planets]
            out[i] = tuple(row)
        return out


def _validate(ratio, stages, tolerance, objective, top, schemes) -> tuple:
    target = _as_ratio(ratio)
    if target <= 1:
        raise TrainError(f"ratio = {target}; a gearbox of reduction stages needs ratio > 1")
    if isinstance(stages, bool) or not isinstance(stages, numbers.Integral) or not 1 <= stages <= 3:
        raise TrainError(f"stages = {stages!r}; valid is 1, 2 or 3")
    tol = float(tolerance) if isinstance(tolerance, numbers.Real) else math.nan
    if not (math.isfinite(tol) and 0 <= tol < 1):
        raise TrainError(f"tolerance = {tolerance!r}; valid is a relative error 0 <= t < 1")
    if objective not in _OBJECTIVES:
        raise TrainError(f"objective = {objective!r}; valid are {list(_OBJECTIVES)}")
    if isinstance(top, bool) or not isinstance(top, numbers.Integral) or top < 1:
        raise TrainError(f"top = {top!r}; valid is an integer >= 1")
    names = (schemes,) if isinstance(schemes, str) else tuple(schemes)
    if not names:
        raise TrainError("schemes is empty; give at least one scheme")
    return target, int(stages), tol, tuple(dict.fromkeys(canonical_scheme(s) for s in names))


def _stage_set(scheme, hi, n_planets, z_min, z_max, module, mesh_checks, min_contact_ratio,
               max_seconds=30.0):  # fmt: skip
    """Every stage of ``scheme`` with 1 < ratio <= hi (one synthesize call; the chunk that
    runs on a thread or as a Dask task). Returns a list of Candidates (empty if out of reach)."""
    mid = (1 + hi) / 2
    cover = (hi - 1) / (hi + 1) * (1 + 1e-12)
    try:
        found = synthesize(mid, n_planets, scheme, tolerance=cover, z_min=z_min, z_max=z_max,
                           module=module, mesh_checks=mesh_checks, limit=10**9,
                           min_contact_ratio=min_contact_ratio,
                           max_seconds=max_seconds)  # fmt: skip
    except TrainError as exc:  # this scheme cannot reach the range with these roles
        if "cannot be reached" in str(exc):
            return []
        raise
    return [c for c in found if 1 < c.ratio <= hi]


def synthesize_gearbox(
    ratio: Any, stages: int = 2, n_planets: Any = 3, schemes: str | Sequence[str] = "simple",
    *, tolerance: float = 0.0, z_min: int = 17, z_max: int = 150, module: float = 1.0,
    objective: str = "ring", top: int = 10, mesh_checks: str = "geometry",
    min_contact_ratio: float = 1.1, full_checks: bool = True, client=None,
    progress: Callable[[int, int], object] | bool | None = None, max_seconds: float = 30.0,
) -> Gearboxes:  # fmt: skip
    """Planetary stages in series whose ratios multiply to ``ratio``, ranked.

    Parameters
    ----------
    ratio : number, Fraction or str
        Total reduction ``w_input / w_output`` (> 1).
    stages : int
        Number of stages, 1 to 3.
    n_planets : int or iterable of int
        Planet counts allowed in every stage.
    schemes : str or sequence of str
        Schemes allowed for each stage (``"simple"``, ``"stepped"``, ``"external"``,
        ``"internal"``, ``"double-planet"``); ring fixed, sun in, carrier out.
    tolerance : float
        Allowed relative error of the total ratio (0: exact).
    z_min, z_max, module, mesh_checks, min_contact_ratio
        As :func:`trains.synthesize`, for every stage.
    objective : {"ring", "teeth", "efficiency"}
        Smallest largest ring, fewest teeth in total, or highest efficiency; ties go to the
        next objectives in that order.
    top : int
        Gearboxes returned.
    full_checks : bool
        Check each stage of the returned gearboxes with :meth:`Planetary.check` and skip
        gearboxes with a failing stage.
    client : dask.distributed.Client, str, None or False
        Run the per-scheme stage searches as Dask tasks (None: the active client if any).
    progress : callable, bool or None
        ``progress(done, total)`` after each stage set and each checked gearbox; True: a tqdm
        bar; None: a bar when stderr is a terminal; False: none.
    max_seconds : float
        The time budget of each stage-set search (:func:`trains.synthesize` refuses a larger
        one before any work).

    Returns
    -------
    Gearboxes

    Examples
    --------
    1:12 in two simple stages, 3 planets each, every gear at most 100 teeth: the smallest ring
    is 75 teeth (54/17 x 34/9 = 12 exactly).

    >>> best = synthesize_gearbox(12, stages=2, z_max=100, progress=False)[0]
    >>> best.ratio, [c.ratio for c in best.stages], [c.teeth for c in best.stages]
    (Fraction(12, 1), [Fraction(54, 17), Fraction(34, 9)], [(34, 20, 20, 74), (27, 24, 24, 75)])
    """
    t0 = time.perf_counter()
    target, k, tol, names = _validate(ratio, stages, tolerance, objective, top, schemes)
    for name, v in (("z_min", z_min), ("z_max", z_max)):
        if isinstance(v, bool) or not isinstance(v, numbers.Integral) or v < 1:
            raise TrainError(f"{name} = {v!r}; valid is an integer >= 1")
    report = _as_train_error(progress_callback, progress, "gearbox search", "stage set")
    # the largest stage ratio: the target over the smallest ratio the other stages can have
    # (a simple stage, ring fixed, gives 1 + z3/z1 > 2; the other schemes more than 1)
    lowest = min(_MIN_RATIO.get(s, 1.0) for s in names)
    hi = float(target) * (1 + tol) / lowest ** (k - 1)
    args = [(s, hi, n_planets, z_min, z_max, module, mesh_checks, min_contact_ratio,
             max_seconds) for s in names]  # fmt: skip
    sets = _run(args, client, report, len(names) + top)
    pool = [c for found in sets for c in found]
    by_ratio: dict[Fraction, list[Candidate]] = {}
    for c in pool:
        by_ratio.setdefault(c.ratio, []).append(c)
    tuples = _ratio_tuples(sorted(by_ratio), target, k, tol)
    key = _stage_key(objective)
    for r in {r for rs in tuples for r in rs}:  # only ratios that take part
        by_ratio[r].sort(key=key)
        del by_ratio[r][top * 4 :]  # the best per ratio suffice (separable objectives)
    heap: list = []
    counter = itertools.count()
    for rs in tuples:
        for combo in itertools.product(*(by_ratio[r] for r in rs)):
            score = _score(combo, target, objective)
            heapq.heappush(heap, (score, next(counter), combo))
    out, checked, verdicts = [], 0, {}
    while heap and len(out) < top:
        score, _, combo = heapq.heappop(heap)
        if full_checks:
            ok = True
            for c in combo:
                if id(c) not in verdicts:
                    verdicts[id(c)] = _stage_ok(c, min_contact_ratio)
                    checked += 1
                ok &= verdicts[id(c)]
            if not ok:
                continue
        out.append(_gearbox(combo, target))
        if report:
            report(len(names) + len(out), len(names) + top)
    if report:
        report(len(names) + top, len(names) + top)
    counts = {s: len(f) for s, f in zip(names, sets, strict=True)}
    return Gearboxes(out, counts, len(tuples), checked, time.perf_counter() - t0)


def _stage_ok(c: Candidate, min_contact_ratio: float) -> bool:
    try:
        return c.stage.check(min_contact_ratio=min_contact_ratio).ok
    except ValueError:  # a stage that cannot be built is not a design
        return False


def _efficiency(c: Candidate) -> float:
    cache = _efficiency.cache  # type: ignore[attr-defined]
    key = (c.scheme, c.teeth, c.n_planets, c.module)
    if key not in cache:
        try:
            cache[key] = float(c.stage.efficiency())
        except ValueError:
            cache[key] = 0.0
    return cache[key]


_efficiency.cache = {}  # type: ignore[attr-defined]


def _stage_key(objective: str) -> Callable[[Candidate], tuple]:
    if objective == "ring":
        return lambda c: (c.teeth[3], _teeth_total(c), c.teeth)
    if objective == "teeth":
        return lambda c: (_teeth_total(c), c.teeth[3], c.teeth)
    return lambda c: (-_efficiency(c), c.teeth[3], _teeth_total(c), c.teeth)


def _score(combo: Sequence[Candidate], target: Fraction, objective: str) -> tuple:
    ring = max(c.teeth[3] * c.module for c in combo)
    teeth = sum(_teeth_total(c) for c in combo)
    ratio = math.prod((c.ratio for c in combo), start=Fraction(1))
    error = float(abs(ratio - target) / target)
    ident = tuple((c.scheme, c.teeth, c.n_planets) for c in combo)
    if objective == "ring":
        return (ring, teeth, error, ident)
    if objective == "teeth":
        return (teeth, ring, error, ident)
    eta = math.prod(_efficiency(c) for c in combo)
    return (-eta, ring, teeth, error, ident)


def _gearbox(combo: Sequence[Candidate], target: Fraction) -> Gearbox:
    ratio = math.prod((c.ratio for c in combo), start=Fraction(1))
    return Gearbox(
        tuple(combo), ratio, float(abs(ratio - target) / target),
        max(c.teeth[3] * c.module for c in combo), sum(_teeth_total(c) for c in combo),
        math.prod(_efficiency(c) for c in combo),
    )  # fmt: skip


def _ratio_tuples(ratios: list[Fraction], target: Fraction, k: int, tol: float) -> list[tuple]:
    """Non-decreasing tuples of stage ratios whose product meets the target (exactly: integer
    look-ups of the reduced fraction; with a tolerance: a float window, then Fractions)."""
    have = set(ratios)
    floats = [float(r) for r in ratios]

    def last(need: Fraction, low: Fraction) -> list[Fraction]:
        if tol == 0:
            return [need] if need in have and need >= low else []
        f = float(need)
        i = bisect.bisect_left(floats, f * (1 - tol) * (1 - 1e-12))
        j = bisect.bisect_right(floats, f * (1 + tol) * (1 + 1e-12))
        return [r for r in ratios[i:j] if r >= low and abs(r / need - 1) <= tol]

    if k == 1:
        return [(r,) for r in last(target, Fraction(0))]
    if k * len(ratios) ** (k - 1) > MAX_LOCAL_PAIRS:
        raise TrainError(
            f"{len(ratios)} stage ratios give about {len(ratios) ** (k - 1):,} combinations for "
            f"{k} stages, over the limit of {MAX_LOCAL_PAIRS:,}; lower z_max or use fewer schemes"
        )
    out = []
    for i, r1 in enumerate(ratios):
        if r1**k > target * (1 + tol):
            break
        if k == 2:
            out += [(r1, r2) for r2 in last(target / r1, r1)]
            continue
        for r2 in ratios[i:]:
            if r1 * r2 * r2 > target * (1 + tol):
                break
            out += [(r1, r2, r3) for r3 in last(target / (r1 * r2), r2)]
    return out


def _run(args: list[tuple], client, report, total: int) -> list[list[Candidate]]:
    """The stage sets: one chunk per scheme, on threads or as Dask tasks."""
    client = _as_train_error(dask_client, client)
    if client is not None:
        futures = {client.submit(_stage_set, *a, pure=False): i for i, a in enumerate(args)}
        results: list = [None] * len(args)
        try:
            for n, (fut, found) in enumerate(dask_results(client, set(futures)), 1):
                results[futures[fut]] = found
                if report:
                    report(n, total)
        except GearError as exc:  # the cluster failed under the work
            raise TrainError(str(exc)) from None
        return results
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(max(1, min(len(args), 4))) as pool:
        futures = [pool.submit(_stage_set, *a) for a in args]
        results = []
        for n, fut in enumerate(futures, 1):
            results.append(fut.result())
            if report:
                report(n, total)
    return results


def _as_train_error(fn, *args):
    """``fn(*args)`` with a bad argument reported as this package's error."""
    try:
        return fn(*args)
    except GearError as exc:
        raise TrainError(str(exc)) from None
