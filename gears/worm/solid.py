"""Layer 8, worm solids: the worm as a helicoid solid and the wheel built on the envelope of its
thread (the worm acting as the hob: an enveloping, throated wheel), placed in mesh.

Frames (the scene's and :func:`worm_placement`'s): the wheel's axis is +z through the origin;
the worm's axis runs along +x through ``(0, a, 0)`` (``a`` the centre distance). In its own
frame the worm's axis is +z, its transverse section at ``z = 0`` is
:func:`worm_section`, and a right-hand thread turns by ``+z / p`` radians at height ``z``
(``p = p_z / (2 pi)``; :mod:`gears.worm.flank`); its own ``(x, y, z)`` go to ``(y, z, x)`` of
the scene, so the pair is a right-handed frame.

**The worm** is its transverse section twisted along its axis, built by
:func:`gears.solid.mesh.gear_solid` (slices from the tolerance; welded and watertight by
construction) and trimmed to its threaded length.

**The wheel** is built directly on its exact surfaces, without booleans. In every plane
``z = zeta`` of the wheel the worm's thread is a rack rolling on the wheel's pitch circle
(:mod:`gears.worm.envelope`), so the wheel's section there is known in closed form: one point
of its flank for each point of the hob's flank (the hob: the worm with its tips lengthened by
the bottom clearance ``c* m``, so that it cuts the wheel's root ``d_f2``), the root fillets the
trochoids of the hob's tip corners, the root an arc of the hob's tip line
``a - sqrt(r_t^2 - zeta^2)`` and the tip an arc of the throat ``a - sqrt(r_k^2 - zeta^2)`` (at
most ``d_e2 / 2``). Where the fillet cuts the flank (undercut) the two are joined at their
crossing; where the flank's contact lies above the tip (near the faces) the hob's corner alone
cuts that side; where a tooth would come to a point below the throat (few teeth, off the
mid-plane) its tip is lowered to a land of one tolerance. Every plane's section is sampled with
the same parameters, so the sections stack into a loft of quads with planar caps at the faces
(:func:`gears.solid.mesh.loft_solid`): welded, watertight and wound outwards by construction.
The sampling: chords within half the tolerance in every plane, and planes split until the
loft between two planes misses the exact section midway by at most the other half. Every
plane's section is computed with the others, in one numpy evaluation per round of splits.
"""

from __future__ import annotations

import math

import numpy as np
import shapely

from gears.arguments import check_callback, check_tolerance
from gears.budget import check_budget
from gears.cutting.sampling import chord_angle
from gears.errors import GearError
from gears.solid.mesh import gear_solid, loft_solid, solid_levels, to_manifold
from gears.worm._wheel import Wheel, hob_tip, planes

__all__ = [
    "wheel_blank",
    "wheel_estimate",
    "wheel_solid",
    "worm_estimate",
    "worm_placement",
    "worm_section",
    "worm_solid",
]


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
    n = max(math.ceil(abs(a1 - a0) / max(chord_angle(r, tolerance), 1e-9)), 1)
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


def _hob_length(pair) -> float:
    """The hob's length: the chord of the blank's outside circle at the hob's tip cylinder,
    plus one axial pitch (the hob reaches every point of the blank it can)."""
    g = pair.geometry
    re2 = float(g.wheel_outside_diameter) / 2.0
    off = float(g.center_distance) - hob_tip(pair)
    return 2.0 * math.sqrt(max(re2**2 - off**2, 0.0)) + float(g.axial_pitch)


def worm_estimate(pair, tolerance: float, hob: bool = False) -> float:
    """Vertices of the worm's (or the hob's) solid at ``tolerance``: its section's vertices
    times its slices (the count :func:`gears.budget.check_budget` holds to the mesh budget)."""
    tip = hob_tip(pair) if hob else float(pair.geometry.worm_tip_diameter) / 2.0
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
    tip = hob_tip(pair)
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
    n = max(math.ceil(2.0 * math.pi / chord_angle(ra, tol)), 8)
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
    n = max(math.ceil(2 * ang / chord_angle(rk, tolerance)), 2)
    t = np.linspace(-ang, ang, n + 1)
    arc = np.stack([a - rk * np.cos(t), rk * np.sin(t)], 1)  # (rho, z), bottom to top
    outline = [(0.0, -half)]
    if half > z_top:
        outline.append((re2, -half))
    outline += [tuple(p) for p in arc]
    if half > z_top:
        outline.append((re2, half))
    outline.append((0.0, half))
    segments = max(math.ceil(2 * math.pi / chord_angle(re2, tolerance)), 16)
    section = manifold3d.CrossSection([np.asarray(outline, float)])  # counter-clockwise
    # revolve takes the section's (x, y) as (rho, z) about the z axis
    return section.revolve(circular_segments=segments)


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


def wheel_estimate(pair, tolerance: float) -> float:
    """Vertices of the wheel at ``tolerance``, estimated before any work: its teeth times the
    vertices of one tooth space (the flanks, fillets and arcs at their chord sag
    ``s^2 / (8 rho)``, ``rho`` about one module) times its planes (the throat's sag over the
    face width)."""
    m, t = pair.module, float(tolerance) / 2.0  # the sampling's share of the tolerance
    chords = math.ceil(2.5 * m / math.sqrt(8.0 * 0.5 * m * t)) + 2
    space = 4 * chords + 2 * math.ceil(math.pi * m / math.sqrt(8.0 * m * t))
    rk = float(pair.geometry.throat_radius)
    planes = math.ceil(pair.face_width / math.sqrt(8.0 * rk * t)) + 5
    return float(pair.wheel_teeth * space * planes)


def wheel_solid(pair, tolerance: float = 0.01, progress=None):
    """The wheel as a watertight, welded ``trimesh.Trimesh`` in its own frame (axis +z,
    mid-plane z = 0): its flanks the exact envelope of the worm's thread (the hob: the worm's
    tips lengthened by ``c* m``, :mod:`gears.worm.envelope`), every vertex on the conjugate
    surface, the root fillets drawn by the hob's tip corners, the root a torus about the
    worm's axis, the tips the throat (at most ``d_e2``), the faces planes at ``+-b_2 / 2``.

    Sampling: in every plane the chords of the flanks, fillets and arcs stay within
    ``tolerance / 2`` of them; the planes are split until the sections interpolated between
    two neighbours miss the exact section between them by at most ``tolerance / 2``.
    ``progress(done, total)`` is called as the work proceeds.

    Raises
    ------
    GearError
        For a bad tolerance or one over the mesh budget (naming the tolerance that fits), a
        face width the hob cannot cut over (the flank does not reach across the tooth at the
        faces), or a section that is not a simple polygon (pointed teeth).
    """
    _trimesh()
    tol = check_tolerance(tolerance, module=pair.module)
    progress = check_callback("progress", progress)
    z2 = pair.wheel_teeth
    check_budget(
        "mesh", f"a wheel of {z2} teeth", lambda t: wheel_estimate(pair, t), tol,
        hint="a wheel of fewer teeth",
    )  # fmt: skip
    w = Wheel(pair)
    if w.half_face >= w.rt:
        raise GearError(
            f"face_width = {pair.face_width:g} mm; the hob (tip radius {w.rt:.6g} mm) cuts "
            f"teeth only over face widths < {2 * w.rt:.6g} mm"
        )
    # half the tolerance to the chords in each plane, half to the quads between planes: a
    # point of the flank is off the mesh by at most the sum
    plan = planes(w, tol / 2.0, progress)
    rings = plan.rings()
    polys = shapely.polygons(rings)
    bad = ~shapely.is_valid(polys) | (shapely.area(polys) <= 0.0)
    if np.any(bad):
        raise GearError(
            f"the wheel's section at z = {plan.zetas[np.argmax(bad)]:.6g} mm is not a simple "
            "polygon (its teeth are pointed or cut by their neighbours' spaces: see check())"
        )
    levels = np.concatenate([rings, np.broadcast_to(plan.zetas[:, None, None],
                                                    (*rings.shape[:2], 1))], -1)  # fmt: skip
    out = loft_solid(levels)
    if progress is not None:
        progress(16, 16)
    return out
