// Rasterizer and tracer agree: for random points in the view volume, the pixel the matrices put
// a point at is the film point whose primary ray passes through it; and for every camera type,
// project() inverts generate_ray().
#include <cmath>

#include <gtest/gtest.h>

#include "obscura/camera/camera.h"
#include "obscura/camera/frames.h"
#include "obscura/math/rng.h"

namespace obscura {
namespace {

// The raster position of a world point by the rasterizer's path: view, projection, perspective
// divide, viewport.
Point2d raster_by_matrices(const Camera& c, Point3d p) {
  Matrix4 m = c.raster_from_ndc() * c.projection_matrix() * c.view_matrix();
  Vector4d h = m * Vector4d(p.x, p.y, p.z, 1);
  return {h.x / h.w, h.y / h.w};
}

// Distance from p to the ray's line, and the parameter of the closest point.
double distance_to_ray(const CameraRay& ray, Point3d p, double* t) {
  Vector3d to_p = p - ray.origin;
  *t = dot(to_p, ray.direction);
  return length(to_p - ray.direction * *t);
}

// A camera placed off-axis, with non-square pixels and a shifted lens, so that no term hides.
Camera test_camera(Projection projection) {
  Camera c;
  c.projection = projection;
  c.film.width_px = 640;
  c.film.height_px = 360;
  c.film.pixel_aspect = 1.1;
  c.near_m = 0.2;
  c.far_m = 50;
  c.world_from_camera = world_from_camera_look_at({2, 1.5, 3}, {-0.5, 0.2, -1}, {0.2, 1, 0});
  return c;
}

TEST(CameraAgreement, MatricesAndRaysAgreeOnTenThousandPerspectivePoints) {
  Perspective p;
  p.focal_length_mm = 28;
  p.lens_shift = {0.05, -0.1};
  Camera c = test_camera(p);
  Pcg32 rng(7);
  double worst_px = 0;
  for (int i = 0; i < 10000; ++i) {
    // A random point in the frustum: a random pixel position and a random depth.
    Point2d film(rng.next_float() * 640, rng.next_float() * 360);
    double depth = 0.2 + rng.next_float() * 49.8;
    Point3d world = *c.unproject(film, depth);
    Point2d raster = raster_by_matrices(c, world);
    auto ray = c.generate_ray(raster);
    ASSERT_TRUE(ray);
    double t;
    double miss_m = distance_to_ray(*ray, world, &t);
    // The miss as an angle seen from the pinhole, in pixels: (miss / distance) · pixels per
    // tangent unit (the focal length in pixels), with the larger pixel pitch.
    ScreenWindow w = c.screen_window();
    double px_per_tangent = std::max(640 / (w.x_max - w.x_min), 360 / (w.y_max - w.y_min));
    worst_px = std::max(worst_px, miss_m / t * px_per_tangent);
  }
  EXPECT_LT(worst_px, 1e-4);
}

TEST(CameraAgreement, MatricesAndRaysAgreeOnTenThousandOrthographicPoints) {
  Camera c = test_camera(Orthographic{.view_height_m = 4, .view_width_m = std::nullopt});
  Pcg32 rng(11);
  double worst_px = 0;
  double metres_per_px = 4.0 / 360;
  for (int i = 0; i < 10000; ++i) {
    Point2d film(rng.next_float() * 640, rng.next_float() * 360);
    double depth = 0.2 + rng.next_float() * 49.8;
    Point3d world = *c.unproject(film, depth);
    auto ray = c.generate_ray(raster_by_matrices(c, world));
    ASSERT_TRUE(ray);
    double t;
    worst_px = std::max(worst_px, distance_to_ray(*ray, world, &t) / metres_per_px);
  }
  EXPECT_LT(worst_px, 1e-4);
}

// project(point on generate_ray(p)) = p for every camera type.
void expect_round_trip(const Camera& c, uint64_t seed) {
  Pcg32 rng(seed);
  int tested = 0;
  for (int i = 0; i < 2000; ++i) {
    Point2d film(rng.next_float() * c.film.width_px, rng.next_float() * c.film.height_px);
    auto ray = c.generate_ray(film);
    if (!ray) continue;  // outside a fisheye's circle
    double t =
        ray->t_min + (std::min(ray->t_max, 30.0) - ray->t_min) * (0.01 + 0.98 * rng.next_float());
    Point3d on_ray = ray->origin + ray->direction * t;
    auto projected = c.project(on_ray);
    ASSERT_TRUE(projected) << "film " << film.x << "," << film.y;
    EXPECT_NEAR(projected->film_point.x, film.x, 1e-4);
    EXPECT_NEAR(projected->film_point.y, film.y, 1e-4);
    ++tested;
  }
  EXPECT_GT(tested, 700);  // a fisheye's circle covers 40 % of this film
}

TEST(CameraAgreement, ProjectInvertsGenerateRayForEveryCameraType) {
  Perspective shifted;
  shifted.lens_shift = {-0.1, 0.05};
  expect_round_trip(test_camera(Perspective{}), 1);
  expect_round_trip(test_camera(shifted), 2);
  expect_round_trip(test_camera(Orthographic{}), 3);
  expect_round_trip(test_camera(Equirectangular{}), 4);
  expect_round_trip(test_camera(Fisheye{}), 5);
  expect_round_trip(test_camera(Fisheye{.fov_degrees = 250}), 6);
  Camera thin_lens = test_camera(Perspective{});  // at the lens centre, the default sample
  thin_lens.lens.depth_of_field = true;
  thin_lens.lens.f_number = 1.4;
  thin_lens.lens.focus_distance_m = 2;
  expect_round_trip(thin_lens, 7);
}

TEST(CameraAgreement, RoundTripHoldsAtEveryTimeOfAMovingCamera) {
  Camera c = test_camera(Perspective{});
  c.world_from_camera = AnimatedTransform(
      {{0, world_from_camera_look_at({2, 1.5, 3}, {-0.5, 0.2, -1})},
       {0.5, world_from_camera_look_at({1, 1.7, 3.5}, {0.5, 0, -1}, {0.3, 1, 0})}});
  Pcg32 rng(8);
  for (int i = 0; i < 500; ++i) {
    double time = rng.next_float() * 0.5;
    Point2d film(rng.next_float() * 640, rng.next_float() * 360);
    auto ray = c.generate_ray(film, {0.5, 0.5}, time);
    ASSERT_TRUE(ray);
    EXPECT_EQ(ray->time_s, time);
    auto projected = c.project(ray->origin + ray->direction * 3.0, time);
    ASSERT_TRUE(projected);
    EXPECT_NEAR(projected->film_point.x, film.x, 1e-4);
    EXPECT_NEAR(projected->film_point.y, film.y, 1e-4);
  }
  // The pose at mid-shutter differs from both keys: the camera really moves.
  Point3d mid = c.world_from_camera.at(0.25)(Point3d(0, 0, 0));
  EXPECT_NEAR(mid.x, 1.5, 1e-12);
  EXPECT_NEAR(mid.z, 3.25, 1e-12);
}

TEST(CameraAgreement, UnprojectInvertsProjectForEveryCameraType) {
  for (Projection p : {Projection(Perspective{}), Projection(Orthographic{}),
                       Projection(Equirectangular{}), Projection(Fisheye{})}) {
    Camera c = test_camera(p);
    Pcg32 rng(3);
    for (int i = 0; i < 200; ++i) {
      Point3d world(rng.next_float() * 4 - 2, rng.next_float() * 4 - 2, rng.next_float() * 4 - 2);
      auto projected = c.project(world);
      if (!projected) continue;
      auto back = c.unproject(projected->film_point, projected->depth_m);
      ASSERT_TRUE(back);
      EXPECT_NEAR(distance(*back, world), 0, 1e-9) << projection_name(p);
    }
  }
}

}  // namespace
}  // namespace obscura
