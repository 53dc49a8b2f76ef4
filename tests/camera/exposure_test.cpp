// Exposure: known photographic values (EV100, sunny 16) and stop ratios in physical mode.
#include "obscura/camera/exposure.h"

#include <cmath>

#include <gtest/gtest.h>

#include "obscura/camera/camera.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

Camera physical_camera(double f_number, double exposure_time_s, double iso) {
  Camera c;
  c.exposure.mode = ExposureMode::physical;
  c.exposure.iso = iso;
  c.lens.f_number = f_number;
  c.shutter = {.open_s = 0, .close_s = exposure_time_s};
  return c;
}

TEST(Exposure, Ev100OfKnownSettings) {
  // EV is log2(N²/t) at ISO 100: f/1 at 1 s is EV 0; sunny 16 (f/16, 1/125 s) is EV 15 as
  // printed on exposure tables (the exact value is log2(256 · 125) = 14.97).
  EXPECT_NEAR(ev100(1, 1, 100), 0, 1e-12);
  EXPECT_NEAR(ev100(16, 1.0 / 125, 100), 15, 0.05);
  EXPECT_NEAR(ev100(2.8, 1.0 / 60, 100), 8.87, 0.01);
  // ISO 400 needs two stops less light: the same settings read two EV lower at ISO 100 terms.
  EXPECT_NEAR(ev100(16, 1.0 / 125, 400), ev100(16, 1.0 / 125, 100) - 2, 1e-12);
}

TEST(Exposure, RadianceModeLeavesRadianceUnscaled) {
  Camera c;
  EXPECT_EQ(c.exposure_scale(), 1.0);
  c.lens.f_number = 1.4;  // no effect in radiance mode
  c.shutter.close_s = 2;
  EXPECT_EQ(c.exposure_scale(), 1.0);
  c.exposure.compensation_ev = -1.5;
  EXPECT_NEAR(c.exposure_scale(), 1 / std::pow(2, 1.5), 1e-15);
}

TEST(Exposure, PhysicalModeFollowsStops) {
  double base = physical_camera(2.8, 1.0 / 60, 100).exposure_scale();
  // f/2.8 → f/4 is one stop less light: the value halves within 1 % (the engraved 2.8 stands
  // for 2√2; taken literally, 2.8² / 4² = 0.49).
  EXPECT_NEAR(physical_camera(4, 1.0 / 60, 100).exposure_scale() / base, 0.5, 0.005);
  EXPECT_NEAR(physical_camera(5.6, 1.0 / 60, 100).exposure_scale() / base, 0.25, 0.0025);
  EXPECT_NEAR(physical_camera(16, 1.0 / 60, 100).exposure_scale() / base, 1.0 / 32, 3e-4);
  // An unengraved value is used as given: f/3 lets in (2√2 / 3)² of f/2.8's light.
  EXPECT_NEAR(physical_camera(3, 1.0 / 60, 100).exposure_scale() / base, 8.0 / 9, 1e-9);
  EXPECT_NEAR(physical_camera(2.8, 1.0 / 30, 100).exposure_scale() / base, 2, 0.02);
  EXPECT_NEAR(physical_camera(2.8, 1.0 / 60, 200).exposure_scale() / base, 2, 0.02);
  Camera compensated = physical_camera(2.8, 1.0 / 60, 100);
  compensated.exposure.compensation_ev = 1;
  EXPECT_NEAR(compensated.exposure_scale() / base, 2, 1e-12);
}

TEST(Exposure, PhysicalCalibrationSaturatesAtTheIsoLuminance) {
  // ISO 12232 saturation speed: L_sat = 78 / (S · 0.65) · N² / t cd/m² maps to 1.
  double n = 8, t = 1.0 / 250, s = 100;
  double l_sat = 78 / (s * 0.65) * n * n / t;
  EXPECT_NEAR(physical_camera(n, t, s).exposure_scale() * l_sat, 1, 1e-12);
}

TEST(Exposure, RejectsBadValuesNamingThem) {
  Camera c = physical_camera(2.8, 0, 100);  // an instantaneous shutter gathers no light
  EXPECT_THROW(c.validate(), Error);
  c = physical_camera(2.8, 1.0 / 60, 0);
  try {
    c.validate();
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("iso: must be positive; got 0"), std::string::npos);
  }
  EXPECT_THROW(parse_exposure_mode("auto"), Error);
}

}  // namespace
}  // namespace obscura
