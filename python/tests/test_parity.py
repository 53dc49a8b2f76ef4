"""One frame, every door: the same request gives the same frame, bit for bit, from the command
line, from Python, as the first frame of a sequence, from 2 MPI ranks (where the build has MPI)
and from `--shard` parts merged (N = 2, 3).

Each case is one request in both spellings: the command line's options, and Python's
resolve_camera() / render() keywords (the options with dashes as underscores). The scenes
exercise every feature that used to be assembled at the doors: calibrated lenses with
distortion, a fisheye with a field limit, a lens system with coating, ghost flares and glare (asked
for on the command line, and by the scene file's render block), spectral transport, a rolling
shutter, motion blur, and the rasterizer's post-process and accumulated depth of field.
"""

import os
import subprocess

import numpy as np
import pytest

import obscura
from conftest import cli_path

SIZE = {"width": 64, "height": 48}

# (name, scene, camera options, render options) — each option a (name, value) pair, spelt as on
# the command line; None: a flag without a value.
CASES = [
    ("calibrated_distortion", "cornell-box",
     {"intrinsics": "60,60,31.5,23.5", "calibration_size": "64x48",
      "distortion": "opencv:-0.2,0.05,0.001,0.0005,0"},
     {"renderer": "path", "spp": 2}),
    ("fisheye_field_limit", "spheres-and-lights",
     {"projection": "calibrated", "intrinsics": "20,20,31.5,23.5", "calibration_size": "64x48",
      "distortion": "kannala-brandt:0.01,-0.002,0,0", "max_field_angle": 80},
     {"renderer": "raster"}),
    ("lens_system_flare_glare_path", "spheres-and-lights",
     {"lens": "double-gauss-50mm", "lens_coating": "none"},
     {"renderer": "path", "spp": 2, "flare": None, "glare": None}),
    ("lens_system_flare_glare_raster", "spheres-and-lights",
     {"lens": "double-gauss-50mm", "fstop": 4},
     {"renderer": "raster", "flare": None, "glare-strength": 3}),
    ("scene_file_flare_glare", "scenes/night-street-flare.json", {},
     {"renderer": "raster"}),
    ("spectral", "cornell-box", {}, {"renderer": "path", "spp": 2, "spectral": None}),
    ("rolling_shutter", "motion-blur", {"rolling_shutter": "1/5000"},
     {"renderer": "path", "spp": 2}),
    ("motion_blur_raster", "motion-blur", {}, {"renderer": "raster", "raster-samples": 4}),
    ("post_dof_raster", "depth-of-field", {}, {"renderer": "raster", "raster-dof": "post"}),
    ("accumulated_dof_raster", "depth-of-field", {},
     {"renderer": "raster", "raster-dof": "accumulate", "raster-samples": 4}),
    ("motion_blur_dof_reyes", "motion-blur", {"fstop": 2.8, "focus_distance": 4},
     {"renderer": "reyes", "reyes-pixel-samples": 4, "reyes-bucket-size": 8}),
]


def mpirun_prefix(session_dir):
    """mpirun as this suite needs it (root allowed, more ranks than cores, its own session
    folder), or None where the build has no MPI or a job cannot start here."""
    mpiexec = os.environ.get("OBSCURA_MPIEXEC")
    if not mpiexec:
        return None
    prefix = ["env", f"TMPDIR={session_dir}", "OMPI_ALLOW_RUN_AS_ROOT=1",
              "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1", "OMPI_MCA_rmaps_base_oversubscribe=1", mpiexec]
    try:
        probe = subprocess.run(prefix + ["-np", "1", "true"], capture_output=True, timeout=60)
    except subprocess.TimeoutExpired:
        return None
    return tuple(prefix) if probe.returncode == 0 else None


def cli_arguments(options):
    args = []
    for name, value in options.items():
        args.append("--" + name.replace("_", "-"))
        if value is not None:
            args.append(str(value))
    return args


def python_render_keywords(options):
    keywords = {}
    for name, value in options.items():
        key = name.replace("-", "_")
        keywords[key] = True if value is None else value
    return keywords


def tmp_path_factory_dir(tmp_path):
    """An empty folder of its own for MPI's session files, one per test."""
    folder = tmp_path / "mpi-session"
    folder.mkdir(exist_ok=True)
    return folder


def scene_argument(scene, source_dir):
    return str(source_dir / scene) if scene.endswith(".json") else scene


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_every_door_gives_the_same_frame(cli, tmp_path, source_dir, case):
    name, scene_name, camera_options, render_options = case
    scene_path = scene_argument(scene_name, source_dir)
    common = [scene_path, "-q", "--width", SIZE["width"], "--height", SIZE["height"],
              "--seed", 5] + cli_arguments(camera_options) + cli_arguments(render_options)

    lone = tmp_path / "lone.exr"
    cli("render", *common, "-o", lone)
    from_cli, _, _ = obscura.read_exr(str(lone))
    assert from_cli.shape == (SIZE["height"], SIZE["width"], 3)

    # Python: the same request as keywords.
    scene = obscura.load_scene(scene_path)
    camera = obscura.resolve_camera(scene, width=SIZE["width"], height=SIZE["height"],
                                    **camera_options)
    result = obscura.render(scene, camera, seed=5, threads=2,
                            **python_render_keywords(render_options))
    assert np.array_equal(result.image, from_cli), f"{name}: Python differs from the CLI"

    # The first frame of a sequence is the frame at time 0.
    at_zero = tmp_path / "at_zero.exr"
    cli("render", *common, "--time", 0, "-o", at_zero)
    cli("render", *common, "--frames", "0:0", "-o", tmp_path / "seq_%04d.exr")
    frame, _, _ = obscura.read_exr(str(tmp_path / "seq_0000.exr"))
    single, _, _ = obscura.read_exr(str(at_zero))
    assert np.array_equal(frame, single), f"{name}: the sequence's frame differs"

    # MPI ranks, where this build and machine can run them.
    session = tmp_path_factory_dir(tmp_path)
    prefix = mpirun_prefix(str(session))
    if prefix:
        ranks = tmp_path / "ranks.exr"
        subprocess.run([*prefix, "-np", "2", cli_path(), "render", *map(str, common), "-o",
                        str(ranks)], check=True, capture_output=True, timeout=300)
        from_ranks, _, _ = obscura.read_exr(str(ranks))
        assert np.array_equal(from_ranks, from_cli), f"{name}: 2 MPI ranks differ"

    # Shards, merged in an order that is not their own.
    for parts in (2, 3):
        files = []
        for part in reversed(range(parts)):
            path = tmp_path / f"part{part}of{parts}.exr"
            cli("render", *common, "--shard", f"{part}/{parts}", "-o", path)
            files.append(path)
        merged = tmp_path / f"merged{parts}.exr"
        cli("merge", *files, "-q", "-o", merged)
        from_parts, _, _ = obscura.read_exr(str(merged))
        assert np.array_equal(from_parts, from_cli), f"{name}: {parts} merged parts differ"


def test_a_calibration_files_size_is_the_films(cli, tmp_path):
    # A 320 x 240 OpenCV calibration: render and camera --export both take its size, unless
    # --width/--height say otherwise; a film of another shape is named in a warning.
    calibration = tmp_path / "camera.yaml"
    calibration.write_text(
        "%YAML:1.0\n---\nimage_width: 320\nimage_height: 240\n"
        "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
        "   data: [ 300., 0., 159.5, 0., 300., 119.5, 0., 0., 1. ]\n"
        "distortion_coefficients: !!opencv-matrix\n   rows: 1\n   cols: 5\n   dt: d\n"
        "   data: [ -0.1, 0.01, 0., 0., 0. ]\n")
    out = tmp_path / "out.exr"
    run = cli("render", "cornell-box", "--calibration", calibration, "--spp", 1, "-o", out)
    image, _, _ = obscura.read_exr(str(out))
    assert image.shape == (240, 320, 3)
    assert "stretch" not in run.stderr

    exported = tmp_path / "export.yaml"
    cli("camera", "cornell-box", "--calibration", calibration, "--export", "opencv-yaml",
        "--output", exported)
    text = exported.read_text()
    assert "image_width: 320" in text and "image_height: 240" in text

    stretched = cli("render", "cornell-box", "--calibration", calibration, "--width", 64,
                    "--height", 64, "--spp", 1, "-o", tmp_path / "square.exr")
    assert "stretches" in stretched.stderr

    scene = obscura.load_scene("cornell-box")
    camera = obscura.resolve_camera(scene, calibration=str(calibration))
    assert (camera.width, camera.height) == (320, 240)
    with pytest.warns(UserWarning, match="stretches"):
        obscura.resolve_camera(scene, calibration=str(calibration), width=64, height=64)


def test_camera_export_describes_the_scene_files_film(cli, source_dir, tmp_path):
    # The night street's render block asks for 960 x 540: what `render` writes and what
    # `camera` reports and exports.
    scene = str(source_dir / "scenes/night-street.json")
    report = cli("camera", scene).stdout
    assert "960 x 540" in report
    exported = tmp_path / "export.yaml"
    cli("camera", scene, "--export", "opencv-yaml", "--output", exported)
    assert "image_width: 960" in exported.read_text()
    camera = obscura.resolve_camera(obscura.load_scene(scene))
    assert (camera.width, camera.height) == (960, 540)


def test_request_mistakes_are_value_errors_naming_the_option():
    scene = obscura.load_scene("cornell-box")
    with pytest.raises(ValueError, match="--shutter"):
        obscura.resolve_camera(scene, shutter="soon")
    with pytest.raises(ValueError, match="--lens"):
        obscura.resolve_camera(scene, lens="no-such-lens")
    with pytest.raises(obscura.Error, match="flare"):
        obscura.render(scene, spp=1, flare=True)  # no lens system, no ghosts


@pytest.mark.parametrize("renderer", ["path", "raster"])
def test_ground_truth_with_flow_is_the_clis(cli, tmp_path, renderer):
    # The moving sphere seen by a moving camera: every channel, flow included, bit for bit (NaN
    # where the file has NaN).
    gt = tmp_path / "gt.exr"
    cli("render", "motion-blur", "-q", "--width", 48, "--height", 36, "--spp", 1, "--renderer",
        renderer, "--ground-truth", gt, "--flow-times", "0:1/50", "-o", tmp_path / "img.exr")
    pixels, names, _ = obscura.read_exr(str(gt))
    by_name = {name: pixels[..., i] for i, name in enumerate(names)}

    scene = obscura.load_scene("motion-blur")
    camera = obscura.resolve_camera(scene, width=48, height=36)
    truth = obscura.ground_truth(scene, camera, renderer=renderer, flow_times=(0, 1 / 50))
    assert truth["times"] == (0, 1 / 50)
    compared = 0
    for layer, array in truth.items():
        if layer == "times":
            continue
        for c in range(array.shape[2]):
            name = layer if array.shape[2] == 1 and layer in by_name else None
            if name is None:
                matches = [n for n in names if n.rsplit(".", 1)[0] == layer]
                name = matches[c]
            assert np.array_equal(array[..., c], by_name[name], equal_nan=True), name
            compared += 1
    assert compared == len(names)
    assert np.isfinite(truth["flow.forward"]).any()  # the sphere moves: some flow is measured


def test_a_python_sequence_is_the_clis(cli, tmp_path):
    # Three frames of the moving sphere, camera options and all: render_frames gives the files
    # `obscura render --frames` writes.
    cli("render", "motion-blur", "-q", "--width", 40, "--height", 30, "--spp", 1, "--seed", 2,
        "--fstop", 8, "--shutter", "0:1/100", "--frames", "0:4:2", "--fps", 30, "-o",
        tmp_path / "f_%02d.exr")
    numbers = []
    for n, result in obscura.render_frames("motion-blur", range(0, 5, 2), fps=30,
                                           camera={"width": 40, "height": 30, "fstop": 8,
                                                   "shutter": "0:1/100"},
                                           spp=1, seed=2):
        from_cli, _, _ = obscura.read_exr(str(tmp_path / f"f_{n:02d}.exr"))
        assert np.array_equal(result.image, from_cli), f"frame {n}"
        numbers.append(n)
    assert numbers == [0, 2, 4]


def test_a_session_compiles_once_and_renders_what_render_renders():
    scene = obscura.load_scene("motion-blur")
    session = obscura.RenderSession(scene)
    for time in (0.0, 0.0, 0.5):
        camera = obscura.resolve_camera(scene, width=32, height=24, time=time)
        kept = obscura.render(session, camera, spp=1)
        alone = obscura.render(scene, camera, spp=1)
        assert np.array_equal(kept.image, alone.image), f"at {time} s"
    assert session.compilations == 2  # the sphere moves: once per exposure interval

    still = obscura.RenderSession(obscura.load_scene("cornell-box"))
    for time in (0.0, 1.0):
        camera = obscura.resolve_camera(still.scene, width=32, height=24, time=time)
        obscura.render(still, camera, spp=1)
    assert still.compilations == 1
    with pytest.raises(TypeError, match="Scene or a RenderSession"):
        obscura.render("cornell-box")


@pytest.mark.parametrize("renderer", ["path", "raster"])
def test_a_skinned_sequence_poses_one_loaded_scene_as_the_cli_does(cli, source_dir, tmp_path,
                                                                   renderer):
    # A glTF skin animated over three frames: the CLI's sequence (one load, posed per frame), the
    # CLI's lone frames at each moment and Python's render_frames are the same images, bit for bit.
    skin = source_dir / "tests/data/gltf/SimpleSkin/SimpleSkin.gltf"
    common = ["-q", "--renderer", renderer, "--width", 40, "--height", 30, "--spp", 1, "--seed", 2]
    cli("render", skin, *common, "--frames", "0:6:3", "--fps", 4, "-o", tmp_path / "s_%02d.exr")
    frames = {}
    for n, result in obscura.render_frames(str(skin), range(0, 7, 3), fps=4,
                                           camera={"width": 40, "height": 30}, spp=1, seed=2,
                                           renderer=renderer):
        frames[n] = result.image
        from_cli, _, _ = obscura.read_exr(str(tmp_path / f"s_{n:02d}.exr"))
        assert np.array_equal(result.image, from_cli), f"frame {n}"
    for n in (3, 6):
        cli("render", skin, *common, "--time", n / 4, "-o", tmp_path / "alone.exr")
        alone, _, _ = obscura.read_exr(str(tmp_path / "alone.exr"))
        assert np.array_equal(frames[n], alone), f"frame {n} alone"
    assert not np.array_equal(frames[0], frames[6])  # the skin bends

    # A session posed per frame compiles once and rebuilds the skin in place.
    session = obscura.RenderSession(obscura.load_scene(str(skin)))
    camera = obscura.resolve_camera(session.scene, width=40, height=30)
    for time in (0.5, 1.0, 1.5):
        session.pose(time)
        obscura.render(session, camera, spp=1, renderer=renderer)
    assert (session.compilations, session.updates) == (1, 2)


def test_camera_export_is_the_camera_of_the_rendered_ground_truth(cli, source_dir, tmp_path):
    # What `obscura camera --export` writes of a scene (its render block asks for 960 x 540) is
    # the camera the rendered ground truth's header records: the same size and K.
    import json

    scene = str(source_dir / "scenes/night-street.json")
    exported = tmp_path / "camera.json"
    cli("camera", scene, "--export", "opencv-json", "--output", exported)
    calibration = json.loads(exported.read_text())
    gt = tmp_path / "gt.exr"
    cli("render", scene, "-q", "--renderer", "raster", "--ground-truth", gt, "-o",
        tmp_path / "img.exr")
    _, _, header = obscura.read_exr(str(gt))
    width, height = map(int, header["obscura:camera:resolution"].split())
    assert (calibration["image_width"], calibration["image_height"]) == (width, height) == (960, 540)
    fx, fy, cx, cy = map(float, header["obscura:camera:K"].split())
    k = calibration["camera_matrix"]["data"]
    assert np.allclose([k[0], k[4], k[2], k[5]], [fx, fy, cx, cy], rtol=1e-12, atol=1e-9)


def test_motion_keys_from_python_render_as_the_scene_files_do():
    # The moving sphere and moving camera of motion-blur.json, their keys read and written back
    # through Python onto the scene's own still copies: the same motion-blurred frame.
    source = obscura.load_scene("motion-blur")
    camera = obscura.resolve_camera(source, width=48, height=36)
    expected = obscura.render(source, camera, spp=2, seed=1).image

    rebuilt = obscura.load_scene("motion-blur")
    moving = [i for i in range(rebuilt.instance_count) if len(rebuilt.motion(i)) > 1]
    assert moving  # the file moves something
    for i in moving:
        keys = rebuilt.motion(i)
        rebuilt.set_motion(i, [keys[0]])  # still
        rebuilt.set_motion(i, keys)       # and moving again, from Python
    still_camera = obscura.resolve_camera(rebuilt, width=48, height=36)
    keys = still_camera.motion
    still_camera.set_motion(keys)
    assert np.array_equal(obscura.render(rebuilt, still_camera, spp=2, seed=1).image, expected)

    # Still keys give a sharper frame than moving ones: the motion is what blurs it.
    for i in moving:
        rebuilt.set_motion(i, [rebuilt.motion(i)[0]])
    sharp = obscura.render(rebuilt, still_camera, spp=2, seed=1).image
    assert not np.array_equal(sharp, expected)
    with pytest.raises(obscura.Error):
        still_camera.set_motion([(1.0, np.eye(4)), (0.5, np.eye(4))])  # times must increase
    with pytest.raises(IndexError):
        rebuilt.set_motion(rebuilt.instance_count, [(0.0, np.eye(4))])
