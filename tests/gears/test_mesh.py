"""3D gear meshes and scenes (issue 10): gears.solid.mesh, Gear.mesh, GearPair.scene,
Planetary.scene.

Reference values and their sources:
- a prism's volume is its section area times its height (exact; spur gears, bores);
- Cavalieri: every transverse section of a helical or herringbone gear is the same outline
  turned, so its exact volume is also area x face width; the mesh differs from the exact surface
  by at most the outline tolerance plus the helix chord tolerance (gears.solid.mesh docstring), so
  |V - A b| <= 2 tol x lateral area (derivation);
- Euler characteristic V - E + F = 2 - 2 g of a closed surface of genus g (a bore or a ring
  is one handle);
- the helix: a transverse section at height z turns by 2 z tan(beta) / d (ISO 21771, right hand
  positive), the transverse tooth thickness is Gear.tooth_thickness (ISO 21771 formula, tested
  against the seeds in test_gear.py);
- meshing: gears placed by scene() touch without overlap (zero backlash) and overlap after a
  further 0.5 deg; stage phasing from Planetary.placement() (tested against the assembly
  condition in tests/trains/test_planetary.py).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import shapely
from shapely import affinity

trimesh = pytest.importorskip("trimesh")
manifold3d = pytest.importorskip("manifold3d")

from gears import Gear, GearError, GearPair  # noqa: E402
from gears.solid.export import save  # noqa: E402
from gears.solid.mesh import (  # noqa: E402
    gear_solid,
    helix_twist,
    scene,
    slice_count,
    to_manifold,
    transform,
)
from trains import Planetary  # noqa: E402


# ------------------------------------------------------------------------------ helpers
def _theta(gear: Gear, z):
    """Section turn at height z, degrees: 2 z tan(beta) / d (ISO 21771)."""
    return np.degrees(2.0 * np.asarray(z) * math.tan(math.radians(gear.helix_angle)) /
                      gear.reference_diameter)  # fmt: skip


def _section(mesh, z: float) -> shapely.Geometry:
    path = mesh.section(plane_origin=[0.0, 0.0, z], plane_normal=[0.0, 0.0, 1.0])
    planar, _ = path.to_2D(to_2D=np.eye(4))
    return shapely.union_all(list(planar.polygons_full))


def _segments(geom) -> shapely.STRtree:
    lines = shapely.get_parts(shapely.line_merge(geom.boundary))
    segs = []
    for line in lines:
        xy = shapely.get_coordinates(line)
        segs.append(np.stack([xy[:-1], xy[1:]], axis=1))
    return shapely.STRtree(shapely.linestrings(np.concatenate(segs)))


def _hausdorff(a, b, step: float = 0.05) -> float:
    """Two-sided Hausdorff distance of the boundaries, sampled every ``step`` mm (points to the
    other boundary's segments, through a segment index)."""
    out = 0.0
    for p, q in ((a, b), (b, a)):
        pts = shapely.points(shapely.get_coordinates(shapely.segmentize(p.boundary, step)))
        _, d = _segments(q).query_nearest(pts, return_distance=True, all_matches=False)
        out = max(out, float(d.max()))
    return out


def _valid(m) -> None:
    assert m.is_watertight and m.is_winding_consistent and m.is_volume
    assert m.volume > 0.0  # outward normals
    assert len(np.unique(m.vertices, axis=0)) == len(m.vertices)  # welded
    assert len(np.unique(np.sort(m.faces, axis=1), axis=0)) == len(m.faces)  # no duplicates
    assert m.area_faces.min() > 0.0  # no degenerate faces


def _lateral(outline, b: float) -> float:
    return outline.length * b


def _node_manifold(sc, node: str):
    matrix, geom = sc.graph[node]
    return to_manifold(sc.geometry[geom], matrix)


def _overlap(a, b) -> float:
    return float((a ^ b).volume())


# ------------------------------------------------------------------------------ solids
def test_spur_is_an_exact_prism():
    g = Gear(20, 1)
    o = g.outline(0.01)
    m = g.mesh(face_width=10, tolerance=0.01)
    _valid(m)
    assert m.euler_number == 2  # genus 0
    assert m.volume == pytest.approx(o.area * 10, rel=1e-9)  # prism volume, exact
    assert m.bounds[:, 2] == pytest.approx([-5.0, 5.0], abs=1e-12)  # mid-plane at z = 0
    assert len(m.vertices) == 2 * (len(o.exterior.coords) - 1)  # two levels, nothing more


def test_bore_and_ring_add_one_handle():
    bored = Gear(20, 1).mesh(face_width=6, tolerance=0.02, bore=6.0)
    _valid(bored)
    assert bored.euler_number == 0  # genus 1
    o = Gear(20, 1).outline(0.02, bore=6.0)
    assert bored.volume == pytest.approx(o.area * 6, rel=1e-9)
    ring = Gear(60, 1, helix_angle=15, internal=True)
    m = ring.mesh(face_width=8, tolerance=0.02)
    _valid(m)
    assert m.euler_number == 0
    o = ring.outline(0.02)
    assert abs(m.volume - o.area * 8) <= 2 * 0.02 * _lateral(o, 8)  # Cavalieri bound


@pytest.mark.parametrize("herringbone", [False, True])
def test_helical_volume_within_the_slice_bound(herringbone):
    g = Gear(20, 1, helix_angle=20)
    tol = 0.01
    m = g.mesh(face_width=10, tolerance=tol, herringbone=herringbone)
    _valid(m)
    assert m.euler_number == 2
    o = g.outline(tol)
    bound = 2 * tol * _lateral(o, 10)  # Cavalieri + surface within 2 tol (module docstring)
    assert abs(m.volume - o.area * 10) <= bound
    # the bound is not vacuous: the measured error is far below it, and nonzero (sliced)
    assert 0.0 < abs(m.volume - o.area * 10) < 0.2 * bound


def test_sections_follow_the_helix_and_its_hand():
    tol = 0.01
    for beta in (20.0, -20.0):
        g = Gear(20, 1, helix_angle=beta)
        o = g.outline(tol)
        m = g.mesh(face_width=10, tolerance=tol)
        for z in (-4.9, -2.3, 0.0, 1.7, 3.1):
            sec = _section(m, z)
            exact = affinity.rotate(o, _theta(g, z), origin=(0, 0))
            assert _hausdorff(sec, exact) <= 2 * tol  # ISO 21771 helix
            if 1 < abs(z) < 4:  # the opposite hand (not a whole pitch away) is far off
                wrong = affinity.rotate(o, -_theta(g, z), origin=(0, 0))
                assert _hausdorff(sec, wrong) > 20 * tol


def test_herringbone_halves_meet_at_the_mid_plane():
    tol = 0.02
    g = Gear(18, 1, helix_angle=25)
    o = g.outline(tol)
    m = g.mesh(face_width=8, tolerance=tol, herringbone=True)
    for z in (-3.7, -1.0, 0.0, 1.0, 3.7):
        sec = _section(m, z)
        # lower half has the gear's hand; the upper half the opposite one: turn -|theta(z)|
        exact = affinity.rotate(o, -abs(_theta(g, z)), origin=(0, 0))
        assert _hausdorff(sec, exact) <= 2 * tol


def _thicknesses(section, d: float, start: float) -> np.ndarray:
    """Arc lengths of the circle of diameter d inside the section (one per tooth), starting
    the circle at angle ``start`` (radians, a space centre) so no tooth is split."""
    t = start + np.linspace(0.0, 2 * np.pi, 40001)
    circle = shapely.LineString(np.c_[d / 2 * np.cos(t), d / 2 * np.sin(t)])
    inside = section.intersection(circle)
    parts = inside.geoms if hasattr(inside, "geoms") else [inside]
    return np.array([p.length for p in parts])


def test_tooth_thickness_on_sections():
    tol = 0.01
    g = Gear(20, 1, helix_angle=20)
    m = g.mesh(face_width=10, tolerance=tol)
    for z in (-3.0, 2.0):
        sec = _section(m, z)
        start = math.radians(_theta(g, z)) + math.pi / g.teeth  # centre of a space
        for d in (g.base_diameter + 0.3, g.reference_diameter, g.tip_diameter - 0.3):
            s = _thicknesses(sec, d, start)
            assert len(s) == g.teeth
            # ISO 21771 transverse arc thickness (Gear.tooth_thickness)
            assert np.all(np.abs(s - g.tooth_thickness(d)) <= 2 * tol)


def test_tolerance_is_honoured_and_triangles_grow_as_one_over_tolerance():
    g = Gear(20, 1, helix_angle=20)
    fine = 1e-4
    exact = g.outline(fine)  # the exact outline to 0.1 um (its own deviation added below)
    tree = _segments(exact)
    counts = []
    tols = (1e-1, 1e-2, 1e-3)
    for tol in tols:
        m = g.mesh(face_width=10, tolerance=tol)
        counts.append(len(m.faces))
        # vertices against the exact surface: each turned back to z = 0 lies on the outline
        v = m.vertices
        back = -np.radians(_theta(g, v[:, 2]))
        x = np.cos(back) * v[:, 0] - np.sin(back) * v[:, 1]
        y = np.sin(back) * v[:, 0] + np.cos(back) * v[:, 1]
        _, dist = tree.query_nearest(shapely.points(x, y), return_distance=True, all_matches=False)
        assert dist.max() <= tol + fine
        # sections half-way between slices (the worst heights) against the exact surface
        n = int(slice_count(helix_twist(10, 20, g.reference_diameter), g.tip_diameter / 2, tol))
        for z in (-5 + 5 / n, 5 - 15 / n if n > 2 else 0.0):
            sec = _section(m, z)
            turned = affinity.rotate(exact, _theta(g, z), origin=(0, 0))
            assert _hausdorff(sec, turned, step=10 * tol) <= 2 * tol + fine
    # outline vertices ~ tol^-1/2 and slices ~ tol^-1/2: triangles ~ tol^-1 (slope 0.5 + 0.5)
    slope = np.polyfit(np.log(1 / np.array(tols)), np.log(counts), 1)[0]
    assert 0.7 <= slope <= 1.2


# ------------------------------------------------------------------------------ meshing
def _pair_checks(pair: GearPair, tol: float, b: float) -> None:
    sc = pair.scene(angle=0.0, face_width=b, tolerance=tol)
    a1, a2 = _node_manifold(sc, "gear1"), _node_manifold(sc, "gear2")
    # stated bound: a layer tol thick over a strip one module high along the face (the chords
    # of a ring's concave flanks stand up to tol into the space; convex flanks lie inside)
    bound = tol * b * pair.g1.module
    touching = _overlap(a1, a2)
    assert touching <= bound
    assert a1.min_gap(a2, 1.0) <= tol
    turned = pair.scene(angle=0.5, face_width=b, tolerance=tol)
    b1 = _node_manifold(turned, "gear1")
    # 0.5 deg more on gear 1 alone (gear 2 where it was): clearly overlapping
    assert _overlap(b1, a2) > max(3 * bound, 10 * touching)


def test_external_helical_pair_meshes_in_3d():
    # opposite hands for an external pair
    _pair_checks(GearPair(Gear(17, 1, helix_angle=15), Gear(29, 1, helix_angle=-15)), 0.01, 6.0)


def test_internal_helical_pair_meshes_in_3d():
    # the same hand for an internal pair
    pinion = Gear(17, 1, helix_angle=15)
    ring = Gear(60, 1, helix_angle=15, internal=True)
    _pair_checks(GearPair(pinion, ring), 0.01, 6.0)


def test_wrong_hand_pair_overlaps():
    # the same hands on an external pair cannot mesh: the twist separates the sections
    pair = GearPair(Gear(17, 1, helix_angle=15), Gear(29, 1, helix_angle=-15))
    sc = pair.scene(face_width=6.0, tolerance=0.02)
    g2_wrong = pair.g2.with_(helix_angle=15)
    m2 = g2_wrong.mesh(6.0, 0.02)
    a1 = _node_manifold(sc, "gear1")
    matrix, _ = sc.graph["gear2"]
    assert _overlap(a1, to_manifold(m2, matrix)) > 1.0


def _stage_checks(p: Planetary, tol: float, b: float, sc=None) -> float:
    """Largest sun-planet / planet-ring overlap volume; also check the +0.5 deg overlaps."""
    sc = p.scene(face_width=b, tolerance=tol) if sc is None else sc
    sun, ring = _node_manifold(sc, "sun"), _node_manifold(sc, "ring")
    planets = [n for n in sc.graph.nodes_geometry if n.startswith("planet")]
    worst = 0.0
    sun_turned = to_manifold(sc.geometry[sc.graph["sun"][1]], transform(0.5))
    ring_matrix, ring_geom = sc.graph["ring"]
    ring_turned = to_manifold(sc.geometry[ring_geom], transform(0.5) @ ring_matrix)
    for name in planets:
        pm = _node_manifold(sc, name)
        worst = max(worst, _overlap(sun, pm), _overlap(ring, pm))
        bound = tol * b * p.module
        assert _overlap(sun_turned, pm) > 3 * bound
        assert _overlap(ring_turned, pm) > 3 * bound
    return worst


@pytest.mark.parametrize("teeth", [(18, 45, 108), (19, 29, 77)])
def test_planetary_scene_every_mesh_engages(teeth):
    p = Planetary(*teeth, n_planets=3, module=1)
    tol, b = 0.01, 4.0
    assert _stage_checks(p, tol, b) <= tol * b * p.module
    for name, pair in p.meshes.items():  # the stage's own pairs, for the minimum gap
        sc = p.scene(face_width=b, tolerance=tol)
        a = _node_manifold(sc, "sun" if name == "sun-planet" else "ring")
        for k in (1, 2, 3):
            assert a.min_gap(_node_manifold(sc, f"planet{k}"), 1.0) <= tol, (name, pair)


def test_same_phase_planets_overlap_where_phasing_says_sequential():
    p = Planetary(19, 29, 77, n_planets=3, module=1)
    assert set(p.phasing.values()) == {"sequential"}
    tol, b = 0.05, 4.0
    pl = p.placement()
    sun, planet, ring = (g.mesh(b, tol) for g in (p.sun, p.planet, p.ring))
    parts = [("sun", sun, transform(pl.sun_rotation)), ("ring", ring, transform(pl.ring_rotation))]
    for k, phi in enumerate(pl.planet_angles):
        # every planet a copy of planet 1 turned about the stage axis: the same tooth phase
        place = transform(phi) @ transform(pl.planet_rotations[0], (pl.planet_radius, 0.0))
        parts.append((f"planet{k + 1}", planet, place))
    sc = scene(parts)
    sun_m, ring_m = _node_manifold(sc, "sun"), _node_manifold(sc, "ring")
    planets = [_node_manifold(sc, f"planet{k}") for k in (1, 2, 3)]
    overlaps = [max(_overlap(sun_m, pm), _overlap(ring_m, pm)) for pm in planets]
    assert overlaps[0] <= tol * b  # planet 1 is placed right
    assert min(overlaps[1:]) > 1.0  # the others collide: phasing is needed


def test_planetary_scene_instances_planets_and_turns_with_the_carrier():
    p = Planetary(18, 45, 108, n_planets=3, module=1)
    sc = p.scene(face_width=4.0, tolerance=0.1)
    assert sorted(sc.geometry) == ["planet", "ring", "sun"]
    assert sorted(sc.graph.nodes_geometry) == ["planet1", "planet2", "planet3", "ring", "sun"]
    # carrier turned by 10 deg, ring fixed: planet centres turn by 10 deg, ring stays
    later = p.scene(angle=10.0, face_width=4.0, tolerance=0.1)
    c0, c1 = sc.graph["planet1"][0][:2, 3], later.graph["planet1"][0][:2, 3]
    assert math.degrees(math.atan2(c1[1], c1[0]) - math.atan2(c0[1], c0[0])) == pytest.approx(10)
    assert np.allclose(sc.graph["ring"][0], later.graph["ring"][0])
    # the sun turns by (1 + z3/z1) x 10 deg (Willis, ring fixed: 1 + 108/18 = 7)
    r0, r1 = sc.graph["sun"][0], later.graph["sun"][0]
    turn = math.degrees(math.atan2(r1[1, 0], r1[0, 0]) - math.atan2(r0[1, 0], r0[0, 0]))
    assert turn % 360 == pytest.approx(70.0)
    assert _stage_checks(p, 0.1, 4.0, later) <= 0.1 * 4.0  # still in mesh


# ------------------------------------------------------------------------------ files
@pytest.mark.parametrize("ext", [".stl", ".3mf", ".glb", ".obj", ".ply"])
def test_files_round_trip_with_the_same_volume(tmp_path, ext):
    m = Gear(16, 1, helix_angle=15).mesh(face_width=5, tolerance=0.05)
    path = save(tmp_path / f"g{ext}", m)
    back = trimesh.load(path, force="mesh")
    assert back.is_watertight or ext in (".stl", ".obj")  # STL/OBJ reload unmerged: weld first
    back.merge_vertices()
    assert back.is_watertight
    assert back.volume == pytest.approx(m.volume, rel=1e-5)  # float32 in STL/GLB


def test_planetary_glb_stores_one_planet_and_3mf_keeps_names(tmp_path):
    p = Planetary(18, 45, 108, n_planets=3, module=1)
    sc = p.scene(face_width=4.0, tolerance=0.05)
    glb = save(tmp_path / "stage.glb", sc)
    back = trimesh.load(glb)
    assert len(back.geometry) == 3  # sun, ring, ONE planet
    names = ["planet1", "planet2", "planet3", "ring", "sun"]
    assert sorted(back.graph.nodes_geometry) == names
    single = sum(save(tmp_path / f"{k}.glb", sc.geometry[k]).stat().st_size for k in sc.geometry)
    assert glb.stat().st_size <= 1.2 * single  # the target
    m3f = trimesh.load(save(tmp_path / "stage.3mf", sc))
    assert {"sun", "ring", "planet"} <= set(m3f.geometry)
    assert sorted(m3f.graph.nodes_geometry) == names  # one named object per gear
    assert m3f.volume == pytest.approx(sc.volume, rel=1e-6)


def test_save_errors(tmp_path):
    m = Gear(12, 1).mesh(face_width=2, tolerance=0.1)
    with pytest.raises(GearError, match="one mesh"):
        save(tmp_path / "a.stl", m, m)
    with pytest.raises(GearError, match="format"):
        save(tmp_path / "a.xyz", m)


# ------------------------------------------------------------------------------ stability
@pytest.mark.parametrize(
    "kwargs",
    [
        dict(teeth=5, module=1, profile_shift=0.5),  # few teeth
        dict(teeth=400, module=1),  # many teeth
        dict(teeth=20, module=0.1, helix_angle=20),
        dict(teeth=20, module=50, helix_angle=-20),
        dict(teeth=20, module=1, helix_angle=45),
        dict(teeth=20, module=1, helix_angle=-45),
        dict(teeth=8, module=1),  # undercut (x = 0 < x_min)
        dict(teeth=10, module=1, profile_shift=0.9),  # pointed tip
        dict(teeth=40, module=1, helix_angle=45, internal=True),
    ],
)
def test_stability(kwargs):
    g = Gear(**kwargs)
    tol = 0.02 * g.module
    m = g.mesh(face_width=5 * g.module, tolerance=tol, herringbone=g.helix_angle > 0)
    _valid(m)  # every case gives a valid mesh (none needs the GearError way out)
    assert m.euler_number == (0 if g.internal else 2)
    assert np.all(np.isfinite(m.vertices))


@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan, math.inf, "x"])
def test_bad_input_raises(bad):
    g = Gear(20, 1)
    with pytest.raises(GearError, match="face_width"):
        g.mesh(face_width=bad)
    with pytest.raises(GearError, match="tolerance"):
        g.mesh(face_width=5, tolerance=bad)
    with pytest.raises(GearError, match="Polygon"):
        gear_solid("not a polygon", 5)
    with pytest.raises(GearError, match="twist"):
        gear_solid(shapely.box(0, 0, 1, 1), 1, twist=math.nan)


def test_mesh_face_width_defaults_like_the_scenes():
    # issue 16: Gear.mesh() takes the gear's own face width, else 10 modules, the default of
    # GearPair.scene, Planetary.scene and geartrain mesh (the extent along the axis is exact:
    # the caps are planes at +-b/2)
    assert Gear(20, 2).mesh(tolerance=0.1).extents[2] == pytest.approx(20.0, abs=1e-12)
    assert Gear(20, 2, face_width=7).mesh(tolerance=0.1).extents[2] == pytest.approx(7, abs=1e-12)


def test_scene_rejects_bad_parts():
    box = trimesh.creation.box()
    with pytest.raises(GearError, match="twice"):
        scene([("a", box), ("a", box)])
    with pytest.raises(GearError, match="4x4"):
        scene([("a", box, np.eye(3))])
    with pytest.raises(GearError, match="at least one"):
        scene([])


# ------------------------------------------------------------------------------ CLI
def test_cli_mesh(tmp_path, capsys):
    from trains.cli.app import main

    out = tmp_path / "g.stl"
    argv = ["mesh", "20", "--module", "1", "--helix", "20", "--face-width", "10"]
    assert main([*argv, "--tolerance", "0.05", "-o", str(out)]) == 0
    back = trimesh.load(out)
    back.merge_vertices()
    assert back.is_watertight
    expected = Gear(20, 1, helix_angle=20).mesh(10, 0.05)
    assert back.volume == pytest.approx(expected.volume, rel=1e-5)  # float32 STL
    herring = tmp_path / "h.glb"
    assert main([*argv, "--herringbone", "--tolerance", "0.1", "-o", str(herring)]) == 0
    ring = tmp_path / "r.3mf"
    assert main(["mesh", "60", "--internal", "--face-width", "4", "--tolerance", "0.1",
                 "-o", str(ring)]) == 0  # fmt: skip
    assert trimesh.load(ring, force="mesh").euler_number == 0
    bored = tmp_path / "b.ply"
    assert main(["mesh", "12", "--module", "3", "--shift", "0.6", "--method", "rack",
                 "--bore", "10", "--tolerance", "0.1", "-o", str(bored)]) == 0  # fmt: skip
    assert trimesh.load(bored).euler_number == 0
    capsys.readouterr()
    # bad input: exit 2 with one line on stderr, before any work
    for bad in (["-o", str(tmp_path / "missing" / "g.stl")], ["-o", str(tmp_path / "g.svg")],
                ["--face-width", "-1", "-o", str(out)]):  # fmt: skip
        assert main(["mesh", "20", *bad]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "Traceback" not in err


def test_cli_pair_and_planetary_scenes(tmp_path, capsys):
    from trains.cli.app import main

    glb = tmp_path / "pair.glb"
    assert main(["pair", "17", "29", "--helix", "15", "--scene", str(glb),
                 "--tolerance", "0.1"]) == 0  # fmt: skip
    assert sorted(trimesh.load(glb).graph.nodes_geometry) == ["gear1", "gear2"]
    stage = tmp_path / "stage.3mf"
    gif = tmp_path / "stage.gif"
    argv = ["planetary", "18", "45", "108", "--planets", "3", "--module", "2"]
    movie = ["--animate", str(gif), "--frames", "2"]
    assert main([*argv, "--scene", str(stage), *movie, "--tolerance", "0.1"]) == 0
    loaded = trimesh.load(stage)
    assert {"sun", "ring", "planet"} <= set(loaded.geometry)
    assert gif.read_bytes()[:6] == b"GIF89a"
    from PIL import Image

    with Image.open(gif) as im:
        assert im.n_frames == 2
    capsys.readouterr()
    # a missing directory or a wrong suffix is refused before any work (exit 2, one line)
    for bad in (
        ["--scene", str(tmp_path / "no" / "s.glb")],
        ["--animate", str(tmp_path / "a.avi")],
    ):
        assert main([*argv, *bad]) == 2
        captured = capsys.readouterr()
        assert captured.out == "" and captured.err.count("\n") == 1


@pytest.mark.parametrize(
    ("args", "scheme", "nodes"),
    [
        ((26, (70, 21), 117), "stepped", 8),  # the stepped example of geartrain planetary
        ((20, (20, 20), 80), "double-planet", 8),
    ],
)
def test_stepped_and_double_planet_scenes_engage(args, scheme, nodes):
    p = Planetary(*args, n_planets=3, module=1, scheme=scheme)
    tol, b = 0.02, 4.0
    sc = p.scene(face_width=b, tolerance=tol)
    names = sorted(sc.graph.nodes_geometry)
    assert len(names) == nodes and len(sc.geometry) == 4  # two planet geometries, instanced
    solids = {n: _node_manifold(sc, n) for n in names}
    for i, a in enumerate(names):  # no two gears overlap beyond the chord bound
        for other in names[i + 1 :]:
            assert _overlap(solids[a], solids[other]) <= tol * b * p.module, (a, other)
    if scheme == "stepped":  # the ring-side step stands on the sun-side step
        assert sc.graph["planet1'"][0][2, 3] - sc.graph["planet1"][0][2, 3] == pytest.approx(b)


@pytest.mark.parametrize("method", ["rack", "shaper"])
def test_generated_teeth_export_as_cut(method):
    # the simulated-cutting outline feeds the solid unchanged: a spur prism of that outline
    g = Gear(14, 1, profile_shift=0.3)
    m = g.mesh(face_width=3, tolerance=0.05, method=method)
    _valid(m)
    o = g.outline(0.05, method=method)
    assert m.volume == pytest.approx(o.area * 3, rel=1e-9)  # prism volume, exact
    sec = _section(m, 0.7)
    assert _hausdorff(sec, o) <= 1e-9  # the section is the cut outline itself
