"""3D files: a helical pinion and a planetary stage
================================================

A printable helical pinion and a phased 18/45/108 planetary stage as 3D files.

1. A right-hand helical pinion z = 20, m = 2, beta = 20 deg, b = 20 mm with a 10 mm bore, to a
   0.01 mm tolerance, as a binary STL for a slicer. The section turns by 2 b tan(beta) / d =
   20.8 deg over the face width.
2. The planetary stage 18/45/108 x 3 (m = 2, ring fixed, u = 7) as a GLB for a viewer or CAD:
   planets at their phases from ``placement()``, the carrier turned by 5 deg and every member by
   its Willis speed, the three planets stored once (instanced).

Writes into the directory given as the first argument (default: a new temporary directory).
Run: ``python examples/mesh_helical_and_planetary.py [out_dir]``.
"""

import pathlib
import sys
import tempfile

from gears import Gear
from gears.solid.export import save
from gears.solid.mesh import to_manifold
from trains import Planetary

out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(tempfile.mkdtemp())
out.mkdir(parents=True, exist_ok=True)

# 1. the pinion
pinion = Gear(20, 2, helix_angle=20)
mesh = pinion.mesh(face_width=20, tolerance=0.01, bore=10)
area = pinion.outline(0.01, bore=10).area
genus = (2 - mesh.euler_number) // 2
print(f"pinion: {len(mesh.faces)} triangles, watertight {mesh.is_watertight}, genus {genus}, "
      f"volume {mesh.volume:.1f} mm^3 (area x b = {area * 20:.1f})")  # fmt: skip
assert mesh.is_watertight and mesh.euler_number == 0  # one handle: the bore
stl = save(out / "pinion.stl", mesh)
print(f"wrote {stl.name} ({stl.stat().st_size} bytes)")

# 2. the stage
stage = Planetary(18, 45, 108, n_planets=3, module=2)
print(f"{stage!r}: ratio {stage.ratio()}, phasing {stage.phasing}")
scene = stage.scene(angle=5.0, face_width=16, tolerance=0.02)
print(f"scene: {len(scene.graph.nodes_geometry)} gears, {len(scene.geometry)} stored meshes "
      f"({', '.join(sorted(scene.geometry))})")  # fmt: skip
# every mesh engages without overlap: manifold3d intersection volumes
sun = to_manifold(scene.geometry["sun"], scene.graph["sun"][0])
ring = to_manifold(scene.geometry["ring"], scene.graph["ring"][0])
for k in (1, 2, 3):
    planet = to_manifold(scene.geometry["planet"], scene.graph[f"planet{k}"][0])
    worst = max((sun ^ planet).volume(), (ring ^ planet).volume())
    print(f"planet{k}: overlap with sun / ring {worst:.4f} mm^3")
    assert worst < 0.02 * 16 * 2  # tolerance x face width x module
glb = save(out / "stage.glb", scene)
print(f"wrote {glb.name} ({glb.stat().st_size} bytes)")

# the stage as a picture: the library's renderer (flat shading, back faces culled)
try:
    import matplotlib.pyplot as plt
except ImportError:  # the STL and the GLB are still written
    pass
else:
    from gears.solid.render import Camera, render_image, scene_parts

    png = render_image(out / "stage.png", scene_parts(scene), Camera(35, -60), size=600)
    fig, ax = plt.subplots(figsize=(6, 6))
    ax.imshow(plt.imread(png))
    ax.set_axis_off()
    ax.set_title("planetary stage 18/45/108, three planets, m = 2")
