// The rasterizer's lens views against the tracer's rays: for a lens sample and a time, the
// sheared matrices must put every point on the pixel whose ray through that lens point (from
// Camera::generate_ray, an independent path through the code) passes through it.
#include "obscura/camera/lens_view.h"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "obscura/camera/frames.h"
#include "obscura/math/error.h"
#include "obscura/math/rng.h"

namespace obscura {
namespace {

Point2d raster_by_matrices(const Camera& c, const LensView& v, Point3d p) {
  Vector4d h = c.raster_from_ndc() * v.projection * v.view * Vector4d(p.x, p.y, p.z, 1);
  return {h.x / h.w, h.y / h.w};
}

double distance_to_ray(const CameraRay& ray, Point3d p) {
  Vector3d to_p = p - ray.origin;
  return length(to_p - ray.direction * dot(to_p, ray.direction));
}

// Off-axis, shifted, non-square pixels, a wide-open lens focused close, moving over the shutter.
Camera thin_lens_camera(int blades, bool focus_breathing = true) {
  Camera c;
  Perspective p;
  p.focal_length_mm = 35;
  p.lens_shift = {0.07, -0.04};
  c.projection = p;
  c.film.width_px = 320;
  c.film.height_px = 200;
  c.film.pixel_aspect = 1.1;
  c.near_m = 0.1;
  c.far_m = 100;
  c.lens.depth_of_field = true;
  c.lens.f_number = 1.4;
  c.lens.focus_distance_m = 2.5;
  c.lens.aperture = {.blades = blades, .rotation_degrees = 17};
  c.lens.focus_breathing = focus_breathing;
  c.shutter = {.open_s = 0, .close_s = 0.02};
  Transform start = world_from_camera_look_at({1, 1.2, 3}, {-0.3, 0.4, -1}, {0.1, 1, 0});
  c.world_from_camera = AnimatedTransform(
      {{0.0, start},
       {0.02, Transform::translate({0.3, 0, -0.2}) * start * Transform::rotate_y(0.1)}});
  return c;
}

TEST(LensView, APointOnTheFocusPlaneLandsOnOnePixelForEveryLensPoint) {
  for (int blades : {0, 6}) {
    Camera c = thin_lens_camera(blades, /*focus_breathing=*/blades == 0);
    Pcg32 rng(11);
    for (int i = 0; i < 200; ++i) {
      double t = rng.next_float() * 0.02;
      Point2d film(rng.next_float() * 320, rng.next_float() * 200);
      Point3d on_focus_plane = *c.unproject(film, c.lens.focus_distance_m, t);
      for (int k = 0; k < 8; ++k) {
        Point2d u(rng.next_float(), rng.next_float());
        Point2d raster = raster_by_matrices(c, lens_view(c, u, t), on_focus_plane);
        EXPECT_NEAR(raster.x, film.x, 1e-6) << "blades " << blades << " lens " << u.x << "," << u.y;
        EXPECT_NEAR(raster.y, film.y, 1e-6);
      }
    }
  }
}

TEST(LensView, AnyPointLandsWhereTheTracersRayThroughThatLensPointSeesIt) {
  // Both sensor conventions: at the image distance v (breathing) and at f (Cycles, pbrt).
  struct Case {
    int blades;
    bool breathing;
  };
  for (Case k : {Case{0, true}, Case{5, true}, Case{0, false}}) {
    const int blades = k.blades;
    Camera c = thin_lens_camera(blades, k.breathing);
    Pcg32 rng(3);
    double worst_m = 0;
    for (int i = 0; i < 2000; ++i) {
      double t = rng.next_float() * 0.02;
      Point2d u(rng.next_float(), rng.next_float());
      // A point anywhere in the view volume, mostly far off the focus plane.
      Point2d film(rng.next_float() * 320, rng.next_float() * 200);
      double depth = 0.3 + rng.next_float() * 40;
      Point3d p = *c.unproject(film, depth, t);
      Point2d raster = raster_by_matrices(c, lens_view(c, u, t), p);
      auto ray = c.generate_ray(raster, u, t);
      ASSERT_TRUE(ray);
      // The ray through the matrices' pixel from the same lens point passes through p.
      worst_m = std::max(worst_m, distance_to_ray(*ray, p) / depth);
    }
    EXPECT_LT(worst_m, 1e-9) << "blades " << blades << " breathing " << k.breathing;
  }
}

TEST(LensView, TheEyeSitsAtTheLensPointAndLooksAlongTheCamerasAxis) {
  Camera c = thin_lens_camera(0);
  Point2d u(0.9, 0.2);
  double t = 0.013;
  LensView v = lens_view(c, u, t);
  // The tracer's ray from that lens point starts at the eye.
  auto ray = c.generate_ray({100, 50}, u, t);
  ASSERT_TRUE(ray);
  EXPECT_NEAR(length(ray->origin - v.eye_world), 0, 1e-12);
  // glm's lookAt from the eye along the camera's axis at time t gives the same view matrix.
  Transform world = c.world_from_camera.at(t);
  Point3d target = v.eye_world + world(Vector3d(0, 0, -1));
  Vector3d up = world(Vector3d(0, 1, 0));
  glm::dmat4 ref =
      glm::lookAt(glm::dvec3(v.eye_world.x, v.eye_world.y, v.eye_world.z),
                  glm::dvec3(target.x, target.y, target.z), glm::dvec3(up.x, up.y, up.z));
  for (int r = 0; r < 4; ++r)
    for (int col = 0; col < 4; ++col) EXPECT_NEAR(v.view[r][col], ref[col][r], 1e-12);
  // The lens point is within the aperture's radius, A/2 = 35 / 1.4 / 2 mm.
  EXPECT_LE(std::hypot(v.lens_point_m.x, v.lens_point_m.y), 0.0125 + 1e-15);
}

TEST(LensView, WithoutDepthOfFieldEveryLensSampleIsThePinhole) {
  Camera c = thin_lens_camera(0);
  c.lens.depth_of_field = false;
  for (Point2d u : {Point2d(0.1, 0.9), Point2d(0.5, 0.5)}) {
    LensView v = lens_view(c, u, 0.01);
    EXPECT_EQ(v.view, c.view_matrix(0.01));
    EXPECT_EQ(v.projection, c.projection_matrix());
  }
}

TEST(LensView, SphericalCamerasHaveNoMatrices) {
  Camera c;
  c.projection = Equirectangular{};
  EXPECT_THROW(lens_view(c, {0.5, 0.5}), Error);
}

}  // namespace
}  // namespace obscura
