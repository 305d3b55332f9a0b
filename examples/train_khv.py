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

# the K-H-V train's efficiency against its mesh efficiency: a high ratio costs efficiency
try:
    import matplotlib.pyplot as plt
except ImportError:
    pass
else:
    eta = [0.95 + 0.0025 * k for k in range(21)]
    out = [power_flow(t, "carrier", "output", fixed=["ring"], mesh_efficiency=e).efficiency
           for e in eta]  # fmt: skip
    fig, ax = plt.subplots(figsize=(6, 3.6))
    ax.plot(eta, out, "o-", ms=3, label="K-H-V 49/50, i = -49")
    ax.plot(eta, eta, "k:", lw=0.8, label="one mesh")
    ax.set_xlabel("mesh efficiency")
    ax.set_ylabel("efficiency carrier -> output")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
