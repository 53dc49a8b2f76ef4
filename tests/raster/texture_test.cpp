// Texture filtering against values worked out by hand.
#include "obscura/raster/texture.h"

#include <gtest/gtest.h>

#include "obscura/math/error.h"

namespace obscura::raster {
namespace {

Image checker(int size, int cell) {
  Image image(size, size, 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      image.set_rgb(x, y, Rgb(((x / cell + y / cell) % 2) ? 1.f : 0.f));
  return image;
}

TEST(Texture, BilinearWeightsTheFourNearestTexelCentres) {
  Image image(2, 2, 3);
  image.set_rgb(0, 0, Rgb(0.f));
  image.set_rgb(1, 0, Rgb(1.f));
  image.set_rgb(0, 1, Rgb(2.f));
  image.set_rgb(1, 1, Rgb(3.f));
  Texture t(image);
  EXPECT_FLOAT_EQ(t.sample_bilinear(0.25f, 0.25f).r, 0.f);  // texel (0, 0)'s centre
  EXPECT_FLOAT_EQ(t.sample_bilinear(0.75f, 0.75f).r, 3.f);
  EXPECT_FLOAT_EQ(t.sample_bilinear(0.5f, 0.5f).r, 1.5f);  // the four averaged
  EXPECT_FLOAT_EQ(t.sample_bilinear(0.5f, 0.25f).r, 0.5f);
  // Wrapping: u = 0 lies halfway between texel 1 (wrapped) and texel 0.
  EXPECT_FLOAT_EQ(t.sample_bilinear(0.f, 0.25f).r, 0.5f);
  EXPECT_FLOAT_EQ(t.sample_nearest(0.9f, 0.1f).r, 1.f);
}

TEST(Texture, MipPyramidAveragesDownToOneTexel) {
  Texture t(checker(16, 1));
  ASSERT_EQ(t.levels(), 5);  // 16, 8, 4, 2, 1
  EXPECT_EQ(t.width(4), 1);
  for (int level = 1; level < t.levels(); ++level)
    EXPECT_FLOAT_EQ(t.texel(level, 0, 0).r, 0.5f) << level;
  // 5 → 2 → 1: level 1 splits the 5×5 checker into blocks of 2 and 3 texels a side, with white
  // fractions 2/4, 3/6, 3/6 and 4/9; the 1×1 level averages those four.
  Texture odd(checker(5, 1));
  ASSERT_EQ(odd.levels(), 3);
  EXPECT_NEAR(odd.texel(2, 0, 0).r, (0.5 + 0.5 + 0.5 + 4.0 / 9) / 4, 1e-6);
}

TEST(Texture, TrilinearPicksTheLevelFromTheFootprint) {
  Texture t(checker(64, 8));  // 8-texel cells: levels 0–3 keep the pattern, 4+ blur it
  float u = (8 * 2 + 4) / 64.f, v = (8 * 1 + 4) / 64.f;  // centre of a white cell
  float one_texel = 1.f / 64;
  EXPECT_FLOAT_EQ(t.sample_trilinear(u, v, one_texel, 0, 0, one_texel).r, 1.f);          // λ = 0
  EXPECT_FLOAT_EQ(t.sample_trilinear(u, v, 4 * one_texel, 0, 0, 4 * one_texel).r, 1.f);  // λ = 2
  // λ = 4.5: halfway between the 4×4 level (cells of half a texel: 0.5) and the 2×2 one (0.5).
  EXPECT_NEAR(t.sample_trilinear(u, v, 22.6274f * one_texel, 0, 0, 0).r, 0.5f, 1e-5);
  // λ = 1.5 stays sharp in a cell's middle (both levels 1 and 2 are white there).
  EXPECT_FLOAT_EQ(t.sample_trilinear(u, v, 2.828f * one_texel, 0, 0, 0).r, 1.f);
}

// Wrap modes as OpenGL defines them (glTF samplers use its names): for a 4-texel row,
// integer coordinate 4 is texel 0 under REPEAT, 3 under CLAMP_TO_EDGE and 3 under
// MIRRORED_REPEAT (the row read backwards); coordinate −1 is texel 3, 0 and 0.
TEST(Texture, WrapModesFollowTheSampler) {
  Image row(4, 1, 3);
  for (int x = 0; x < 4; ++x) row.set_rgb(x, 0, Rgb(float(x)));
  struct Case {
    TextureWrap wrap;
    float at_4, at_5, at_minus_1;
  };
  for (Case c : {Case{TextureWrap::kRepeat, 0, 1, 3}, Case{TextureWrap::kClampToEdge, 3, 3, 0},
                 Case{TextureWrap::kMirroredRepeat, 3, 2, 0}}) {
    Texture t(row, c.wrap, c.wrap);
    EXPECT_EQ(t.sample_nearest(4.5f / 4, 0.5f).r, c.at_4) << int(c.wrap);
    EXPECT_EQ(t.sample_nearest(5.5f / 4, 0.5f).r, c.at_5) << int(c.wrap);
    EXPECT_EQ(t.sample_nearest(-0.5f / 4, 0.5f).r, c.at_minus_1) << int(c.wrap);
  }
  // Bilinear at the right edge: clamping blends the last texel with itself.
  Texture clamped(row, TextureWrap::kClampToEdge, TextureWrap::kClampToEdge);
  EXPECT_FLOAT_EQ(clamped.sample_bilinear(1.f, 0.5f).r, 3.f);
  Texture repeated(row);
  EXPECT_FLOAT_EQ(repeated.sample_bilinear(1.f, 0.5f).r, 1.5f);  // halfway between 3 and 0
}

TEST(Texture, RejectsEmptyImages) {
  Image empty;
  EXPECT_THROW(Texture{empty}, Error);
}

}  // namespace
}  // namespace obscura::raster
