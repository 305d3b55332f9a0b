"""Layer 8, frames: 3D scenes drawn as pictures and animations (matplotlib, the ``plot`` extra).

A plain software renderer for the figures and GIFs of bevel gears and differentials, whose teeth
do not lie in one plane: an orthographic camera given by its elevation and azimuth (degrees, as
matplotlib's ``view_init``), back faces culled, flat shading by one directional light, and the
painter's algorithm (faces drawn far to near) into a matplotlib ``PolyCollection``. A *part* is
``(vertices, faces, colour)`` in world coordinates; a frame is a list of parts. PNG (and SVG,
PDF) through ``savefig``; GIF through Pillow and MP4 through ffmpeg, as
:func:`gears.animate.write_animation` writes the 2D animations.
"""

from __future__ import annotations

import math
import pathlib
from collections.abc import Callable, Sequence

import numpy as np

from gears.animate import check_frames
from gears.errors import GearError
from gears.files import check_output, writing

__all__ = ["MAX_FACES", "Camera", "render_image", "scene_parts", "write_animation_3d"]

#: Most triangles one animation draws in all (frames x faces): about a minute of matplotlib.
MAX_FACES = 40_000_000


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


def _figure(size: float):
    try:
        import matplotlib

        matplotlib.use("Agg", force=False)
        import matplotlib.pyplot as plt
        from matplotlib.collections import PolyCollection
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise GearError("pictures need matplotlib: pip install 'geartrain[plot]'") from exc
    fig, ax = plt.subplots(figsize=(size, size))
    ax.set_aspect("equal")
    ax.set_axis_off()
    fig.subplots_adjust(0, 0, 1, 1)
    return plt, fig, ax, PolyCollection


def _limits(ax, polys) -> None:
    lo = polys.reshape(-1, 2).min(axis=0)
    hi = polys.reshape(-1, 2).max(axis=0)
    pad = 0.04 * float(max(hi - lo))
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)


def render_image(path, parts, camera: Camera | None = None, size: float = 5.0,
                 dpi: int = 100) -> pathlib.Path:  # fmt: skip
    """Draw ``parts`` (``(vertices, faces, colour)``) into a picture (.png, .svg, .pdf)."""
    path = check_output(path, (".png", ".svg", ".pdf"))
    camera = camera or Camera()
    polys, colours = camera.project(parts)
    plt, fig, ax, PolyCollection = _figure(size)
    try:
        ax.add_collection(PolyCollection(polys, facecolors=colours, edgecolors=colours, lw=0.2))
        _limits(ax, polys)
        with writing(path):
            fig.savefig(path, dpi=dpi)
    finally:
        plt.close(fig)
    return path


def write_animation_3d(
    path, frames: Callable[[int], Sequence], n_frames: int, camera: Camera | None = None,
    fps: float = 20.0, size: float = 5.0, dpi: int = 80,
    progress: Callable[[int, int], None] | None = None,
) -> pathlib.Path:  # fmt: skip
    """Write an animation of 3D parts, ``frames(i)`` giving frame i's parts: ``.gif``
    (Pillow) or ``.mp4`` (ffmpeg). The view is fixed by the first frame; ``progress(i, n)``
    after each frame.

    Raises
    ------
    GearError
        For a bad path, frame count or fps, or a request above :data:`MAX_FACES` (frames times
        triangles; the message names the size).
    """
    path = check_output(path, (".gif", ".mp4"))
    n = check_frames(n_frames, "frames")
    fps_ = float(fps) if not isinstance(fps, bool) and isinstance(fps, int | float) else math.nan
    if not (math.isfinite(fps_) and fps_ > 0):
        raise GearError(f"fps = {fps!r}; valid is a finite number > 0")
    camera = camera or Camera()
    first = list(frames(0))
    faces = sum(len(f) for _, f, _ in first)
    if faces * n > MAX_FACES:
        raise GearError(
            f"{n} frames of {faces} triangles ({faces * n:.3g}) exceed the budget of "
            f"{MAX_FACES:.3g}; use fewer frames or a coarser tolerance"
        )
    plt, fig, ax, PolyCollection = _figure(size)
    from matplotlib import animation

    if path.suffix.lower() == ".mp4":
        if not animation.writers.is_available("ffmpeg"):
            plt.close(fig)
            raise GearError("MP4 needs ffmpeg on the PATH; install it or write a .gif")
        writer = animation.FFMpegWriter(fps=fps_)
    else:
        writer = animation.PillowWriter(fps=fps_)
    try:
        polys, colours = camera.project(first)
        _limits(ax, polys)
        with writing(path), writer.saving(fig, str(path), dpi):
            for i in range(n):
                if i:
                    polys, colours = camera.project(list(frames(i)))
                coll = PolyCollection(polys, facecolors=colours, edgecolors=colours, lw=0.2)
                ax.add_collection(coll)
                writer.grab_frame()
                coll.remove()
                if progress is not None:
                    progress(i + 1, n)
    finally:
        plt.close(fig)
    return path


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
