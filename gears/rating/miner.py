"""Layer 3, load spectra: Miner's rule on the S-N curves of ISO 6336-2/-3 (ISO 6336-6) over
arrays: the damage, the equivalent safety and the life of each gear and failure mode from the
stresses of the bins (the formulas as math: docs/rating.md, "Load spectra").

For each bin i and gear the rating at the bin's own load gives the stress sigma_i and the
allowable stress at the bin's cycles; divided by its life factor (Z_NT, Y_NT) it leaves the
strength at the endurance knot with every other factor of that bin, sigma_inf,i. The
material's S-N curve (the knots of Z_NT and Y_NT in :mod:`gears.rating.life`, straight lines
in log-log) read backwards gives the cycles to failure N_f,i at sigma_i / sigma_inf,i, and
Miner's rule sums the damage D = sum(N_L,i / N_f,i) (Miner's elementary rule: a stress above
the curve's static knot fails in one cycle, a stress below its last knot, the endurance limit,
does no damage). The equivalent safety S is the factor by which every bin's stress may grow
before D reaches 1; the life is the spectrum's hours over D (:data:`LIFE_CAP` where endless).
The ratings of the bins come from :func:`gears.rating.sizing.rate_spectrum`.
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np

from gears.arguments import common_shape
from gears.errors import GearError
from gears.meshing import _pool
from gears.rating._arrays import number
from gears.rating.life import _BENDING_TABLE, _PITTING_TABLE
from gears.rating.materials import KINDS

__all__ = [
    "LIFE_CAP",
    "MAX_BINS",
    "MODES",
    "SpectrumRatings",
    "check_spectrum",
    "cycles_to_failure",
    "equivalent_safety",
    "miner_damage",
]

#: The life reported where the spectrum does no damage (every stress below the endurance limit).
LIFE_CAP = 1e12
#: Failure modes and the life curve each reads: pitting (Z_NT), tooth-root bending (Y_NT).
MODES = ("pitting", "bending")
#: Most bins a spectrum may have.
MAX_BINS = 10_000
# most load cycles a bin of miner_damage and equivalent_safety may have: far past any gear's
# (10^9 hours at 10^7 rpm are 6 x 10^17), and Miner's sum of any array of bins stays finite
_MAX_CYCLES = 1e30
_BLOCK = 1 << 17  # bins x pairs solved at once (larger blocks: fewer numpy calls a pair)
_ROUNDS = 6  # rounds of the fast path before a row goes to the bisection
_THREADED = 1 << 14  # ratings (pairs x bins) from which the gears and modes run on threads
_TABLES = {"pitting": _PITTING_TABLE, "bending": _BENDING_TABLE}


def _mode_table(mode: str):
    if mode not in _TABLES:
        raise GearError(f"mode = {mode!r}; valid are {', '.join(MODES)}")
    return _TABLES[mode]


def _knots(code, table):
    """The curve's knots (k0, k1, k2, y0, y1, y2) for material ``code`` (arrays with a trailing
    axis for the bins, or numbers)."""
    logn, logy = table
    code = np.asarray(code)
    if code.ndim == 0:
        c = int(code)
        return tuple(float(v) for v in (*logn[c], *logy[c]))
    return tuple(v[..., None] for v in (*logn[code].T, *logy[code].T))


def _slopes(knots):
    """The S-N curve's slopes d ln N_f / d ln sigma above and below its knee (both < 0)."""
    k0, k1, k2, y0, y1, y2 = knots
    return (k1 - k0) / (y1 - y0), (k2 - k1) / (y2 - y1)


def _hinge(u, a1, a2):
    """ln N_f - ln N_knee on the sloped part of the S-N curve: a2 u below the knee, a1 u above
    it (``u`` = ln(sigma / sigma_inf) - y1, the log-log lines through the knots)."""
    return a2 * u + (a1 - a2) * np.maximum(u, 0.0)


def _sloped_log_cycles(u, knots):
    """ln N_f on the sloped part of the S-N curve, ``u`` = ln(sigma / sigma_inf) - y1 from its
    knee."""
    return knots[1] + _hinge(u, *_slopes(knots))


def _line_at_one(e1, a, ln_knee, out=None):
    """ln N_f at S = 1 on the S-N curve's log-log line of slope ``a`` through its knee (ln N_f
    = ``ln_knee`` there) for a bin whose knee lies at x = ln S = ``e1`` (y1 - z): the line of
    both Miner's solvers (:class:`_Lines`, :func:`_bisect`); into ``out`` where given."""
    out = np.multiply(e1, a, out=out)
    return np.subtract(ln_knee, out, out=out)


def _log_cycles(z, knots):
    """ln N_f at ``z = ln(sigma / sigma_inf)``: +inf below the endurance knot, 0 (one cycle)
    above the static knot, the log-log lines between."""
    y0, y1, y2 = knots[3:]
    ln_nf = np.where(z > y0, 0.0, _sloped_log_cycles(z - y1, knots))
    return np.where(z <= y2, np.inf, ln_nf)


def _material_code(code):
    """``code`` a material group's integer code (:func:`gears.rating.materials.kind_code`) or
    an array of them, or a GearError naming it."""
    c = number("code", code, 0, len(KINDS) - 1, low_open=False, high_open=False, integer=True)
    return int(c) if np.ndim(c) == 0 else c.astype(int)


def _checked(stress, strength, cycles, code, mode, axis):
    """The bins of :func:`miner_damage` and :func:`equivalent_safety` checked before any work
    (stresses and strengths finite and > 0 in MPa, cycles 0 ... 10^30, ``axis`` one of
    their broadcast shape's, an array ``code`` of the result's shape), or a GearError naming
    the first bad one."""
    _mode_table(mode)
    stress, strength = number("stress", stress, 0.0, math.inf), number(
        "strength", strength, 0.0, math.inf)  # fmt: skip
    cycles = number("cycles", cycles, 0.0, _MAX_CYCLES, low_open=False, high_open=False)
    code = _material_code(code)
    shape = common_shape({"stress": np.shape(stress), "strength": np.shape(strength),
                          "cycles": np.shape(cycles)})  # fmt: skip
    k = len(shape)
    if isinstance(axis, bool) or not isinstance(axis, int | np.integer) or not -k <= axis < k:
        raise GearError(f"axis = {axis!r}; valid is an axis of the bins' arrays, of shape "
                        f"{shape}: an integer from {-k} to {k - 1}" if k else
                        f"axis = {axis!r}: the bins' arrays are numbers; valid are arrays "
                        "with the bins on an axis")  # fmt: skip
    if shape[axis] == 0:
        raise GearError(f"no bins (arrays of shape {shape}, the bins on axis {axis}); valid is "
                        "one bin or more")  # fmt: skip
    rest = shape[: axis % k] + shape[axis % k + 1 :]
    if np.ndim(code) and common_shape({"the result": rest, "code": np.shape(code)}) != rest:
        raise GearError(f"code has shape {np.shape(code)}; valid is the result's shape {rest} "
                        "(or one code)")  # fmt: skip
    return stress, strength, cycles, code


def cycles_to_failure(ratio, code, mode="pitting"):
    """Cycles to failure N_f at the stress ratio ``sigma / sigma_inf`` on the S-N curve of the
    material group ``code`` (:func:`gears.rating.materials.kind_code`) for ``mode`` (arrays
    broadcast). Below the endurance knot the curve is flat and the life endless: returned as
    ``LIFE_CAP * 3.6e6`` cycles (finite); above the static knot, 1 cycle.

    >>> from gears.rating.materials import kind_code
    >>> round(float(cycles_to_failure(1.0, kind_code("Eh"))))   # Z_NT = 1 at 5 x 10^7
    50000000
    """
    table = _mode_table(mode)
    ratio, code = number("ratio", ratio, 0.0, math.inf), np.asarray(_material_code(code))
    common_shape({"ratio": np.shape(ratio), "code": code.shape})
    z = np.log(ratio)
    knots = _knots(code, table)
    if code.ndim:
        knots = tuple(v[..., 0] for v in knots)
    return np.exp(np.minimum(_log_cycles(z, knots), math.log(LIFE_CAP * 3.6e6)))


def _log_ratio_cycles(stress, strength, cycles, axis):
    """ln(sigma / sigma_inf) and ln N_L with the bins moved to the last axis."""
    z = np.log(np.asarray(stress, float)) - np.log(np.asarray(strength, float))
    with np.errstate(divide="ignore"):
        lc = np.log(np.asarray(cycles, float))
    z, lc = np.broadcast_arrays(z, lc)
    return np.moveaxis(z, axis, -1), np.moveaxis(lc, axis, -1)


def miner_damage(stress, strength, cycles, code, mode="pitting", axis=-1):
    """Miner's sum D = sum N_L,i / N_f,i over the bins on ``axis``: ``stress`` sigma_i,
    ``strength`` sigma_inf,i (the allowable stress over its life factor) in MPa, ``cycles``
    N_L,i (0 ... 10^30), ``code`` the material group (arrays broadcast; an array ``code`` has
    the shape of the result).

    >>> round(float(miner_damage([1000.0], [1000.0], [2.5e7], 4)), 6)   # Eh: half of 5 x 10^7
    0.5
    """
    stress, strength, cycles, code = _checked(stress, strength, cycles, code, mode, axis)
    z, lc = _log_ratio_cycles(stress, strength, cycles, axis)
    return np.sum(np.exp(lc - _log_cycles(z, _knots(code, _mode_table(mode)))), axis=-1)


def equivalent_safety(stress, strength, cycles, code, mode="pitting", axis=-1):
    """The factor S by which every bin's stress may grow until Miner's sum reaches 1: the bound
    between D(S sigma) < 1 and D(S sigma) >= 1 in [1e-4, 1e4] (arrays broadcast, the bins on
    ``axis``, as :func:`miner_damage`'s; an array ``code`` has the shape of the result).

    With x = ln S, each bin's damage is 0 up to its endurance knot, exp(g - a x) on a sloped
    segment of the S-N curve (a the segment's slope d ln N_f / d ln sigma) and N_L above the
    static knot: D(x) is non-decreasing, smooth between the knots of the bins and jumps at
    some. Rounds over the stretches (each solving its D = 1, kept where the bins' states at
    the root are the stretch's: docs/rating.md) or, for the rows they leave, a bisection over
    the bins' knots, sorted (3 per bin), find the stretch where D reaches 1; there
    D = C + A_1 exp(-a_1 x) + A_2 exp(-a_2 x): the answer is the stretch's start where D jumps
    over 1, in closed form where one segment is loaded, and by Newton's method on the convex
    ln D otherwise, from the nearer root of one term alone (D >= 1 there). The search's
    bounds: D(0), and D >= N_L past a static knot.

    >>> round(float(equivalent_safety([1000.0], [1000.0], [5e7], 4)), 9)   # one bin at its knot
    1.0
    """
    stress, strength, cycles, code = _checked(stress, strength, cycles, code, mode, axis)
    return _damage_and_safety(stress, strength, cycles, code, mode, axis)[1]


def _damage_and_safety(stress, strength, cycles, code, mode, axis=-1):
    """Miner's sum and the equivalent safety (:func:`equivalent_safety`) of the same bins."""
    stress, strength, cycles = (np.moveaxis(v, axis, -1) for v in np.broadcast_arrays(
        *(np.asarray(v, float) for v in (stress, strength, cycles))))  # fmt: skip
    shape, bins = stress.shape[:-1], stress.shape[-1]
    stress, strength, cycles = (v.reshape(-1, bins) for v in (stress, strength, cycles))
    n = len(stress)
    knots = tuple(np.broadcast_to(k, (*shape, 1)).reshape(n) if np.ndim(k) else k
                  for k in _knots(code, _mode_table(mode)))  # fmt: skip
    d, s = np.empty(n), np.empty(n)
    step = max(1, _BLOCK // bins)
    with np.errstate(divide="ignore", invalid="ignore"):
        for i in range(0, n, step):
            rows = slice(i, i + step)
            # the bins on the first axis, the rows contiguous on the last (fast broadcasts,
            # sums), written so as the ratio is taken
            m = len(stress[rows])
            z, n_l = np.empty((bins, m)), np.empty((bins, m))
            np.divide(stress[rows].T, strength[rows].T, out=z)
            np.log(z, out=z)  # ln(sigma / sigma_inf)
            np.copyto(n_l, cycles[rows].T)
            d[rows], s[rows] = _solve(z, n_l, tuple(k[rows] if np.ndim(k) else k for k in knots))
    return (d.reshape(shape), s.reshape(shape)) if shape else (d[0], s[0])


def _solve(z, cycles, knots):
    """Miner's sum and the equivalent safety of one block: ``z`` = ln(sigma / sigma_inf) and
    the cycles N_L (bins, rows).

    On a stretch between knots D(x) = C + A_1 exp(b_1 x) + A_2 exp(b_2 x) (b = -a > 0), its
    coefficients summed over the bins by their states. From a start (:meth:`_Lines.start`: at
    or below the answer but for a curve steeper above its knee than below, group 7 in bending)
    each round takes the states at x, solves that stretch's D = 1 (:func:`_regime_root`) and
    moves there, from below or above; a row is settled when the states at the root are the
    ones it was solved with (the root is then D's).
    A row not settled in :data:`_ROUNDS` rounds (D jumps over 1 at a knot, or a root so far
    out that the lines' factors at S = 1 lose it) is solved by :func:`_bisect`."""
    n = z.shape[1]
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        lines = _Lines(z, cycles, knots)
        sums = lines.sums(0.0)
        d0 = sums.sum(axis=0)
        x, bound = lines.start()
        solved = np.zeros(n, bool)
        out = np.full(n, np.nan)
        rows = np.arange(n)
        lo, hi = np.full(n, -np.inf), np.full(n, np.inf)  # D < 1 at lo, D >= 1 at hi
        r_lo, r_hi = np.full(n, np.nan), np.full(n, np.nan)  # their stretches' roots
        for _ in range(_ROUNDS):
            new = lines.sums(x)
            done = solved & (new == sums).all(axis=0)  # the states x was solved with
            out[rows[done]] = x[done]
            if 2 * np.count_nonzero(done) >= done.size:  # the settled rows set aside
                left = ~done
                if not left.any():
                    break
                rows = rows[left]
                lines.keep(left)
                x, bound, new = x[left], bound[left], new[:, left]
                lo, hi, r_lo, r_hi = lo[left], hi[left], r_lo[left], r_hi[left]
            sums = new
            root = _regime_root(sums, lines.b)
            below = np.where(np.isfinite(root), root > x, sums[0] < 1.0)
            up, down = below & (x >= lo), ~below & (x <= hi)
            lo, r_lo = np.where(up, x, lo), np.where(up, root, r_lo)
            hi, r_hi = np.where(down, x, hi), np.where(down, root, r_hi)
            # at the bound D stays below 1 up to it and jumps over 1 there (a bin of N_L >= 1
            # turns static): settled there too
            jumps = (x == bound) & (root > x)
            solved = (np.isfinite(root) & (root <= bound)) | jumps
            x = np.where(solved & ~jumps, root, np.where(root > bound, bound, x))
        # D jumps over 1 at a knot k, the one between lo and hi, where the stretch of lo ends
        # below 1 (its root past k, or none: C < 1) and that of hi starts at 1 or more (its
        # root at or before k, or none: C >= 1); else (the rounds ran out before a root was
        # tried, or no D >= 1 seen) the bisection
        pending = np.flatnonzero(np.isnan(out[rows]))
        if pending.size:
            lo, hi, knot = lo[pending], hi[pending], lines.knots[:, :, pending]
            between = (knot >= lo) & (knot < hi)
            first = np.where(between, knot, np.inf).min(axis=(0, 1))
            last = np.where(between, knot, -np.inf).max(axis=(0, 1))
            one = np.isfinite(first) & (first == last) & np.isfinite(hi)
            one &= ~(r_lo[pending] <= first) & ~(r_hi[pending] > first)
            out[rows[pending[one]]] = first[one]
        out[np.abs(out) * lines.steepest >= 550.0] = np.nan  # far out: exp's range (e^600)
        # and rows the lines' factors cannot hold (N_L over 1e47: an inf factor, a NaN sum)
        rest = np.flatnonzero(np.isnan(out) | ~np.isfinite(d0))
        if rest.size:
            part = tuple(k[rest] if np.ndim(k) else k for k in knots)
            d0[rest], s = _bisect(z[:, rest].copy(), np.log(cycles[:, rest]), part)
            out[rest] = np.log(s)
    return d0, np.exp(np.clip(out, math.log(1e-4), math.log(1e4)))


class _Lines:
    """A block's bins (bins, rows) for :func:`_solve`: ``n`` stacks, for each bin, its cycles
    N_L (its damage were it static) and its damage at S = 1 on the S-N curve's upper and lower
    log-log lines (their exponents at N_L = 1 held in [-600, 600]: exp's normal range); ``b``
    the lines' slopes -a_1, -a_2 in ln D per ln S; buffers for the rounds."""

    def __init__(self, z, cycles, knots):
        y0, y1, y2 = knots[3:]
        a1, a2 = _slopes(knots)
        y = (np.stack(np.broadcast_arrays(y0, y1, y2))[:, None] if np.ndim(y0)
             else np.array([y0, y1, y2])[:, None, None])  # fmt: skip
        a = np.stack(np.broadcast_arrays(a1, a2)) if np.ndim(a1) else np.array([a1, a2])
        self.b = -a
        self.steepest = float(np.max(self.b))
        n = np.empty((3, *z.shape))
        n[0] = cycles
        self.knots = np.subtract(y, z)  # each bin's knots in x = ln S (3, bins, rows)
        h = n[1:]  # ln(1 / N_f) at S = 1 on each line, then N_L / N_f
        _line_at_one(self.knots[1], a[:, None] if a.ndim == 2 else a[:, None, None], knots[1], h)
        np.negative(h, out=h)
        np.clip(h, -600.0, 600.0, out=h)  # times N_L up to 1e47 a normal number
        np.exp(h, out=h)
        h *= n[0]
        self.n = n
        self._buffers()

    def _buffers(self):
        self.mask = np.empty(self.knots.shape, bool)

    def sums(self, x):
        """``(C, A_1, A_2)`` at x (rows): the static bins' cycles and each line's bins' damage
        at S = 1 (a bin at a knot is on the side below, as in :func:`_bisect`)."""
        m = self.mask
        np.greater(x, self.knots, out=m)  # past the static knot, the knee, the endurance
        np.logical_xor(m[1:], m[:-1], out=m[1:])  # on the upper line, on the lower line
        return np.einsum("ijk,ijk->ik", self.n, m)  # one pass: the products summed

    def start(self):
        """Where the rounds start: the larger x at which one line summed over every bin
        reaches 1, below the first static knot of a bin of N_L >= 1 (D >= 1 past it). Where a
        bin's damage is the lower of its lines (a_1 >= a_2) D is at most either sum, and this is
        at or below the answer; else (group 7 in bending) it may lie above, and the rounds come
        down."""
        total = self.n[1:].sum(axis=1)
        b = self.b.reshape(2, -1)
        x = _term_root(0.0, total, b).max(axis=0)
        static = np.where(self.n[0] >= 1.0, self.knots[0], np.inf).min(axis=0)
        return np.minimum(x, static), static

    def keep(self, rows):
        """Only ``rows`` (a mask) from now on."""
        self.n, self.knots = self.n[:, :, rows], self.knots[:, :, rows]
        if self.b.ndim > 1:
            self.b = self.b[:, rows]
        self._buffers()


def _term_root(left, a, b):
    """x where one term alone, ``a`` exp(``b`` x), reaches exp(``left``) (1 - C: the root of
    C + a exp(b x) = 1): (left - ln a) / b."""
    return (left - np.log(a)) / b


def _regime_root(sums, b):
    """x where C + A_1 exp(b_1 x) + A_2 exp(b_2 x) = 1 (``sums`` = (C, A_1, A_2), ``b`` > 0):
    the nearer root of one term alone where one is loaded, else Newton's method on the convex
    ln D from it (D >= 1 there: it comes down monotonically); NaN where C >= 1 or nothing is
    loaded."""
    c, p, q = sums
    b1, b2 = b
    ok = (c < 1.0) & ((p > 0.0) | (q > 0.0))
    c = np.where(ok, c, 0.0)
    left = np.log1p(-c)  # ln(1 - C)
    w = np.minimum(_term_root(left, np.maximum(p, 1e-300), b1),
                   _term_root(left, np.maximum(q, 1e-300), b2))  # fmt: skip
    both = ok & (p > 0.0) & (q > 0.0)
    every = bool(both.all())
    two = slice(None) if every else np.flatnonzero(both)
    if every or two.size:
        c, p, q = c[two], p[two], q[two]
        v = w if every else w[two]
        if np.ndim(b1) and not every:
            b1, b2 = b1[two], b2[two]
        for k in range(60):
            t1 = np.exp(b1 * v)
            t1 *= p
            t2 = np.exp(b2 * v)
            t2 *= q
            d = t1 + t2
            d += c
            t1 *= b1
            t2 *= b2
            t1 += t2
            step = np.log(d)
            step *= d
            step /= t1
            v -= step
            # quadratic: after a step below 1e-9 the error is below 1e-16 (f''/2f' < 100)
            if k >= 3 and not (np.abs(step) > 1e-9 * (1.0 + np.abs(v))).any():
                break
        if not every:
            w[two] = v
    w[~ok] = np.nan
    return w


def _bisect(z, lc, knots):
    """Miner's sum and the equivalent safety of one block, ``z``, ``lc`` (bins, rows), by a
    bisection over the rows' knots, sorted: exact for any bins, the fallback of :func:`_solve`."""
    n = z.shape[1]
    y0, y1, y2 = knots[3:]
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        # each bin's knots in x = ln S: endless up to e2, the knee at e1, static above e0
        e2, e1, e0 = y2 - z, y1 - z, y0 - z
        n_l = np.exp(lc)
        a1, a2 = _slopes(knots)

        damage, log_terms = _damage_at(e2, e1, e0, n_l, lc, knots[1], a1, a2)
        d0 = damage(np.zeros(n))
        # the first stretch (knots[k-1], knots[k]] at whose end D >= 1 (k = 3 bins: beyond the
        # last knot, every bin static)
        sorted_knots = np.concatenate([e2.T, e1.T, e0.T], axis=1, dtype=float)
        sorted_knots = np.ascontiguousarray(sorted_knots)  # the rows' knots side by side
        sorted_knots.sort(axis=1)
        last = sorted_knots.shape[1]
        flat = sorted_knots.ravel()
        offsets = np.arange(n) * last
        # a bound: D >= N_L >= 1 past a bin's static knot (the search needs no static bin of
        # N_L >= 1 then)
        static_at = np.where(n_l >= 1.0, e0, np.inf).min(axis=0)
        lo = np.zeros(n, np.intp)
        hi = (sorted_knots <= static_at[:, None]).sum(axis=1)
        while True:
            searching = lo < hi
            if not searching.any():
                break
            mid = (lo + hi) >> 1
            at = flat[offsets + np.minimum(mid, last - 1)]
            reached = (damage(at, exact=False) >= 1.0) | (mid == last)
            hi = np.where(searching & reached, mid, hi)
            lo = np.where(searching & ~reached, mid + 1, lo)
        end = np.where(hi < last, flat[offsets + np.minimum(hi, last - 1)], np.inf)
        start = np.where(hi > 0, flat[offsets + np.maximum(hi - 1, 0)], -np.inf)
        # on the stretch D = C + A1 exp(-a1 w) + A2 exp(-a2 w), w = x - its end: each bin on
        # its segment there
        ref = np.where(np.isfinite(end), end, 0.0)
        static = end > e0
        sloped = (end > e2) & ~static
        upper = end > e1
        t = np.exp(log_terms(ref))
        c = (n_l * static).sum(axis=0)
        A1 = (t * (sloped & upper)).sum(axis=0)
        A2 = (t * (sloped & ~upper)).sum(axis=0)
        a1, a2 = (np.broadcast_to(a, (n,)) for a in (a1, a2))
        w0 = start - ref
        # D at its start (a line no bin is on adds 0, where its exp overflows too: 0 * inf)
        at_start = c + np.where(A1 > 0.0, A1 * np.exp(-a1 * w0), 0.0)
        at_start += np.where(A2 > 0.0, A2 * np.exp(-a2 * w0), 0.0)
        jumped = at_start >= 1.0
        solve = np.flatnonzero(~jumped & np.isfinite(end))
        w = np.full(n, np.nan)
        if solve.size:  # the stretch's root in w = x - ref (its slopes -a)
            w[solve] = _regime_root(np.stack([c[solve], A1[solve], A2[solve]]),
                                    (-a1[solve], -a2[solve]))  # fmt: skip
        x = np.where(jumped, start, ref + w)
        x = np.where(np.isnan(x), np.inf, x)
    return d0, np.exp(np.clip(x, math.log(1e-4), math.log(1e4)))


def _damage_at(e2, e1, e0, n_l, lc, ln_knee, a1, a2):
    """``(damage, log_terms)``: ``damage(x)`` Miner's sum at x per row, bins on the first axis
    (left-continuous: a bin at one of its knots is on the side below), ``log_terms(x)`` the ln
    of each bin's damage at x were it on its sloped segment (held in [-700, 700]: the masked
    terms stay out of exp's slow underflow and its overflow). ``damage(x, exact=False)`` where
    x lies at or below the static knot of every bin of N_L >= 1 (the search's bound): only a
    bin of less than one cycle can be static there. On its sloped segment a bin's ln damage is
    one of the S-N curve's two log-log lines, written in x through the bin's knee e1 (the
    lower of the two where the curve is steeper below the knee), so that a search step is a
    few passes over buffers kept for it."""
    below = lc - _line_at_one(e1, a2, ln_knee)  # ln damage = below - a2 x below the knee
    above = lc - _line_at_one(e1, a1, ln_knee)  # and above - a1 x above it
    if np.all(np.greater_equal(a1, a2)):
        pick = np.minimum
    elif np.all(np.less_equal(a1, a2)):
        pick = np.maximum
    else:
        pick = None
    terms, other, mask = np.empty(e1.shape), np.empty(e1.shape), np.empty(e1.shape, bool)

    short = bool(np.any(n_l < 1.0))  # a bin of less than one cycle

    def sloped(x, out, spare):
        """ln of each bin's damage at x on its sloped segment, into ``out``."""
        np.subtract(below, a2 * x, out=out)
        np.subtract(above, a1 * x, out=spare)
        if pick is None:
            np.copyto(out, spare, where=np.greater(x, e1))
        else:
            pick(out, spare, out=out)
        # exp's slow underflow kept out, and its overflow: a static bin's line far past its
        # static knot (inf times a False mask would be NaN)
        return np.clip(out, -700.0, 700.0, out=out)

    def damage(x, exact=True):
        np.exp(sloped(x, terms, other), out=terms)
        np.greater(x, e2, out=mask)
        np.multiply(terms, mask, out=terms)
        if not exact and not short:
            return terms.sum(axis=0)  # below every static knot of N_L >= 1 (the search's bound)
        np.greater(x, e0, out=mask)
        if mask.any():  # a static bin: N_L (its line's value replaced, not corrected)
            static = n_l * mask
            np.multiply(terms, np.logical_not(mask, out=mask), out=terms)
            np.add(terms, static, out=terms)
        return terms.sum(axis=0)

    def log_terms(x):
        return sloped(x, np.empty(e1.shape), np.empty(e1.shape))

    return damage, log_terms


def check_spectrum(spectrum: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(torques, speeds, hours)`` as float arrays from a list of bins ``(torque N m, speed rpm,
    hours)`` or three sequences, every value finite and > 0, or a GearError naming the bin."""
    try:
        arr = np.asarray(spectrum, dtype=float)
    except (TypeError, ValueError):
        raise GearError(
            f"spectrum = {spectrum!r:.80}; valid is a list of bins (torque, speed, hours)"
        ) from None
    if arr.ndim != 2 or arr.shape[1] != 3 or not 1 <= arr.shape[0] <= MAX_BINS:
        raise GearError(
            f"spectrum of shape {arr.shape}; valid is a list of 1 ... {MAX_BINS} bins "
            "(torque N m, speed rpm, hours)"
        )
    bad = ~(np.isfinite(arr) & (arr > 0.0))
    if bad.any():
        i, j = (int(k) for k in np.argwhere(bad)[0])
        what = ("torque", "speed", "hours")[j]
        raise GearError(
            f"spectrum bin {i}: {what} = {float(arr[i, j])!r}; valid is a finite number > 0"
        )
    return arr[:, 0].copy(), arr[:, 1].copy(), arr[:, 2].copy()


class SpectrumRatings(NamedTuple):
    """Arrays returned by :func:`rate_spectrum`, one value per pair: Miner's sums ``D_H1, D_H2,
    D_F1, D_F2``, the equivalent safeties ``S_H1 ... S_F2`` and the lives ``L_H1 ... L_F2``
    (hours, :data:`LIFE_CAP` where endless); ``valid`` is False for a pair with no rating at
    some bin (``errors="mask"``: zero safeties and lives, NaN sums)."""

    D_H1: np.ndarray
    D_H2: np.ndarray
    D_F1: np.ndarray
    D_F2: np.ndarray
    S_H1: np.ndarray
    S_H2: np.ndarray
    S_F1: np.ndarray
    S_F2: np.ndarray
    L_H1: np.ndarray
    L_H2: np.ndarray
    L_F1: np.ndarray
    L_F2: np.ndarray
    valid: np.ndarray | bool = True


def _combine(r, code1: int, code2: int, total_hours: float, threads: int = 1) -> SpectrumRatings:
    """Miner's sums, equivalent safeties and lives from the bins' stresses (bins on the last
    axis of every field of the mapping ``r``); the four gears and modes on ``threads``
    threads."""

    def one(job):
        mode, s, p, f, sym, i, code = job
        stress = np.asarray(r[f"{s}{i}"], float)
        strength = np.asarray(r[f"{p}{i}"], float) / np.asarray(r[f"{f}{i}"], float)
        cycles = np.asarray(r[f"N_L{i}"], float)
        d, safety = _damage_and_safety(stress, strength, cycles, code, mode)
        with np.errstate(divide="ignore"):
            life = np.where(d > 0, np.minimum(total_hours / d, LIFE_CAP), LIFE_CAP)
        return {f"D_{sym}{i}": d, f"S_{sym}{i}": safety, f"L_{sym}{i}": life}

    jobs = [(*mode, i, code) for mode in (("pitting", "sigma_H", "sigma_HP", "Z_NT", "H"),
                                          ("bending", "sigma_F", "sigma_FP", "Y_NT", "F"))
            for i, code in ((1, code1), (2, code2))]  # fmt: skip
    out = {}
    if threads > 1 and np.size(r["sigma_H1"]) >= _THREADED:
        for part in _pool(threads).map(one, jobs):
            out |= part
    else:
        for job in jobs:
            out |= one(job)
    return SpectrumRatings(**{k: v[()] if np.ndim(v) == 0 else v for k, v in out.items()})
