"""3D: meshes of spur, helical, herringbone and ring gears to a tolerance, scenes, animations,
pictures, and the files they are written to (SVG, DXF, PNG, STL, 3MF, GLB, ...).

The names below are imported on first use (:mod:`gears.lazy`): importing one module of the
family does not load the rest.
"""

from gears.lazy import attach

__getattr__, __dir__, __all__ = attach(
    __name__,
    {
        "Camera": "gears.solid.render",
        "check_frames": "gears.solid.animate",
        "check_output": "gears.solid.export",
        "gear_solid": "gears.solid.mesh",
        "helix_twist": "gears.solid.mesh",
        "MAX_FACES": "gears.solid.render",
        "MAX_FRAMES": "gears.solid.animate",
        "points": "gears.solid.export",
        "polygon_path": "gears.solid.animate",
        "render_image": "gears.solid.render",
        "save": "gears.solid.export",
        "save_mesh": "gears.solid.export",
        "scene": "gears.solid.mesh",
        "scene_parts": "gears.solid.render",
        "slice_count": "gears.solid.mesh",
        "solid_levels": "gears.solid.mesh",
        "solid_radius": "gears.solid.mesh",
        "to_dxf": "gears.solid.export",
        "to_manifold": "gears.solid.mesh",
        "to_svg": "gears.solid.export",
        "transform": "gears.solid.mesh",
        "write_animation": "gears.solid.animate",
        "write_animation_3d": "gears.solid.render",
    },
)
