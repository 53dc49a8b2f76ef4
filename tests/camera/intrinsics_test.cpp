// The intrinsics matrix K against OpenCV's pinhole model.
#include "obscura/camera/intrinsics.h"

#include <gtest/gtest.h>

#include "obscura/math/error.h"

namespace obscura {
namespace {

// Reference pixels computed offline (Python, double precision) with OpenCV's documented pinhole
// model without distortion (calib3d: u = fx·X/Z + cx, v = fy·Y/Z + cy; X right, Y down, Z forward;
// integer pixel centres) for K = [800 0 330.25; 0 780 245.75; 0 0 1]. OpenCV itself is not a
// dependency of this project, so it was not called.
TEST(Intrinsics, CameraFromKProjectsAsOpenCV) {
  Intrinsics k{.fx = 800, .fy = 780, .cx = 330.25, .cy = 245.75};
  Camera c = camera_from_intrinsics(k, 640, 480);
  struct Case {
    Point3d opencv_point;
    Point2d uv;
  } cases[] = {
      {{0.1, -0.2, 2.0}, {370.2500000000, 167.7500000000}},
      {{-0.5, 0.3, 4.0}, {230.2500000000, 304.2500000000}},
      {{0.0, 0.0, 1.0}, {330.2500000000, 245.7500000000}},
      {{0.75, 0.6, 3.5}, {501.6785714286, 379.4642857143}},
      {{-0.3, -0.25, 1.25}, {138.2500000000, 89.7500000000}},
  };
  for (const Case& k_case : cases) {
    // OpenCV's camera frame is Obscura's with Y and Z negated.
    Point3d p(k_case.opencv_point.x, -k_case.opencv_point.y, -k_case.opencv_point.z);
    auto projected = c.project(p);
    ASSERT_TRUE(projected);
    EXPECT_NEAR(projected->film_point.x - 0.5, k_case.uv.x, 1e-9);
    EXPECT_NEAR(projected->film_point.y - 0.5, k_case.uv.y, 1e-9);
  }
  Intrinsics back = intrinsics(c);
  EXPECT_NEAR(back.fx, 800, 1e-9);
  EXPECT_NEAR(back.fy, 780, 1e-9);
  EXPECT_NEAR(back.cx, 330.25, 1e-9);
  EXPECT_NEAR(back.cy, 245.75, 1e-9);
}

TEST(Intrinsics, FocalLengthInPixelsIsFTimesWidthOverSensor) {
  // fx = f·W / sensor width: 50 mm on 36 mm at 1920 px → 2666.67 px; centred: cx = (W − 1)/2.
  Camera c;
  c.film.width_px = 1920;
  c.film.height_px = 1280;
  Intrinsics k = intrinsics(c);
  EXPECT_NEAR(k.fx, 50.0 * 1920 / 36, 1e-9);
  EXPECT_NEAR(k.fy, 50.0 * 1280 / 24, 1e-9);
  EXPECT_NEAR(k.cx, 959.5, 1e-9);
  EXPECT_NEAR(k.cy, 639.5, 1e-9);
}

TEST(Intrinsics, RejectsBadValues) {
  EXPECT_THROW(camera_from_intrinsics({.fx = 0, .fy = 1, .cx = 0, .cy = 0}, 10, 10), Error);
  EXPECT_THROW(camera_from_intrinsics({.fx = 1, .fy = 1, .cx = 0, .cy = 0}, 0, 10), Error);
  Camera ortho;
  ortho.projection = Orthographic{};
  EXPECT_THROW(intrinsics(ortho), Error);
}

}  // namespace
}  // namespace obscura
