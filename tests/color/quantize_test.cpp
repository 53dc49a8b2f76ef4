// Quantization, dithering and the blue-noise mask.
#include "obscura/color/quantize.h"

#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "obscura/color/blue_noise.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

TEST(Quantize, ExactIntegersAtFiveToEightBits) {
  // By hand: q = floor(v·(2ᴺ − 1) + ½).
  struct Case {
    double v;
    uint32_t q5, q6, q7, q8;
  };
  const Case cases[] = {
      {0.0, 0, 0, 0, 0},   {1.0, 31, 63, 127, 255}, {0.5, 16, 32, 64, 128},
      {0.1, 3, 6, 13, 26}, {0.2, 6, 13, 25, 51},    {0.75, 23, 47, 95, 191},
      {-0.3, 0, 0, 0, 0},  {1.7, 31, 63, 127, 255}, {1.0 / 3, 10, 21, 42, 85},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(quantize(c.v, 5), c.q5) << c.v;
    EXPECT_EQ(quantize(c.v, 6), c.q6) << c.v;
    EXPECT_EQ(quantize(c.v, 7), c.q7) << c.v;
    EXPECT_EQ(quantize(c.v, 8), c.q8) << c.v;
  }
  EXPECT_EQ(quantize(std::nan(""), 8), 0u);  // a defined value, never garbage
  EXPECT_EQ(quantize(0.5, 1), 1u);           // 1 bit: round half up
  EXPECT_EQ(quantize(0.49, 1), 0u);
  EXPECT_EQ(quantize(1.0, 16), 65535u);
}

TEST(Quantize, RequantizeIsExactRoundingNotBitReplication) {
  EXPECT_EQ(requantize(31, 5, 8), 255u);
  EXPECT_EQ(requantize(1, 5, 8), 8u);     // 255/31 = 8.23 → 8 (bit replication gives 8 too)
  EXPECT_EQ(requantize(16, 5, 8), 132u);  // 16·255/31 = 131.6 → 132 (bit replication: 132)
  EXPECT_EQ(requantize(3, 5, 8), 25u);    // 24.68 → 25 (bit replication: 24)
  EXPECT_EQ(requantize(128, 8, 1), 1u);
  EXPECT_THROW(requantize(32, 5, 8), Error);
}

TEST(Quantize, BadBitDepthsAreErrors) {
  EXPECT_THROW(quantize(0.5, 0), Error);
  EXPECT_THROW(quantize(0.5, 17), Error);
  EXPECT_THROW(parse_dither("floyd"), Error);
}

// The average code of a dithered flat field equals the exact level (to well within ½ LSB),
// where plain rounding is off by up to ½ LSB: the whole point of dithering.
TEST(Dither, KeepsTheMeanOfAFlatField) {
  const int bits = 5, size = 128;
  const double max = 31;
  for (Dither d : {Dither::kBayer, Dither::kBlueNoise})
    for (double v : {0.1, 0.237, 0.5, 0.61, 0.9}) {
      for (int channel = 0; channel < 3; ++channel) {
        double sum = 0;
        std::set<uint32_t> distinct;
        for (int y = 0; y < size; ++y)
          for (int x = 0; x < size; ++x) {
            uint32_t q = quantize_dithered(v, bits, dither_offset(d, x, y, channel));
            sum += q;
            distinct.insert(q);
          }
        double mean = sum / (size * size);
        EXPECT_LT(std::abs(mean - v * max), 0.5) << dither_name(d) << " at " << v;
        EXPECT_LT(std::abs(mean - v * max), 0.02) << dither_name(d) << " at " << v;
        EXPECT_EQ(distinct.size(), 2u) << "a flat field dithers between two neighbouring codes";
      }
    }
}

TEST(Dither, OffsetsAreCentredAndBounded) {
  for (Dither d : {Dither::kBayer, Dither::kBlueNoise}) {
    double sum = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        float o = dither_offset(d, x, y);
        EXPECT_GT(o, -0.5f);
        EXPECT_LT(o, 0.5f);
        sum += o;
      }
    EXPECT_NEAR(sum / 4096, 0, 1e-6);
  }
  EXPECT_EQ(dither_offset(Dither::kNone, 3, 4), 0.f);
}

TEST(BlueNoise, MaskIsAPermutation) {
  const BlueNoiseMask& mask = blue_noise_mask();
  ASSERT_EQ(mask.size, 64);
  std::set<uint32_t> ranks(mask.ranks.begin(), mask.ranks.end());
  EXPECT_EQ(ranks.size(), 4096u);
  EXPECT_EQ(*ranks.rbegin(), 4095u);
}

// Blue noise spreads the dots of every threshold level evenly: at 10 % density, random (white)
// noise gives about 57 % of dots a neighbour among their 8 surrounding pixels (1 − 0.9⁸); a
// blue-noise pattern almost none.
TEST(BlueNoise, DotsOfALevelAvoidEachOther) {
  const BlueNoiseMask& mask = blue_noise_mask();
  const int n = mask.size;
  auto dot = [&](int x, int y) { return mask.threshold((x + n) % n, (y + n) % n) < 0.1f; };
  int dots = 0, crowded = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      if (!dot(x, y)) continue;
      ++dots;
      bool neighbour = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if ((dx || dy) && dot(x + dx, y + dy)) neighbour = true;
      crowded += neighbour;
    }
  EXPECT_NEAR(dots, 410, 2);
  EXPECT_LT(crowded, dots / 20);
}

TEST(BlueNoise, GenerationIsDeterministic) {
  EXPECT_EQ(generate_blue_noise(16, 7).ranks, generate_blue_noise(16, 7).ranks);
}

}  // namespace
}  // namespace obscura
