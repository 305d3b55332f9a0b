"""Layer 11, consumers: design search over gear pairs, in chunks, on every local core or a Dask
cluster (issue 13): the entry points :func:`pairs` and :func:`estimate`.

:func:`pairs` enumerates a candidate space (modules x helix angles x tooth pairs x profile
shifts, or, at a given centre distance, the exact shift sum split by a rule), checks every
candidate with the vectorised margins of :mod:`gears.checks` (the functions
``GearPair.check()`` calls), keeps the feasible ones and returns the best ``top`` by the
objective, or the Pareto front of two or three objectives.

**One code path.** The flat candidate index ``0 .. N-1`` is cut into chunks of ``chunk_size``;
one function (:func:`gears.search.checks.evaluate_chunk`) decodes a chunk, checks it and reduces
it to its own top-k (or Pareto set) before anything leaves it. The chunks run on a thread pool
of the local cores (numpy releases the GIL, as in :func:`gears.meshing.pair_geometry`) or, with
``client=`` (a ``dask.distributed.Client``, its address, or the active client), as Dask tasks;
the reductions are merged as they arrive, so memory never grows with N. Ties are broken on the
candidate's parameters, so the answer does not depend on the chunk size or the scheduler.

The family's modules, bottom to top: :mod:`gears.search.tables` (writing a table),
:mod:`gears.search.cluster` (the Dask client, results and heap; the progress bar),
:mod:`gears.search.candidates` (the candidate space from the arguments),
:mod:`gears.search.reduction` (top-k and Pareto), :mod:`gears.search.checks` (one chunk checked),
:mod:`gears.search.scheduling` (threads or Dask), :mod:`gears.search.result` (the table) and
this one. See ``docs/design_search.md``.
"""

from __future__ import annotations

import contextlib
import dataclasses
import time
from dataclasses import dataclass

import numpy as np

from gears.errors import GearError
from gears.meshing import default_threads
from gears.report import format_duration
from gears.search.candidates import _Space, candidate_space
from gears.search.checks import _LOCAL_BLOCK, evaluate_chunk
from gears.search.cluster import dask_client
from gears.search.result import SearchResult
from gears.search.scheduling import LOCAL_RATE, MAX_SECONDS, run_chunks

__all__ = ["Estimate", "estimate", "pairs"]


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
        Profile-shift coefficients to try (a ring's in the sign of DIN 3960 / ISO 21771:
        positive thickens its teeth).
    limits : Limits or dict
        Contact ratio, tip land, undercut and sliding limits
        (:class:`gears.search.candidates.Limits`).
    objective : str or sequence of 2-3 str
        A column to minimise (``"-contact_ratio"`` maximises): the best ``top`` rows are
        returned. Two or three columns: the whole Pareto front (at most ``top`` of it, in
        order of the first objective, when ``top`` is given). Default ``"sliding"``, or
        ``"volume"`` with a face width. With a face width also ``"volume"`` (both gears'
        material, mm^3: :func:`gears.rating.sizing.pair_volume`) and ``"mass"`` (kg), with a torque
        ``"-S_H"`` and ``"-S_F"`` (the smaller safety of the two gears, maximised) and
        ``"-mesh_efficiency"`` (the mesh loss at the load, ISO/TR 14179-2, maximised).
    top : int or None
        Rows returned; None returns every feasible row (use ``to_parquet`` for large results,
        or ``dataset=``).
    torque, speed : float, optional
        Rate every candidate by ISO 6336 method B (:func:`gears.rating.iso6336.rate_pairs`, the
        function ``GearPair.rating`` calls) with this torque on gear 1 (N m) at this speed
        (rpm), and keep only those that meet ``min_safety``. The result gains the columns
        ``S_H1, S_H2, S_F1, S_F2`` (each gear's safety against pitting and bending) and
        ``S_H``, ``S_F`` (the smaller of each) and ``mesh_efficiency`` (1 - mu_mz H_V at the
        load by ISO/TR 14179-2, as ``GearPair.efficiency(torque, speed)`` with its default oil
        and the load's ``roughness``; under a spectrum the energy's, sum(P_i h_i eta_i) /
        sum(P_i h_i)); ``result.rating(i)`` rates row i on its own.
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
        with a torque (:func:`gears.rating.sizing.load_case`); ``spectrum=[(torque, speed,
        hours), ...]`` instead of ``torque``, ``speed`` and ``life`` rates every candidate
        under that load spectrum (ISO 6336-6: its equivalent safeties, as
        ``GearPair.rating(spectrum=...)`` gives them; :func:`gears.rating.sizing.rate_spectrum`).

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
    space, resolved, threads = _prepare(
        ratio, center_distance, module, teeth, shifts, helix, ratio_tolerance=ratio_tolerance,
        split=split, pressure_angle=pressure_angle, rack=rack, internal=internal,
        tip_shortening=tip_shortening, limits=limits, objective=objective, top=top,
        friction=friction, torque=torque, speed=speed, material=material,
        face_width=face_width, life=life, min_safety=min_safety, smallest_width=smallest_width,
        dataset=dataset, chunk_size=chunk_size, client=client, threads=threads,
        **rating_options,
    )  # fmt: skip
    try:
        table, feasible, examined, chunks = run_chunks(
            space, resolved, threads, chunk_size, progress, max_seconds
        )
    finally:
        _close_opened(client, resolved)
    return SearchResult(table, examined, feasible, chunks, time.perf_counter() - t0, space)


def _close_opened(given, resolved) -> None:
    """Close the client opened here from an address (one per call would pile up on the
    scheduler); a client the caller gave stays theirs."""
    if isinstance(given, str) and resolved is not None:
        with contextlib.suppress(Exception):
            resolved.close()


def _prepare(*args, client=None, threads=None, **kwargs) -> tuple[_Space, object, int]:
    """The checked candidate space of :func:`pairs`, its Dask client (or None) and the local
    thread count; every bad argument is a GearError here, before any work."""
    space = candidate_space(*args, **kwargs)
    client = dask_client(client)
    if threads is None:
        threads = default_threads()
    elif isinstance(threads, bool) or not isinstance(threads, int) or threads < 1:
        raise GearError(f"threads = {threads!r}; valid is an integer >= 1")
    return space, client, threads


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
    connect_seconds : float
        Time taken to reach the Dask scheduler given as ``client=`` (its address asked, a
        client opened, its workers' versions checked), which a search on it spends again;
        0 without a cluster.
    """

    candidates: int
    chunks: int
    rate: float
    sampled: int
    threads: int
    connect_seconds: float = 0.0

    @property
    def local_seconds(self) -> float:
        """Expected wall time on the local threads (at :data:`THREAD_EFFICIENCY` per thread
        beyond the first)."""
        return self.candidates / (self.rate * (1 + THREAD_EFFICIENCY * (self.threads - 1)))

    @property
    def worker_seconds(self) -> float:
        """Expected time on one single-threaded Dask worker: a cluster of ``w`` of them takes
        about ``connect_seconds + worker_seconds / w``."""
        return self.candidates / self.rate

    def cluster_seconds(self, worker_threads: int) -> float:
        """Expected wall time on a Dask cluster of ``worker_threads`` threads, the connection
        counted."""
        return self.connect_seconds + self.worker_seconds / max(1, int(worker_threads))

    def __str__(self) -> str:
        return (
            f"{self.candidates:,} candidates in {self.chunks:,} chunks at about "
            f"{self.rate:.3g} candidates/s per thread (measured on {self.sampled:,}): about "
            f"{_duration(self.local_seconds)} on {self.threads} local thread(s); on a Dask "
            f"cluster about {_duration(self.worker_seconds)} divided by its worker threads"
            + (
                f", plus {_duration(self.connect_seconds)} to connect"
                if self.connect_seconds
                else ""
            )
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
    t_connect = time.perf_counter()
    space, resolved, threads = _prepare(*args, **kwargs)
    # what reaching the cluster took, the space's own checks aside (microseconds)
    connect = time.perf_counter() - t_connect if resolved is not None else 0.0
    _close_opened(kwargs.get("client"), resolved)
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
    return Estimate(space.candidates, -(-n // chunk_size), rate, checked, threads, connect)


def _replace(space: _Space, **changes) -> _Space:
    return dataclasses.replace(space, **changes)
