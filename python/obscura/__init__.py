"""Obscura from Python: scenes, cameras, the path tracer and the rasterizer into numpy arrays,
and the colour pipeline. See docs/python.md for a worked example.

Everything lives in the C++ extension ``obscura._obscura``; this package re-exports it, and adds
``render_frames`` (a sequence, as ``obscura render --frames``) on top of it.
"""

from ._obscura import (  # noqa: F401
    Camera,
    Error,
    RenderInterrupted,
    RenderResult,
    RenderSession,
    Scene,
    __version__,
    blackbody_xyz,
    builtin_scenes,
    capture_raw,
    chromaticity,
    color_spaces,
    convert,
    develop,
    develop_raw,
    ground_truth,
    load_scene,
    meter,
    planck_radiance,
    read_exr,
    read_image,
    render,
    render_dataset,
    resolve_camera,
    wavelength_lms,
    wavelength_xyz,
    write_dng,
    write_image,
)
from ._view import View, view  # noqa: F401



def render_frames(scene, frames, *, fps=24.0, camera=None, load=None, **render_options):
    """Renders a sequence as ``obscura render SCENE --frames A:B --fps F`` does, yielding
    ``(frame_number, RenderResult)`` one frame at a time.

    ``scene``: a built-in scene's name or a scene file. ``frames``: the frame numbers (e.g.
    ``range(0, 48)``); frame n is exposed around n / fps seconds. The scene is loaded once
    (``load_scene`` with ``load``'s keywords: environment, gltf_scene, gltf_animation, variant)
    and rendered through one RenderSession, which each frame poses at its moment (skins and
    morph targets, across the shutter: ``RenderSession.pose``), rebuilding only what moved. Each
    frame's camera is resolved from ``camera``, a dict of ``resolve_camera`` keywords
    (``{"fstop": 2, "width": 320}``), with the shutter centred on the frame's moment.
    ``render_options`` go to ``render()``. The frames are the command line's, bit for bit.
    """
    camera = dict(camera or {})
    load = dict(load or {})
    if "time" in camera or "time" in load:
        raise ValueError("render_frames: each frame's time is frame / fps; give no time")
    if not fps > 0:
        raise ValueError(f"render_frames: fps must be positive; got {fps}")
    frame_scene = session = None
    for n in frames:
        time = n / fps
        if session is None:
            frame_scene = load_scene(scene, time=time, shutter=camera.get("shutter"), **load)
            session = RenderSession(frame_scene)
        session.pose(time, camera.get("shutter"))
        frame_camera = resolve_camera(frame_scene, time=time, **camera)
        yield n, render(session, frame_camera, **render_options)


__all__ = [
    "Camera",
    "Error",
    "RenderInterrupted",
    "RenderResult",
    "RenderSession",
    "Scene",
    "View",
    "blackbody_xyz",
    "builtin_scenes",
    "capture_raw",
    "chromaticity",
    "color_spaces",
    "convert",
    "develop",
    "develop_raw",
    "ground_truth",
    "load_scene",
    "meter",
    "planck_radiance",
    "read_exr",
    "read_image",
    "render",
    "render_dataset",
    "render_frames",
    "resolve_camera",
    "view",
    "wavelength_lms",
    "wavelength_xyz",
    "write_dng",
    "write_image",
]
