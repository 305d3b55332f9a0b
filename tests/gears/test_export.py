"""2D export (gears/export.py) and the profile CLI."""

import xml.etree.ElementTree as ET

import numpy as np
import pytest
import shapely

from gears import Gear, GearError, GearPair
from gears.export import points, save, to_dxf, to_svg
from trains.cli import main


def _svg_rings(path):
    root = ET.parse(path).getroot()
    rings = []
    for el in root.iter("{http://www.w3.org/2000/svg}path"):
        for part in el.get("d").split("M")[1:]:
            xy = [tuple(map(float, p.split(","))) for p in part.rstrip(" Z").split(" L")]
            rings.append(np.array(xy))
    return root, rings


def test_svg_round_trip_in_mm(tmp_path):
    # source: the SVG spec (viewBox user units = mm here): the written vertices (1 nm
    # resolution) reproduce the outline's area after undoing the y flip
    p = Gear(12, 2, profile_shift=0.4).outline(0.01, bore=6)
    root, rings = _svg_rings(to_svg(tmp_path / "g.svg", p))
    assert root.get("width").endswith("mm")
    _x0, y0, _w, h = map(float, root.get("viewBox").split())
    flipped = [np.column_stack([r[:, 0], 2 * y0 + h - r[:, 1]]) for r in rings]
    back = shapely.Polygon(flipped[0], holes=flipped[1:])
    assert back.area == pytest.approx(p.area, rel=1e-8)


def test_dxf_and_npz(tmp_path):
    # source: ezdxf reads back the closed polylines with the same vertices
    ezdxf = pytest.importorskip("ezdxf")
    p1, p2 = GearPair(Gear(12, 3, profile_shift=0.6), Gear(24, 3, profile_shift=0.36)).outlines(
        tolerance=0.01
    )
    doc = ezdxf.readfile(to_dxf(tmp_path / "p.dxf", p1, p2))
    lw = list(doc.modelspace().query("LWPOLYLINE"))
    assert len(lw) == 2 and all(e.closed for e in lw)
    assert len(lw[0]) == len(points(p1)[0])
    data = np.load(save(tmp_path / "p.npz", p1, p2))
    assert np.array_equal(data["outline0_ring0"], points(p1)[0])
    with pytest.raises(GearError, match="format"):
        save(tmp_path / "p.stl", p1)


def test_cli_profile_writes_files(tmp_path, capsys):
    # source: issue 5 CLI example
    out = tmp_path / "gear.svg"
    args = ["profile", "12", "--module", "3", "--shift", "0.6", "--method", "rack"]
    assert main([*args, "--tolerance", "0.001", "-o", str(out)]) == 0
    assert out.read_text().count("<path") == 1
    png = tmp_path / "pair.png"
    assert main(["profile", "12", "-m", "3", "-x", "0.6", "--mate", "24", "-o", str(png)]) == 0
    assert png.stat().st_size > 1000
    assert main(["profile", "80", "--internal", "--method", "rack", "-o", str(out)]) == 2
    assert "cannot generate an internal gear" in capsys.readouterr().err
    # a ring cut by a 30-tooth shaper (simulated): one outer circle and one toothed hole
    args = ["profile", "80", "-m", "2", "--internal", "--method", "shaper", "--cutter-teeth", "30"]
    assert main([*args, "--tolerance", "0.01", "-o", str(out)]) == 0
    assert out.read_text().count("<path") == 1 and "shaper" in capsys.readouterr().out
    assert main(["profile", "40", "--internal", "--cutter-teeth", "40", "-o", str(out)]) == 2
    assert "--cutter-teeth < z" in capsys.readouterr().err  # the CLI names its option (issue 11)


def test_plots_render(tmp_path):
    # source: smoke test of the three figure kinds (matplotlib Agg)
    pytest.importorskip("matplotlib")
    import matplotlib.pyplot as plt

    from gears.plot import generation_figure, pair_figure, tooth_figure

    for fig in (
        tooth_figure(Gear(8, 1)),
        generation_figure(Gear(8, 1), 1e-2),
        pair_figure(
            GearPair(Gear(20, 2, profile_shift=0.5), Gear(80, 2, internal=True, profile_shift=0.5))
        ),
    ):
        fig.savefig(tmp_path / "f.png")
        plt.close(fig)


def test_shaper_generation_figure(tmp_path):
    # the shaper's teeth over an internal and an external gear; a rack cannot cut a ring
    pytest.importorskip("matplotlib")
    import matplotlib.pyplot as plt

    from gears.cutter import ShaperCutter
    from gears.plot import generation_figure

    ring = Gear(40, 1, internal=True, profile_shift=0.3)
    for fig in (
        generation_figure(ring, 1e-2, method="shaper", cutter=ShaperCutter(20)),
        generation_figure(Gear(8, 1), 1e-2, every=2, method="shaper"),
    ):
        assert "shaper generation" in fig.axes[0].get_title()
        fig.savefig(tmp_path / "f.png")
        plt.close(fig)
    with pytest.raises(GearError, match="rack cutter cannot"):
        generation_figure(ring)
    with pytest.raises(GearError, match="method"):
        generation_figure(Gear(8, 1), method="hob")
