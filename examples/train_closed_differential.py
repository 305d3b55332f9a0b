"""Closed differential
===================

Closed differential (Ozols example 7-7, the electric hoist), read from its TOML file.

Design task: the drum speed (book: i_14 = 44, n4 = 20 rpm at n1 = 880 rpm; exact 2767/63),
every speed and the efficiency with 98 % meshes. Then the K3 train of the lectures, where the
closing gear pair carries twice the input power (power circulation).
"""

import sys
from fractions import Fraction
from pathlib import Path

from trains import power_flow, read_train, simple_planetary

t = read_train(Path(sys.argv[0]).with_name("train_closed_differential.toml"))
i = t.ratio("1", "4")
m = t.solve({"1": 880})
print(f"i_14 = {i} = {float(i):.4f}; drum n4 = {float(m['4']):.3f} rpm")
pf = power_flow(t, "1", "4", mesh_efficiency=0.98, input_speed=880)
print(f"efficiency {pf.efficiency:.4f}")
assert i == Fraction(2767, 63)

k3 = simple_planetary(18, 45, 108)
k3.mesh("sun", "ring", teeth=(20, 60), name="closing")
flow = power_flow(k3, "sun", "carrier", mesh_efficiency=0.98)
print(f"K3: i = {k3.ratio('sun', 'carrier')}, closing mesh carries"
      f" {flow.relations['closing'].power / flow.input_power:.2f} x input power,"
      f" efficiency {flow.efficiency:.4f}")  # fmt: skip
assert flow.circulating_power > 0.8 * flow.input_power  # lossless: exactly 1

# the power each mesh of K3 carries, against the input power: the closing mesh carries twice it
try:
    import matplotlib.pyplot as plt
except ImportError:
    pass
else:
    names = list(flow.relations)
    share = [abs(flow.relations[n].power) / flow.input_power for n in names]
    fig, ax = plt.subplots(figsize=(6, 3.2))
    ax.barh(names, share, color=["tab:red" if n == "closing" else "tab:blue" for n in names])
    ax.axvline(1, color="k", ls="--", lw=0.8, label="input power")
    ax.invert_yaxis()
    ax.set_xlabel("power through the mesh / input power")
    ax.legend(loc="lower right")
    ax.set_title("K3 with its closing pair 20/60: power circulates")
    fig.tight_layout()
