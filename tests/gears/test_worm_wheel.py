"""The worm wheel built on the envelope of the worm's thread (gears.worm.envelope,
gears.worm.solid.wheel_solid), held to references computed another way.

References:
- the exact conjugate surface off the mid-plane: the contact lines of the worm's helicoid found
  in 3D by the condition of meshing n . v_12 = 0 (Litvin, Gear Geometry and Applied Theory,
  eq. 6.1.13; Joldasbekov 6-3), with the worm placed and turned by WormPair.placements: an
  independent route (the library reduces each plane of the wheel to a rack instead);
- the pair at zero backlash has no volume in common beyond the chords (the meshing theorem: the
  conjugate flanks touch along lines), and a small extra turn of the worm makes them overlap;
- the limit of a large worm diameter: a ZI worm is an involute helicoid, and as its diameter
  grows (lead angle gamma -> 0) its axial section tends to a straight rack of alpha_x, so the
  wheel's mid-plane section tends to the transverse section of the involute helical gear of
  helix angle gamma, normal module m_x cos gamma and normal pressure angle alpha_n (DIN 3975;
  the core's Gear.tooth_thickness, ISO 21771, as the independent formula).
"""

from __future__ import annotations

import math
import time

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from gears import Gear, GearError, WormPair
from gears.cutting.measure import thickness_on
from gears.worm.envelope import plane_rack, rack_conjugate, rolled

trimesh = pytest.importorskip("trimesh")

from gears.solid.mesh import to_manifold  # noqa: E402


def contact_points(w: WormPair, flank: float, n_r: int = 24, n_phi: int = 90) -> np.ndarray:
    """Points of the wheel's flank in its own frame by the 3D condition of meshing: the worm's
    flank ``Z = flank h(r) + s p theta`` (its own frame), each point's normal ``n`` and its
    velocity relative to the wheel ``v_12`` (a finite difference of the placements in the
    wheel's frame); along each worm radius ``n . v_12`` changes sign at the contact line."""
    g = w.geometry
    s = 1.0 if w.hand == "right" else -1.0
    p = float(g.lead) / (2.0 * math.pi)
    rf = float(g.worm_root_diameter) / 2.0
    rt = float(g.worm_tip_diameter) / 2.0 + w.clearance * w.module
    r = np.linspace(rf + 0.05 * (rt - rf), rt - 0.05 * (rt - rf), n_r)[:, None]
    th = np.linspace(-3.0 * np.pi, 3.0 * np.pi, 2400)[None, :]

    def surface(rr, tt):
        hh = flank * np.asarray(w.axial_profile(np.broadcast_to(rr, tt.shape * 0 + rr.shape)))
        hh = np.broadcast_to(hh, np.broadcast_shapes(rr.shape, tt.shape))
        return np.stack(np.broadcast_arrays(rr * np.cos(tt), rr * np.sin(tt), hh + s * p * tt), -1)

    pts = surface(r, th)
    dr = (surface(r + 1e-6, th) - surface(r - 1e-6, th)) / 2e-6
    dt = (surface(r, th + 1e-6) - surface(r, th - 1e-6)) / 2e-6
    normal = np.cross(dr, dt)
    out = []
    for phi in np.linspace(-180.0, 180.0, n_phi, endpoint=False):
        frames = []
        for ang in (phi, phi + 1e-4):
            worm_at, wheel_at = w.placements(ang)
            frames.append(np.linalg.inv(wheel_at) @ worm_at)  # the worm's frame in the wheel's
        m0, m1 = frames
        p0 = pts @ m0[:3, :3].T + m0[:3, 3]
        f = np.einsum("...i,...i->...", normal @ m0[:3, :3].T, pts @ m1[:3, :3].T + m1[:3, 3] - p0)
        i, j = np.nonzero(np.sign(f[:, :-1]) * np.sign(f[:, 1:]) < 0)
        a = (f[i, j] / (f[i, j] - f[i, j + 1]))[:, None]
        out.append(p0[i, j] + a * (p0[i, j + 1] - p0[i, j]))
    return np.concatenate(out)


def signed_distance(mesh, pts: np.ndarray, k: int = 8) -> np.ndarray:
    """Distance of points to a mesh, > 0 outside (signed by the outward normal of the triangle
    holding the closest point). Exact, not a guess from the triangles nearest by centroid (long
    thin triangles between far planes can hold the closest point with a far centroid): the
    ``k`` triangles nearest by centroid bound the distance by ``d``, and a triangle can come
    nearer only if its centroid lies within ``d`` plus its reach (the largest distance from its
    centroid to its corners), so every such triangle is searched: a ball query (scipy cKDTree)
    for the triangles of small reach, the bounding boxes for the few large ones (the caps)."""
    from scipy.spatial import cKDTree

    pts = np.asarray(pts, float)
    tri = mesh.triangles
    cen = tri.mean(axis=1)
    reach = np.linalg.norm(tri - cen[:, None], axis=2).max(axis=1)
    big = reach > 2.0 * np.median(reach)
    small = np.flatnonzero(~big)
    tree = cKDTree(cen[small])
    _, nn = tree.query(pts, k=k)
    rep = np.repeat(pts, k, axis=0)
    cp = trimesh.triangles.closest_point(tri[small[nn.ravel()]], rep)
    bound = np.linalg.norm(rep - cp, axis=1).reshape(-1, k).min(axis=1)
    near = tree.query_ball_point(pts, bound + reach[small].max())
    i = np.repeat(np.arange(len(pts)), [len(c) for c in near])
    j = small[np.concatenate([np.asarray(c, dtype=int) for c in near])]
    ok = np.linalg.norm(cen[j] - pts[i], axis=1) <= bound[i] + reach[j]
    cand_p, cand_t = [i[ok]], [j[ok]]
    lo, hi, bi = tri[big].min(axis=1), tri[big].max(axis=1), np.flatnonzero(big)
    for start in range(0, len(pts), 256):
        chunk = pts[start : start + 256, None]
        gap = np.linalg.norm(np.maximum(np.maximum(lo - chunk, chunk - hi), 0.0), axis=2)
        i, j = np.nonzero(gap <= bound[start : start + 256, None])
        cand_p.append(i + start)
        cand_t.append(bi[j])
    cand_p, cand_t = np.concatenate(cand_p), np.concatenate(cand_t)
    foot = trimesh.triangles.closest_point(tri[cand_t], pts[cand_p])
    dist = np.linalg.norm(pts[cand_p] - foot, axis=1)
    order = np.lexsort((dist, cand_p))
    best = order[np.searchsorted(cand_p[order], np.arange(len(pts)))]
    side = np.einsum("ij,ij->i", mesh.face_normals[cand_t[best]], pts - foot[best])
    return dist[best] * np.where(side < 0.0, -1.0, 1.0)


def plane_tips(wheel) -> tuple[np.ndarray, np.ndarray]:
    """The planes of a lofted wheel and the largest radius of each one's vertices: its tip,
    the throat's, or lower where a pointed tooth's flanks cross (above that the neighbouring
    flank cuts the contact lines away)."""
    v = wheel.vertices
    zs, inv = np.unique(np.round(v[:, 2], 9), return_inverse=True)
    tips = np.zeros(len(zs))
    np.maximum.at(tips, inv, np.hypot(v[:, 0], v[:, 1]))
    return zs, tips


def working_flank(w: WormPair, wheel, q: np.ndarray) -> np.ndarray:
    """The points ``q`` on the working flank: inside the faces and 0.1 mm below the tip, above
    the pitch circle (below it the fillet may cut the envelope away: undercut)."""
    a, rk, re2 = w.center_distance, w.throat_radius, w.wheel_outside_diameter / 2.0
    rho = np.hypot(q[:, 0], q[:, 1])
    tip = np.minimum(a - np.sqrt(np.maximum(rk**2 - q[:, 2] ** 2, 0.0)), re2)
    tip = np.minimum(tip, np.interp(q[:, 2], *plane_tips(wheel)))
    keep = (np.abs(q[:, 2]) < w.face_width / 2 - 0.2) & (rho < tip - 0.1)
    return q[keep & (rho > w.wheel_diameter / 2.0)]


@pytest.mark.parametrize(
    ("w", "tol"),
    [
        (WormPair(2, 30, 2.0, diameter_quotient=10, flank="ZI", hand="left"), 0.1),
        (
            WormPair(1, 16, 2.0, diameter_quotient=10, flank="ZA", profile_shift=0.3, face_width=8),
            0.1,
        ),
        # the benchmark's pair (docs/performance.md): teeth pointed near the faces, undercut
        (WormPair(1, 16, 2.0, diameter_quotient=10, flank="ZA"), 0.02),
    ],
    ids=["ZI-2-30-left", "ZA-1-16", "ZA-1-16-x0"],
)
def test_flanks_off_the_mid_plane_are_the_exact_conjugate(w, tol):
    wheel = w.wheel_mesh(tol)
    for flank in (1.0, -1.0):
        q = working_flank(w, wheel, contact_points(w, flank))
        assert np.count_nonzero(np.abs(q[:, 2]) > 3.0) > 200  # off the mid-plane
        d = signed_distance(wheel, q)
        assert np.all(np.abs(d) <= tol), (flank, d.min(), d.max())


def test_the_distance_to_a_mesh_finds_a_long_triangle_whose_centroid_is_far():
    # a cylinder lofted through one tall band (z 0 to 1) and short ones above: a point just
    # outside the tall band near its top has the short bands' centroids nearer than the tall
    # band's (the 24 nearest centroids missed the closest triangle there, as they once did on
    # a wheel at tolerance 0.01 mm: 0.019 mm reported inside). Reference: the closest point on
    # every triangle, the sign by the radius
    from gears.solid.mesh import loft_solid

    ang = np.linspace(0.0, 2.0 * np.pi, 2000, endpoint=False)
    ring = np.column_stack([10.0 * np.cos(ang), 10.0 * np.sin(ang)])
    heights = np.concatenate([[0.0], np.linspace(1.0, 1.4, 21)])
    mesh = loft_solid(np.stack([np.column_stack([ring, np.full(len(ring), h)])
                                for h in heights]))  # fmt: skip
    t = np.array([0.1, 1.3, 2.0, 4.0])
    pts = np.column_stack([10.001 * np.cos(t), 10.001 * np.sin(t), [0.95, 0.9, 0.5, 1.25]])
    pts = np.vstack([pts, pts * [0.9998, 0.9998, 1.0]])  # and just inside
    tri = mesh.triangles
    brute = []
    for p in pts:
        foot = trimesh.triangles.closest_point(tri, np.repeat(p[None], len(tri), 0))
        dist = np.linalg.norm(foot - p, axis=1)
        brute.append(dist.min() * (1.0 if np.hypot(p[0], p[1]) > 9.999 else -1.0))
    np.testing.assert_allclose(signed_distance(mesh, pts, k=24), brute, rtol=0, atol=1e-12)


def test_zero_backlash_shares_no_volume_and_an_extra_turn_overlaps():
    # the flanks' chords (tolerance 0.1 mm) leave at most a film of the chords' sag between
    # the two solids' vertices: bound 0.01 mm^3, against about 1 mm^3 for 3 degrees more turn
    w = WormPair(1, 16, 2.0, diameter_quotient=10, flank="ZA", profile_shift=0.3)
    worm, wheel = w.worm_mesh(0.1), w.wheel_mesh(0.1)
    for angle in (0.0, 7.0, 90.0, 200.0):
        worm_at, wheel_at = w.placements(angle)
        common = to_manifold(worm, worm_at) ^ to_manifold(wheel, wheel_at)
        assert common.volume() < 0.01, (angle, common.volume())
    for extra in (3.0, -3.0):
        worm_at, _ = w.placements(extra)
        _, wheel_at = w.placements(0.0)
        assert (to_manifold(worm, worm_at) ^ to_manifold(wheel, wheel_at)).volume() > 0.1


def _mid_plane_deviation(q: float, tol: float) -> np.ndarray:
    w = WormPair(1, 30, 2.0, diameter_quotient=q, flank="ZI", face_width=4)
    rings = to_manifold(w.wheel_mesh(tol)).slice(0.0).to_polygons()
    section = max((shapely.Polygon(r) for r in rings), key=lambda p: p.area)
    m_n = w.normal_module
    helical = Gear(30, module=m_n, helix_angle=w.lead_angle, pressure_angle=w.normal_pressure_angle)
    # above the form circle of the hob's sharp corner (d_Ff 56.75 mm here, ISO 21771)
    lo = max(w.wheel_diameter - 1.5 * w.module, helical.base_diameter + 0.3)
    return np.concatenate(
        [
            thickness_on(section, d) - helical.tooth_thickness(d)
            for d in np.linspace(lo, w.wheel_tip_diameter - 0.3, 5)
        ]
    )


def test_a_large_worm_diameter_makes_the_wheel_the_involute_helical_gear():
    tol = 0.005
    near = _mid_plane_deviation(10.0, tol)
    far = _mid_plane_deviation(200.0, tol)
    # the limit: within the chords' share (each flank's chords inside the tooth, at most
    # tol / 2 in the plane) and 1e-3 mm of the remaining lead angle's effect (0.29 deg)
    assert np.all(far > -tol - 1e-3) and np.all(far < 1e-3), far
    # and approached: a ZI worm of q 10 (gamma 5.7 deg) is measurably farther from it
    assert np.max(np.abs(near)) > np.max(np.abs(far)) + 2e-3


PAIRS = st.builds(
    lambda z1, z2, q, flank, x, hand, face: WormPair(
        z1,
        z2,
        2.0,
        diameter_quotient=q,
        flank=flank,
        profile_shift=x,
        hand=hand,
        face_width=face,
    ),
    st.integers(1, 4),
    st.integers(12, 60),
    st.floats(7.0, 20.0),
    st.sampled_from(["ZA", "ZN", "ZI", "ZK"]),
    st.floats(-0.5, 0.5),
    st.sampled_from(["right", "left"]),
    st.one_of(st.none(), st.floats(2.0, 30.0)),
)


@given(PAIRS, st.floats(0.2, 0.5))
@settings(max_examples=8, deadline=None, derandomize=True, database=None,
          suppress_health_check=list(HealthCheck))  # fmt: skip
def test_any_wheel_is_watertight_or_refused_with_our_error(w, tol):
    t0 = time.perf_counter()
    try:
        wheel = w.wheel_mesh(tol)
    except GearError as exc:
        assert "=" in str(exc) or "plane" in str(exc)
    else:
        assert wheel.is_watertight and wheel.is_winding_consistent and wheel.volume > 0.0
        assert np.all(np.isfinite(wheel.vertices))
    assert time.perf_counter() - t0 < 20.0


FINITE = st.floats(-1e3, 1e3, allow_nan=False)


@given(FINITE, FINITE, st.sampled_from([-1.0, 1.0]), FINITE, FINITE, st.floats(1.0, 1e3))
@settings(max_examples=60, deadline=None, derandomize=True, database=None)
def test_envelope_formulas_are_finite(zeta, depth, side, half, slope, pitch_radius):
    # every formula of the plane's rack and its conjugate answers finite numbers for finite
    # input (a normal parallel to the pitch line is sent far away, not to inf)
    x, y, nx, ny = plane_rack(zeta, depth, side, half, slope, 60.0, 1.5)
    px, py, u = rack_conjugate(x, y, nx, ny, pitch_radius)
    rx, ry = rolled(x, y, depth, pitch_radius)
    assert all(np.all(np.isfinite(v)) for v in (x, y, nx, ny, px, py, u, rx, ry))


def test_animation_writes_its_frames(tmp_path):
    from PIL import Image

    w = WormPair(1, 20, 2.0, flank="ZA")
    out = w.animate(tmp_path / "pair.gif", frames=3, tolerance=0.3, size=120)
    with Image.open(out) as im:
        assert im.n_frames == 3 and im.size == (120, 120)


@given(st.sampled_from([0, -1, 1.5, "3", None, 10**9]), st.sampled_from([0.0, -1.0, float("nan")]))
@settings(max_examples=10, deadline=None, derandomize=True, database=None)
def test_animation_refuses_bad_frames_and_fps_before_any_work(frames, fps):
    w = WormPair(1, 20, 2.0)
    t0 = time.perf_counter()
    with pytest.raises(GearError, match=r"frames|fps"):
        w.animate("pair.gif", frames=frames, fps=fps)
    assert time.perf_counter() - t0 < 2.0
