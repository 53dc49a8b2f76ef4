"""Scenes (files, built-ins, arrays), image files and errors."""

import numpy as np
import pytest

import obscura


def test_builtin_and_file_scenes_load(source_dir):
    names = [name for name, _ in obscura.builtin_scenes()]
    assert names[0] == "cornell-box"
    scene = obscura.load_scene()
    assert scene.stats()["triangles"] > 0
    box = obscura.load_scene(str(source_dir / "tests/data/gltf/Box/Box.glb"))
    assert box.stats()["triangles"] == 12


def test_errors_carry_obscuras_message(tmp_path):
    with pytest.raises(obscura.Error) as caught:
        obscura.load_scene("no-such-scene")
    assert "cornell-box" in str(caught.value)  # lists the built-in names
    assert isinstance(caught.value, RuntimeError)
    bad = tmp_path / "bad.json"
    bad.write_text('{\n  "meshes": 3,\n  "camra": {}\n}\n')
    with pytest.raises(obscura.Error, match="bad.json"):
        obscura.load_scene(str(bad))


def test_scene_from_arrays_validates_its_input():
    scene = obscura.Scene()
    white = scene.add_material()
    quad = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=np.float32)
    assert scene.add_mesh(quad, np.array([[0, 1, 2], [0, 2, 3]], dtype=np.uint32), material=white) == 0
    with pytest.raises(ValueError, match="index 4"):
        scene.add_mesh(quad, np.array([[0, 1, 4]]))
    with pytest.raises(TypeError):
        scene.add_mesh(quad, np.array([[0.0, 1.0, 2.0]]))
    with pytest.raises(ValueError):
        scene.add_mesh(quad, np.array([[0, 1, 2]]), normals=np.zeros((3, 3)))
    with pytest.raises(ValueError):
        scene.add_mesh(quad, np.array([[0, 1, 2]]), material=5)
    with pytest.raises(ValueError):
        scene.add_material("plastic")
    nan_quad = quad.copy()
    nan_quad[0, 0] = np.nan
    with pytest.raises(ValueError):
        scene.add_mesh(nan_quad, np.array([[0, 1, 2]]))


def test_image_files_round_trip(tmp_path):
    rng = np.random.default_rng(1)
    pixels = rng.uniform(0, 4, size=(7, 9, 3)).astype(np.float32)
    obscura.write_image(str(tmp_path / "a.exr"), pixels)
    back = obscura.read_image(str(tmp_path / "a.exr"))
    assert back.dtype == np.float32 and back.shape == (7, 9, 3)
    np.testing.assert_array_equal(back, pixels)
    assert type(back.base).__name__ == "PyCapsule"
    obscura.write_image(str(tmp_path / "a.png"), pixels, tonemap="aces")
    png = obscura.read_image(str(tmp_path / "a.png"))
    np.testing.assert_array_equal(np.round(png * 255).astype(np.uint8),
                                  obscura.develop(pixels, tonemap="aces"))
    with pytest.raises(obscura.Error):
        obscura.read_image(str(tmp_path / "missing.exr"))
    with pytest.raises(obscura.Error):
        obscura.write_image(str(tmp_path / "a.xyz"), pixels)
    with pytest.raises(ValueError):
        obscura.write_image(str(tmp_path / "b.exr"), np.zeros((4, 4, 5), dtype=np.float32))
    assert not (tmp_path / "b.exr").exists()
