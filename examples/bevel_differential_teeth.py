"""A differential with real bevel teeth
====================================

The car differential of Ozols (Fig. 7-11, eq. (7.9)) with real straight bevel teeth.

examples/train_bevel_differential.py solves this drive by the Willis formula alone; here every
mesh is a real straight bevel pair: side gears of 16 teeth, two pinions of 10 (Gleason
proportions, m = 3), and the final drive 11/41 as a bevel pair too (m = 4, its input counted about
the axis pointing to the apex, so the case turns the input's way). The design task: the speeds
when the inner wheel runs 10 % slower than the case, every check of the three meshes and of the
pinions, the losses, and the differential in 3D (GLB) and cornering (GIF).

Writes into the directory given as the first argument (default: a new temporary directory).
Run: ``python examples/bevel_differential_teeth.py [out_dir]``.
"""

import pathlib
import sys
import tempfile
from fractions import Fraction

from gears import BevelPair
from gears.solid.export import save
from gears.solid.mesh import to_manifold
from trains import Differential, power_flow

out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(tempfile.mkdtemp())
out.mkdir(parents=True, exist_ok=True)

diff = Differential(side=16, pinion=10, n_pinions=2, module=3, gleason=True)
t = diff.train
drive = BevelPair.gleason(11, 41, module=4, face_width=20)
t.mesh("input", "case", pair=drive, opposed=True, name="final-drive")

# cornering: 3000 rpm in, the inner (left) wheel 10 % slower than the case
case = Fraction(3000 * 11, 41)
m = t.solve(input=3000, left=case * Fraction(9, 10))
spin = float(m.relative("pinion", "case"))
print(f"case {float(m['case']):.2f} rpm, left {float(m['left']):.2f}, right "
      f"{float(m['right']):.2f}, pinions spin {spin:.2f} rpm")  # fmt: skip
assert m["left"] + m["right"] == 2 * m["case"]  # Ozols (7.9), exact

report = t.check()
print(f"{len(report)} findings, all hold: {report.ok}")
assert report.ok, report.failed()
for name in ("pinion-right.contact_ratio", "final-drive.contact_ratio", "pinion.assembly"):
    print(report[name])

flow = power_flow(t, "input", "left", fixed=["right"], friction=0.06)
print(f"efficiency input -> left wheel (right wheel held), friction 0.06: {flow.efficiency:.4f}")

scene = diff.scene(angle=12.0, left=0.9, right=1.1, tolerance=0.02)
solids = {n: to_manifold(scene.geometry[scene.graph[n][1]], scene.graph[n][0])
          for n in scene.graph.nodes_geometry}  # fmt: skip
worst = max((solids[a] ^ solids[b]).volume() for a in solids for b in solids if a < b)
print(f"scene: {len(solids)} gears, {len(scene.geometry)} stored meshes, largest overlap "
      f"{worst:.2g} mm^3")  # fmt: skip
assert worst <= 1e-6
glb = save(out / "differential.glb", scene)
gif = diff.animate(out / "differential.gif", frames=12, left=0.9, right=1.1, tolerance=0.1)
print(f"wrote {glb.name} and {gif.name}")

# the scene as a picture: the library's renderer (flat shading, back faces culled)
try:
    import matplotlib.pyplot as plt
except ImportError:  # the GLB and the GIF are still written
    pass
else:
    from gears.solid.render import Camera, render_image, scene_parts

    png = render_image(out / "differential.png", scene_parts(scene), Camera(20, -50), size=600)
    fig, ax = plt.subplots(figsize=(6, 6))
    ax.imshow(plt.imread(png))
    ax.set_axis_off()
    ax.set_title("differential 16/10, Gleason, m = 3: the left wheel 10 % slower")
