"""Kinematics: every gear-train worked example of the seed digests, with the printed answers.

Sources: Ozols = seed-001-ozols.md (§3 worked examples, §5 errata); Joldasbekov =
seed-000-joldasbekov.md (§3); lectures = seed-004-lectures.md (§3.3, §4.2); standards =
standards.md §4.
"""

from fractions import Fraction as F

import numpy as np
import pytest

from trains import (
    Train,
    TrainError,
    biplanetary,
    ferguson,
    khv,
    point_path,
    reduced_inertia,
    simple_planetary,
    stepped_planetary,
    strain_wave,
)


def test_ozols_7_1_three_stage_coaxial_reducer():
    # Ozols Ex 7-1 (Fig 7-5), printed formula OCR-damaged; digest §3/§5 gives the consistent
    # i15 = (-1)^3 z3 z4 z5 / (z1 z3' z4'): 1 -> idler 2 -> internal 3=3' -> 4=4' -> 5.
    # Tooth counts chosen to satisfy the figure's coaxiality r1 + 2 r2 = r3, r3' + r4 = r4' + r5.
    z1, z2, z3, z3p, z4, z4p, z5 = 20, 20, 60, 18, 54, 24, 48
    t = Train()
    t.mesh("1", "2", teeth=(z1, z2))
    t.mesh("2", "3", teeth=(z2, z3), internal=True)
    t.mesh("3", "4", teeth=(z3p, z4))
    t.mesh("4", "5", teeth=(z4p, z5))
    i15 = t.ratio("1", "5")
    assert i15 == -F(z3 * z4 * z5, z1 * z3p * z4p)
    assert i15 < 0  # printed: shaft 5 turns opposite to shaft 1


def test_ozols_7_2_equal_gear_rolls_around_fixed_gear():
    # Ozols Ex 7-2: i_1H = 1 - (-1) z2/z1 = 2 (two turns per carrier turn).
    t = Train()
    t.mesh("1", "2", teeth=(30, 30), carrier="H")
    assert t.ratio("1", "H", fixed=["2"]) == 2


def test_ozols_7_3_ferguson_satellite_translates():
    # Ozols Ex 7-3: z1 = z3 gives i_1H = 1 - (+1) z3/z1 = 0: the satellite does not rotate.
    t = ferguson(sun=40, idler=17, satellites=(40,))
    assert t.solve(carrier=1, sun=0)["satellite1"] == 0
    assert t.ratio("satellite1", "carrier", fixed=["sun"]) == 0
    with pytest.raises(TrainError, match="stands still"):
        t.ratio("carrier", "satellite1", fixed=["sun"])


def test_ozols_7_4_david_mechanism_exact():
    # Ozols Ex 7-4: z = 100, 101, 100, 99; i_1H = 1 - 9999/10000 = 1/10000 exactly.
    t = stepped_planetary(100, 101, 100, 99, meshes=("external", "external"))
    assert t.ratio("1", "H", fixed=["3"]) == F(1, 10000)
    assert t.ratio("H", "1", fixed=["3"]) == 10000
    # float speeds through the exact map lose nothing either
    assert t.solve({"H": 1.0, "3": 0})["1"] == 1e-4


def test_ozols_7_5_thread_tapping_differential():
    # Ozols Ex 7-5 (Fig 7-8): z1 = 100, z2 = 50, z2' = 100, z3 = 50, carrier n4 = 100 rpm.
    t = stepped_planetary(100, 50, 100, 50, meshes=("external", "external"))
    work = t.solve({"H": 100, "3": 0})
    assert work["1"] == 75  # printed n1 = 75 rpm
    assert work.relative("2", "H") == 50  # printed n24 = 50 rpm
    back = t.solve({"H": 100, "1": 0})
    assert back["3"] == -300  # printed n3 = -300 rpm
    assert back.relative("2", "H") == 200  # printed n24 = 200 rpm


def test_ozols_7_6_summator_angles():
    # Ozols Ex 7-6: phi1 = +60 deg, phi3 = -60 deg -> phi4 = +100 deg (via (7.8)).
    t = stepped_planetary(100, 50, 100, 50, meshes=("external", "external"))
    assert t.solve({"1": 60, "3": -60})["H"] == 100
    # the same through Motion.integrate over a time series of constant speeds
    time = np.linspace(0.0, 2.0, 11)
    ang = t.solve({"1": np.full(11, 30.0), "3": np.full(11, -30.0)}).integrate(time)
    assert ang["H"][-1] == pytest.approx(100.0, rel=1e-14)


def test_ozols_7_7_electric_hoist_closed_differential():
    # Ozols Ex 7-7 (Fig 7-13): book i14 = 44, n4 = +20 rpm (rounded); exact 2767/63, 20.036.
    t = Train()
    t.mesh("1", "2", teeth=(24, 52), carrier="4")
    t.mesh("2", "3", teeth=(21, 78), carrier="4", internal=True)  # sign: i13^(4) = -169/21
    t.mesh("3", "5", teeth=(18, 30))  # closing chain 3' -> idler 5 -> 4: i34 = -z4/z3'
    t.mesh("5", "4", teeth=(30, 78), internal=True)
    assert t.ratio("1", "4") == F(2767, 63)
    assert float(t.ratio("1", "4")) == pytest.approx(44, rel=2e-3)
    m = t.solve({"1": 880})
    assert float(m["4"]) == pytest.approx(20, rel=2e-3)
    assert float(m["4"]) == pytest.approx(20.036, abs=5e-4)  # digest recomputation
    assert float(m["3"]) == pytest.approx(-86.82, abs=5e-3)
    # digest: i14 = 1 + i13^(4) (i34 - 1)
    assert t.ratio("1", "4") == 1 + F(-169, 21) * (F(-13, 3) - 1)


def test_ozols_7_8_multiplier_with_belt():
    # Ozols Ex 7-8 (Fig 7-14): n1 = 90; z1 = z2' = 25, z2 = z3 = 20 (3 fixed), z4 = 100,
    # z5 = 20, d5 = 600, d6 = 150. Book: n6 = 5000 rpm, same direction as 1.
    # The printed i46 = (-1)^2 z5 d6 / (z4 d5) needs an even count of external meshes: gear 4
    # (on the carrier) is modelled as internal, the V-belt as a + link.
    t = Train()
    t.mesh("1", "2", teeth=(25, 20), carrier="4")
    t.mesh("2", "3", teeth=(25, 20), carrier="4")
    t.mesh("4", "5", teeth=(100, 20), internal=True)
    t.link("5", "6", ratio=F(150, 600))  # belt: w5 d5 = w6 d6
    assert t.ratio("1", "4", fixed=["3"]) == F(9, 25)
    assert t.ratio("1", "6", fixed=["3"]) == F(9, 500)
    assert t.solve({"1": 90, "3": 0})["6"] == 5000


@pytest.mark.parametrize(
    "z", [(20, 40, 18, 24, 30, 20, 84, 24, 60, 30), (17, 51, 19, 23, 29, 31, 96, 22, 15, 44)]
)
def test_ozols_7_9_combined_train(z):
    # Ozols Ex 7-9 (Fig 7-15), symbolic; digest derived test:
    # i18 = (-z2/z1) / (1 - z5' z4' z3 / (z6 z5 z4)) * (z8/z6'). Shaft 2 carries the carrier,
    # gear 3 is the fixed sun (here a ring); the planetary is entered from the carrier side.
    z1, z2, z4, z4p, z5, z5p, z3, z6, z6p, z8 = z
    t = Train()
    t.mesh("1", "2", teeth=(z1, z2))
    t.mesh("6", "5", teeth=(z6, z5p), carrier="2")
    t.mesh("5", "4", teeth=(z5, z4p), carrier="2")
    t.mesh("4", "3", teeth=(z4, z3), carrier="2", internal=True)
    t.mesh("6", "7", teeth=(z6p, 23))  # idler 7: (-1)^2
    t.mesh("7", "8", teeth=(23, z8))
    expected = F(-z2, z1) / (1 - F(z5p * z4p * z3, z6 * z5 * z4)) * F(z8, z6p)
    assert t.ratio("1", "8", fixed=["3"]) == expected


def test_ozols_7_10_variable_centre_distance_coupling():
    # Ozols Ex 7-10 (Fig 7-17): equal gears 1, 2 (R), gear 3 (r) on links at +phi and -phi:
    # w2 = w1 - 2 phidot (1 + r/R). Digest derived numbers: R = 3, r = 2, w1 = 10,
    # phidot = 0.3, phi = 0.7 -> w2 = 9.0, also = w1 + xdot/(R sin phi).
    t = Train()
    t.mesh("1", "3", teeth=(30, 20), carrier="L1")
    t.mesh("3", "2", teeth=(20, 30), carrier="L2")
    assert t.mobility == 3
    m = t.solve({"1": 10, "L1": F(3, 10), "L2": F(-3, 10)})
    assert m["2"] == 9
    phi, R, r = 0.7, 3.0, 2.0
    xdot = -2 * (r + R) * 0.3 * np.sin(phi)
    assert float(m["2"]) == pytest.approx(10 + xdot / (R * np.sin(phi)), rel=1e-14)


def _grandi_rose_train(z=20):
    # Ozols Ex 7-11 (Fig 7-18): z1 = z2 = z3' = z, z0 = z3 = 2z. Rod 1 (with gear 1) and gear 0
    # turn about O; on rod 1 an intermediate gear 5 and gear 2 (with rod 2): i20^(1) = +z0/z2.
    # Shaft 3 (gears 3, 3') closes the loop: 3 meshes 0, 3' meshes 1 through idler 4.
    t = Train()
    t.mesh("0", "5", teeth=(2 * z, 25), carrier="1")
    t.mesh("5", "2", teeth=(25, z), carrier="1")
    t.mesh("3", "0", teeth=(2 * z, 2 * z))
    t.mesh("3", "4", teeth=(z, 31))
    t.mesh("4", "1", teeth=(31, z))
    return t


def test_ozols_7_11_grandi_rose_ratio_and_path():
    t = _grandi_rose_train()
    m = t.solve({"3": -1})  # rod 1 turns at -1 (alpha = 90 deg - k t with k = 1)
    assert m["1"] == -1
    assert m.ratio("0", "1") == -1  # printed i01 = -1
    assert m.relative("2", "1") / m["1"] == -4  # printed i = delta_dot / alpha_dot = -4
    time = np.linspace(0.0, np.pi, 2001)
    ang = t.solve({"3": np.full_like(time, -1.0)}).integrate(
        time, initial={"1": np.pi / 2, "2": np.pi / 2}
    )
    # B = l [e(alpha) - e(alpha + delta)], l = 1: rod 2 starts pointing back to O
    x, y = point_path(ang, [("1", 1.0), ("2", 1.0, np.pi)])
    assert abs(x[0]) < 1e-15 and abs(y[0]) < 1e-15  # B starts at O
    lhs, rhs = (x**2 + y**2) ** 3, 16 * x**2 * y**2  # printed: (x^2 + y^2)^3 = 16 x^2 y^2
    assert np.max(np.abs(lhs - rhs) / np.maximum(lhs, 1.0)) < 1e-12  # angles summed 2000 times
    assert x[10] > 0 and y[10] > 0  # printed: B first moves into the first quadrant


def test_ozols_13_1_reduced_inertia_with_corrected_z3():
    # Ozols Ex 13-1: book w3/w1 = 0.0045, I_r = 0.7123. The printed z3 = 76 gives 0.0042674,
    # inconsistent with 0.0045; z3 = 72 (digest §5, probable OCR 76 <- 72) gives 1/222 and
    # I_r = 0.71244 (digest recomputation; the book's rounded 0.7123 is 1.4e-4 off).
    def hoist(z3):
        t = Train()
        t.mesh("worm", "wheel", teeth=(1, 37))
        t.mesh("wheel", "drum", teeth=(12, z3))
        m = t.solve(worm=1)
        w3 = abs(m["drum"])
        v = w3 * F(2, 10) / 2  # two-fall block on a drum of radius 0.2 m
        inert = reduced_inertia(
            {"worm": 1, "wheel": m["wheel"], "drum": w3, "block": w3 / 2},
            "worm",
            {"worm": F(7, 10), "wheel": F(18, 10), "drum": 107, "block": 2},
            translating=[(80, v), (44000, v)],
        )
        return w3, inert

    w3, inert = hoist(72)
    assert w3 == F(1, 222)
    assert float(inert) == pytest.approx(0.71244, abs=1e-5)
    assert float(inert) == pytest.approx(0.7123, abs=3e-4)  # the printed answer
    w3_printed, _ = hoist(76)
    assert float(w3_printed) == pytest.approx(0.0042674, abs=1e-7)  # not the printed 0.0045


def test_ozols_biplanetary_ratio():
    # Ozols Fig 7-10 (a): i_1H = 1 + (1 + rH/r1) r3/r2; digest derived r3, r2, rH, r1 =
    # 60, 20, 10, 5 -> 10 (the velocity plan (b) gives 10 too).
    assert biplanetary(60, 20, 10, 5).ratio("1", "H", fixed=["3"]) == 10
    z3, z2, zh, z1 = 72, 18, 14, 9
    expected = 1 + (1 + F(zh, z1)) * F(z3, z2)
    assert biplanetary(z3, z2, zh, z1).ratio("1", "H", fixed=["3"]) == expected


def test_ozols_khv_coupled_satellite():
    # Ozols Fig 7-9b: i_1H = 1 - z2/z1 = i_3H; digest derived z1 = 49, z2 = 50 -> -1/49.
    t = khv(49, 50)
    assert t.ratio("planet", "carrier", fixed=["ring"]) == F(-1, 49)
    assert t.ratio("output", "carrier", fixed=["ring"]) == F(-1, 49)
    assert t.ratio("carrier", "output", fixed=["ring"]) == -49


def test_ozols_car_differential_special_cases():
    # Ozols (7.9): w1 + w2 = 2 wH; straight: w1 = w2 = wH; w1 = 0 -> w2 = 2 wH; wH = 0 -> w1 = -w2.
    from trains import bevel_differential

    t = bevel_differential()
    assert t.solve(left=50, carrier=50)["right"] == 50
    assert t.solve(left=0, carrier=50)["right"] == 100
    assert t.solve(left=30, carrier=0)["right"] == -30


def test_joldasbekov_e1_structural_mobility():
    # Joldasbekov E1 (Fig 31): n = 4 moving links, p5 = 4, p4 = 3 -> W = 1.
    t = Train()
    t.mesh("1", "2", teeth=(20, 40))
    t.mesh("2", "3", teeth=(18, 36))
    t.mesh("3", "4", teeth=(15, 45))
    s = t.structure
    assert (s.links, s.lower_pairs, s.higher_pairs, s.chebyshev) == (4, 4, 3, 1)
    assert s.mobility == 1 and s.redundant == 0


def test_joldasbekov_e6_compound_differential():
    # Joldasbekov E6 (Fig 191): n1 = 1500, n9 = -1000. Printed: z6' = 15 (coaxiality),
    # n1/n4 = 5, n9/n5 = 5/6, |i^H_{5'7}| = 1/3; final answer lost in the OCR.
    # Sign choice (digest recommendation): n1/n4 = +5 as printed (gear 4 modelled as internal),
    # i^H = -1/3 (ring 5' internal with planet 6, planet 6' external with sun 7, as the
    # coaxiality z7 + z6' = z5' - z6 requires) -> n_H = 300, n5 = -1200, n7 = 4800.
    z6p = 50 - 10 - 25
    assert z6p == 15
    t = Train()
    t.mesh("1", "2", teeth=(15, 30))
    t.mesh("2", "3", teeth=(20, 25))
    t.mesh("3", "H", teeth=(25, 50), internal=True)  # gear 4 on the carrier H
    t.mesh("9", "8", teeth=(15, 10))
    t.mesh("8", "5", teeth=(20, 25))
    t.mesh("5", "6", teeth=(50, 10), carrier="H", internal=True)
    t.mesh("6", "7", teeth=(z6p, 25), carrier="H")
    assert t.ratio("1", "H") == 5
    assert t.ratio("9", "5") == F(5, 6)
    m = t.solve({"1": 1500, "9": -1000})
    assert (m["H"], m["5"], m["7"]) == (300, -1200, 4800)


def test_joldasbekov_e8_strain_wave_ratio():
    # Joldasbekov E8: printed "i31 = -0.5 z2" for z2 - z1 = 2 is OCR/approximation; Willis gives
    # -z1/(z2 - z1) = -0.5 z1 (digest §3 E8): z1 = 200, z2 = 202 -> -100, not -101.
    assert strain_wave(200, 202).ratio("generator", "flexspline", fixed=["rigid"]) == -100


@pytest.mark.parametrize("kinds", [("external", "internal"), ("external", "external"),
                                   ("internal", "internal")])  # fmt: skip
@pytest.mark.parametrize("closing", ["external", "internal"])
def test_joldasbekov_e10_closed_differential_formula(kinds, closing):
    # Joldasbekov E10 (Fig 192) [R]: n1/n5 = 1 + i13^H (i35 - 1); same as Ozols §2.2
    # i15 = (i13 - 1)/(i13 i31 - 1) (Fig 7-12). Solver vs both closed forms.
    rng = np.random.default_rng(len(kinds[0]) + len(kinds[1]) + len(closing))
    for _ in range(5):
        z1, z2, z2p, z3, z3p, z5 = (int(v) for v in rng.integers(12, 90, size=6))
        t = stepped_planetary(z1, z2, z2p, z3, meshes=kinds)
        t.mesh("3", "H", teeth=(z3p, z5), internal=closing == "internal")  # 3' -> 5 (= H)
        s1 = -1 if kinds[0] == "external" else 1
        s2 = -1 if kinds[1] == "external" else 1
        i13 = s1 * s2 * F(z2 * z3, z1 * z2p)
        i35 = (-1 if closing == "external" else 1) * F(z5, z3p)
        if i35 == 1:
            continue
        assert t.ratio("1", "H") == 1 + i13 * (i35 - 1)
        # Ozols Fig 7-12: the closing chain joins 3 and 1 instead: i31 = w3/w1
        t = stepped_planetary(z1, z2, z2p, z3, meshes=kinds)
        t.mesh("3", "1", teeth=(z3p, z5), internal=closing == "internal")
        i31 = (-1 if closing == "external" else 1) * F(z5, z3p)
        if i13 * i31 == 1:
            continue
        assert t.ratio("1", "H") == (i13 - 1) / (i13 * i31 - 1)


def test_lectures_k1_k2_k3_james_train():
    # lectures §3.3 [D] K1: z 18/45/108, ring fixed, w1 = 100: i13^H = -6, i1H = 7,
    # wH = 14.285714, w2 = -20, w2 - wH = -34.285714.
    t = simple_planetary(18, 45, 108)
    m = t.solve(sun=100, ring=0)
    assert m["carrier"] == F(100, 7)
    assert m["planet"] == -20
    assert float(m.relative("planet", "carrier")) == pytest.approx(-34.285714, abs=1e-6)
    # K2: as a differential, w1 = 100, w3 = 10 -> wH = (w1 + 6 w3)/7 = 22.857143
    assert t.solve(sun=100, ring=10)["carrier"] == F(160, 7)
    # K3: closed by a pinion 20 on the input shaft driving external teeth 60 on the ring
    t.mesh("sun", "ring", teeth=(20, 60), name="closing")
    assert t.ratio("sun", "carrier") == -7
    assert float(t.solve(sun=100)["carrier"]) == pytest.approx(-14.285714, abs=1e-6)


@pytest.mark.parametrize(
    ("kinds", "sign"),
    [(("external", "internal"), -1), (("external", "external"), 1), (("internal", "internal"), 1)],
)
def test_lectures_4_2_scheme_basic_ratios(kinds, sign):
    # lectures §4.2: B: i13^H = -z2 z3/(z1 z2'); C and D: +z2 z3/(z1 z2'); i1H = 1 - i13^H.
    z1, z2, z2p, z3 = 30, 45, 20, 81
    t = stepped_planetary(z1, z2, z2p, z3, meshes=kinds)
    i13 = sign * F(z2 * z3, z1 * z2p)
    m = t.solve({"1": 1, "H": 0})
    assert m["1"] / m["3"] == i13
    assert t.ratio("1", "H", fixed=["3"]) == 1 - i13


def test_standards_compound_planet_example():
    # standards.md §4: compound planet 20/40/20/80, ring fixed: ws/wH = 1 + zr zp1/(zs zp2) = 9.
    assert stepped_planetary(20, 40, 20, 80).ratio("1", "H", fixed=["3"]) == 9
    # and the simple set: ring fixed 1 - i0, sun fixed 1 - 1/i0 (i0 = -4)
    t = simple_planetary(20, 30, 80)
    assert t.ratio("sun", "carrier", fixed=["ring"]) == 5
    assert t.ratio("ring", "carrier", fixed=["sun"]) == 1 - 1 / F(-4)
