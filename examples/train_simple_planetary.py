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

# the speeds of the members, ring held, 1500 rpm on the sun (the planet also about its carrier)
try:
    import matplotlib.pyplot as plt
except ImportError:
    pass
else:
    names = ["sun", "planet", "planet in carrier", "carrier", "ring"]
    speeds = [m["sun"], m["planet"], m.relative("planet", "carrier"), m["carrier"], m["ring"]]
    fig, ax = plt.subplots(figsize=(6, 3.2))
    ax.barh(names, [float(v) for v in speeds], color="tab:blue")
    ax.axvline(0, color="k", lw=0.8)
    ax.invert_yaxis()
    ax.set_xlabel("speed, rpm")
    ax.set_title("sun 20, planets 30, ring 80 (held): sun 1500 rpm -> carrier 300 rpm")
    fig.tight_layout()
