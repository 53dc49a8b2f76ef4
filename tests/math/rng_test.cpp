#include "obscura/math/rng.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace obscura {
namespace {

TEST(Pcg32, MatchesTheReferenceImplementationsSequence) {
  // pcg32_srandom_r(&rng, 42, 54) followed by pcg32_random_r, as printed by the pcg-c-basic demo
  // (O'Neill, pcg-random.org).
  Pcg32 rng(42, 54);
  const uint32_t expected[] = {0xa15c02b7, 0x7b47f409, 0xba1d3330, 0x83d2f293, 0xbfa4784b,
                               0xcbed606e};
  for (uint32_t e : expected) EXPECT_EQ(rng.next_uint32(), e);
}

TEST(PixelSampler, SameKeyGivesTheSameNumbers) {
  for (int dim = 0; dim < 8; ++dim)
    EXPECT_EQ(sample_uniform(7, {3, 4}, 5, dim), sample_uniform(7, {3, 4}, 5, dim));
  PixelSampler a(7, {3, 4}, 5), b(7, {3, 4}, 5);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(a.next_1d(), b.next_1d());
  // The sampler's n-th number is the dimension-n value, whatever was drawn before it.
  PixelSampler c(7, {3, 4}, 5);
  c.next_2d();
  EXPECT_EQ(c.next_1d(), sample_uniform(7, {3, 4}, 5, 2));
}

TEST(PixelSampler, EveryPartOfTheKeyChangesTheNumber) {
  float base = sample_uniform(1, {10, 20}, 3, 4);
  EXPECT_NE(base, sample_uniform(2, {10, 20}, 3, 4));
  EXPECT_NE(base, sample_uniform(1, {11, 20}, 3, 4));
  EXPECT_NE(base, sample_uniform(1, {10, 21}, 3, 4));
  EXPECT_NE(base, sample_uniform(1, {20, 10}, 3, 4));  // x and y are not interchangeable
  EXPECT_NE(base, sample_uniform(1, {10, 20}, 4, 4));
  EXPECT_NE(base, sample_uniform(1, {10, 20}, 3, 5));
}

TEST(PixelSampler, ValuesAreUniformAndPairsIndependent) {
  // Chi-square over 16 bins in 1D and 16×16 cells for consecutive dimensions.
  constexpr int kBins = 16, kN = 256 * 1024;
  std::vector<int> bins(kBins, 0), cells(kBins * kBins, 0);
  for (int i = 0; i < kN; ++i) {
    PixelSampler s(99, {i % 512, i / 512}, 0);
    Point2f u = s.next_2d();
    ASSERT_GE(u.x, 0.f);
    ASSERT_LT(u.x, 1.f);
    ++bins[int(u.x * kBins)];
    ++cells[int(u.x * kBins) * kBins + int(u.y * kBins)];
  }
  auto chi2 = [](const std::vector<int>& counts, double expected) {
    double sum = 0;
    for (int c : counts) sum += (c - expected) * (c - expected) / expected;
    return sum;
  };
  // 99.9th percentiles of χ² with 15 and 255 degrees of freedom: 37.70 and 330.5.
  EXPECT_LT(chi2(bins, double(kN) / kBins), 37.70);
  EXPECT_LT(chi2(cells, double(kN) / (kBins * kBins)), 330.5);
}

TEST(Pcg32, FloatsStayInTheUnitInterval) {
  Pcg32 rng(1);
  std::set<float> distinct;
  for (int i = 0; i < 10000; ++i) {
    float f = rng.next_float();
    ASSERT_GE(f, 0.f);
    ASSERT_LT(f, 1.f);
    distinct.insert(f);
  }
  EXPECT_GT(distinct.size(), 9990u);
}

}  // namespace
}  // namespace obscura
