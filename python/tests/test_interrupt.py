"""Ctrl-C stops the long calls that render without a progress callback — ground_truth() and
render_dataset() — within a fraction of their full time, raising KeyboardInterrupt (issue 32:
cancel means cancel, from Python too)."""

import os
import signal
import threading
import time

import pytest

import obscura


def interrupt_after(seconds):
    def send():
        time.sleep(seconds)
        os.kill(os.getpid(), signal.SIGINT)

    threading.Thread(target=send, daemon=True).start()


def test_ground_truth_stops_on_ctrl_c():
    scene = obscura.load_scene("cornell-box")
    camera = scene.camera
    camera.width, camera.height = 1600, 1600
    start = time.monotonic()
    obscura.ground_truth(scene, camera)
    full = time.monotonic() - start
    if full < 1.0:
        pytest.skip(f"the ground truth took {full:.2f} s here: too fast to interrupt reliably")
    interrupt_after(0.25 * full)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        obscura.ground_truth(scene, camera)
    assert time.monotonic() - start < 0.8 * full


def test_render_dataset_stops_on_ctrl_c_and_keeps_the_views_written(tmp_path):
    scene = obscura.load_scene("cornell-box")
    camera = obscura.resolve_camera(scene, width=64, height=48)
    out = tmp_path / "set"
    interrupt_after(1.0)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        # Minutes if not interrupted: 200 views at 256 samples per pixel.
        obscura.render_dataset(scene, "orbit:200", str(out), camera=camera, spp=256)
    assert time.monotonic() - start < 30
    written = sorted((out / "images").glob("*.png")) if (out / "images").exists() else []
    assert len(written) < 200
    # What was written is whole: resuming renders only the rest.
    again = obscura.render_dataset(scene, "orbit:200", str(out), camera=camera, spp=1)
    assert again["skipped"] == len(written)
