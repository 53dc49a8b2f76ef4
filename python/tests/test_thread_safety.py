"""A Scene changed by another Python thread while it renders (the GIL is free meanwhile).

render(), ground_truth() and RenderSession work on a snapshot taken when they are called: the
other thread's changes neither crash them (they once read freed mesh arrays: a use-after-free)
nor reach the image.
"""

import threading
import time

import numpy as np

import obscura


def grey_square_scene():
    # A 4 x 4 m grey square 5 m in front of the camera, under a white sky.
    scene = obscura.Scene()
    grey = scene.add_material("diffuse", color=(0.5, 0.5, 0.5))
    square = np.array([[-2, -2, -5], [2, -2, -5], [2, 2, -5], [-2, 2, -5]], dtype=np.float64)
    scene.add_mesh(square, np.array([[0, 1, 2], [0, 2, 3]]), material=grey)
    scene.set_environment(color=(1, 1, 1))
    return scene


class Mutator:
    """Adds meshes and lights to `scene` from another thread until stopped: each addition may
    move the scene's arrays, freeing what a render without a snapshot would be reading. What it
    adds cannot be seen: triangles hidden behind the square (its unlit back side) and dark
    lights, so every image stays the one of the square alone."""

    def __init__(self, scene):
        self.scene, self.changes = scene, 0
        self.stop = threading.Event()
        self.started = threading.Event()
        self.thread = threading.Thread(target=self.run)

    def run(self):
        hidden = np.array([[-0.5, -0.5, -9], [0.5, -0.5, -9], [0, 0.5, -9]], dtype=np.float64)
        while not self.stop.is_set():
            self.scene.add_mesh(hidden, np.array([[0, 1, 2]]), material=0)
            self.scene.add_point_light((0, 0, -9), intensity=(0, 0, 0))
            self.changes += 1
            self.started.set()

    def __enter__(self):
        self.thread.start()
        self.started.wait(10)
        return self

    def __exit__(self, *exc):
        self.stop.set()
        self.thread.join()


def test_render_uses_a_snapshot_while_another_thread_changes_the_scene():
    camera = obscura.Camera.perspective(fov=90, width=48, height=48)
    for renderer in ("path", "raster"):
        scene = grey_square_scene()
        reference = obscura.render(scene, camera, renderer=renderer, spp=4, seed=3,
                                   threads=2).image.copy()
        for _ in range(3):
            with Mutator(scene) as mutator:
                changes_before = mutator.changes
                result = obscura.render(scene, camera, renderer=renderer, spp=4, seed=3,
                                        threads=2)
                changes_during = mutator.changes - changes_before
            # The scene was changed while it rendered (the GIL was free); the render finished
            # with the image of the square (the changes are invisible by construction).
            assert changes_during > 0, renderer
            np.testing.assert_array_equal(result.image, reference, err_msg=renderer)
        # Every change the other thread made is in the scene afterwards.
        assert scene.stats()["meshes"] > 1


def test_ground_truth_and_sessions_snapshot_the_scene():
    camera = obscura.Camera.perspective(fov=90, width=32, height=32)
    scene = grey_square_scene()
    reference = obscura.ground_truth(scene, camera)["Z"].copy()
    with Mutator(scene) as mutator:
        depth = obscura.ground_truth(scene, camera)["Z"]
        session = obscura.RenderSession(scene)
        changes = mutator.changes
        while mutator.changes == changes:  # at least one change after the session was made
            time.sleep(0.001)
    np.testing.assert_array_equal(depth, reference)
    # The session holds the scene as it was when it was made, without the later changes.
    assert session.scene.stats()["meshes"] < scene.stats()["meshes"]
