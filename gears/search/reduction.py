"""Layer 7, reduction: a chunk's rows reduced to their top-k or Pareto front, and reductions merged.

Ties are broken on the candidate's parameters (a total order), so the answer does not depend on
the chunk size or the scheduler.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from gears.search.candidates import _KEYS, _Space


def _objectives(rows: np.ndarray, objective: Sequence[str]) -> list[np.ndarray]:
    """Objective columns, each to be minimised (a '-' prefix maximises)."""
    return [-rows[o[1:]] if o.startswith("-") else rows[o] for o in objective]


def _order(rows: np.ndarray, objective: Sequence[str]) -> np.ndarray:
    # lexsort: last key first; the parameters (and the face width) break ties: a total order
    params = (*_KEYS, "face_width") if "face_width" in rows.dtype.names else _KEYS
    keys = [rows[k] for k in reversed(params)] + list(reversed(_objectives(rows, objective)))
    return np.lexsort(keys)


#: Objective values within this relative distance tie on the Pareto front: module twins (the same
#: teeth and shifts at another module) have the same sliding and contact ratio up to the last
#: bits (1.4e-15 apart), and one must not dominate the other.
PARETO_TOLERANCE = 1e-9


def _tie(values: np.ndarray) -> np.ndarray:
    """``values`` with each run of neighbours within :data:`PARETO_TOLERANCE` (relative) of
    the previous one replaced by the run's smallest value."""
    order = np.argsort(values, kind="stable")
    v = values[order]
    gap = np.diff(v) > PARETO_TOLERANCE * np.maximum(np.abs(v[:-1]), np.abs(v[1:]))
    gap |= ~np.isfinite(v[1:]) | ~np.isfinite(v[:-1])  # infinities tie only exactly
    start = np.concatenate([[0], np.flatnonzero(gap) + 1])
    runs = np.repeat(start, np.diff(np.concatenate([start, [len(v)]])))
    out = np.empty_like(values)
    out[order] = np.where(np.isfinite(v), v[runs], v)
    return out


def _pareto(rows: np.ndarray, objective: Sequence[str]) -> np.ndarray:
    """The rows no other row dominates (all objectives <=, one <), in objective order.

    Rows with equal objective vectors (equal within :data:`PARETO_TOLERANCE`) stand or fall
    together. Two objectives: one sweep in sorted order (a running minimum); three: each
    distinct vector against the front so far.
    """
    if len(rows) < 2:
        return rows
    rows = rows[_order(rows, objective)]
    obj = np.stack([_tie(np.asarray(o, float)) for o in _objectives(rows, objective)], axis=1)
    vec, inverse = np.unique(obj, axis=0, return_inverse=True)
    inverse = inverse.ravel()
    if vec.shape[1] == 2:  # vec is sorted by (o1, o2): an earlier vector has o1 <=
        prev = np.minimum.accumulate(np.concatenate([[np.inf], vec[:-1, 1]]))
        good = prev > vec[:, 1]
    else:  # sorted by o1, a vector can be dominated only by an earlier one: a 2-D query on
        # (o2, o3) against the staircase of the earlier front, block by block
        good = np.zeros(len(vec), bool)
        st2, st3 = np.empty(0), np.empty(0)  # staircase: o2 rising, o3 falling
        for b0 in range(0, len(vec), 512):
            b2, b3 = vec[b0 : b0 + 512, 1], vec[b0 : b0 + 512, 2]
            j = np.searchsorted(st2, b2, side="right") - 1
            hit = (j >= 0) & (st3[np.maximum(j, 0)] <= b3) if st2.size else np.zeros(b2.size, bool)
            le = (b2[None, :] <= b2[:, None]) & (b3[None, :] <= b3[:, None])
            hit |= np.tril(le, -1).any(axis=1)
            good[b0 : b0 + 512] = ~hit
            c2, c3 = np.concatenate([st2, b2[~hit]]), np.concatenate([st3, b3[~hit]])
            order = np.lexsort((c3, c2))
            c2, c3 = c2[order], c3[order]
            low = np.minimum.accumulate(np.concatenate([[np.inf], c3[:-1]]))
            st2, st3 = c2[c3 < low], c3[c3 < low]
    return rows[good[inverse]]


def _reduce(rows: np.ndarray, space: _Space) -> np.ndarray:
    if space.pareto:
        return _pareto(rows, space.objective)
    rows = rows[_order(rows, space.objective)]
    return rows if space.top is None else rows[: space.top]


def _merge(acc: np.ndarray | None, part: np.ndarray, space: _Space) -> np.ndarray:
    if acc is None:
        return part
    return _reduce(np.concatenate([acc, part]), space)
