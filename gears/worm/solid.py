"""Layer 8, worm solids: the worm as a helicoid solid and the wheel cut by simulated hobbing
(the worm acting as the hob: an enveloping, throated wheel), placed in mesh.

Frames (the scene's and :func:`worm_placement`'s): the wheel's axis is +z through the origin;
the worm's axis runs along +x through ``(0, a, 0)`` (``a`` the centre distance). In its own
frame the worm's axis is +z, its transverse section at ``z = 0`` is
:func:`worm_section`, and a right-hand thread turns by ``+z / p`` radians at height ``z``
(``p = p_z / (2 pi)``; :mod:`gears.worm.flank`); its own ``(x, y, z)`` go to ``(y, z, x)`` of
the scene, so the pair is a right-handed frame.

**The worm** is its transverse section twisted along its axis, built by
:func:`gears.solid.mesh.gear_solid` (slices from the tolerance; welded and watertight by
construction) and trimmed to its threaded length.

**The wheel** is a blank of revolution (the throat, a torus of radius ``r_k`` about the worm's
axis, up to the outside diameter ``d_e2``, over the face width ``b_2``) from which a hob cuts the
teeth: the worm with its tips lengthened by the bottom clearance ``c* m`` (so it cuts the
wheel's root, ``d_f2``), turned by ``phi_1`` while the wheel turns by ``phi_2 = phi_1 z_1 / z_2``
(Ozols (21.45); a left hand turns the other way). One angular pitch of the wheel suffices: turning
the wheel by ``2 pi / z_2`` turns the hob by ``2 pi / z_1``, a symmetry of its ``z_1`` threads, so
the hob's positions over one pitch, repeated ``z_2`` times about the wheel's axis, are all its
positions. Those positions are united (manifold3d), cut into the sectors of the teeth and turned
into one sector (each piece widened by a tenth of a pitch, so that the copies overlap instead of
touching: one tooth space), and the union of the ``z_2`` copies of that space is subtracted from
the blank.

The hob's positions leave scallops on the flanks: between two positions the tooth moves by
``s = pi m / N`` along the wheel's reference circle, and a flank of curvature radius
``rho`` keeps a ridge of height ``s^2 / (8 rho)`` (the chord sag of the generating positions,
the same law as the rack's simulated cutting). :func:`hob_positions` takes ``N`` from the
tolerance with ``rho`` the smallest radius of curvature of the mid-plane flank
(``r_b2 tan alpha`` at the root form circle, at least one module), doubled: off the mid-plane
the ridges grow (measured against a dense simulation).

At the hob's own positions the worm fills exactly the space it cut: the pair placed at
``phi_1 = 0`` (a position of the hob) has no volume in common at zero backlash.
"""

from __future__ import annotations

import math

import numpy as np
import shapely

from gears.arguments import check_callback, check_tolerance
from gears.budget import check_budget
from gears.errors import GearError
from gears.solid.mesh import gear_solid, solid_levels, to_manifold

__all__ = [
    "hob_positions",
    "wheel_blank",
    "wheel_estimate",
    "wheel_solid",
    "worm_estimate",
    "worm_placement",
    "worm_section",
    "worm_solid",
]

#: The most hob positions one pitch of the wheel takes, however fine the tolerance.
MAX_POSITIONS = 400


def _trimesh():
    import trimesh

    return trimesh


def _mesh(out):
    """A ``trimesh.Trimesh`` owning copies of a manifold3d ``MeshGL64``'s arrays (double
    precision: a float32 copy moves vertices by 6e-8 of their size, enough to make flanks that
    touch at zero backlash overlap)."""
    v = np.array(out.vert_properties[:, :3], dtype=np.float64, order="C")
    f = np.array(out.tri_verts, dtype=np.int64, order="C")
    return _trimesh().Trimesh(v, f, process=False)


def _flank_radii(curve, r0: float, r1: float, tolerance: float) -> np.ndarray:
    """Radii from ``r0`` to ``r1`` at which the transverse curve ``curve(r) -> (x, y)`` is
    sampled so that no chord departs from it by more than ``tolerance`` (midpoints checked,
    chords halved where they do)."""
    r = np.linspace(r0, r1, 9)
    for _ in range(40):
        mid = (r[:-1] + r[1:]) / 2.0
        p0, p1, pm = curve(r[:-1]), curve(r[1:]), curve(mid)
        chord = p1 - p0
        length = np.hypot(chord[:, 0], chord[:, 1])
        d = pm - p0
        off = np.abs(chord[:, 0] * d[:, 1] - chord[:, 1] * d[:, 0]) / np.maximum(length, 1e-300)
        bad = off > tolerance
        if not np.any(bad):
            return r
        r = np.sort(np.concatenate([r, mid[bad]]))
    return r


def _arc(r: float, a0: float, a1: float, tolerance: float) -> np.ndarray:
    """Angles from ``a0`` to ``a1`` (exclusive of both) of an arc of radius ``r`` sampled to
    ``tolerance`` (chord sag)."""
    step = 2.0 * math.acos(max(1.0 - tolerance / r, -1.0))
    n = max(math.ceil(abs(a1 - a0) / max(step, 1e-9)), 1)
    return np.linspace(a0, a1, n + 1)[1:-1]


def worm_section(pair, tolerance: float, tip_radius: float | None = None) -> shapely.Polygon:
    """The worm's transverse section at ``z = 0`` (its own frame), flanks and arcs sampled to
    ``tolerance``; ``tip_radius`` lengthens the threads (a hob: the tip plus the clearance)."""
    g = pair.geometry
    rf = float(g.worm_root_diameter) / 2.0
    ra = float(g.worm_tip_diameter) / 2.0 if tip_radius is None else float(tip_radius)
    p = float(g.lead) / (2.0 * math.pi)
    z1 = pair.starts

    def half(r):
        return np.asarray(pair.axial_profile(r), float)

    def curve(r):  # the flank facing +z of thread 0 in the plane z = 0: theta = -h(r) / p
        th = -half(r) / p
        return np.stack([r * np.cos(th), r * np.sin(th)], axis=-1)

    radii = _flank_radii(curve, rf, ra, tolerance)
    th_low = -half(radii) / p  # the thread's lower flank, root to tip
    pts = []
    for k in range(z1):
        c = 2.0 * math.pi * k / z1
        low = c + th_low
        high = c - th_low[::-1]  # the mirror flank, tip to root
        pts.append(np.stack([radii, low], 1))
        tip = _arc(ra, low[-1], high[0], tolerance)
        pts.append(np.stack([np.full(len(tip), ra), tip], 1))
        pts.append(np.stack([radii[::-1], high], 1))
        nxt = c + 2.0 * math.pi / z1 + th_low[0]
        root = _arc(rf, high[-1], nxt, tolerance)
        pts.append(np.stack([np.full(len(root), rf), root], 1))
    polar = np.concatenate(pts)
    xy = np.stack([polar[:, 0] * np.cos(polar[:, 1]), polar[:, 0] * np.sin(polar[:, 1])], 1)
    if pair.hand == "left":
        xy[:, 1] = -xy[:, 1]
        xy = xy[::-1]
    poly = shapely.Polygon(xy)
    if not poly.is_valid or poly.area <= 0.0:
        raise GearError(
            f"the worm's section at tolerance = {tolerance:g} mm is not a simple polygon (the "
            "threads' flanks cross: a thread thicker than its pitch allows)"
        )
    return poly


def _twist(pair, length: float) -> float:
    """Degrees the section turns over ``length`` (right hand > 0)."""
    p = float(pair.geometry.lead) / (2.0 * math.pi)
    return math.degrees(length / p) * (1.0 if pair.hand == "right" else -1.0)


def _hob_tip(pair) -> float:
    g = pair.geometry
    return float(g.worm_tip_diameter) / 2.0 + pair.clearance * pair.module


def _hob_length(pair) -> float:
    """The hob's length: the chord of the blank's outside circle at the hob's tip cylinder,
    plus one axial pitch (the hob reaches every point of the blank it can)."""
    g = pair.geometry
    re2 = float(g.wheel_outside_diameter) / 2.0
    off = float(g.center_distance) - _hob_tip(pair)
    return 2.0 * math.sqrt(max(re2**2 - off**2, 0.0)) + float(g.axial_pitch)


def worm_estimate(pair, tolerance: float, hob: bool = False) -> float:
    """Vertices of the worm's (or the hob's) solid at ``tolerance``: its section's vertices
    times its slices (the count :func:`gears.budget.check_budget` holds to the mesh budget)."""
    tip = _hob_tip(pair) if hob else float(pair.geometry.worm_tip_diameter) / 2.0
    section = worm_section(pair, tolerance, tip if hob else None)
    length = max(_hob_length(pair), pair.worm_length)
    n = len(section.exterior.coords) - 1
    return n * float(solid_levels(_twist(pair, length), tip, tolerance))


def worm_solid(pair, tolerance: float = 0.01, hob: bool = False):
    """The worm as a watertight ``trimesh.Trimesh`` in its own frame (axis +z, centred), or
    with ``hob=True`` the hob that cuts the wheel (tips lengthened by ``c* m``, as long as the
    blank needs). The worm is the hob's twisted section trimmed to the tip cylinder and the
    threaded length, so its flanks are the hob's own triangles."""
    _trimesh()
    tol = check_tolerance(tolerance, module=pair.module)
    tip = _hob_tip(pair)
    length = max(_hob_length(pair), pair.worm_length)
    check_budget(
        "mesh", f"a worm of {pair.starts} starts and {length:.6g} mm",
        lambda t: worm_estimate(pair, t, hob=True), tol,
    )  # fmt: skip
    section = worm_section(pair, tol, tip)
    long = gear_solid(section, length, _twist(pair, length), tol, tip_radius=tip)
    if hob:
        return long
    ra = float(pair.geometry.worm_tip_diameter) / 2.0
    step = 2.0 * math.acos(1.0 - tol / ra)
    n = max(math.ceil(2.0 * math.pi / step), 8)
    import manifold3d

    # the tip cylinder circumscribes a polygon whose chords stay within the tolerance
    cut = manifold3d.Manifold.cylinder(
        pair.worm_length, ra / math.cos(math.pi / n), circular_segments=n, center=True
    )
    out = (to_manifold(long) ^ cut).to_mesh64()
    return _mesh(out)


def wheel_blank(pair, tolerance: float):
    """The wheel's blank as a ``manifold3d.Manifold``: revolved about +z from its axial
    section (the throat arc of radius ``r_k`` about the worm's axis, the outside cylinder
    ``d_e2``, the faces at ``+-b_2 / 2``), sampled to ``tolerance``."""
    import manifold3d

    g = pair.geometry
    a, rk = float(g.center_distance), float(g.throat_radius)
    re2 = float(g.wheel_outside_diameter) / 2.0
    half = pair.face_width / 2.0
    # where the throat arc reaches the outside diameter
    z_e = math.sqrt(max(rk**2 - (a - re2) ** 2, 0.0))
    z_top = min(half, z_e)
    ang = math.asin(z_top / rk)
    n = max(math.ceil(2 * ang / (2 * math.acos(1 - tolerance / rk))), 2)
    t = np.linspace(-ang, ang, n + 1)
    arc = np.stack([a - rk * np.cos(t), rk * np.sin(t)], 1)  # (rho, z), bottom to top
    outline = [(0.0, -half)]
    if half > z_top:
        outline.append((re2, -half))
    outline += [tuple(p) for p in arc]
    if half > z_top:
        outline.append((re2, half))
    outline.append((0.0, half))
    segments = max(math.ceil(2 * math.pi / (2 * math.acos(1 - tolerance / re2))), 16)
    section = manifold3d.CrossSection([np.asarray(outline, float)])  # counter-clockwise
    # revolve takes the section's (x, y) as (rho, z) about the z axis
    return section.revolve(circular_segments=segments)


def hob_positions(pair, tolerance: float) -> int:
    """Hob positions over one angular pitch of the wheel that keep the flanks' scallops within
    ``tolerance`` (module docstring): twice ``pi m / sqrt(8 rho tolerance)``. The mid-plane law
    alone left the flanks 1.3 times the tolerance off a dense simulation 3 mm off the mid-plane
    (z1 1, z2 10, m 2, tolerance 0.1 mm: 0.131 mm); twice the count gave 0.097 mm."""
    g = pair.geometry
    rb2 = float(g.wheel_diameter) / 2.0 * math.cos(math.radians(float(g.axial_pressure_angle)))
    rf2 = float(g.wheel_root_diameter) / 2.0
    rho = max(math.sqrt(max(rf2**2 - rb2**2, 0.0)), pair.module)
    s = math.sqrt(8.0 * rho * tolerance)
    return int(min(max(math.ceil(2.0 * math.pi * pair.module / s), 2), MAX_POSITIONS))


def _hob_matrix(pair, phi1: float) -> np.ndarray:
    """4x4: the hob's own frame turned by ``phi1`` (rad) about its axis, placed at the centre
    distance, then the scene turned back by the wheel's ``phi2`` (the hob in the wheel's
    frame)."""
    return worm_placement(pair, phi1, -1.0)


def worm_placement(pair, phi1: float, wheel_sign: float = 1.0) -> np.ndarray:
    """4x4 placing the worm turned by ``phi1`` radians about its axis in the scene's frame
    (module docstring); with ``wheel_sign = -1`` the same seen from the wheel turned by
    ``phi2 = phi1 z_1 / z_2`` (the hob's position in the wheel's frame)."""
    a = float(pair.geometry.center_distance)
    c, s = math.cos(phi1), math.sin(phi1)
    spin = np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]])
    axes = np.array(
        [[0, 0, 1, 0], [1, 0, 0, a], [0, 1, 0, 0], [0, 0, 0, 1.0]]
    )  # (x,y,z)->(z,x+a,y)
    out = axes @ spin
    if wheel_sign < 0:
        sign = 1.0 if pair.hand == "right" else -1.0
        phi2 = sign * phi1 * pair.starts / pair.wheel_teeth
        c2, s2 = math.cos(-phi2), math.sin(-phi2)
        back = np.array([[c2, -s2, 0, 0], [s2, c2, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]])
        out = back @ out
    return out


def _sector(angle0: float, angle1: float, radius: float, height: float):
    """A wedge about +z from ``angle0`` to ``angle1`` (rad, < pi apart) as a Manifold."""
    import manifold3d

    r = 2.0 * radius
    pts = [(0.0, 0.0)] + [(r * math.cos(t), r * math.sin(t))
                          for t in np.linspace(angle0, angle1, 5)]  # fmt: skip
    return manifold3d.Manifold.extrude(
        manifold3d.CrossSection([np.asarray(pts, float)]), 2.0 * height
    ).translate((0.0, 0.0, -height))


def wheel_estimate(pair, tolerance: float) -> float:
    """Vertices of the hobbed wheel at ``tolerance``: the hob's vertices over one axial pitch
    of its length, times the hob positions and the wheel's teeth (measured: the wheel's tooth
    spaces keep about one vertex of every hob position's pitch of thread they cut)."""
    hob = worm_estimate(pair, tolerance, hob=True)
    per_pitch = hob * float(pair.geometry.axial_pitch) / _hob_length(pair)
    return pair.wheel_teeth * per_pitch * hob_positions(pair, tolerance)


def wheel_solid(pair, tolerance: float = 0.01, positions: int | None = None, progress=None):
    """The wheel cut by simulated hobbing (module docstring) as a watertight
    ``trimesh.Trimesh`` in its own frame (axis +z, mid-plane z = 0). ``positions`` overrides
    :func:`hob_positions`; ``progress(done, total)`` is called as the work proceeds.

    The discrete positions can leave slivers of the blank that no position quite removes
    (where the hob's tips only graze the rim); they are not part of the wheel, and only the
    largest connected body is returned.
    """
    import manifold3d

    _trimesh()
    tol = check_tolerance(tolerance, module=pair.module)
    progress = check_callback("progress", progress)
    n = hob_positions(pair, tol) if positions is None else int(positions)
    z2 = pair.wheel_teeth
    check_budget(
        "mesh", f"a hobbed wheel of {z2} teeth ({n} hob positions a pitch)",
        lambda t: wheel_estimate(pair, t), tol, hint="a wheel of fewer teeth",
    )  # fmt: skip
    steps = n + 3

    def tick(i):
        if progress is not None:
            progress(i, steps)

    hob = to_manifold(worm_solid(pair, tol, hob=True))
    blank = wheel_blank(pair, tol)
    re2 = float(pair.geometry.wheel_outside_diameter) / 2.0
    # the half of the blank on the worm's side: the hob reaches nothing else
    region = blank ^ manifold3d.Manifold.cube((2.0 * re2, re2, pair.face_width + 2.0)).translate(
        (-re2, 0.0, -pair.face_width / 2.0 - 1.0)
    )
    pitch = 2.0 * math.pi / z2
    sign = 1.0 if pair.hand == "right" else -1.0
    cuts = []
    for i in range(n):
        phi1 = sign * (pitch * i / n) * z2 / pair.starts
        cuts.append(hob.transform(_hob_matrix(pair, phi1)[:3, :]) ^ region)
        tick(i + 1)
    swept = manifold3d.Manifold.batch_boolean(cuts, manifold3d.OpType.Add)
    swept.num_vert()  # evaluate now: manifold3d's lazy tree would merge the steps below into one
    # one tooth space: every sector's piece of the sweep, turned into sector 0 (widened by a
    # tenth of a pitch, so that neighbouring copies overlap instead of touching)
    pad = 0.1 * pitch
    pieces = []
    for k in range(-(z2 // 2), z2 // 2 + 1):
        lo, hi = k * pitch - pitch / 2.0 - pad, k * pitch + pitch / 2.0 + pad
        piece = swept ^ _sector(lo, hi, re2, pair.face_width)
        if not piece.is_empty():
            pieces.append(piece.rotate((0.0, 0.0, -math.degrees(k * pitch))))
    space = manifold3d.Manifold.batch_boolean(pieces, manifold3d.OpType.Add)
    space.num_vert()
    tick(n + 1)
    copies = [space.rotate((0.0, 0.0, math.degrees(j * pitch))) for j in range(z2)]
    wheel = blank - manifold3d.Manifold.batch_boolean(copies, manifold3d.OpType.Add)
    wheel.num_vert()
    tick(n + 2)
    bodies = wheel.decompose()
    wheel = max(bodies, key=lambda b: b.volume()) if len(bodies) > 1 else wheel
    out = wheel.to_mesh64()
    tick(steps)
    return _mesh(out)
