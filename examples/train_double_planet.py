"""Double-planet train
===================

Double-planet (sun - planet - planet - ring) train: a "plus" train.

Design task: with the ring fixed, the carrier turns against the sun; with the sun fixed it
follows the ring slowly. Efficiency of a plus train stays high only far from i0 = 1.
"""

from trains import double_planet, power_flow

t = double_planet(sun=30, planet1=15, planet2=15, ring=90)
print(t.name)
print("ring fixed: i_sun,carrier =", t.ratio("sun", "carrier", fixed=["ring"]))
print("sun fixed: i_ring,carrier =", t.ratio("ring", "carrier", fixed=["sun"]))
pf = power_flow(t, "carrier", "ring", fixed=["sun"], mesh_efficiency=0.98)
print(f"carrier -> ring efficiency {pf.efficiency:.5f}")
assert t.ratio("sun", "carrier", fixed=["ring"]) == -2
