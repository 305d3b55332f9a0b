"""2D export (gears/export.py) and the profile CLI."""

import xml.etree.ElementTree as ET

import numpy as np
import pytest
import shapely

from gears import Gear, GearError, GearPair
from gears.solid.export import points, save, to_dxf, to_svg
from trains.cli.app import main


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

    from gears.figures.plot import generation_figure, pair_figure, tooth_figure

    for fig in (
        tooth_figure(Gear(8, 1)),
        generation_figure(Gear(8, 1), 1e-2),
        pair_figure(
            GearPair(Gear(20, 2, profile_shift=0.5), Gear(80, 2, internal=True, profile_shift=-0.5))
        ),
    ):
        fig.savefig(tmp_path / "f.png")
        plt.close(fig)


def test_shaper_generation_figure(tmp_path):
    # the shaper's teeth over an internal and an external gear; a rack cannot cut a ring
    pytest.importorskip("matplotlib")
    import matplotlib.pyplot as plt

    from gears.cutting.cutter import ShaperCutter
    from gears.figures.plot import generation_figure

    ring = Gear(40, 1, internal=True, profile_shift=-0.3)
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


# ---------------------------------------------------------------------------------------------
# issue 16: standard 3MF, one material file per OBJ; issue 17 item 4: bad paths before any work


def _strict_3mf(path):
    """Read ``path`` with lib3mf (the 3MF Consortium's reference library) in strict mode: the
    model, after asserting that the read raised nothing and warned nothing."""
    import lib3mf  # the test extra

    model = lib3mf.get_wrapper().CreateModel()
    reader = model.QueryReader("3mf")
    reader.SetStrictModeActive(True)
    reader.ReadFromFile(str(path))  # strict: a non-standard attribute raises
    assert [reader.GetWarning(i) for i in range(reader.GetWarningCount())] == []
    return model


def _count(iterator) -> int:
    n = 0
    while iterator.MoveNext():
        n += 1
    return n


def test_every_3mf_passes_lib3mf_strict(tmp_path):
    # source: the 3MF core spec as lib3mf enforces it. Before the fix every file failed with
    # "Invalid Attribute in namespace" (xmlns repeated on each build <item>). A gear, a pair
    # scene and a planetary scene: build items = parts, mesh objects = distinct geometries
    from trains import Planetary

    cases = [
        ("gear", Gear(20, 1, helix_angle=15).mesh(8, 0.05), 1, 1),
        ("pair", GearPair(Gear(12, 1), Gear(24, 1)).scene(tolerance=0.05), 2, 2),
        ("stage", Planetary(18, 45, 108, 3, 1).scene(tolerance=0.05), 5, 3),  # planets shared
    ]
    for name, obj, items, objects in cases:
        model = _strict_3mf(save(tmp_path / f"{name}.3mf", obj))
        assert _count(model.GetBuildItems()) == items, name
        assert _count(model.GetMeshObjects()) == objects, name


def test_obj_materials_are_named_after_the_obj(tmp_path):
    # two scenes in one folder keep their own materials: pair.obj -> pair.mtl, ring.obj ->
    # ring.mtl, each OBJ naming its own (the OBJ spec's mtllib statement)
    from trains import Planetary

    save(tmp_path / "pair.obj", GearPair(Gear(12, 1), Gear(24, 1)).scene(tolerance=0.1))
    save(tmp_path / "stage.obj", Planetary(18, 45, 108, 3, 1).scene(tolerance=0.1))
    assert sorted(p.name for p in tmp_path.glob("*.mtl")) == ["pair.mtl", "stage.mtl"]
    for name in ("pair", "stage"):
        head = (tmp_path / f"{name}.obj").read_text()[:2000]
        assert f"mtllib {name}.mtl" in head
    assert not (tmp_path / "material.mtl").exists()


def _read_only_dir(tmp_path, monkeypatch):
    """A folder this process may not write into. As root the permission bits do not bind, so
    ``os.access`` is made to answer as it would for an ordinary user (the bits say no)."""
    import os

    folder = tmp_path / "ro"
    folder.mkdir()
    folder.chmod(0o555)
    if os.geteuid() == 0:
        real = os.access
        monkeypatch.setattr(
            os, "access", lambda p, mode: False if str(p) == str(folder) else real(p, mode)
        )
    return folder


@pytest.mark.parametrize("writer", ["save", "save_mesh", "to_svg", "to_dxf"])
def test_bad_paths_are_refused_before_any_work(tmp_path, monkeypatch, writer):
    # issue 17 item 4: each writer checks its path first (gears.files.check_output): the error
    # names the path and what is valid, and comes before the objects are looked at (an invalid
    # object is passed, so any work would fail differently)
    import os

    from gears.solid import export

    fn = getattr(export, writer)
    ext = {"save": ".svg", "save_mesh": ".stl", "to_svg": ".svg", "to_dxf": ".dxf"}[writer]
    read_only = _read_only_dir(tmp_path, monkeypatch)
    cases = [
        (tmp_path / "missing" / f"g{ext}", "does not exist"),
        (None, "give a file name"),
        (3.5, "give a file name"),
        (shapely.box(0, 0, 1, 1), "give a file name"),
        (read_only / f"g{ext}", "not writable"),
        (tmp_path / "g.xyz", "not a format written here; valid are"),
        (tmp_path, "is a directory"),
        ("", "give a file name"),
    ]
    for path, why in cases:
        with pytest.raises(GearError, match=why) as info:
            fn(path, "not an outline")
        message, named = (
            str(info.value),
            str(path) if isinstance(path, str | os.PathLike) else repr(path),
        )
        assert message.startswith("path ") and named[:20] in message and ext in message, message
    assert list(read_only.iterdir()) == []


def test_a_failed_write_is_a_gear_error(tmp_path, monkeypatch):
    # a write that fails after the check (a full disk, a read-only mount) names the path
    import pathlib

    def full(self, *args, **kwargs):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(pathlib.Path, "write_text", full)
    with pytest.raises(GearError, match=r"g\.svg' could not be written: No space left"):
        save(tmp_path / "g.svg", Gear(12, 1).outline(0.01))


def test_tooth_figure_texts_do_not_overlap():
    # issue 16: the circle labels of an undercut pinion (form d_Ff = 7.614 mm and base
    # d_b = 7.518 mm, 0.05 mm apart in radius) were drawn on top of each other; every text of
    # the figure (title, legend, ticks) now has its own place inside the figure
    from gears.figures.plot import tooth_figure

    fig = tooth_figure(Gear(8, 1))
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    (ax,) = fig.axes
    (x0, x1), (y0, y1) = sorted(ax.get_xlim()), sorted(ax.get_ylim())
    ticks = [t for t in ax.get_xticklabels() if x0 <= t.get_position()[0] <= x1]
    ticks += [t for t in ax.get_yticklabels() if y0 <= t.get_position()[1] <= y1]
    texts = [ax.title, ax.xaxis.label, *ax.get_legend().get_texts(), *ticks]
    texts = [t for t in texts if t.get_text()]
    labels = [t.get_text() for t in texts]
    assert "form circle d_Ff = 7.614 mm" in labels and "base circle d_b = 7.518 mm" in labels
    boxes = [t.get_window_extent(renderer) for t in texts]
    for i, a in enumerate(boxes):
        assert fig.bbox.contains(a.x0, a.y0) and fig.bbox.contains(a.x1, a.y1), labels[i]
        for j in range(i):
            assert not a.overlaps(boxes[j]), (labels[i], labels[j])
    import matplotlib.pyplot as plt

    plt.close(fig)


def test_an_animation_title_is_never_clipped(tmp_path):
    # issue 16: the planetary GIFs' titles ran off both sides. The first frame's left and right
    # edge columns hold no ink in the title band (the top eighth of the picture)
    from PIL import Image

    from gears.solid.animate import write_animation

    title = "Planetary(sun=26, planet=(70, 21), ring=117, n_planets=3, module=1, scheme='stepped')"
    frames = [[(shapely.box(-1, -1, 1, 1), "tab:blue")]]
    path = write_animation(tmp_path / "a.gif", frames, fps=5, title=title)
    pixels = np.asarray(Image.open(path).convert("L"), dtype=float)
    band = pixels[: pixels.shape[0] // 8]
    assert band[:, :3].min() > 200 and band[:, -3:].min() > 200  # white margins
    assert band.min() < 100  # and the title is there
