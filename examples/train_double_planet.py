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

# the efficiency carrier -> ring (sun held) for meshes of 0.90 ... 1
try:
    import matplotlib.pyplot as plt
except ImportError:
    pass
else:
    eta = [0.90 + 0.005 * k for k in range(21)]
    out = [power_flow(t, "carrier", "ring", fixed=["sun"], mesh_efficiency=e).efficiency
           for e in eta]  # fmt: skip
    fig, ax = plt.subplots(figsize=(6, 3.6))
    ax.plot(eta, out, "o-", ms=3)
    ax.plot(eta, eta, "k:", lw=0.8, label="one mesh")
    ax.set_xlabel("efficiency of each mesh")
    ax.set_ylabel("efficiency carrier -> ring")
    ax.grid(alpha=0.3)
    ax.legend()
    ax.set_title("double planet 30/15/15/90, sun held")
    fig.tight_layout()
