"""K-H-V train and strain-wave drive
=================================

K-H-V train and strain-wave drive: one planet inside a ring, a small tooth difference.

Design task: reduction of an internal pair 49/50 with a W-coupling output (Ozols Fig 7-9b:
-49), and of a two-wave strain-wave drive 200/202 (Joldasbekov E8: -z1/(z2 - z1) = -100).
"""

from trains import khv, power_flow, strain_wave

t = khv(planet=49, ring=50)
i = t.ratio("carrier", "output", fixed=["ring"])
pf = power_flow(t, "carrier", "output", fixed=["ring"], mesh_efficiency=0.99)
print(f"K-H-V: i = {i}, efficiency {pf.efficiency:.4f}")
w = strain_wave(flexspline=200, rigid=202)
j = w.ratio("generator", "flexspline", fixed=["rigid"])
print("strain wave: i =", j)
assert i == -49 and j == -100
