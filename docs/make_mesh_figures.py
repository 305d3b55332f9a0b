"""Draw the figures of docs/meshes.md (and the stage in mesh of docs/planetary.md) from the meshes.

Rendered with matplotlib (flat shading, one light) from the very meshes ``Gear.mesh`` and
``Planetary.scene`` return; the chart comes from the benchmark's results
(``python tests/benchmarks/bench_mesh.py`` writes ``tests/benchmarks/results/mesh.json``).

Run: ``python docs/make_mesh_figures.py`` (writes ``docs/images/mesh_*.png`` and
``docs/images/mesh_planetary.gif``).
"""

from __future__ import annotations

import json
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import PathPatch
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from gears import Gear
from gears.solid.animate import polygon_path
from gears.solid.mesh import COLOURS
from trains import Planetary

HERE = pathlib.Path(__file__).resolve().parent
IMAGES = HERE / "images"
RESULTS = HERE.parent / "tests" / "benchmarks" / "results" / "mesh.json"
LIGHT = np.array([0.4, -0.5, 0.77])


def _view_direction(elev, azim):
    """Unit vector from the scene towards an orthographic camera at ``elev``/``azim`` (deg)."""
    e, a = np.radians(elev), np.radians(azim)
    return np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])


def _draw(ax, mesh, colour, matrix=None, elev=32, azim=-60):
    """The mesh's faces that face the camera, shaded by their own (outward) normals.

    matplotlib has no depth buffer: it paints polygons sorted by depth, which goes wrong where
    long faces of a non-convex solid (a ring's rim behind its teeth) overlap. Faces turned away
    from the camera are hidden in the solid anyway; leaving them out removes those errors."""
    v = np.asarray(mesh.vertices)
    n = np.asarray(mesh.face_normals)
    if matrix is not None:
        v = v @ matrix[:3, :3].T + matrix[:3, 3]
        n = n @ matrix[:3, :3].T
    front = n @ _view_direction(elev, azim) > 0.0
    tri, n = v[mesh.faces[front]], n[front]
    shade = 0.35 + 0.65 * np.clip(n @ (LIGHT / np.linalg.norm(LIGHT)), 0.0, 1.0)
    rgb = np.asarray(colour[:3], dtype=float) / 255.0
    faces = np.clip(shade[:, None] * rgb, 0.0, 1.0)
    # not antialiased: antialiased edges of neighbouring faces leave seams that read as cracks
    ax.add_collection3d(
        Poly3DCollection(tri, facecolors=faces, edgecolors=faces, lw=0.2, antialiased=False)
    )
    return v


def _frame(ax, points, title, elev=32, azim=-60):
    lo, hi = points.min(axis=0), points.max(axis=0)
    c, r = (lo + hi) / 2, (hi - lo).max() / 2
    ax.set_xlim(c[0] - r, c[0] + r)
    ax.set_ylim(c[1] - r, c[1] + r)
    ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect((1, 1, max((hi[2] - lo[2]) / (2 * r), 0.05)), zoom=1.25)
    ax.set_proj_type("ortho")  # the camera _draw culls for: no perspective
    ax.view_init(elev=elev, azim=azim)
    ax.set_axis_off()
    ax.set_title(title, fontsize=10)


def solo(path, mesh, colour, title, elev=32, azim=-60):
    fig = plt.figure(figsize=(4.2, 4.2))
    ax = fig.add_subplot(projection="3d")
    _frame(ax, _draw(ax, mesh, colour, elev=elev, azim=azim), title, elev=elev, azim=azim)
    fig.tight_layout()
    fig.savefig(path, dpi=110, bbox_inches="tight")  # the whole title, no empty margins
    plt.close(fig)
    print("wrote", path)


def stage_3d(path, p, b, tol):
    sc = p.scene(face_width=b, tolerance=tol)
    fig = plt.figure(figsize=(5.5, 5.5))
    ax = fig.add_subplot(projection="3d")
    pts = []
    for node in sc.graph.nodes_geometry:
        matrix, geom = sc.graph[node]
        colour = sc.geometry[geom].visual.material.baseColorFactor
        pts.append(_draw(ax, sc.geometry[geom], colour, matrix, elev=40))
    z = p.teeth
    title = f"Planetary({z[0]}, {z[1]}, {z[3]}, n_planets={p.n_planets}).scene()"
    _frame(ax, np.concatenate(pts), title, elev=40)
    fig.tight_layout()
    fig.savefig(path, dpi=110, bbox_inches="tight")  # the whole title, no empty margins
    plt.close(fig)
    print("wrote", path)


def stage_2d(path, p, tol):
    shapes = p.outlines(0.0, tol)
    fig, ax = plt.subplots(figsize=(5, 5))
    for name, shape in shapes.items():
        key = "sun" if name == "sun" else ("ring" if name == "ring" else "planet")
        ax.add_patch(PathPatch(polygon_path(shape), facecolor=np.asarray(COLOURS[key]) / 255,
                               edgecolor="k", lw=0.3))  # fmt: skip
    pl = p.placement()
    z = p.teeth
    title = (f"Planetary({z[0]}, {z[1]}, {z[3]}, n_planets={p.n_planets}, module={p.module:g})"
             f".outlines()\nplanets at {', '.join(f'{a:g}' for a in pl.planet_angles)} deg, "
             f"turned {', '.join(f'{r:.1f}' for r in pl.planet_rotations)} deg")  # fmt: skip
    ax.set_title(title, fontsize=9)
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_axis_off()
    fig.tight_layout()
    fig.savefig(path, dpi=110, bbox_inches="tight")  # the whole title, no empty margins
    plt.close(fig)
    print("wrote", path)


def chart(path):
    if not RESULTS.exists():
        print("no benchmark results; run tests/benchmarks/bench_mesh.py first")
        return
    data = json.loads(RESULTS.read_text())
    rows = data["rows"]
    tol = np.array([r["tolerance"] for r in rows])
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(8, 3.6))  # readable at the page width
    for key, label, style in (
        ("spur_solid_ms", "spur: gear_solid on the outline", "o-"),
        ("naive_extrude_ms", "spur: trimesh extrude_polygon (naive)", "s--"),
        ("spur_ms", "spur: Gear.mesh (outline included)", "o:"),
        ("helical_ms", "helical beta 20: Gear.mesh", "^-"),
        ("planetary_ms", "18/45/108 x 3: Planetary.scene", "d-"),
    ):
        a1.loglog(tol, [r[key] for r in rows], style, label=label)
    a1.set_xlabel("tolerance, mm")
    a1.set_ylabel("best wall time, ms")
    a1.invert_xaxis()
    a1.grid(True, which="both", alpha=0.3)
    a1.legend(fontsize=7)
    a1.set_title("time (z = 20, m = 1, b = 10; stage m = 1)", fontsize=9)
    a2.loglog(tol, [r["helical_section_deviation"] for r in rows], "^-",
              label="helical: sections between slices (Hausdorff)")  # fmt: skip
    a2.loglog(tol, 2 * tol, "k--", lw=0.8, label="2 x tolerance (the tested bound)")
    a2.loglog(tol, tol, "k:", lw=0.8, label="tolerance")
    a3 = a2.twinx()
    a3.loglog(tol, [r["helical_triangles"] for r in rows], "g.-", alpha=0.6)
    a3.set_ylabel("helical triangles (green)", color="g")
    a2.set_xlabel("tolerance, mm")
    a2.set_ylabel("achieved deviation, mm")
    a2.invert_xaxis()
    a2.grid(True, which="both", alpha=0.3)
    a2.legend(fontsize=7, loc="lower left")
    a2.set_title("accuracy (helical, against the exact surface)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110, bbox_inches="tight")  # the whole title, no empty margins
    plt.close(fig)
    print("wrote", path)


def main():
    IMAGES.mkdir(exist_ok=True)
    solo(IMAGES / "mesh_helical_pinion.png",
         Gear(20, 2, helix_angle=20).mesh(face_width=20, tolerance=0.02),
         COLOURS["gear1"], "Gear(20, 2, helix_angle=20).mesh(20)")  # fmt: skip
    solo(IMAGES / "mesh_herringbone.png",
         Gear(24, 2, helix_angle=25).mesh(face_width=24, tolerance=0.02, herringbone=True),
         COLOURS["gear2"], "Gear(24, 2, helix_angle=25).mesh(24, herringbone=True)")  # fmt: skip
    solo(IMAGES / "mesh_ring.png",
         Gear(60, 2, helix_angle=15, internal=True).mesh(face_width=16, tolerance=0.02),
         COLOURS["ring"], "Gear(60, 2, helix_angle=15, internal=True).mesh(16)",
         elev=45)  # fmt: skip
    stage = Planetary(18, 45, 108, n_planets=3, module=2)
    stage_3d(IMAGES / "mesh_planetary.png", stage, 16.0, 0.05)
    stage_2d(IMAGES / "mesh_planetary_2d.png", stage, 0.01)
    path = IMAGES / "mesh_planetary.gif"
    stage.animate(path, frames=36, fps=12, turn=6 * stage.mesh_cycle(), tolerance=0.05)
    print("wrote", path)
    chart(IMAGES / "mesh_speed_accuracy.png")


if __name__ == "__main__":
    main()
