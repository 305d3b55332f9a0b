"""Benchmark: 3D gear meshes, speed versus accuracy (issue 10).

For tolerances 1e-1 ... 1e-3 mm, best-of-N wall time, triangle count and achieved deviation of

* ``spur``: z = 20, m = 1, b = 10 (``Gear.mesh``, outline included) and, on the same outline,
  ``gear_solid`` alone against the naive baseline ``trimesh.creation.extrude_polygon``;
* ``helical``: the same gear with beta = 20 deg (``Gear.mesh``, outline included);
* ``planetary``: the 18/45/108 x 3 stage at m = 1, b = 10 (``Planetary.scene``, every outline
  and solid included, the stage object built once);

and the GLB size of the planetary scene against sun + ring + one planet written alone and
against a naive scene that stores every planet's own copy.

Achieved deviation of the helical gear: (a) every vertex turned back by ``2 z tan(beta)/d`` to
the exact outline (tolerance / 100); (b) sections half-way between two slices (the worst
heights) against the exact outline turned, as a vertex-to-segment Hausdorff distance.

Writes ``tests/benchmarks/results/mesh.json``; ``python docs/make_mesh_figures.py`` draws the
chart from it. Run: ``python tests/benchmarks/bench_mesh.py``. Not collected by pytest.
"""

from __future__ import annotations

import json
import os
import pathlib
import platform
import tempfile
import time

import numpy as np
import shapely
import trimesh
from shapely import affinity

from gears import Gear
from gears.solid.export import save
from gears.solid.mesh import gear_solid, helix_twist, scene, slice_count
from trains import Planetary

HERE = pathlib.Path(__file__).resolve().parent
RESULTS = HERE / "results" / "mesh.json"
TOLERANCES = [1e-1, 3e-2, 1e-2, 3e-3, 1e-3]


def best_of(fn, repeat):
    best = np.inf
    out = None
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t)
    return best, out


def _directed(a, b):
    """Largest distance from a vertex of ``a`` to the segments of ``b`` (indexed)."""
    pb = [shapely.get_coordinates(r) for r in b]
    segs = np.concatenate([np.stack([p[:-1], p[1:]], axis=1) for p in pb])
    tree = shapely.STRtree(shapely.linestrings(segs))
    pts = np.concatenate([shapely.get_coordinates(r) for r in a])
    _, d = tree.query_nearest(shapely.points(pts), return_distance=True)
    return float(d.max())


def _rings(p):
    polys = p.geoms if hasattr(p, "geoms") else [p]
    return [r for q in polys for r in (q.exterior, *q.interiors)]


def hausdorff(a, b):
    ra, rb = _rings(a), _rings(b)
    return max(_directed(ra, rb), _directed(rb, ra))


def section(mesh, z):
    path = mesh.section(plane_origin=[0.0, 0.0, z], plane_normal=[0.0, 0.0, 1.0])
    planar, _ = path.to_2D(to_2D=np.eye(4))
    return shapely.union_all(list(planar.polygons_full))


def helical_deviation(g, b, tol, mesh):
    exact = g.outline(tol / 100)
    rate = 2 * np.tan(np.radians(g.helix_angle)) / g.reference_diameter  # rad per mm
    v = mesh.vertices
    back = -rate * v[:, 2]
    x = np.cos(back) * v[:, 0] - np.sin(back) * v[:, 1]
    y = np.sin(back) * v[:, 0] + np.cos(back) * v[:, 1]
    vertex = float(shapely.distance(shapely.points(x, y), exact.boundary).max())
    n = int(slice_count(helix_twist(b, g.helix_angle, g.reference_diameter), g.tip_diameter / 2,
                        tol))  # fmt: skip
    dz = b / n
    sec = 0.0
    for z in (-b / 2 + dz / 2, -b / 2 + (n // 2 + 0.5) * dz):
        turned = affinity.rotate(exact, np.degrees(rate * z), origin=(0, 0))
        sec = max(sec, hausdorff(section(mesh, z), turned))
    return vertex, sec, n


def glb_sizes(p, tol, b):
    sc = p.scene(face_width=b, tolerance=tol)
    tmp = pathlib.Path(tempfile.mkdtemp())
    instanced = save(tmp / "stage.glb", sc).stat().st_size
    alone = sum(save(tmp / f"{k}.glb", sc.geometry[k]).stat().st_size for k in sc.geometry)
    # naive: every gear its own mesh with the placement baked into the vertices (no instancing)
    parts = []
    for node in sc.graph.nodes_geometry:
        matrix, geom = sc.graph[node]
        parts.append((node, sc.geometry[geom].copy().apply_transform(matrix)))
    naive = save(tmp / "naive.glb", scene(parts)).stat().st_size
    soup = save(tmp / "stage.stl", sc).stat().st_size  # STL: every triangle on its own
    triangles = sum(len(sc.geometry[sc.graph[n][1]].faces) for n in sc.graph.nodes_geometry)
    stored = sum(len(g.faces) for g in sc.geometry.values())
    return dict(instanced=instanced, alone=alone, naive=naive, stl=soup, triangles_shown=triangles,
                triangles_stored=stored)  # fmt: skip


def main():
    b = 10.0
    spur, helical = Gear(20, 1), Gear(20, 1, helix_angle=20)
    stage = Planetary(18, 45, 108, n_planets=3, module=1)
    stage.scene(face_width=b, tolerance=0.1)  # warm caches and imports
    rows = []
    for tol in TOLERANCES:
        repeat = 15 if tol >= 1e-2 else 7
        outline = spur.outline(tol)
        t_spur, m_spur = best_of(lambda t=tol: spur.mesh(b, t), repeat)
        t_solid, _ = best_of(lambda o=outline: gear_solid(o, b), repeat)
        t_naive, m_naive = best_of(lambda o=outline: trimesh.creation.extrude_polygon(o, b), repeat)
        t_hel, m_hel = best_of(lambda t=tol: helical.mesh(b, t), repeat)
        t_stage, sc = best_of(lambda t=tol: stage.scene(face_width=b, tolerance=t), 5)
        vertex, sec, n = helical_deviation(helical, b, tol, m_hel)
        row = dict(
            tolerance=tol,
            spur_ms=1e3 * t_spur, spur_triangles=len(m_spur.faces),
            spur_solid_ms=1e3 * t_solid, naive_extrude_ms=1e3 * t_naive,
            naive_triangles=len(m_naive.faces), naive_watertight=bool(m_naive.is_watertight),
            helical_ms=1e3 * t_hel, helical_triangles=len(m_hel.faces), helical_slices=n,
            helical_vertex_deviation=vertex, helical_section_deviation=sec,
            planetary_ms=1e3 * t_stage,
            planetary_triangles_stored=sum(len(g.faces) for g in sc.geometry.values()),
        )  # fmt: skip
        rows.append(row)
        print(
            f"tol {tol:7.0e}: spur {row['spur_ms']:6.2f} ms (solid {row['spur_solid_ms']:.2f}"
            f" vs naive extrude {row['naive_extrude_ms']:.2f} ms), helical {row['helical_ms']:6.2f}"
            f" ms {row['helical_triangles']:6d} tri ({n} slices), dev vertex {vertex:.2e}"
            f" section {sec:.2e}, planetary {row['planetary_ms']:6.1f} ms"
            f" {row['planetary_triangles_stored']} tri"
        )
    sizes = glb_sizes(stage, 0.01, b)
    print(
        f"planetary GLB at 10 um: {sizes['instanced']} bytes instanced, {sizes['alone']} sun + "
        f"ring + one planet alone ({sizes['instanced'] / sizes['alone']:.3f}x), "
        f"{sizes['naive']} naive per-planet copies, {sizes['stl']} as STL; triangles stored "
        f"{sizes['triangles_stored']}"
        f" of {sizes['triangles_shown']} shown"
    )
    RESULTS.parent.mkdir(exist_ok=True)
    meta = dict(machine=platform.machine(), cpus=os.cpu_count(), python=platform.python_version(),
                numpy=np.__version__, trimesh=trimesh.__version__)  # fmt: skip
    RESULTS.write_text(json.dumps(dict(meta=meta, rows=rows, glb=sizes), indent=1))
    print(f"wrote {RESULTS}")


if __name__ == "__main__":
    main()
