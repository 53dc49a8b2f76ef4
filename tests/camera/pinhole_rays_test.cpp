// The tracer's single-precision camera rays: the directions and clipping distances of a
// perspective pinhole, against the lens geometry and against the double-precision camera.
#include "obscura/camera/pinhole_rays.h"

#include <gtest/gtest.h>

#include <cmath>

#include "obscura/camera/frames.h"

namespace obscura {
namespace {

Camera full_frame_camera(Point3d eye, Point3d target) {
  Camera c;
  Perspective lens;
  lens.focal_length_mm = 50;
  lens.sensor_width_mm = 36;
  lens.sensor_height_mm = 24;
  c.projection = lens;
  c.film.width_px = 300;
  c.film.height_px = 200;
  c.near_m = 0.25;
  c.far_m = 40;
  c.world_from_camera = AnimatedTransform(world_from_camera_look_at(eye, target));
  return c;
}

TEST(PinholeRays, DirectionsFollowTheSensorGeometry) {
  // Looking down −Z from the origin: the film centre looks straight ahead, the middle of the
  // left edge 18 mm off-axis at 50 mm, the top-right corner (18, 12) mm off-axis.
  Camera c = full_frame_camera({0, 0, 0}, {0, 0, -1});
  std::optional<PinholeRays> rays = PinholeRays::of(c);
  ASSERT_TRUE(rays);
  Ray centre = rays->generate({150, 100}, 0);
  EXPECT_NEAR(centre.direction.x, 0, 1e-7);
  EXPECT_NEAR(centre.direction.y, 0, 1e-7);
  EXPECT_NEAR(centre.direction.z, -1, 1e-7);
  EXPECT_NEAR(centre.t_min, 0.25, 1e-7);  // the near plane, straight ahead
  EXPECT_NEAR(centre.t_max, 40, 1e-5);

  Ray left = rays->generate({0, 100}, 0);
  double length = std::hypot(18.0, 50.0);
  EXPECT_NEAR(left.direction.x, -18 / length, 1e-6);
  EXPECT_NEAR(left.direction.z, -50 / length, 1e-6);
  // Planes of constant depth: the slanted ray reaches them further along.
  EXPECT_NEAR(left.t_min, 0.25 * length / 50, 1e-6);

  Ray corner = rays->generate({300, 0}, 0);
  double corner_length = std::sqrt(18.0 * 18 + 12 * 12 + 50 * 50);
  EXPECT_NEAR(corner.direction.x, 18 / corner_length, 1e-6);
  EXPECT_NEAR(corner.direction.y, 12 / corner_length, 1e-6);
  EXPECT_NEAR(corner.direction.z, -50 / corner_length, 1e-6);
}

TEST(PinholeRays, AgreeWithTheCameraToFloatRounding) {
  Camera c = full_frame_camera({1.5, -2, 3}, {-0.3, 0.7, -1.1});
  auto& p = std::get<Perspective>(c.projection);
  p.lens_shift = {0.1, -0.05};
  std::optional<PinholeRays> rays = PinholeRays::of(c);
  ASSERT_TRUE(rays);
  for (double x : {0.0, 0.37, 77.5, 150.0, 299.99})
    for (double y : {0.0, 12.25, 100.0, 199.5}) {
      std::optional<CameraRay> expected = c.generate_ray({x, y});
      ASSERT_TRUE(expected);
      Ray ray = rays->generate({x, y}, 0.125);
      EXPECT_NEAR(ray.origin.x, expected->origin.x, 1e-6);
      EXPECT_NEAR(ray.origin.y, expected->origin.y, 1e-6);
      EXPECT_NEAR(ray.origin.z, expected->origin.z, 1e-6);
      EXPECT_NEAR(ray.direction.x, expected->direction.x, 2e-7);
      EXPECT_NEAR(ray.direction.y, expected->direction.y, 2e-7);
      EXPECT_NEAR(ray.direction.z, expected->direction.z, 2e-7);
      EXPECT_NEAR(ray.t_min, expected->t_min, 1e-6);
      EXPECT_NEAR(ray.t_max, expected->t_max, 1e-4);
      EXPECT_EQ(ray.time, 0.125f);
    }
}

TEST(PinholeRays, OnlyForAStillPerspectivePinhole) {
  Camera c = full_frame_camera({0, 0, 0}, {0, 0, -1});
  Camera lens = c;
  lens.lens.depth_of_field = true;
  EXPECT_FALSE(PinholeRays::of(lens));
  Camera moving = c;
  moving.world_from_camera =
      AnimatedTransform({{0, world_from_camera_look_at({0, 0, 0}, {0, 0, -1})},
                         {1, world_from_camera_look_at({1, 0, 0}, {1, 0, -1})}});
  EXPECT_FALSE(PinholeRays::of(moving));
  Camera ortho = c;
  ortho.projection = Orthographic{};
  EXPECT_FALSE(PinholeRays::of(ortho));
}

}  // namespace
}  // namespace obscura
