// Projection of arrays of points against the one-point Camera::project / unproject (the same
// doubles, point for point, for every model and thread count) and against the pinhole formula
// written here.
#include "obscura/camera/point_projection.h"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "obscura/camera/frames.h"

namespace obscura {
namespace {

Camera camera_with(Projection projection) {
  Camera c;
  c.projection = projection;
  c.film.width_px = 320;
  c.film.height_px = 240;
  c.world_from_camera = AnimatedTransform(world_from_camera_look_at({1, 2, 3}, {0, 0, -1}));
  return c;
}

std::vector<double> random_points(size_t n) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-4, 4);
  std::vector<double> p(3 * n);
  for (double& x : p) x = u(rng);
  return p;
}

bool same_double(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) || a == b;
}

TEST(PointProjection, EqualsCameraProjectPointForPointForEveryModel) {
  const size_t n = 20000;  // several parallel chunks
  const std::vector<double> world = random_points(n);
  const Projection models[] = {Perspective::from_vertical_fov_degrees(60), Orthographic{},
                               Equirectangular{}};
  for (const Projection& model : models) {
    const Camera camera = camera_with(model);
    std::vector<double> film(2 * n), depth(n);
    ASSERT_TRUE(project_points(camera, world.data(), n, 0.0, film.data(), depth.data()));
    size_t seen = 0;
    for (size_t i = 0; i < n; ++i) {
      auto one = camera.project({world[3 * i], world[3 * i + 1], world[3 * i + 2]});
      const double x = one ? one->film_point.x : NAN, y = one ? one->film_point.y : NAN;
      const double d = one ? one->depth_m : NAN;
      ASSERT_TRUE(same_double(film[2 * i], x) && same_double(film[2 * i + 1], y) &&
                  same_double(depth[i], d))
          << "point " << i;
      seen += one.has_value();
    }
    EXPECT_GT(seen, n / 20);  // the comparison is not only between misses

    std::vector<double> back(3 * n);
    unproject_points(camera, film.data(), depth.data(), n, 0.0, back.data());
    for (size_t i = 0; i < n; ++i) {
      if (std::isnan(depth[i])) continue;
      auto one = camera.unproject({film[2 * i], film[2 * i + 1]}, depth[i]);
      ASSERT_TRUE(one);
      for (int k = 0; k < 3; ++k) ASSERT_TRUE(same_double(back[3 * i + k], (*one)[k]));
    }
  }
}

// A camera at the origin looking down −Z with vertical FOV 90° on 320 × 240: the pinhole maps
// (x, y, z) to (160 + 120·x/−z, 120 − 120·y/−z).
TEST(PointProjection, PerspectiveFollowsThePinholeFormula) {
  Camera camera;
  camera.projection = Perspective::from_vertical_fov_degrees(90);
  camera.film.width_px = 320;
  camera.film.height_px = 240;
  const std::vector<double> world = {0.5, -0.25, -2, 0, 0, -5, 3, 0, -1 /* outside the frame */};
  std::vector<double> film(6), depth(3);
  ASSERT_TRUE(project_points(camera, world.data(), 3, 0.0, film.data(), depth.data()));
  EXPECT_NEAR(film[0], 160 + 120 * 0.25, 1e-9);
  EXPECT_NEAR(film[1], 120 + 120 * 0.125, 1e-9);
  EXPECT_EQ(depth[0], 2);
  EXPECT_NEAR(film[2], 160, 1e-9);
  EXPECT_NEAR(film[3], 120, 1e-9);
  EXPECT_TRUE(std::isnan(film[4]) && std::isnan(film[5]) && std::isnan(depth[2]));
}

TEST(PointProjection, SameResultsForAnyThreadCountAndNonFiniteInputReported) {
  const size_t n = 50000;
  std::vector<double> world = random_points(n);
  const Camera camera = camera_with(Perspective::from_vertical_fov_degrees(50));
  std::vector<double> many(2 * n), many_depth(n), one(2 * n), one_depth(n);
  project_points(camera, world.data(), n, 0.0, many.data(), many_depth.data());
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    project_points(camera, world.data(), n, 0.0, one.data(), one_depth.data());
  }
  for (size_t i = 0; i < 2 * n; ++i) ASSERT_TRUE(same_double(many[i], one[i]));
  world[3 * 31337 + 1] = NAN;
  EXPECT_FALSE(project_points(camera, world.data(), n, 0.0, many.data(), many_depth.data()));
  EXPECT_TRUE(std::isnan(many[2 * 31337]) && std::isnan(many_depth[31337]));
}

}  // namespace
}  // namespace obscura
