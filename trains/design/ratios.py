"""Layer 6, design: the stage ratios of a gearbox search and the tuples that meet the target.

The distinct exact ratios of a pool of stages (reduced fractions, ascending), the non-decreasing
tuples of them whose product is the target (for k = 2 an integer look-up of ``R b / a`` over all
ratios at once; for k = 3 the first two paired and the third looked up the same way; with a
tolerance a sorted float window preselects and :class:`fractions.Fraction` decides), their places
in the gearbox and their errors (:func:`trains.design.gearbox.synthesize_gearbox`, step 2).
"""

from __future__ import annotations

import bisect
import math
from fractions import Fraction

import numpy as np

from trains.errors import TrainError

#: combinations of stage ratios examined before the search is refused
MAX_LOCAL_PAIRS = 5 * 10**7


def _ratio_ids(pool) -> tuple[_Ratios, np.ndarray]:
    """The distinct stage ratios (ascending, exact) and each stage's index into them.

    Distinct reduced fractions with denominators below 2^26 differ by more than a float64 can
    confuse, so the float order is the exact order."""
    if not len(pool["num"]):
        return _Ratios(np.empty(0, np.int64), np.empty(0, np.int64)), np.empty(0, np.int64)
    num, den = pool["num"], pool["den"]
    width = int(den.max()) + 1
    if int(num.max()) < 2**62 // width:  # one int64 key per ratio: a 1-d unique, 20x faster
        codes, inverse = np.unique(num * width + den, return_inverse=True)
        uniq = np.stack([codes // width, codes % width], axis=1)
    else:
        uniq, inverse = np.unique(np.stack([num, den], axis=1), axis=0, return_inverse=True)
    order = np.argsort(uniq[:, 0] / uniq[:, 1], kind="stable")
    rank = np.empty(len(order), np.int64)
    rank[order] = np.arange(len(order))
    return _Ratios(uniq[order, 0], uniq[order, 1]), rank[np.ravel(inverse)]


class _Ratios:
    """Distinct reduced ratios ``num/den`` in ascending order (int64 arrays); ``ratios[i]``
    is the exact Fraction (made only for the ratios asked for)."""

    def __init__(self, num: np.ndarray, den: np.ndarray):
        self.num, self.den = num, den

    def __len__(self) -> int:
        return len(self.num)

    def __getitem__(self, i: int) -> Fraction:
        return Fraction(int(self.num[i]), int(self.den[i]))

    def __iter__(self):
        return (self[i] for i in range(len(self)))


def _ratio_tuples(ratios: _Ratios, target: Fraction, k: int, tol: float) -> list[tuple]:
    """Non-decreasing tuples of indices into ``ratios`` (ascending) whose product meets the
    target: exactly (the reduced fraction looked up in integers, all first ratios at once) or
    within a tolerance (a float window, then Fractions decide)."""
    n = len(ratios)
    if k > 1 and k * n ** (k - 1) > MAX_LOCAL_PAIRS:
        raise TrainError(
            f"{n} stage ratios give about {n ** (k - 1):,} combinations for {k} stages, over "
            f"the limit of {MAX_LOCAL_PAIRS:,}; lower z_max or use fewer schemes"
        )
    if tol == 0 and k > 1 and n:
        found = _exact_tuples(ratios, target, k)
        if found is not None:
            return found
    ratios = list(ratios)
    find = _Finder(ratios, tol)
    if k == 1:
        return [(i,) for i in find(target, 0)]
    out = []
    limit = target * (1 + Fraction(tol))
    for i, r1 in enumerate(ratios):
        if r1**k > limit:
            break
        if k == 2:
            out += [(i, j) for j in find(target / r1, i)]
            continue
        for j in range(i, n):
            r2 = ratios[j]
            if r1 * r2 * r2 > limit:
                break
            out += [(i, j, m) for m in find(target / (r1 * r2), j)]
    return out


def _exact_tuples(ratios: _Ratios, target: Fraction, k: int) -> list[tuple] | None:
    """:func:`_ratio_tuples` for an exact target in int64 arithmetic: for each first ratio
    (and second, k = 3) the needed last ratio reduced by its gcd and looked up among the
    sorted ``num * K + den`` keys. None when the numbers could overflow (then Fractions)."""
    num, den = ratios.num, ratios.den
    p, q = target.numerator, target.denominator
    top = int(max(num.max(), den.max()))
    if max(p, q) * top ** (2 * (k - 1)) >= 2**62 or top * (top + 1) >= 2**62:
        return None
    width = top + 1
    keys = num * width + den  # ascending ratios are not ascending keys: sort them
    order = np.argsort(keys)
    sorted_keys = keys[order]

    def lookup(need_num, need_den):
        g = np.gcd(need_num, need_den)
        a, b = need_num // g, need_den // g
        inside = (a <= top) & (b <= top)
        key = np.where(inside, a * width + b, -1)
        pos = np.minimum(np.searchsorted(sorted_keys, key), len(keys) - 1)
        hit = inside & (sorted_keys[pos] == key)
        return np.where(hit, order[pos], -1)

    out = []
    idx = np.arange(len(num))
    if k == 2:
        j = lookup(p * den, q * num)
        for i in np.flatnonzero(j >= idx):
            out.append((int(i), int(j[i])))
        return out
    limit = float(target)
    for i in range(len(num)):
        r1 = num[i] / den[i]
        if r1**3 > limit * (1 + 1e-12):
            break
        js = idx[i:]
        js = js[r1 * (num[js] / den[js]) ** 2 <= limit * (1 + 1e-12)]
        if not js.size:
            continue
        m = lookup(p * den[i] * den[js], q * num[i] * num[js])
        for j, last in zip(js[m >= js].tolist(), m[m >= js].tolist(), strict=True):
            out.append((i, j, last))
    return out


class _Finder:
    """Indices of ``ratios`` (ascending) equal to a needed ratio (tol = 0: a dictionary
    look-up) or within the relative tolerance, from index ``low`` on."""

    def __init__(self, ratios: list[Fraction], tol: float):
        self.ratios, self.tol = ratios, tol
        self.index = {r: i for i, r in enumerate(ratios)}
        self.floats = [float(r) for r in ratios]

    def __call__(self, need: Fraction, low: int) -> list[int]:
        if self.tol == 0:
            j = self.index.get(need)
            return [j] if j is not None and j >= low else []
        f, tol = float(need), self.tol
        a = bisect.bisect_left(self.floats, f * (1 - tol) * (1 - 1e-12))
        b = bisect.bisect_right(self.floats, f * (1 + tol) * (1 + 1e-12))
        return [j for j in range(max(a, low), b) if abs(self.ratios[j] / need - 1) <= tol]


def _place_keys(tuples: list[tuple], ratios: _Ratios) -> tuple[list, list[tuple]]:
    """The sizing keys of ratio tuples: each place's ``(ratio index, product of the ratios
    before it)`` (the stage there carries the input torque times that product, a float), the
    distinct keys in ascending order, and each tuple as indices into them. The products are
    exact (reduced integers) so that equal loads share a key."""
    num, den = ratios.num.tolist(), ratios.den.tolist()
    value = {}
    for pre in {t[:j] for t in tuples for j in range(len(t))}:
        p = q = 1
        for r in pre:
            p, q = p * num[r], q * den[r]
        g = math.gcd(p, q)
        value[pre] = (p // g, q // g)
    # ascending products (the float first; (p, q) orders products a float cannot tell apart)
    ordered = sorted(value, key=lambda pre: (value[pre][0] / value[pre][1], value[pre]))
    products: list[tuple[int, int]] = []
    ident = {}
    for pre in ordered:
        if not products or products[-1] != value[pre]:
            products.append(value[pre])
        ident[pre] = len(products) - 1
    places = [tuple((r, ident[t[:j]]) for j, r in enumerate(t)) for t in tuples]
    distinct = sorted({key for pl in places for key in pl})
    index = {key: i for i, key in enumerate(distinct)}
    keys = [(r, products[q][0] / products[q][1]) for r, q in distinct]
    return keys, [tuple(index[key] for key in pl) for pl in places]


def _ratio_errors(key_tuples, tuples, ratios: _Ratios, target: Fraction, tol: float) -> dict:
    """Each tuple's relative ratio error ``abs(prod - target) / target``: 0 for an exact search (its
    tuples meet the target exactly), else from the exact products."""
    if tol == 0:
        return dict.fromkeys(key_tuples, 0.0)
    return {kt: float(abs(math.prod((ratios[r] for r in t), start=Fraction(1)) - target)
                      / target) for kt, t in zip(key_tuples, tuples, strict=True)}  # fmt: skip
