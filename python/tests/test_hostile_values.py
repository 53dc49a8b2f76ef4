"""Values that parse fine but once crashed or aborted a render (issue 32), given from Python:
each is refused with obscura.Error naming the field; none reaches Embree (which aborts on
coordinates beyond ~1.8e18) or the shading tables (NaN indices)."""

import numpy as np
import pytest

import obscura


def floor_scene():
    scene = obscura.Scene()
    grey = scene.add_material("diffuse", color=(0.5, 0.5, 0.5))
    square = np.array([[-2, 0, -2], [2, 0, -2], [2, 0, 2], [-2, 0, 2]], dtype=np.float64)
    scene.add_mesh(square, np.array([[0, 2, 1], [0, 3, 2]]), material=grey)
    scene.set_environment(color=(1, 1, 1))
    return scene


def camera(**kwargs):
    kwargs.setdefault("position", (0, 2, 6))
    return obscura.Camera.perspective(width=16, height=12, look_at=(0, 0, 0), **kwargs)


@pytest.mark.parametrize("renderer", ["path", "raster"])
@pytest.mark.parametrize("kwargs, field", [
    ({"position": (2e18, 2, 6)}, "camera.position"),
    ({"focal_length_mm": 1e-20}, "camera.focal_length_mm"),
    ({"sensor_mm": (1e300, 1e300)}, "camera.sensor_mm"),
    ({"lens_shift": (1e20, 0)}, "camera.lens_shift"),
    ({"f_number": 1e-300, "focus_distance": 6}, "camera.f_number"),
])
def test_cameras_beyond_what_rays_can_hold_are_refused(renderer, kwargs, field):
    with pytest.raises(obscura.Error, match=field.replace(".", r"\.")):
        obscura.render(floor_scene(), camera(**kwargs), renderer=renderer, spp=1)


@pytest.mark.parametrize("renderer", ["path", "raster"])
def test_scene_values_beyond_the_bounds_are_refused(renderer):
    far = floor_scene()
    translate = np.eye(4)
    translate[0, 3] = 2e7  # past the ±1e7 m bound
    far.add_mesh(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=np.float64),
                 np.array([[0, 1, 2]]), transform=translate, name="huge")
    with pytest.raises(obscura.Error, match="instance 'huge'.*single-precision"):
        obscura.render(far, camera(), renderer=renderer, spp=1)
    light = floor_scene()
    light.add_point_light((1e30, 0, 0), name="bulb")
    with pytest.raises(obscura.Error, match="light 'bulb'.*position"):
        obscura.render(light, camera(), renderer=renderer, spp=1)
    bright = floor_scene()
    bright.add_point_light((0, 2, 0), intensity=(1e38, 1e38, 1e38), name="bright")
    with pytest.raises(obscura.Error, match="light 'bright'.*intensity"):
        obscura.render(bright, camera(), renderer=renderer, spp=1)
    # The same scene within the bounds renders.
    assert np.isfinite(obscura.render(floor_scene(), camera(), renderer=renderer, spp=1).image).all()
