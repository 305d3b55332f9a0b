"""Design to a load: the smallest pair, the lightest gearbox
=========================================================

Design to a load: the smallest pair for a housing, the lightest gearbox.

1. A housing holds two shafts 100 mm apart; the pair between them must give 3.2:1 (+- 2 %) and
   carry 60 N m on the pinion at 1500 rpm for 20 000 h with S_H >= 1.1 and S_F >= 1.5
   (ISO 6336 method B, case-carburized steel). Which module, tooth counts, shifts and face
   width use the least material? Every candidate is checked as ``GearPair.check()`` does and
   rated as ``GearPair.rating()`` does, vectorised; each is sized to the smallest face width
   of the set that carries the load.
2. The lightest two-stage planetary gearbox for 1:20 at 50 N m (1500 rpm in): each stage rated
   at its own torque and speed, its module the smallest of ISO 54 that carries it.

Run: ``python examples/design_for_load.py``.
"""

import math

from gears import search
from trains import synthesize_gearbox

# 1. the smallest pair for the housing
pairs = search.pairs(
    ratio=3.2, ratio_tolerance=0.02, center_distance=100, module=[1.5, 2, 2.5, 3, 4],
    teeth=(14, 120), shifts=(-0.5, 1.0, 0.05), torque=60, speed=1500, life=20000,
    face_width=(8, 40, 2), min_safety={"pitting": 1.1, "bending": 1.5}, objective="volume",
    top=3, progress=False,
)  # fmt: skip
print(pairs)
best = pairs.pair(0)
rating = pairs.rating(0)  # the first row rated on its own: the same safeties
print(f"\nbest: {best.g1.teeth}/{best.g2.teeth}, m = {best.g1.module:g} mm, "
      f"x = {best.g1.profile_shift:.3f}/{best.g2.profile_shift:.3f}, "
      f"b = {pairs['face_width'][0]:g} mm")  # fmt: skip
print(repr(rating))
assert min(rating.safety_pitting) >= 1.1 and min(rating.safety_bending) >= 1.5
assert math.isclose(rating.safety_pitting[0], pairs["S_H1"][0], rel_tol=1e-9)  # the same

# the smallest pairs' safeties against their volume (every candidate of the search that
# carries the load, the three smallest marked)
try:
    import matplotlib.pyplot as plt
except ImportError:
    pass
else:
    every = search.pairs(
        ratio=3.2, ratio_tolerance=0.02, center_distance=100, module=[1.5, 2, 2.5, 3, 4],
        teeth=(14, 120), shifts=(-0.5, 1.0, 0.05), torque=60, speed=1500, life=20000,
        face_width=(8, 40, 2), min_safety={"pitting": 1.1, "bending": 1.5}, objective="volume",
        top=None, progress=False,
    )  # fmt: skip
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.scatter(every["volume"] / 1e3, every["S_H"], s=4, color="0.7",
               label=f"{every.feasible} pairs that carry the load")  # fmt: skip
    ax.plot(pairs["volume"] / 1e3, pairs["S_H"], "o", color="tab:red", label="the three smallest")
    ax.axhline(1.1, color="tab:blue", ls="--", lw=0.8, label="required S_H = 1.1")
    ax.set_xlabel("volume of both gears, cm^3 (pitch cylinders)")
    ax.set_ylabel("smaller pitting safety S_H")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("3.2:1 pairs for 60 N m at 1500 rpm, a = 100 mm")
    fig.tight_layout()

# 2. the lightest 1:20 gearbox in two stages
boxes = synthesize_gearbox(
    20, stages=2, torque=50, speed=1500, life=20000, face_width=range(10, 45, 5),
    objective="mass", top=3, progress=False,
)  # fmt: skip
print()
print(boxes.table())
box = boxes[0]
for stage, torque, speed, b in zip(box.stages, box.torques, box.speeds, box.face_widths,
                                   strict=True):  # fmt: skip
    meshes = stage.stage.rating(torque, speed, face_width=b, root="standard")
    worst = min(min(r.safety_pitting) for r in meshes.values())
    print(f"stage {stage.teeth} m = {stage.module:g} b = {b:g}: {torque:.4g} N m at "
          f"{speed:.4g} rpm, smallest S_H {worst:.3f}")  # fmt: skip
    assert worst >= 1.0
