"""Layer 1, budget: one estimator of the work a request takes, refused before the work starts.

Outlines, simulations, meshes, scenes and animations count their work in one unit each, and
each unit has one budget (:data:`BUDGETS`), measured so that the largest accepted request stays
well below 2 GB of memory and about half a minute on one core (docs/performance.md, "Work
budgets"):

* ``"outline"``: vertices of one outline (about 40 bytes each with shapely's copy);
* ``"simulation"``: tool-polygon vertices placed by a simulated cutter (the union is about
  1 us and 50 bytes a vertex);
* ``"mesh"``: vertices of one solid or of all the distinct solids of a scene (``gear_solid``
  peaks near 400 bytes a vertex; trimesh's own checks afterwards take twice that);
* ``"animation"``: outline vertices drawn, over all frames (matplotlib takes about 20 us a
  vertex).

The count is estimated before the work from a cheap sample (one tooth's vertices, the slice
rule, the frame count), as a function of the tolerance, and :func:`check_budget` refuses a
request over the budget with its size and the coarsest tolerance that fits, found on that same
function. Every size is relative: the counts depend on the tolerance as a fraction of the
module, so a watch gear and a mill gear cost the same at the same relative tolerance.

Examples
--------
>>> check_budget("mesh", "a solid", lambda t: 1e5 * (0.01 / t), 0.01)
100000.0
>>> check_budget("mesh", "a solid", lambda t: 1e5 * (0.01 / t), 1e-5)  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
gears.errors.GearError: a solid at tolerance = 1e-05 mm would take about 1e+08 vertices, ...
>>> fitting_tolerance(lambda t: 1e5 * (0.01 / t), 1e-5, 2e6)   # 1e5 x 0.01 / 2e6
0.0005
"""

from __future__ import annotations

import math
from collections.abc import Callable

from gears.errors import GearError

__all__ = ["BUDGETS", "check_budget", "fitting_tolerance", "round_up"]

#: The budget of each kind of work, in its unit (see the module docstring).
BUDGETS = {
    "outline": 10_000_000,
    "simulation": 20_000_000,
    "mesh": 2_000_000,
    "animation": 1_000_000,
}

_UNITS = {"animation": "vertices drawn", "simulation": "vertex operations"}


def round_up(value: float, digits: int = 2) -> float:
    """``value`` rounded up to ``digits`` significant digits (a suggestion that still fits).

    >>> round_up(0.000123401), round_up(2.0)
    (0.00013, 2.0)
    """
    if not (math.isfinite(value) and value > 0):
        return value
    scale = 10.0 ** (math.floor(math.log10(value)) - digits + 1)
    out = math.ceil(value / scale * (1 - 1e-12)) * scale
    return float(f"{out:.{digits}g}")


def fitting_tolerance(
    estimate: Callable[[float], float], tolerance: float, budget: float, most: float = 1e6
) -> float | None:
    """The smallest tolerance (two significant digits, rounded up) at which ``estimate`` fits
    the budget, searched from ``tolerance`` upwards on the estimate's own local power law (a
    secant in log-log); None when even ``most`` times the tolerance does not fit (the work has
    a part no tolerance reduces)."""
    t0, n0 = tolerance, float(estimate(tolerance))
    if n0 <= budget:
        return tolerance
    t1 = t0 * 2.0
    n1 = float(estimate(t1))
    for _ in range(60):
        if n1 <= budget:
            break
        p = math.log(n0 / n1) / math.log(t1 / t0) if n1 < n0 else 0.0
        p = min(max(p, 0.25), 4.0)  # the counts fall as tol^-1/2 ... tol^-2
        jump = min(math.log(n1 / budget) / p, math.log(most)) + 0.01  # no overflow
        t0, n0, t1 = t1, n1, min(t1 * math.exp(jump), tolerance * most)
        n1 = float(estimate(t1))
        if t1 >= tolerance * most and n1 > budget:
            return None
    else:
        return None
    # bisect down in log space to the smallest fitting value, then round it up
    lo, hi = t0, t1
    for _ in range(30):
        if hi / lo < 1.02:
            break
        mid = math.sqrt(lo * hi)
        if float(estimate(mid)) <= budget:
            hi = mid
        else:
            lo = mid
    out = round_up(lo)
    while float(estimate(out)) > budget:  # the next two-digit value (hi fits: this ends)
        out = round_up(out + 10.0 ** (math.floor(math.log10(out)) - 1))
    return out


def check_budget(
    kind: str, what: str, estimate: Callable[[float], float], tolerance: float,
    hint: str = "", budget: float | None = None,
) -> float:  # fmt: skip
    """The estimated size of ``what`` at ``tolerance`` (``estimate(tolerance)``, in the unit of
    ``kind``), or a :class:`GearError` before any work when it exceeds the budget of ``kind``,
    naming the size, the budget and the coarsest tolerance that fits (or ``hint``, what else to
    reduce, when no tolerance does).
    """
    limit = BUDGETS[kind] if budget is None else float(budget)
    n = float(estimate(tolerance))
    if n <= limit:
        return n
    unit = _UNITS.get(kind, "vertices")
    head = (
        f"{what} at tolerance = {tolerance:g} mm would take about {n:.3g} {unit}, over the "
        f"{kind} budget of {limit:.3g}"
    )
    fits = fitting_tolerance(estimate, tolerance, limit)
    if fits is None:
        raise GearError(f"{head}; no tolerance brings it within the budget" + (
            f": {hint}" if hint else ""))  # fmt: skip
    more = f" (or {hint})" if hint else ""
    raise GearError(f"{head}; use tolerance >= {fits:.2g} mm{more}")
