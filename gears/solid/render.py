"""Layer 8, frames: 3D scenes drawn as pictures and animations (Pillow, the ``plot`` extra).

A plain software renderer for the figures and GIFs of bevel gears and differentials, whose teeth
do not lie in one plane: an orthographic camera given by its elevation and azimuth (degrees, as
matplotlib's ``view_init``), back faces culled, flat shading by one directional light, and the
painter's algorithm (faces drawn far to near) with Pillow's polygon fill at twice the size,
filtered down (matplotlib's PolyCollection took ten times longer a frame). A *part* is
``(vertices, faces, colour)`` in world coordinates; a frame is a list of parts. PNG and GIF
through Pillow, MP4 through ffmpeg (matplotlib's writer).
"""

from __future__ import annotations

import math
import pathlib
from collections.abc import Callable, Sequence

import numpy as np

from gears.arguments import check_fps, check_frames
from gears.errors import GearError
from gears.files import check_output, writing

__all__ = [
    "ANIMATION_BUDGET_3D",
    "DRAWN_PER_VERTEX",
    "MAX_FACES",
    "Camera",
    "render_image",
    "scene_parts",
    "write_animation_3d",
]

#: Most triangles one animation draws in all (frames x faces): about a minute of matplotlib.
MAX_FACES = 40_000_000


#: Triangle vertices a 3D animation draws per vertex of its solids and frame (about half the
#: faces face the camera, two faces a vertex, three vertices a face: measured 2.9 on the pairs).
DRAWN_PER_VERTEX = 3.0
#: The work budget of a 3D animation, in triangle vertices drawn over all frames: Pillow fills
#: about 3 us a vertex on one free core (10 us under a load of 6), so 15 to 50 s at most.
ANIMATION_BUDGET_3D = 5_000_000


class Camera:
    """An orthographic camera looking at the origin from ``elevation`` and ``azimuth`` degrees
    (matplotlib's convention), lit from ``light`` (a direction in camera terms: right, up,
    towards the viewer)."""

    def __init__(self, elevation: float = 25.0, azimuth: float = -60.0, light=(-0.4, 0.6, 1.0)):
        for name, v in (("elevation", elevation), ("azimuth", azimuth)):
            if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v):
                raise GearError(f"{name} = {v!r}; valid is a finite angle in degrees")
        e, a = math.radians(elevation), math.radians(azimuth)
        self.toward = np.array([math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e)])
        up = np.array([0.0, 0.0, 1.0])
        right = np.cross(up, self.toward)
        if np.linalg.norm(right) < 1e-9:  # looking straight down or up
            right = np.array([-math.sin(a), math.cos(a), 0.0])
        self.right = right / np.linalg.norm(right)
        self.up = np.cross(self.toward, self.right)
        light = np.asarray(light, float)
        light = light[0] * self.right + light[1] * self.up + light[2] * self.toward
        self.light = light / np.linalg.norm(light)

    def project(self, parts):
        """Screen polygons, their colours and depth order of every visible face of ``parts``."""
        polys, colours, depth = [], [], []
        for vertices, faces, colour in parts:
            v = np.asarray(vertices, float)
            f = np.asarray(faces, np.int64)
            tri = v[f]
            n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
            length = np.linalg.norm(n, axis=1)
            keep = length > 0
            n = n[keep] / length[keep, None]
            tri = tri[keep]
            facing = n @ self.toward > 0.0
            tri, n = tri[facing], n[facing]
            shade = 0.35 + 0.65 * np.clip(n @ self.light, 0.0, 1.0)
            rgb = np.asarray(_rgb(colour))[None, :] * shade[:, None]
            xy = np.stack([tri @ self.right, tri @ self.up], axis=-1)
            polys.append(xy)
            colours.append(np.clip(rgb, 0.0, 1.0))
            depth.append((tri @ self.toward).mean(axis=1))
        if not polys:
            raise GearError("nothing to draw: give at least one part (vertices, faces, colour)")
        polys, colours, depth = (np.concatenate(x) for x in (polys, colours, depth))
        order = np.argsort(depth)  # far (small toward-component) first
        return polys[order], colours[order]


def _rgb(colour) -> tuple[float, float, float]:
    c = [float(v) for v in colour][:3]
    if len(c) != 3:
        raise GearError(f"colour = {colour!r} must be RGB or RGBA (0-1 or 0-255)")
    if max(c) > 1.0:
        c = [v / 255.0 for v in c]
    return c[0], c[1], c[2]


def _pil():
    try:
        from PIL import Image, ImageDraw
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise GearError("pictures need Pillow: pip install 'geartrain[plot]'") from exc
    return Image, ImageDraw


def _raster(polys, colours, box, size: int, supersample: int = 2):
    """The faces painted far to near into a white square image of ``size`` pixels (drawn at
    ``supersample`` times the size and filtered down, so edges are smooth); ``box`` is the
    drawing's extent (x0, y0, x1, y1) in world units."""
    image, draw_mod = _pil()
    big = size * supersample
    x0, y0, x1, y1 = box
    span = max(x1 - x0, y1 - y0, 1e-12)
    scale = (big - 1) / span
    cx, cy = (x0 + x1) / 2.0, (y0 + y1) / 2.0
    px = (polys[..., 0] - cx) * scale + big / 2.0
    py = big / 2.0 - (polys[..., 1] - cy) * scale
    flat = np.stack([px, py], axis=-1).reshape(len(polys), -1).tolist()
    fill = [tuple(c) for c in np.round(np.asarray(colours) * 255).astype(int).tolist()]
    img = image.new("RGB", (big, big), (255, 255, 255))
    draw = draw_mod.Draw(img)
    for xy, c in zip(flat, fill, strict=True):
        draw.polygon(xy, fill=c, outline=c)  # the outline closes the seams between faces
    return img.resize((size, size), image.LANCZOS) if supersample > 1 else img


def _box(polys) -> tuple[float, float, float, float]:
    lo = polys.reshape(-1, 2).min(axis=0)
    hi = polys.reshape(-1, 2).max(axis=0)
    pad = 0.04 * float(max(hi - lo))
    return float(lo[0] - pad), float(lo[1] - pad), float(hi[0] + pad), float(hi[1] + pad)


def _pixels(size) -> int:
    if isinstance(size, bool) or not isinstance(size, int | np.integer) or not 16 <= size <= 4096:
        raise GearError(f"size = {size!r}; valid is a whole number of pixels 16 ... 4096")
    return int(size)


def render_image(path, parts, camera: Camera | None = None, size: int = 500) -> pathlib.Path:
    """Draw ``parts`` (``(vertices, faces, colour)``) into a square PNG of ``size`` pixels."""
    path = check_output(path, (".png",))
    size = _pixels(size)
    camera = camera or Camera()
    polys, colours = camera.project(parts)
    img = _raster(polys, colours, _box(polys), size)
    with writing(path):
        img.save(path)
    return path


def write_animation_3d(
    path, frames: Callable[[int], Sequence], n_frames: int, camera: Camera | None = None,
    fps: float = 20.0, size: int = 400, progress: Callable[[int, int], None] | None = None,
) -> pathlib.Path:  # fmt: skip
    """Write an animation of 3D parts, ``frames(i)`` giving frame i's parts, as a GIF (Pillow) or
    an MP4 (ffmpeg through matplotlib). The view is fixed by the first frame; ``progress(i, n)``
    after each frame. The work is bounded by the callers (:data:`MAX_FACES` as a last guard).

    Raises
    ------
    GearError
        For a bad path, frame count, fps or size, or frames times triangles above
        :data:`MAX_FACES` (the message names the size).
    """
    path = check_output(path, (".gif", ".mp4"))
    n = check_frames(n_frames, "frames")
    fps = check_fps(fps)
    size = _pixels(size)
    camera = camera or Camera()
    first = list(frames(0))
    faces = sum(len(f) for _, f, _ in first)
    if faces * n > MAX_FACES:
        raise GearError(
            f"{n} frames of {faces} triangles ({faces * n:.3g}) exceed the budget of "
            f"{MAX_FACES:.3g}; use fewer frames or a coarser tolerance"
        )
    polys, colours = camera.project(first)
    box = _box(polys)
    images = []
    for i in range(n):
        if i:
            polys, colours = camera.project(list(frames(i)))
        images.append(_raster(polys, colours, box, size))
        if progress is not None:
            progress(i + 1, n)
    with writing(path):
        if path.suffix.lower() == ".gif":
            images[0].save(path, save_all=True, append_images=images[1:],
                           duration=max(round(1000.0 / fps), 10), loop=0)  # fmt: skip
        else:
            _mp4(path, images, fps)
    return path


def _mp4(path, images, fps: float) -> None:
    try:
        import matplotlib

        matplotlib.use("Agg", force=False)
        import matplotlib.pyplot as plt
        from matplotlib import animation
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise GearError("MP4 needs matplotlib: pip install 'geartrain[plot]'") from exc
    if not animation.writers.is_available("ffmpeg"):
        raise GearError("MP4 needs ffmpeg on the PATH; install it or write a .gif")
    px = images[0].size[0]
    fig = plt.figure(figsize=(px / 100, px / 100), dpi=100)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_axis_off()
    shown = ax.imshow(np.asarray(images[0]))
    writer = animation.FFMpegWriter(fps=fps)
    try:
        with writer.saving(fig, str(path), 100):
            for img in images:
                shown.set_data(np.asarray(img))
                writer.grab_frame()
    finally:
        plt.close(fig)


def scene_parts(scene) -> list[tuple]:
    """The parts of a ``trimesh.Scene``: each node's vertices placed by its transform, its faces
    and its material's base colour (grey without one)."""
    parts = []
    for node in scene.graph.nodes_geometry:
        matrix, geom = scene.graph[node]
        mesh = scene.geometry[geom]
        v = mesh.vertices @ matrix[:3, :3].T + matrix[:3, 3]
        colour = (180, 180, 180)
        material = getattr(getattr(mesh, "visual", None), "material", None)
        base = getattr(material, "baseColorFactor", None)
        if base is not None:
            colour = tuple(base[:3])
        parts.append((v, mesh.faces, colour))
    return parts
