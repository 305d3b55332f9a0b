"""Layer 1, base.

The geometric conditions of a train of real gears, as vectorised numpy functions.

Pure formulas (no classes, no trains): :class:`trains.willis.Train` (``Train.check``) and
:class:`trains.planetary.stage.Planetary` both evaluate them. Below them, the findings
``Train.check`` reports from them on a train's relations (coaxial groups, one gear meshing twice,
identical planets), as functions of the relations and members.

* assembly number of identical planets between two central gears (lectures §4.3,
  KHK Gear Technical Reference): ``T = |z_b z_c - s_a s_b z_a z_d| / gcd(z_c, z_d)``, s = -1 for an
  external mesh and +1 for an internal one; ``k`` equally spaced planets assemble iff
  ``T % k == 0``;
* neighbour gap of ``k`` planets in one row: ``2 a_w sin(pi/k) - d_a`` (Ozols §21-13), and of
  ``k`` bevel planets on a common apex (a differential's pinions);
* closure of a chain of centre distances between two coaxial axes: two distances must be equal
  (the reverted-train and planetary coaxiality condition ``a_w12 = a_w34``), three or more form
  a polygon that closes iff the longest side does not exceed the sum of the others.

Examples
--------
>>> int(assembly_number(18, 45, 45, 108, internal_b=True))   # lectures §4.3: z_s + z_r
126
>>> round(float(neighbour_gap(63.0, 94.0, 3)), 4)   # 2 x 63 sin 60 deg - 94
15.1192
>>> float(closure_margin([57.0, 58.0], tolerance=0.01))
-0.99
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from gears import BevelPair, Finding, Gear, GearError, GearPair
from gears.arguments import check_flag
from trains.errors import TrainError

__all__ = [
    "assembly_number",
    "bevel_neighbour_gap",
    "closure_margin",
    "neighbour_gap",
    "refuse_failing",
]


def assembly_number(z_a, z_c, z_d, z_b, internal_a=False, internal_b=False):
    """Assembly number T of planets between central gears a and b (integer arithmetic).

    Parameters
    ----------
    z_a, z_b : int or array
        Tooth counts of the two central gears.
    z_c, z_d : int or array
        Tooth counts of the planet's gears meshing a and b (equal for a simple planet).
    internal_a, internal_b : bool or array
        True where the mesh with that central gear is internal.

    Returns
    -------
    int or array
        ``|z_b z_c - s_a s_b z_a z_d| // gcd(z_c, z_d)``: planet positions per turn.
    """
    z_a, z_c, z_d, z_b = (np.asarray(v, dtype=np.int64) for v in (z_a, z_c, z_d, z_b))
    s = np.where(np.asarray(internal_a, bool), 1, -1) * np.where(
        np.asarray(internal_b, bool), 1, -1
    )
    out = np.abs(z_b * z_c - s * z_a * z_d) // np.gcd(z_c, z_d)
    return out[()] if out.ndim == 0 else out


def neighbour_gap(center_distance, tip_diameter, n):
    """Gap between the tip circles of ``n`` equally spaced planets at ``center_distance`` (mm).

    ``2 a_w sin(pi/n) - d_a``; infinite for one planet.
    """
    a = np.asarray(center_distance, float)
    d = np.asarray(tip_diameter, float)
    n = np.asarray(n, float)
    with np.errstate(divide="ignore"):
        out = np.where(n >= 2, 2.0 * a * np.sin(np.pi / np.maximum(n, 1.0)) - d, np.inf)
    return out[()] if out.ndim == 0 else out


def bevel_neighbour_gap(face_angle, reach, n):
    """Gap between ``n`` equally spaced bevel planets on a common apex (the pinions of a
    differential), mm: their axes are ``360/n`` deg apart and each face cone (half angle
    ``face_angle`` deg) reaches ``reach`` mm from the apex at its outer tips, so the cones clear
    each other by ``reach (2 pi / n - 2 delta_a)`` (an arc at the outer tips); infinite for one.

    >>> round(float(bevel_neighbour_gap(36.0, 30.0, 4)), 4)   # 30 mm x (90 - 72) deg
    9.4248
    """
    da = np.radians(np.asarray(face_angle, float))
    r = np.asarray(reach, float)
    n = np.asarray(n, float)
    with np.errstate(divide="ignore"):
        out = np.where(n >= 2, r * (2.0 * np.pi / np.maximum(n, 1.0) - 2.0 * da), np.inf)
    return out[()] if out.ndim == 0 else out


def closure_margin(distances, tolerance=0.0):
    """Signed margin (mm) for a chain of centre distances to join two coaxial axes.

    One distance: the axes cannot coincide (margin ``tolerance - a``). Two distances (one
    intermediate shaft: a reverted train, sun-planet-ring): ``tolerance - |a_1 - a_2|``. Three
    or more: the polygon of the distances closes, ``sum - 2 max`` (>= 0). ``distances`` runs
    over the last axis, so many chains of equal length evaluate at once.
    """
    d = np.asarray(distances, float)
    if d.shape[-1] == 1:
        out = tolerance - d[..., 0]
    elif d.shape[-1] == 2:
        out = tolerance - np.abs(d[..., 0] - d[..., 1])
    else:
        out = d.sum(axis=-1) - 2.0 * d.max(axis=-1)
    return out[()] if np.ndim(out) == 0 else out


# ------------------------------------------------------------- the findings of Train.check


def coaxiality_finding(group: tuple[str, ...], members, relations, tolerance: float) -> Finding:
    """The ``coaxiality(a, b, ...)`` finding of :meth:`trains.Train.check` for one coaxial group
    of ``members``: every chain of real-gear meshes (``relations``) between two of them closes."""
    name = f"coaxiality({', '.join(group)})"
    shaft = {m: m for m in members}  # coupled members turn on one shaft: one axis

    def axis(m: str) -> str:
        while shaft[m] != m:
            m = shaft[m]
        return m

    for r in relations:
        if r.kind == "couple":
            shaft[axis(r.a)] = axis(r.b)
    edges: dict[str, list[tuple[str, Any]]] = {}
    for r in relations:
        a, b = axis(r.a), axis(r.b)
        if r.kind == "mesh" and isinstance(r.pair, GearPair) and a != b:
            edges.setdefault(a, []).append((b, r))
            edges.setdefault(b, []).append((a, r))
    axes = list(dict.fromkeys(axis(m) for m in group))
    inside = set(axes)
    paths: list[tuple[str, list[Any]]] = []
    for start in axes:
        stack = [(start, [start], [])]
        while stack and len(paths) < 1000:
            node, seen, rels = stack.pop()
            for nxt, r in edges.get(node, ()):
                if nxt in seen or len(rels) >= 8:
                    continue
                if nxt in inside:
                    if axes.index(nxt) > axes.index(start):
                        paths.append((" - ".join([*seen, nxt]), [*rels, r]))
                    continue
                stack.append((nxt, [*seen, nxt], [*rels, r]))
    if not paths:
        return Finding(
            name, 0.0,
            f"no chain of real-gear meshes joins {', '.join(group)}: coaxiality not checked"
            " (give the meshes gears=)", ok=True,
        )  # fmt: skip
    worst, text = math.inf, []
    for label, rels in paths:
        dist = [r.pair.center_distance for r in rels]
        margin = float(closure_margin(dist, tolerance))
        worst = min(worst, margin)
        text.append(f"{label}: a_w {' / '.join(f'{d:.4f}' for d in dist)} mm")
    rule = f"equal within {tolerance:g} mm; chains of 3+ close as a polygon"
    return Finding(name, worst, f"{'; '.join(text)} ({rule})")


def same_gear_findings(relations) -> list[Finding]:
    """The ``<member>.same_gear`` findings of :meth:`trains.Train.check`."""
    seen: dict[tuple[str, int, float], tuple[str, Gear]] = {}
    out: list[Finding] = []
    for r in relations:
        if r.pair is None or r.gears is None:  # kinematic, or a worm mesh (no Gear objects)
            continue
        for member, gear in ((r.a, r.gears[0]), (r.b, r.gears[1])):
            key = (member, gear.teeth, gear.module)
            if key not in seen:
                seen[key] = (r.name, gear)
                continue
            first, g0 = seen[key]
            diffs = []
            for attr, unit in (("profile_shift", ""), ("helix_angle", " deg"),
                               ("pressure_angle", " deg"), ("face_width", " mm")):  # fmt: skip
                x, y = getattr(g0, attr), getattr(gear, attr)
                if x is not None and y is not None and not math.isclose(x, y, abs_tol=1e-12):
                    diffs.append((attr, x, y, unit))
            name = f"{member}.same_gear"
            if any(f.name == name for f in out):
                continue
            if diffs:
                unit = {"profile_shift": "module"}.get(diffs[0][0], diffs[0][3].strip())
                d = abs(diffs[0][1] - diffs[0][2])
                what = ", ".join(f"{a} {x:g}{u} vs {y:g}{u}" for a, x, y, u in diffs)
                out.append(Finding(
                    name, -d,
                    f"{member} meshes in {first} and {r.name} with one gear of {gear.teeth}"
                    f" teeth, module {gear.module:g}, but the two descriptions differ:"
                    f" {what} (a stepped gear needs another tooth count or module)",
                    unit=unit,
                ))  # fmt: skip
    return out


def planet_findings(planet_meshes, planets, relations, clearance: float) -> list[Finding]:
    """The ``<planet>.assembly`` and ``<planet>.neighbour`` findings of :meth:`trains.Train.check`
    for each planet of ``planet_meshes`` (planet, its meshes with central members, carrier) with
    ``planets[planet]`` copies."""
    out: list[Finding] = []
    for planet, central, _carrier in planet_meshes:
        k = planets[planet]
        if k < 2:
            continue
        real = [r for r in central if r.pair is not None]
        if not real:
            continue  # a kinematic-only planet: nothing to check
        if len(central) == 2:
            z, internal = [], []
            for r in central:
                on_a = r.a == planet
                z.append((r.teeth[1] if on_a else r.teeth[0], r.teeth[0] if on_a else r.teeth[1]))
                internal.append(r.internal or r.opposed)
            (za, zc), (zb, zd) = z
            t = int(assembly_number(za, zc, zd, zb, internal[0], internal[1]))
            rem = t % k if t else 0
            ok = rem == 0
            names = " and ".join(r.name for r in central)
            out.append(Finding(
                f"{planet}.assembly", -float(min(rem, k - rem)) + 0.0,
                f"{k} equally spaced planets {planet} ({names}): assembly number T = {t}"
                f" {'is' if ok else 'is not'} a multiple of {k} (lectures §4.3)",
                unit="teeth", ok=ok,
            ))  # fmt: skip
        tips, modules = [], []
        for r in relations:
            got = r.gear_of(planet) if r.kind == "mesh" else None
            if got is not None:
                tips.append(got[1])
                modules.append(got[0].module)
        if isinstance(real[0].pair, BevelPair):
            out.append(bevel_neighbour_finding(planet, real[0], k, clearance))
            continue
        tips_by_gear = max(tips)
        a = real[0].pair.center_distance
        gap = float(neighbour_gap(a, tips_by_gear, k))
        need = clearance * max(modules)
        out.append(Finding(
            f"{planet}.neighbour", gap - need,
            f"{k} planets {planet} at a_w = {a:.4f} mm: gap between tip circles (d_a ="
            f" {tips_by_gear:.4f} mm) {gap:.4f} mm vs clearance {need:.4f} mm",
        ))  # fmt: skip
    return out


def bevel_neighbour_finding(planet: str, r, k: int, clearance: float) -> Finding:
    """``k`` bevel planets on a common apex, their axes 360/k deg apart (a differential's
    pinions): the gap between their face cones at the outer tips
    (:func:`trains.conditions.bevel_neighbour_gap`) against ``clearance`` modules."""
    gear = r.gears[0] if r.a == planet else r.gears[1]
    reach = math.hypot(gear.cone_distance, gear.addendum)
    gap = float(bevel_neighbour_gap(gear.face_angle, reach, k))
    need = clearance * gear.module
    return Finding(
        f"{planet}.neighbour", gap - need,
        f"{k} bevel planets {planet} (face cone {gear.face_angle:.4f} deg, outer tips "
        f"{reach:.4f} mm from the apex): gap between neighbours {gap:.4f} mm vs clearance "
        f"{need:.4f} mm",
    )  # fmt: skip


def refuse_failing(design: Any, check: bool, what: str) -> None:
    """Refuse to draw a design (a planetary stage, a differential) that fails its ``check()``
    (planets or pinions that collide, teeth that interfere) unless ``check`` is False: its
    ``what`` (scene, animation) would show what cannot be built."""
    try:
        check = check_flag("check", check)
    except GearError as exc:
        raise TrainError(str(exc)) from None
    if check:
        failed = design.check().failed()
        if failed:
            raise TrainError(
                f"{design!r} fails its checks ({', '.join(failed)}: see check()), so its {what} "
                "would show what cannot be built; fix the design, or pass check=False to draw "
                "it anyway"
            )
