// HSL and HSV at their degenerate points (greys, white, black, colours a rounding error away from
// them, colours outside the sRGB cube), against the definitions of CSS Color 4 §7 (rgbToHsl,
// hslToRgb) and its published examples.
#include "obscura/color/color_models.h"

#include <gtest/gtest.h>

#include <cmath>

#include "obscura/color/color_space.h"

namespace obscura {
namespace {

void expect_near3(const Vec3d& got, const Vec3d& want, double tolerance = 1e-9) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], tolerance) << "component " << i;
}

Vec3d vec(const std::vector<double>& v) {
  return {v.at(0), v.at(1), v.at(2)};
}

TEST(ColorModels, CssColor4HslExamples) {
  // CSS Color 4 §7: hsl(120deg 100% 50%) is lime, 25% dark green #008000's hue, 75% light green.
  expect_near3(rgb_from_hsl({120, 1, 0.5}), {0, 1, 0});
  expect_near3(rgb_from_hsl({120, 1, 0.25}), {0, 0.5, 0});
  expect_near3(rgb_from_hsl({120, 1, 0.75}), {0.5, 1, 0.5});
  expect_near3(hsl_from_rgb({0, 0.5, 0}), {120, 1, 0.25});
  expect_near3(hsl_from_rgb({0.5, 1, 0.5}), {120, 1, 0.75});
}

TEST(ColorModels, GreysWhiteAndBlackHaveNoHueOrSaturation) {
  for (double grey : {0.0, 0.18, 0.5, 1.0}) {
    expect_near3(hsl_from_rgb({grey, grey, grey}), {0, 0, grey}, 0);
    expect_near3(hsv_from_rgb({grey, grey, grey}), {0, 0, grey}, 0);
  }
}

TEST(ColorModels, WhiteThroughXyzStaysAGrey) {
  // The CLI's path: encoded sRGB → XYZ → HSL. Rounding leaves white as 1 ± 2e-16 per channel;
  // before, that noise divided by a noise-sized denominator gave saturation 0.5.
  expect_near3(vec(convert_color("srgb", "hsl", {1, 1, 1})), {0, 0, 1}, 1e-12);
  expect_near3(vec(convert_color("srgb", "hsv", {1, 1, 1})), {0, 0, 1}, 1e-12);
  expect_near3(vec(convert_color("srgb", "hsl", {0, 0, 0})), {0, 0, 0}, 1e-12);
  // A hair above white: still a grey (before: saturation −4.5e8).
  Vec3d above = vec(convert_color("srgb", "hsl", {1.0000001, 1.0000001, 1.0000001}));
  EXPECT_EQ(above[1], 0);
  EXPECT_NEAR(above[2], 1.0000001, 1e-12);
}

TEST(ColorModels, LightnessAtWhiteOrBlackGivesZeroSaturation) {
  // CSS: "sat = (light === 0 || light === 1) ? 0 : …": a colour whose lightness is 1 but whose
  // channels straddle 1 is outside the cube; its saturation is 0, never a division by ~0.
  Vec3d hsl = hsl_from_rgb({1.5, 0.5 + 1e-12, 1});
  EXPECT_EQ(hsl[1], 0);
  EXPECT_TRUE(std::isfinite(hsl[0]));
  hsl = hsl_from_rgb({-0.5, 0.5, 0});
  EXPECT_EQ(hsl[1], 0);
}

TEST(ColorModels, OutOfCubeColoursFollowCssAndRoundTrip) {
  // (1.2, 0.5, 0.4): max 1.2, min 0.4, L = 0.8, S = (1.2 − 0.8) / min(0.8, 0.2) = 2,
  // hue = 60 × (0.5 − 0.4) / 0.8 = 7.5°.
  expect_near3(hsl_from_rgb({1.2, 0.5, 0.4}), {7.5, 2, 0.8});
  // (1.5, 1.2, 0.9): L = 1.2, S = 0.3 / min(1.2, −0.2) = −1.5 → 1.5 with the hue turned by 180°
  // (30° → 210°), as CSS Color 4 does for negative saturation.
  expect_near3(hsl_from_rgb({1.5, 1.2, 0.9}), {210, 1.5, 1.2});
  for (Vec3d rgb : {Vec3d{1.2, 0.5, 0.4}, Vec3d{1.5, 1.2, 0.9}, Vec3d{-0.2, 0.3, 0.1}})
    expect_near3(rgb_from_hsl(hsl_from_rgb(rgb)), rgb, 1e-12);
}

TEST(ColorModels, HsvPublishedValuesAndBelowBlack) {
  // Orange (1, 0.5, 0): hue 30°, saturation 1, value 1; (0.25, 0.5, 0.5) teal-grey: 180°, 0.5.
  expect_near3(hsv_from_rgb({1, 0.5, 0}), {30, 1, 1});
  expect_near3(hsv_from_rgb({0.25, 0.5, 0.5}), {180, 0.5, 0.5});
  // Every channel below 0: no saturation, not a negative one.
  Vec3d hsv = hsv_from_rgb({-0.5, -0.2, -0.3});
  EXPECT_EQ(hsv[1], 0);
  EXPECT_DOUBLE_EQ(hsv[2], -0.2);
}

}  // namespace
}  // namespace obscura
