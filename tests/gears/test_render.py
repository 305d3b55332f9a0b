"""3D pictures and animations (gears.solid.render), the frames of docs/bevel.md and the
differential.

Checks are on the files themselves: their format signature, the frame count Pillow reads back,
and that a picture shows the object (non-background pixels where the part projects); bad input
is refused before any work, naming the value.
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("matplotlib")
trimesh = pytest.importorskip("trimesh")

from gears import BevelPair, GearError  # noqa: E402
from gears.solid.render import Camera, render_image, scene_parts, write_animation_3d  # noqa: E402


def _box():
    b = trimesh.creation.box()
    return b.vertices, b.faces, (0.2, 0.4, 0.8)


def test_picture_of_a_scene(tmp_path):
    from PIL import Image

    sc = BevelPair(20, 40, module=3, face_width=20).scene(tolerance=0.1)
    parts = scene_parts(sc)
    assert len(parts) == 2 and all(len(v) > 100 for v, _, _ in parts)
    f = render_image(tmp_path / "pair.png", parts, Camera(30, -40), size=180)
    img = np.asarray(Image.open(f).convert("RGB"), float)
    assert img.shape[:2] == (180, 180)
    # both gears' colours appear (blue and orange, shaded)
    blue = (img[..., 2] > img[..., 0] + 30).mean()
    orange = (img[..., 0] > img[..., 2] + 30).mean()
    assert blue > 0.02 and orange > 0.02


def test_back_faces_are_culled_and_painted_far_to_near():
    polys, _ = Camera(0.0, 0.0).project([_box()])  # looking from +x: only the +x face
    assert len(polys) == 2
    polys, colours = Camera(30.0, 30.0).project([_box()])
    assert len(polys) == 6  # three faces seen obliquely, the three turned away culled
    assert np.all(colours <= 1.0)
    # a small box in front of a large one is painted last
    v, f, c = _box()
    near = (v * 0.2 + [2.0, 0.0, 0.0], f, (1.0, 0.0, 0.0))
    polys, colours = Camera(0.0, 0.0).project([near, (v * 3.0, f, c)])
    assert tuple(colours[-1] / colours[-1].max()) == pytest.approx((1.0, 0.0, 0.0))


def test_animation_writes_every_frame(tmp_path):
    from PIL import Image

    def frame(i):
        v, f, c = _box()
        return [(v + np.array([i * 0.1, 0.0, 0.0]), f, c)]

    out = write_animation_3d(tmp_path / "a.gif", frame, 4, fps=5, size=80)
    with Image.open(out) as im:
        assert im.format == "GIF" and im.n_frames == 4


def test_pair_animation(tmp_path):
    from PIL import Image

    p = BevelPair(12, 18, module=2, face_width=6)
    out = p.animate(tmp_path / "pair.gif", frames=3, tolerance=0.2)
    with Image.open(out) as im:
        assert im.n_frames == 3


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"n_frames": 0}, "frames"),
        ({"n_frames": 10**6}, "frames"),
        ({"fps": 0}, "fps"),
        ({"fps": "x"}, "fps"),
        ({"path": "a.txt"}, "a.txt"),
    ],
)
def test_animation_bad_input(tmp_path, kwargs, match):
    args = {"path": tmp_path / "a.gif", "frames": lambda i: [_box()], "n_frames": 2, **kwargs}
    if not str(args["path"]).startswith(str(tmp_path)):
        args["path"] = tmp_path / args["path"]
    with pytest.raises(GearError, match=match):
        write_animation_3d(**args)


def test_bad_camera_and_empty_picture(tmp_path):
    with pytest.raises(GearError, match="elevation"):
        Camera(float("nan"))
    with pytest.raises(GearError, match="nothing to draw"):
        render_image(tmp_path / "e.png", [])
    with pytest.raises(GearError, match=r"20 frames of 3000000 triangles .* exceed the budget"):
        big = [(np.zeros((3, 3)), np.zeros((3_000_000, 3), int), (1, 0, 0))]
        write_animation_3d(tmp_path / "b.gif", lambda i: big, 20)
