"""Layer 1, output files: the one check of a path that a writer is about to write.

Every writer of the library (:func:`gears.solid.export.save` and its format writers, the animation
writer) and every output option of the ``geartrain`` CLI calls :func:`check_output` before any
work, so a bad path is one clear :class:`~gears.errors.GearError` naming the path and what is
valid, never a ``FileNotFoundError`` after a long computation. :func:`writing` turns what can
still go wrong during the write itself (a full disk, a read-only mount) into the same error.
:func:`pyplot` is the one import of matplotlib that every figure makes (headless, or a clear
error naming the extra that installs it).
"""

from __future__ import annotations

import contextlib
import errno
import os
import pathlib
from collections.abc import Iterable, Iterator
from types import ModuleType

from gears.errors import GearError

__all__ = ["check_output", "pyplot", "writing"]


def check_output(path, formats: Iterable[str], name: str = "path") -> pathlib.Path:
    """``path`` as a :class:`pathlib.Path` when a file of one of ``formats`` (suffixes such as
    ``".svg"``, compared without case) can be written there; a GearError otherwise.

    Refused, each with a message that starts with ``name`` and the path and says what is
    valid: anything but a ``str`` or ``os.PathLike`` (``None``, a number, a polygon), an empty
    name, a suffix not in ``formats``, an existing directory, a directory that does not exist,
    and a directory or existing file this process may not write.

    Examples
    --------
    >>> check_output("stage.glb", (".glb", ".stl")).name
    'stage.glb'
    >>> check_output("g.gif", (".glb",))
    Traceback (most recent call last):
    ...
    gears.errors.GearError: path 'g.gif': '.gif' is not a format written here; valid are .glb
    >>> check_output(None, (".svg",))
    Traceback (most recent call last):
    ...
    gears.errors.GearError: path None: give a file name (a str or os.PathLike ending in .svg)
    """
    formats = tuple(formats)
    valid = ", ".join(formats)
    if isinstance(path, bytes) or not isinstance(path, str | os.PathLike):
        raise GearError(
            f"{name} {path!r:.60}: give a file name (a str or os.PathLike ending in {valid})"
        )
    text = os.fspath(path)
    if not isinstance(text, str) or not text.strip():
        raise GearError(f"{name} {text!r}: give a file name ending in {valid}")
    out = pathlib.Path(text)
    try:
        return _check_path(out, text, name, formats, valid)
    except OSError as exc:  # a name the file system refuses (too long, a loop of links)
        why = _WHY.get(exc.errno, exc.strerror or str(exc)).format(parent=str(out.parent))
        raise GearError(f"{name} {text!r:.80} cannot be written: {why}") from None


def _check_path(out: pathlib.Path, text: str, name: str, formats, valid: str) -> pathlib.Path:
    if out.is_dir():
        raise GearError(f"{name} {text!r} is a directory; give a file name ending in {valid}")
    if out.suffix.lower() not in formats:
        raise GearError(
            f"{name} {text!r}: {out.suffix or 'no suffix'!r} is not a format written here; "
            f"valid are {valid}"
        )
    parent = out.parent if str(out.parent) else pathlib.Path(".")
    if not parent.is_dir():
        raise GearError(f"{name} {text!r}: the directory {str(parent)!r} does not exist")
    if not os.access(parent, os.W_OK | os.X_OK) or (out.exists() and not os.access(out, os.W_OK)):
        where = f"the file {text!r}" if out.exists() else f"the directory {str(parent)!r}"
        raise GearError(f"{name} {text!r} is not writable: {where} is read-only for this user")
    _try_open(out, text, name, parent)
    return out


#: why a file cannot be created, in a user's words, by errno
_WHY = {
    errno.ENOENT: "the directory {parent!r} does not accept new files (a virtual file system "
    "such as /proc)",
    errno.EROFS: "the directory {parent!r} is on a read-only file system",
    errno.EACCES: "the directory {parent!r} or the file is read-only for this user",
    errno.EPERM: "the directory {parent!r} or the file is read-only for this user",
    errno.ENOSPC: "the disk is full",
    errno.ENAMETOOLONG: "the file name is longer than the file system allows",
}


def _try_open(out: pathlib.Path, text: str, name: str, parent: pathlib.Path) -> None:
    """Open ``out`` for writing the way the writer will (a new file is created and removed at
    once; an existing one is opened to append, unchanged): the permission bits do not say what
    a read-only mount, /proc or a root process may do, the attempt does."""
    existed = out.exists()
    try:
        fd = os.open(out, os.O_WRONLY | (os.O_APPEND if existed else os.O_CREAT | os.O_EXCL))
    except FileExistsError:  # created meanwhile by someone else: the writer will replace it
        return
    except OSError as exc:
        why = _WHY.get(exc.errno, exc.strerror or str(exc)).format(parent=str(parent))
        raise GearError(f"{name} {text!r} cannot be written: {why}") from None
    os.close(fd)
    if not existed:
        with contextlib.suppress(OSError):
            out.unlink()


@contextlib.contextmanager
def writing(path) -> Iterator[None]:
    """Run the write of ``path``; an ``OSError`` it raises (a full disk, a read-only mount, a
    name the file system refuses) becomes a GearError naming the path and the reason."""
    try:
        yield
    except OSError as exc:
        reason = exc.strerror or str(exc)
        raise GearError(f"path {str(path)!r} could not be written: {reason}") from exc


def pyplot() -> ModuleType:
    """``matplotlib.pyplot`` on a headless backend (Agg, unless one is already chosen), or a
    :class:`~gears.errors.GearError` naming the ``plot`` extra when matplotlib is missing."""
    try:
        import matplotlib

        matplotlib.use("Agg", force=False)
        import matplotlib.pyplot as plt
    except ImportError as exc:  # pragma: no cover - the plot extra
        raise GearError("figures need matplotlib: pip install 'geartrain[plot]'") from exc
    return plt
