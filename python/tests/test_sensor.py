"""The raw sensor from Python: the same capture as the command line's, bit for bit; the dict of
sensor fields named as the JSON block names them; bad values are ValueErrors naming the field."""

import numpy as np
import pytest

import obscura


def small_scene_camera():
    scene = obscura.load_scene("cornell-box")
    camera = scene.camera
    camera.width, camera.height = 48, 36
    return scene, camera


def test_capture_matches_the_cli(cli, tmp_path):
    dng = tmp_path / "cli.dng"
    cli("render", "cornell-box", "--width", 48, "--height", 36, "--spp", 3, "--seed", 7, "-q",
        "--raw-sensor", "cfa=GRBG,read_noise_e=4", "-o", dng)
    from_cli, channels, _ = obscura.read_exr(str(tmp_path / "cli.raw.exr"))
    assert channels == ["raw"]

    scene, camera = small_scene_camera()
    film = obscura.render(scene, camera, spp=3, seed=7).image
    capture = obscura.capture_raw(film, camera, sensor={"cfa": "GRBG", "read_noise_e": 4}, seed=7)
    assert capture["raw"].dtype == np.uint16
    assert capture["raw"].shape == (36, 48)
    assert np.array_equal(capture["raw"].astype(np.float32), from_cli[:, :, 0])
    assert capture["cfa"] == "GRBG"
    assert capture["white_level"] > capture["black_level"] == 256


def test_write_dng_and_develop(tmp_path):
    scene, camera = small_scene_camera()
    film = obscura.render(scene, camera, spp=2).image
    paths = obscura.write_dng(str(tmp_path / "x.dng"), film, camera, sensor={"cfa": "BGGR"})
    assert [p.split("/")[-1] for p in paths] == [
        "x.dng", "x.raw.exr", "x.irradiance.exr", "x.electrons.exr"]
    developed = obscura.develop_raw(film, camera, demosaic="bilinear")
    assert developed.shape == (36, 48, 3)
    assert np.isfinite(developed).all()


@pytest.mark.parametrize("field,value", [("read_noise_e", -1), ("full_well_e", 0),
                                         ("qe_green", 1.5), ("adc_bits", 0), ("adc_bits", 64),
                                         ("prnu", float("nan")), ("cfa", "RGBW")])
def test_bad_fields_are_value_errors_naming_the_field(field, value):
    scene, camera = small_scene_camera()
    film = np.zeros((4, 4, 3), np.float32)
    with pytest.raises(ValueError, match=f"sensor.{field}"):
        obscura.capture_raw(film, camera, sensor={field: value})


def test_meter_reads_iso_2720():
    # A uniform luminance of 10 cd/m² meters EV100 = log2(10 · 100 / 12.5).
    film = np.full((8, 8, 3), 10.0, np.float32)
    assert obscura.meter(film) == pytest.approx(np.log2(10 * 100 / 12.5), abs=1e-6)
