"""Simple planetary reducer
========================

Simple (James) planetary reducer: sun 20, planet 30, ring 80, three planets.

Design task: the speeds of a motor-driven reducer (sun at 1500 rpm, ring held), the planet
bearing speed, the torques and the efficiency with 98 % meshes (Kreines' rule).
"""

from trains import power_flow, simple_planetary

t = simple_planetary(sun=20, planet=30, ring=80, n_planets=3)
print(t.name, "| mobility", t.mobility, "| redundant constraints", t.structure.redundant)
i = t.ratio("sun", "carrier", fixed=["ring"])
m = t.solve(sun=1500, ring=0)
print(f"ratio sun/carrier = {i}; carrier {m['carrier']} rpm;"
      f" planet bearing {m.relative('planet', 'carrier')} rpm")  # fmt: skip
pf = power_flow(t, "sun", "carrier", fixed=["ring"], mesh_efficiency=0.98, input_speed=1500)
print(pf)
assert i == 5 and m["carrier"] == 300
assert abs(pf.efficiency - (1 + 4 * 0.98**2) / 5) < 1e-12
