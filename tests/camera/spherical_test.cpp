// Equirectangular and equidistant fisheye cameras: known directions at known film points.
#include "obscura/camera/spherical.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "obscura/camera/camera.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

constexpr double kPi = std::numbers::pi;

void expect_direction(std::optional<CameraRay> ray, Vector3d expected) {
  ASSERT_TRUE(ray);
  expected = normalize(expected);
  EXPECT_NEAR(ray->direction.x, expected.x, 1e-12);
  EXPECT_NEAR(ray->direction.y, expected.y, 1e-12);
  EXPECT_NEAR(ray->direction.z, expected.z, 1e-12);
}

TEST(Equirectangular, LooksForwardAtTheCentreAndAroundAtTheEdges) {
  Camera c;
  c.projection = Equirectangular{};
  c.film.width_px = 400;
  c.film.height_px = 200;
  expect_direction(c.generate_ray({200, 100}), {0, 0, -1});  // centre: forward
  expect_direction(c.generate_ray({300, 100}), {1, 0, 0});   // three quarters: right
  expect_direction(c.generate_ray({100, 100}), {-1, 0, 0});  // one quarter: left
  expect_direction(c.generate_ray({0, 100}), {0, 0, 1});     // left edge: behind
  expect_direction(c.generate_ray({200, 0}), {0, 1, 0});     // top: up
  expect_direction(c.generate_ray({200, 50}), {0, 1, -1});   // 45° up
}

TEST(Fisheye, AngleGrowsLinearlyWithRadius) {
  Camera c;
  c.projection = Fisheye{.fov_degrees = 180};
  c.film.width_px = 300;
  c.film.height_px = 200;  // circle radius 100 px around (150, 100)
  expect_direction(c.generate_ray({150, 100}), {0, 0, -1});
  expect_direction(c.generate_ray({250, 100}), {1, 0, 0});  // the rim: 90° right
  expect_direction(c.generate_ray({150, 50}), {0, 1, -1});  // half-way up: 45°
  // 30° at a third of the radius, to the lower left at 45°.
  double r = 100.0 / 3, d = r / std::sqrt(2.0);
  double s = std::sin(kPi / 6);
  expect_direction(c.generate_ray({150 - d, 100 + d}),
                   {-s / std::sqrt(2.0), -s / std::sqrt(2.0), -std::cos(kPi / 6)});
  EXPECT_FALSE(c.generate_ray({260, 100}));  // outside the circle
  EXPECT_FALSE(c.generate_ray({5, 5}));
  EXPECT_FALSE(c.project({0, 0, 1}));  // behind a 180° fisheye
}

TEST(Fisheye, RejectsFieldOfViewOutOfRange) {
  EXPECT_THROW(validate(Fisheye{.fov_degrees = 0}), Error);
  EXPECT_THROW(validate(Fisheye{.fov_degrees = 361}), Error);
  EXPECT_NO_THROW(validate(Fisheye{.fov_degrees = 360}));
}

}  // namespace
}  // namespace obscura
