"""A published internal mesh against geartrain (issue 26): the ring's profile-shift sign (DIN 3960
/ ISO 21771's, as the report prints it), the single stiffness that takes it, and the root
fillet a shaper cutter leaves on the ring.

Source: a commercial tool's ISO 6336:2006 method B report of the NREL 5 MW reference gearbox's
planetary stage (KISSsoft 03/2017, published in the open repository gfsReboucas/Drivetrain as
``@NREL_5MW/stage_02.rtf``): planet z 36, x 0.5039 (ISO 53 A), ring z 93 (printed -93), x 0.1171 in
the sign of DIN 3960 / ISO 21771 (ISO 53 B), m_n 21, alpha_n 20 deg, spur, the planet's tip altered
by -1.750 mm; printed a_w 584.000, ring d_a 1906.081, d_f 2000.581, s_n* 1.6560, eps_alpha 1.618, at
F_t 285900.438 N c' 14.053 and c_gamma_alpha 20.563 N/(mm um) with the gear-body factor C_R 0.862;
the ring cut by a pinion-type cutter z0 30, x0 0, rho_a0* 0.300, its 60 deg tangent point at d
1998.168 mm with rho_F 8.78 mm and s_Fn 56.76 mm, the load at d 1928.177 mm, h_F 30.32 mm, alpha_Fen
18.63 deg, Y_F 1.20, Y_S 2.34.

The independent route for the fillet is this file's own kinematics (no library code): the
cutter's pitch circle rolls inside the ring's at the working centre distance of zero backlash
(DIN 3960: inv alpha_w = inv alpha + 2 tan alpha (x0 + x2)/(z0 + z2), z2 < 0), the centre of the
cutter's tip round (tangent to its tip circle and its involute flank) describes its path in the
ring's frame, and the fillet is that path offset by rho_a0 along the line through the
instantaneous centre (the pitch point); its radius of curvature by finite differences.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from gears import BasicRack, Gear, GearPair
from gears.cutting.cutter import ShaperCutter
from gears.rating.bending import form_factors
from gears.rating.capacity import load_diameters
from gears.rating.root import measure_root

M, Z_PLANET, Z_RING, X_PLANET, X_RING_DIN = 21.0, 36, 93, 0.5039, 0.1171


def _mesh(ring_shift: float, cutter=None) -> GearPair:
    # the planet's tip is shortened by its sun mesh: k m_n = -1.750 mm (printed)
    planet = Gear(Z_PLANET, M, profile_shift=X_PLANET, rack=BasicRack.iso53("A"), face_width=550,
                  tip_alteration=-1.75 / M)  # fmt: skip
    ring = Gear(Z_RING, M, profile_shift=ring_shift, internal=True, rack=BasicRack.iso53("B"),
                face_width=550, cutter=cutter)  # fmt: skip
    return GearPair(planet, ring)


def test_the_ring_shift_follows_din_3960():
    # geartrain's sign is DIN 3960 / ISO 21771's (the report's): a positive shift thickens a
    # ring's teeth and shrinks its tip circle, so the report's ring is entered as printed
    pair = _mesh(X_RING_DIN)
    ring = pair.g2
    # x is printed to 4 decimals: +-5e-5 x 2 m_n = +-2.1e-3 mm on the diameters
    assert pair.center_distance == pytest.approx(584.000, abs=2.5e-3)
    assert ring.tip_diameter == pytest.approx(1906.081, abs=2.5e-3)
    assert ring.root_diameter == pytest.approx(2000.581, abs=2.5e-3)
    assert ring.tooth_thickness(ring.reference_diameter) / M == pytest.approx(1.6560, abs=5e-5)
    assert pair.contact_ratio == pytest.approx(1.618, abs=5e-4)
    # entered in KHK's sign (geartrain's up to 0.2.0), the ring is another gear: thinner teeth,
    # a larger tip (KHK: d_a = d - 2 m (1 - x) with x = 0.1171)
    other = _mesh(-X_RING_DIN)
    assert other.g2.tip_diameter == pytest.approx(1915.918, abs=5e-4)
    assert other.center_distance == pytest.approx(589.883, abs=5e-4)


def test_the_single_stiffness_takes_the_ring_shift_in_din_3960_s_sign():
    # ISO 6336-1 §9.3 method B: q' has the term C6 x2 (C6 = -0.00193), x2 in the standard's
    # (DIN 3960 / ISO 21771) sign. The report prints c' = 14.053 N/(mm um) for this mesh with its
    # gear-body factor C_R = 0.862 (b_s/b = 0.25); geartrain takes solid gears (C_R = 1), so
    # c' C_R must agree to C_R's print rounding (+-0.06 %). At the report's F_t = 285900.438 N
    # (w = 519.82 N/mm > 100: no light-load reduction). The other sign gives 13.917 (-1.0 %).
    torque = 285900.438 * Z_PLANET * M / 2000
    v = _mesh(X_RING_DIN).rating(torque, 123.4).values
    assert v.c_prime * 0.862 == pytest.approx(14.053, rel=1e-3)
    assert v.c_gamma_alpha * 0.862 == pytest.approx(20.563, rel=1e-3)  # c' (0.75 eps + 0.25)


def _independent_fillet(z0=30, x0=0.0, ha0=1.25, rho0=0.3, x2=X_RING_DIN, alpha=20.0):
    """(tangent-point diameter, s_Fn, rho_F) at the 60 deg tangent of the ring's fillet."""
    al = math.radians(alpha)

    def inv(a):
        return math.tan(a) - a

    r0 = z0 * M / 2
    rb0 = r0 * math.cos(al)
    ia = inv(al) + 2 * math.tan(al) * (x0 + x2) / (z0 - Z_RING)
    aw = brentq(lambda a: inv(a) - ia, 1e-6, 1.2)
    a0 = (Z_RING - z0) * M / 2 * math.cos(al) / math.cos(aw)
    rw2 = a0 * z0 / (Z_RING - z0) + a0  # the ring's working pitch radius
    rho = rho0 * M
    rq = r0 + (ha0 + x0) * M - rho  # radius of the tip round's centre
    beta0 = math.pi / (2 * z0) + inv(al)  # base point of the right flank, from the centre line

    def centre(eps):  # rho inside the flank point of roll angle eps, along its normal
        th = beta0 - eps
        base = rb0 * np.array([math.sin(th), math.cos(th)])
        return base + (rb0 * eps - rho) * np.array([math.cos(th), -math.sin(th)])

    eps = brentq(lambda e: np.linalg.norm(centre(e)) - rq, 0.01, 1.5)
    gq = math.atan2(*centre(eps))  # the round centre's angle from the tooth centre line

    def point(t):  # the fillet point cut when the cutter's centre is at angle t
        oc = a0 * np.array([math.sin(t), math.cos(t)])
        g = -t * (Z_RING - z0) / z0 + gq  # the cutter turns back as its centre goes round
        c = oc + rq * np.array([math.sin(g), math.cos(g)])
        d = c - rw2 * np.array([math.sin(t), math.cos(t)])
        return c + rho * d / np.linalg.norm(d)

    phi = math.pi / Z_RING  # the centre line of the ring tooth beside this fillet
    axis = np.array([math.sin(phi), math.cos(phi)])

    def angle(t, h=1e-7):
        d = point(t + h) - point(t - h)
        return math.degrees(math.acos(abs(d @ axis) / np.linalg.norm(d)))

    t60 = brentq(lambda t: angle(t) - 60.0, -0.02, 0.0)
    h = 1e-5
    p, pm, pp = point(t60), point(t60 - h), point(t60 + h)
    d1, d2 = (pp - pm) / (2 * h), (pp - 2 * p + pm) / h**2
    radius = np.linalg.norm(d1) ** 3 / abs(d1[0] * d2[1] - d1[1] * d2[0])
    chord = 2 * abs(p[0] * axis[1] - p[1] * axis[0])
    return 2 * np.linalg.norm(p), chord, radius


def test_the_shaper_cut_ring_fillet_is_the_cutter_s_envelope():
    pair = _mesh(X_RING_DIN, ShaperCutter(30, 0.0))
    ring = pair.mounted[1]
    form = measure_root(ring, load_diameters(pair)[1])
    diameter, chord, radius = _independent_fillet()
    x, y = form.tangent_point
    # the exact envelope (the default route for a ring) against the independent kinematics
    assert 2 * math.hypot(x, y) == pytest.approx(diameter, abs=1e-3)
    assert form.s_Fn == pytest.approx(chord, abs=1e-3)
    assert form.rho_F == pytest.approx(radius, rel=1e-4)
    # the report's tangent point agrees within 0.1 mm (d 1998.168) and its chord within 1.3 %
    # (56.76); its rho_F 8.78 mm is not the fillet this cutter cuts (7.78 mm: 11 % smaller),
    # whatever ISO 6336-3 approximation the report applies ("roF according to ISO 6336-3")
    assert diameter == pytest.approx(1998.168, abs=0.15)
    assert radius == pytest.approx(7.78, abs=0.01) and radius < 8.78 * 0.9
    # the rating's default route for a ring measures this fillet, and the load where the
    # report puts it
    r = pair.rating(3000, 100)
    v = r.values
    assert v.rho_F2 == pytest.approx(form.rho_F, rel=1e-9)
    assert load_diameters(pair)[1] == pytest.approx(1928.177, abs=1e-3)
    assert v.h_Fe2 == pytest.approx(30.32, rel=2e-3) and v.alpha_Fen2 == pytest.approx(
        18.63, abs=0.01
    )
    # the report's own lengths through our Y_F, Y_S give its printed 1.20, 2.34: the Y's differ
    # by its fillet (rho_F, and s_Fn 1.3 %) alone
    yf, ys, _ = form_factors(56.76, 8.78, 30.32, math.radians(18.63), M, 20.0)
    assert (float(yf), float(ys)) == pytest.approx((1.20, 2.34), abs=5e-3)
