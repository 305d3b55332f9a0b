"""A shifted pinion and its wheel, cut by a rack
=============================================

A shifted 12-tooth pinion in mesh with its 24-tooth wheel (KHK example pair, m = 3):
outlines cut by the simulated rack, checked for clearance, written as SVG and PNG.

The pinion needs x = 0.6 (x_min = 0.298 against undercut at z = 12); the pair then runs at the
working pressure angle 26.09 deg and centre distance 56.50 mm.

Writes into the directory given as the first argument (default: a new temporary directory).
"""

import pathlib
import sys
import tempfile

from gears import Gear, GearPair
from gears.cutting.measure import thickness_on
from gears.solid.export import to_svg

pinion = Gear(12, 3, profile_shift=0.6)
wheel = Gear(24, 3, profile_shift=0.36)
pair = GearPair(pinion, wheel)
out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(tempfile.mkdtemp())
out.mkdir(parents=True, exist_ok=True)
print(f"a_w = {pair.center_distance:.4f} mm, alpha_wt = {pair.working_pressure_angle:.4f} deg")

p1, p2 = pair.outlines(angle=0.0, tolerance=0.001, method="rack", backlash=0.1)
print(f"overlap {p1.intersection(p2).area:.2e} mm^2, clearance {p1.distance(p2) * 1000:.1f} um")
s = thickness_on(p1, pinion.reference_diameter)
# backlash 0.1 mm (normal): each gear is thinned by 0.05 / cos(alpha) on its reference circle
print(f"pinion thickness on d: {s.mean():.4f} mm (formula {pinion.reference_thickness:.4f})")
assert p1.intersection(p2).area < 1e-4

to_svg(out / "pinion_wheel.svg", p1, p2)
try:
    from gears.figures.plot import pair_figure
except ImportError:  # matplotlib missing: the SVG is still written
    pass
else:
    pair_figure(pair, tolerance=0.001).savefig(out / "pinion_wheel.png", dpi=120)
print("wrote pinion_wheel.svg and pinion_wheel.png")
