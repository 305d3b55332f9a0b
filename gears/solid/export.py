"""Layer 11, consumers.

Export of outlines (plain SVG with no dependency, DXF with ezdxf, PNG, point arrays) and of 3D
meshes and scenes (STL, 3MF, GLB, OBJ, PLY through trimesh's own exporters, the ``mesh`` extra).

Export picks the format from the file extension (:func:`save`), the way trimesh does.
"""

from __future__ import annotations

import io
import pathlib
import re
import zipfile

import numpy as np
import shapely

from gears.display import svg
from gears.errors import GearError
from gears.files import check_output, writing

__all__ = ["check_output", "points", "save", "save_mesh", "to_dxf", "to_svg"]


def _polygons(outlines) -> list[shapely.Polygon]:
    out = []
    for o in outlines:
        if isinstance(o, shapely.MultiPolygon):
            out.extend(o.geoms)
        elif isinstance(o, shapely.Polygon):
            out.append(o)
        else:
            raise GearError(f"expected shapely Polygons; got {type(o).__name__}")
    if not out:
        raise GearError("nothing to export: pass at least one outline")
    return out


def points(outline) -> list[np.ndarray]:
    """The rings of ``outline`` as ``(n, 2)`` float arrays in mm (exterior first, then holes;
    the closing point is not repeated)."""
    (p,) = _polygons([outline])
    return [np.asarray(r.coords)[:-1] for r in (p.exterior, *p.interiors)]


def to_svg(path, *outlines, margin: float = 1.0, stroke: float = 0.05) -> pathlib.Path:
    """Write ``outlines`` as a plain SVG whose user unit is 1 mm (y up, as in the drawings).

    Each polygon is one ``<path>`` with ``fill-rule="evenodd"`` (holes stay open); the text
    is :func:`gears.display.svg`'s, which the notebook displays draw too.

    Examples
    --------
    >>> import tempfile, os
    >>> from gears import Gear
    >>> f = to_svg(os.path.join(tempfile.mkdtemp(), "g.svg"), Gear(12, 1).outline(0.01))
    >>> f.read_text().startswith("<?xml")
    True
    """
    path = check_output(path, (".svg",))
    polys = _polygons(outlines)
    style = {"fill": "none", "stroke": "black", "stroke-width": stroke}
    text = svg([(p, style) for p in polys], margin=margin, declaration=True)
    with writing(path):
        path.write_text(text)
    return path


def to_dxf(path, *outlines) -> pathlib.Path:
    """Write ``outlines`` as closed LWPOLYLINEs in a DXF (mm units). Needs ezdxf
    (``pip install geartrain[dxf]``)."""
    path = check_output(path, (".dxf",))
    polys = _polygons(outlines)
    try:
        import ezdxf
        from ezdxf import units
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise GearError("DXF export needs ezdxf: pip install 'geartrain[dxf]'") from exc
    doc = ezdxf.new("R2010")
    doc.units = units.MM
    msp = doc.modelspace()
    for p in polys:
        for ring in points(p):
            msp.add_lwpolyline(ring.tolist(), close=True)
    with writing(path):
        doc.saveas(path)
    return path


MESH_FORMATS = (".stl", ".3mf", ".glb", ".obj", ".ply")
OUTLINE_FORMATS = (".svg", ".dxf", ".png", ".npz")


def _is_mesh(obj) -> bool:
    return type(obj).__name__ in ("Trimesh", "Scene") and hasattr(obj, "export")


def _standard_3mf(data: bytes) -> bytes:
    """trimesh's 3MF package with the namespace declarations it repeats on every build
    ``<item>`` removed. They are the ``<model>``'s own (the same prefixes and URIs), so the
    document means the same; lib3mf's strict reader refuses the repeats ("Invalid Attribute in
    namespace")."""

    def item(match: re.Match) -> bytes:
        return re.sub(rb'\sxmlns(?::\w+)?="[^"]*"', b"", match.group())

    src = zipfile.ZipFile(io.BytesIO(data))
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as dst:
        for info in src.infolist():
            part = src.read(info)
            if info.filename.endswith(".model"):
                part = re.sub(rb"<item\b[^>]*>", item, part)
            dst.writestr(info, part)
    return out.getvalue()


def save_mesh(path, mesh_or_scene) -> pathlib.Path:
    """Write a ``trimesh.Trimesh`` or ``trimesh.Scene`` by extension with trimesh's exporters:
    ``.stl`` (binary), ``.3mf`` (needs lxml), ``.glb``, ``.obj`` (with its materials beside it
    in a file named after it, ``pair.obj`` -> ``pair.mtl``, when the parts have colours),
    ``.ply``. A 3MF or GLB of a scene keeps one named object per part and stores a shared
    (instanced) geometry once; STL, OBJ and PLY hold the merged scene. A 3MF passes the strict
    reader of lib3mf, the 3MF Consortium's reference library.

    The path is checked before any work (:func:`gears.files.check_output`): a missing
    directory, an unknown extension or a path that is not a file name is a GearError.

    Examples
    --------
    >>> import tempfile, os, shapely
    >>> from gears.solid.mesh import gear_solid
    >>> cube = gear_solid(shapely.box(0, 0, 1, 1), 1)
    >>> f = save_mesh(os.path.join(tempfile.mkdtemp(), "g.stl"), cube)
    >>> f.stat().st_size   # binary STL: 84 + 50 bytes per triangle
    684
    """
    path = check_output(path, MESH_FORMATS)
    ext = path.suffix.lower()
    if not _is_mesh(mesh_or_scene):
        raise GearError(
            f"the {ext} format needs a trimesh.Trimesh or trimesh.Scene; "
            f"got {type(mesh_or_scene).__name__}"
        )
    try:
        with writing(path):
            if ext == ".3mf":
                path.write_bytes(_standard_3mf(mesh_or_scene.export(file_type="3mf")))
            elif ext == ".obj":
                mesh_or_scene.export(str(path), file_type="obj", mtl_name=f"{path.stem}.mtl")
            else:
                mesh_or_scene.export(str(path), file_type=ext[1:])
    except ImportError as exc:
        missing = getattr(exc, "name", None) or str(exc)
        raise GearError(
            f"{ext} export needs the module {missing!r}: pip install 'geartrain[mesh]'"
        ) from exc
    return path


def save(path, *objects) -> pathlib.Path:
    """Write by extension: outlines to ``.svg``, ``.dxf``, ``.png`` (matplotlib, the ``plot``
    extra) or ``.npz`` (point arrays); one mesh or scene to ``.stl``, ``.3mf``, ``.glb``,
    ``.obj`` or ``.ply`` (:func:`save_mesh`).

    The path is checked before any work (:func:`gears.files.check_output`): ``None``, a
    non-path, a missing or read-only directory and an unknown extension are a GearError
    naming the path and what is valid.

    Examples
    --------
    >>> save("no/such/dir/g.svg", None)
    Traceback (most recent call last):
    ...
    gears.errors.GearError: path 'no/such/dir/g.svg': the directory 'no/such/dir' does not exist
    """
    path = check_output(path, OUTLINE_FORMATS + MESH_FORMATS)
    ext = path.suffix.lower()
    if ext in MESH_FORMATS:
        if len(objects) != 1:
            raise GearError(f"{ext} export takes one mesh or scene; got {len(objects)} objects")
        return save_mesh(path, objects[0])
    if objects and _is_mesh(objects[0]):
        raise GearError(
            f"a mesh or scene is written as {', '.join(MESH_FORMATS)}; {str(path)!r} is an "
            f"outline format ({', '.join(OUTLINE_FORMATS)})"
        )
    outlines = _polygons(objects)  # a clear error for anything that is not an outline
    if ext == ".svg":
        return to_svg(path, *outlines)
    if ext == ".dxf":
        return to_dxf(path, *outlines)
    if ext == ".png":
        from gears.figures.plot import outlines_figure  # matplotlib: for a PNG only

        fig = outlines_figure(*outlines)
        import matplotlib.pyplot as plt

        try:
            with writing(path):
                fig.savefig(path, dpi=150)
        finally:
            plt.close(fig)
        return path
    arrays = {  # .npz
        f"outline{i}_ring{j}": r for i, p in enumerate(outlines) for j, r in enumerate(points(p))
    }
    with writing(path):
        np.savez(path, **arrays)
    return path
