"""A cycloidal drive and its compound variant
===========================================

A cycloidal drive and its compound variant: ratio, clearance, pin loads.

Design task: a robot joint reducer of about 1:20 in one stage, 80 mm across the pins, and a
compound drive for about 1:64. One disc of 20 lobes on 21 pins gives -20 (the K-H-V train,
Ozols Fig 7-9b); the disc is cut 0.02 mm undersize (equidistant modification) for running
clearance, and the pin loads at 20 N m follow the equal-rigidity sharing. The compound drive of
discs with 8 and 7 lobes on 9 fixed and 8 turning pins gives 64 (a published generator printed 56
for these discs). Both discs are drawn (SVG).
"""

from gears.solid.export import save
from trains import CycloidalDrive

drive = CycloidalDrive(pins=21, pin_radius=2.5, eccentricity=1.2, pin_circle_radius=40.0,
                       equidistant=0.02)  # fmt: skip
print(drive, "ratio", drive.ratio)
print(drive.check())
forces = drive.contact_forces(20_000.0, 0.0)
print(f"pins loaded {int((forces > 0).sum())} of {drive.pins}, largest {forces.max():.0f} N")
disc, pins = drive.outlines(0.0, tolerance=0.005)
save("cycloidal_drive.svg", disc, *pins.geoms)
compound = CycloidalDrive(9, 3.0, 1.0, 40.0, output_pins=8, output_pin_circle_radius=36.0)
print(compound, "ratio", compound.ratio)
assert drive.ratio == -20 and compound.ratio == 64 and drive.check().ok

# the disc among its pins at crank angle 0
try:
    from gears.figures.plot import outlines_figure
except ImportError:  # matplotlib missing: the SVG is still written
    pass
else:
    fig = outlines_figure(disc, *pins.geoms)
    fig.axes[0].set_title(f"cycloidal disc, {drive.pins} pins: ratio {drive.ratio}")
