// A lens-system camera exported as a calibration: its fitted camera (OpenCV's pinhole model for
// the double-Gauss, Kannala–Brandt for the fisheye) written as OpenCV YAML, read back by the
// calibration loader, is the same projection and pose, and puts points on the plane of focus
// where the lens system's own chief rays do.
#include <gtest/gtest.h>

#include <random>

#include "obscura/camera/builtin_lenses.h"
#include "obscura/camera/frames.h"
#include "obscura/camera/lens_system_fit.h"
#include "obscura/io/calibration_file.h"

namespace obscura {
namespace {

constexpr double kFocusM = 3;

Camera lens_camera(const std::string& lens) {
  Camera c;
  c.name = "lens.png";
  LensSystemProjection p;
  p.lens = builtin_lens(lens);
  p.sensor_width_mm = 24;
  c.projection = p;
  c.film.width_px = 640;
  c.film.height_px = 427;
  c.lens.focus_distance_m = kFocusM;
  c.world_from_camera = world_from_camera_look_at({1.5, 0.7, 4.2}, {-0.3, 0.2, 0.1}, {0.1, 1, 0});
  c.validate();
  return c;
}

TEST(LensSystemExport, OpenCvYamlReloadsIntoTheFittedProjection) {
  for (const char* name : {"double-gauss-50mm", "fisheye-10mm"}) {
    Camera camera = lens_camera(name);
    FittedLensCamera fitted = fitted_lens_camera(camera, {.check_illumination = false});
    const std::string yaml =
        calibration_text(CalibrationFormat::opencv_yaml, calibration_of(camera));
    CameraCalibration back = parse_calibration_text(yaml, "lens.yaml", "");
    const CalibratedProjection& p = back.projection;
    const CalibratedProjection& expected = fitted.fit.projection;
    EXPECT_EQ(p.k, expected.k) << name;
    EXPECT_EQ(p.lens, expected.lens) << name;
    EXPECT_EQ(p.width_px, 640);
    EXPECT_EQ(p.height_px, 427);
    EXPECT_EQ(p.max_field_angle_degrees, expected.max_field_angle_degrees) << name;
    ASSERT_TRUE(back.world_from_camera);
    // Posed at the centre of projection, in front of the sensor along the view.
    const Point3d sensor = camera.world_from_camera.at(0)(Point3d(0, 0, 0));
    const Point3d centre = (*back.world_from_camera)(Point3d(0, 0, 0));
    EXPECT_NEAR(length(centre - sensor), fitted.fit.measured.centre_of_projection_mm / 1000, 1e-9);
    // The reloaded camera puts points of the focus plane where the lens system's chief rays do.
    Camera reloaded;
    reloaded.near_m = 1e-3;
    apply_calibration(reloaded, back);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> x(0, 640), y(0, 427);
    int checked = 0;
    double worst = 0;
    for (int i = 0; i < 200; ++i) {
      Point2d pixel(x(random), y(random));
      auto world = camera.unproject(pixel, kFocusM);
      auto at = world ? reloaded.project(*world) : std::nullopt;
      if (!at) continue;  // outside the fisheye's image circle
      worst = std::max(worst, std::hypot(at->film_point.x - pixel.x, at->film_point.y - pixel.y));
      ++checked;
    }
    EXPECT_GT(checked, 100) << name;
    EXPECT_LT(worst, 0.01) << name;
  }
}

}  // namespace
}  // namespace obscura
