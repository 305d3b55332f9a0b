"""Layer 6, candidates: the candidate space of a pair search, its columns and limits, built from
the arguments of :func:`gears.search.pairs` (every bad one a GearError before any work).

The space is small and picklable (a Dask task carries it): the (module, helix, z1, z2) rows, the
profile shifts, the rules and limits, the face widths and the load case.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from gears.errors import GearError
from gears.geometry import check_real, transverse_pressure_angle
from gears.meshing import center_distance_shift_sum
from gears.rack import BasicRack
from gears.rating.sizing import Load, load_case
from gears.search.tables import TABLE_FORMATS

__all__ = ["Limits"]

_KEYS = ("module", "helix_angle", "z1", "z2", "x1", "x2")
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
#: and with a torque: each gear's safety against pitting and bending, the smaller of each, and
#: the mesh efficiency at the load (ISO/TR 14179-2; a spectrum's by energy)
_SAFETY = ("S_H1", "S_H2", "S_F1", "S_F2", "S_H", "S_F", "mesh_efficiency")


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


def candidate_space(
    ratio=None, center_distance=None, module=1.0, teeth=(12, 60), shifts=(-0.5, 1.0, 0.1),
    helix=0.0, *, ratio_tolerance=0.01, split="proportional", pressure_angle=None, rack=None,
    internal=False, tip_shortening=True, limits=None, objective=None, top=20,
    friction=0.1, torque=None, speed=None, material="case-carburized", face_width=None,
    life=20000.0, min_safety=None, smallest_width=True, dataset=None, chunk_size=1 << 16,
    **rating_options,
) -> _Space:  # fmt: skip
    """The checked candidate space of :func:`gears.search.pairs` (its arguments but the
    scheduler's); every bad argument is a GearError here, before any work."""
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
            s_lo, s_hi = 2 * lo, 2 * hi  # x1 + x2, a ring's x2 in DIN 3960's sign too
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
    return space


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
    spectrum = options.pop("spectrum", None)
    if torque is None and spectrum is None:
        extra = [k for k, v in (("speed", speed), ("min_safety", min_safety)) if v is not None]
        extra += list(options)
        if extra:
            raise GearError(f"{', '.join(extra)} rate the candidates under a load: "
                            "give torque= (N m on gear 1) and speed= (rpm) too")  # fmt: skip
        return widths, None, density
    if speed is None and spectrum is None:
        raise GearError("torque= needs speed= (rpm of gear 1) to rate the candidates")
    if widths is None:
        raise GearError(
            f"{'torque' if spectrum is None else 'spectrum'}= needs face_width=: a width in "
            "mm, a list of widths, or (low, high, step); each candidate is rated at each width "
            "(the smallest that carries the load is kept)"
        )
    if spectrum is not None and life != 20000.0:
        raise GearError("life= and spectrum= exclude each other: the spectrum gives the hours")
    load = load_case(torque, speed, material_, None if spectrum is not None else life,
                     min_safety, spectrum=spectrum, **options)  # fmt: skip
    return widths, load, density


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
