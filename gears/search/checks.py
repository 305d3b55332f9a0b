"""Layer 8, checks: one chunk of candidates decoded, checked with the vectorised margins of
:mod:`gears.checks` (the functions ``GearPair.check()`` calls), sized and rated under a load, and
reduced before anything leaves it (:func:`evaluate_chunk`, on a local thread or a Dask worker).
"""

from __future__ import annotations

import itertools

import numpy as np

from gears.checks import (
    equal_sliding_split,
    has_working_angle,
    pair_margins,
    proportional_split,
)
from gears.geometry import min_profile_shift
from gears.meshing import center_distance_shift_sum, mesh_efficiency
from gears.rating.sizing import pair_volume, smallest_width
from gears.rating.sizing import rate as rate_load
from gears.search.candidates import _SAFETY, _SIZE, _dtype, _Space
from gears.search.reduction import _reduce
from gears.search.tables import write_table

__all__ = ["evaluate_chunk"]

#: candidates checked at once inside a chunk on a Dask worker: temporaries of 64 kB stay on
#: the heap (workers set MALLOC_TRIM_THRESHOLD_, which maps and unmaps larger ones per call);
#: local threads take larger blocks (less Python, so less time holding the GIL)
_BLOCK = 8192
_LOCAL_BLOCK = 1 << 15


def evaluate_chunk(
    space: _Space, start: int, stop: int, block: int = _BLOCK
) -> tuple[np.ndarray, int, int]:
    """Check candidates ``start .. stop-1`` of ``space`` and reduce them.

    Returns ``(rows, feasible, checked)``: the chunk's best rows (its top-k, its Pareto set, or
    all its feasible rows when ``top`` is None), the number of feasible candidates and the
    number checked (geometries times face widths). This one function runs on local threads and
    as a Dask task; it checks ``block`` geometries at a time. With ``space.dataset`` (a folder)
    the rows are written there as ``part-<start>.parquet`` and none are returned.
    """
    found = []
    for lo in range(start, stop, block):
        idx = np.arange(lo, min(lo + block, stop), dtype=np.int64)
        ib, i1, i2 = np.unravel_index(idx, space.shape)
        # base rows are ordered module-major, then helix: a block holds a few (m, beta)
        # groups, each checked with scalar m and beta (the helix trigonometry is then scalar)
        mb = space.base[ib, 0] * 1e3 + space.base[ib, 1]
        cuts = np.flatnonzero(mb[1:] != mb[:-1]) + 1
        for a, b in itertools.pairwise([0, *cuts.tolist(), len(idx)]):
            f = _check_group(space, ib[a:b], i1[a:b], i2[a:b])
            if f is not None:
                found.append(f)
    checked = (stop - start) * space.per_geometry
    if not found:
        return np.empty(0, _dtype(space.columns)), 0, checked
    n_ok = sum(n for _, n in found)
    values = {c: np.concatenate([f[c] for f, _ in found]) for c in space.columns}
    pick = _preselect(values, space)
    rows = np.empty(len(pick), _dtype(space.columns))
    for c in space.columns:
        rows[c] = values[c][pick]
    rows = _reduce(rows, space)
    if space.dataset is not None:
        if len(rows):
            write_table(rows, f"{space.dataset}/part-{start:015d}.parquet")
        rows = rows[:0]
    return rows, n_ok, checked


def _check_group(space: _Space, ib, i1, i2) -> tuple[dict[str, np.ndarray], int] | None:
    """The feasible candidates of one (module, helix) group, as columns (only those that can
    reach the top-k when there is one), and how many were feasible."""
    m, beta = (float(v) for v in space.base[ib[0], :2])
    z1, z2 = space.base[ib, 2], space.base[ib, 3]
    x1 = space.x1[i1]
    if space.center_distance is None:
        x2 = space.x2[i2]
    else:
        total = center_distance_shift_sum(z1, z2, m, space.center_distance, space.pressure_angle,
                                          beta, space.internal)  # fmt: skip
        total = np.asarray(total, float)
        if space.split == "proportional":
            x1 = proportional_split(z1, z2, total)
        elif space.split == "equal_sliding":
            x1 = equal_sliding_split(z1, z2, m, total, space.pressure_angle, beta,
                                     space.internal, space.rack.addendum,
                                     space.tip_shortening)  # fmt: skip
        x2 = total - x1  # x1 + x2 = S, a ring's x2 too (DIN 3960)
    lo, hi = space.shift_range
    keep = np.isfinite(x1) & np.isfinite(x2)  # a split may not exist (equal sliding)
    x1, x2 = np.where(keep, x1, 0.0), np.where(keep, x2, 0.0)
    keep &= has_working_angle(z1, z2, x1, x2, space.pressure_angle, beta, space.internal)
    keep &= (x1 >= lo - 1e-12) & (x1 <= hi + 1e-12) & (x2 >= lo - 1e-12) & (x2 <= hi + 1e-12)
    lim = space.limits
    if not lim.allow_undercut:  # cheap first: both gears' undercut finding (x >= x_min)
        depth = space.rack.straight_flank_depth
        pa = space.pressure_angle
        keep &= x1 >= min_profile_shift(z1, pa, beta, depth)
        if not space.internal:
            keep &= x2 >= min_profile_shift(z2, pa, -beta, depth)
    z1, z2, x1, x2 = (v[keep] for v in (z1, z2, x1, x2))
    if not z1.size:
        return None
    with np.errstate(all="ignore"):
        pm = pair_margins(
            z1, z2, m, x1, x2, space.pressure_angle, beta, space.internal, space.rack,
            space.tip_shortening, lim.min_contact_ratio, lim.min_tip_land,
            allow_undercut=lim.allow_undercut, threads=1,
        )  # fmt: skip
    ok = pm.ok(lim.allow_undercut)
    sliding = np.maximum(pm.sliding_1, pm.sliding_2)
    if lim.max_sliding is not None:
        ok &= sliding <= lim.max_sliding
    if not ok.any():
        return None
    f = pm.findings()
    n = len(z1)
    values = {
        "module": np.full(n, m), "helix_angle": np.full(n, beta), "z1": z1, "z2": z2,
        "x1": x1, "x2": x2, "ratio": z2 / z1, "center_distance": pm.center_distance,
        "working_pressure_angle": pm.working_pressure_angle,
        "contact_ratio": pm.contact_ratio, "tip_diameter_1": pm.tip_diameter_1,
        "tip_diameter_2": pm.tip_diameter_2, "sliding_1": pm.sliding_1,
        "sliding_2": pm.sliding_2, "sliding": sliding,
        "efficiency": mesh_efficiency(z1, z2, pm.contact_ratio, space.friction, space.internal),
        "contact_ratio_margin": f["contact_ratio"],
    }  # fmt: skip

    def column(c: str) -> np.ndarray:
        return values[c] if c in values else f[c.replace("g1_", "g1.").replace("g2_", "g2.")]

    if space.widths is not None:  # every feasible geometry over the face widths
        sel = np.flatnonzero(ok)
        cols = {c: np.broadcast_to(column(c), ok.shape)[sel] for c in space.columns
                if c not in _SIZE and c not in _SAFETY}  # fmt: skip
        cols = _size_rows(space, cols, m, beta)
        n_ok = len(cols["z1"])
        if not n_ok:
            return None
        if not space.pareto and space.top is not None and n_ok > space.top:
            o = space.objective[0]
            key = -cols[o[1:]] if o.startswith("-") else cols[o]
            keep = key <= np.partition(key, space.top - 1)[space.top - 1]
            cols = {c: v[keep] for c, v in cols.items()}
        return cols, n_ok
    n_ok = int(ok.sum())
    if not space.pareto and space.top is not None and n_ok > space.top:
        # only rows that can reach the top-k leave the group (ties on the k-th value stay)
        o = space.objective[0]
        key = np.broadcast_to(column(o.removeprefix("-")), ok.shape)
        key = np.where(ok, -key if o.startswith("-") else key, np.inf)
        ok &= key <= np.partition(key, space.top - 1)[space.top - 1]
    return {c: np.broadcast_to(column(c), ok.shape)[ok] for c in space.columns}, n_ok


def _size_rows(space: _Space, cols: dict[str, np.ndarray], m: float, beta: float) -> dict:
    """The geometry-feasible rows ``cols`` of one (module, helix) group over the face widths:
    with a load, rated (:mod:`gears.rating.sizing`) and kept where they meet the minimum safeties
    (only the smallest such width per geometry with ``smallest_width``); then b, volume and
    mass, and with a load the safeties, as columns."""
    widths, load = space.widths, space.load
    geometry = dict(pressure_angle=space.pressure_angle, helix_angle=beta,
                    internal=space.internal, rack=space.rack,
                    tip_shortening=space.tip_shortening)  # fmt: skip
    safety = None
    if load is not None and space.smallest_width:
        index, r = smallest_width(load, widths, cols["z1"], cols["z2"], m, cols["x1"],
                                  cols["x2"], **geometry)  # fmt: skip
        keep = index >= 0
        cols = {c: v[keep] for c, v in cols.items()}
        b = widths[index[keep]]
        safety = {f: np.asarray(getattr(r, f))[keep] for f in _SAFETY[:4]}
    else:
        n, w = len(cols["z1"]), len(widths)
        cols = {c: np.repeat(v, w) for c, v in cols.items()}
        b = np.tile(widths, n)
        if load is not None:
            with np.errstate(all="ignore"):
                r = rate_load(load, cols["z1"], cols["z2"], m, b, cols["x1"], cols["x2"],
                              **geometry)  # fmt: skip
            keep = load.meets(r)
            cols = {c: v[keep] for c, v in cols.items()}
            b = b[keep]
            safety = {f: np.broadcast_to(getattr(r, f), keep.shape)[keep] for f in _SAFETY[:4]}
    volume, mass = pair_volume(cols["z1"], cols["z2"], m, b, beta, space.internal, cols["x2"],
                               space.rack.dedendum, space.density)  # fmt: skip
    cols["face_width"] = b
    cols["volume"] = np.asarray(volume, float)
    cols["mass"] = np.asarray(mass, float)
    if safety is not None:
        cols.update(safety)
        cols["S_H"] = np.minimum(safety["S_H1"], safety["S_H2"])
        cols["S_F"] = np.minimum(safety["S_F1"], safety["S_F2"])
        with np.errstate(all="ignore"):
            cols["mesh_efficiency"] = np.broadcast_to(load.efficiency(
                cols["z1"], cols["z2"], m, b, cols["x1"], cols["x2"], **geometry
            ), b.shape)  # fmt: skip
    return cols


def _preselect(values: dict[str, np.ndarray], space: _Space) -> np.ndarray:
    """Indices that can reach the chunk's top-k: every row not worse than the k-th by the
    first objective (ties kept), so the exact reduction sorts only those."""
    n = len(values["z1"])
    if space.pareto or space.top is None or n <= space.top:
        return np.arange(n)
    o = space.objective[0]
    key = -values[o[1:]] if o.startswith("-") else values[o]
    kth = np.partition(key, space.top - 1)[space.top - 1]
    return np.flatnonzero(key <= kth)
