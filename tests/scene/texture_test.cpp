// Texture lookups worked by hand on tiny images: texel centres, bilinear weights, each wrap
// mode, sRGB decoding (IEC 61966-2-1: encoded 0.5 is linear 0.21404) and grey expansion.
#include "obscura/scene/texture.h"

#include <gtest/gtest.h>

#include "obscura/color/srgb.h"

namespace obscura {
namespace {

// A 2 × 1 linear float texture: left texel 0, right texel 1 (one channel).
Texture ramp(TextureWrap wrap, TextureFilter filter) {
  Texture t;
  t.width = 2, t.height = 1, t.channels = 1;
  t.texels_float = {0.f, 1.f};
  t.encoding = TextureEncoding::kLinear;
  t.wrap_u = t.wrap_v = wrap;
  t.filter = filter;
  return t;
}

TEST(Texture, BilinearBetweenTexelCentres) {
  Texture t = ramp(TextureWrap::kClampToEdge, TextureFilter::kBilinear);
  EXPECT_FLOAT_EQ(sample_texture(t, {0.25f, 0.5f}).x, 0);    // left centre
  EXPECT_FLOAT_EQ(sample_texture(t, {0.75f, 0.5f}).x, 1);    // right centre
  EXPECT_FLOAT_EQ(sample_texture(t, {0.5f, 0.5f}).x, 0.5f);  // half way
  EXPECT_FLOAT_EQ(sample_texture(t, {0.375f, 0.5f}).x, 0.25f);
  EXPECT_FLOAT_EQ(sample_texture(t, {0.f, 0.5f}).x, 0);      // clamped beyond the centre
  EXPECT_FLOAT_EQ(sample_texture(t, {0.5f, 0.5f}).w, 1);     // no alpha channel → 1
  EXPECT_FLOAT_EQ(sample_texture(t, {0.5f, 0.5f}).y, 0.5f);  // grey fills G and B
}

TEST(Texture, WrapModes) {
  // u = 1.0 lies half a texel past the right centre: repeat blends right (1) with left (0).
  EXPECT_FLOAT_EQ(
      sample_texture(ramp(TextureWrap::kRepeat, TextureFilter::kBilinear), {1.f, 0.5f}).x, 0.5f);
  EXPECT_FLOAT_EQ(
      sample_texture(ramp(TextureWrap::kClampToEdge, TextureFilter::kBilinear), {1.f, 0.5f}).x, 1);
  // Mirrored: the texel after the right one is the right one again.
  EXPECT_FLOAT_EQ(
      sample_texture(ramp(TextureWrap::kMirroredRepeat, TextureFilter::kBilinear), {1.f, 0.5f}).x,
      1);
  // Nearest: u = 1.1 repeats to 0.1 (left), mirrors to 0.9 (right).
  EXPECT_FLOAT_EQ(
      sample_texture(ramp(TextureWrap::kRepeat, TextureFilter::kNearest), {1.1f, 0.5f}).x, 0);
  EXPECT_FLOAT_EQ(
      sample_texture(ramp(TextureWrap::kMirroredRepeat, TextureFilter::kNearest), {1.1f, 0.5f}).x,
      1);
  EXPECT_FLOAT_EQ(
      sample_texture(ramp(TextureWrap::kRepeat, TextureFilter::kNearest), {-0.2f, 0.5f}).x, 1);
}

TEST(Texture, SrgbEightBitTexelsAreDecoded) {
  Texture t;
  t.width = t.height = 1, t.channels = 3;
  t.texels_8bit = {255, 128, 0};
  t.filter = TextureFilter::kNearest;
  Vector4f v = sample_texture(t, {0.5f, 0.5f});
  EXPECT_FLOAT_EQ(v.x, 1);
  EXPECT_NEAR(v.y, 0.2158605f, 1e-6);  // 128/255 = 0.50196 encoded → 0.21586 linear
  EXPECT_FLOAT_EQ(v.z, 0);
  t.encoding = TextureEncoding::kLinear;
  EXPECT_NEAR(sample_texture(t, {0.5f, 0.5f}).y, 128 / 255.f, 1e-7);
}

// 8-bit sRGB texels are decoded through a table; it must give exactly srgb_decode's floats for
// every value, in every channel layout (grey, grey + alpha, RGB, RGBA), alpha left linear.
TEST(Texture, SrgbEightBitTableIsExactForEveryValue) {
  for (int channels = 1; channels <= 4; ++channels) {
    Texture t;
    t.width = 256, t.height = 1, t.channels = channels;
    t.filter = TextureFilter::kNearest;
    for (int i = 0; i < 256; ++i)
      for (int c = 0; c < channels; ++c) t.texels_8bit.push_back(uint8_t((i + 85 * c) % 256));
    for (int i = 0; i < 256; ++i) {
      Vector4f v = sample_texture(t, {(i + 0.5f) / 256, 0.5f});
      auto encoded = [&](int c) { return uint8_t((i + 85 * c) % 256) * (1.f / 255.f); };
      float grey = srgb_decode(encoded(0));
      EXPECT_EQ(v.x, grey) << channels << " channels, texel " << i;
      EXPECT_EQ(v.y, channels >= 3 ? srgb_decode(encoded(1)) : grey);
      EXPECT_EQ(v.z, channels >= 3 ? srgb_decode(encoded(2)) : grey);
      EXPECT_EQ(v.w, channels == 2 ? encoded(1) : channels == 4 ? encoded(3) : 1.f);
    }
  }
}

// Bilinear lookups of 8-bit sRGB colour textures (their own path): the weighted mean of the four
// nearest texels' decoded values, alpha linear, across the repeat seam too.
TEST(Texture, SrgbEightBitBilinearBlendsDecodedTexels) {
  for (int channels : {3, 4}) {
    Texture t;
    t.width = 2, t.height = 2, t.channels = channels;
    t.filter = TextureFilter::kBilinear;
    const uint8_t values[4][4] = {
        {0, 64, 128, 255}, {255, 0, 32, 0}, {10, 20, 30, 40}, {200, 100, 50, 25}};
    for (const auto& texel : values)
      for (int c = 0; c < channels; ++c) t.texels_8bit.push_back(texel[c]);
    auto decoded = [&](int texel, int c) {
      float e = values[texel][c] * (1.f / 255.f);
      return c < 3 ? srgb_decode(e) : channels == 4 ? e : 1.f;
    };
    // u = v = 0.375: a quarter of the way from column 0's centre to column 1's, and likewise
    // from row 0 to row 1. Weights (1 − a)(1 − b), a(1 − b), (1 − a)b, ab with a = b = 0.25.
    Vector4f v = sample_texture(t, {0.375f, 0.375f});
    // u = 1.0: half way between column 1 and (repeated) column 0, on row 0's centre line.
    Vector4f seam = sample_texture(t, {1.0f, 0.25f});
    for (int c = 0; c < 4; ++c) {
      float expected = 0.5625f * decoded(0, c) + 0.1875f * decoded(1, c) + 0.1875f * decoded(2, c) +
                       0.0625f * decoded(3, c);
      EXPECT_NEAR(v[c], expected, 1e-6f) << channels << " channels, c " << c;
      EXPECT_NEAR(seam[c], 0.5f * (decoded(0, c) + decoded(1, c)), 1e-6f) << c;
    }
  }
}

}  // namespace
}  // namespace obscura
