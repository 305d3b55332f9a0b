"""Wolfrom train
=============

Wolfrom (3K) train: high ratio from a stepped planet between two rings (Ozols Fig 7-9a).

Design task: ratio and efficiency of sun 20 / planet 30-29 / rings 80 (fixed) and 77 (output);
the carrier idles. Power circulates inside, so the efficiency is far below one mesh's.
"""

from fractions import Fraction

from trains import power_flow, wolfrom

t = wolfrom(sun=20, planet=30, ring1=80, planet2=29, ring2=77)
i = t.ratio("sun", "ring2", fixed=["ring1"])
print(t.name, "| i_sun,ring2 =", i, f"= {float(i):.2f}")
assert i == (1 + Fraction(80, 20)) / (1 - Fraction(29 * 80, 77 * 30))  # Ozols §2.2
pf = power_flow(t, "sun", "ring2", fixed=["ring1"], mesh_efficiency=0.98)
print(f"efficiency {pf.efficiency:.4f}, circulating power {pf.circulating_power:.3f}")

# the power through each mesh against the input power: the Wolfrom train circulates power,
# which is why its efficiency falls as its ratio rises
try:
    import matplotlib.pyplot as plt
except ImportError:
    pass
else:
    names = list(pf.relations)
    share = [abs(pf.relations[n].power) / pf.input_power for n in names]
    fig, ax = plt.subplots(figsize=(6, 3.2))
    ax.barh(names, share, color="tab:blue")
    ax.axvline(1, color="k", ls="--", lw=0.8, label="input power")
    ax.invert_yaxis()
    ax.set_xlabel("power through the mesh / input power")
    ax.legend(loc="lower right")
    ax.set_title(f"Wolfrom 20/30/80 + 29/77: i = {float(i):.1f}, efficiency {pf.efficiency:.3f}")
    fig.tight_layout()
