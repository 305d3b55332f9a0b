"""Load spectra through trains: trains.rating(spectrum=...), Planetary.rating(spectrum=...), the
CLI ``geartrain rate --spectrum FILE`` (issue 30).

Sources: each bin of a train's spectrum is the train rated at that load (trains.rating), so the
spectrum rating of every mesh equals the one of its own GearPair under the mesh's per-bin
torques and speeds (gears.rating.spectrum, tested against Miner's rule by hand in
tests/gears/test_spectrum.py); a one-bin spectrum equals the single-load rating.
"""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gears import Gear
from trains import Planetary, Train
from trains import rating as rate_train
from trains.cli import main
from trains.errors import TrainError


def _stage():
    return Planetary(sun=21, planet=36, ring=93, n_planets=3, module=2)


def test_planetary_spectrum_is_each_mesh_under_its_bins():
    stage = _stage()
    bins = [(120.0, 1500.0, 5000.0), (200.0, 1500.0, 200.0)]
    spec = stage.rating(spectrum=bins, face_width=20)
    for name, s in spec.items():
        # the mesh's own bins: the torques and speeds its single-load ratings carried
        rows = [(r.settings["torque"], r.settings["speed"], h) for r, (_, _, h) in
                zip(s.bins, bins, strict=True)]  # fmt: skip
        pair = s.pair
        kw = {k: s.bins[0].settings[k] for k in ("contacts",)}
        idler = tuple(bool(y) for y in (s.bins[0].factors["Y_M"][0] < 1,
                                         s.bins[0].factors["Y_M"][1] < 1))  # fmt: skip
        direct = pair.rating(spectrum=rows, face_width=20, idler=idler,
                             K_gamma=s.bins[0].factors["K_gamma"], **kw)  # fmt: skip
        for a, b in zip((*s.safety_pitting, *s.safety_bending),
                        (*direct.safety_pitting, *direct.safety_bending), strict=True):  # fmt: skip
            assert a == pytest.approx(b, rel=1e-9), name


def test_one_bin_train_spectrum_is_the_single_load():
    t = Train()
    t.mesh("in", "out", gears=(Gear(19, 3, face_width=30), Gear(61, 3, face_width=30)))
    single = rate_train(t, "in", "out", torque=250, speed=1450, life=8000)["in-out"]
    spec = rate_train(t, "in", "out", spectrum=[(250, 1450, 8000)])["in-out"]
    assert spec.safety_pitting[0] == pytest.approx(single.safety_pitting[0], rel=1e-9)
    assert spec.safety_bending[1] == pytest.approx(single.safety_bending[1], rel=1e-9)


def test_bad_train_spectrum():
    with pytest.raises(TrainError, match="hours"):
        _stage().rating(spectrum=[(1.0, 1.0, 0.0)], face_width=20)
    with pytest.raises(TrainError, match="not both"):
        _stage().rating(10.0, 100.0, spectrum=[(1.0, 1.0, 1.0)], face_width=20)
    with pytest.raises(TrainError, match="life"):
        _stage().rating(spectrum=[(1.0, 1.0, 1.0)], face_width=20, life=3.0)


def test_cli_rate_spectrum(tmp_path, capsys):
    f = tmp_path / "duty.csv"
    f.write_text("torque, speed, hours\n150 1450 2000\n250, 1450, 200  # peak\n")
    code = main(["rate", "19", "61", "--module", "3", "--face-width", "30", "--spectrum", str(f)])
    out = capsys.readouterr().out
    assert code == 0 and "ISO 6336-6 load spectrum: 2 bins" in out
    bad = tmp_path / "bad.csv"
    bad.write_text("150 1450\n")
    assert main(["rate", "19", "61", "-m", "3", "--face-width", "30", "--spectrum", str(bad)]) == 2
    assert "--spectrum" in capsys.readouterr().err
    assert main(["rate", "19", "61", "-m", "3", "--face-width", "30", "--torque", "9"]) == 2


@settings(max_examples=8, deadline=None)
@given(st.lists(st.tuples(st.floats(1e-2, 1e4), st.floats(1.0, 1e4), st.floats(1e-2, 1e6)),
                min_size=1, max_size=3))  # fmt: skip
def test_planetary_spectrum_property(bins):
    try:
        spec = _stage().rating(spectrum=bins, face_width=20)
    except TrainError:
        return
    for s in spec.values():
        assert all(math.isfinite(v) and v > 0 for v in (*s.safety_pitting, *s.safety_bending))
