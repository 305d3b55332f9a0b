"""Reverted two-stage reducer
==========================

Reverted (coaxial) two-stage reducer on real gears: input and output shafts on one axis.

Design task: a reducer of about 4.5 with stages 17/40 and 20/38 at module 2 whose output shaft
lines up with its input. The zero-shift centre distances are 57 and 58 mm, so the stage with the
smaller tooth sum is profile-shifted to 58 mm (``coaxial_shifts``; the inverse involute,
ISO 21771 §5); the train is then checked mesh by mesh and for coaxiality, and its efficiency is
estimated from each mesh's own contact ratio (Ozols (14.25), friction 0.06).
"""

from gears import Gear
from trains import Train, coaxial_shifts, power_flow

m = 2.0
p12, p34 = coaxial_shifts([(Gear(17, m, face_width=20), Gear(40, m, face_width=20)),
                           (Gear(20, m, face_width=22), Gear(38, m, face_width=20))])  # fmt: skip
print(f"stage 1: x = {p12.g1.profile_shift:+.4f} / {p12.g2.profile_shift:+.4f}, "
      f"a_w = {p12.center_distance:.6f} mm, contact ratio {p12.contact_ratio:.4f}")  # fmt: skip
print(f"stage 2: x = {p34.g1.profile_shift:+.4f} / {p34.g2.profile_shift:+.4f}, "
      f"a_w = {p34.center_distance:.6f} mm, contact ratio {p34.contact_ratio:.4f}")  # fmt: skip

t = Train()
t.name = "reverted reducer 17/40 + 20/38, m = 2"
t.mesh("in", "lay", pair=p12)
t.mesh("lay", "out", pair=p34)
t.coaxial("in", "out")
i = t.ratio("in", "out")
print(f"ratio in/out = {i} = {float(i):.4f}")

report = t.check()
print(report)
assert report.ok, report.failed()
assert abs(p12.center_distance - p34.center_distance) < 1e-9

flow = power_flow(t, "in", "out", friction=0.06)
for name, rel in flow.relations.items():
    print(f"mesh {name}: efficiency {rel.efficiency:.5f} (from its contact ratio)")
print(f"overall efficiency {flow.efficiency:.5f}")
assert abs(flow.efficiency - p12.mesh_efficiency(0.06) * p34.mesh_efficiency(0.06)) < 1e-12

# both stages with their real tooth outlines at the common centre distance
try:
    from gears.figures.plot import pair_figure
except ImportError:  # matplotlib missing
    pass
else:
    for pair, name in ((p12, "17/40"), (p34, "20/38")):
        fig = pair_figure(pair, tolerance=0.01)
        fig.axes[0].set_title(f"stage {name}: a_w = {pair.center_distance:.3f} mm, contact ratio "
                              f"{pair.contact_ratio:.3f}")  # fmt: skip
