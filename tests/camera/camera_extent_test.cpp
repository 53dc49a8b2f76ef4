// The camera's side of the value contract (camera/camera_extent.h, math/value_limits.h): ray
// origins beyond ±1e7 m and ray slopes beyond 1e6 are refused by Camera::validate, naming the
// field. Each of these once reached Embree, which aborts (SIGABRT) on |origin| or |direction|
// beyond ~1.8e18; and calibrations that image nothing are refused rather than rendered black.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "obscura/camera/camera.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

using ::testing::HasSubstr;

std::string refusal(const std::function<void(Camera&)>& change) {
  Camera c;
  change(c);
  try {
    c.validate();
  } catch (const Error& e) {
    return e.what();
  }
  return "(accepted)";
}

Perspective& perspective(Camera& c) {
  return std::get<Perspective>(c.projection);
}

TEST(CameraExtent, OrdinaryCamerasAreAccepted) {
  EXPECT_EQ(refusal([](Camera&) {}), "(accepted)");
  EXPECT_EQ(refusal([](Camera& c) {
              c.world_from_camera = Transform::translate({9e6, 0, 0});
              perspective(c).focal_length_mm = 8;
              c.lens.depth_of_field = true;
              c.lens.f_number = 0.95;
            }),
            "(accepted)");
}

TEST(CameraExtent, PositionsBeyondTheBoundAreRefused) {
  EXPECT_THAT(
      refusal([](Camera& c) {
        c.world_from_camera = Transform::translate({2e18, 0, 0});
      }),
      AllOf(HasSubstr("camera.position"), HasSubstr("2e+18"), HasSubstr("single-precision")));
  EXPECT_THAT(refusal([](Camera& c) {
                c.world_from_camera = AnimatedTransform(
                    {{0, Transform()}, {1, Transform::translate({0, 0, -1e308})}});
              }),
              AllOf(HasSubstr("camera.position (key 1)")));
}

TEST(CameraExtent, DegenerateOpticsAreRefusedByField) {
  EXPECT_THAT(refusal([](Camera& c) { perspective(c).focal_length_mm = 1e-20; }),
              HasSubstr("camera.focal_length_mm"));
  EXPECT_THAT(refusal([](Camera& c) {
                perspective(c).sensor_width_mm = 1e300;
                perspective(c).sensor_height_mm = 1e300;
              }),
              HasSubstr("camera.sensor_mm"));
  EXPECT_THAT(refusal([](Camera& c) {
                perspective(c).lens_shift = {1e20, 0};
              }),
              HasSubstr("camera.lens_shift"));
  EXPECT_THAT(refusal([](Camera& c) {
                c.lens.depth_of_field = true;
                c.lens.f_number = 1e-300;
              }),
              HasSubstr("camera.f_number"));
  EXPECT_THAT(refusal([](Camera& c) {
                Orthographic o;
                o.view_height_m = 1e12;
                c.projection = o;
              }),
              HasSubstr("camera.view_height_m"));
}

TEST(CameraExtent, CalibrationsThatImageNothingAreRefused) {
  auto calibrated = [](Intrinsics k, LensModel lens) {
    return [=](Camera& c) {
      c.projection = CalibratedProjection{.k = k, .width_px = 640, .height_px = 480, .lens = lens};
    };
  };
  const Intrinsics k{.fx = 500, .fy = 500, .cx = 319.5, .cy = 239.5};
  EXPECT_EQ(refusal(calibrated(k, PinholeDistortion{.k1 = -0.2})), "(accepted)");
  Intrinsics tiny = k;
  tiny.fx = 1e-300;
  EXPECT_THAT(refusal(calibrated(tiny, PinholeDistortion{})), HasSubstr("camera.intrinsics.fx"));
  EXPECT_THAT(refusal(calibrated(k, PinholeDistortion{.k1 = 1e300})), HasSubstr("camera.lens.k1"));
  EXPECT_THAT(refusal(calibrated(k, KannalaBrandt{.k2 = -1e20})), HasSubstr("camera.lens.k2"));
}

}  // namespace
}  // namespace obscura
