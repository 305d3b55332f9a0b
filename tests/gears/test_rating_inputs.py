"""The rating's inputs (issue 26): what a rating accepts, what it refuses with the value and its
bound, and that every accepted pair gets finite safeties that fall as the torque rises.

Sources: ISO 6336-1 (the load factors are at least 1; one K_alpha for contact and root, each
within its bound, §8.3; F_t K_A / b taken as 100 N/mm where smaller in K_v and K_alpha), ISO
6336-2 §8 (Z_eps), ISO 6336-3 §14 (Y_RrelT of the root's roughness); identities of the rating's
own formulas (S_F proportional to 1/T with every load factor pinned; a row of ``rate_pairs``
equals the scalar call); the brute force of rating every row alone.
"""

from __future__ import annotations

import math
import re
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import Gear, GearPair, pair_geometry, rate_pairs
from gears.errors import GearError
from gears.rating import REASONS, load_case, rate
from gears.rating.bending import root_surface_factor
from trains import Planetary
from trains.cli.app import main
from trains.errors import TrainError


def _pair(m=3.0, b=30.0, **kw):
    return GearPair(Gear(19, m, face_width=b, **kw), Gear(61, m, face_width=b, **kw))


# --- tip relief, in mm, bounded by the tooth ------------------------------------------------------
def test_tip_relief_is_bounded_by_the_tooth_and_the_message_says_mm():
    pair = _pair(m=8.0, b=100.0)
    with pytest.raises(GearError, match=r"tip_relief = 5 mm.*0\.8 mm.*5 um is 0\.005"):
        pair.rating(9000, 360, tip_relief=5.0)  # meant as 5 um
    r = pair.rating(9000, 360, tip_relief=0.005)  # 5 um, as meant: rated
    assert min(r.safety_pitting) > 0
    with pytest.raises(GearError, match="tip_relief"):
        rate_pairs(17, 103, 8, 100, 9000, 360, tip_relief=[0.01, 1.0])


# --- root roughness -------------------------------------------------------------------------------
def test_root_roughness_reaches_y_rrelt_through_every_entry():
    pair = _pair()
    flank = pair.rating(150, 1450, roughness=0.4)
    hobbed = pair.rating(150, 1450, roughness=0.4, root_roughness=3.2)
    # ISO 6336-3 §14 (case-hardened): Y_RrelT = 1.674 - 0.529 (R_z + 1)^0.1, R_z = 6 Ra
    assert hobbed.values.Y_RrelT1 == pytest.approx(1.674 - 0.529 * (6 * 3.2 + 1) ** 0.1, rel=1e-12)
    assert float(root_surface_factor(6 * 3.2, 4)) == pytest.approx(hobbed.values.Y_RrelT1, 1e-12)
    ratio = hobbed.values.Y_RrelT1 / flank.values.Y_RrelT1
    assert hobbed.safety_bending[0] == pytest.approx(flank.safety_bending[0] * ratio, rel=1e-12)
    assert hobbed.safety_pitting == pytest.approx(flank.safety_pitting, rel=1e-12)
    # rate_pairs took it already: the same row
    row = rate_pairs(19, 61, 3, 30, 150, 1450, roughness=0.4, root_roughness=3.2)
    assert float(row.S_F1) == pytest.approx(hobbed.safety_bending[0], rel=1e-12)
    # Planetary.rating and trains.rating pass it to every mesh
    stage = Planetary(21, 36, 93, n_planets=3, module=2)
    plain = stage.rating(120, 1500, face_width=20)
    rough = stage.rating(120, 1500, face_width=20, root_roughness=3.2)
    for name in plain:
        assert rough[name].settings["root_roughness"] == pytest.approx(3.2, rel=1e-15)
        assert rough[name].safety_bending[0] < plain[name].safety_bending[0]


def test_cli_rate_takes_root_roughness(capsys):
    argv = ["rate", "19", "61", "-m", "3", "--face-width", "30", "--torque", "150", "--speed",
            "1450", "--roughness", "0.4", "--root-roughness", "3.2"]  # fmt: skip
    main(argv)
    out = capsys.readouterr().out
    api = _pair().rating(150, 1450, roughness=0.4, root_roughness=3.2)
    line = next(x for x in out.splitlines() if x.startswith("safety bending S_F"))
    # printed to 4 decimals
    assert [float(v) for v in line.split()[-2:]] == pytest.approx(api.safety_bending, abs=1e-4)
    assert main([*argv[:-1], "0"]) == 2
    assert "--root-roughness" in capsys.readouterr().err


# --- the load factors a user gives ----------------------------------------------------------------
def test_a_given_k_halpha_sets_k_falpha_within_its_bound():
    pair = _pair()
    pinned = {"K_v": 1.05, "K_Hbeta": 1.2, "K_Halpha": 1.0}
    r1 = pair.rating(150, 1450, **pinned)
    r2 = pair.rating(300, 1450, **pinned)
    assert r1.values.K_Falpha == pytest.approx(1.0, abs=1e-15)
    # every load factor pinned: sigma_F is linear in F_t, so S_F halves as the torque doubles
    assert r2.safety_bending == pytest.approx([s / 2 for s in r1.safety_bending], rel=1e-12)
    # above its bound K_Falpha <= eps_gamma / (0.25 eps_alpha + 0.75) (ISO 6336-1 §8.3)
    r = pair.rating(150, 1450, K_Halpha=1.5)
    ea, eg = r.values.eps_alpha, r.values.eps_gamma
    assert r.values.K_Falpha == pytest.approx(min(1.5, eg / (0.25 * ea + 0.75)), rel=1e-12)
    # and the other way round: K_Falpha given sets K_Halpha (bound eps_gamma/(eps_alpha Z_eps^2))
    r = pair.rating(150, 1450, K_Falpha=1.2)
    bound = eg / (ea * r.values.Z_eps**2)
    assert r.values.K_Halpha == pytest.approx(min(1.2, bound), rel=1e-12)


@pytest.mark.parametrize("factor", ["K_A", "K_v", "K_gamma", "K_Hbeta", "K_Halpha", "K_Fbeta"])
def test_load_factors_below_one_are_refused_with_the_bound(factor):
    with pytest.raises(GearError, match=rf"{factor} = 0\.9.*1 <= {factor}"):
        _pair().rating(150, 1450, **{factor: 0.9})


def test_planet_load_sharing_below_one_and_life_as_text_are_refused():
    stage = Planetary(21, 36, 93, n_planets=3, module=2)
    with pytest.raises(TrainError, match=r"load_sharing_factor = 0\.5.*>= 1"):
        stage.rating(120, 1500, face_width=20, load_sharing_factor=0.5)
    with pytest.raises(GearError, match="life = '20000'; valid is one number"):
        _pair().rating(150, 1450, life="20000")
    with pytest.raises(GearError, match="life"):
        rate_pairs(19, 61, 3, 30, 150, 1450, life="20000")


# --- NaN where the contact ratio exceeds 4 --------------------------------------------------------
def test_contact_ratio_above_four_has_no_z_eps_and_no_nan(capsys):
    # alpha = 5 deg, x = 0: eps_alpha about 5.6 (ISO 6336-2 §8: (4 - eps_alpha)/3 < 0)
    pair = GearPair(Gear(150, 2, 5, face_width=20), Gear(150, 2, 5, face_width=20))
    assert pair.contact_ratio > 4
    with pytest.raises(GearError, match="Z_eps"):
        pair.rating(100, 1500)
    r = rate_pairs(150, 150, 2, 20, 100, 1500, pressure_angle=5, errors="mask")
    assert not r.valid and "Z_eps" in REASONS[int(r.reason)] and float(r.S_H1) == 0.0
    code = main(["rate", "150", "150", "-m", "2", "--pressure-angle", "5", "--face-width", "20",
                 "--torque", "100", "--speed", "1500"])  # fmt: skip
    err = capsys.readouterr().err
    assert code == 2 and "Z_eps" in err and "Traceback" not in err


# --- no load point of method B at a small pressure angle ------------------------------------------
def test_a_small_pressure_angle_names_itself_and_where_method_b_applies(capsys):
    # 20/40, m = 2, alpha = 5 deg: eps_alpha = 2.78, so the outer point of single contact of
    # ISO 6336-3 §6.2 lies eps_alpha_n - 1 = 1.78 base pitches inside the pinion's tip, past its
    # base circle; the rating said "alpha = nan rad" (issue 26). The range it names is checked
    # by rating at its ends (independent: the rating itself, not the range's search)
    def pair(alpha):
        return GearPair(Gear(20, 2, alpha, face_width=20), Gear(40, 2, alpha, face_width=20))

    with pytest.raises(GearError, match=r"pressure_angle = 5 deg .* valid is pressure_angle >= "
                                        r"7\.2 deg") as exc:  # fmt: skip
        pair(5.0).rating(100, 1500)
    assert "single contact" in str(exc.value) and "nan" not in str(exc.value)
    with pytest.raises(GearError, match="single contact"):
        pair(7.15).rating(100, 1500)
    s = pair(7.2).rating(100, 1500).safety_bending
    assert all(math.isfinite(v) and v > 0 for v in s)
    # the arrays: the row is masked with the reason, the other rated
    r = rate_pairs(20, 40, 2, 20, 100, 1500, pressure_angle=[5.0, 20.0], errors="mask")
    assert r.valid.tolist() == [False, True] and "single contact" in REASONS[int(r.reason[0])]
    # the command line: one line naming the option, exit 2
    code = main(["rate", "20", "40", "-m", "2", "--pressure-angle", "5", "--face-width", "20",
                 "--torque", "100", "--speed", "1500"])  # fmt: skip
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "nan" not in err
    assert "--pressure-angle = 5 deg" in err and "--pressure-angle >= 7.2 deg" in err


# --- values no rating can take --------------------------------------------------------------------
@pytest.mark.parametrize(
    "name", ["torque", "face_width", "roughness", "root_roughness", "sigma_Hlim", "sigma_Flim"]
)
@pytest.mark.parametrize(
    "value", [5e-324, 10**400, -(10**400), 1e300], ids=["denormal", "10**400", "-10**400", "1e300"]
)
def test_denormal_and_huge_values_are_refused_naming_them(name, value):
    pair = _pair()
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no RuntimeWarning before the check
        kw = {"torque": 150, "speed": 1450, name: value}
        with pytest.raises(GearError, match=name):
            pair.rating(kw.pop("torque"), kw.pop("speed"), **kw)
        kw = {"torque": 150, "face_width": 30, name: value}
        with pytest.raises(GearError, match=name):
            rate_pairs(19, 61, 3, kw.pop("face_width"), kw.pop("torque"), 1450, **kw)


@pytest.mark.parametrize("name", ["torque", "speed", "life"])
def test_huge_integers_are_refused_in_sizing(name):
    kw = {"torque": 60, "speed": 1500, "life": 20000}
    kw[name] = 10**400
    with pytest.raises(GearError, match=name):
        load_case(kw["torque"], kw["speed"], life=kw["life"])
    with pytest.raises(GearError, match="module"):
        rate(load_case(60, 1500), 20, 40, 10**400, 20)


def test_a_face_width_no_gear_can_have_is_bad_input(capsys):
    with pytest.raises(GearError, match=r"face_width = 1e-09 mm; valid is face_width >= 0\.1 m_n"):
        _pair().rating(150, 1450, face_width=1e-9)
    code = main(["rate", "19", "61", "-m", "3", "--face-width", "1e-9", "--torque", "150",
                 "--speed", "1450"])  # fmt: skip
    err = capsys.readouterr().err
    assert code == 2 and "--face-width" in err and err.count("\n") == 1


# --- arrays ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("name", ["torque", "speed", "life", "quality", "face_width", "K_v"])
def test_one_pair_rating_refuses_arrays_before_work(name):
    kw = {"torque": 150, "speed": 1450}
    kw[name] = np.array([150.0, 160.0]) if name != "quality" else np.array([6, 7])
    with pytest.raises(GearError, match=f"{name} = .*one number"):
        _pair().rating(kw.pop("torque"), kw.pop("speed"), **kw)


def test_tip_shortening_may_be_an_array():
    z2 = np.array([28, 28])
    flags = np.array([True, False])
    geo = pair_geometry(12, z2, 1.0, 0.6, 0.6, tip_shortening=flags)
    for i, flag in enumerate(flags):
        one = pair_geometry(12, 28, 1.0, 0.6, 0.6, tip_shortening=bool(flag))
        assert geo.tip_alteration[i] == pytest.approx(float(one.tip_alteration), abs=1e-15)
    assert geo.tip_alteration[0] < 0 and geo.tip_alteration[1] == 0
    r = rate_pairs(12, z2, 2, 20, 20, 1500, x1=0.6, x2=0.6, tip_shortening=flags, errors="mask")
    for i, flag in enumerate(flags):
        one = rate_pairs(12, 28, 2, 20, 20, 1500, x1=0.6, x2=0.6, tip_shortening=bool(flag),
                         errors="mask")  # fmt: skip
        assert r.S_H1[i] == pytest.approx(float(one.S_H1), rel=1e-12)
    with pytest.raises(GearError, match="tip_shortening"):
        pair_geometry(12, 28, 1.0, tip_shortening="yes")


# --- one default tool tip radius ------------------------------------------------------------------
def test_rate_pairs_takes_the_gear_s_tool_tip_radius_at_steep_pressure_angles():
    pair = GearPair(Gear(20, 2, 30, face_width=20), Gear(40, 2, 30, face_width=20))
    assert pair.g1.rack.root_radius < 0.38  # capped to fit the tool at 30 deg
    r = pair.rating(60, 1500)
    row = rate_pairs(20, 40, 2, 20, 60, 1500, pressure_angle=30)
    assert float(row.S_F1) == pytest.approx(r.safety_bending[0], rel=1e-12)
    assert float(row.rho_F1) == pytest.approx(r.values.rho_F1, rel=1e-12)


# --- finite and monotone in torque ----------------------------------------------------------------
@settings(max_examples=60, deadline=None)
@given(
    z1=st.integers(12, 40),
    dz=st.integers(1, 80),
    m=st.sampled_from([0.5, 1.0, 2.0, 5.0]),
    b_per_m=st.floats(2.0, 30.0),
    helix=st.sampled_from([0.0, 15.0]),
    speed=st.floats(1.0, 20000.0),
    log_t=st.floats(-9.0, 4.0),
    quality=st.integers(3, 10),
)
def test_safeties_are_finite_and_fall_as_the_torque_rises(z1, dz, m, b_per_m, helix, speed, log_t,
                                                          quality):  # fmt: skip
    torques = 10.0 ** (log_t + np.linspace(0.0, 3.0, 13))
    torques = torques[torques < 1e6]
    r = rate_pairs(z1, z1 + dz, m, b_per_m * m, torques, speed, helix_angle=helix,
                   quality=quality, errors="mask")  # fmt: skip
    if not np.any(r.valid):
        return
    assert np.all(r.valid) or not np.any(r.valid)  # validity does not depend on the load
    for s in (r.S_H1, r.S_H2, r.S_F1, r.S_F2):
        assert np.all(np.isfinite(s)) and np.all(s > 0)
        # non-increasing within rounding as the torque rises
        assert np.all(np.diff(s) <= 1e-12 * s[:-1]), s


# --- one pair at many loads: the gears' part kept, the numbers those of the array path ------------
def test_repeated_ratings_of_one_pair_agree_with_the_array_path():
    pair = GearPair(Gear(19, 3, helix_angle=12.0, face_width=30),
                    Gear(61, 3, helix_angle=-12.0, face_width=30))  # fmt: skip
    torques, speeds = [5.0, 80.0, 150.0, 900.0], [300.0, 1450.0, 1450.0, 6000.0]
    # brute force: the same formulas over arrays (no cache), row by row
    rows = rate_pairs(19, 61, 3, 30, torques, speeds, helix_angle=12.0, tip_shortening=True)
    for i, (t, n) in enumerate(zip(torques, speeds, strict=True)):
        for _ in range(2):  # the second call finds the gears' part kept
            r = pair.rating(t, n)
            for f in ("S_H1", "S_H2", "S_F1", "S_F2", "K_v", "Z_v", "Y_NT1"):
                assert getattr(r.values, f) == pytest.approx(getattr(rows, f)[i], rel=1e-12), f
    # the load's factors given by symbol are the load's too: kept apart from the gears' part
    plain = pair.rating(150, 1450)
    for factors in ({"K_gamma": 1.16}, {"K_A": 1.5}, {}):
        row = rate_pairs(19, 61, 3, 30, [150.0, 151.0], 1450, helix_angle=12.0, factors=factors)
        for _ in range(2):  # the second call finds the gears' part and the arguments kept
            r = pair.rating(150, 1450, **factors)
            assert r.values.S_H1 == pytest.approx(row.S_H1[0], rel=1e-12), factors
    assert r.values.S_H1 == pytest.approx(plain.values.S_H1, rel=1e-12)
    # another pair is not served from the kept part
    other = GearPair(Gear(19, 3, face_width=30, profile_shift=0.3), Gear(61, 3, face_width=30))
    assert other.rating(150, 1450).safety_bending[0] != pytest.approx(
        pair.rating(150, 1450).safety_bending[0], rel=1e-6
    )


# --- every option at the edges of floats: a finite rating or our own error, no warning ------------
_OPTIONS = ["life", "application_factor", "quality", "roughness", "root_roughness",
            "oil_viscosity", "tip_relief", "sigma_Hlim", "sigma_Flim", "face_width",
            "misalignment", "K_v", "K_Hbeta", "Z_E", "Y_F"]  # fmt: skip
_EDGES = [5e-324, 1e-300, 1e300, 10**400, -1.0, math.nan, math.inf, 0.0]


@pytest.mark.parametrize("name", ["torque", "speed", *_OPTIONS])
def test_every_option_at_the_edges_of_floats_gives_a_rating_or_our_error(name):
    pair = _pair()
    for value in _EDGES:
        kw = {"torque": 150, "speed": 1450, name: value}
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            try:
                r = pair.rating(kw.pop("torque"), kw.pop("speed"), **kw)
            except GearError as exc:
                assert name in str(exc), (name, value, exc)
                continue
        s = [*r.safety_pitting, *r.safety_bending]
        assert all(math.isfinite(v) and v > 0 for v in s), (name, value, s)
        r.check()
        r._repr_html_()


@settings(max_examples=25, deadline=None)
@given(
    z1=st.integers(8, 40),
    dz=st.integers(1, 90),
    x1=st.floats(-0.5, 1.0),
    x2=st.floats(-0.5, 1.0),
    internal=st.booleans(),
    pressure_angle=st.sampled_from([5.0, 8.0, 14.5, 20.0, 25.0, 30.0]),
    log_t=st.floats(-9.0, 5.0),
    speed=st.floats(0.1, 30000.0),
)
def test_every_accepted_pair_rates_finite_or_refuses(z1, dz, x1, x2, internal, pressure_angle,
                                                     log_t, speed):  # fmt: skip
    try:
        g1 = Gear(z1, 2, pressure_angle, profile_shift=x1, face_width=20)
        g2 = Gear(z1 + dz + (10 if internal else 0), 2, pressure_angle, profile_shift=x2,
                  face_width=20, internal=internal)  # fmt: skip
        pair = GearPair(g1, g2)
    except GearError:
        return
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            r = pair.rating(10.0**log_t, speed)
        except GearError as exc:
            assert not re.search(r"\bnan\b", str(exc)), exc  # the reason, never a NaN
            return
    s = [*r.safety_pitting, *r.safety_bending]
    assert all(math.isfinite(v) and v > 0 for v in s), s
    r.check()  # silent: a Report, whatever the margins
    assert "<table>" in r._repr_html_()
