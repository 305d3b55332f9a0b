"""Layer 7, solids and frames: straight bevel gear solids built on their spherical sections, and
the placement of bevel gears on a common apex (trimesh, the ``mesh`` extra).

Conventions: the gear axis is +z, the pitch apex is the origin, tooth 0 is centred on azimuth 0
(the +x side); the teeth lie between the front end (cone distance ``R_i = R_e - b``) and the back
end (``R_e``).

**The solid without booleans.** Flanks, fillets and root are cones over the sampled directrix of
:mod:`gears.bevel.spherical` (the one-sided polygon of each tooth space on the unit sphere), so
between
two end sections they are exact *generator quads*: each quad lies in the plane through the apex
and one chord of the directrix. The face (tip) cone trims them; with constant clearance its apex
is not the pitch apex, so the tip changes from one section to the next and the solid is built on
*levels* (sections at cone distances between R_i and R_e, as many as the tolerance needs for the
tip edge), joined by a zipper that pairs the vertices of neighbouring levels along a common
parameter. The ends are cones (``back_cone=True``: the back cone and the front cone, normal to
the pitch cone at R_e and R_i, the blank of KHK and ISO 23509) or planes normal to the axis
through the outer and inner pitch points (``back_cone=False``). Both are developable, so each end
face is triangulated tooth by tooth in its development (Tredgold's plane for the back cone):
rows across the tooth between mirror vertices, each row split into as many pieces as the
surface's curvature allows within the tolerance, every vertex lifted back onto the end surface.
Below the teeth a band of the end surface (one module deep) leads to a plane normal to the axis,
closed at the axis or at the bore. Every vertex is shared by construction: the mesh is welded,
watertight and consistently wound (outward normals).

**Tolerance.** ``tolerance`` (mm) bounds the deviation of every vertex and chord from the exact
surfaces at the back end, the farthest from the apex: the directrix is sampled at the angle
``tolerance / t_max``.
"""

from __future__ import annotations

import itertools
import math
from typing import NamedTuple

import numpy as np

from gears.bevel.spherical import SphericalTooth, direction, polar
from gears.budget import check_budget
from gears.errors import GearError

__all__ = ["BevelBlank", "bevel_placement", "bevel_solid", "rotation", "solid_estimate"]


class BevelBlank(NamedTuple):
    """The blank of one bevel gear (mm, radians): what :func:`bevel_solid` needs besides its
    tooth directrix."""

    pitch_angle: float  # delta
    face_angle: float  # delta_a
    cone_distance: float  # R_e
    face_width: float  # b
    outer_addendum: float  # h_ae
    outer_dedendum: float  # h_fe
    dedendum_angle: float  # theta_f
    module: float  # m_et, sets the depth of the rim below the teeth


def _trimesh():
    try:
        import trimesh
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise GearError("3D meshes need trimesh: pip install 'geartrain[mesh]'") from exc
    return trimesh


class _End:
    """An end surface at one level: a cone (or plane) of revolution given by its meridian line
    ``M0 + s d``; ``apex`` is where the line meets the axis."""

    def __init__(self, m0, d) -> None:
        self.m0 = np.asarray(m0, float)
        self.d = np.asarray(d, float) / math.hypot(*d)
        if self.d[0] < 0:
            self.d = -self.d  # from the axis outwards
        self.sin_beta = float(self.d[0])  # the line's angle to the axis
        self.apex_z = float(self.m0[1] - self.m0[0] / self.d[0] * self.d[1])

    def distance(self, theta):
        """Distance t from the pitch apex along the ray of polar angle ``theta`` to the surface."""
        st, ct = np.sin(theta), np.cos(theta)
        p, d = self.m0, self.d
        return (p[0] * d[1] - p[1] * d[0]) / (st * d[1] - ct * d[0])

    def point(self, theta, azimuth):
        return direction(theta, azimuth) * self.distance(theta)[..., None]

    def slant(self, rho):
        """Distance from the apex of the end surface along its line, for radius ``rho``."""
        return rho / self.sin_beta

    def meridian(self, slant):
        """``(rho, z)`` at distance ``slant`` from the end surface's apex."""
        return slant * self.d[0], self.apex_z + slant * self.d[1]

    def curvature(self, rho):
        """Largest normal curvature of the surface at radius rho (the circle's, cos(beta)/rho)."""
        return abs(self.d[1]) / rho


def _face_line(blank: BevelBlank):
    """The face cone's meridian line: the outer tip point and its direction (delta_a)."""
    d = blank.pitch_angle
    n = np.array([math.cos(d), -math.sin(d)])
    tip = blank.cone_distance * np.array([math.sin(d), math.cos(d)]) + blank.outer_addendum * n
    return tip, np.array([math.sin(blank.face_angle), math.cos(blank.face_angle)])


def _intersect(p0, d0, p1, d1):
    """Intersection of the lines p0 + a d0 and p1 + b d1 (2D)."""
    m = np.array([[d0[0], -d1[0]], [d0[1], -d1[1]]])
    a, _ = np.linalg.solve(m, p1 - p0)
    return p0 + a * d0


class _Levels:
    """The sections of the solid: cone distances R from R_i (front, level 0) to R_e (back)."""

    def __init__(self, blank: BevelBlank, back_cone: bool) -> None:
        self.blank = blank
        self.back_cone = back_cone
        d = blank.pitch_angle
        self.g = np.array([math.sin(d), math.cos(d)])
        self.n = np.array([math.cos(d), -math.sin(d)])
        self.face = _face_line(blank)

    def end(self, f: float) -> _End:
        b = self.blank
        r = b.cone_distance - (1.0 - f) * b.face_width
        m0 = r * self.g
        return _End(m0, self.n if self.back_cone else np.array([1.0, 0.0]))

    def tip_polar(self, f: float) -> float:
        e = self.end(f)
        p = _intersect(e.m0, e.d, *self.face)
        return math.atan2(p[0], p[1])


def bevel_solid(
    tooth: SphericalTooth, blank: BevelBlank, tolerance: float, bore: float | None = None,
    back_cone: bool = True,
):  # fmt: skip
    """A straight bevel gear solid (see the module docstring).

    Parameters
    ----------
    tooth : SphericalTooth
        The exact tooth space on the unit sphere (its profile kind, thickness and fillets).
    blank : BevelBlank
        Cone angles, cone distance, face width and outer heights.
    tolerance : float
        Largest deviation from the exact surfaces, mm.
    bore : float or None
        Bore diameter, mm.
    back_cone : bool
        True: the ends are the back and front cones; False: planes normal to the axis.

    Returns
    -------
    trimesh.Trimesh
        Watertight, welded, outward normals; axis +z, pitch apex at the origin.
    """
    trimesh = _trimesh()
    levels = _Levels(blank, back_cone)
    z = tooth.z
    half_pitch = math.pi / z
    f_levels = _level_fractions(tooth, levels, tolerance)
    tips = [levels.tip_polar(f) for f in f_levels]
    back = levels.end(1.0)
    theta_lo = tooth.root_polar
    t_max = float(np.max(back.distance(np.array([theta_lo, max(tips)]))))
    eps = tolerance / t_max
    check_budget("mesh", f"the bevel solid of z = {z}",
                 solid_estimate(tooth, blank, back_cone, len(f_levels)), tolerance)  # fmt: skip
    half = tooth.conical_half(eps, max(tips))
    n_con = len(half.y)
    # one half profile per level: (theta, azimuth from the space centre, tau)
    halves = [_level_half(tooth, half, th, eps) for th in tips]
    big = n_con + 2.0
    period = 2.0 * big
    verts: list[np.ndarray] = []
    count = 0
    rings = []  # per level: vertex indices (ccw) and tau
    for f, (theta, eta, tau) in zip(f_levels, halves, strict=True):
        end = levels.end(f)
        psi_left = eta - half_pitch
        th_tooth = np.concatenate([theta, theta[-2:0:-1]])
        ps_tooth = np.concatenate([psi_left, -psi_left[-2:0:-1]])
        ta_tooth = np.concatenate([tau, period - tau[-2:0:-1]])
        turn = 2.0 * half_pitch * np.arange(z)
        th = np.tile(th_tooth, z)
        ps = (ps_tooth[None, :] + turn[:, None]).ravel()
        ta = (ta_tooth[None, :] + period * np.arange(z)[:, None]).ravel()
        pts = end.point(th, ps)
        idx = count + np.arange(len(pts))
        verts.append(pts)
        count += len(pts)
        rings.append((idx, ta, len(theta)))
    faces = []
    for (ia, ta, _), (ib, tb, _) in itertools.pairwise(rings):
        faces.append(_zipper(ia, ta, ib, tb, z * period))
    bore_steps = 0 if bore is None else _circle_steps(bore / 2.0, 2 * math.pi, tolerance)
    bores = []
    for which in (0, len(rings) - 1):
        idx = rings[which][0]
        f = f_levels[which]
        theta, eta, _ = halves[which]
        r_level = blank.cone_distance - (1.0 - f) * blank.face_width
        depth = blank.module * r_level / blank.cone_distance
        cap_v, cap_f, count, ring, _zq = _end_face(
            levels.end(f), idx, theta, eta, z, count, tolerance, blank, bore,
            front=(which == 0), bore_steps=bore_steps, depth=depth,
        )  # fmt: skip
        verts.extend(cap_v)
        faces.append(cap_f)
        bores.append(ring)
    if bore is not None:
        steps = np.arange(bore_steps, dtype=float)
        faces.append(_zipper(bores[0], steps, bores[1], steps, float(bore_steps))[:, ::-1])
    v = np.concatenate(verts)
    fc = np.concatenate([np.asarray(x, dtype=np.int64).reshape(-1, 3) for x in faces])
    return trimesh.Trimesh(v, fc, process=False)


def solid_estimate(tooth: SphericalTooth, blank: BevelBlank, back_cone: bool = True,
                   n_levels: int = 2):  # fmt: skip
    """The vertex count of :func:`bevel_solid` as a function of the tolerance (mm), for the
    budget check before any sampling (:func:`gears.budget.check_budget`): a half tooth space
    takes about ``0.4 / sqrt(eps) + 8`` vertices on the unit sphere (measured on the KHK pairs:
    31 at eps = 1.4e-4 rad; eps = tolerance / t_max), each level a ring of ``2 z`` halves, each
    end face a strip of ``k + 1`` columns per row (``k`` from the end surface's curvature,
    :func:`_end_face`)."""
    z = tooth.z
    back = _End(
        blank.cone_distance * np.array([math.sin(blank.pitch_angle), math.cos(blank.pitch_angle)]),
        np.array([math.cos(blank.pitch_angle), -math.sin(blank.pitch_angle)])
        if back_cone else np.array([1.0, 0.0]),
    )  # fmt: skip
    t_max = float(np.max(back.distance(np.array([tooth.root_polar, blank.face_angle]))))
    r_in = (blank.cone_distance - blank.face_width) * math.sin(tooth.root_polar)
    kappa = 0.0 if not back_cone else abs(back.d[1]) / max(r_in, 1e-12)
    width = 2.0 * math.pi * blank.cone_distance * math.sin(blank.pitch_angle) / z

    def vertices(tolerance: float) -> float:
        half = 0.4 / math.sqrt(tolerance / t_max) + 8.0
        k = 1.0 + width * math.sqrt(kappa / (2.0 * tolerance))
        return z * half * 2.0 * (n_levels + k + 2.0)

    return vertices


def _level_fractions(tooth: SphericalTooth, levels: _Levels, tolerance: float) -> list[float]:
    """Levels 0 (front) ... 1 (back): two when the tip is conical (tapered clearance), more when
    the tip edge between two levels would leave the tolerance (bisection on the cut point and
    the tooth's tip centre, measured in mm)."""
    tips = {f: levels.tip_polar(f) for f in (0.0, 0.5, 1.0)}
    if max(tips.values()) - min(tips.values()) < 1e-12:
        return [0.0, 1.0]

    def edge(f):
        th = levels.tip_polar(f)
        t = float(levels.end(f).distance(np.array(th)))
        _, az, _ = tooth.cut_azimuth(th)
        return t * direction(th, np.array([az, math.pi / tooth.z]))

    done, todo = [0.0], [(0.0, 1.0, edge(0.0), edge(1.0))]
    while todo:
        f0, f1, e0, e1 = todo.pop()
        fm = 0.5 * (f0 + f1)
        em = edge(fm)
        dev = np.linalg.norm(em - 0.5 * (e0 + e1), axis=-1).max()
        if dev > 0.25 * tolerance and len(done) + len(todo) < 200:
            todo.extend([(fm, f1, em, e1), (f0, fm, e0, em)])
        else:
            done.append(f1)
    return sorted(done)


def _level_half(tooth: SphericalTooth, half, theta_tip: float, eps: float):
    """One level's half space: ``(theta, azimuth from the space centre, tau)`` from the space
    centre to the tooth centre: the conical vertices below the tip, the cut point on the tip
    circle (exact) and the tip arc (see :func:`_zipper` for tau)."""
    half_pitch = math.pi / tooth.z
    n = len(half.y)
    s_cut, az_cut, pointed = tooth.cut_azimuth(theta_tip)
    th_cut = theta_tip if not pointed else float(polar(tooth.flank_points(s_cut))[0])
    keep = (half.kind != 2) | ((half.theta < th_cut) & (half.azimuth < az_cut))
    keep = np.flatnonzero(keep)
    # the cut point replaces a kept vertex that (nearly) coincides with it
    cut = direction(th_cut, az_cut)
    while len(keep) and np.linalg.norm(half.y[keep[-1]] - cut) < 1e-6 * eps:
        keep = keep[:-1]
    j = int(keep[-1])
    s = half.s
    if j + 1 < n and np.isfinite(s[j]) and np.isfinite(s[j + 1]) and s[j + 1] != s[j]:
        frac = float(np.clip((s_cut - s[j]) / (s[j + 1] - s[j]), 0.0, 1.0))
    else:
        frac = 0.5
    theta = [half.theta[keep], [th_cut]]
    eta = [half.azimuth[keep], [az_cut]]
    tau = [keep.astype(float), [j + max(frac, 1e-9)]]
    if pointed:
        tau[-1] = [n + 2.0]
    else:
        from gears.bevel.spherical import _adaptive  # the same bisection as the directrix

        a = _adaptive(lambda x: direction(theta_tip, x), az_cut, half_pitch, eps)[1:]
        theta.append(np.full(len(a), theta_tip))
        eta.append(a)
        frac_a = (a - az_cut) / (half_pitch - az_cut)
        frac_a[-1] = 1.0
        tau.append(n + 1.0 + frac_a)
    return (np.concatenate(theta), np.concatenate(eta), np.concatenate(tau))


def _zipper(ia, ta, ib, tb, period: float) -> np.ndarray:
    """Triangles between two closed rings whose vertices carry a common increasing parameter
    (``ta``, ``tb``, both starting with one shared value): walk both rings at once, always
    advancing the one whose next vertex comes first (a quad where they agree). Winding: ring A
    then B gives the normal of ``(A_i, A_i+1, B_i+1)``."""
    ia2, ib2 = np.append(ia, ia[0]), np.append(ib, ib[0])
    ta2, tb2 = np.append(ta, period + ta[0]), np.append(tb, period + tb[0])
    keys = np.concatenate([ta2[1:], tb2[1:]])
    which = np.concatenate([np.zeros(len(ta), bool), np.ones(len(tb), bool)])
    order = np.lexsort((which, keys))
    adv_b = which[order]
    i = np.concatenate([[0], np.cumsum(~adv_b)])[:-1]
    j = np.concatenate([[0], np.cumsum(adv_b)])[:-1]
    i1, j1 = np.minimum(i + 1, len(ta)), np.minimum(j + 1, len(tb))
    i, j = np.minimum(i, len(ta)), np.minimum(j, len(tb))
    tri_a = np.stack([ia2[i], ia2[i1], ib2[j]], -1)
    tri_b = np.stack([ia2[i], ib2[j1], ib2[j]], -1)
    return np.where(adv_b[:, None], tri_b, tri_a)


def _circle_steps(radius: float, angle: float, tolerance: float) -> int:
    """Pieces for an arc of ``radius`` over ``angle`` rad whose chords sag <= tolerance / 2."""
    if radius <= 0:
        return 1
    c = 1.0 - 0.5 * tolerance / radius
    step = 2.0 * math.acos(max(c, -1.0))
    return max(1, math.ceil(angle / step))


def _end_face(end: _End, idx, theta, eta, z: int, count: int, tolerance: float, blank, bore,
              front: bool, bore_steps: int, depth: float):  # fmt: skip
    """The end face at one level: per tooth, rows between mirror vertices in the development of
    the end surface (interior points lifted back onto it); below the teeth a band of the end
    surface ``depth`` deep along its line; then a plane normal to the axis, closed by a fan at
    the axis or by the bore circle. Returns ``(vertices, faces, next index, bore ring)``."""
    n = len(theta)
    m = 2 * n - 2  # ring vertices per tooth
    half_pitch = math.pi / z
    t = end.distance(theta)
    rho = t * np.sin(theta)
    slant = end.slant(rho)
    sb = end.sin_beta
    a = (eta - half_pitch) * sb  # developed angle of the left half (tooth centre at 0)
    x, y = slant * np.sin(a), slant * np.cos(a)  # x <= 0: left of the tooth centre
    # columns: rows and the band below must keep their chords within the tolerance
    kappa = end.curvature(float(rho.min()))
    w = 2.0 * float(np.max(-x[: n - 1]))
    k = 1 if kappa == 0 else math.ceil(w * math.sqrt(kappa / (2.0 * tolerance)))
    k = max(k, _circle_steps(float(rho.max()), 2 * half_pitch, tolerance), 1)
    rows = n - 1  # rows 0 .. n-2 with k+1 columns; row n-1 is the tooth's centre vertex
    frac = np.linspace(-1.0, 1.0, k + 1)[1:-1]
    xs = x[:rows, None] * -frac[None, :]  # left (x < 0) to right
    ys = np.broadcast_to(y[:rows, None], xs.shape)
    ell = np.hypot(xs, ys)
    psi = np.arctan2(xs, ys) / sb
    if k > 1:  # the band must reach below the row chords, which dip under the root circle
        depth = max(depth, 1.5 * float(slant[0] - ell[0].min()))
    r_in, z_in = end.meridian(ell)
    turn = 2.0 * half_pitch * np.arange(z)
    ang = psi[None] + turn[:, None, None]
    inner = np.stack(
        [r_in * np.cos(ang), r_in * np.sin(ang), np.broadcast_to(z_in, ang.shape)], axis=-1
    )  # fmt: skip  (z, rows, k-1, 3)
    n_in = rows * (k - 1)
    start_in = count
    count += z * n_in
    # the grid of one tooth: (rows, k+1) vertex indices
    tooth_ring = np.arange(z)[:, None] * m  # offset of each tooth in the ring
    left = np.arange(n)  # L_i at ring offset i
    right = np.concatenate([[m], 2 * n - 2 - np.arange(1, n - 1)])  # R_0 = next tooth's L_0
    grid = np.empty((z, rows, k + 1), dtype=np.int64)
    ring_len = z * m
    grid[:, :, 0] = idx[(tooth_ring + left[None, :rows]) % ring_len]
    grid[:, :, k] = idx[(tooth_ring + right[None, :rows]) % ring_len]
    if k > 1:
        grid[:, :, 1:k] = start_in + np.arange(z * n_in).reshape(z, rows, k - 1)
    apex = idx[tooth_ring[:, 0] + n - 1]
    a0, a1 = grid[:, :-1, :-1], grid[:, :-1, 1:]
    b0, b1 = grid[:, 1:, :-1], grid[:, 1:, 1:]
    quads = [np.stack([a0, a1, b1], -1), np.stack([a0, b1, b0], -1)]
    top = grid[:, -1, :]
    fan = np.stack([top[:, :-1], top[:, 1:], np.broadcast_to(apex[:, None], top[:, 1:].shape)], -1)
    cap = np.concatenate([q.reshape(-1, 3) for q in quads] + [fan.reshape(-1, 3)])
    # band: row 0 of every tooth (k points each, ccw) down the end surface's lines
    row0 = grid[:, 0, :k].reshape(-1)
    ell_q = slant[0] - depth
    if bore is None and not ell_q > 0.0:
        # a pinion of very few teeth: its root reaches near the axis, so the band stops
        # halfway between the axis and the lowest row point (still below every row chord)
        ell_q = 0.5 * (float(slant[0]) if k == 1 else min(float(slant[0]), float(ell[0].min())))
    rho_q, z_q = end.meridian(ell_q)
    r_bore = 0.0 if bore is None else bore / 2.0
    where = "front" if front else "back"
    if not rho_q > 0.0:
        if bore is None:
            raise GearError(
                f"z = {z}: the tooth spaces reach the gear's axis at its {where} end, so no solid "
                "can be drawn; use more teeth or a positive profile shift"
            )
        raise GearError(
            f"bore = {bore:g} mm does not fit: the rim below the teeth of this {z}-tooth gear "
            f"reaches the axis at its {where} end; valid is no bore (bore=None)"
        )
    if not rho_q > r_bore:
        raise GearError(
            f"bore = {bore:g} mm does not fit: the gear's rim below the teeth reaches down to a "
            f"diameter of {2 * rho_q:.4f} mm at its {where} end; valid is "
            f"bore < {2 * rho_q:.4f} mm"
        )
    az0 = np.concatenate([
        (np.concatenate([[-half_pitch], psi[0]]) + t_)
        for t_ in turn
    ])  # fmt: skip
    q_pts = np.stack([rho_q * np.cos(az0), rho_q * np.sin(az0), np.full(len(az0), z_q)], -1)
    q_idx = count + np.arange(len(az0))
    count += len(az0)
    nxt = np.roll(row0, -1)
    q_nxt = np.roll(q_idx, -1)
    band = np.concatenate([np.stack([row0, nxt, q_nxt], -1), np.stack([row0, q_nxt, q_idx], -1)])
    verts = [inner.reshape(-1, 3), q_pts]
    if bore is None:
        centre = count
        count += 1
        verts.append(np.array([[0.0, 0.0, z_q]]))
        disk = np.stack([np.full(len(q_idx), centre), q_idx, q_nxt], -1)
        bore_ring = None
    else:
        ab = -half_pitch + 2 * math.pi * np.arange(bore_steps) / bore_steps
        b_pts = np.stack([r_bore * np.cos(ab), r_bore * np.sin(ab), np.full(len(ab), z_q)], -1)
        bore_ring = count + np.arange(bore_steps)
        count += bore_steps
        verts.append(b_pts)
        disk = _zipper(q_idx, az0 + half_pitch, bore_ring, ab + half_pitch, 2 * math.pi)
    if front:
        faces = np.concatenate([cap, band[:, ::-1], disk[:, ::-1]])
    else:
        faces = np.concatenate([cap[:, ::-1], band, disk])
    return verts, faces, count, bore_ring, z_q


def rotation(axis, angle: float) -> np.ndarray:
    """4x4 rotation by ``angle`` degrees about the unit ``axis`` through the origin (the common
    apex of bevel gears)."""
    k = np.asarray(axis, float)
    k = k / np.linalg.norm(k)
    t = math.radians(math.fmod(float(angle), 360.0))  # cos and sin of a huge angle lose it
    c, s = math.cos(t), math.sin(t)
    kx = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    m = np.eye(4)
    m[:3, :3] = c * np.eye(3) + s * kx + (1.0 - c) * np.outer(k, k)
    return m


def bevel_placement(z1: int, z2: int, shaft_angle: float, angle: float = 0.0):
    """4x4 placements ``(gear 1, gear 2)`` of a bevel pair on a common apex (the origin).

    Gear 1's axis is +z, turned by ``angle`` degrees; gear 2's axis lies in the xz-plane at the
    shaft angle from it, ``(sin Sigma, 0, cos Sigma)``, the common pitch generator between them.
    At ``angle = 0`` tooth 0 of gear 1 faces gear 2 (azimuth 0) and gear 2 shows a tooth space
    there (turned by 180 + 180/z2 deg about its own axis); the pitch cones roll, so gear 2 turns
    by ``-angle z1/z2`` (both speeds counted about the axes pointing away from the apex, the
    bevel mesh is an external one: ``z1 w1 + z2 w2 = 0``).

    >>> g1, g2 = bevel_placement(20, 40, 90.0)
    >>> np.round(g2[:3, 2], 12).tolist()   # gear 2's axis
    [1.0, 0.0, 0.0]
    """
    # the pair repeats itself every 360 z2 deg of gear 1: reduce before scaling (no overflow)
    angle = math.fmod(float(angle), 360.0 * z2)
    g1 = rotation((0.0, 0.0, 1.0), angle)
    a2 = 180.0 + 180.0 / z2 - angle * z1 / z2
    g2 = rotation((0.0, 1.0, 0.0), shaft_angle) @ rotation((0.0, 0.0, 1.0), a2)
    return g1, g2
