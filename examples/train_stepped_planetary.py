"""Stepped-planet trains
=====================

Stepped-planet 2K-H trains: external+internal, two external (David), two internal meshes.

Design task: compare the three schemes of lectures §4.2 for the same tooth counts, then the
David mechanism of Ozols example 7-4 (1/10000, exact) and its efficiency both ways (ex. 14-3).
"""

from trains import power_flow, stepped_planetary

for kinds in [("external", "internal"), ("external", "external"), ("internal", "internal")]:
    t = stepped_planetary(30, 45, 20, 81, meshes=kinds)
    print(f"{kinds}: i_1H = {t.ratio('1', 'H', fixed=['3'])}")

david = stepped_planetary(100, 101, 100, 99, meshes=("external", "external"))
i = david.ratio("1", "H", fixed=["3"])
print("David mechanism i_1H =", i)
fwd = power_flow(david, "1", "H", fixed=["3"], mesh_efficiency={"1-2": 0.98})
back = power_flow(david, "H", "1", fixed=["3"], mesh_efficiency={"1-2": 0.98})
print(f"gear 1 driving: efficiency {fwd.efficiency:.2f}, self-locking {fwd.self_locking}")
print(f"carrier driving: efficiency {back.efficiency:.5f}")
assert i.denominator == 10000 and fwd.self_locking and abs(back.efficiency - 0.004976) < 1e-6

# gear 1 -> carrier of the three meshings of 30/45/20/81 (gear 3 held): signed ratios
try:
    import matplotlib.pyplot as plt
except ImportError:
    pass
else:
    kinds = [("external", "internal"), ("external", "external"), ("internal", "internal")]
    ratios = [float(stepped_planetary(30, 45, 20, 81, meshes=k).ratio("1", "H", fixed=["3"]))
              for k in kinds]  # fmt: skip
    fig, ax = plt.subplots(figsize=(6, 2.8))
    ax.barh([" / ".join(k) for k in kinds], ratios, color="tab:blue")
    ax.axvline(0, color="k", lw=0.8)
    ax.invert_yaxis()
    ax.set_xlabel("i_1H (gear 3 held)")
    ax.set_title("stepped planetary 30/45/20/81, by mesh kinds")
    fig.tight_layout()
