"""Obscura from Python: scenes, cameras, the path tracer and the rasterizer into numpy arrays,
and the colour pipeline. See docs/python.md for a worked example.

Everything lives in the C++ extension ``obscura._obscura``; this package re-exports it.
"""

from ._obscura import (  # noqa: F401
    Camera,
    Error,
    RenderInterrupted,
    RenderResult,
    Scene,
    __version__,
    blackbody_xyz,
    builtin_scenes,
    chromaticity,
    color_spaces,
    convert,
    develop,
    ground_truth,
    load_scene,
    planck_radiance,
    read_exr,
    read_image,
    render,
    resolve_camera,
    wavelength_lms,
    wavelength_xyz,
    write_image,
)

__all__ = [
    "Camera",
    "Error",
    "RenderInterrupted",
    "RenderResult",
    "Scene",
    "blackbody_xyz",
    "builtin_scenes",
    "chromaticity",
    "color_spaces",
    "convert",
    "develop",
    "ground_truth",
    "load_scene",
    "planck_radiance",
    "read_exr",
    "read_image",
    "render",
    "resolve_camera",
    "wavelength_lms",
    "wavelength_xyz",
    "write_image",
]
