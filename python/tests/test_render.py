"""render(): bit-identical to the CLI, no copy of the film, AOVs, progress, Ctrl-C."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import obscura


def small_scene_camera(width=48, height=36):
    scene = obscura.load_scene("cornell-box")
    camera = scene.camera
    camera.width, camera.height = width, height
    return scene, camera


@pytest.mark.parametrize("renderer", ["path", "direct", "whitted", "raster", "reyes"])
def test_render_is_bit_identical_to_the_cli(cli, tmp_path, renderer):
    out = tmp_path / "cli.exr"
    cli("render", "cornell-box", "--renderer", renderer, "--width", 48, "--height", 36,
        "--spp", 3, "--seed", 7, "-q", "-o", out)
    from_cli, _, _ = obscura.read_exr(str(out))

    scene, camera = small_scene_camera()
    result = obscura.render(scene, camera, renderer=renderer, spp=3, seed=7, threads=2)
    # Written and read back through the same EXR path as the CLI's, then compared as arrays.
    mine = tmp_path / "python.exr"
    obscura.write_image(str(mine), result.image)
    from_python, _, _ = obscura.read_exr(str(mine))
    assert from_cli.shape == (36, 48, 3)
    assert np.array_equal(from_python, from_cli)
    assert np.array_equal(result.image, from_cli)  # the film has no NaN, so nothing was altered


def test_reyes_knobs_match_the_cli(cli, tmp_path):
    out = tmp_path / "cli.exr"
    cli("render", "cornell-box", "--renderer", "reyes", "--width", 48, "--height", 36,
        "--reyes-shading-rate", 2, "--reyes-pixel-samples", 4, "--reyes-bucket-size", 8,
        "--seed", 3, "-q", "-o", out)
    from_cli, _, _ = obscura.read_exr(str(out))
    scene, camera = small_scene_camera()
    result = obscura.render(scene, camera, renderer="reyes", seed=3, reyes_shading_rate=2,
                            reyes_pixel_samples=4, reyes_bucket_size=8)
    assert np.array_equal(result.image, from_cli)
    with pytest.raises(obscura.Error, match="shading-rate"):
        obscura.render(scene, camera, renderer="reyes", reyes_shading_rate=0)


def test_raster_options_and_aovs_match_the_cli(cli, tmp_path):
    out = tmp_path / "cli.exr"
    cli("render", "cornell-box", "--renderer", "raster", "--width", 40, "--height", 30, "--msaa", 4,
        "--shading", "flat", "--shadow-map", 256, "--aovs", "-q", "-o", out)
    scene, camera = small_scene_camera(40, 30)
    result = obscura.render(scene, camera, renderer="raster", msaa=4, shading="flat",
                            shadow_map=256, aovs=["depth", "range", "id", "normal"])
    assert np.array_equal(result.image, obscura.read_exr(str(out))[0])
    for name in ("depth", "range", "id", "normal"):
        written = sorted(tmp_path.glob(f"*{name}*.exr"))
        assert written, f"the CLI wrote no {name} AOV"
        from_cli = obscura.read_exr(str(written[0]))[0]
        # Image files get 0 where a value is not finite (depth: +inf where nothing was hit).
        mine = np.where(np.isfinite(result.aovs[name]), result.aovs[name], 0)
        assert np.array_equal(mine, from_cli), name
    with pytest.raises(ValueError, match="albedo"):
        obscura.render(scene, camera, renderer="raster", aovs=["albedo"])


def test_image_and_aovs_share_the_renderers_memory():
    scene, camera = small_scene_camera(16, 12)
    result = obscura.render(scene, camera, spp=1, aovs=["depth", "id", "albedo", "normal"])
    arrays = [result.image] + [result.aovs[k] for k in ("depth", "id", "albedo", "normal")]
    for array in arrays:
        assert array.dtype == np.float32 and array.shape[:2] == (12, 16)
        assert not array.flags.owndata  # the memory belongs to the capsule, not to numpy
        assert type(array.base).__name__ == "PyCapsule"
        assert array.flags.c_contiguous and array.flags.writeable
    # Reading the attribute twice gives the same object and memory: nothing is copied on access.
    assert result.image is result.image
    assert np.shares_memory(result.image, result.image[1:, 1:])
    assert result.image.__array_interface__["data"][0] == result.image.__array_interface__["data"][0]
    assert result.aovs["depth"].shape[2] == 1 and result.aovs["albedo"].shape[2] == 3


def test_depth_range_and_id_against_a_known_plane():
    # A 4 x 4 m square 5 m in front of a pinhole camera at the origin, facing it: every pixel's
    # depth along the optical axis is 5 m; a ray at angle a from the axis travels 5 / cos(a).
    scene = obscura.Scene()
    grey = scene.add_material("diffuse", color=(0.5, 0.5, 0.5))
    square = np.array([[-2, -2, -5], [2, -2, -5], [2, 2, -5], [-2, 2, -5]], dtype=np.float64)
    scene.add_mesh(square, np.array([[0, 1, 2], [0, 2, 3]]), material=grey)
    scene.set_environment(color=(1, 1, 1))
    camera = obscura.Camera.perspective(fov=90, width=33, height=33)
    result = obscura.render(scene, camera, renderer="direct", spp=1,
                            aovs=["depth", "range", "id"])
    depth = result.aovs["depth"][..., 0]
    rng = result.aovs["range"][..., 0]
    ids = result.aovs["id"][..., 0]
    # One sample per pixel lands somewhere inside the pixel, so each range lies between the
    # distances through the pixel's nearest and farthest points (16.5 px = tan 45 degrees).
    def bounds(x, y):
        near = [max(0.0, abs(c - 16.5) - 0.5) for c in (x + 0.5, y + 0.5)]
        far = [abs(c - 16.5) + 0.5 for c in (x + 0.5, y + 0.5)]
        return (5 * np.sqrt(1 + (near[0] ** 2 + near[1] ** 2) / 16.5**2),
                5 * np.sqrt(1 + (far[0] ** 2 + far[1] ** 2) / 16.5**2))

    for x, y in [(16, 16), (20, 16), (12, 19), (21, 12)]:
        low, high = bounds(x, y)
        assert low * (1 - 1e-6) <= rng[y, x] <= high * (1 + 1e-6), (x, y, rng[y, x])
        assert abs(depth[y, x] - 5) <= 5e-6, (x, y, depth[y, x])
    assert ids[16, 16] == 0
    # The square spans +-2 m at 5 m: tan = 0.4 of the half-width 1 (fov 90), so the corners miss.
    assert ids[0, 0] == -1 and np.isinf(depth[0, 0]) and np.isinf(rng[0, 0])



def test_progress_reports_passes_in_order():
    scene, camera = small_scene_camera(16, 16)
    seen = []
    obscura.render(scene, camera, spp=8, progress=lambda done, total: seen.append((done, total)))
    assert seen, "the callback was never called"
    assert seen[-1][0] == seen[-1][1]
    assert [d for d, _ in seen] == sorted(d for d, _ in seen)


def test_an_exception_in_the_callback_stops_the_render():
    scene, camera = small_scene_camera(64, 64)

    def stop(done, total):
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        obscura.render(scene, camera, spp=4096, progress=stop)


@pytest.mark.parametrize("interrupt", ["sigint", "interrupt_main"])
def test_ctrl_c_raises_keyboard_interrupt_with_the_partial_image(interrupt):
    import _thread

    scene, camera = small_scene_camera(128, 128)

    def send():
        time.sleep(0.5)
        if interrupt == "sigint":
            os.kill(os.getpid(), signal.SIGINT)
        else:
            _thread.interrupt_main()

    threading.Thread(target=send, daemon=True).start()
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt) as caught:
        obscura.render(scene, camera, spp=1 << 20)  # hours if not interrupted
    assert time.monotonic() - start < 60
    stopped = caught.value
    assert isinstance(stopped, obscura.RenderInterrupted)
    assert stopped.image.shape == (128, 128, 3)
    assert stopped.result.cancelled and stopped.result.partial
    assert stopped.result.samples_per_pixel < 1 << 20


def test_other_python_threads_run_while_rendering():
    # The GIL is released while the renderer works: a Python thread keeps counting meanwhile.
    scene, camera = small_scene_camera(96, 96)
    count, stop = [0], threading.Event()

    def spin():
        while not stop.is_set():
            count[0] += 1

    spinner = threading.Thread(target=spin)
    spinner.start()
    try:
        before = count[0]
        result = obscura.render(scene, camera, spp=64, threads=1)
        during = count[0] - before
    finally:
        stop.set()
        spinner.join()
    assert result.seconds > 0.2
    assert during > 1000


def test_time_limit_ends_early_and_says_so():
    scene, camera = small_scene_camera(64, 64)
    result = obscura.render(scene, camera, spp=1 << 20, time_limit=0.5)
    assert result.time_limited and result.partial and not result.cancelled
    assert 1 <= result.samples_per_pixel < result.requested


def test_thread_count_does_not_change_the_image():
    scene, camera = small_scene_camera(24, 24)
    one = obscura.render(scene, camera, spp=2, threads=1).image
    two = obscura.render(scene, camera, spp=2, threads=2).image
    assert np.array_equal(one, two)


@pytest.mark.parametrize(
    "kwargs, error",
    [
        ({"renderer": "pathtracer"}, obscura.Error),
        ({"spp": 0}, obscura.Error),
        ({"aovs": ["depht"]}, ValueError),
        ({"threads": -1}, ValueError),
        ({"sampler": "halton"}, obscura.Error),
        ({"progress": 3}, TypeError),
        ({"renderer": "raster", "shading": "toon"}, obscura.Error),
        ({"renderer": "raster", "raster_dof": "blur"}, obscura.Error),
        ({"renderer": "raster", "msaa": 3}, obscura.Error),
    ],
)
def test_bad_render_arguments_raise(kwargs, error):
    scene, camera = small_scene_camera(8, 8)
    with pytest.raises(error):
        obscura.render(scene, camera, **kwargs)
