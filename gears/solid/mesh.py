"""Layer 7, solids and frames.

3D gear solids and scenes built on the exact 2D outlines (trimesh, the ``mesh`` extra).

This module sits above the 2D outline code and below the classes: it works on shapely Polygons
and numbers only (``Gear.mesh``, ``GearPair.scene`` and ``Planetary.scene`` are thin views that
pass it their outlines and placements). It needs no CAD kernel.

Conventions
-----------
- The gear axis is +z and the mid-plane is z = 0; the section at z = 0 is the 2D outline itself.
- A helical gear's transverse section turns with the lead: by ``theta(z) = 2 z tan(beta) / d``
  radians at height z (ISO 21771: a right hand has beta > 0 and turns counter-clockwise seen
  from +z as z grows), so the *twist* over the face width b is ``2 b tan(beta) / d``
  (:func:`helix_twist`, in degrees).
- The number of axial slices comes from the tolerance: a vertex at radius r turns by
  ``dtheta`` between two slices, and the chord between them deviates from the true helix by
  ``r (1 - cos(dtheta / 2))``; :func:`slice_count` keeps that below ``tolerance`` at the largest
  radius of the outline. The transverse outline keeps its own tolerance, so a section deviates
  from the exact gear by at most about twice the tolerance.
- A herringbone gear is two opposite-hand halves meeting at the mid-plane: the lower half
  (z < 0) has the given hand, the upper half the opposite one.

The solid is built directly: one triangulated cap (mapbox-earcut, or manifold3d's robust
triangulator when earcut would drop a vertex) and quads between consecutive slices. Every vertex
is an outline vertex turned to its slice, so the mesh is welded by construction, watertight,
consistently wound with outward normals, and its spur volume is the outline area times the face
width to rounding.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

import numpy as np
import shapely

from gears.arguments import (
    check_angle,
    check_flag,
    check_length,
    check_tolerance,
)
from gears.budget import check_budget
from gears.errors import GearError

__all__ = [
    "gear_solid",
    "helix_twist",
    "loft_solid",
    "scene",
    "slice_count",
    "solid_levels",
    "solid_radius",
    "to_manifold",
    "transform",
]

#: Default colours (RGBA 0-255) of the scene builders, by role.
COLOURS = {
    "gear1": (70, 130, 180, 255),
    "gear2": (222, 140, 60, 255),
    "sun": (205, 92, 92, 255),
    "planet": (70, 130, 180, 255),
    "planet2": (100, 160, 90, 255),
    "ring": (150, 150, 150, 255),
    "carrier": (200, 190, 120, 255),
}


def _trimesh():
    try:
        import trimesh
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise GearError("3D meshes need trimesh: pip install 'geartrain[mesh]'") from exc
    return trimesh


def helix_twist(face_width, helix_angle, reference_diameter):
    """Twist of the transverse section over the face width, degrees: ``2 b tan(beta) / d``.

    Signed as ISO 21771: right hand (beta > 0) turns counter-clockwise seen from +z as z grows.
    Vectorised (numpy broadcasting).

    Examples
    --------
    >>> round(float(helix_twist(10.0, 45.0, 20.0 / math.pi)), 9)   # b tan 45 = 10, d = 20/pi
    180.0
    """
    b = np.asarray(face_width, dtype=float)
    beta = np.radians(np.asarray(helix_angle, dtype=float))
    d = np.asarray(reference_diameter, dtype=float)
    out = np.degrees(2.0 * b * np.tan(beta) / d)
    return out if out.ndim else out[()]


#: The most a section turns between two slices, degrees, however coarse the tolerance: the quads
#: between slices stay near planar (a tolerance larger than the gear once gave one slice for a
#: 121-degree twist, and a self-intersecting solid of negative volume).
MAX_SLICE_TURN = 15.0


def _slices(twist, radius, tolerance):
    """:func:`slice_count` as floats (no integer overflow for an absurd twist)."""
    t = np.radians(np.abs(np.asarray(twist, dtype=float)))
    r = np.asarray(radius, dtype=float)
    tol = np.asarray(tolerance, dtype=float)
    step = 2.0 * np.arccos(np.clip(1.0 - tol / r, -1.0, 1.0))
    step = np.minimum(step, math.radians(MAX_SLICE_TURN))
    return np.maximum(1.0, np.ceil(t / step - 1e-12))


def slice_count(twist, radius, tolerance):
    """Axial slices needed so a vertex at ``radius`` that turns by ``twist`` degrees keeps its
    chord within ``tolerance`` of the true helix: ``r (1 - cos(dtheta / 2)) <= tolerance``, and
    turns by at most :data:`MAX_SLICE_TURN` a slice.

    At least 1 (a prism). Vectorised.

    Examples
    --------
    >>> int(slice_count(0.0, 10.0, 0.01)), int(slice_count(180.0, 10.0, 0.01))
    (1, 36)
    """
    n = _slices(twist, radius, tolerance)
    if not np.all(n <= 2.0**53):  # NaN too
        raise GearError(
            f"twist = {np.ravel(twist)[0]!r} deg at tolerance = {np.ravel(tolerance)[0]!r} mm "
            "needs more slices than any solid can hold; use a coarser tolerance or less twist"
        )
    out = n.astype(np.int64)
    return out if out.ndim else out[()]


def solid_levels(twist: float, radius: float, tolerance: float, herringbone: bool = False):
    """Vertex levels (slices + 1) of :func:`gear_solid` for a section that turns by ``twist``
    degrees, held to ``tolerance`` at ``radius``: a float, so the budget can be checked
    before any count is made (:func:`gears.budget.check_budget`). Vectorised over tolerance.

    >>> float(solid_levels(0.0, 10.0, 0.01)), float(solid_levels(180.0, 10.0, 0.01))
    (2.0, 37.0)
    """
    if herringbone:
        half = np.where(twist != 0, _slices(np.asarray(twist) / 2.0, radius, tolerance), 1.0)
        return 2.0 * half + 1.0
    return np.where(twist != 0, _slices(twist, radius, tolerance), 1.0) + 1.0


def solid_radius(outline) -> float:
    """The largest vertex radius of an outline (about its own axis, the origin), mm."""
    xy = shapely.get_coordinates(outline)
    return float(np.max(np.hypot(xy[:, 0], xy[:, 1]))) if len(xy) else 0.0


def _rings(outline) -> list[np.ndarray]:
    """Rings of a valid polygon: exterior counter-clockwise, holes clockwise, no repeated or
    collinear vertices, closing point dropped."""
    if not isinstance(outline, shapely.Polygon):
        raise GearError(f"expected a shapely Polygon outline; got {type(outline).__name__}")
    if outline.is_empty or not outline.is_valid or outline.area <= 0.0:
        raise GearError("the outline must be a valid polygon of positive area")
    p = shapely.orient_polygons(shapely.simplify(outline, 0.0), exterior_cw=False)
    return [np.asarray(r.coords)[:-1, :2] for r in (p.exterior, *p.interiors)]


def _cap(rings: list[np.ndarray]) -> np.ndarray:
    """Triangles (indices into the stacked rings, counter-clockwise seen from +z) using every
    vertex: earcut when it keeps them all, else manifold3d's robust triangulator."""
    pts = np.concatenate(rings)
    n, holes = len(pts), len(rings) - 1
    expected = n + 2 * holes - 2
    try:
        import mapbox_earcut as earcut

        ends = np.cumsum([len(r) for r in rings]).astype(np.uint32)
        tri = np.asarray(earcut.triangulate_float64(pts, ends), dtype=np.int64).reshape(-1, 3)
    except ImportError:  # pragma: no cover - earcut is in the mesh extra
        tri = np.empty((0, 3), dtype=np.int64)
    if len(tri) == expected and len(np.unique(tri)) == n:
        a, b, c = pts[tri[:, 0]], pts[tri[:, 1]], pts[tri[:, 2]]
        area = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
        if np.all(area > 0.0):
            return tri
    try:
        import manifold3d
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise GearError("3D meshes need manifold3d: pip install 'geartrain[mesh]'") from exc
    return np.asarray(manifold3d.triangulate(rings), dtype=np.int64)


def gear_solid(
    outline, face_width: float, twist: float = 0.0, tolerance: float = 0.01,
    tip_radius: float | None = None, herringbone: bool = False, lead=None,
):  # fmt: skip
    """A gear solid from its transverse outline: a prism, a helical twist or a herringbone.

    Parameters
    ----------
    outline : shapely.Polygon
        Transverse outline centred on the axis (holes allowed: bores, ring gears).
    face_width : float
        Axial length b, mm; the solid spans ``-b/2 <= z <= b/2``.
    twist : float
        Degrees the section turns over the face width, :func:`helix_twist` (right hand > 0).
        For a herringbone gear, the rate of each half (each half turns by ``twist / 2``).
    tolerance : float
        Largest chord deviation from the true helix, mm, at ``tip_radius``.
    tip_radius : float, optional
        Radius at which the helix chord is held to ``tolerance``; default the outline's
        largest vertex radius (conservative for rings, whose rim lies outside the teeth).
    herringbone : bool
        Two opposite-hand halves meeting at z = 0 (the lower half has the hand of ``twist``).
    lead : tuple, optional
        A lead modification along the face, ``(turns_of, relief_of, levels)``: ``turns_of
        (rings)`` gives each vertex's turn (radians) per mm of relief, ``relief_of(z)`` the
        relief (mm) at the axial positions ``z``, and ``levels`` the axial positions the
        relief needs (its kinks, and enough between them to hold its curve within the
        tolerance); each level's vertices turn by their share of its relief
        (:func:`gears.contact.flank.solid_lead`).

    Returns
    -------
    trimesh.Trimesh
        Watertight, consistently wound, outward normals, welded.

    Raises
    ------
    GearError
        For a face width outside :data:`gears.arguments.LENGTH_RANGE` times the outline's
        radius, a tolerance that is not a number > 0, a twist that is not a finite number of
        degrees, an invalid outline, or a solid over the mesh budget
        (:data:`gears.budget.BUDGETS`; the message names the tolerance that fits).

    Examples
    --------
    >>> sq = shapely.box(-1.0, -1.0, 1.0, 1.0)
    >>> m = gear_solid(sq, 2.0)
    >>> m.is_watertight, float(m.volume), m.bounds[:, 2].tolist()
    (True, 8.0, [-1.0, 1.0])
    """
    trimesh = _trimesh()
    rings = _rings(outline)
    pts = np.concatenate(rings)
    n_pts = len(pts)
    r_out = float(np.max(np.hypot(pts[:, 0], pts[:, 1])))
    of = "the outline's radius"
    b = check_length("face_width", face_width, r_out, of)
    tol = check_tolerance(
        tolerance, floor=1e-9 * r_out,
        why=f"1e-9 of the outer radius {r_out:g} mm: a larger module or more teeth need a "
        "coarser tolerance",
    )  # fmt: skip
    twist = check_angle("twist", twist)
    herringbone = check_flag("herringbone", herringbone)
    r = r_out if tip_radius is None else check_length("tip_radius", tip_radius, r_out, of)
    check_budget(
        "mesh", f"a solid of {n_pts} outline vertices twisted by {twist:.6g} deg",
        lambda t: n_pts * float(solid_levels(twist, r, t, herringbone)), tol,
        hint="a coarser outline",
    )  # fmt: skip
    rate = math.radians(twist) / b  # radians per mm
    if herringbone:
        half = int(slice_count(twist / 2.0, r, tol)) if twist else 1
        z = np.linspace(-b / 2.0, b / 2.0, 2 * half + 1)
        theta = -rate * np.abs(z)  # lower half: theta = rate z (z < 0)
    else:
        n = int(slice_count(twist, r, tol)) if twist else 1
        z = np.linspace(-b / 2.0, b / 2.0, n + 1)
        theta = rate * z
    unit = None
    if lead is not None:
        turns_of, relief_of, extra = lead
        unit = np.asarray(turns_of(rings), float)
        z = np.unique(np.round(np.concatenate([z, np.clip(extra, -b / 2.0, b / 2.0)]), 12))
        theta = -rate * np.abs(z) if herringbone else rate * z
    levels = len(z)
    hole = np.repeat(np.arange(len(rings)) > 0, [len(rr) for rr in rings])
    if levels > 2 or rate:
        # one-sided: the chord between two slices of a vertex at radius r runs at
        # r cos(dtheta / 2), towards the axis: inside an outer ring's material, but in the space
        # of a hole (a ring gear's teeth). The holes grow by 1 / cos(dtheta / 2), so every
        # chord of theirs touches its helix at mid-step and lies in the material elsewhere
        grow = 1.0 / math.cos(float(np.max(np.abs(np.diff(theta)))) / 2.0)
        pts = np.where(hole[:, None], pts * grow, pts)
        rings = np.split(pts, np.cumsum([len(rr) for rr in rings])[:-1])
    theta = theta[:, None]
    if unit is not None:
        theta = theta + np.asarray(relief_of(z), float)[:, None] * unit[None, :]
    c, s = np.cos(theta), np.sin(theta)
    verts = np.empty((levels, n_pts, 3))
    verts[:, :, 0] = c * pts[:, 0] - s * pts[:, 1]
    verts[:, :, 1] = s * pts[:, 0] + c * pts[:, 1]
    verts[:, :, 2] = z[:, None]
    # side quads: edge i -> j of each ring, between level k and k + 1
    i = np.arange(n_pts)
    j = np.concatenate([np.roll(np.arange(len(rr)), -1) for rr in rings])
    j += np.repeat(np.cumsum([0] + [len(rr) for rr in rings[:-1]]), [len(rr) for rr in rings])
    k = (np.arange(levels - 1) * n_pts)[:, None]
    a, bb, cc, d = i + k, j + k, j + k + n_pts, i + k + n_pts
    v = verts.reshape(-1, 3)
    if levels > 2 or rate:
        # split each twisted quad along the diagonal that bulges outwards on an outer ring (the
        # chords of the helices lie inside the true surface, so this halves the volume
        # deficit) and inwards, into the material, on a hole (its chords touch the surface)
        normal = np.cross(v[bb] - v[a], v[d] - v[a])
        bulge = np.einsum("...i,...i->...", v[a] + v[cc] - v[bb] - v[d], normal)
        flip = (bulge < 0.0) != hole
    else:
        flip = np.zeros(a.shape, dtype=bool)
    t1 = np.where(flip[..., None], np.stack([a, bb, d], -1), np.stack([a, bb, cc], -1))
    t2 = np.where(flip[..., None], np.stack([bb, cc, d], -1), np.stack([a, cc, d], -1))
    side = np.stack([t1, t2], -2).reshape(-1, 3)
    cap = _cap(rings)
    faces = np.concatenate([cap[:, ::-1], side, cap + (levels - 1) * n_pts])
    return trimesh.Trimesh(v, faces, process=False)


def loft_solid(levels):
    """A watertight solid through planar rings stacked along +z: ``levels`` is an array
    ``(L, N, 3)`` of ``L >= 2`` closed rings of ``N`` vertices each (the closing vertex not
    repeated), each ring at one height, the heights increasing, counter-clockwise seen from +z,
    vertex ``i`` of one ring joined to vertex ``i`` of the next by quads; the end rings are
    capped (:func:`_cap`). Welded and consistently wound with outward normals, by construction.

    Examples
    --------
    >>> sq = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])
    >>> lv = np.stack([np.column_stack([sq, np.full(4, z)]) for z in (0.0, 1.0, 2.0)])
    >>> m = loft_solid(lv)
    >>> m.is_watertight, round(float(m.volume), 12)
    (True, 8.0)
    """
    trimesh = _trimesh()
    v = np.asarray(levels, dtype=float)
    if v.ndim != 3 or v.shape[0] < 2 or v.shape[1] < 3 or v.shape[2] != 3:
        raise GearError(f"levels of shape {v.shape}; valid is (L >= 2, N >= 3, 3)")
    if not np.all(np.isfinite(v)):
        raise GearError("levels hold a coordinate that is not finite")
    n_lv, n = v.shape[:2]
    i = np.arange(n)
    j = np.roll(i, -1)
    k = (np.arange(n_lv - 1) * n)[:, None]
    a, b, c, d = i + k, j + k, j + k + n, i + k + n
    side = np.stack([np.stack([a, b, c], -1), np.stack([a, c, d], -1)], -2).reshape(-1, 3)
    cap = _cap([v[0, :, :2]])
    top = _cap([v[-1, :, :2]])
    faces = np.concatenate([cap[:, ::-1], side, top + (n_lv - 1) * n])
    return trimesh.Trimesh(v.reshape(-1, 3), faces, process=False)


def transform(angle: float = 0.0, center=(0.0, 0.0), z: float = 0.0) -> np.ndarray:
    """4x4 placement: turn by ``angle`` degrees about +z, then move the axis to ``center``
    (and the mid-plane to ``z``).

    Examples
    --------
    >>> transform(90.0, (1.0, 2.0)).round(12)[:2].tolist()
    [[0.0, -1.0, 0.0, 1.0], [1.0, 0.0, 0.0, 2.0]]
    """
    t = math.radians(float(angle))
    m = np.eye(4)
    m[0, 0], m[0, 1], m[1, 0], m[1, 1] = math.cos(t), -math.sin(t), math.sin(t), math.cos(t)
    m[0, 3], m[1, 3], m[2, 3] = float(center[0]), float(center[1]), float(z)
    return m


def _rgba(colour) -> list[int]:
    if colour is None:
        return [180, 180, 180, 255]
    c = [float(v) for v in colour]
    if len(c) == 3:
        c.append(255.0 if max(c) > 1.0 else 1.0)
    if len(c) != 4:
        raise GearError(f"colour = {colour!r} must be RGB or RGBA (0-1 or 0-255)")
    if max(c) <= 1.0:
        c = [v * 255.0 for v in c]
    return [round(min(255.0, max(0.0, v))) for v in c]


def scene(parts: Iterable[Sequence]):
    """A ``trimesh.Scene`` from ``(name, mesh, transform, colour)`` parts.

    Parts that pass the *same* mesh object share one geometry (instanced by node transforms),
    so a GLB of a planetary stage stores one planet mesh. The geometry is named by
    ``mesh.metadata["name"]`` when set, otherwise by its first node. ``transform`` is a 4x4
    matrix (None: identity; see :func:`transform`); ``colour`` RGB(A), 0-1 or 0-255, becomes a
    PBR material of the geometry (the first part's colour wins for a shared mesh).

    Examples
    --------
    >>> box = _trimesh().creation.box()
    >>> s = scene([("a", box, transform(0, (0, 0)), (1, 0, 0)),
    ...            ("b", box, transform(0, (3, 0)), None)])
    >>> len(s.geometry), sorted(s.graph.nodes_geometry)
    (1, ['a', 'b'])
    """
    trimesh = _trimesh()
    from trimesh.visual import TextureVisuals
    from trimesh.visual.material import PBRMaterial

    out = trimesh.Scene()
    names: dict[int, str] = {}
    seen: set[str] = set()
    for part in parts:
        if len(part) < 2 or len(part) > 4:
            raise GearError("each scene part is (name, mesh[, transform[, colour]])")
        name, mesh = str(part[0]), part[1]
        matrix = part[2] if len(part) > 2 and part[2] is not None else np.eye(4)
        colour = part[3] if len(part) > 3 else None
        matrix = np.asarray(matrix, dtype=float)
        if matrix.shape != (4, 4) or not np.all(np.isfinite(matrix)):
            raise GearError(f"transform of part {name!r} must be a finite 4x4 matrix")
        if name in seen:
            raise GearError(f"part name {name!r} is used twice; names must be unique")
        seen.add(name)
        key = id(mesh)
        if key not in names:
            geom = str(mesh.metadata.get("name") or name)
            while geom in out.geometry:
                geom += "_"
            view = trimesh.Trimesh(mesh.vertices, mesh.faces, process=False)
            rgba = _rgba(colour)
            view.visual = TextureVisuals(
                material=PBRMaterial(name=geom, baseColorFactor=rgba, metallicFactor=0.2)
            )
            view.metadata["name"] = geom
            out.add_geometry(view, geom_name=geom, node_name=name, transform=matrix)
            names[key] = geom
        else:
            out.graph.update(
                frame_to=name, frame_from=out.graph.base_frame, matrix=matrix,
                geometry=names[key],
            )  # fmt: skip
    if not seen:
        raise GearError("a scene needs at least one part")
    return out


def to_manifold(mesh, matrix=None):
    """A ``manifold3d.Manifold`` of a (watertight) mesh, optionally placed by a 4x4 matrix, for
    exact booleans (intersection volumes of meshing gears, minimum gaps)."""
    try:
        import manifold3d
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise GearError("manifold3d is needed: pip install 'geartrain[mesh]'") from exc
    v = np.asarray(mesh.vertices, dtype=float)
    if matrix is not None:
        m = np.asarray(matrix, dtype=float)
        v = v @ m[:3, :3].T + m[:3, 3]
    # double precision where the build has it: a float32 copy moves vertices by 6e-8 of their
    # size, enough to make gears that touch at zero backlash overlap by rounding alone
    build = getattr(manifold3d, "Mesh64", None)
    dtype = np.float64 if build is not None else np.float32
    out = manifold3d.Manifold(
        (build or manifold3d.Mesh)(
            vert_properties=np.ascontiguousarray(v, dtype=dtype),
            tri_verts=np.ascontiguousarray(mesh.faces, dtype=np.uint32),
        )
    )
    if out.status() != manifold3d.Error.NoError:
        raise GearError(f"the mesh is not a closed manifold ({out.status()})")
    return out
