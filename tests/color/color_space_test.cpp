// Colour spaces: matrices derived from primaries against published matrices, round trips
// through every invertible pair, and bad input.
#include "obscura/color/color_space.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "obscura/color/primaries.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

void expect_matrix_near(const Matrix3d& actual, const double (&expected)[3][3], double tolerance) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(actual.m[i][j], expected[i][j], tolerance) << "row " << i << ", column " << j;
}

TEST(ColorSpace, Rec709MatrixMatchesIec61966) {
  // IEC 61966-2-1 publishes the sRGB→XYZ matrix to 4 decimals.
  const double published[3][3] = {
      {0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};
  expect_matrix_near(xyz_from_rgb(primaries::kRec709), published, 5e-5);
}

TEST(ColorSpace, Ap0MatrixMatchesSmpteSt2065_1) {
  // SMPTE ST 2065-1 publishes the AP0 → XYZ (ACES white) matrix to 10 decimals.
  const double published[3][3] = {{0.9525523959, 0.0, 0.0000936786},
                                  {0.3439664498, 0.7281660966, -0.0721325464},
                                  {0.0, 0.0, 1.0088251844}};
  expect_matrix_near(xyz_from_rgb(primaries::kAcesAp0), published, 1e-9);
}

TEST(ColorSpace, Rec2020MatrixMatchesItuBt2087) {
  // ITU-R BT.2087 gives the BT.709 → BT.2020 conversion to 4 decimals.
  const double published[3][3] = {
      {0.6274, 0.3293, 0.0433}, {0.0691, 0.9195, 0.0114}, {0.0164, 0.0880, 0.8956}};
  expect_matrix_near(rgb_to_rgb_matrix(primaries::kRec709, primaries::kRec2020), published, 5e-5);
}

TEST(ColorSpace, BradfordD65ToD50MatchesLindbloom) {
  // Bruce Lindbloom's published Bradford D65 → D50 matrix (white XYZ from his tables differ
  // from the xy-derived whites by < 1e-4, hence the tolerance).
  const double published[3][3] = {{1.0478112, 0.0228866, -0.0501270},
                                  {0.0295424, 0.9904844, -0.0170491},
                                  {-0.0092345, 0.0150436, 0.7521316}};
  expect_matrix_near(bradford_adaptation(white::kD65, white::kD50), published, 3e-4);
}

TEST(ColorSpace, WhiteMapsToWhiteInEverySpace) {
  for (const char* space : {"srgb", "display-p3", "rec2020", "acescg", "aces2065-1"}) {
    std::vector<double> xyz = convert_color(space, "xyz-d65", {1, 1, 1});
    EXPECT_NEAR(xyz[0], 0.3127 / 0.3290, 1e-9) << space;
    EXPECT_NEAR(xyz[1], 1, 1e-9) << space;
    EXPECT_NEAR(xyz[2], (1 - 0.3127 - 0.3290) / 0.3290, 1e-9) << space;
  }
  std::vector<double> lab = convert_color("srgb", "lab-d50", {1, 1, 1});
  EXPECT_NEAR(lab[0], 100, 1e-9);
  EXPECT_NEAR(lab[1], 0, 1e-9);
  EXPECT_NEAR(lab[2], 0, 1e-9);
}

TEST(ColorSpace, CmyAndCmykAreSubtractive) {
  // A cyan ink absorbs red: pure cyan is R′ = 0 with G′ = B′ = 1.
  std::vector<double> cyan = convert_color("srgb", "cmy", {0, 1, 1});
  EXPECT_NEAR(cyan[0], 1, 1e-12);
  EXPECT_NEAR(cyan[1], 0, 1e-12);
  EXPECT_NEAR(cyan[2], 0, 1e-12);
  std::vector<double> black = convert_color("srgb", "cmyk", {0, 0, 0});
  EXPECT_EQ(black, (std::vector<double>{0, 0, 0, 1}));
  std::vector<double> red = convert_color("cmyk", "srgb", {0, 1, 1, 0});
  EXPECT_NEAR(red[0], 1, 1e-9);
  EXPECT_NEAR(red[1], 0, 1e-9);
  EXPECT_NEAR(red[2], 0, 1e-9);
}

// Every pair of spaces that is invertible on the sample (all but the quantized YCbCr codes),
// there and back, from in-gamut sRGB colours (HSV/HSL only hold those).
TEST(ColorSpace, RoundTripsWithin1e6) {
  const std::vector<std::vector<double>> samples = {
      {0.2, 0.4, 0.6}, {0.9, 0.1, 0.3}, {0.05, 0.8, 0.7}, {0.5, 0.5, 0.5}, {1, 0.99, 0.01}};
  int pairs = 0;
  for (const ColorSpaceInfo& a : color_spaces()) {
    if (a.model == ColorModel::kYcbcr8) continue;
    for (const ColorSpaceInfo& b : color_spaces()) {
      if (b.model == ColorModel::kYcbcr8) continue;
      for (const std::vector<double>& srgb : samples) {
        std::vector<double> in = convert_color("srgb", a.name, srgb);
        std::vector<double> there = convert_color(a.name, b.name, in);
        std::vector<double> back = convert_color(b.name, a.name, there);
        for (size_t i = 0; i < in.size(); ++i) {
          double scale = std::max(1.0, std::abs(in[i]));
          bool hue = (a.model == ColorModel::kHsv || a.model == ColorModel::kHsl) && i == 0;
          bool grey = std::abs(in[1]) < 1e-9;
          if (a.model == ColorModel::kOklch) hue = i == 2, grey = std::abs(in[1]) < 1e-6;
          if (hue && grey) continue;  // the hue of a grey is undefined
          EXPECT_NEAR(back[i], in[i], 1e-6 * scale) << a.name << " → " << b.name << " → " << a.name;
        }
      }
      ++pairs;
    }
  }
  EXPECT_GT(pairs, 500);
}

TEST(ColorSpace, YcbcrCodesRoundTripWithinHalfACode) {
  for (const char* space : {"ycbcr8-bt709-limited", "ycbcr8-bt2020-full"}) {
    std::vector<double> codes = convert_color("srgb", space, {0.25, 0.5, 0.75});
    std::vector<double> back = convert_color(space, "srgb", codes);
    EXPECT_NEAR(back[0], 0.25, 1.0 / 219);
    EXPECT_NEAR(back[2], 0.75, 1.0 / 219);
  }
}

TEST(ColorSpace, BadInputIsAClearError) {
  EXPECT_THROW(convert_color("srgb", "nonsense", {0, 0, 0}), Error);
  EXPECT_THROW(convert_color("nonsense", "srgb", {0, 0, 0}), Error);
  EXPECT_THROW(convert_color("srgb", "xyz-d65", {0, 0}), Error);
  EXPECT_THROW(convert_color("cmyk", "srgb", {0, 0, 0}), Error);
  EXPECT_THROW(convert_color("srgb", "xyz-d65", {std::nan(""), 0, 0}), Error);
  EXPECT_THROW(convert_color("srgb", "xyz-d65", {std::numeric_limits<double>::infinity(), 0, 0}),
               Error);
  EXPECT_THROW(convert_color("ycbcr8-bt709-full", "srgb", {12.5, 128, 128}), Error);
  try {
    convert_color("srgb", "lab-d99", {0, 0, 0});
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("lab-d99"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("lab-d50"), std::string::npos);  // lists known names
  }
}

}  // namespace
}  // namespace obscura
