"""Layer 11, consumers: design search over gear pairs, in chunks, on every local core or a Dask
cluster (issue 13).

:func:`pairs` enumerates a candidate space (modules x helix angles x tooth pairs x profile
shifts, or, at a given centre distance, the exact shift sum split by a rule), checks every
candidate with the vectorised margins of :mod:`gears.checks` (the functions
``GearPair.check()`` calls), keeps the feasible ones and returns the best ``top`` by the
objective, or the Pareto front of two or three objectives.

**One code path.** The flat candidate index ``0 .. N-1`` is cut into chunks of ``chunk_size``;
one function (:func:`evaluate_chunk`) decodes a chunk, checks it and reduces it to its own
top-k (or Pareto set) before anything leaves it. The chunks run on a thread pool of the local
cores (numpy releases the GIL, as in :func:`gears.meshing.pair_geometry`) or, with
``client=`` (a ``dask.distributed.Client``, its address, or the active client), as Dask tasks;
the reductions are merged as they arrive, so memory never grows with N. Ties are broken on the
candidate's parameters, so the answer does not depend on the chunk size or the scheduler.

See ``docs/search.md``.
"""

from __future__ import annotations

import contextlib
import itertools
import math
import os
import sys
import threading
import time
from collections.abc import Callable, Sequence
from concurrent.futures import FIRST_COMPLETED, CancelledError, ThreadPoolExecutor, wait
from dataclasses import dataclass, field

import numpy as np

from gears.checks import (
    equal_sliding_split,
    has_working_angle,
    pair_margins,
    proportional_split,
)
from gears.display import html_table
from gears.errors import GearError
from gears.files import check_output, writing
from gears.geometry import check_real, min_profile_shift, transverse_pressure_angle
from gears.meshing import center_distance_shift_sum, default_threads, mesh_efficiency
from gears.rack import BasicRack
from gears.rating.sizing import Load, load_case, pair_volume, smallest_width
from gears.rating.sizing import rate as rate_load
from gears.report import format_duration

__all__ = [
    "Estimate",
    "Limits",
    "SearchResult",
    "check_table_output",
    "dask_client",
    "dask_results",
    "estimate",
    "evaluate_chunk",
    "in_kept_heap",
    "kept_heap",
    "pairs",
    "write_table",
]

#: candidates per second per local thread assumed by the size check (measured 1.2e6 on one
#: shared core, docs/performance.md)
LOCAL_RATE = 1.0e6
#: rated candidates (pair and face width) per second per local thread assumed by the size check
#: when a torque is given (measured 2-5 x 10^5 on one shared core, docs/performance.md)
RATED_RATE = 1.5e5
#: default limit on the estimated time of a local search, seconds
MAX_SECONDS = 600.0

#: candidates checked at once inside a chunk on a Dask worker: temporaries of 64 kB stay on
#: the heap (workers set MALLOC_TRIM_THRESHOLD_, which maps and unmaps larger ones per call);
#: local threads take larger blocks (less Python, so less time holding the GIL)
_BLOCK = 8192
_LOCAL_BLOCK = 1 << 15

_KEYS = ("module", "helix_angle", "z1", "z2", "x1", "x2")
#: rows a notebook shows of a search result (its text form has them all)
_HTML_ROWS = 50
_GEOMETRY = (
    "ratio", "center_distance", "working_pressure_angle", "contact_ratio", "tip_diameter_1",
    "tip_diameter_2", "sliding_1", "sliding_2", "sliding", "efficiency",
)  # fmt: skip
_MARGINS = (
    "g1_undercut", "g1_tip_above_base", "g1_pointed_tip", "g1_tooth_height", "g2_undercut",
    "g2_tip_above_base", "g2_pointed_tip", "g2_tooth_height", "contact_ratio_margin",
    "tip_interference", "tip_interference_2",
)  # fmt: skip
_INTERNAL = (
    "involute_interference", "trochoid_interference", "radial_interference",
    "ring_tip_above_base",
)  # fmt: skip
_SPLITS = ("proportional", "equal_sliding", "keep")
#: columns of a search with a face width (and a load): b, the gears' volume (mm^3) and mass (kg)
_SIZE = ("face_width", "volume", "mass")
#: and with a torque: each gear's safety against pitting and bending, and the smaller of each
_SAFETY = ("S_H1", "S_H2", "S_F1", "S_F2", "S_H", "S_F")


@dataclass(frozen=True)
class Limits:
    """What a feasible pair must meet (the parameters of ``GearPair.check()`` and more).

    Attributes
    ----------
    min_contact_ratio : float
        Transverse contact ratio at least this (``GearPair.check``'s default 1.1).
    min_tip_land : float
        Normal tip land at least this many modules (0.2).
    allow_undercut : bool
        Accept undercut gears (their ``undercut`` findings are then not required).
    max_sliding : float or None
        Largest specific sliding of either flank at most this.
    """

    min_contact_ratio: float = 1.1
    min_tip_land: float = 0.2
    allow_undercut: bool = False
    max_sliding: float | None = None

    def __post_init__(self) -> None:
        check_real("min_contact_ratio", self.min_contact_ratio, 0.0, low_open=False)
        check_real("min_tip_land", self.min_tip_land, 0.0, low_open=False)
        if self.max_sliding is not None:
            check_real("max_sliding", self.max_sliding, 0.0)


@dataclass(frozen=True)
class _Space:
    """The candidate space, small and picklable (a Dask task carries it)."""

    base: np.ndarray  # (n, 4): module, helix angle, z1, z2
    x1: np.ndarray
    x2: np.ndarray
    center_distance: float | None
    split: str
    pressure_angle: float
    rack: BasicRack
    internal: bool
    tip_shortening: bool
    limits: Limits
    objective: tuple[str, ...]
    top: int | None
    friction: float = 0.1
    shift_range: tuple[float, float] = (-math.inf, math.inf)
    columns: tuple[str, ...] = field(default=())
    widths: np.ndarray | None = None  # face widths (mm), ascending; None: no sizing
    load: Load | None = None
    smallest_width: bool = True
    density: tuple[float, float] = (7.83e-6, 7.83e-6)
    dataset: str | None = None  # a folder: each chunk writes its rows there (top=None)

    @property
    def shape(self) -> tuple[int, int, int]:
        return (len(self.base), len(self.x1), len(self.x2))

    @property
    def size(self) -> int:
        """Geometries: the flat index the chunks cut."""
        return math.prod(self.shape)

    @property
    def per_geometry(self) -> int:
        """Candidates per geometry: its face widths (1 without)."""
        return 1 if self.widths is None else len(self.widths)

    @property
    def candidates(self) -> int:
        return self.size * self.per_geometry

    @property
    def pareto(self) -> bool:
        return len(self.objective) > 1


def _dtype(columns: Sequence[str]) -> np.dtype:
    return np.dtype([(c, np.int64 if c in ("z1", "z2") else np.float64) for c in columns])


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
        x2 = total + x1 if space.internal else total - x1
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


class SearchResult:
    """The ranked (or Pareto) pairs of a search: a numpy structured array with named columns.

    ``result.table`` is the array (``result["z1"]``, ``len(result)``, iteration work on it);
    ``result.pair(i)`` builds row ``i`` as a :class:`gears.GearPair`; ``to_pandas()`` and
    ``to_parquet(path)`` export it.

    Attributes
    ----------
    examined : int
        Candidates checked.
    feasible : int
        Candidates that met every limit.
    chunks : int
    seconds : float
        Wall time of the search.
    """

    def __init__(self, table, examined, feasible, chunks, seconds, space: _Space):
        self.table = table
        self.examined = int(examined)
        self.feasible = int(feasible)
        self.chunks = int(chunks)
        self.seconds = float(seconds)
        self._space = space

    @property
    def columns(self) -> tuple[str, ...]:
        return tuple(self.table.dtype.names)

    def __len__(self) -> int:
        return len(self.table)

    def __getitem__(self, key):
        return self.table[key]

    def __iter__(self):
        return iter(self.table)

    @property
    def rate(self) -> float:
        """Candidates checked per second."""
        return self.examined / self.seconds if self.seconds > 0 else math.inf

    @property
    def dataset(self) -> str | None:
        """The folder the rows were written to (``dataset=``), else None."""
        return self._space.dataset

    def pair(self, i: int = 0):
        """Row ``i`` as a :class:`gears.GearPair` (its ``check()`` gives the same margins; with
        a face width, both gears carry it)."""
        from gears.gear import Gear
        from gears.pair import GearPair

        r = self.table[i]
        sp = self._space
        beta = float(r["helix_angle"])
        common = {"module": float(r["module"]), "pressure_angle": sp.pressure_angle,
                  "rack": sp.rack}  # fmt: skip
        if "face_width" in self.columns:
            common["face_width"] = float(r["face_width"])
        g1 = Gear(int(r["z1"]), profile_shift=float(r["x1"]), helix_angle=beta, **common)
        g2 = Gear(int(r["z2"]), profile_shift=float(r["x2"]), internal=sp.internal,
                  helix_angle=beta if sp.internal else -beta, **common)  # fmt: skip
        return GearPair(g1, g2, sp.tip_shortening)

    def rating(self, i: int = 0):
        """Row ``i`` rated on its own: ``pair(i).rating(...)`` under the search's load case
        (torque, speed, materials, life, options, the row's face width, ``root="standard"``,
        the route the search rates by): the same safeties as the row's ``S_H1 ... S_F2``."""
        load = self._space.load
        if load is None:
            raise GearError("this search had no torque=: rate a row with "
                            "result.pair(i).rating(torque, speed, ...)")  # fmt: skip
        return self.pair(i).rating(load.torque, load.speed, load.materials,
                                   **load.rating_options())  # fmt: skip

    def to_pandas(self):
        """The table as a ``pandas.DataFrame`` (needs pandas: ``pip install pandas``)."""
        try:
            import pandas as pd
        except ImportError:
            raise GearError("to_pandas needs pandas: pip install pandas") from None
        return pd.DataFrame.from_records(self.table)

    def to_parquet(self, path) -> None:
        """Write the table to a ``.parquet`` file (needs pyarrow: the ``parquet`` extra)."""
        write_table(self.table, path, ".parquet")

    def format(self, columns: Sequence[str] | None = None) -> str:
        """A ranked text table (default: the parameters, a, eps, sliding, efficiency; with a
        face width b and the volume, with a load the smaller safeties S_H and S_F)."""
        head, body = self._cells(columns)
        widths = [max(len(x) for x in col) for col in zip(head, *body, strict=False)]
        lines = ["  ".join(h.rjust(w) for h, w in zip(row, widths, strict=True))
                 for row in [head, *body]]  # fmt: skip
        return "\n".join(lines)

    def _cells(self, columns: Sequence[str] | None = None, rows: int | None = None):
        """Header and body cells (text) of the first ``rows`` ranked rows."""
        if not columns:
            columns = (*_KEYS, "center_distance", "contact_ratio", "sliding", "efficiency")
            if "face_width" in self.columns:
                columns = (*_KEYS, "face_width", "center_distance", "contact_ratio", "volume")
            if "S_H" in self.columns:
                columns = (*columns, "S_H", "S_F")
        body = []
        for i, r in enumerate(self.table[:rows], 1):
            cells = [str(i)]
            for c in columns:
                v = r[c]
                cells.append(str(int(v)) if c in ("z1", "z2") else f"{float(v):.6g}")
            body.append(cells)
        return ["#", *columns], body

    def _repr_html_(self) -> str:
        """The ranked table in HTML (the first 50 rows), what a notebook shows."""
        head, body = self._cells(rows=_HTML_ROWS)
        more = len(self) - len(body)
        caption = self._summary() + (f"; the first {len(body)} shown" if more > 0 else "")
        return html_table(head, body, caption=caption)

    def _summary(self) -> str:
        if self.dataset is not None:
            return (f"{self.feasible} feasible pairs among {self.examined} candidates "
                    f"({self.seconds:.3g} s), every one written to {self.dataset}")  # fmt: skip
        return (f"{len(self)} pairs of {self.feasible} feasible among {self.examined} candidates "
                f"({self.seconds:.3g} s)")  # fmt: skip

    def __str__(self) -> str:
        if self.dataset is not None:
            return self._summary()
        return f"{self._summary()}\n" + self.format()

    def __repr__(self) -> str:
        return (f"SearchResult({len(self)} rows, examined={self.examined}, "
                f"feasible={self.feasible})")  # fmt: skip


TABLE_FORMATS = (".parquet", ".csv")


def check_table_output(path, suffix: str | None = None):
    """``path`` checked for :func:`write_table` before any work: a writable file name with a
    suffix of :data:`TABLE_FORMATS` (or ``suffix``) and, for Parquet, pyarrow importable
    (the ``parquet`` extra); a GearError saying which otherwise."""
    path = check_output(path, (suffix,) if suffix else TABLE_FORMATS)
    if (suffix or path.suffix).lower() == ".parquet":
        try:
            import pyarrow.parquet  # noqa: F401
        except ImportError:
            raise GearError(
                f"path {str(path)!r}: writing Parquet needs pyarrow: pip install "
                "'geartrain[parquet]' (or write .csv)"
            ) from None
    return path


def write_table(table: np.ndarray, path, suffix: str | None = None) -> None:
    """Write a structured array to ``path``: Parquet (``.parquet``, needs pyarrow, the
    ``parquet`` extra) or CSV (``.csv``, a header line of column names); the format follows
    the suffix. The path is checked first (:func:`check_table_output`)."""
    path = check_table_output(path, suffix)
    if (suffix or path.suffix).lower() == ".csv":
        import csv

        with writing(path), path.open("w", newline="") as f:
            out = csv.writer(f)
            out.writerow(table.dtype.names)
            out.writerows(row.tolist() if hasattr(row, "tolist") else row for row in table)
        return
    import pyarrow as pa
    import pyarrow.parquet as pq

    with writing(path):
        pq.write_table(pa.table({c: table[c] for c in table.dtype.names}), str(path))


# --- input -------------------------------------------------------------------------------------


def _values(name: str, value, low=None, high=None) -> np.ndarray:
    """A scalar or a sequence of finite reals, validated."""
    items = np.atleast_1d(np.asarray(value, dtype=object)).ravel().tolist()
    if not items:
        raise GearError(f"{name} is empty; give at least one value")
    return np.array([check_real(name, v, low, high) for v in items], float)


def _grid(name: str, value) -> np.ndarray:
    """Profile shifts: a number, a sequence, or ``(low, high, step)``."""
    if isinstance(value, tuple) and len(value) == 3:
        lo, hi, step = (check_real(name, v) for v in value)
        if step <= 0 or hi < lo:
            raise GearError(f"{name} = {value}; valid is (low, high, step) with high >= low, "
                            "step > 0")  # fmt: skip
        n = math.floor((hi - lo) / step + 1e-9) + 1
        return np.round(lo + step * np.arange(n), 12)
    return _values(name, value)


def _teeth(value) -> np.ndarray:
    if isinstance(value, tuple) and len(value) == 2 and all(np.ndim(v) == 0 for v in value):
        lo, hi = value
        for v in (lo, hi):
            if isinstance(v, bool) or not isinstance(v, int | np.integer) or v < 1:
                raise GearError(f"teeth = {value}; valid is (z_min, z_max), integers >= 1")
        if hi < lo:
            raise GearError(f"teeth = {value}; valid is z_min <= z_max")
        return np.arange(lo, hi + 1)
    z = np.atleast_1d(np.asarray(value))
    if z.size == 0 or z.dtype.kind not in "iu" or np.any(z < 1):
        raise GearError(f"teeth = {value!r}; valid is (z_min, z_max) or integers >= 1")
    return np.unique(z)


def _objective(objective, columns: Sequence[str]) -> tuple[str, ...]:
    if isinstance(objective, str):
        obj = (objective,)
    elif isinstance(objective, list | tuple):
        obj = tuple(objective)
    else:
        raise GearError(f"objective = {objective!r}; valid is a column name or 2-3 of them")
    names = set(columns)
    if not 1 <= len(obj) <= 3 or not all(isinstance(o, str) for o in obj):
        raise GearError(f"objective = {objective!r}; valid is a column name or 2-3 of them")
    for o in obj:
        name = o.removeprefix("-")
        if name in names:
            continue
        if name in _SIZE:
            raise GearError(f"objective {o!r} needs face_width= (mm): the gears' size")
        if name in _SAFETY:
            raise GearError(f"objective {o!r} needs torque= and speed=: the candidates rated")
        raise GearError(
            f"objective {o!r} is not a column; valid are {sorted(names)} ('-' maximises)"
        )
    return obj


def dask_timeout(timeout=None) -> float:
    """Seconds to wait for a Dask scheduler to answer, and for a worker when a cluster has none:
    ``timeout`` (a finite number > 0), or Dask's own setting
    ``distributed.comm.timeouts.connect`` (``dask.config.set(...)``; the CLI's
    ``--connect-timeout`` sets it)."""
    if timeout is None:
        import dask
        from dask.utils import parse_timedelta

        timeout = parse_timedelta(dask.config.get("distributed.comm.timeouts.connect"), "s")
    return check_real("distributed.comm.timeouts.connect", timeout, 0.0)


def _check_scheduler(address: str, seconds: float) -> None:
    """A GearError unless a Dask scheduler answers at ``address`` within ``seconds``: an unknown
    scheme, nothing listening, and a port where something else listens (an HTTP server, which
    would keep a Dask client waiting for ever) are told apart."""
    import asyncio

    from distributed.comm import connect
    from distributed.comm.addressing import parse_address
    from distributed.comm.registry import get_backend

    try:
        get_backend(parse_address(address)[0])
    except (ValueError, TypeError) as exc:
        raise GearError(
            f"Dask scheduler address {address!r}: {exc}; an address reads tcp://host:8786"
        ) from None

    async def identity():
        comm = await connect(address, timeout=seconds)
        try:
            await comm.write({"op": "identity"})
            return await comm.read()
        finally:
            comm.abort()

    def ask():  # in a thread of its own, so that it also runs under a live event loop (Jupyter)
        return asyncio.run(asyncio.wait_for(identity(), seconds))

    wait = f"within {seconds:g} s (distributed.comm.timeouts.connect)"
    with ThreadPoolExecutor(1, thread_name_prefix="gears.dask_probe") as pool:
        try:
            reply = pool.submit(ask).result()
        except TimeoutError:  # asyncio's is the same class
            raise GearError(
                f"no Dask scheduler answered at {address!r} {wait}: nothing listens there, or "
                "something that is not a Dask scheduler does; check the address and the port"
            ) from None
        except OSError as exc:
            raise GearError(
                f"no Dask scheduler answered at {address!r} {wait}: {exc}; check the address "
                "and that the scheduler runs"
            ) from None
        except Exception as exc:  # a reply that is no Dask message
            raise GearError(
                f"{address!r} answered, but not as a Dask scheduler ({type(exc).__name__}); "
                "check the port (a scheduler listens on 8786 by default, its dashboard on 8787)"
            ) from None
    if not (isinstance(reply, dict) and reply.get("type") == "Scheduler"):
        kind = reply.get("type") if isinstance(reply, dict) else type(reply).__name__
        raise GearError(f"{address!r} answered as a {kind}, not as a Dask scheduler")


def dask_client(client, timeout: float | None = None):
    """The Dask client to use: the given one, one at this address, the active one, or None
    (``client=False``: local threads even with an active client).

    An address is asked first, within ``timeout`` seconds (default: Dask's
    ``distributed.comm.timeouts.connect``, see :func:`dask_timeout`): an unknown scheme
    (``foo://``), an address where nothing listens or where something else than a Dask
    scheduler answers (an HTTP server) is a GearError saying which, never a hang.
    """
    if client is False:
        return None
    if isinstance(client, str):
        try:
            from distributed import Client
        except ImportError:
            raise GearError("client='address' needs dask: pip install 'geartrain[scale]'") from None
        seconds = dask_timeout(timeout)
        _check_scheduler(client, seconds)
        try:
            return Client(client, timeout=seconds)
        except (OSError, TimeoutError) as exc:
            raise GearError(
                f"the Dask scheduler at {client!r} did not take a client: {exc}"
            ) from None
    if client is not None:
        if not hasattr(client, "submit"):
            raise GearError(f"client must be a dask.distributed.Client or an address; "
                            f"got {client!r}")  # fmt: skip
        return client
    if "distributed" in sys.modules:  # an active client implies distributed is imported
        try:
            from distributed import get_client

            return get_client()
        except (ValueError, ImportError):
            return None
    return None


_HEAP = {"lock": None, "active": 0}


@contextlib.contextmanager
def kept_heap():
    """Keep freed memory in this process's heap while the block runs, then give it back.

    Dask's nannies start workers with ``MALLOC_TRIM_THRESHOLD_=65536``: glibc then returns each
    free block over 64 kB to the system at once and maps each allocation over 128 kB afresh, so
    every numpy temporary of a chunk costs page faults (a gearbox sizing chunk ran 1.6-3x
    slower on a worker than in the client, docs/performance.md). Inside, the thresholds are
    raised (``mallopt``: trim 1 GiB, mmap 32 MiB); when the last such block of the process ends
    they are set back to the environment's values and the heap is trimmed (``malloc_trim``),
    so between tasks the worker's memory is as it asked. Does nothing without that setting or
    where the C library is not glibc.
    """
    trim = os.environ.get("MALLOC_TRIM_THRESHOLD_")
    libc = _glibc() if trim is not None else None
    if libc is None:
        yield
        return
    if _HEAP["lock"] is None:
        _HEAP["lock"] = threading.Lock()
    with _HEAP["lock"]:
        if _HEAP["active"] == 0:
            libc.mallopt(_M_TRIM_THRESHOLD, 1 << 30)
            libc.mallopt(_M_MMAP_THRESHOLD, 1 << 25)
        _HEAP["active"] += 1
    try:
        yield
    finally:
        with _HEAP["lock"]:
            _HEAP["active"] -= 1
            if _HEAP["active"] == 0:
                libc.mallopt(_M_TRIM_THRESHOLD, int(trim))
                mmap = os.environ.get("MALLOC_MMAP_THRESHOLD_", str(128 * 1024))
                libc.mallopt(_M_MMAP_THRESHOLD, int(mmap))
                libc.malloc_trim(0)


_M_TRIM_THRESHOLD, _M_MMAP_THRESHOLD = -1, -3  # glibc's mallopt parameters


def _glibc():
    """The C library when it is glibc (it has mallopt and malloc_trim), else None."""
    import ctypes
    import ctypes.util

    if not sys.platform.startswith("linux"):
        return None
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
        libc.mallopt  # noqa: B018 - glibc has both
        libc.malloc_trim  # noqa: B018
    except (OSError, AttributeError):
        return None
    return libc


def in_kept_heap(fn: Callable, *args):
    """``fn(*args)`` inside :func:`kept_heap` (a Dask task that runs numpy on large blocks)."""
    with kept_heap():
        return fn(*args)


def dask_results(client, pending: set, timeout: float | None = None):
    """``(future, result)`` of each future of ``pending`` as it finishes; the caller may add
    futures to ``pending`` meanwhile.

    A cluster that fails under the work is a GearError saying what happened, not a Dask
    traceback: a worker lost with its task or with data the work needs (``KilledWorker``, a
    cancelled future), a lost connection to the scheduler, or a cluster left without workers
    for ``timeout`` seconds (default :func:`dask_timeout`). An error raised by the task itself
    reaches the caller unchanged.
    """
    from distributed import wait
    from distributed.scheduler import KilledWorker

    seconds = dask_timeout(timeout)
    lost = (CancelledError, KilledWorker, OSError)
    idle_since = None
    while pending:
        try:
            with client.as_current():  # wait() asks for the current client: this one, even
                done, _ = wait(  # when it is not the default (set_as_default=False)
                    list(pending), timeout=min(seconds, 1.0), return_when="FIRST_COMPLETED"
                )
        except TimeoutError:
            if _workers(client):
                idle_since = None
            elif idle_since is None:
                idle_since = time.monotonic()
            elif time.monotonic() - idle_since > seconds:
                raise GearError(
                    f"the Dask cluster has had no worker for {seconds:g} s "
                    "(distributed.comm.timeouts.connect) with work left: its workers died or "
                    "left; start workers, or run without client= (local threads)"
                ) from None
            continue
        except lost as exc:
            raise _lost_work(exc) from None
        done = list(done)
        pending.difference_update(done)
        try:  # every finished result in one round trip (one per future cost 5-10 ms each)
            results = client.gather(done)
        except lost as exc:
            raise _lost_work(exc) from None
        yield from zip(done, results, strict=True)


def _lost_work(exc: BaseException) -> GearError:
    return GearError(
        f"the Dask cluster lost work mid-run ({type(exc).__name__}): a worker died or left "
        "with tasks or data the work needs, or the scheduler went away; check the cluster and "
        "run again"
    )


def _workers(client) -> int:
    """Workers the scheduler knows of now (0 when it cannot be asked)."""
    try:
        return len(client.nthreads())
    except (OSError, TimeoutError, CancelledError):
        return 0


def progress_callback(
    progress, desc: str = "pair search", unit: str = "candidate"
) -> Callable[..., None] | None:
    """``progress`` as a callback ``(done, total)`` or None: a user's callable is returned as
    it is; None shows a tqdm bar on a terminal (the units done, their rate per second and the
    time left) and nothing otherwise; True always; False nothing."""
    if progress is False:
        return None
    if callable(progress):
        return lambda done, total: progress(done, total)
    if progress is None and not sys.stderr.isatty():
        return None
    if progress not in (None, True):
        raise GearError(f"progress = {progress!r}; valid are None, True, False or a callable")
    from tqdm import tqdm

    state = {}

    def update(done: int, total: int) -> None:
        if "bar" not in state:
            state["bar"] = tqdm(total=total, desc=desc, unit=unit, unit_scale=True, leave=False,
                                file=sys.stderr)  # fmt: skip
        bar = state["bar"]
        bar.total = total
        bar.update(done - bar.n)  # update(), not n =: tqdm's rate and time left follow it
        bar.refresh()
        if done >= total:
            bar.close()

    return update


def _announce_dashboard(client, progress) -> None:
    """Print the Dask dashboard's address on stderr above the progress bar (when the bar is
    shown and the cluster has a dashboard)."""
    if callable(progress):
        return
    link = getattr(client, "dashboard_link", None)
    if link:
        print(f"Dask dashboard: {link}", file=sys.stderr)


# --- the search ----------------------------------------------------------------------------------


def pairs(
    ratio=None, center_distance=None, module=1.0, teeth=(12, 60), shifts=(-0.5, 1.0, 0.1),
    helix=0.0, *, ratio_tolerance=0.01, split="proportional", pressure_angle=None, rack=None,
    internal=False, tip_shortening=True, limits=None, objective=None, top=20,
    friction=0.1, torque=None, speed=None, material="case-carburized", face_width=None,
    life=20000.0, min_safety=None, smallest_width=True, dataset=None, chunk_size=1 << 16,
    client=None, threads=None, progress=None, max_seconds=MAX_SECONDS, **rating_options,
) -> SearchResult:  # fmt: skip
    """Search gear pairs: every feasible candidate is checked as ``GearPair.check()`` does.

    Parameters
    ----------
    ratio : float or None
        Target gear ratio z2/z1; tooth pairs within ``ratio_tolerance`` (relative) are tried.
    center_distance : float or None
        None: x1 and x2 both run over ``shifts``. A number (mm): the shift sum that gives this
        centre distance is solved exactly per tooth pair and split by ``split``, the rules of
        ``GearPair.at_center_distance`` (``"proportional"``: the DIN 3992 style rule;
        ``"equal_sliding"``: equal largest specific sliding of both flanks; ``"keep"``: x1
        runs over ``shifts``, x2 takes the rest); both shifts must lie within the range of
        ``shifts``.
    module, helix : float or sequence
        Normal modules (mm) and helix angles of gear 1 (degrees) to try.
    teeth : (z_min, z_max) or sequence of int
        Tooth counts for both gears (gear 2 a ring with ``internal=True``).
    shifts : float, sequence or (low, high, step)
        Profile-shift coefficients to try.
    limits : Limits or dict
        Contact ratio, tip land, undercut and sliding limits (:class:`Limits`).
    objective : str or sequence of 2-3 str
        A column to minimise (``"-contact_ratio"`` maximises): the best ``top`` rows are
        returned. Two or three columns: the whole Pareto front (at most ``top`` of it, in
        order of the first objective, when ``top`` is given). Default ``"sliding"``, or
        ``"volume"`` with a face width. With a face width also ``"volume"`` (both gears'
        material, mm^3: :func:`gears.rating.sizing.pair_volume`) and ``"mass"`` (kg), with a torque
        ``"-S_H"`` and ``"-S_F"`` (the smaller safety of the two gears, maximised).
    top : int or None
        Rows returned; None returns every feasible row (use ``to_parquet`` for large results,
        or ``dataset=``).
    torque, speed : float, optional
        Rate every candidate by ISO 6336 method B (:func:`gears.rating.iso6336.rate_pairs`, the
        function ``GearPair.rating`` calls) with this torque on gear 1 (N m) at this speed
        (rpm), and keep only those that meet ``min_safety``. The result gains the columns
        ``S_H1, S_H2, S_F1, S_F2`` (each gear's safety against pitting and bending) and
        ``S_H``, ``S_F`` (the smaller of each); ``result.rating(i)`` rates row i on its own.
    material : name, Material or pair
        ISO 6336-5 material of both gears or ``(gear 1, gear 2)`` (also the density of
        ``"mass"``).
    face_width : float, sequence or (low, high, step), optional
        Face widths b to try, mm: each candidate pair is taken at each (a column
        ``face_width``, with ``volume`` and ``mass``).
    life : float
        Required life, hours.
    min_safety : dict, optional
        ``{"pitting": S_Hmin, "bending": S_Fmin}``, default ``{"pitting": 1.0, "bending":
        1.4}`` (a key left out keeps its default).
    smallest_width : bool
        With a torque: keep for each pair only the smallest face width of the set that meets
        the safeties (the pair sized from the load); False keeps every width that meets them
        as a candidate of its own (a Pareto front of volume against safety needs them).
    dataset : str or path, optional
        With ``top=None``: a folder in which each chunk writes its feasible rows as
        ``part-<first index>.parquet``, where it runs (on a Dask worker or a local thread), so
        no row passes through this process; the result's table is then empty and
        ``result.dataset`` names the folder (read it with ``pyarrow.dataset`` or
        ``pandas.read_parquet``). On a cluster the folder must be one the workers can write.
    chunk_size : int
        Candidates per chunk (the answer does not depend on it).
    client : dask.distributed.Client, str, None or False
        Run the chunks as Dask tasks on this client (or at this scheduler address). None uses
        the active client if there is one, else the local threads; False forces local.
    threads : int or None
        Local threads (default: :func:`gears.meshing.default_threads`).
    progress : None, bool or callable
        A tqdm bar with the candidates done, their rate and the time left (None: when stderr is
        a terminal; True: always; on a cluster the Dask dashboard's address is printed above
        it), False for none, or a callback ``progress(candidates_done, candidates)`` called
        after each chunk.
    max_seconds : float
        A local search estimated to take longer is refused before any work (pass
        ``client=``, narrow the space or raise the limit); :func:`estimate` tells the time
        before running.
    **rating_options
        Any other option of ``GearPair.rating`` (``quality``, ``application_factor``,
        ``oil_viscosity``, ``sigma_Hlim``, ... and factors by their ISO symbols, ``K_v=1.0``),
        with a torque (:func:`gears.rating.sizing.load_case`).

    Returns
    -------
    SearchResult

    Raises
    ------
    GearError
        Bad input, or a local search estimated over ``max_seconds``; before any work.

    Examples
    --------
    Joldasbekov §5.4's 12/28 pair (m = 1) among shifts 0 ... 0.4: the least sliding pair with
    a contact ratio of at least 1.3.

    >>> r = pairs(ratio=28 / 12, module=1, teeth=[12, 28], shifts=(0.0, 0.4, 0.1),
    ...           limits={"min_contact_ratio": 1.3}, top=1, progress=False)
    >>> int(r["z1"][0]), int(r["z2"][0]), float(r["x1"][0]), float(r["x2"][0])
    (12, 28, 0.4, 0.3)
    >>> round(float(r["contact_ratio"][0]), 4)
    1.3046

    The smallest (least material) 1:3 pair of module 2 that carries 60 N m at 1500 rpm for
    20 000 h with S_H >= 1.1 and S_F >= 1.5, face widths 10 ... 40 mm:

    >>> r = pairs(ratio=3, module=2, teeth=(14, 80), shifts=(0.0, 0.6, 0.2), torque=60,
    ...           speed=1500, face_width=(10, 40, 5), min_safety={"pitting": 1.1,
    ...           "bending": 1.5}, top=1, progress=False)
    >>> int(r["z1"][0]), int(r["z2"][0]), float(r["face_width"][0]), round(float(r["S_H"][0]), 3)
    (26, 78, 10.0, 1.101)
    """
    t0 = time.perf_counter()
    space, client, threads = _prepare(
        ratio, center_distance, module, teeth, shifts, helix, ratio_tolerance=ratio_tolerance,
        split=split, pressure_angle=pressure_angle, rack=rack, internal=internal,
        tip_shortening=tip_shortening, limits=limits, objective=objective, top=top,
        friction=friction, torque=torque, speed=speed, material=material,
        face_width=face_width, life=life, min_safety=min_safety, smallest_width=smallest_width,
        dataset=dataset, chunk_size=chunk_size, client=client, threads=threads,
        **rating_options,
    )  # fmt: skip
    check_real("max_seconds", max_seconds, 0.0)
    n = space.candidates
    if client is None:
        rate = (RATED_RATE if space.load is not None else LOCAL_RATE) * threads
        estimate = n / rate
        if estimate > max_seconds:
            raise GearError(
                f"the search has {n:,} candidates: about {format_duration(estimate)} on "
                f"{threads} local thread(s) at {rate / threads:.3g} candidates/s each, over the "
                f"limit max_seconds = {max_seconds:g} s; pass client= (a dask.distributed "
                "Client or scheduler address), narrow the space, or raise max_seconds"
            )
    if dataset is not None:
        _open_dataset(space.dataset)
    bounds = [(i, min(i + chunk_size, space.size)) for i in range(0, space.size, chunk_size)]
    report = progress_callback(progress, unit="candidate")
    if report is not None and client is not None and progress is not False:
        _announce_dashboard(client, progress)
    if client is None:
        parts = _run_local(space, bounds, threads, report)
    else:
        parts = _run_dask(space, bounds, client, report)
    table, feasible, examined = parts
    if space.pareto and top is not None:  # the front is whole until here; then its head
        table = table[:top]
    return SearchResult(table, examined, feasible, len(bounds), time.perf_counter() - t0, space)


def _prepare(
    ratio=None, center_distance=None, module=1.0, teeth=(12, 60), shifts=(-0.5, 1.0, 0.1),
    helix=0.0, *, ratio_tolerance=0.01, split="proportional", pressure_angle=None, rack=None,
    internal=False, tip_shortening=True, limits=None, objective=None, top=20,
    friction=0.1, torque=None, speed=None, material="case-carburized", face_width=None,
    life=20000.0, min_safety=None, smallest_width=True, dataset=None, chunk_size=1 << 16,
    client=None, threads=None, **rating_options,
) -> tuple[_Space, object, int]:  # fmt: skip
    """The checked candidate space of :func:`pairs`, its Dask client (or None) and the local
    thread count; every bad argument is a GearError here, before any work."""
    rack = rack if rack is not None else BasicRack.iso53()
    if not isinstance(rack, BasicRack):
        raise GearError(f"rack must be a BasicRack; got {rack!r}")
    pa = rack.pressure_angle if pressure_angle is None else pressure_angle
    pa = check_real("pressure_angle", pa, 0.0, 45.0)
    if pa != rack.pressure_angle:
        rack = rack.with_pressure_angle(pa)
    modules = _values("module", module, 0.0)
    helices = _values("helix", helix, -60.0, 60.0)
    z = _teeth(teeth)
    x = _grid("shifts", shifts)
    if isinstance(limits, dict):
        limits = Limits(**limits)
    limits = limits if limits is not None else Limits()
    if not isinstance(limits, Limits):
        raise GearError(f"limits must be a Limits or a dict; got {limits!r}")
    widths, load, density = _load(torque, speed, material, face_width, life, min_safety,
                                  rating_options)  # fmt: skip
    if objective is None:
        objective = "sliding" if widths is None else "volume"
    if top is not None and (isinstance(top, bool) or not isinstance(top, int) or top < 1):
        raise GearError(f"top = {top!r}; valid is an integer >= 1 or None")
    if isinstance(chunk_size, bool) or not isinstance(chunk_size, int) or chunk_size < 1:
        raise GearError(f"chunk_size = {chunk_size!r}; valid is an integer >= 1")
    if split not in _SPLITS:
        raise GearError(f"split = {split!r}; valid are {list(_SPLITS)}")
    if split == "proportional" and internal and center_distance is not None:
        raise GearError("split='proportional' is defined for external pairs; use 'keep'")
    check_real("ratio_tolerance", ratio_tolerance, 0.0, low_open=False)
    check_real("friction", friction, 0.0, 1.0, low_open=False)
    if not isinstance(smallest_width, bool):
        raise GearError(f"smallest_width = {smallest_width!r}; valid are True and False")
    if dataset is not None:
        if top is not None:
            raise GearError(f"dataset = {str(dataset)!r} holds every feasible row: it needs "
                            f"top=None (top = {top!r})")  # fmt: skip
        dataset = _dataset_path(dataset)
    internal = bool(internal)

    z1, z2 = (v.ravel() for v in np.meshgrid(z, z, indexing="ij"))
    keep = z2 > z1 if internal else np.ones(z1.shape, bool)
    if ratio is not None:
        r = check_real("ratio", ratio, 0.0)
        keep &= np.abs(z2 / z1 - r) <= ratio_tolerance * r * (1 + 1e-12)
    z1, z2 = z1[keep], z2[keep]
    # module-major, then helix, then tooth pair (a chunk then holds few (m, beta) groups)
    grid = np.meshgrid(modules, helices, np.arange(z1.size), indexing="ij")
    base = np.stack([grid[0].ravel(), grid[1].ravel(), z1[grid[2].ravel()], z2[grid[2].ravel()]],
                    axis=1).astype(float)  # fmt: skip
    x1, x2 = x, x
    if center_distance is not None:
        a = check_real("center_distance", center_distance, 0.0)
        m, b = base[:, 0], base[:, 1]
        s = -1.0 if internal else 1.0
        at = transverse_pressure_angle(pa, b)
        a_d = np.abs(base[:, 2] + s * base[:, 3]) * m / (2 * np.cos(np.radians(b)))
        base = base[a_d * np.cos(at) < a]  # the shift sum exists
        if len(base):
            total = center_distance_shift_sum(base[:, 2], base[:, 3], base[:, 0], a, pa,
                                              base[:, 1], internal)  # fmt: skip
            total = np.atleast_1d(total)
            lo, hi = x.min(), x.max()
            s_lo, s_hi = (2 * lo, 2 * hi) if not internal else (lo - hi, hi - lo)
            base = base[(total >= s_lo - 1e-9) & (total <= s_hi + 1e-9)]
        x2 = np.zeros(1)
        if split != "keep":
            x1 = np.zeros(1)
    columns = (*_KEYS, *_GEOMETRY, *_MARGINS, *(_INTERNAL if internal else ()))
    if widths is not None:
        columns = (*columns, *_SIZE, *(_SAFETY if load is not None else ()))
    obj = _objective(objective, columns)
    space = _Space(
        base, x1, x2, None if center_distance is None else float(center_distance), split, pa,
        rack, internal, bool(tip_shortening), limits, obj, top, float(friction),
        (float(x.min()), float(x.max())), columns, widths, load, smallest_width, density,
        dataset,
    )  # fmt: skip
    client = dask_client(client)
    if threads is None:
        threads = default_threads()
    elif isinstance(threads, bool) or not isinstance(threads, int) or threads < 1:
        raise GearError(f"threads = {threads!r}; valid is an integer >= 1")
    return space, client, threads


def _load(torque, speed, material_, face_width, life, min_safety, options):
    """``(widths, load, densities)``: the face widths (ascending, or None), the checked
    :class:`gears.rating.sizing.Load` (or None without a torque) and both materials' densities."""
    from gears.rating.materials import material as as_material

    mats = material_ if isinstance(material_, tuple | list) else (material_, material_)
    if len(mats) != 2:
        raise GearError(f"material = {material_!r}; give one material or a pair (gear 1, gear 2)")
    density = (as_material(mats[0]).density, as_material(mats[1]).density)
    widths = None
    if face_width is not None:
        widths = np.unique(_grid("face_width", face_width))
        if widths[0] <= 0 or widths[-1] > 1e5:
            bad = widths[0] if widths[0] <= 0 else widths[-1]
            raise GearError(f"face_width = {bad:g}; valid is 0 < face_width <= 1e5 mm")
    if torque is None:
        extra = [k for k, v in (("speed", speed), ("min_safety", min_safety)) if v is not None]
        extra += list(options)
        if extra:
            raise GearError(f"{', '.join(extra)} rate the candidates under a load: "
                            "give torque= (N m on gear 1) and speed= (rpm) too")  # fmt: skip
        return widths, None, density
    if speed is None:
        raise GearError("torque= needs speed= (rpm of gear 1) to rate the candidates")
    if widths is None:
        raise GearError(
            "torque= needs face_width=: a width in mm, a list of widths, or (low, high, step); "
            "each candidate is rated at each width (the smallest that carries the load is kept)"
        )
    load = load_case(torque, speed, material_, life, min_safety, **options)
    return widths, load, density


@dataclass(frozen=True)
class Estimate:
    """What a search will cost, before it runs (:func:`estimate`).

    Attributes
    ----------
    candidates : int
        Candidates the search decides (geometries times face widths).
    chunks : int
        Chunks (tasks) it is cut into.
    rate : float
        Candidates per second on one thread, measured on ``sampled`` candidates spread over
        the space.
    sampled : int
    threads : int
        Local threads :func:`pairs` would use.
    """

    candidates: int
    chunks: int
    rate: float
    sampled: int
    threads: int

    @property
    def local_seconds(self) -> float:
        """Expected wall time on the local threads (at :data:`THREAD_EFFICIENCY` per thread
        beyond the first)."""
        return self.candidates / (self.rate * (1 + THREAD_EFFICIENCY * (self.threads - 1)))

    @property
    def worker_seconds(self) -> float:
        """Expected time on one single-threaded Dask worker: a cluster of ``w`` of them takes
        about ``worker_seconds / w``."""
        return self.candidates / self.rate

    def __str__(self) -> str:
        return (
            f"{self.candidates:,} candidates in {self.chunks:,} chunks at about "
            f"{self.rate:.3g} candidates/s per thread (measured on {self.sampled:,}): about "
            f"{_duration(self.local_seconds)} on {self.threads} local thread(s); on a Dask "
            f"cluster about {_duration(self.worker_seconds)} divided by its worker threads"
        )


def _duration(seconds: float) -> str:
    return f"{seconds:.2g} s" if seconds < 10 else format_duration(seconds)


#: speed-up of each local thread beyond the first (measured 1.47-1.68 on 2 threads,
#: docs/performance.md)
THREAD_EFFICIENCY = 0.7
#: geometries :func:`estimate` times by default (each with its face widths), in four windows
ESTIMATE_SAMPLE = 1 << 14


def estimate(*args, sample: int = ESTIMATE_SAMPLE, **kwargs) -> Estimate:
    """The size and expected time of ``pairs(*args, **kwargs)`` (the same arguments), before
    running it: the candidates are counted exactly; their rate is measured by checking (and
    rating) some of them on one thread (a rate depends on how many pass the cheap tests
    first). ``sample`` counts geometries (pairs
    before their face widths), timed in four windows spread over the space, each long enough
    that the per-block overhead weighs as in the search. Takes a fraction of a second.

    >>> e = estimate(ratio=3.2, module=[2, 2.5], teeth=(12, 100), shifts=(-0.5, 1.0, 0.05))
    >>> e.candidates, e.chunks
    (49972, 1)
    >>> e.local_seconds < 10
    True
    """
    for name in ("progress", "max_seconds"):
        kwargs.pop(name, None)
    if isinstance(sample, bool) or not isinstance(sample, int) or sample < 1:
        raise GearError(f"sample = {sample!r}; valid is an integer >= 1")
    space, _, threads = _prepare(*args, **kwargs)
    chunk_size = kwargs.get("chunk_size", 1 << 16)
    space = _replace(space, dataset=None, top=1 if space.top is not None else None)
    n = space.size
    windows = 4
    width = max(1, min(n, sample) // windows)
    starts = sorted({int(i) for i in np.linspace(0, max(n - width, 0), windows)})
    if n:
        evaluate_chunk(space, 0, min(n, 64), _LOCAL_BLOCK)  # first calls: imports, caches
    t0 = time.perf_counter()
    checked = 0
    for lo in starts:
        checked += evaluate_chunk(space, lo, min(lo + width, n), _LOCAL_BLOCK)[2]
    seconds = max(time.perf_counter() - t0, 1e-9)
    rate = checked / seconds if checked else LOCAL_RATE
    return Estimate(space.candidates, -(-n // chunk_size), rate, checked, threads)


def _dataset_path(path) -> str:
    """``path`` as the absolute folder of a Parquet dataset, checked before any work: not a
    file name, new or without part files, in a writable folder, pyarrow importable."""
    import os
    import pathlib

    try:
        p = pathlib.Path(os.fspath(path)).absolute()
    except TypeError:
        raise GearError(f"dataset = {path!r}; valid is a folder path") from None
    if p.suffix.lower() in TABLE_FORMATS:
        raise GearError(f"dataset = {str(path)!r} names a file; give a folder (a Parquet "
                        "dataset: one part file per chunk)")  # fmt: skip
    if p.exists() and not p.is_dir():
        raise GearError(f"dataset = {str(path)!r} exists and is not a folder")
    if p.is_dir() and any(p.glob("part-*.parquet")):
        raise GearError(f"dataset = {str(path)!r} already holds part files; give a new or "
                        "empty folder")  # fmt: skip
    if not p.parent.is_dir() or not os.access(p.parent, os.W_OK):
        raise GearError(f"dataset = {str(path)!r}: its folder {str(p.parent)!r} does not exist "
                        "or is not writable")  # fmt: skip
    try:
        import pyarrow.parquet  # noqa: F401
    except ImportError:
        raise GearError("dataset= writes Parquet: it needs pyarrow: pip install "
                        "'geartrain[parquet]'") from None  # fmt: skip
    return str(p)


def _open_dataset(path: str) -> None:
    import os

    try:
        os.makedirs(path, exist_ok=True)
    except OSError as exc:
        raise GearError(f"dataset = {path!r} cannot be made: {exc}") from None


def _replace(space: _Space, **changes) -> _Space:
    import dataclasses

    return dataclasses.replace(space, **changes)


def _merge(acc: np.ndarray | None, part: np.ndarray, space: _Space) -> np.ndarray:
    if acc is None:
        return part
    return _reduce(np.concatenate([acc, part]), space)


def _run_local(space, bounds, threads, report):
    acc, feasible, examined, done = None, 0, 0, 0
    total = space.candidates
    if not bounds:
        return np.empty(0, _dtype(space.columns)), 0, 0
    if threads == 1:
        results = (evaluate_chunk(space, *b, _LOCAL_BLOCK) for b in bounds)
        for rows, f, c in results:
            acc, feasible, examined, done = _merge(acc, rows, space), feasible + f, examined + c, \
                done + 1  # fmt: skip
            if report:
                report(examined, total)
        return acc, feasible, examined
    pool = ThreadPoolExecutor(threads, thread_name_prefix="gears.search.engine")
    try:
        pending = set()
        queue = iter(bounds)
        for b in itertools.islice(queue, 2 * threads):
            pending.add(pool.submit(evaluate_chunk, space, *b, _LOCAL_BLOCK))
        while pending:
            finished, pending = wait(pending, return_when=FIRST_COMPLETED)
            for fut in finished:
                rows, f, c = fut.result()
                acc = _merge(acc, rows, space)
                feasible, examined, done = feasible + f, examined + c, done + 1
                nxt = next(queue, None)
                if nxt is not None:
                    pending.add(pool.submit(evaluate_chunk, space, *nxt, _LOCAL_BLOCK))
                if report:
                    report(examined, total)
    finally:
        pool.shutdown(wait=True, cancel_futures=True)
    return acc, feasible, examined


def _run_dask(space, bounds, client, report):
    total = space.candidates
    if not bounds:
        return np.empty(0, _dtype(space.columns)), 0, 0
    seconds = dask_timeout()
    try:
        spec = client.scatter(space, broadcast=True, hash=False, timeout=seconds)
    except (TimeoutError, OSError) as exc:
        raise GearError(
            f"the Dask cluster took no work within {seconds:g} s "
            f"(distributed.comm.timeouts.connect): {exc}; start workers, or run without client="
        ) from None
    window = max(4, 4 * len(client.scheduler_info().get("workers", {}) or [0]))
    queue = iter(bounds)
    first = [client.submit(evaluate_chunk, spec, *b, pure=False) for b in
             itertools.islice(queue, window)]  # fmt: skip
    acc, feasible, examined, done = None, 0, 0, 0
    pending = set(first)
    for fut, (rows, f, c) in dask_results(client, pending):
        fut.release()
        acc = _merge(acc, rows, space)
        feasible, examined, done = feasible + f, examined + c, done + 1
        nxt = next(queue, None)
        if nxt is not None:
            pending.add(client.submit(evaluate_chunk, spec, *nxt, pure=False))
        if report:
            report(examined, total)
    return acc, feasible, examined
