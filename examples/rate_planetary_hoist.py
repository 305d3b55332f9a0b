"""Load capacity of the electric hoist
===================================

Rate the electric hoist of Ozols example 7-7 (the closed differential, Fig. 7-13) by ISO 6336.

Design task: the hoist's motor gives 5.5 kW at n1 = 880 rpm (T1 = 59.7 N m); the drum 4 turns
at 20 rpm (i_14 = 2767/63, examples/train_closed_differential.py). Is every mesh safe against
pitting (S_H >= 1) and tooth-root breakage (S_F >= 1.4) for 10 000 h with K_A = 1.25 (electric
motor, a hoist's moderate shocks), case-carburized gears of ISO 1328 grade 6?

The book gives tooth counts only. Real gears make it: the differential 1-2 / 2'-3 needs modules
in the ratio 4:3 to be coaxial (a = 38 m_12 = 28.5 m_23, so m 3 and 4, a = 114 mm); the closing
chain 3'-5-4 is coaxial with one module (a = 24 m, m 4, a = 96 mm). Every mesh is rated from
the train's statics (trains.rating on trains.power_flow): the ring gears 3 and 4 from the root
their shaper cutter leaves, the idler 5 with its reversed bending (Y_M).
"""

import math

from gears import Gear
from trains import Train, rating

POWER, N1 = 5500.0, 880.0  # W, rpm
T1 = POWER / (N1 * 2 * math.pi / 60)  # N m


def hoist(closing_width: float) -> Train:
    def g(z, m, b, internal=False):
        return Gear(z, m, face_width=b, internal=internal)

    t = Train()
    t.mesh("1", "2", gears=(g(24, 3, 30), g(52, 3, 30)), carrier="4")
    t.mesh("2", "3", gears=(g(21, 4, 40), g(78, 4, 40, True)), carrier="4")
    t.mesh("3", "5", gears=(g(18, 4, closing_width), g(30, 4, closing_width)))
    t.mesh("5", "4", gears=(g(30, 4, closing_width), g(78, 4, closing_width, True)))
    return t


def rate(closing_width: float) -> dict:
    ratings = rating(hoist(closing_width), "1", "4", torque=T1, speed=N1, life=10000,
                     application_factor=1.25, quality=6)  # fmt: skip
    print(f"closing chain b = {closing_width:g} mm, T1 = {T1:.1f} N m at {N1:g} rpm:")
    print(f"  {'mesh':6s} {'T1 [N m]':>9s} {'n1 [rpm]':>9s}  {'S_H1':>6s} {'S_H2':>6s}"
          f" {'S_F1':>6s} {'S_F2':>6s}")  # fmt: skip
    for name, r in ratings.items():
        sh, sf = r.safety_pitting, r.safety_bending
        print(f"  {name:6s} {r.settings['torque']:9.1f} {r.settings['speed']:9.1f}  "
              f"{sh[0]:6.3f} {sh[1]:6.3f} {sf[0]:6.3f} {sf[1]:6.3f}")  # fmt: skip
    return ratings


first = rate(40.0)
weakest = min(first, key=lambda k: min(first[k].safety_pitting))
print(f"weakest mesh: {weakest} (S_H = {min(first[weakest].safety_pitting):.3f})")
failed = [n for n, r in first.items() if not r.check(1.0, 1.4).ok]
print("failing checks:", failed or "none")
assert weakest == "3-5" and failed == ["3-5"]  # the closing pinion 3' carries 480 N m

# the closing chain 50 % wider: sigma_H ~ 1/sqrt(b)
second = rate(60.0)
assert all(r.check(1.0, 1.4).ok for r in second.values())
print("with b = 60 mm every mesh passes")

# the smaller safety of every mesh, closing chain 40 and 60 mm wide, against the required S_H
try:
    import matplotlib.pyplot as plt
except ImportError:
    pass
else:
    names = list(first)
    fig, ax = plt.subplots(figsize=(6, 3.4))
    for k, (ratings, b) in enumerate(((first, 40), (second, 60))):
        ax.bar([i + 0.38 * k for i in range(len(names))],
               [min(ratings[n].safety_pitting) for n in names], width=0.38,
               label=f"closing chain b = {b} mm")  # fmt: skip
    ax.axhline(1.0, color="k", ls="--", lw=0.8, label="required S_H = 1")
    ax.set_xticks([i + 0.19 for i in range(len(names))], names)
    ax.set_ylabel("smaller pitting safety S_H")
    ax.legend(fontsize=8, loc="lower right")
    ax.set_title("hoist: 5.5 kW at 880 rpm, ISO 6336 method B")
    fig.tight_layout()
