// Depth of field: points on the focus plane stay sharp for every lens sample; points off it
// spread over a disk whose diameter is the photographic circle of confusion
//   c = A · |S − S_f| / S · f / (S_f − f).
#include "obscura/camera/thin_lens.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "obscura/camera/camera.h"
#include "obscura/camera/frames.h"
#include "obscura/math/error.h"
#include "obscura/math/rng.h"

namespace obscura {
namespace {

// 50 mm f/2 (A = 25 mm) on 36 × 24 mm at 1200 × 800, focused at 2 m, placed off the origin.
Camera lens_camera() {
  Camera c;
  c.projection = Perspective{};
  c.film.width_px = 1200;
  c.film.height_px = 800;
  c.lens.depth_of_field = true;
  c.lens.f_number = 2;
  c.lens.focus_distance_m = 2;
  c.world_from_camera = world_from_camera_look_at({0.5, 1, 2}, {0.5, 1, -10});
  return c;
}

double distance_to_ray(const CameraRay& ray, Point3d p) {
  Vector3d to_p = p - ray.origin;
  return length(to_p - ray.direction * dot(to_p, ray.direction));
}

TEST(ThinLens, FocusPlanePointsConvergeForEveryLensSample) {
  Camera c = lens_camera();
  Point3d world = *c.unproject({300, 500}, 2.0);  // on the focus plane
  Point2d film = c.project(world)->film_point;
  Pcg32 rng(1);
  for (int i = 0; i < 1000; ++i) {
    Point2d u(rng.next_float(), rng.next_float());
    auto ray = c.generate_ray(film, u);
    ASSERT_TRUE(ray);
    EXPECT_LT(distance_to_ray(*ray, world), 1e-12);
  }
}

// For lens sample u, the film point whose ray passes through `world`: the ray from the lens
// point aims at the focus-plane point it crosses, and generate_ray must confirm it.
Point2d film_point_seeing(const Camera& c, Point3d world, Point2d u) {
  CameraRay any = *c.generate_ray({0, 0}, u);
  Point3d lens_point = inverse(c.world_from_camera.at(0))(any.origin);
  Point3d p = inverse(c.world_from_camera.at(0))(world);
  double s = (-c.lens.focus_distance_m - lens_point.z) / (p.z - lens_point.z);
  Point3d on_focus_plane = lens_point + (p - lens_point) * s;
  Point2d film = c.raster_from_window(
      {on_focus_plane.x / c.lens.focus_distance_m, on_focus_plane.y / c.lens.focus_distance_m});
  EXPECT_LT(distance_to_ray(*c.generate_ray(film, u), world), 1e-9);
  return film;
}

// The spread of a point's image over the aperture's rim, in mm on a 36 mm-wide sensor.
double defocus_spread_mm(const Camera& c, double depth) {
  Point3d world = *c.unproject({600, 400}, depth);
  // Lens samples on the rim of the square map to the rim of the aperture: the spread's diameter
  // is the largest distance between two of their film points.
  std::vector<Point2d> rim;
  for (int i = 0; i < 64; ++i) {
    double s = (i + 0.5) / 64;
    rim.push_back(film_point_seeing(c, world, {s, 0}));
    rim.push_back(film_point_seeing(c, world, {0, s}));
  }
  double diameter_px = 0;
  for (Point2d a : rim)
    for (Point2d b : rim) diameter_px = std::max(diameter_px, length(a - b));
  // Random interior samples stay inside the disk.
  Pcg32 rng(5);
  Point2d centre = c.project(world)->film_point;
  for (int i = 0; i < 200; ++i) {
    Point2d f = film_point_seeing(c, world, {rng.next_float(), rng.next_float()});
    EXPECT_LE(length(f - centre), 0.5 * diameter_px * (1 + 1e-9));
  }
  return diameter_px * 36.0 / 1200;
}

TEST(ThinLens, DefocusSpreadMatchesTheCircleOfConfusion) {
  Camera c = lens_camera();
  double mm_per_px = 36.0 / 1200;
  for (double depth : {0.8, 1.5, 3.0, 8.0}) {
    // The formula with A = 25 mm, f = 50 mm, S_f = 2000 mm.
    double s = depth * 1000;
    double expected_mm = 25 * std::abs(s - 2000) / s * 50 / (2000 - 50);
    EXPECT_NEAR(defocus_spread_mm(c, depth), expected_mm, expected_mm * 1e-3) << depth << " m";
    EXPECT_NEAR(circle_of_confusion_mm(c.lens, 50, depth), expected_mm, 1e-12);
    EXPECT_NEAR(c.circle_of_confusion_px(depth), expected_mm / mm_per_px, 1e-9);
  }
}

TEST(ThinLens, WithoutFocusBreathingTheFramingIsThePinholesAsInCycles) {
  // Blender Cycles' thin lens: the field of view of f on the sensor at any focus, rays from the
  // aperture (radius f / 2N) through the focus plane, so c = A · |S − S_f| / S · f / S_f.
  Camera c = lens_camera();
  c.lens.focus_breathing = false;
  Camera pinhole = lens_camera();
  pinhole.lens.depth_of_field = false;
  EXPECT_NEAR(c.fov_degrees().x, 39.597752709, 1e-8);  // 2·atan(18/50), as without the lens
  EXPECT_NEAR(c.fov_degrees().x, pinhole.fov_degrees().x, 1e-12);
  EXPECT_DOUBLE_EQ(c.image_distance_mm(), 50);
  double mm_per_px = 36.0 / 1200;
  for (double depth : {0.8, 1.5, 3.0, 8.0}) {
    double s = depth * 1000;
    double expected_mm = 25 * std::abs(s - 2000) / s * 50 / 2000;
    EXPECT_NEAR(defocus_spread_mm(c, depth), expected_mm, expected_mm * 1e-3) << depth << " m";
    EXPECT_NEAR(c.circle_of_confusion_px(depth), expected_mm / mm_per_px, 1e-9);
  }
}

TEST(ThinLens, ApertureFromFNumberOrDiameter) {
  ThinLens lens;
  lens.f_number = 1.8;
  EXPECT_NEAR(aperture_diameter_mm(lens, 50), 27.777777777777, 1e-9);
  lens.aperture_diameter_mm = 10;
  EXPECT_DOUBLE_EQ(aperture_diameter_mm(lens, 50), 10);
  EXPECT_DOUBLE_EQ(effective_f_number(lens, 50), 5);
}

TEST(ThinLens, SensorSitsAtTheImageDistance) {
  // 1/f = 1/S_f + 1/v: f = 50 mm focused at 1 m → v = 50·1000/950 = 52.6316 mm.
  EXPECT_NEAR(image_distance_mm(50, 1), 52.631578947, 1e-8);
  EXPECT_DOUBLE_EQ(image_distance_mm(50, std::numeric_limits<double>::infinity()), 50);
}

TEST(ThinLens, RejectsBadParametersNamingThem) {
  auto message = [](ThinLens lens) -> std::string {
    try {
      validate(lens, 50);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  ThinLens lens;
  lens.f_number = 0;
  EXPECT_NE(message(lens).find("f_number: must be positive; got 0"), std::string::npos);
  lens = {};
  lens.f_number = -2;
  EXPECT_NE(message(lens).find("-2"), std::string::npos);
  lens = {};
  lens.focus_distance_m = 0;
  EXPECT_NE(message(lens).find("focus_distance_m"), std::string::npos);
  lens = {};
  lens.depth_of_field = true;
  lens.focus_distance_m = 0.04;  // closer than the 50 mm focal length
  EXPECT_NE(message(lens).find("must exceed the focal length"), std::string::npos);
  lens = {};
  lens.aperture.blades = 2;
  EXPECT_NE(message(lens).find("aperture_blades"), std::string::npos);
}

}  // namespace
}  // namespace obscura
