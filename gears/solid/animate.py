"""Layer 7, solids and frames.

One frame writer for animations of 2D outlines in mesh (GIF with Pillow, MP4 with ffmpeg).

It knows nothing of gears or trains: each frame is a list of ``(polygon, colour)`` pairs, given
as a sequence of frames or as a callable ``frame(i)``. ``GearPair.animate`` and
``Planetary.animate`` build the frames (placement, Willis speeds) and call
:func:`write_animation`. Needs matplotlib (the ``plot`` extra), which brings Pillow.
"""

from __future__ import annotations

import pathlib
import textwrap
from collections.abc import Callable, Sequence

import numpy as np
import shapely

from gears.arguments import (
    MAX_FRAMES,
    check_callback,
    check_fps,
    check_frames,
    check_integer,
    check_positive,
)
from gears.errors import GearError
from gears.files import check_output

__all__ = ["MAX_FRAMES", "check_frames", "polygon_path", "write_animation"]

#: The animation formats and their writers.
FORMATS = (".gif", ".mp4")

Frame = Sequence[tuple]


def polygon_path(polygon):
    """A matplotlib ``Path`` of a shapely (Multi)Polygon, holes included (even-odd)."""
    from matplotlib.path import Path

    polys = polygon.geoms if isinstance(polygon, shapely.MultiPolygon) else [polygon]
    verts, codes = [], []
    for p in polys:
        if not isinstance(p, shapely.Polygon):
            raise GearError(f"frames hold shapely Polygons; got {type(p).__name__}")
        for ring in (p.exterior, *p.interiors):
            xy = np.asarray(ring.coords)[:, :2]
            if len(xy) < 4:
                continue
            c = np.full(len(xy), Path.LINETO, dtype=np.uint8)
            c[0], c[-1] = Path.MOVETO, Path.CLOSEPOLY
            verts.append(xy)
            codes.append(c)
    if not verts:
        return Path(np.zeros((1, 2)), [Path.MOVETO])
    return Path(np.concatenate(verts), np.concatenate(codes))


def write_animation(
    path, frames: Sequence[Frame] | Callable[[int], Frame], fps: float = 20.0,
    n_frames: int | None = None, size: float = 5.0, dpi: int = 80, title: str | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> pathlib.Path:  # fmt: skip
    """Write an animation of filled outlines: ``.gif`` (Pillow) or ``.mp4`` (ffmpeg).

    Parameters
    ----------
    path : str or pathlib.Path
        Output file; the extension picks the writer.
    frames : sequence of frames, or callable
        A frame is a list of ``(polygon, colour)`` pairs (shapely Polygons, matplotlib
        colours). A callable is called as ``frames(i)`` for ``i in range(n_frames)``.
    fps : float
        Frames per second, > 0.
    n_frames : int, optional
        Number of frames when ``frames`` is a callable (required then).
    size, dpi : float, int
        Figure size in inches (square) and resolution.
    title : str, optional
    progress : callable, optional
        Called as ``progress(i, n)`` after each frame is drawn.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    GearError
        Before any frame is drawn: for an unknown extension or a folder that does not exist
        or is not writable, ``fps`` outside 0.01 ... 1000, no frames, a missing ``n_frames``,
        an MP4 without ffmpeg, or matplotlib missing.

    Examples
    --------
    >>> import os, tempfile
    >>> sq = shapely.box(-1, -1, 1, 1)
    >>> frames = [[(shapely.affinity.rotate(sq, 10 * i), "tab:blue")] for i in range(3)]
    >>> f = write_animation(os.path.join(tempfile.mkdtemp(), "a.gif"), frames, fps=5)
    >>> f.read_bytes()[:6]
    b'GIF89a'
    """
    path = check_output(path, FORMATS)
    ext = path.suffix.lower()
    fps = check_fps(fps)
    size = check_positive("size", size, "inches")
    if not 0.1 <= size <= 100:
        raise GearError(f"size = {size!r} inches; valid is 0.1 ... 100")
    dpi = check_integer("dpi", dpi, 10, 1000)
    check_callback("progress", progress)
    if callable(frames):
        if n_frames is None:
            raise GearError("n_frames = None: a callable of frames needs n_frames >= 1")
        n = check_frames(n_frames, "n_frames")
        get = frames
    else:
        seq = list(frames)
        n = len(seq)
        get = seq.__getitem__
    if n < 1:
        raise GearError("an animation needs at least one frame")
    check_frames(n)
    try:
        import matplotlib

        matplotlib.use("Agg", force=False)
        import matplotlib.pyplot as plt
        from matplotlib import animation
        from matplotlib.patches import PathPatch
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise GearError("animations need matplotlib: pip install 'geartrain[plot]'") from exc
    if ext == ".mp4":
        if not animation.writers.is_available("ffmpeg"):
            raise GearError("MP4 needs ffmpeg on the PATH; install it or write a .gif")
        writer = animation.FFMpegWriter(fps=fps)
    else:
        writer = animation.PillowWriter(fps=fps)
    first = list(get(0))
    for item in first:
        if len(item) != 2 or not isinstance(item[0], shapely.Polygon | shapely.MultiPolygon):
            raise GearError(f"a frame holds (shapely Polygon, colour) pairs; got {item!r:.60}")
    if not first:
        raise GearError("the first frame is empty: give at least one (polygon, colour) pair")
    x0, y0, x1, y1 = shapely.total_bounds([p for p, _ in first])
    pad = 0.04 * max(x1 - x0, y1 - y0, 1e-9)
    fig, ax = plt.subplots(figsize=(size, size))
    try:
        ax.set_aspect("equal")
        ax.set_xlim(x0 - pad, x1 + pad)
        ax.set_ylim(y0 - pad, y1 + pad)
        ax.set_axis_off()
        if title:  # wrapped to the figure's width (10 pt: about 6 pt a character): never clipped
            ax.set_title(textwrap.fill(title, max(20, int(size * 72 / 6))), fontsize=10)
        fig.tight_layout()
        with writer.saving(fig, str(path), dpi):
            for i in range(n):
                items = first if i == 0 else list(get(i))
                # add_artist, not add_patch: the limits are fixed above, and add_patch would
                # walk every Bezier segment of every outline to update data limits nobody reads
                # (three quarters of the animation's time)
                patches = [
                    ax.add_artist(PathPatch(polygon_path(p), facecolor=c, edgecolor="k", lw=0.4))
                    for p, c in items
                ]
                writer.grab_frame()
                for patch in patches:
                    patch.remove()
                if progress is not None:
                    progress(i + 1, n)
    finally:
        plt.close(fig)
    return path
