"""Animations of outlines in mesh (issue 10): gears.solid.animate.write_animation, GearPair.animate,
Planetary.animate and the frames they draw (Planetary.outlines over one mesh cycle).

Sources: the Willis relation (w_a - w_H) z_a = -(w_b - w_H) z_b for each mesh, so relative to the
carrier every mesh advances one tooth pitch per mesh cycle (derivation); phasing from
Planetary.placement() (tests/trains/test_planetary.py); zero-backlash outlines touch without
overlap up to their chords (tests/gears/test_profile.py).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
import shapely
from shapely import affinity

pytest.importorskip("matplotlib")
from PIL import Image

from gears import Gear, GearError, GearPair
from gears.solid.animate import write_animation
from trains import Planetary, TrainError


def test_write_animation_gif_frames(tmp_path):
    sq = shapely.box(-1, -1, 1, 1)
    calls = []
    path = write_animation(
        tmp_path / "a.gif", lambda i: [(affinity.rotate(sq, 15 * i), "tab:blue")], fps=10,
        n_frames=4, progress=lambda i, n: calls.append((i, n)),
    )  # fmt: skip
    with Image.open(path) as im:
        assert im.format == "GIF" and im.n_frames == 4
    assert calls == [(1, 4), (2, 4), (3, 4), (4, 4)]


def test_write_animation_errors(tmp_path):
    frame = [(shapely.box(0, 0, 1, 1), "k")]
    with pytest.raises(GearError, match="format"):
        write_animation(tmp_path / "a.avi", [frame])
    with pytest.raises(GearError, match="fps"):
        write_animation(tmp_path / "a.gif", [frame], fps=0)
    with pytest.raises(GearError, match="n_frames"):
        write_animation(tmp_path / "a.gif", lambda i: frame)
    with pytest.raises(GearError, match="at least one"):
        write_animation(tmp_path / "a.gif", [])
    with pytest.raises(GearError, match="Polygon"):
        write_animation(tmp_path / "a.gif", [[("no", "k")]])


def test_mp4_needs_ffmpeg(tmp_path):
    from matplotlib import animation

    frame = [(shapely.box(0, 0, 1, 1), "k")]
    if animation.writers.is_available("ffmpeg"):
        assert write_animation(tmp_path / "a.mp4", [frame, frame]).stat().st_size > 0
    else:
        with pytest.raises(GearError, match="ffmpeg"):
            write_animation(tmp_path / "a.mp4", [frame])


def test_pair_animation(tmp_path):
    pair = GearPair(Gear(12, 2), Gear(20, 2))
    path = pair.animate(tmp_path / "p.gif", frames=3, tolerance=0.05)
    with Image.open(path) as im:
        assert im.n_frames == 3
    with pytest.raises(GearError, match="frames"):
        pair.animate(tmp_path / "p.gif", frames=0)


def _max_overlap(shapes: dict) -> float:
    """Largest area shared by two different gears of a frame."""
    return max(a.intersection(b).area for a, b in itertools.combinations(shapes.values(), 2))


@pytest.mark.parametrize("teeth", [(18, 45, 108), (19, 29, 77)])
def test_no_frame_of_a_mesh_cycle_overlaps(teeth):
    p = Planetary(*teeth, n_planets=3, module=1)
    tol = 0.02
    cycle = p.mesh_cycle()
    # the sun advances one tooth relative to the carrier per cycle (Willis, ring fixed)
    w = float(p.ratio())  # sun speed per unit carrier speed
    assert cycle == pytest.approx(360.0 / (teeth[0] * abs(w - 1)))
    cache_frames = [p.outlines(a, tol) for a in np.linspace(0.0, cycle, 9)]
    # chords of the concave ring flanks stand up to tol into the spaces: area < tol x depth
    bound = tol * 2.25 * p.module
    for shapes in cache_frames:
        assert _max_overlap(shapes) < bound
    # the picture repeats after one mesh cycle, seen from the carrier
    first, last = cache_frames[0], cache_frames[-1]
    for name in first:
        back = affinity.rotate(last[name], -cycle, origin=(0, 0))
        assert shapely.hausdorff_distance(back, first[name]) < 10 * tol, name


def test_same_phase_frames_overlap():
    # 19/29/77 x 3 is 'sequential': every planet a copy of planet 1 turned about the axis
    # collides with the sun or the ring (the same fact as the 3D test, in 2D)
    p = Planetary(19, 29, 77, n_planets=3, module=1)
    shapes = p.outlines(0.0, 0.02)
    for k, phi in ((2, 120.0), (3, 240.0)):
        copy = affinity.rotate(shapes["planet1"], phi, origin=(0, 0))
        worst = max(copy.intersection(shapes["sun"]).area, copy.intersection(shapes["ring"]).area)
        assert worst > 0.1, k


def test_planetary_animation(tmp_path):
    p = Planetary(18, 45, 108, n_planets=3, module=1)
    seen = []
    path = p.animate(
        tmp_path / "s.gif", frames=3, tolerance=0.1, progress=lambda i, n: seen.append(i)
    )
    with Image.open(path) as im:
        assert im.n_frames == 3
    assert seen == [1, 2, 3]
    with pytest.raises(TrainError, match="frames"):
        p.animate(tmp_path / "s.gif", frames=0)
    with pytest.raises(TrainError, match="format"):
        p.animate(tmp_path / "s.avi", frames=2)
    with pytest.raises(TrainError, match="fixed"):
        p.outlines(0.0, 0.1, fixed="planet")
    assert math.isfinite(p.mesh_cycle("carrier"))
