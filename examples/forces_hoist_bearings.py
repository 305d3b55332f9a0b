"""Bearing loads of the electric hoist
======================================

The forces on every tooth and every bearing of the electric hoist of Ozols example 7-7 (the
closed differential of Fig. 7-13), on the real gears of ``rate_planetary_hoist.py``.

Design task: the motor gives 5.5 kW at n1 = 880 rpm (T1 = 59.7 N m) with 98 % meshes. Which
radial load must each bearing carry: the input shaft 1, the drum 4 (the carrier of the
planets 2-2'), the planets' pins, the idler 5 of the closing chain? The idler's shaft has two
bearings 50 mm either side of its gear; how do they share its load?

``trains.loads`` turns the power flow's torques into the mesh forces (Ozols (11.8)) and sums
them on every member; every member's forces and torques balance, and the frame's bearings
carry no net force.
"""

import math

import numpy as np

from gears import Gear
from trains import Train, loads

POWER, N1 = 5500.0, 880.0  # W, rpm
T1 = POWER / (N1 * 2 * math.pi / 60)  # N m


def g(z, m, b, internal=False):
    return Gear(z, m, face_width=b, internal=internal)


t = Train()
t.mesh("1", "2", gears=(g(24, 3, 30), g(52, 3, 30)), carrier="4")
t.mesh("2", "3", gears=(g(21, 4, 40), g(78, 4, 40, True)), carrier="4")
t.mesh("3", "5", gears=(g(18, 4, 60), g(30, 4, 60)))
t.mesh("5", "4", gears=(g(30, 4, 60), g(78, 4, 60, True)))
t.set_planets("2", 3)

ld = loads(t, "1", "4", torque=T1, speed=N1, mesh_efficiency=0.98,
           axial={"3-5": 0.0, "5-4": 0.0}, bearings={"5": (-50.0, 50.0)})  # fmt: skip
print(f"T1 = {T1:.2f} N m at {N1:g} rpm, meshes 98 %")
print(ld)

# every member balances: its mesh forces' moment and its torque, its forces and its bearings
for m in ld.members.values():
    assert abs(m.moment + m.torque) < 1e-9 * max(1.0, abs(m.torque))
held = np.sum([m.bearing for m in ld.members.values() if m.carried_by == "frame"], axis=0)
assert np.allclose(held, 0.0, atol=1e-6)

# three planets: the input shaft carries no radial load; the idler's two bearings share its
# load equally (its gear is centred between them) and its two meshes' radial parts cancel
assert ld.members["1"].radial_load < 1e-6
ra, rb = ld.members["5"].reactions
print(f"idler 5: {ld.members['5'].radial_load:.1f} N, bearings {np.hypot(*ra[:2]):.1f} N "
      f"and {np.hypot(*rb[:2]):.1f} N")  # fmt: skip
assert np.allclose(ra, rb)
print(f"planet pin 2: {ld.members['2'].radial_load:.1f} N each; drum 4 holds "
      f"{-ld.members['4'].torque:.1f} N m")  # fmt: skip

# the radial load on each member's bearings (N), the planets' pins per planet
try:
    import matplotlib.pyplot as plt
except ImportError:
    pass
else:
    names = list(ld.members)
    fig, ax = plt.subplots(figsize=(6, 3.2))
    ax.barh(names, [ld.members[n].radial_load for n in names], color="tab:blue")
    ax.invert_yaxis()
    ax.set_xlabel("radial bearing load, N")
    ax.set_ylabel("member")
    ax.set_title(f"hoist at {T1:.1f} N m, {N1:g} rpm: the loads on the bearings")
    fig.tight_layout()
