"""Worm hoist that holds its load
===============================

A hoist drum driven by an electric motor through a single-start worm pair and a spur stage
(the arrangement of Ozols' hoist, Ex. 13-1): lifting, its efficiency is that of the worm with
the worm driving (Ozols (14.15)) times the spur stage's (14.10); lowering, the load tries to
drive the worm through its wheel, and the worm's lead angle below the friction angle makes it
self-locking (14.18): the hoist holds its load without a brake.

Design task: pick the worm (z1 1, q 16, m_x 4) and the wheel (z2 40), check the pair, and read
the efficiency both ways from the train's power flow; then compare a two-start worm of q 10,
which lifts better but lets the load run back. For the worm's bearings, read the forces of the
worm mesh under a drum load of 400 N m from the train's loads: the worm's axial force (the
wheel's tangential force, the largest force of the drive) lifting and lowering, the friction
against the sliding of whichever member drives.
"""

import math

from gears import Gear, WormPair
from trains import Train, loads, power_flow

MU = 0.06  # friction coefficient of bronze on hardened steel, well lubricated
SPUR = {"pinion-drum": 0.98}  # the spur stage's efficiency (Ozols (14.25) gives about as much)
DRUM = 400.0  # N m: the load's torque on the drum


def hoist(worm: WormPair) -> Train:
    t = Train()
    t.mesh("worm", "wheel", pair=worm)  # the motor turns the worm
    t.couple("wheel", "pinion")  # the wheel and the spur pinion share a shaft
    t.mesh("pinion", "drum", gears=(Gear(17, 3), Gear(68, 3)))
    return t


for worm in (
    WormPair(1, 40, 4.0, diameter_quotient=16),
    WormPair(2, 40, 4.0, diameter_quotient=10),
):
    t = hoist(worm)
    phi = worm.friction_angle(MU)
    head = f"worm z1 {worm.starts}, q {worm.diameter_quotient:g}"
    print(f"{head}: lead angle {worm.lead_angle:.3f} deg, friction angle {phi:.3f} deg")
    print(f"  ratio motor/drum {abs(float(t.ratio('worm', 'drum'))):g}, checks "
          f"{'pass' if worm.check().ok else worm.check().failed()}")  # fmt: skip
    up = power_flow(t, "worm", "drum", friction=MU, mesh_efficiency=SPUR)
    down = power_flow(t, "drum", "worm", friction=MU, mesh_efficiency=SPUR)
    print(f"  lifting: efficiency {up.efficiency:.4f}")
    verdict = "self-locking: it holds its load" if down.self_locking else "it runs back"
    print(f"  lowering (the load drives): efficiency {down.efficiency:.4f}, {verdict}")
    # the power flow agrees with Ozols (14.15) and (14.10) written out
    g, phi = math.radians(worm.lead_angle), math.radians(worm.friction_angle(MU))
    assert abs(up.efficiency - math.tan(g) / math.tan(g + phi) * 0.98) < 1e-9
    assert down.self_locking == (worm.lead_angle <= worm.friction_angle(MU))
    # the worm mesh's forces under the drum load: lifting, the motor's torque that carries it;
    # lowering, the drum drives (the wheel drives the worm)
    motor = DRUM / (abs(float(t.ratio("worm", "drum"))) * up.efficiency)
    lift = loads(t, "worm", "drum", torque=motor, friction=MU, mesh_efficiency=SPUR)
    lower = loads(t, "drum", "worm", torque=DRUM, friction=MU, mesh_efficiency=SPUR)
    for what, ld in (("lifting", lift), ("lowering", lower)):
        m, w = ld.meshes["worm-wheel"], ld.members["worm"]
        pushes = w.torque * ld.flow.speeds["worm"] > 0  # the motor supplies power
        print(f"  {what}: worm thrust {m.axial[0]:.0f} N, radial {m.radial[0]:.0f} N, worm "
              f"tangential {m.tangential[0]:.1f} N ({m.driver} drives); the motor "
              f"{'drives' if pushes else 'brakes'} with {abs(w.torque):.3f} N m")  # fmt: skip
    # DIN 3996 by hand: the wheel's torque (the spur stage's) over d_2 / 2 is the worm's thrust
    wheel = DRUM * 17 / 68 * 0.98  # lowering: the drum drives the spur stage
    thrust = 2000 * wheel / worm.wheel_diameter
    assert abs(lower.meshes["worm-wheel"].axial[0] - thrust) < 1e-9 * thrust

# the worm's efficiency both ways over its lead angle (Ozols (14.15), (14.18)) at this friction:
# lowering stays at or below zero (self-locking) until the lead angle passes the friction angle
try:
    import matplotlib.pyplot as plt
except ImportError:
    pass
else:
    from gears.worm import worm_efficiency

    phi = WormPair(1, 40, 4.0, diameter_quotient=16).friction_angle(MU)
    gammas = [0.5 + 0.25 * k for k in range(119)]  # lead angle, deg
    fig, ax = plt.subplots(figsize=(6, 3.6))
    for driving, label in (("worm", "lifting (worm drives)"), ("wheel", "lowering (load drives)")):
        eta = [max(float(worm_efficiency(g, phi, driving)), 0.0) for g in gammas]
        ax.plot(gammas, eta, label=label)
    for worm in (
        WormPair(1, 40, 4.0, diameter_quotient=16),
        WormPair(2, 40, 4.0, diameter_quotient=10),
    ):
        ax.axvline(worm.lead_angle, color="0.5", ls=":", lw=0.8)
        ax.annotate(f"z1 {worm.starts}, q {worm.diameter_quotient:g}", (worm.lead_angle, 0.05),
                    rotation=90, fontsize=8, ha="right")  # fmt: skip
    ax.axvline(phi, color="k", lw=0.8, label=f"friction angle {phi:.2f} deg")
    ax.set_xlabel("lead angle gamma [deg]")
    ax.set_ylabel("tooth efficiency")
    ax.set_ylim(0, 1)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
