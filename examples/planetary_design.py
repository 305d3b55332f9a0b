"""Planetary stage design from a target ratio
==========================================

Design a planetary stage from a target ratio to a validated, coaxial, assemblable design.

Task: a sun-input, carrier-output reducer with the ring fixed, ratio 6.2 within 1 %, three
planets, module 2 mm. Steps: search the tooth numbers (trains.synthesize), take the best set,
make it coaxial with profile shifts if it is off by a tooth, check every condition, and print the
assembly data (planet angles and the rotation of every gear at assembly).
"""

from fractions import Fraction

from trains import synthesize

TARGET = Fraction(62, 10)
MODULE = 2.0

candidates = synthesize(TARGET, n_planets=3, tolerance=0.01, module=MODULE, allow_shift=True,
                        z_max=150, limit=5)  # fmt: skip
print(candidates.table())
best = candidates[0]
print(f"\nchosen: {best}")

stage = best.stage  # a Planetary; shifted by Planetary.coaxial when the set is off by a tooth
for name, pair in stage.meshes.items():
    x1, x2 = pair.g1.profile_shift, pair.g2.profile_shift
    print(f"{name}: x = {x1:+.4f} / {x2:+.4f}, a_w = {pair.center_distance:.4f} mm")
report = stage.check()
for name in ("coaxiality", "assembly", "neighbour"):
    print(report[name])
    assert report[name].ok, name
ratio = stage.ratio()
print(f"ratio {ratio} = {float(ratio):.5f} (target {float(TARGET)}, error "
      f"{abs(float(ratio / TARGET) - 1):.2%})")  # fmt: skip
assert abs(float(ratio / TARGET) - 1) <= 0.01
placement = stage.placement()
assert placement.residual < 1e-9  # every planet meshes in phase
print("planet centre angles (deg):", [round(a, 3) for a in placement.planet_angles])
print("planet rotations at assembly (deg):", [round(a, 3) for a in placement.planet_rotations])
print(f"ring rotation at assembly: {placement.ring_rotation:.3f} deg; phasing {stage.phasing}")
print(f"planet bearing speed per input rpm: {float(stage.planet_speed()['planet']):+.4f}")
print(f"efficiency sun -> carrier: {stage.efficiency():.4f}")
# the ring's tip reaching below the planet's form circle (fillet contact) is reported, not
# hidden: a designer shortens the ring tip or chooses a tool with a deeper straight flank
print("findings that need attention:", report.failed() or "none")

# the chosen stage drawn with its real teeth, planets phased as assembled
try:
    from gears.figures.plot import outlines_figure
except ImportError:  # matplotlib missing
    pass
else:
    parts = stage.outlines(tolerance=0.02)
    fig = outlines_figure(*parts.values())
    fig.axes[0].set_title(f"the chosen stage: ratio {ratio}, three planets, m = {MODULE:g} mm")
