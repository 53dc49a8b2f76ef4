// The thin lens's mechanical vignetting against geometry: seen from a film point's focus point,
// the barrel's opening projects onto the aperture plane as a disc (similar triangles, derived
// below), so the lens samples whose rays pass are the intersection of two discs, the cat-eye,
// whose area is the classic lens-shaped overlap computed here in closed form.
#include "obscura/camera/vignetting.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "obscura/camera/camera.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

constexpr double kPi = std::numbers::pi;

// Area of the intersection of two discs of radii r1, r2 whose centres are d apart.
double overlap_area(double r1, double r2, double d) {
  if (d >= r1 + r2) return 0;
  if (d <= std::abs(r1 - r2)) return kPi * std::pow(std::min(r1, r2), 2);
  double a1 = r1 * r1 * std::acos((d * d + r1 * r1 - r2 * r2) / (2 * d * r1));
  double a2 = r2 * r2 * std::acos((d * d + r2 * r2 - r1 * r1) / (2 * d * r2));
  double kite = 0.5 * std::sqrt((-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2) * (d + r1 + r2));
  return a1 + a2 - kite;
}

// 35 mm f/2 (aperture 17.5 mm) on 36 × 24 mm, 300 × 200 pixels, focused at 3 m; a barrel of
// 24 mm diameter 30 mm in front of the aperture.
Camera barrel_camera(bool depth_of_field) {
  Camera c;
  Perspective lens;
  lens.focal_length_mm = 35;
  c.projection = lens;
  c.film.width_px = 300;
  c.film.height_px = 200;
  c.lens.depth_of_field = depth_of_field;
  c.lens.f_number = 2;
  c.lens.focus_distance_m = 3;
  c.lens.vignetting = {.barrel_diameter_mm = 24, .barrel_distance_mm = 30};
  c.validate();
  return c;
}

// The kept area in the aperture plane for a film point whose chief ray has tangent t = |w|:
// the ray from lens point l to the focus point F = (w·S, −S) crosses the barrel plane z = −D at
// l + (F − l)·D/S; inside the barrel |·| ≤ B/2 means |l − (−w·D/(1 − D/S))| ≤ (B/2)/(1 − D/S).
double expected_kept_area_mm2(double t) {
  const double aperture_radius = 17.5 / 2, b = 24, d = 30, s = 3000;
  const double k = 1 - d / s;
  return overlap_area(aperture_radius, 0.5 * b / k, t * d / k);
}

TEST(Vignetting, CatEyeAreaOfTheKeptLensSamplesIsTheOverlapOfTwoDiscs) {
  const Camera c = barrel_camera(true);
  const PreparedCamera prepared = c.prepare();
  const double aperture_area = kPi * std::pow(17.5 / 2, 2);
  // Film points on the diagonal towards the corner, and along x.
  for (Point2d film_point : {Point2d(150, 100), Point2d(260, 100), Point2d(290, 190),
                             Point2d(10, 5), Point2d(200, 150)}) {
    Point2d w = c.window_from_raster(film_point);
    const int n = 200;  // stratified lens samples; the aperture map preserves area
    int kept = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        auto ray = prepared.generate_ray(film_point, {(i + 0.5) / n, (j + 0.5) / n});
        ASSERT_TRUE(ray);
        kept += ray->weight > 0;
      }
    double measured = aperture_area * kept / (n * n);
    double expected = expected_kept_area_mm2(std::hypot(w.x, w.y));
    EXPECT_NEAR(measured, expected, 0.02 * aperture_area)
        << "film point " << film_point.x << "," << film_point.y;
    // The camera's integrated share (its pinhole renders and the rasterizer) agrees too.
    EXPECT_NEAR(c.relative_illumination(film_point), expected / aperture_area, 0.005);
  }
  // The centre is not clipped, the far corner is.
  EXPECT_EQ(c.relative_illumination({150, 100}), 1.0);
  EXPECT_LT(c.relative_illumination({299, 199}), 0.8);
}

TEST(Vignetting, KeptSamplesFormACatEyeOffAxis) {
  // Off axis the kept region is the aperture cut by a disc shifted against the film point's
  // direction w: lens points on the side opposite w survive (their rays cross the axis on the
  // way to the barrel), those on w's side are stopped.
  const Camera c = barrel_camera(true);
  Point2d corner(230, 150);  // lower right: window w has x > 0, y < 0
  Point2d w = c.window_from_raster(corner);
  ASSERT_GT(w.x, 0);
  int kept_opposite = 0, kept_same = 0;
  for (int i = 0; i < 100; ++i) {
    double a = 2 * kPi * (i + 0.5) / 100, r = 0.95;
    Point2d u(0.5 + 0.5 * r * std::cos(a), 0.5 + 0.5 * r * std::sin(a));  // near the rim
    auto ray = c.generate_ray(corner, u);
    Point2d l(ray->origin.x, ray->origin.y);  // camera at the origin, unrotated
    bool kept = ray->weight > 0;
    (l.x * w.x + l.y * w.y < 0 ? kept_opposite : kept_same) += kept;
  }
  EXPECT_GT(kept_opposite, 35);
  EXPECT_LT(kept_same, 10);
}

TEST(Vignetting, NaturalIsCosineToTheFourth) {
  for (double degrees : {0.0, 10.0, 30.0, 45.0, 60.0}) {
    double t = std::tan(degrees * kPi / 180);
    double c4 = std::pow(std::cos(degrees * kPi / 180), 4);
    EXPECT_NEAR(natural_vignetting({t / std::sqrt(2.0), t / std::sqrt(2.0)}), c4, 1e-12);
  }
}

TEST(Vignetting, RejectsABarrelThatWouldBeTheAperture) {
  Camera c = barrel_camera(true);
  c.lens.vignetting.barrel_diameter_mm = 10;  // < 17.5 mm
  EXPECT_THROW(c.validate(), Error);
  c = barrel_camera(true);
  c.lens.vignetting.barrel_distance_mm = -1;
  EXPECT_THROW(c.validate(), Error);
  c = barrel_camera(true);
  c.lens.vignetting.barrel_distance_mm = 4000;  // beyond the focus plane
  EXPECT_THROW(c.validate(), Error);
}

TEST(Vignetting, BladedApertureChordsCoverItsArea) {
  for (int blades : {5, 6, 9}) {
    Aperture a{.blades = blades, .rotation_degrees = 7};
    double area = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      auto [low, high] = aperture_chord(a, -1 + (i + 0.5) * 2.0 / n);
      if (high > low) area += (high - low) * 2.0 / n;
    }
    EXPECT_NEAR(area, 0.5 * blades * std::sin(2 * kPi / blades), 1e-4) << blades;
  }
}

}  // namespace
}  // namespace obscura
