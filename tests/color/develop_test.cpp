// develop(): the film → display codes path, against the double-precision reference conversion
// (color_space.h, itself checked against the shared vectors), and its handling of NaN/Inf.
#include "obscura/color/develop.h"

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "obscura/color/color_space.h"
#include "obscura/color/gamut.h"
#include "obscura/color/quantize.h"
#include "obscura/math/error.h"
#include "obscura/math/rng.h"

namespace obscura {
namespace {

// Settings changed from the defaults by `edit` (designated initializers that skip members
// trip -Wmissing-field-initializers).
template <typename Edit>
DisplaySettings settings(Edit edit) {
  DisplaySettings s;
  edit(s);
  return s;
}

// A w×h RGB image of deterministic values in [lo, hi).
std::vector<float> random_image(int w, int h, float lo, float hi, uint64_t seed) {
  std::vector<float> v(size_t(w) * h * 3);
  for (size_t i = 0; i < v.size(); ++i)
    v[i] = lo + (hi - lo) * bits_to_unit_float(hash_words(seed, i));
  return v;
}

// Display codes against the double reference, for each display and bit depth of the exact
// path (including the vectorised blocks: a width that is not a multiple of 8 covers the tail).
TEST(Develop, ExactPathMatchesTheDoublePrecisionReference) {
  const int w = 37, h = 9;
  std::vector<float> pixels = random_image(w, h, -0.3f, 2.5f, 1);
  for (DisplaySpace d : {DisplaySpace::kSrgb, DisplaySpace::kDisplayP3, DisplaySpace::kRec2020Pq})
    for (int bits : {1, 5, 8}) {
      DisplaySettings s = settings(
          [&](DisplaySettings& s) { s.tonemap.op = ToneMap::kNone, s.display = d, s.bits = bits; });
      DisplayImage out = develop({pixels.data(), w, h, 3}, s);
      const DisplaySpaceInfo& info = display_space_info(d);
      const ColorSpaceInfo& space = color_space(info.color_space);
      int mismatches = 0;
      for (int p = 0; p < w * h; ++p) {
        Vec3d xyz = xyz_d65_from(color_space("srgb-linear"),
                                 {pixels[3 * p], pixels[3 * p + 1], pixels[3 * p + 2]});
        std::vector<double> e = from_xyz_d65(space, xyz);
        for (int k = 0; k < 3; ++k) {
          double level = std::clamp(e[k], 0.0, 1.0) * ((1 << bits) - 1);
          uint32_t reference = quantize(e[k], bits);
          if (out.codes[3 * p + k] == reference) continue;
          // Only a float-vs-double difference at a rounding tie may flip a code.
          EXPECT_LT(std::abs(level - std::floor(level) - 0.5), 1e-4) << "pixel " << p;
          ++mismatches;
        }
      }
      EXPECT_LE(mismatches, 1) << display_space_info(d).name << " " << bits << " bits";
    }
}

TEST(Develop, GenericPathAgreesWithTheExactPath) {
  // 12 bits goes through the per-channel double encode; compared at 8 bits of precision.
  const int w = 19, h = 3;
  std::vector<float> pixels = random_image(w, h, 0.f, 1.f, 2);
  DisplayImage fast = develop({pixels.data(), w, h, 3}, {});
  DisplayImage wide =
      develop({pixels.data(), w, h, 3}, settings([](DisplaySettings& s) { s.bits = 12; }));
  // Half an 8-bit code of rounding, plus half a 12-bit code.
  for (size_t i = 0; i < fast.codes.size(); ++i)
    EXPECT_NEAR(double(wide.codes[i]) / 4095 * 255, fast.codes[i], 0.5 + 0.5 * 255 / 4095);
}

TEST(Develop, ExposureScalesLinearLight) {
  std::vector<float> a = {0.1f, 0.2f, 0.05f}, b = {0.2f, 0.4f, 0.1f};
  DisplaySettings plus_one = settings([](DisplaySettings& s) { s.exposure_ev = 1, s.bits = 12; });
  DisplaySettings none = settings([](DisplaySettings& s) { s.bits = 12; });
  EXPECT_EQ(develop({a.data(), 1, 1, 3}, plus_one).codes, develop({b.data(), 1, 1, 3}, none).codes);
}

TEST(Develop, NanAndInfAreCountedAndWrittenAsDefinedValues) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  // 20 pixels so that the bad ones also fall inside an 8-pixel vector block.
  std::vector<float> pixels(20 * 3, 0.5f);
  auto set = [&](int p, float r, float g, float b) {
    pixels[3 * p] = r, pixels[3 * p + 1] = g, pixels[3 * p + 2] = b;
  };
  set(3, nan, 0.5f, 0.5f);
  set(4, inf, inf, inf);
  set(9, -inf, 0.5f, nan);
  set(10, 0.5f, -inf, 0.5f);
  for (Dither d : {Dither::kNone, Dither::kBlueNoise}) {
    DisplayImage out =
        develop({pixels.data(), 20, 1, 3}, settings([&](DisplaySettings& s) { s.dither = d; }));
    EXPECT_EQ(out.stats.nan_pixels, 2u);
    EXPECT_EQ(out.stats.inf_pixels, 2u);
    EXPECT_EQ(out.codes[3 * 3 + 0], 0);    // NaN → 0
    EXPECT_EQ(out.codes[3 * 4 + 0], 0);    // +Inf → 0 as well
    EXPECT_EQ(out.codes[3 * 9 + 0], 0);    // −Inf → 0
    EXPECT_EQ(out.codes[3 * 9 + 2], 0);
    EXPECT_EQ(out.codes[3 * 10 + 1], 0);
  }
}

TEST(Develop, OutOfGamutMaskAndCount) {
  // Linear Rec.709 with a negative channel: a colour outside sRGB (but inside Rec.2020).
  std::vector<float> pixels = {0.5f, 0.5f, 0.5f, -0.1f, 0.6f, 0.2f, 3.f, 3.f, 3.f};
  DisplaySettings srgb = settings([](DisplaySettings& s) { s.tonemap.op = ToneMap::kNone; });
  std::vector<uint8_t> mask = out_of_gamut_mask({pixels.data(), 3, 1, 3}, srgb);
  EXPECT_EQ(mask, (std::vector<uint8_t>{0, 1, 1}));
  EXPECT_EQ(develop({pixels.data(), 3, 1, 3}, srgb).stats.out_of_gamut_pixels, 2u);
  DisplaySettings wide = settings([](DisplaySettings& s) {
    s.tonemap.op = ToneMap::kAces, s.display = DisplaySpace::kRec2020Pq;
  });
  EXPECT_EQ(out_of_gamut_mask({pixels.data(), 3, 1, 3}, wide), (std::vector<uint8_t>{0, 0, 0}));
}

TEST(Develop, GamutCompressionKeepsHueWhereClippingShiftsIt) {
  // A saturated Rec.2020 green-cyan, shown on an sRGB display.
  std::vector<double> lin709 = convert_color("rec2020-linear", "srgb-linear", {0.05, 0.6, 0.45});
  std::vector<float> pixel = {float(lin709[0]), float(lin709[1]), float(lin709[2])};
  auto hue_of_codes = [](const DisplayImage& im) {
    std::vector<double> lch = convert_color(
        "srgb", "oklch", {im.codes[0] / 255.0, im.codes[1] / 255.0, im.codes[2] / 255.0});
    return lch[2];
  };
  double original_hue = convert_color("srgb-linear", "oklch", lin709)[2];
  double clipped = hue_of_codes(develop({pixel.data(), 1, 1, 3}, {}));
  double compressed = hue_of_codes(
      develop({pixel.data(), 1, 1, 3},
              settings([](DisplaySettings& s) { s.gamut = GamutMapping::kCompress; })));
  EXPECT_LT(std::abs(compressed - original_hue), 2.0);
  EXPECT_LT(std::abs(compressed - original_hue), std::abs(clipped - original_hue));
}

TEST(Develop, AlphaAndGreyChannels) {
  std::vector<float> rgba = {1.f, 1.f, 1.f, 0.5f};
  DisplayImage out = develop({rgba.data(), 1, 1, 4}, {});
  EXPECT_EQ(out.channels, 4);
  EXPECT_EQ(out.codes, (std::vector<uint16_t>{255, 255, 255, 128}));  // alpha stays linear
  std::vector<float> grey = {0.2158605f};                             // sRGB-encodes to 128/255
  EXPECT_EQ(develop({grey.data(), 1, 1, 1}, {}).codes, (std::vector<uint16_t>{128, 128, 128}));
}

TEST(Develop, BadSettingsAndImagesAreErrors) {
  std::vector<float> px = {0, 0, 0};
  EXPECT_THROW(develop({px.data(), 1, 1, 3}, settings([](DisplaySettings& s) { s.bits = 0; })),
               Error);
  EXPECT_THROW(develop({px.data(), 1, 1, 3}, settings([](DisplaySettings& s) { s.bits = 17; })),
               Error);
  EXPECT_THROW(
      develop({px.data(), 1, 1, 3}, settings([](DisplaySettings& s) { s.exposure_ev = NAN; })),
      Error);
  EXPECT_THROW(develop({px.data(), 1, 1, 2}, {}), Error);
  EXPECT_THROW(develop({px.data(), 0, 1, 3}, {}), Error);
  EXPECT_THROW(parse_display_space("rec709-hlg"), Error);
}

}  // namespace
}  // namespace obscura
