"""Statics and efficiency: Ozols §14 (examples 14-1 ... 14-3, (14.26)-(14.29)), the digest's
derived tables, standards.md §4 (Kreines), Ozols §11-2 torques, power circulation."""

from fractions import Fraction as F

import pytest

from trains import (
    Train,
    TrainError,
    parallel_efficiency,
    planetary_efficiency,
    power_flow,
    self_locking_range,
    series_efficiency,
    simple_planetary,
    stepped_planetary,
)


def _planetary(i1h, eta_h):
    """Gear 1, fixed gear n, carrier H with basic ratio i0 = 1 - i_1H, one lossy relation."""
    t = Train()
    t.link("1", "n", ratio=1 - F(i1h), carrier="H", name="inverted")
    return t, {"inverted": eta_h}


# Ozols digest §3 "Planetary efficiency (14.26)" table, eta_H = 0.98, corrected exponent k.
TABLE_14_26 = [
    ("4", 0.98500, 0.98492),
    ("-3", 0.97333, 0.97351),
    ("2", 0.99000, 0.98990),
    ("0.5", 0.97959, 0.98039),
    ("0.01", -1.02041, 0.33557),
    ("-0.01", -1.02000, 0.32667),
    ("0.0001", -203.061, 0.0049756),
    ("10000", 0.98000, 0.98000),
]


@pytest.mark.parametrize(("i1h", "eta_1h", "eta_h1"), TABLE_14_26)
def test_ozols_14_26_table_both_directions(i1h, eta_1h, eta_h1):
    t, eta = _planetary(i1h, 0.98)
    fwd = power_flow(t, "1", "H", fixed=["n"], mesh_efficiency=eta)
    back = power_flow(t, "H", "1", fixed=["n"], mesh_efficiency=eta)
    assert fwd.efficiency == pytest.approx(eta_1h, abs=6e-6 * max(1, abs(eta_1h)))
    assert back.efficiency == pytest.approx(eta_h1, abs=6e-6)
    # closed form (14.26) with the corrected exponent: an independent route, to round-off
    assert fwd.efficiency == pytest.approx(planetary_efficiency(F(i1h), 0.98), rel=1e-12)
    assert back.efficiency == pytest.approx(
        planetary_efficiency(F(i1h), 0.98, "carrier"), rel=1e-12
    )
    # self-locking exactly inside (14.27) when gear 1 drives; never when the carrier drives
    lo, hi = self_locking_range(0.98)
    assert fwd.self_locking == (lo < float(F(i1h)) < hi)
    assert not back.self_locking


def test_ozols_14_26_printed_exponent_h_is_a_misprint():
    # Ozols (14.26) prints i_1H eta^h; with h = +1 for H -> 1 at i_1H = 1e-4 that gives
    # eta = (1 - (1 - i) eta_H^h)/i = 196, impossible; the book's own answer 0.005 (ex. 14-3)
    # needs exponent k = -1 (digest §2.7, §5).
    i, eta_h = 1e-4, 0.98
    printed = (1 - (1 - i) * eta_h) / i
    assert printed > 1
    assert planetary_efficiency(i, eta_h, "carrier") == pytest.approx(0.005, abs=3e-5)


def test_ozols_14_3_david_mechanism_efficiency():
    # Ozols Ex 14-3: i_1H = 0.0001, eta_H = 0.98. Book: self-locking range -0.0204 < i < 0.02,
    # so 1 -> H locks (recomputed eta = -203.06); H -> 1: eta = 0.005 (recomputed 0.004976).
    t = stepped_planetary(100, 101, 100, 99, meshes=("external", "external"))
    eta = {"1-2": 0.98}  # eta_H = 0.98 for the whole inverted train
    lo, hi = self_locking_range(0.98)
    assert (lo, hi) == pytest.approx((-0.0204, 0.02), abs=5e-5)  # the book's four decimals
    fwd = power_flow(t, "1", "H", fixed=["3"], mesh_efficiency=eta)
    assert fwd.self_locking
    assert fwd.efficiency == pytest.approx(-203.06, abs=5e-3)
    back = power_flow(t, "H", "1", fixed=["3"], mesh_efficiency=eta)
    assert not back.self_locking
    assert back.efficiency == pytest.approx(0.005, abs=3e-5)
    assert back.efficiency == pytest.approx(0.0049756, abs=1e-7)


def test_lectures_efficiency_e_a_and_e_c():
    # lectures §3.3 [D] E-A: James 18/108, eta^H = 0.97 -> eta_1H = 1 - 0.03*108/126 = 0.974286.
    t = simple_planetary(18, 45, 108)
    pf = power_flow(t, "sun", "carrier", fixed=["ring"], mesh_efficiency={"sun-planet": 0.97})
    assert pf.efficiency == pytest.approx(0.974286, abs=1e-6)
    # E-C: David type (100/101/100/99), eta^H = 0.9: H -> 1 0.000999; 1 -> H self-locking with
    # output power about -1110 x input.
    t = stepped_planetary(100, 101, 100, 99, meshes=("external", "external"))
    back = power_flow(t, "H", "1", fixed=["3"], mesh_efficiency={"1-2": 0.9})
    assert back.efficiency == pytest.approx(0.0001 / 0.10009, rel=1e-9)
    fwd = power_flow(t, "1", "H", fixed=["3"], mesh_efficiency={"1-2": 0.9})
    assert fwd.self_locking and fwd.efficiency == pytest.approx(-1110, rel=1e-3)


@pytest.mark.parametrize(
    ("i0", "eta0", "eta_1h", "eta_h1"),
    [  # standards.md §4 values [C]
        (F(-4), 0.97, 0.97600, 0.97586),
        (F(-3, 2), 0.97, 0.98200, 0.98178),
        (F(98, 100), 0.95, -1.579, 0.28986),
        (F(102, 100), 0.95, -1.55, 0.27143),
    ],
)
def test_standards_kreines_table(i0, eta0, eta_1h, eta_h1):
    t = Train()
    t.link("1", "3", ratio=i0, carrier="H", name="basic")
    fwd = power_flow(t, "1", "H", fixed=["3"], mesh_efficiency={"basic": eta0})
    back = power_flow(t, "H", "1", fixed=["3"], mesh_efficiency={"basic": eta0})
    digits = 5e-6 if abs(eta_1h) < 1 else 5e-3
    assert fwd.efficiency == pytest.approx(eta_1h, abs=digits)
    assert back.efficiency == pytest.approx(eta_h1, abs=5e-6)
    assert fwd.self_locking == (eta_1h < 0)


def test_simple_planetary_per_mesh_efficiency_matches_kreines():
    # standards.md §4: i0 = -4, eta0 = 0.97 as the product of two meshes (0.97 = a * b).
    t = simple_planetary(20, 30, 80)
    a = 0.985
    eta = {"sun-planet": a, "planet-ring": 0.97 / a}
    assert power_flow(t, "sun", "carrier", fixed=["ring"], mesh_efficiency=eta).efficiency == (
        pytest.approx(0.976, abs=1e-12)
    )


def test_differential_14_28_general_sign_rule():
    # Ozols (14.28), drivers n and H, output 1; digest derived test: i^H_1n = -3, eta_H = 0.98,
    # w_n = -1, w_H = 1 -> w1 = 7; the general rule gives h = -1 and eta = 0.982808. The printed
    # rule (h = +1) would give 1.0174 > 1, impossible.
    t = Train()
    t.link("1", "n", ratio=-3, carrier="H", name="inverted")
    pf = power_flow(t, ["H", "n"], "1", mesh_efficiency={"inverted": 0.98},
                      input_speed={"H": 1, "n": -1})  # fmt: skip
    assert pf.speeds["1"] == 7
    assert pf.efficiency == pytest.approx(0.982808, abs=1e-6)
    i_eta = -3 / 0.98  # (14.28) with h = -1
    assert pf.efficiency == pytest.approx(1 / (i_eta * (-1 / 7) + (1 - i_eta) * (1 / 7)), rel=1e-12)
    assert pf.powers["H"] > 0 and pf.powers["n"] > 0  # both really drive


def test_differential_14_29_drivers_1_and_n():
    # Ozols (14.29), drivers 1 and n, output H; digest derived: w1 = 5, w_n = 1 -> wH = 2,
    # h = +1, eta = 0.992443.
    t = Train()
    t.link("1", "n", ratio=-3, carrier="H", name="inverted")
    pf = power_flow(t, ["1", "n"], "H", mesh_efficiency={"inverted": 0.98},
                      input_speed={"1": 5, "n": 1})  # fmt: skip
    assert pf.speeds["H"] == 2
    assert pf.efficiency == pytest.approx(0.992443, abs=1e-6)
    i_eta = -3 * 0.98
    assert pf.efficiency == pytest.approx((1 - i_eta) / (5 / 2 - i_eta * 1 / 2), rel=1e-12)


def test_fixed_axis_train_is_product_of_mesh_efficiencies():
    # Ozols (14.10) and example 14-1: eta = 0.95^2 * 0.90 = 0.81225; N_Q = Q v = 10000 kgf *
    # 12 m/min -> 26.67 hp (the printed 26.5 is a slip, digest §5), N_P = 32.83 hp = 24.15 kW.
    t = Train()
    t.mesh("motor", "a", teeth=(17, 60), name="s1")
    t.couple("a", "b")
    t.mesh("b", "c", teeth=(19, 70), name="s2")
    t.link("c", "drum", ratio=3, name="drum")
    eta = {"s1": 0.95, "s2": 0.95, "drum": 0.90}
    pf = power_flow(t, "motor", "drum", mesh_efficiency=eta, input_speed=1500)
    assert pf.efficiency == pytest.approx(0.81225, rel=1e-12)
    assert series_efficiency(0.95, 0.95, 0.90) == pytest.approx(0.81225, rel=1e-14)
    n_q = 10000 * 12 / (60 * 75)
    assert n_q == pytest.approx(26.67, abs=5e-3)
    assert n_q / pf.efficiency == pytest.approx(32.83, abs=5e-3)
    assert n_q / pf.efficiency * 0.7355 == pytest.approx(24.15, abs=5e-3)


def test_parallel_branches_14_2():
    # Ozols Ex 14-2: N1 = 15 hp at 0.95, N2 = 20 hp at 0.98 -> book 0.97, 36 hp
    # (recomputed 0.96691, 36.20).
    eta = parallel_efficiency([0.95, 0.98], output_power=[15, 20])
    assert eta == pytest.approx(0.96691, abs=5e-6)
    assert eta == pytest.approx(0.97, abs=0.005)  # the book's two decimals
    assert 35 / eta == pytest.approx(36.20, abs=5e-3)
    # Joldasbekov (9.8)/(9.9): equal shares and equal eta give eta.
    assert parallel_efficiency([0.9, 0.9, 0.9], input_power=[1, 1, 1]) == pytest.approx(0.9)
    # the two forms agree (14.13): input shares nu_i = (N_i/eta_i) / sum
    n_in = [15 / 0.95, 20 / 0.98]
    assert parallel_efficiency([0.95, 0.98], input_power=n_in) == pytest.approx(eta, rel=1e-14)


def test_ozols_11_11_planetary_torques():
    # Ozols (11.11), 3 satellites: M_H = M1 (1 + r3/r1) = 400 N m for M1 = 100, r1 = 0.05,
    # r3 = 0.15; mesh force R = M1/(3 r1 cos 20 deg) = 709.45 N (digest derived).
    import math

    pf = power_flow(
        simple_planetary(20, 20, 60, n_planets=3),
        "sun",
        "carrier",
        fixed=["ring"],
        input_torque=100.0,
    )
    assert pf.torques["carrier"] == pytest.approx(-400.0, rel=1e-14)
    assert pf.torques["ring"] == pytest.approx(300.0, rel=1e-14)
    assert pf.torques["sun"] / (3 * 0.05 * math.cos(math.radians(20))) == pytest.approx(
        709.45, abs=5e-3
    )
    assert sum(pf.torques.values()) == pytest.approx(0.0, abs=1e-12)
    assert pf.efficiency == pytest.approx(1.0, rel=1e-12)


def test_closed_differential_power_circulation():
    # lectures K3 train (James 18/45/108; pinion 20 on the input shaft drives the ring's 60
    # external teeth). Independent derivation (lossless): Willis levers on (sun, ring, carrier)
    # are lambda (1, 6, -7); the ring's external torque is 0, so the closing mesh puts -6 lambda
    # on the ring, turning at -w1/3: it carries 2 lambda w1 = twice the input power lambda w1.
    t = simple_planetary(18, 45, 108)
    t.mesh("sun", "ring", teeth=(20, 60), name="closing")
    pf = power_flow(t, "sun", "carrier")
    assert pf.relations["closing"].power == pytest.approx(2.0 * pf.input_power, rel=1e-12)
    assert pf.circulating_power == pytest.approx(1.0 * pf.input_power, rel=1e-12)
    assert pf.efficiency == pytest.approx(1.0, rel=1e-12)
    lossy = power_flow(t, "sun", "carrier", mesh_efficiency=0.98)
    assert lossy.efficiency < 0.98 * 0.98  # circulating power multiplies the losses
    assert sum(lossy.torques.values()) == pytest.approx(0.0, abs=1e-12)
    assert lossy.input_power - lossy.output_power == pytest.approx(
        sum(r.loss for r in lossy.relations.values()), rel=1e-9
    )


def test_power_flow_errors():
    t = simple_planetary(20, 30, 80)
    with pytest.raises(TrainError, match="under-determined"):
        power_flow(t, "sun", "carrier")
    with pytest.raises(TrainError, match="unknown relation 'sun-moon'"):
        power_flow(t, "sun", "carrier", fixed=["ring"], mesh_efficiency={"sun-moon": 0.9})
    with pytest.raises(TrainError, match=r"in \(0, 1\]"):
        power_flow(t, "sun", "carrier", fixed=["ring"], mesh_efficiency=1.2)
    with pytest.raises(TrainError, match="must all differ"):
        power_flow(t, "sun", "sun", fixed=["ring"])
    with pytest.raises(TrainError, match="supply no power"):
        power_flow(t, "sun", "carrier", fixed=["ring"], input_torque=-1.0)
