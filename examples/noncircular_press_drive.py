"""Elliptical gears for a press drive
===================================

Elliptical gears for a press drive: a slow working stroke and a quick return from a constant
motor speed.

Design task: a crank press should move at most 1.6 times slower than the mean on its working
half-turn and return quickly. Two identical elliptical gears (Litvin) give the ratio
(1 - e)/(1 + e) ... (1 + e)/(1 - e), so e = (1.6 - 1)/(1.6 + 1) = 0.2308. The centre distance
is 2 A = 100 mm; the teeth (module 2.5) are cut by a rack rolled along the ellipse, checked
tooth by tooth, and their transmission error measured against the law. The pair is drawn in mesh
(SVG) and written as a 3D scene (GLB).
"""

import numpy as np

from gears import NonCircularPair
from gears.solid.export import save

slowest = 1.6
e = (slowest - 1) / (slowest + 1)
pair = NonCircularPair.elliptical(50.0, e, module=2.5)
print(pair)
phi = np.linspace(0.0, 360.0, 721)
speed = pair.output_speed(phi)  # the crank's speed per unit motor speed
print(f"crank speed {speed.min():.4f} ... {speed.max():.4f} of the motor's")
print(f"slowest / mean {1 / speed.min():.4f}, fastest / slowest {speed.max() / speed.min():.4f}")
report = pair.check()
print(report)
te = pair.transmission_error(np.linspace(0.0, 360.0, 25), tolerance=0.02)
arc = np.abs(np.radians(te)) * pair.radius2(np.linspace(0.0, 360.0, 25))
print(f"transmission error of the cut teeth: {arc.max() * 1000:.1f} um of arc (tolerance 20 um)")
save("press_pair.svg", *pair.outlines(30.0, 0.02))
save("press_pair.glb", pair.scene(30.0, face_width=12.0, tolerance=0.02))
assert report.ok and abs(1 / speed.min() - slowest) < 1e-6 and arc.max() < 0.02

# the crank's speed over one turn of the motor: slow through the pressing stroke
try:
    import matplotlib.pyplot as plt
except ImportError:
    pass
else:
    fig, ax = plt.subplots(figsize=(6, 3.4))
    ax.plot(phi, speed)
    ax.axhline(1.0, color="k", lw=0.6, ls=":")
    ax.set_xlabel("motor angle, deg")
    ax.set_ylabel("crank speed / motor speed")
    ax.set_xticks(range(0, 361, 60))
    ax.grid(alpha=0.3)
    ax.set_title(
        f"elliptical pair e = {e:.4f}: slowest {speed.min():.3f}, fastest {speed.max():.3f}"
    )
    fig.tight_layout()
