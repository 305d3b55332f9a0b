"""Bevel tooth surfaces, solids and scenes (issue 19): gears.bevel.spherical, gears.bevel.crown,
gears.bevel.solid, BevelGear.mesh and BevelPair.scene.

Reference values and their sources:
- the exact octoid by an independent route: the envelope of the crown gear's flank plane
  N(phi) . x = 0 in the gear frame, its characteristic line x ~ N x dN/dphi (written out here,
  not through the library's meshing equation);
- the exact spherical involute by its closed form: a great circle rolling on the base cone
  sin(delta_b) = sin(delta) cos(alpha) (Ozols §21-10), polar angle cos(theta) = cos(psi)
  cos(delta_b), azimuth roll - atan2(sin psi, cos psi sin delta_b) (written out here);
- brute force: the crown gear rolled position by position and united (gears.bevel.crown), against
the
  closed-form envelope;
- the design tooth thickness on the mean pitch cone (ISO 23509, tested in test_bevel.py), scaled
  with the cone distance (the teeth are conical);
- manifold3d's exact boolean intersection volumes for interpenetration, as tests/gears/
  test_mesh.py does for spur pairs; Euler's V - E + F = 2 - 2 g for watertightness.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

trimesh = pytest.importorskip("trimesh")
manifold3d = pytest.importorskip("manifold3d")
from scipy.spatial import cKDTree  # noqa: E402

from gears import BevelPair, GearError  # noqa: E402
from gears.bevel.crown import crown_space, gnomonic  # noqa: E402
from gears.bevel.spherical import direction, polar  # noqa: E402
from gears.solid.mesh import to_manifold  # noqa: E402


# ------------------------------------------------------------------------------ helpers
def _valid(m, genus: int = 0) -> None:
    assert m.is_watertight and m.is_winding_consistent and m.is_volume
    assert m.volume > 0.0  # outward normals
    assert len(np.unique(m.vertices, axis=0)) == len(m.vertices)  # welded
    assert len(np.unique(np.sort(m.faces, axis=1), axis=0)) == len(m.faces)
    assert m.area_faces.min() > 0.0
    assert m.euler_number == 2 - 2 * genus


def _sphere_section(mesh, radius: float) -> np.ndarray:
    """Segments (n, 2, 3) where the sphere of ``radius`` about the apex cuts the mesh: each
    triangle edge crossing the sphere gives its exact crossing point."""
    v = np.asarray(mesh.vertices, float)
    f = np.asarray(mesh.faces)
    d = np.linalg.norm(v, axis=1) - radius
    ends = []
    for a, b in ((0, 1), (1, 2), (2, 0)):
        va, vb = v[f[:, a]], v[f[:, b]]
        da, db = d[f[:, a]], d[f[:, b]]
        cross = (da < 0) != (db < 0)
        e = vb - va
        qa = np.einsum("ij,ij->i", e, e)
        qb = 2 * np.einsum("ij,ij->i", va, e)
        qc = np.einsum("ij,ij->i", va, va) - radius**2
        disc = np.sqrt(np.maximum(qb * qb - 4 * qa * qc, 0.0))
        t1 = (-qb + disc) / (2 * qa)
        t2 = (-qb - disc) / (2 * qa)
        t = np.where((t1 >= 0) & (t1 <= 1), t1, t2)
        ends.append((cross, va + t[:, None] * e))
    mask = np.stack([c for c, _ in ends], 1)
    two = mask.sum(1) == 2
    pts = np.stack([p for _, p in ends], 1)[two]
    return pts[mask[two]].reshape(-1, 2, 3)


def _fold(u, z: int):
    """(polar, azimuth from the space centre) of unit vectors of a gear whose tooth 0 is centred
    on azimuth 0, folded onto the half space of gears.bevel.spherical (space centre at 0, tooth at
    +pi/z)."""
    th, az = polar(u)
    pitch = 2 * math.pi / z
    psi = (az + pitch / 2) % pitch - pitch / 2  # tooth-centred, in [-pi/z, pi/z)
    return th, math.pi / z - np.abs(psi)


def _exact_octoid(tooth, n: int = 40001) -> np.ndarray:
    """The octoid as the envelope of the crown flank plane (independent route): in the gear
    frame the plane normal is N(phi) = Rz(-phi) Rc(sin(delta) phi) N0, and the envelope's line is
    along N x N'(phi)."""
    d, a, sig = tooth.delta, tooth.alpha, math.sin(tooth.delta)
    g = np.array([math.sin(d), 0.0, math.cos(d)])
    ec = np.array([-math.cos(d), 0.0, math.sin(d)])
    ey = np.array([0.0, 1.0, 0.0])
    p = math.cos(tooth.psi_p) * g + math.sin(tooth.psi_p) * ey
    lp = np.cross(ec, p)
    up = math.cos(a) * ec - math.sin(a) * lp
    n0 = np.cross(p, up)

    def rot(v, k, t):
        t = t[:, None]
        return v * np.cos(t) + np.cross(k, v) * np.sin(t) + k * (v @ k)[:, None] * (1 - np.cos(t))

    phi = np.linspace(-1.2, 1.2, n)
    nc = rot(np.broadcast_to(n0, (n, 3)), ec, sig * phi)
    ez = np.array([0.0, 0.0, 1.0])
    big_n = rot(nc, ez, -phi)
    dn = rot(sig * np.cross(ec, nc) - np.cross(ez, nc), ez, -phi)
    u = np.cross(big_n, dn)
    u /= np.linalg.norm(u, axis=1)[:, None]
    return u * np.sign(u[:, 2])[:, None]


def _exact_spherical_involute(tooth, n: int = 40001) -> np.ndarray:
    """The spherical involute of the base cone sin(delta_b) = sin(delta) cos(alpha), through the
    pitch point (delta, psi_p / sin(delta)), on the flank of the space centred at azimuth 0."""
    db = math.asin(math.sin(tooth.delta) * math.cos(tooth.alpha))

    def inv_s(th):
        psi = np.arccos(np.clip(np.cos(th) / math.cos(db), -1, 1))
        return psi / math.sin(db) - np.arctan2(np.sin(psi), np.cos(psi) * math.sin(db))

    th = np.linspace(db + 1e-9, tooth.delta + 0.25, n)
    eta = tooth.psi_p / math.sin(tooth.delta) + inv_s(th) - inv_s(tooth.delta)
    return direction(th, eta)


def _tip_polar(gear, radius: float) -> float:
    """Polar angle where the face cone cuts the sphere of ``radius``: the face line through the
    outer tip point (R_e along the pitch generator, h_ae off it) at the face angle delta_a."""
    d, da = math.radians(gear.pitch_angle), math.radians(gear.face_angle)
    tip = gear.cone_distance * np.array([math.sin(d), math.cos(d)])
    tip = tip + gear.addendum * np.array([math.cos(d), -math.sin(d)])
    u = np.array([math.sin(da), math.cos(da)])
    b = tip @ u
    w = -b + math.sqrt(b * b - (tip @ tip - radius**2))
    q = tip + w * u
    return math.atan2(q[0], q[1])


def _flank_deviation(mesh, gear, radius: float, tol: float) -> float:
    """Largest distance (mm, on the sphere of ``radius``) from the mesh's section points and
    chord midpoints on the working flank to the exact flank."""
    tooth = gear.tooth()
    seg = _sphere_section(mesh, radius)
    pts = np.concatenate([seg[:, 0], seg[:, 1], 0.5 * (seg[:, 0] + seg[:, 1])])
    u = pts / np.linalg.norm(pts, axis=1)[:, None]
    th, eta = _fold(u, gear.teeth)
    exact = _exact_octoid(tooth) if gear.pair.profile == "octoid" else (
        _exact_spherical_involute(tooth))  # fmt: skip
    form = float(polar(tooth.flank_points(tooth.form[1]))[0])
    top = _tip_polar(gear, radius)
    on_flank = (th > form + 0.002) & (th < top - 0.002) & (eta < math.pi / gear.teeth - 1e-4)
    assert on_flank.sum() > 20
    folded = direction(th[on_flank], eta[on_flank])
    d, _ = cKDTree(exact * radius).query(folded * radius)
    return float(d.max())


# ------------------------------------------------------------------------------ solids
@pytest.mark.parametrize(
    "kwargs",
    [
        {"clearance": "tapered"},
        {"clearance": "constant"},
        {"profile": "spherical_involute"},
        {"shaft_angle": 70.0, "profile_shift": 0.2, "thickness_modification": 0.03},
    ],
)
def test_meshes_are_watertight_and_welded(kwargs):
    p = BevelPair(20, 40, module=3, face_width=20, **kwargs)
    for g in p.gears:
        _valid(g.mesh(tolerance=0.02))
    _valid(p.g1.mesh(tolerance=0.02, bore=12.0), genus=1)
    _valid(p.g2.mesh(tolerance=0.02, back_cone=False))


def test_undercut_pinion_meshes():
    # the seeds' 10/16 differential pinion without shift is undercut (test_bevel.py)
    p = BevelPair(10, 16, module=3, face_width=8)
    assert p.g1.tooth().undercut
    _valid(p.g1.mesh(tolerance=0.02))


@pytest.mark.parametrize("z", [3, 4])
@pytest.mark.parametrize("back_cone", [True, False])
def test_pinions_of_three_and_four_teeth_mesh(z, back_cone):
    # issue 26: the rim below the teeth of a 3- or 4-tooth pinion reached past the axis and its
    # message formatted bore=None (TypeError); the band now stops above the axis. The solid must
    # still be valid and, its flanks being the exact ones within the tolerance, its volume lies
    # inside the blank's face cone: below pi R_a^2 times the axial face width plus the rim
    p = BevelPair(z, 40, 3, 10)
    m = p.g1.mesh(tolerance=0.01, back_cone=back_cone)
    _valid(m)
    r_a = p.g1.tip_diameter / 2.0
    assert 0.0 < m.volume < math.pi * r_a**2 * float(np.ptp(m.vertices[:, 2]))
    with pytest.raises(GearError, match=r"bore = 1 mm does not fit.*valid is no bore"):
        p.g1.mesh(tolerance=0.01, bore=1.0, back_cone=back_cone)


@pytest.mark.parametrize("profile", ["octoid", "spherical_involute"])
@pytest.mark.parametrize("clearance", ["tapered", "constant"])
def test_flank_within_tolerance_of_the_exact_surface_on_spherical_sections(profile, clearance):
    p = BevelPair(20, 40, module=3, face_width=20, profile=profile, clearance=clearance)
    tol = 0.01
    r_e, r_i = p.cone_distance, p.cone_distance - p.face_width
    for gear in p.gears:
        mesh = gear.mesh(tolerance=tol)
        for radius in (r_i + 1.0, p.mean_cone_distance, r_e - 0.5):
            dev = _flank_deviation(mesh, gear, radius, tol)
            assert dev <= tol, (gear.teeth, radius, dev)


def test_tooth_thickness_on_the_pitch_cone():
    # design: the arc s_m on the mean pitch cone, scaled with the cone distance (conical teeth);
    # the one-sided sampling may only thin each flank, by less than the tolerance
    p = BevelPair(17, 31, module=4, face_width=14, profile_shift=0.25, thickness_modification=0.04)
    tol = 0.01
    for gear in p.gears:
        mesh = gear.mesh(tolerance=tol)
        delta = math.radians(gear.pitch_angle)
        for radius in (p.cone_distance - 12.0, p.mean_cone_distance, p.cone_distance - 1.0):
            seg = _sphere_section(mesh, radius)
            u = seg / np.linalg.norm(seg, axis=2)[..., None]
            th0, th1 = polar(u[:, 0])[0], polar(u[:, 1])[0]
            cross = (th0 - delta) * (th1 - delta) < 0
            w = (delta - th0[cross]) / (th1[cross] - th0[cross])
            pt = u[cross, 0] + w[:, None] * (u[cross, 1] - u[cross, 0])
            _, eta = _fold(pt / np.linalg.norm(pt, axis=1)[:, None], gear.teeth)
            half_tooth = math.pi / gear.teeth - eta  # tooth half-angle at each flank crossing
            s = 2 * half_tooth * radius * math.sin(delta)
            design = gear.mean_thickness * radius / p.mean_cone_distance
            assert len(s) == 2 * gear.teeth
            assert np.all(s <= design + 1e-9)
            assert np.all(s >= design - 2 * tol)


def test_octoid_and_spherical_involute_differ_by_micrometres():
    # docs/bevel.md states the difference: KHK's 20/40 pair, module 3, at the outer end
    p = BevelPair(20, 40, module=3, face_width=22, clearance="tapered")
    q = BevelPair(
        20, 40, module=3, face_width=22, clearance="tapered", profile="spherical_involute"
    )
    for a, b in zip(p.gears, q.gears, strict=True):
        to, ts = a.tooth(), b.tooth()
        tip = math.radians(a.face_angle)
        form = max(float(polar(t.flank_points(t.form[1]))[0]) for t in (to, ts))
        theta = np.linspace(form + 1e-4, tip, 200)
        eta_o = np.array([polar(to.flank_points(to.flank_at_polar(t)))[1] for t in theta])
        eta_s = np.array([polar(ts.flank_points(ts.flank_at_polar(t)))[1] for t in theta])
        diff = np.abs(eta_o - eta_s) * np.sin(theta) * p.cone_distance
        # they agree at the pitch cone (same point, same pressure angle) ...
        k = np.argmin(np.abs(theta - math.radians(a.pitch_angle)))
        assert diff[k] < 1e-4
        # ... and part by a few micrometres towards root and tip
        assert 5e-4 < diff.max() < 0.01


@pytest.mark.parametrize("undercut", [False, True])
def test_crown_simulation_agrees_with_the_envelope(undercut):
    import shapely

    p = BevelPair(10, 16, module=3, face_width=8) if undercut else BevelPair(20, 40, 3, 20)
    tooth = p.g1.tooth()
    assert tooth.undercut == undercut
    eps = 2e-4
    tip = math.radians(p.g1.face_angle)
    space = crown_space(tooth, eps * p.cone_distance, p.cone_distance, tip)
    half = tooth.conical_half(eps / 20, tip - 1e-4)
    exact = gnomonic(tooth, half.y)
    exact = np.concatenate([exact[::-1] * [-1, 1], exact])
    line = shapely.LineString(exact)
    # the exact curve lies on the simulated boundary within the tolerance ...
    assert max(space.boundary.distance(shapely.points(exact))) <= 0.5 * eps
    # ... and the simulated boundary below the tip lies on the exact curve
    pts = shapely.get_coordinates(shapely.segmentize(space.boundary, eps / 4))
    y = np.stack([np.ones(len(pts)), *pts.T], -1) @ np.stack([tooth.g, tooth.ey, tooth.ec])
    below = polar(y / np.linalg.norm(y, axis=1)[:, None])[0] < tip - 1e-4
    assert max(line.distance(shapely.points(pts[below]))) <= 0.5 * eps


# ------------------------------------------------------------------------------ pairs
def _parts(sc):
    return [to_manifold(sc.geometry[sc.graph[n][1]], sc.graph[n][0]) for n in ("gear1", "gear2")]


@pytest.mark.parametrize("shaft", [90.0, 65.0, 115.0])
def test_pair_scene_meshes_without_interpenetration(shaft):
    p = BevelPair(18, 27, module=3, face_width=12, shaft_angle=shaft)
    tol = 0.01
    pitch = 360.0 / p.z1
    sc = p.scene(tolerance=tol)
    # the axes meet at the apex at the shaft angle
    (m1, _), (m2, _) = sc.graph["gear1"], sc.graph["gear2"]
    assert np.allclose(m1[:3, 3], 0) and np.allclose(m2[:3, 3], 0)
    assert float(m1[:3, 2] @ m2[:3, 2]) == pytest.approx(math.cos(math.radians(shaft)), abs=1e-12)
    m1_mesh = p.g1.mesh(tolerance=tol)
    a, b = _parts(sc)
    assert a.min_gap(b, 1.0) <= tol  # the flanks touch ...
    for angle in (0.0, 0.3 * pitch, 0.55 * pitch, 0.8 * pitch):
        q1, q2 = p.placement(angle)
        g1 = to_manifold(m1_mesh, q1)
        g2 = to_manifold(sc.geometry[sc.graph["gear2"][1]], q2)
        assert (g1 ^ g2).volume() <= 1e-6, angle  # ... and never interpenetrate
        # a quarter pitch more on gear 1 alone: deep interpenetration
        extra = to_manifold(m1_mesh, p.placement(angle + pitch / 4)[0])
        assert (extra ^ g2).volume() > 50.0


def test_backlash_opens_a_gap():
    p = BevelPair(18, 27, module=3, face_width=12)
    a, b = _parts(p.scene(tolerance=0.01, backlash=0.2))
    gap = a.min_gap(b, 1.0)
    # each flank moved by j/4 along its normal at the mean cone: a gap of about j/2 there, the
    # smallest at the inner end (scaled by R_i / R_m)
    assert 0.2 / 2 * (p.cone_distance - p.face_width) / p.mean_cone_distance * 0.9 <= gap


# ------------------------------------------------------------------------------ bad input
@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"tolerance": 0}, "tolerance"),
        ({"tolerance": float("nan")}, "tolerance"),
        ({"tolerance": 1e-9}, "tolerance"),
        ({"bore": -1}, "bore"),
        ({"bore": 200.0}, r"bore = 200 mm does not fit.*valid is bore <"),
        ({"back_cone": "yes"}, "back_cone"),
        ({"backlash": 100.0}, "backlash"),
    ],
)
def test_mesh_bad_input_names_the_value(kwargs, match):
    with pytest.raises(GearError, match=match):
        BevelPair(20, 40, module=3, face_width=20).g1.mesh(**{"tolerance": 0.05, **kwargs})


def test_work_is_bounded():
    big = BevelPair(20, 40, module=200, face_width=1000)
    with pytest.raises(GearError, match=r"would take about .* vertices.*use tolerance >="):
        big.g2.mesh(tolerance=1e-6)
    with pytest.raises(GearError, match="angle"):
        BevelPair(20, 40, 3, 20).scene(angle=float("inf"))


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    z1=st.integers(6, 40),
    z2=st.integers(6, 60),
    shaft=st.floats(40.0, 140.0),
    x=st.floats(-0.3, 0.6),
    clearance=st.sampled_from(["constant", "tapered"]),
    profile=st.sampled_from(["octoid", "spherical_involute"]),
    back_cone=st.booleans(),
)
def test_property_mesh_is_watertight_or_refused(z1, z2, shaft, x, clearance, profile, back_cone):
    try:
        p = BevelPair(z1, z2, 2.0, 1.0, shaft, profile_shift=x, clearance=clearance,
                      profile=profile)  # fmt: skip
        p = BevelPair(z1, z2, 2.0, p.cone_distance / 4, shaft, profile_shift=x,
                      clearance=clearance, profile=profile)  # fmt: skip
    except GearError:
        return
    for gear in p.gears:
        try:
            m = gear.mesh(tolerance=0.05, back_cone=back_cone)
        except GearError as exc:
            assert str(exc)
            continue
        _valid(m)
