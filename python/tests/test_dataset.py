"""render_dataset(): the command line's `obscura dataset` from Python, the same files byte for
byte; resumable; a field limit the formats cannot hold is a warning; placement keywords."""

import json
import pathlib

import pytest

import obscura


def small_camera(scene, **keywords):
    return obscura.resolve_camera(scene, width=32, height=24, **keywords)


def files_of(folder):
    folder = pathlib.Path(folder)
    return {p.relative_to(folder).as_posix(): p.read_bytes()
            for p in sorted(folder.rglob("*")) if p.is_file()}


def test_a_dataset_names_its_images_and_resumes(tmp_path):
    scene = obscura.load_scene("cornell-box")
    out = tmp_path / "set"
    result = obscura.render_dataset(scene, "orbit:4", str(out), camera=small_camera(scene), spp=1,
                                    ground_truth=True)
    assert result["rendered"] == 4 and result["skipped"] == 0
    assert result["views"] == ["view_0000", "view_0001", "view_0002", "view_0003"]
    transforms = json.loads((out / "transforms.json").read_text())
    assert [f["file_path"] for f in transforms["frames"]] == [
        f"images/view_000{i}.png" for i in range(4)]
    assert (out / "ground_truth/view_0003.exr").is_file()
    assert (out / "opencv/view_0001.yaml").is_file()
    (out / "images/view_0001.png").unlink()
    again = obscura.render_dataset(scene, "orbit:4", str(out), camera=small_camera(scene), spp=1,
                                   ground_truth=True)
    assert again["rendered"] == 1 and again["skipped"] == 3


def test_the_command_line_writes_the_same_bytes(tmp_path, cli):
    scene = obscura.load_scene("cornell-box")
    obscura.render_dataset(scene, "sphere:3", str(tmp_path / "py"), camera=small_camera(scene),
                           spp=2, ground_truth=True)
    cli("dataset", "cornell-box", "-q", "--views", "sphere:3", "--width", 32, "--height", 24,
        "--spp", 2, "--ground-truth", "-o", tmp_path / "cli")
    assert files_of(tmp_path / "py") == files_of(tmp_path / "cli")


def test_a_field_limit_the_formats_cannot_hold_is_a_warning(tmp_path):
    scene = obscura.load_scene("cornell-box")
    fisheye = small_camera(scene, projection="calibrated", intrinsics="10,10,15.5,11.5",
                           distortion="kannala-brandt:0,0,0,0", max_field_angle=95)
    with pytest.warns(UserWarning, match="COLMAP cannot hold the fisheye's 190° field limit"):
        obscura.render_dataset(scene, "orbit:1", str(tmp_path / "f"), camera=fisheye, spp=1)


def test_placement_keywords(tmp_path):
    scene = obscura.load_scene("cornell-box")
    camera = small_camera(scene, position=(0, 1, 5), look_at=(0, 1, 0))
    pose = camera.world_from_camera
    assert [pose[i][3] for i in range(3)] == [0, 1, 5]
    assert pose[2][2] == 1  # looking down -Z, at the point
    with pytest.raises(ValueError, match="the camera's position"):
        small_camera(scene, position=(1, 2, 3), look_at=(1, 2, 3))
    with pytest.raises(ValueError, match="parallel"):
        small_camera(scene, position=(0, 0, 0), look_at=(0, 3, 0), up=(0, 1, 0))
