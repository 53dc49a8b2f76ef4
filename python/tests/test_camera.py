"""Cameras: vectorized project/unproject against an independent NumPy pinhole, every model,
K, the exports against the CLI's."""

import numpy as np
import pytest

import obscura


def numpy_look_at_pinhole(points, eye, target, up, vfov_degrees, width, height):
    """Raster coordinates of a pinhole camera, written from the textbook formula: camera axes
    from look-at, perspective divide, pixel centres at half-integers, y down."""
    eye, target, up = map(np.asarray, (eye, target, up))
    forward = (target - eye) / np.linalg.norm(target - eye)
    right = np.cross(forward, up)
    right /= np.linalg.norm(right)
    true_up = np.cross(right, forward)
    rel = points - eye
    x, y, z = rel @ right, rel @ true_up, rel @ forward  # z: depth in front of the camera
    focal_px = (height / 2) / np.tan(np.radians(vfov_degrees) / 2)
    return np.stack([width / 2 + focal_px * x / z, height / 2 - focal_px * y / z], axis=1), z


@pytest.fixture
def points():
    rng = np.random.default_rng(16)
    return rng.uniform([-3, -2, -12], [3, 2, -1], size=(10_000, 3))


def test_project_matches_an_independent_pinhole_on_10k_points(points):
    eye, target, up = (0.3, -0.2, 1.0), (0.0, 0.1, -5.0), (0.0, 1.0, 0.0)
    camera = obscura.Camera.perspective(fov=55, width=640, height=480, position=eye,
                                        look_at=target, up=up, near=0.01, far=100)
    film, depth = camera.project(points)
    expected, expected_depth = numpy_look_at_pinhole(points, eye, target, up, 55, 640, 480)
    seen = ~np.isnan(depth)
    on_film = ((expected[:, 0] >= 0) & (expected[:, 0] <= 640) & (expected[:, 1] >= 0)
               & (expected[:, 1] <= 480) & (expected_depth > 0.01))
    assert seen.sum() > 5000
    assert np.array_equal(seen, on_film)
    np.testing.assert_allclose(film[seen], expected[seen], rtol=0, atol=1e-9)
    np.testing.assert_allclose(depth[seen], expected_depth[seen], rtol=1e-12, atol=1e-12)
    # and back: unproject inverts project
    np.testing.assert_allclose(camera.unproject(film[seen], depth[seen]), points[seen], atol=1e-9)


def test_k_and_fields_of_view_are_the_pinholes(points):
    camera = obscura.Camera.perspective(fov=55, width=640, height=480)
    f = 240 / np.tan(np.radians(27.5))
    np.testing.assert_allclose(camera.K, [[f, 0, 319.5], [0, f, 239.5], [0, 0, 1]], atol=1e-9)
    h, v = camera.fov_degrees
    assert v == pytest.approx(55)
    assert h == pytest.approx(2 * np.degrees(np.arctan(320 / f)))
    # from_intrinsics gives back the same K
    again = obscura.Camera.from_intrinsics(camera.K, 640, 480)
    np.testing.assert_allclose(again.K, camera.K, atol=1e-9)


def test_calibrated_camera_without_distortion_is_the_pinhole(points):
    K = np.array([[500.0, 0, 319.5], [0, 500.0, 239.5], [0, 0, 1]])
    camera = obscura.Camera.calibrated(K=K, width=640, height=480)
    film, depth = camera.project(points)
    cam_x, cam_y, depth_ref = points[:, 0], points[:, 1], -points[:, 2]
    expected = np.stack([500 * cam_x / depth_ref + 320, -500 * cam_y / depth_ref + 240], axis=1)
    seen = ~np.isnan(depth)
    np.testing.assert_allclose(film[seen], expected[seen], atol=1e-6)
    distorted = obscura.Camera.calibrated(K=K, distortion="opencv",
                                          coefficients=[-0.2, 0.05, 0, 0, 0], width=640,
                                          height=480)
    dfilm, ddepth = distorted.project(points)
    both = seen & ~np.isnan(ddepth)
    # Barrel distortion pulls points towards the centre.
    centre = np.array([320, 240])
    assert np.all(np.linalg.norm(dfilm[both] - centre, axis=1)
                  <= np.linalg.norm(film[both] - centre, axis=1) + 1e-9)


def test_orthographic_spherical_fisheye_thin_lens():
    ortho = obscura.Camera.orthographic(view_height=2, width=200, height=100)
    film, depth = ortho.project(np.array([[1.0, 0.5, -3.0]]))
    # 2 m tall over 100 px, 4 m wide over 200 px: (1, 0.5) is 50 px right and 25 px up.
    np.testing.assert_allclose(film, [[150, 25]], atol=1e-9)
    assert depth[0] == pytest.approx(3)
    for camera in (obscura.Camera.spherical(width=200, height=100),
                   obscura.Camera.fisheye(fov=180, width=100, height=100)):
        film, depth = camera.project(np.array([[0.0, 0.0, -2.0]]))
        np.testing.assert_allclose(film, [[camera.width / 2, camera.height / 2]], atol=1e-9)
        assert depth[0] == pytest.approx(2)
    assert obscura.Camera.spherical().fov_degrees == (360, 180)
    lens = obscura.Camera.thin_lens(focus_distance=2, f_number=2, focal_length_mm=50)
    # aperture radius = f / (2 N) = 12.5 mm
    assert lens.lens_radius_m == pytest.approx(0.0125)
    assert lens.projection == "perspective"


def test_exposure():
    camera = obscura.Camera.perspective(exposure_ev=2)
    assert camera.exposure_ev == 2
    assert camera.exposure_scale == pytest.approx(4)


def test_exports_match_the_cli(cli, tmp_path):
    scene = obscura.load_scene("cornell-box")
    for fmt in ("opencv-yaml", "opencv-json", "nerf"):
        expected = cli("camera", "cornell-box", "--export", fmt).stdout
        assert scene.camera.export(fmt) == expected, fmt
    scene.camera.export("colmap", str(tmp_path / "py"))
    cli("camera", "cornell-box", "--export", "colmap", "--output", tmp_path / "cli")
    for name in ("cameras.txt", "images.txt"):
        assert (tmp_path / "py" / name).read_text() == (tmp_path / "cli" / name).read_text()


def test_fov_matches_the_cli(cli):
    out = cli("camera", "cornell-box").stdout
    camera = obscura.load_scene("cornell-box").camera
    h, v = camera.fov_degrees
    assert f"{h:.6g}° horizontal, {v:.6g}° vertical" in out
    k = camera.K
    assert f"K (OpenCV)      [{k[0, 0]:.6g} {k[0, 1]:.6g} {k[0, 2]:.6g}; 0 {k[1, 1]:.6g} {k[1, 2]:.6g}; 0 0 1]" in out


@pytest.mark.parametrize(
    "call, error",
    [
        (lambda c: c.project(np.zeros((5, 3), dtype=np.int64)), TypeError),
        (lambda c: c.project(np.zeros((5, 2))), ValueError),
        (lambda c: c.project(np.zeros((5, 3, 1))), ValueError),
        (lambda c: c.project(np.zeros((5, 6))[:, ::2]), ValueError),
        (lambda c: c.project(np.full((5, 3), np.nan)), ValueError),
        (lambda c: c.project("points"), TypeError),
        (lambda c: c.unproject(np.zeros((5, 2)), np.zeros(4)), ValueError),
        (lambda c: obscura.Camera.perspective(fov=190), obscura.Error),
        (lambda c: obscura.Camera.perspective(sensor_fit="diagonal"), ValueError),
        (lambda c: obscura.Camera.calibrated(K=np.eye(3), distortion="opencv",
                                             coefficients=[1, 2, 3]), ValueError),
        (lambda c: c.export("blender"), ValueError),
        (lambda c: obscura.Camera.spherical().K, obscura.Error),
    ],
)
def test_bad_camera_input_raises(call, error):
    with pytest.raises(error):
        call(obscura.Camera.perspective())


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
@pytest.mark.parametrize("model", ["perspective", "orthographic", "fisheye"])
def test_one_non_finite_coordinate_among_many_points_raises(bad, model):
    # project checks finiteness inside its parallel loop: one bad value far from the start,
    # in either dtype, must still be reported for the whole call.
    camera = getattr(obscura.Camera, model)()
    for dtype in (np.float64, np.float32):
        points = np.tile(np.array([0.0, 0.0, -2.0], dtype=dtype), (300_000, 1))
        points[257_123, 1] = bad
        with pytest.raises(ValueError, match="finite"):
            camera.project(points)


def test_float32_points_project_as_their_float64_values(points):
    # A float32 array widens exactly to float64, so both dtypes give the same raster points.
    for camera in (obscura.Camera.perspective(fov=55), obscura.Camera.spherical()):
        single = points.astype(np.float32)
        film32, depth32 = camera.project(single)
        film64, depth64 = camera.project(single.astype(np.float64))
        assert np.array_equal(film32, film64, equal_nan=True)
        assert np.array_equal(depth32, depth64, equal_nan=True)
