// The fitted camera of a lens system against references computed here: a thin element's paraxial
// focal length (the test's ABCD matrices), its stop as its centre of projection and cos⁴θ as its
// relative illumination; the built-in designs' chief rays, traced here over the whole image and
// projected through the fitted calibrated camera; the fisheye's lit field; the double-Gauss's
// barrel distortion from its traced corner against the ABCD focal length.
#include "obscura/camera/lens_system_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>

#include "camera/thin_element.h"
#include "lens_optics.h"
#include "obscura/camera/builtin_lenses.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kDegrees = std::numbers::pi / 180;
constexpr int kWidth = 1024, kHeight = 683;  // a 36 mm wide sensor: 35 µm pixels
constexpr double kSensorHeightMm = 36.0 * kHeight / kWidth;

Camera lens_camera(std::shared_ptr<const LensSystem> lens, double focus_m = kInfinity) {
  Camera c;
  LensSystemProjection projection;
  projection.lens = std::move(lens);
  projection.sensor_width_mm = 36;
  c.projection = projection;
  c.film.width_px = kWidth;
  c.film.height_px = kHeight;
  c.lens.focus_distance_m = focus_m;
  c.near_m = 1e-3;
  c.far_m = 1e12;
  c.validate();
  return c;
}

// The raster point of image point `image_mm` (x right, y up on the sensor).
Point2d raster_of(Point2d image_mm) {
  return {(image_mm.x / 36 + 0.5) * kWidth, (0.5 - image_mm.y / kSensorHeightMm) * kHeight};
}

// The paraxial image height per unit tan θ of a chief ray through a stop at the front vertex,
// on a sensor `film_mm` behind the rear vertex: the ABCD matrices take (y, n·u) = (0, u) at the
// front to (B·u, D·u) at the rear, and the ray then runs film_mm further in air.
double paraxial_chief_slope(const LensPrescription& p, double film_mm) {
  test::Matrix2 system{{{1, 0}, {0, 1}}};
  double n = 1;
  for (size_t i = 0; i < p.surfaces.size(); ++i) {
    const LensSurface& s = p.surfaces[i];
    double n_after = s.n_d;
    if (s.radius_mm != 0)
      system = test::multiply({{{1, 0}, {-(n_after - n) / s.radius_mm, 1}}}, system);
    n = n_after;
    if (i + 1 < p.surfaces.size())
      system = test::multiply({{{1, s.thickness_mm / n}, {0, 1}}}, system);
  }
  return std::abs(system[0][1] + film_mm * system[1][1]);
}

TEST(LensSystemFit, ThinElementFitsItsParaxialFocalLengthWithoutDistortionAndCosFourth) {
  auto lens = std::make_shared<const LensSystem>(test::thin_element());
  const test::ParaxialOptics optics = test::paraxial_optics(lens->prescription());
  Camera camera = lens_camera(lens);
  auto focused = focused_lens_system(lens, camera.lens_system_settings());
  FittedLensCamera fitted = fitted_lens_camera(camera);
  const LensSystemFit& fit = fitted.fit;
  ASSERT_TRUE(std::holds_alternative<PinholeDistortion>(fit.projection.lens));
  // The focal length: K's fx in sensor millimetres against the ABCD matrices' image height per
  // unit tan θ on this sensor (the best focus sits a little inside the paraxial focus, so this
  // is a little under the EFL).
  const double f_mm = fit.projection.k.fx * 36 / kWidth;
  const double paraxial = paraxial_chief_slope(lens->prescription(), focused->film_distance_mm());
  EXPECT_NEAR(f_mm, paraxial, 1e-4 * paraxial);
  EXPECT_NEAR(f_mm, optics.efl_mm, 0.01 * optics.efl_mm);
  // No distortion: a direction θ off the axis lands at f·tan θ from the centre, within 0.05 %.
  for (double degrees : {2.0, 5.0, 8.0, 9.5}) {
    const double theta = degrees * kDegrees;
    Point3d far(std::sin(theta) * 1e6, 0, -std::cos(theta) * 1e6);
    auto at = fitted.camera.project(fitted.camera.world_from_camera.at(0)(far));
    ASSERT_TRUE(at) << degrees;
    const double height_mm = (at->film_point.x / kWidth - 0.5) * 36;
    EXPECT_NEAR(height_mm, paraxial * std::tan(theta), 5e-4 * paraxial * std::tan(theta))
        << degrees << "°";
  }
  // The centre of projection: the stop, at the front vertex (film distance + front z).
  EXPECT_NEAR(fit.measured.centre_of_projection_mm,
              focused->film_distance_mm() + lens->front_z_mm(), 1e-3);
  EXPECT_LT(fit.pupil_shift_mm, 1e-3);
  // Relative illumination: cos⁴ of the chief ray's angle, within 1.5 %.
  double worst = 0;
  for (const LensFieldPoint& p : fit.measured.field) {
    const double c = std::cos(std::atan(p.image_height_mm / optics.efl_mm));
    EXPECT_NEAR(p.relative_illumination, c * c * c * c, 0.015) << p.image_height_mm << " mm";
    worst = std::max(worst, std::abs(p.relative_illumination - c * c * c * c));
  }
  std::printf(
      "thin element: f %.4f mm (paraxial %.4f, EFL %.4f), illumination vs cos⁴ within %.4f\n", f_mm,
      paraxial, optics.efl_mm, worst);
}

class BuiltinLensFit : public testing::TestWithParam<const char*> {};

// Chief rays traced through the lens for image points all over the frame (not only along the
// diagonal the fit measures), their directions projected through the fitted camera from far
// away: each lands within 0.1 px of the image point it came from.
TEST_P(BuiltinLensFit, FittedCameraPutsTracedChiefRaysWithinATenthOfAPixel) {
  Camera camera = lens_camera(builtin_lens(GetParam()));
  FittedLensCamera fitted = fitted_lens_camera(camera);
  auto focused = focused_lens_system(builtin_lens(GetParam()), camera.lens_system_settings());
  const Transform world = fitted.camera.world_from_camera.at(0);
  const double edge = fitted.fit.measured.edge_height_mm;
  double worst = 0;
  int checked = 0;
  for (int j = 0; j <= 12; ++j)
    for (int i = 0; i <= 16; ++i) {
      Point2d image(35 * (i / 16.0 - 0.5), 23 * (0.5 - j / 12.0));  // inside the frame
      if (std::hypot(image.x, image.y) > 0.99 * edge) continue;     // outside a fisheye's circle
      auto chief = focused->chief_ray(image);
      ASSERT_TRUE(chief);
      auto at = fitted.camera.project(world(Point3d(0, 0, 0) + chief->direction * 1e9));
      ASSERT_TRUE(at) << image.x << ", " << image.y;
      Point2d expected = raster_of(image);
      worst =
          std::max(worst, std::hypot(at->film_point.x - expected.x, at->film_point.y - expected.y));
      ++checked;
    }
  EXPECT_GT(checked, 100);
  EXPECT_LT(worst, 0.1) << GetParam();
  EXPECT_LT(fitted.fit.max_error_px, 0.1);
  std::printf("%s: %s, worst chief ray %.2g px over %d points; fit max %.2g px, RMS %.2g px\n",
              GetParam(), lens_model_name(fitted.fit.projection.lens), worst, checked,
              fitted.fit.max_error_px, fitted.fit.rms_error_px);
}

INSTANTIATE_TEST_SUITE_P(Designs, BuiltinLensFit,
                         testing::Values("double-gauss-50mm", "telephoto-250mm", "fisheye-10mm"));

TEST(LensSystemFit, FisheyeFieldMatchesTheTracedOne) {
  auto lens = builtin_lens("fisheye-10mm");
  Camera camera = lens_camera(lens);
  FittedLensCamera fitted = fitted_lens_camera(camera);
  ASSERT_TRUE(std::holds_alternative<KannalaBrandt>(fitted.fit.projection.lens));
  // The lit field: the largest image height (along x) where some of a 24 × 24 grid of pupil
  // samples passes the lens, by bisection, and its chief ray's angle.
  auto focused = focused_lens_system(lens, camera.lens_system_settings());
  auto lit = [&](double x) {
    for (int j = 0; j < 24; ++j)
      for (int i = 0; i < 24; ++i)
        if (focused->ray({x, 0}, {(i + 0.5) / 24, (j + 0.5) / 24})) return true;
    return false;
  };
  double lo = 0, hi = 18;
  ASSERT_FALSE(lit(hi));  // the image circle is narrower than the 36 mm frame
  for (int i = 0; i < 30; ++i) ((lit(0.5 * (lo + hi))) ? lo : hi) = 0.5 * (lo + hi);
  auto rim = focused->chief_ray({lo, 0});
  ASSERT_TRUE(rim);
  const double traced_field = 2 * std::acos(-rim->direction.z) / kDegrees;
  EXPECT_NEAR(2 * fitted.fit.projection.max_field_angle_degrees, traced_field, 0.5);
  EXPECT_NEAR(traced_field, 153.8, 1.0);  // where the published design's apertures end the light
  // Across the frame's height (inside the circle) the two cameras' own fields of view agree.
  EXPECT_NEAR(fitted.camera.fov_degrees().y, camera.fov_degrees().y, 0.5);
}

TEST(LensSystemFit, DoubleGaussHasTheBarrelDistortionItsCornerIsTracedWith) {
  auto lens = builtin_lens("double-gauss-50mm");
  const double efl = test::paraxial_optics(lens->prescription()).efl_mm;
  Camera camera = lens_camera(lens);
  FittedLensCamera fitted = fitted_lens_camera(camera);
  auto focused = focused_lens_system(lens, camera.lens_system_settings());
  // Traced: the corner's chief ray against where a distortion-free lens of the ABCD focal length
  // would image its direction (f·tan θ).
  const Point2d corner(18, 12);
  auto chief = focused->chief_ray(corner);
  ASSERT_TRUE(chief);
  const double theta = std::acos(-chief->direction.z);
  const double traced = std::hypot(corner.x, corner.y) / (efl * std::tan(theta)) - 1;
  // Fitted: the radial factor of OpenCV's model at ρ = tan θ.
  const auto& d = std::get<PinholeDistortion>(fitted.fit.projection.lens);
  const double r2 = std::tan(theta) * std::tan(theta);
  const double fitted_distortion = d.k1 * r2 + d.k2 * r2 * r2 + d.k3 * r2 * r2 * r2;
  EXPECT_LT(traced, 0);  // barrel
  EXPECT_LT(fitted_distortion, 0);
  EXPECT_NEAR(fitted_distortion, traced, 0.1 * std::abs(traced));
  std::printf("double-Gauss corner distortion: traced %.3f %%, fitted %.3f %%\n", 100 * traced,
              100 * fitted_distortion);
}

TEST(LensSystemFit, CloseObjectsLandWhereTheLensPutsThemWithinTheReportedParallax) {
  // Focused at 2 m: points on the focus plane project through the fitted camera where the lens
  // system's chief rays put them (exactly, but for the fit), points at 0.7 m and far away within
  // parallax_px_m · |1/D − 1/S|.
  Camera camera = lens_camera(builtin_lens("double-gauss-50mm"), 2);
  FittedLensCamera fitted = fitted_lens_camera(camera);
  for (double depth : {2.0, 0.7, 1e4}) {
    const double bound = fitted.fit.parallax_px_m * std::abs(1 / depth - 1 / 2.0) + 0.01;
    double worst = 0;
    for (Point2d p : {Point2d(900, 600), Point2d(20, 20), Point2d(512, 100), Point2d(300, 341)}) {
      auto world = camera.unproject(p, depth);
      ASSERT_TRUE(world);
      auto at = fitted.camera.project(*world);
      ASSERT_TRUE(at);
      worst = std::max(worst, std::hypot(at->film_point.x - p.x, at->film_point.y - p.y));
    }
    EXPECT_LT(worst, bound) << "at " << depth << " m";
  }
  EXPECT_LT(fitted.fit.parallax_px_m, 0.5);
}

TEST(LensSystemFit, OnlyLensSystemCamerasHaveOne) {
  Camera perspective;
  EXPECT_THROW(fitted_lens_camera(perspective), Error);
}

}  // namespace
}  // namespace obscura
