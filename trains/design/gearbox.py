"""Layer 7, design: multi-stage planetary gearbox search (issues 13 and 20).

:func:`synthesize_gearbox` finds ``stages`` planetary stages in series (any of the five
schemes each, ring fixed, sun in, carrier out) whose ratios multiply to a target, ranked; with a
``torque`` each stage is rated for the torque and speed it carries and sized: its module is the
smallest of a list that carries the load, its face width the smallest of a set.

1. **Stage sets, in blocks.** Every single stage a scheme allows with a reduction ratio
   ``1 < r <= R / r_min^(k-1)`` comes from :func:`trains.design.synthesis.stage_block` (exact
   Fractions, the assembly, neighbour, coaxiality and mesh conditions; vectorised), the
   tooth-count sets of each scheme cut into many blocks: tasks for the local threads or a Dask
   cluster.
2. **Prune on the exact ratio, in integers.** Stages are grouped by their reduced ratio
   ``a/b``; for k = 2 the second ratio must be exactly ``R b / a`` (an integer look-up over all
   ratios at once); for k = 3 the first two are paired and the third looked up the same way.
   With ``tolerance > 0`` a sorted float window preselects and ``Fraction`` decides.
3. **Sizing (with a torque).** A stage's load depends on its place: its input torque is the
   gearbox's times the ratios before it (lossless, as :meth:`Planetary.rating`'s power flow),
   so the ratio tuples are taken in every order and each (ratio, place) gets its load. Every
   stage of a ratio is sized at each load it meets (:func:`trains.design.sizing.size_stages`, every
   mesh rated by ISO 6336 as :meth:`Planetary.rating` rates it), in chunks of stages: tasks.
4. **Combine, not recompute.** The objectives are separable (a sum of the stages' volumes or
   masses, the largest ring, the sum of the tooth counts, the product of the efficiencies), so
   the best gearboxes of a ratio tuple combine the best stages of each (ratio, place): the
   ``4 top`` best of each are combined, vectorised, in chunks of tuples (tasks), each chunk
   reduced to its best before it returns.
5. **Full checks, lazily.** Walking the ranking, each stage is checked once with
   :meth:`trains.planetary.stage.Planetary.check` (the checks of the next stages in batches, as
   tasks); a gearbox with a failing stage is skipped, until ``top`` are found.

Without a torque, stages are listed input first in non-decreasing ratio (any order gives the
same product); with one, in the order found best.
"""

from __future__ import annotations

import contextlib
import itertools
import math
import numbers
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import numpy as np

from gears.errors import GearError
from gears.meshing import default_threads
from gears.search.cluster import dask_client, progress_callback
from trains.design.combine import _COMBINE_FIELDS, _best_per_key, _combine_task, _score_order
from trains.design.plan import _Plan, _plan
from trains.design.ratios import (
    _place_keys,
    _ratio_errors,
    _ratio_ids,
    _ratio_tuples,
)
from trains.design.scheduling import _Runner
from trains.design.sizing import size_stages
from trains.design.synthesis import (
    BLOCK,
    STAGE_FIELDS,
    Candidate,
    _as_ratio,
    _check_size,
    _counts,
    set_count,
    stage_block,
)
from trains.errors import TrainError
from trains.planetary.schemes import SCHEMES, canonical_scheme

__all__ = ["Gearbox", "Gearboxes", "synthesize_gearbox"]

_MIN_RATIO = {"simple": 2.0}
#: stages sized per task at most, and combinations crossed per combination task about
SIZING_CHUNK = 4096
COMBINATIONS = 200_000
#: stages sized per task at least (a smaller task costs a cluster more than it saves)
MIN_SIZING = 512
#: tooth-count sets per stage-set task at least (smaller blocks cost more than they save)
MIN_SETS = 4096
#: (stage, module, width) rows a rating call takes
LOCAL_BLOCK = 1 << 16
_ALPHABET = {s: i for i, s in enumerate(sorted(SCHEMES))}  # ident order: scheme names sorted


@dataclass(frozen=True)
class Gearbox:
    """Planetary stages in series.

    Attributes
    ----------
    stages : tuple of Candidate
        The stages, input first (each with its ``stage``: a :class:`Planetary`, at its module).
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
    face_widths : tuple of float
        With a load: each stage's face width, mm (its module is ``stages[i].module``).
    safety : tuple of (float, float)
        With a load: each stage's smallest safety against pitting S_H and bending S_F (of any
        gear of any of its meshes).
    volume, mass : float or None
        With a load: the gears' material, mm^3 and kg (:func:`trains.design.sizing.size_stages`).
    torques, speeds : tuple of float
        With a load: each stage's input torque (N m) and speed (rpm).
    mesh_efficiency : float or None
        With a load: the product of ``stage_efficiencies``.
    stage_efficiencies : tuple of float
        With a load: each stage's efficiency from its meshes at its load
        (:func:`trains.design.sizing.stage_efficiency`: ISO/TR 14179-2 per mesh, Ozols (14.26)
        for the stage; 0 where the friction equation does not give a mesh's loss).
    """

    stages: tuple[Candidate, ...]
    ratio: Fraction
    ratio_error: float
    ring: float
    teeth: int
    efficiency: float
    face_widths: tuple[float, ...] = ()
    safety: tuple[tuple[float, float], ...] = ()
    volume: float | None = None
    mass: float | None = None
    torques: tuple[float, ...] = ()
    speeds: tuple[float, ...] = ()
    mesh_efficiency: float | None = None
    stage_efficiencies: tuple[float, ...] = ()

    @property
    def modules(self) -> tuple[float, ...]:
        """Each stage's module, mm."""
        return tuple(c.module for c in self.stages)

    def __str__(self) -> str:
        parts = []
        for i, c in enumerate(self.stages):
            text = (f"{c.scheme} {'/'.join(str(z) for z in _distinct(c))} x{c.n_planets} "
                    f"({c.ratio})")  # fmt: skip
            if self.face_widths:
                sh, sf = self.safety[i]
                text += (f" m {c.module:g} b {self.face_widths[i]:g} S_H {sh:.3f} "
                         f"S_F {sf:.3f}")  # fmt: skip
            parts.append(text)
        head = (f"ratio {self.ratio} (error {self.ratio_error:.2e}), ring {self.ring:g} mm, "
                f"{self.teeth} teeth, efficiency {self.efficiency:.4f}")  # fmt: skip
        if self.volume is not None:
            head += (f", volume {self.volume / 1e3:.4g} cm^3, mass {self.mass:.4g} kg, mesh "
                     f"efficiency {self.mesh_efficiency:.4f}")  # fmt: skip
        return f"{head}: {' | '.join(parts)}"


def _distinct(c: Candidate) -> tuple[int, ...]:
    z1, z2, z2p, z3 = c.teeth
    return (z1, z2, z3) if c.scheme == "simple" else (z1, z2, z2p, z3)


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
    tasks : int
        Tasks the work was cut into (stage-set blocks, sizing chunks, combination chunks,
        check batches), run on local threads or as Dask tasks.
    sized : int
        With a load: stage-load rows sized.
    """

    def __init__(self, items: Iterable[Gearbox], stage_sets: dict[str, int], ratio_tuples: int,
                 checked: int, seconds: float, tasks: int = 0, sized: int = 0) -> None:  # fmt: skip
        super().__init__(items)
        self.stage_sets = dict(stage_sets)
        self.ratio_tuples = int(ratio_tuples)
        self.checked = int(checked)
        self.seconds = float(seconds)
        self.tasks = int(tasks)
        self.sized = int(sized)

    def table(self) -> str:
        """One line per gearbox, ranked."""
        if not self:
            return (f"no gearbox meets the request ({self.ratio_tuples} ratio combinations; "
                    f"stage sets: {self.stage_sets})")  # fmt: skip
        return "\n".join(f"{i:3d}. {g}" for i, g in enumerate(self, 1))

    def to_array(self) -> np.ndarray:
        """A numpy structured array: rank, ratio, error, ring, teeth, efficiency (with a load
        also volume, mass and mesh_efficiency) and, per stage ``s``, ``s_scheme``, ``s_z1``,
        ``s_z2``, ``s_z2p``, ``s_z3``, ``s_planets`` (with a load also ``s_module``,
        ``s_face_width``, ``s_S_H``, ``s_S_F``, ``s_torque``, ``s_efficiency``)."""
        k = len(self[0].stages) if self else 0
        rated = bool(self and self[0].face_widths)
        fields = [("rank", int), ("ratio", float), ("ratio_error", float), ("ring", float),
                  ("teeth", int), ("efficiency", float)]  # fmt: skip
        if rated:
            fields += [("volume", float), ("mass", float), ("mesh_efficiency", float)]
        for s in range(1, k + 1):
            fields += [(f"{s}_scheme", "U13"), (f"{s}_z1", int), (f"{s}_z2", int),
                       (f"{s}_z2p", int), (f"{s}_z3", int), (f"{s}_planets", int)]  # fmt: skip
            if rated:
                fields += [(f"{s}_module", float), (f"{s}_face_width", float),
                           (f"{s}_S_H", float), (f"{s}_S_F", float),
                           (f"{s}_torque", float), (f"{s}_efficiency", float)]  # fmt: skip
        out = np.zeros(len(self), fields)
        for i, g in enumerate(self):
            row = [i + 1, float(g.ratio), g.ratio_error, g.ring, g.teeth, g.efficiency]
            if rated:
                row += [g.volume, g.mass, g.mesh_efficiency]
            for j, c in enumerate(g.stages):
                row += [c.scheme, *c.teeth, c.n_planets]
                if rated:
                    row += [c.module, g.face_widths[j], *g.safety[j], g.torques[j],
                            g.stage_efficiencies[j]]  # fmt: skip
            out[i] = tuple(row)
        return out


# --- input ---------------------------------------------------------------------------------------


def _validate(ratio, stages, tolerance, top, schemes) -> tuple:
    target = _as_ratio(ratio)
    if target <= 1:
        raise TrainError(f"ratio = {target}; a gearbox of reduction stages needs ratio > 1")
    if isinstance(stages, bool) or not isinstance(stages, numbers.Integral) or not 1 <= stages <= 3:
        raise TrainError(f"stages = {stages!r}; valid is 1, 2 or 3")
    tol = float(tolerance) if isinstance(tolerance, numbers.Real) else math.nan
    if not (math.isfinite(tol) and 0 <= tol < 1):
        raise TrainError(f"tolerance = {tolerance!r}; valid is a relative error 0 <= t < 1")
    if isinstance(top, bool) or not isinstance(top, numbers.Integral) or top < 1:
        raise TrainError(f"top = {top!r}; valid is an integer >= 1")
    names = (schemes,) if isinstance(schemes, str) else tuple(schemes)
    if not names:
        raise TrainError("schemes is empty; give at least one scheme")
    return target, int(stages), tol, tuple(dict.fromkeys(canonical_scheme(s) for s in names))


# --- the runner: local threads or Dask tasks ----------------------------------------------------


# --- the search ----------------------------------------------------------------------------------


def synthesize_gearbox(
    ratio: Any, stages: int = 2, n_planets: Any = 3, schemes: str | Sequence[str] = "simple",
    *, tolerance: float = 0.0, z_min: int = 17, z_max: int = 150,
    module: float | Sequence[float] | None = None,
    objective: str | None = None, top: int = 10, mesh_checks: str = "geometry",
    min_contact_ratio: float = 1.1, full_checks: bool = True, torque: float | None = None,
    speed: float | None = None, material: Any = "case-carburized",
    face_width: float | Sequence[float] | None = None, life: float = 20000.0,
    min_safety: dict[str, float] | None = None, client: Any = None,
    threads: int | None = None, chunk_size: int | None = None,
    progress: Callable[[int, int], object] | bool | None = None, max_seconds: float = 30.0,
    **rating_options,
) -> Gearboxes:  # fmt: skip
    """Planetary stages in series whose ratios multiply to ``ratio``, ranked; with a
    ``torque``, each stage sized for the load it carries.

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
    z_min, z_max, mesh_checks, min_contact_ratio
        As :func:`trains.synthesize`, for every stage.
    module : float or sequence, optional
        Without a torque: the module of every stage (default 1). With a torque: the modules to
        choose from (default the ISO 54 series I, 1 ... 50 mm,
        :data:`gears.rating.sizing.ISO54`): each stage takes the smallest that carries its load.
    objective : str, optional
        Without a torque ``"ring"`` (default: the smallest largest ring), ``"teeth"`` (fewest
        teeth in total) or ``"efficiency"`` (highest, each mesh by Ozols (14.25) with friction
        0.1); ties go to the next objectives in that order. With a torque also ``"volume"``
        (default: the least material in total, mm^3), ``"mass"`` (kg) and
        ``"mesh_efficiency"`` (highest: each stage's efficiency from its meshes at its load and
        its module and face width, ISO/TR 14179-2 per mesh and Ozols (14.26) for the stage,
        :func:`trains.design.sizing.stage_efficiency`; the gearbox's the product); ties then
        go to the volume.
    top : int
        Gearboxes returned.
    full_checks : bool
        Check each stage of the returned gearboxes with :meth:`Planetary.check` and skip
        gearboxes with a failing stage.
    torque, speed : float, optional
        Torque (N m) and speed (rpm) on the input (the first sun). Each stage carries the
        input torque times the ratios before it (lossless, as :meth:`Planetary.rating`), at
        the input speed over them; every mesh is rated as :meth:`Planetary.rating` rates it
        (``root="standard"``: ISO 6336-3's root form, the ring's by the rack approximation).
    material : name or Material
        ISO 6336-5 material of every gear (:mod:`gears.rating.materials`).
    face_width : float or sequence
        With a torque: face widths to choose from, mm; at its module each stage takes the
        smallest that carries its load.
    life : float
        Required life, hours.
    min_safety : dict, optional
        ``{"pitting": S_Hmin, "bending": S_Fmin}`` for every gear of every mesh (default 1.0
        and 1.4).
    client : dask.distributed.Client, str, None or False
        Run the tasks (stage-set blocks, sizing and combination chunks, check batches) on a
        Dask cluster (None: the active client if any; False: local threads).
    threads : int, optional
        Local threads (default :func:`gears.meshing.default_threads`).
    chunk_size : int, optional
        Tooth-count sets per stage-set task (default: the sets over four tasks per thread or
        worker thread, at least 4096 and at most 10^6).
    progress : callable, bool or None
        ``progress(done, total)`` in tasks; True: a tqdm bar; None: a bar when stderr is a
        terminal; False: none.
    max_seconds : float
        The time budget of each scheme's stage set (refused before any work, as
        :func:`trains.synthesize`).
    **rating_options
        With a torque: any other option of :meth:`Planetary.rating` (``quality``,
        ``application_factor``, ``load_sharing_factor``, factors such as ``K_v=1.0``).

    Returns
    -------
    Gearboxes

    Raises
    ------
    TrainError
        Bad input (naming the value), before any work; a Dask cluster that fails.

    Examples
    --------
    1:12 in two simple stages, 3 planets each, every gear at most 100 teeth: the smallest ring
    is 65 teeth (10/3 x 18/5 = 12 exactly; the rings' tips relieved as :class:`Planetary`
    relieves them).

    >>> best = synthesize_gearbox(12, stages=2, z_max=100, progress=False)[0]
    >>> best.ratio, [c.ratio for c in best.stages], [c.teeth for c in best.stages]
    (Fraction(12, 1), [Fraction(10, 3), Fraction(18, 5)], [(27, 18, 18, 63), (25, 20, 20, 65)])

    The lightest 1:12 gearbox for 50 N m at 1500 rpm, modules of ISO 54, face widths 10 ... 30:

    >>> best = synthesize_gearbox(12, 2, z_max=100, torque=50, speed=1500,
    ...                           face_width=[10, 15, 20, 25, 30], progress=False)[0]
    >>> best.modules, best.face_widths
    ((1.25, 1.5), (15.0, 20.0))
    """
    t0 = time.perf_counter()
    target, k, tol, names = _validate(ratio, stages, tolerance, top, schemes)
    cr = _check_stages(names, n_planets, z_min, z_max, mesh_checks, min_contact_ratio, max_seconds)
    plan = _plan(objective, module, torque, speed, material, face_width, life, min_safety,
                 rating_options)  # fmt: skip
    runner = _runner(threads, chunk_size, progress, client)
    try:
        # 1. stage sets, in blocks of tooth-count sets; 2. the ratio tuples, the stages sized
        pool, counts = _stage_pool(runner, names, target, k, tol, n_planets, z_min, z_max,
                                   mesh_checks, cr, chunk_size)  # fmt: skip
        table, lists, key_tuples, errors, n_tuples, design = _stage_lists(
            runner, pool, plan, names, target, k, tol, top)  # fmt: skip
        # 3. combine in chunks of tuples (tasks), each reduced to its best; then check lazily
        out, checked = _walk(runner, table, lists, key_tuples, errors, plan, top, full_checks,
                             cr, names, target)  # fmt: skip
        runner.finish()
    finally:
        if isinstance(client, str) and runner.client is not None:  # opened here: close it
            with contextlib.suppress(Exception):
                runner.client.close()
    sized = 0 if design is None else len(design["stage"])
    return Gearboxes(out, counts, n_tuples, checked, time.perf_counter() - t0, runner.tasks, sized)


def _check_stages(names, n_planets, z_min, z_max, mesh_checks, min_contact_ratio,
                  max_seconds) -> float:  # fmt: skip
    """Refuse bad stage-set options and a stage set over its time budget, before any work; the
    minimum contact ratio as a float."""
    for name, v in (("z_min", z_min), ("z_max", z_max)):
        if isinstance(v, bool) or not isinstance(v, numbers.Integral) or v < 1:
            raise TrainError(f"{name} = {v!r}; valid is an integer >= 1")
    if z_min > z_max:
        raise TrainError(f"z_min = {z_min} > z_max = {z_max}; give z_min <= z_max")
    _counts(n_planets)
    if mesh_checks not in ("textbook", "geometry", "full"):
        raise TrainError(f"mesh_checks = {mesh_checks!r}; valid are 'textbook', 'geometry' "
                         "and 'full'")  # fmt: skip
    cr = float(min_contact_ratio) if isinstance(min_contact_ratio, numbers.Real) else math.nan
    if not (math.isfinite(cr) and cr >= 0):
        raise TrainError(f"min_contact_ratio = {min_contact_ratio!r}; valid is a number >= 0")
    budget = float(max_seconds) if isinstance(max_seconds, numbers.Real) else math.nan
    if not (budget > 0 and math.isfinite(budget)):
        raise TrainError(f"max_seconds = {max_seconds!r}; valid is a number > 0")
    for s in names:
        _check_size(s, z_min, z_max, 1, budget)
    return cr


def _runner(threads, chunk_size, progress, client) -> _Runner:
    """The runner of the search's tasks (threads, chunk size, progress and client checked)."""
    if threads is None:
        threads = default_threads()
    elif isinstance(threads, bool) or not isinstance(threads, int) or threads < 1:
        raise TrainError(f"threads = {threads!r}; valid is an integer >= 1")
    if chunk_size is not None and (
        isinstance(chunk_size, bool) or not isinstance(chunk_size, int) or chunk_size < 1
    ):
        raise TrainError(f"chunk_size = {chunk_size!r}; valid is an integer >= 1")
    report = _as_train_error(progress_callback, progress, "gearbox search", "task")
    client = _as_train_error(dask_client, client)
    return _Runner(client, threads, report)


def _stage_pool(runner, names, target, k, tol, n_planets, z_min, z_max, mesh_checks, cr,
                chunk_size) -> tuple[dict[str, np.ndarray], dict[str, int]]:  # fmt: skip
    """Step 1: every stage of every scheme whose ratio may take part, from blocks of tooth-count
    sets (tasks), merged in a fixed order (:func:`_merge_blocks`); the stages per scheme."""
    lowest = min(_MIN_RATIO.get(s, 1.0) for s in names)
    hi = float(target) * (1 + tol) / lowest ** (k - 1)
    args = []
    for code, s in enumerate(names):
        total = set_count(s, z_min, z_max)
        size = chunk_size or min(BLOCK, max(MIN_SETS, -(-total // (4 * runner.parallel))))
        args += [(code, s, hi, n_planets, z_min, z_max, a, min(a + size, total), mesh_checks,
                  cr) for a in range(0, total, size)]  # fmt: skip
    pool = _merge_blocks(runner.map(_stage_block, args), names)
    return pool, {s: int(np.count_nonzero(pool["scheme"] == i)) for i, s in enumerate(names)}


def _stage_lists(runner, pool, plan: _Plan, names, target, k, tol, top) -> tuple:
    """Step 2: the ratio tuples that meet the target, each (ratio, place) with its best stages
    (sized for their load when the plan is rated): ``(table, lists, key_tuples, errors,
    n_tuples, design)``."""
    ratios, rid = _ratio_ids(pool)
    tuples = _ratio_tuples(ratios, target, k, tol)
    if plan.rated:  # a stage's load depends on its place: every order of a tuple
        tuples = sorted({p for t in tuples for p in itertools.permutations(t)})
        keys, key_tuples = _place_keys(tuples, ratios)
        design = _size(runner, pool, rid, keys, plan, names)
        rows, row_key = design["stage"], design["key"]
        feasible = design["ok"]
        if plan.objective == "mesh_efficiency":  # a stage whose mesh loss is not given: no
            feasible = feasible & (design["efficiency"] > 0.0)
    else:
        keys = list(range(len(ratios)))
        key_tuples = list(tuples)
        design = None
        rows, row_key = np.arange(len(rid)), rid
        feasible = np.ones(len(rid), bool)
    wanted = {i for kt in key_tuples for i in kt}
    if plan.objective == "efficiency":  # every stage that may take part (module-free: at m0)
        m0 = float(plan.modules[0]) if not plan.rated else 1.0
        use = np.unique(rows[feasible & np.isin(row_key, sorted(wanted))])
        pool["eta"] = np.zeros(len(pool["z1"]))
        pool["eta"][use] = _efficiencies(runner, pool, use, names, m0)
    table = _stage_table(pool, rows, design, plan, names)
    lists = _best_per_key(table, row_key, feasible, len(keys), plan, top)
    errors = _ratio_errors(key_tuples, tuples, ratios, target, tol)
    key_tuples = [kt for kt in key_tuples if all(len(lists[i]) for i in kt)]
    return table, lists, key_tuples, errors, len(tuples), design


def _stage_block(code, scheme, hi, n_planets, z_min, z_max, first, last, mesh_checks, cr):
    """One block of one scheme's stage set (a task), tagged with the scheme's code."""
    out = stage_block(scheme, hi, n_planets, z_min, z_max, first, last, mesh_checks, cr)
    out["scheme"] = np.full(len(out["z1"]), code, np.int64)
    return out


def _merge_blocks(parts: list[dict], names: Sequence[str]) -> dict[str, np.ndarray]:
    """The stage pool: every block's stages in a fixed order (scheme, the tooth counts, more
    planets first), so the answer does not depend on how the blocks ran; ``total`` is a
    stage's tooth count (z1 + z2 + z3, and z2' of a two-gear planet)."""
    fields = (*STAGE_FIELDS, "scheme")
    parts = [p for p in parts if len(p["z1"])]
    if not parts:
        pool = {f: np.empty(0, np.int64) for f in fields}
    else:
        pool = {f: np.concatenate([p[f] for p in parts]).astype(np.int64) for f in fields}
    order = np.lexsort((-pool["k"], pool["z3"], pool["z2p"], pool["z2"], pool["z1"],
                        pool["scheme"]))  # fmt: skip
    pool = {f: v[order] for f, v in pool.items()}
    two = np.array([s != "simple" for s in names], bool)[pool["scheme"]] if len(order) else \
        np.empty(0, bool)  # fmt: skip
    pool["total"] = pool["z1"] + pool["z2"] + pool["z3"] + np.where(two, pool["z2p"], 0)
    return pool


def _size(runner: _Runner, pool, rid, keys, plan: _Plan, names) -> dict:
    """Every stage of a key's ratio at the key's load (the input torque times the ratios
    before it), sized in chunks of stages of one scheme (tasks): per (key, stage) row the
    module, face width, safeties, volume, mass and ring diameter (``ok`` where one fits)."""
    load = plan.load
    order = np.argsort(rid, kind="stable")
    cuts = np.searchsorted(rid[order], np.arange(len(keys) and (int(rid.max()) + 2)))
    # every key's stages (those of its ratio), all keys at once: key i takes order[cuts[r_i]
    # : cuts[r_i + 1]] at the multiplier p_i
    r = np.array([key[0] for key in keys], np.int64)
    counts = cuts[r + 1] - cuts[r] if len(keys) else np.empty(0, np.int64)
    key_ids = np.repeat(np.arange(len(keys)), counts)
    offset = np.arange(key_ids.size) - np.repeat(np.cumsum(counts) - counts, counts)
    stage_ids = order[np.repeat(cuts[r], counts) + offset] if len(keys) else key_ids
    mult = np.repeat(np.array([float(key[1]) for key in keys]), counts)
    fields = ("module", "face_width", "S_H", "S_F", "volume", "mass", "ring", "efficiency")
    design = {f: np.zeros(stage_ids.size) for f in fields}
    design["ok"] = np.zeros(stage_ids.size, bool)
    scheme = pool["scheme"][stage_ids]
    block = LOCAL_BLOCK  # the tasks keep their heap on Dask workers too (kept_heap)
    args, where = [], []
    for code in np.unique(scheme):
        rows = np.flatnonzero(scheme == code)
        size = max(MIN_SIZING, min(SIZING_CHUNK, -(-rows.size // (4 * runner.parallel))))
        for a in range(0, rows.size, size):
            part = rows[a : a + size]
            st = stage_ids[part]
            cols = [pool[f][st] for f in ("z1", "z2", "z2p", "z3", "k", "num", "den")]
            args.append((load, names[int(code)], *cols, load.torque * mult[part],
                         load.speed / mult[part], plan.modules, plan.widths,
                         plan.load_sharing, None, block))  # fmt: skip
            where.append(part)
    for part, res in zip(where, runner.map(size_stages, args), strict=True):
        for f in fields:
            design[f][part] = res[f]
        design["ok"][part] = res["module_index"] >= 0
    design.update(key=key_ids, stage=stage_ids, torque=load.torque * mult,
                  speed=load.speed / mult)  # fmt: skip
    return design


def _efficiencies(runner: _Runner, pool, use: np.ndarray, names, module: float) -> np.ndarray:
    """:meth:`Planetary.efficiency` of the pool's stages ``use`` at ``module``, in chunks
    (tasks); 0 where a stage cannot be built."""
    chunk = max(8, -(-use.size // (4 * runner.parallel)))
    parts = [use[a : a + chunk] for a in range(0, use.size, chunk)]
    args = [([names[int(c)] for c in pool["scheme"][part]],
             *(pool[f][part] for f in ("z1", "z2", "z2p", "z3", "k")), module)
            for part in parts]  # fmt: skip
    res = runner.map(_efficiency_task, args)
    return np.concatenate(res) if res else np.empty(0)


def _efficiency_task(schemes, z1, z2, z2p, z3, k, module) -> np.ndarray:
    out = np.zeros(len(schemes))
    for i, s in enumerate(schemes):
        c = _candidate(s, z1[i], z2[i], z2p[i], z3[i], k[i], Fraction(1), module)
        out[i] = _stage_efficiency(c)
    return out


def _stage_efficiency(c: Candidate) -> float:
    key = (c.scheme, c.teeth, c.n_planets, c.module)
    if key not in _EFFICIENCY:
        try:
            _EFFICIENCY[key] = float(c.stage.efficiency())
        except ValueError:
            _EFFICIENCY[key] = 0.0
    return _EFFICIENCY[key]


_EFFICIENCY: dict[tuple, float] = {}


def _candidate(scheme, z1, z2, z2p, z3, k, ratio, module) -> Candidate:
    return Candidate((int(z1), int(z2), int(z2p), int(z3)), int(k), ratio, 0.0, 0, False,
                     scheme, float(module))  # fmt: skip


def _stage_table(pool, rows: np.ndarray, design, plan: _Plan, names) -> dict:
    """The rows the combination picks from (a stage, or with a load a stage at a load), with
    the columns the scores read."""
    if design is None:
        m = np.full(rows.size, float(plan.modules[0]))
        t = {"module": m, "ring": pool["z3"][rows] * m, "volume": np.zeros(rows.size),
             "mass": np.zeros(rows.size)}  # fmt: skip
    else:
        t = {f: design[f] for f in ("module", "ring", "volume", "mass", "face_width", "S_H",
                                    "S_F", "torque", "speed")}  # fmt: skip
    for f in ("z1", "z2", "z2p", "z3", "k", "scheme", "num", "den", "total"):
        t[f] = pool[f][rows]
    t["eta"] = pool["eta"][rows] if "eta" in pool else np.zeros(rows.size)
    t["mesh_eta"] = design["efficiency"] if design is not None else np.zeros(rows.size)
    t["alpha"] = np.array([_ALPHABET[s] for s in names], np.int64)[t["scheme"]] if rows.size \
        else np.empty(0, np.int64)  # fmt: skip
    return t


def _walk(runner, t, lists, key_tuples, errors, plan, top, full_checks, cr, names,
          target) -> tuple[list[Gearbox], int]:  # fmt: skip
    """Combine the tuples in chunks (tasks), rank, and walk the ranking checking stages in
    batches (tasks) until ``top`` gearboxes pass."""
    if not key_tuples:
        return [], 0
    keep = 16 * top
    verdicts: dict[tuple, bool] = {}
    checked = 0
    t["row"] = np.arange(len(t["z1"]))
    sizes = np.array([math.prod(len(lists[i]) for i in kt) for kt in key_tuples], float)
    # the rows the lists name (the columns a score reads) and the lists packed, made once; on
    # a cluster sent to every worker once (scatter), so that a task carries only its tuples (a
    # dict of small arrays per task cost a cluster ten times the work in serialisation)
    keys = np.array(sorted({i for kt in key_tuples for i in kt}), np.int64)
    lengths = np.array([len(lists[i]) for i in keys], np.int64)
    rows = np.concatenate([lists[i] for i in keys])
    used = np.unique(rows)
    packed = ({f: t[f][used] for f in _COMBINE_FIELDS}, keys, lengths,
              np.searchsorted(used, rows))  # fmt: skip
    shared = None
    err_all = np.array([errors[kt] for kt in key_tuples], float)
    kt_array = np.array(key_tuples, np.int64)
    while True:
        # chunks of about COMBINATIONS crossed rows each (a small search: one, in this process)
        tasks = max(1, min(4 * runner.parallel, math.ceil(sizes.sum() / COMBINATIONS)))
        chunk = max(1, -(-len(key_tuples) // tasks))
        if tasks > 1 and shared is None:
            shared = runner.share(packed)
        args = [(shared if tasks > 1 else packed, kt_array[a : a + chunk],
                 err_all[a : a + chunk], plan.objective, plan.rated, keep)
                for a in range(0, len(key_tuples), chunk)]  # fmt: skip
        parts = runner.map(_combine_task, args) if len(args) > 1 else [_combine_task(*args[0])]
        c = np.concatenate([p[0] for p in parts])
        err = np.concatenate([p[1] for p in parts])
        c = c[_score_order(t, c, err, plan.objective, plan.rated)]
        complete = all(len(p[0]) < keep for p in parts)
        out = []
        for start in range(0, len(c), 4 * top):
            batch = c[start : start + 4 * top]
            if full_checks:
                todo = sorted({_ident(t, s, names) for s in batch.ravel()} - set(verdicts))
                if todo:
                    size = max(1, -(-len(todo) // (2 * runner.parallel)))
                    groups = [todo[i : i + size] for i in range(0, len(todo), size)]
                    results = runner.map(_check_task, [(g, cr) for g in groups])
                    for group, res in zip(groups, results, strict=True):
                        verdicts.update(zip(group, res, strict=True))
                        checked += len(group)
            for combo in batch:
                if full_checks and not all(verdicts[_ident(t, s, names)] for s in combo):
                    continue
                out.append(_gearbox(combo, t, plan, target, names))
                if len(out) == top:
                    return out, checked
        if complete:
            return out, checked
        keep *= 4  # failing checks used up the best: combine deeper


def _ident(t: dict, row, names) -> tuple:
    """A stage as checked: scheme, teeth, planets, module."""
    row = int(row)
    return (names[int(t["scheme"][row])], *(int(t[f][row]) for f in ("z1", "z2", "z2p", "z3",
            "k")), float(t["module"][row]))  # fmt: skip


def _check_task(group, cr) -> list[bool]:
    """Full checks (:meth:`Planetary.check`) of a batch of stages (a task)."""
    return [_stage_ok(_candidate(*g[:6], Fraction(1), g[6]), cr) for g in group]


def _stage_ok(c: Candidate, min_contact_ratio: float) -> bool:
    try:
        return c.stage.check(min_contact_ratio=min_contact_ratio).ok
    except ValueError:  # a stage that cannot be built is not a design
        return False


def _gearbox(combo, t, plan: _Plan, target, names) -> Gearbox:
    rows = [int(r) for r in combo]
    stages = tuple(
        Candidate(tuple(int(t[f][r]) for f in ("z1", "z2", "z2p", "z3")), int(t["k"][r]),
                  Fraction(int(t["num"][r]), int(t["den"][r])), 0.0, 0, False,
                  names[int(t["scheme"][r])], float(t["module"][r]))
        for r in rows
    )  # fmt: skip
    ratio = math.prod((c.ratio for c in stages), start=Fraction(1))
    common = dict(
        stages=stages, ratio=ratio, ratio_error=float(abs(ratio - target) / target),
        ring=max(c.teeth[3] * c.module for c in stages),
        teeth=int(sum(int(t["total"][r]) for r in rows)),
        efficiency=math.prod(_stage_efficiency(c) for c in stages),
    )  # fmt: skip
    if not plan.rated:
        return Gearbox(**common)
    return Gearbox(
        **common, face_widths=tuple(float(t["face_width"][r]) for r in rows),
        safety=tuple((float(t["S_H"][r]), float(t["S_F"][r])) for r in rows),
        volume=float(sum(t["volume"][r] for r in rows)),
        mass=float(sum(t["mass"][r] for r in rows)),
        torques=tuple(float(t["torque"][r]) for r in rows),
        speeds=tuple(float(t["speed"][r]) for r in rows),
        mesh_efficiency=math.prod(float(t["mesh_eta"][r]) for r in rows),
        stage_efficiencies=tuple(float(t["mesh_eta"][r]) for r in rows),
    )  # fmt: skip


def _as_train_error(fn, *args):
    """``fn(*args)`` with a bad argument reported as this package's error."""
    try:
        return fn(*args)
    except GearError as exc:
        raise TrainError(str(exc)) from None
