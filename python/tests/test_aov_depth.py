"""The depth and range AOVs follow ground truth's names (docs/tracer.md's AOV table): `depth` is
depth along the camera's optical axis (ground truth's Z, what Camera.unproject takes for planar
projections), `range` the distance along the ray (ground truth's `range`).

The references are independent of the AOV code: ground truth (the tracer's, for both renderers)
traces one ray per pixel centre and
reports the exact position P it meets, and the scene is three walls facing the camera at known
depths, so the expected depth of every pixel is the depth of the wall it sees (2, 3 or 5 m) and
its range |P − camera|. The tracer renders with a box filter 1e-4 px wide, so that all its
samples go through the pixel centre (to 1e-4 px) like ground truth's ray; the rasterizer takes
the pixel centre anyway."""

import numpy as np
import pytest

import obscura

W, H = 64, 48
WALL_DEPTHS = (5.0, 3.0, 2.0)  # instance 0, 1, 2
TOLERANCE_M = 1e-4             # positions within a scene 5 m deep


def walls_scene():
    scene = obscura.Scene()
    scene.add_material("diffuse", color=(0.6, 0.6, 0.6))
    quads = [(-40.0, 40.0, -40.0, 40.0, -5.0),   # x0, x1, y0, y1, z: the back wall
             (-1.2, 0.4, -0.9, 0.6, -3.0),       # a panel off centre
             (0.1, 0.9, -0.2, 0.5, -2.0)]        # a smaller one nearer, overlapping it
    for x0, x1, y0, y1, z in quads:
        positions = np.array([[x0, y0, z], [x1, y0, z], [x1, y1, z], [x0, y1, z]], np.float32)
        # Counter-clockwise seen from +Z: facing the camera at the origin.
        scene.add_mesh(positions, np.array([0, 1, 2, 0, 2, 3], np.uint32))
    scene.add_point_light((0.0, 1.0, 0.0), intensity=(20, 20, 20))
    return scene


def cameras():
    pose = dict(position=(0.0, 0.0, 0.0), look_at=(0.0, 0.0, -1.0))
    K = [[52.0, 0, 31.3], [0, 53.0, 24.6], [0, 0, 1]]
    return {
        "pinhole": obscura.Camera.perspective(fov=70, width=W, height=H, **pose),
        "opencv": obscura.Camera.calibrated(K, distortion="opencv",
                                            coefficients=[-0.28, 0.09, 0.002, -0.003],
                                            width=W, height=H, **pose),
        "fisheye": obscura.Camera.fisheye(fov=180, width=W, height=H, **pose),
        # Its rays start on the plane z = 0: range and depth are one.
        "orthographic": obscura.Camera.orthographic(view_height=3.0, width=W, height=H, **pose),
    }


def render_aovs(scene, camera, renderer):
    scene.camera = camera
    if renderer == "path":
        # Every sample through the pixel centre: the tracer's means are the centre's values.
        camera = obscura.resolve_camera(scene, filter="box", filter_radius=1e-4)
        assert camera.projection == scene.camera.projection
    result = obscura.render(scene, camera, renderer=renderer, spp=4, seed=1, threads=2,
                            aovs=["depth", "range", "id"])
    return camera, result.aovs


@pytest.mark.parametrize("renderer", ["path", "raster"])
@pytest.mark.parametrize("name", ["pinhole", "opencv", "fisheye", "orthographic"])
def test_depth_is_ground_truth_z_and_range_is_ground_truth_range(name, renderer):
    scene = walls_scene()
    camera, aovs = render_aovs(scene, cameras()[name], renderer)
    # The tracer's ground truth for both: the rasterizer's is only for matrix cameras.
    gt = obscura.ground_truth(scene, camera, renderer="path")
    instance = gt["instance"][..., 0].astype(int)
    depth, rng, ids = aovs["depth"][..., 0], aovs["range"][..., 0], aovs["id"][..., 0]

    # Away from the walls' edges (where a pixel straddles two walls, or a wall and nothing, and
    # the rasterizer's lens views look up to a view pixel aside), each pixel sees what ground
    # truth sees: the same wall, or nothing (+inf in both AOVs).
    same = np.full(instance.shape, True)
    for dy, dx in ((0, 1), (0, -1), (1, 0), (-1, 0)):
        same &= np.roll(instance, (dy, dx), axis=(0, 1)) == instance
    same[0, :] = same[-1, :] = same[:, 0] = same[:, -1] = False
    miss = instance < 0
    assert np.array_equal(miss[same], ~np.isfinite(depth[same]))
    assert np.array_equal(miss[same], ~np.isfinite(rng[same]))
    assert np.array_equal(ids[same], instance[same])
    inner = same & ~miss
    assert inner.sum() > (0.3 if name == "fisheye" else 0.4) * W * H

    # depth: the seen wall's depth, and ground truth's Z.
    expected_depth = np.array(WALL_DEPTHS)[instance[inner]]
    np.testing.assert_allclose(depth[inner], expected_depth, rtol=0, atol=TOLERANCE_M)
    np.testing.assert_allclose(depth[inner], gt["Z"][..., 0][inner], rtol=0, atol=TOLERANCE_M)
    # range: the distance to ground truth's point from the camera (from the plane z = 0, where
    # an orthographic camera's rays start).
    P = gt["P"][inner].astype(np.float64)
    expected_range = -P[:, 2] if name == "orthographic" else np.linalg.norm(P, axis=1)
    np.testing.assert_allclose(rng[inner], expected_range, rtol=0, atol=TOLERANCE_M)
    np.testing.assert_allclose(rng[inner], gt["range"][..., 0][inner], rtol=0, atol=TOLERANCE_M)

    # unproject puts the pixel centres back on ground truth's points. Planar projections take
    # depth along the axis; spherical ones (the fisheye) take the distance from the camera
    # (Camera.project's depth for them, docs/camera.md), which is the range AOV.
    ys, xs = np.nonzero(inner)
    film = np.stack([xs + 0.5, ys + 0.5], axis=1)
    along = rng if name == "fisheye" else depth
    world = camera.unproject(film, along[inner].astype(np.float64))
    assert np.max(np.abs(world - P)) <= TOLERANCE_M
    # The depth AOV is the unprojected point's depth along the axis for every projection.
    np.testing.assert_allclose(-world[:, 2], depth[inner], rtol=0, atol=TOLERANCE_M)


def test_unproject_of_the_range_misplaces_points_off_axis():
    # Why the names matter: the old depth AOV (now range) read as depth puts a pinhole's points
    # behind the wall, by |P|·(1 − cos θ): centimetres at the frame's corners.
    scene = walls_scene()
    camera, aovs = render_aovs(scene, cameras()["pinhole"], "raster")
    gt = obscura.ground_truth(scene, camera, renderer="raster")
    rng = aovs["range"][..., 0]
    corner = (2, 2)
    world = camera.unproject(np.array([[corner[1] + 0.5, corner[0] + 0.5]]),
                             np.array([rng[corner]], np.float64))
    assert np.linalg.norm(world[0] - gt["P"][corner]) > 0.5
