"""Sizing a car differential's bevel gears by ISO 10300
=====================================================

The car differential of Ozols (Fig. 7-11) on real straight bevel teeth (side gears of 16 teeth,
pinions of 10, Gleason proportions, the face width R_e / 3.5) rated by ISO 10300 method B1
through the virtual cylindrical gears of each mesh. The design task: the smallest module whose
teeth carry two duties of the case, with two and with four pinions:

* bending under the peak torque, 800 N m on the case for 50 hours of cornering (first gear at
  full throttle), S_F >= 1.4;
* pitting under the usual cornering torque, 200 N m for 500 hours, S_H >= 1.0.

The pinions spin in the case only while the wheels turn at different speeds (here 90 and 110
rpm, a corner); the case torque splits equally between the side gears and among the pinions,
and each pinion, loaded on both flanks, is an idler (Y_M = 0.7 of ISO 6336-5).

Run: ``python examples/rate_bevel_differential.py``.
"""

import matplotlib.pyplot as plt

from trains import Differential

PEAK, CORNERING = (800.0, 50.0), (200.0, 500.0)  # N m on the case, hours
MODULES = (3.0, 3.5, 4.0, 4.5, 5.0, 5.5)
chosen, curves = {}, {}
print(f"{'pinions':>7s} {'m':>4s} {'b':>5s} {'S_F peak':>15s} {'S_H cornering':>15s}  holds")
for n_pinions in (2, 4):
    curves[n_pinions] = []
    for module in MODULES:
        d = Differential(side=16, pinion=10, n_pinions=n_pinions, module=module, gleason=True)
        peak = d.rating(PEAK[0], left=90, right=110, life=PEAK[1])["pinion-left"]
        usual = d.rating(CORNERING[0], left=90, right=110, life=CORNERING[1])["pinion-left"]
        s_f, s_h = min(peak.safety_bending), min(usual.safety_pitting)
        holds = s_f >= 1.4 and s_h >= 1.0
        curves[n_pinions].append((s_f, s_h))
        print(f"{n_pinions:7d} {module:4g} {d.face_width:5.1f} {s_f:15.3f} {s_h:15.3f}  "
              f"{'yes' if holds else 'no'}")  # fmt: skip
        if holds and n_pinions not in chosen:
            chosen[n_pinions] = (d, peak)
print("smallest modules:", {n: d.module for n, (d, _) in chosen.items()})

# the two-pinion design, every factor of its rating under the peak torque
print()
print(chosen[2][1])

# the safeties over the module: where each duty's line crosses its minimum
fig, ax = plt.subplots(figsize=(6.4, 4.0), layout="constrained")
for n_pinions, style in ((2, "-"), (4, "--")):
    s_f, s_h = zip(*curves[n_pinions], strict=True)
    ax.plot(MODULES, s_f, "o" + style, color="C0", label=f"S_F at the peak, {n_pinions} pinions")
    ax.plot(MODULES, s_h, "s" + style, color="C1",
            label=f"S_H cornering, {n_pinions} pinions")  # fmt: skip
ax.axhline(1.4, color="C0", lw=0.8, ls=":")
ax.axhline(1.0, color="C1", lw=0.8, ls=":")
ax.set_xlabel("module m, mm")
ax.set_ylabel("safety (ISO 10300 method B1)")
ax.set_title("Car differential, side gears 16 / pinions 10")
ax.legend(fontsize="small")
plt.show()
