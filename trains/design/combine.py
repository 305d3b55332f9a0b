"""Layer 6, design: the best gearboxes of a search combined from the best stages, vectorised.

The objectives of :func:`trains.design.gearbox.synthesize_gearbox` are separable (a sum of the
stages' volumes, masses or tooth counts, the largest ring, the product of the efficiencies), so
the best gearboxes of a ratio tuple combine the best stages of each (ratio, place):
:func:`_best_per_key` keeps those, :func:`_combine_task` crosses a chunk of tuples' lists (a
task), scores and reduces them, :func:`_score_order` ranks by the objective and its
tie-breakers.
"""

from __future__ import annotations

from typing import Any

import numpy as np


def _head(objective: str, rated: bool, ring, teeth, vol, mass, eta, mesh_eta) -> list:
    """The leading score keys of an objective (most significant first)."""
    if objective == "mesh_efficiency":
        return [-mesh_eta, vol, ring, teeth]
    if objective == "volume":
        return [vol, ring, teeth]
    if objective == "mass":
        return [mass, vol, ring, teeth]
    if objective == "ring":
        return [ring, vol, teeth] if rated else [ring, teeth]
    if objective == "teeth":
        return [teeth, vol, ring] if rated else [teeth, ring]
    return [-eta, vol, ring, teeth] if rated else [-eta, ring, teeth]


def _best_per_key(t: dict, row_key, feasible, n_keys: int, plan: Any, top: int) -> list:
    """For each key, its feasible rows of the table in objective order, the best ``4 top``
    (the objectives are separable, so the best gearboxes combine only those)."""
    rows = np.flatnonzero(feasible)
    head = _head(plan.objective, plan.rated, t["ring"][rows], t["total"][rows],
                 t["volume"][rows], t["mass"][rows], t["eta"][rows],
                 t["mesh_eta"][rows])  # fmt: skip
    ident = [t[f][rows] for f in ("z1", "z2", "z2p", "z3", "scheme")] + [-t["k"][rows]]
    order = rows[np.lexsort([*reversed([*head, *ident]), row_key[rows]])]
    bounds = np.searchsorted(row_key[order], np.arange(n_keys + 1))
    return [order[bounds[i] : bounds[i + 1]][: 4 * top] for i in range(n_keys)]


def _score_order(t: dict, c: np.ndarray, err: np.ndarray, objective: str, rated: bool):
    """The order of combinations ``c`` (table rows, one column per place) by score: the
    objective, its tie-breakers, the ratio error, then each stage's identity (scheme name,
    teeth, planets), as the unrated search always ranked."""
    head = _head(objective, rated, *_columns(t, c))
    ident = []
    for j in range(c.shape[1]):
        cj = c[:, j]
        ident += [t[f][cj] for f in ("alpha", "z1", "z2", "z2p", "z3", "k", "module")]
    return np.lexsort(list(reversed([*head, err, *ident])))


def _combine_task(shared: tuple, key_tuples: np.ndarray, errors: np.ndarray, objective: str,
                  rated: bool, keep: int) -> tuple[np.ndarray, np.ndarray]:  # fmt: skip
    """The best ``keep`` combinations of a chunk of key tuples (a task; ``key_tuples`` an
    (T, k) array, ``errors`` their ratio errors): each tuple's lists crossed, scored, reduced.
    ``shared`` is ``(table, keys, sizes, flat)``, the same for every chunk: the rows the lists
    name and the lists packed (key ``keys[i]`` owns ``sizes[i]`` rows of ``flat``, positions
    in the table). Returns the combinations' ``row`` ids (an (n, k) array) and their ratio
    errors, in score order."""
    t, keys, sizes, flat = shared
    c, tuple_of = _cross(keys, sizes, flat, key_tuples)
    err = errors[tuple_of]
    if len(c) > 2 * keep:  # only rows that can reach the best `keep` by the first key
        first = _head(objective, rated, *_columns(t, c))[0]
        near = first <= np.partition(first, keep - 1)[keep - 1]
        c, err = c[near], err[near]
    order = _score_order(t, c, err, objective, rated)[:keep]
    return t["row"][c[order]], err[order]


def _cross(keys: np.ndarray, sizes: np.ndarray, flat: np.ndarray,
           key_tuples: np.ndarray) -> tuple[np.ndarray, np.ndarray]:  # fmt: skip
    """Every combination of each key tuple's lists (the rows per place, an (n, k) array), and
    the index of the tuple each came from: all tuples at once, by mixed-radix counting. The
    lists are packed: key ``keys[i]`` (ascending) owns ``sizes[i]`` entries of ``flat``."""
    k = key_tuples.shape[1]
    start = np.cumsum(sizes) - sizes
    at = np.searchsorted(keys, key_tuples)  # (T, k) positions of the keys
    radix, base = sizes[at], start[at]
    count = radix.prod(axis=1)
    tuple_of = np.repeat(np.arange(len(key_tuples)), count)
    local = np.arange(count.sum()) - np.repeat(np.cumsum(count) - count, count)
    out = np.empty((local.size, k), np.int64)
    for j in range(k - 1, -1, -1):  # the last place counts fastest
        r = radix[tuple_of, j]
        out[:, j] = flat[base[tuple_of, j] + local % r]
        local = local // r
    return out, tuple_of


def _columns(t: dict, c: np.ndarray) -> tuple:
    """``(ring, teeth, volume, mass, efficiency, mesh efficiency)`` of combinations ``c``."""
    return (t["ring"][c].max(axis=1), t["total"][c].sum(axis=1), t["volume"][c].sum(axis=1),
            t["mass"][c].sum(axis=1), np.prod(t["eta"][c], axis=1),
            np.prod(t["mesh_eta"][c], axis=1))  # fmt: skip


#: the table columns a combination's score reads (:func:`_columns`, :func:`_score_order`)
_COMBINE_FIELDS = ("row", "ring", "total", "volume", "mass", "eta", "mesh_eta", "alpha", "z1",
                   "z2", "z2p", "z3", "k", "module")  # fmt: skip
