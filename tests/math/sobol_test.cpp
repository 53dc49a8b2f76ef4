#include "obscura/math/sobol.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace obscura {
namespace {

// Whether points (as 32-bit fractions) put exactly one point in every elementary interval
// [i/2^a, (i+1)/2^a) × [j/2^b, (j+1)/2^b) with a + b = k: a (0, k, 2)-net in base 2.
bool is_zero_net(const std::vector<std::pair<uint32_t, uint32_t>>& points, int k) {
  for (int a = 0; a <= k; ++a) {
    int b = k - a;
    std::set<uint64_t> cells;
    for (auto [x, y] : points) {
      uint64_t cx = a == 0 ? 0 : x >> (32 - a), cy = b == 0 ? 0 : y >> (32 - b);
      if (!cells.insert((cx << 32) | cy).second) return false;
    }
  }
  return true;
}

TEST(Sobol, FirstDimensionIsVanDerCorput) {
  // The radical inverse in base 2: 0, 1/2, 1/4, 3/4, 1/8, 5/8, …
  const double expected[] = {0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
  for (uint32_t i = 0; i < 8; ++i) EXPECT_EQ(sobol_bits(i, 0) * 0x1p-32, expected[i]);
  EXPECT_EQ(sobol_bits(0xffffffffu, 0), 0xffffffffu);
}

TEST(Sobol, SecondDimensionMatchesItsPolynomial) {
  // Dimension 1 (x + 1, m₁ = 1): v_k = v_{k−1} ⊕ v_{k−1}/2, i.e. 1/2, 3/4, 5/8, 15/16, … and
  // point i is the XOR of the v_k for the bits of i (worked by hand).
  const double expected[] = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
  for (uint32_t i = 0; i < 8; ++i) EXPECT_EQ(sobol_bits(i, 1) * 0x1p-32, expected[i]) << i;
}

TEST(Sobol, FirstTwoDimensionsFormZeroNetsForEveryPowerOfTwo) {
  for (int k = 0; k <= 12; ++k) {
    std::vector<std::pair<uint32_t, uint32_t>> points;
    for (uint32_t i = 0; i < (1u << k); ++i) points.push_back({sobol_bits(i, 0), sobol_bits(i, 1)});
    EXPECT_TRUE(is_zero_net(points, k)) << "2^" << k << " points";
    // And so does every later aligned block of 2^k points.
    points.clear();
    for (uint32_t i = 0; i < (1u << k); ++i)
      points.push_back({sobol_bits((5u << k) + i, 0), sobol_bits((5u << k) + i, 1)});
    EXPECT_TRUE(is_zero_net(points, k)) << "block 5 of 2^" << k;
  }
}

TEST(Sobol, EveryDimensionStratifiesTheUnitInterval) {
  // Each one-dimensional projection of a Sobol sequence is a (0, 1)-sequence: the first 2^k
  // points fall one in each interval [i/2^k, (i+1)/2^k).
  for (int d = 0; d < kSobolDimensions; ++d)
    for (int k : {1, 4, 10}) {
      std::set<uint32_t> strata;
      for (uint32_t i = 0; i < (1u << k); ++i) strata.insert(sobol_bits(i, d) >> (32 - k));
      EXPECT_EQ(strata.size(), size_t(1) << k) << "dimension " << d << " 2^" << k;
    }
}

TEST(Sobol, DimensionsDiffer) {
  for (int d = 1; d < kSobolDimensions; ++d) {
    int same = 0;
    for (uint32_t i = 1; i < 64; ++i) same += sobol_bits(i, d) == sobol_bits(i, d - 1);
    EXPECT_LT(same, 32) << d;
  }
}

TEST(OwenScramble, KeepsTheNetAndMovesThePoints) {
  for (uint32_t seed : {1u, 0xdeadbeefu, 12345u}) {
    std::vector<std::pair<uint32_t, uint32_t>> points;
    int moved = 0;
    for (uint32_t i = 0; i < 256; ++i) {
      points.push_back(
          {owen_scramble(sobol_bits(i, 0), seed), owen_scramble(sobol_bits(i, 1), seed * 7 + 1)});
      moved += points.back().first != sobol_bits(i, 0);
    }
    EXPECT_TRUE(is_zero_net(points, 8)) << seed;
    EXPECT_GT(moved, 200);
  }
}

TEST(OwenScramble, IsABijectionOfTheLowBitsUnderFixedHighBits) {
  // Scrambling from the top down maps the first 2^k integers onto one aligned block of 2^k.
  for (uint32_t seed : {3u, 77u}) {
    std::set<uint32_t> images;
    for (uint32_t i = 0; i < 1024; ++i) images.insert(owen_scramble(i, seed));
    EXPECT_EQ(images.size(), 1024u);
    EXPECT_EQ(*images.rbegin() - *images.begin(), 1023u);
    EXPECT_EQ(*images.begin() % 1024, 0u);
  }
}

TEST(Sobol, ReverseBits) {
  EXPECT_EQ(reverse_bits(1u), 0x80000000u);
  EXPECT_EQ(reverse_bits(0x0000f00fu), 0xf00f0000u);
  // Against bit i moved to bit 31 − i, one bit at a time.
  for (uint32_t v : {0u, 0xffffffffu, 0x12345678u, 0x80000001u, 0x00ff00f0u, 0xdeadbeefu}) {
    uint32_t expected = 0;
    for (int i = 0; i < 32; ++i)
      if (v & (1u << i)) expected |= 1u << (31 - i);
    EXPECT_EQ(reverse_bits(v), expected) << std::hex << v;
  }
}

// The shortcut for a scrambled dimension-0 point is the scramble of the built point.
TEST(OwenScramble, VanDerCorputShortcutEqualsScramblingThePoint) {
  for (uint32_t seed : {0u, 1u, 0x9e3779b9u, 0xffffffffu})
    for (uint32_t i : {0u, 1u, 2u, 3u, 255u, 256u, 65535u, 0x12345678u})
      EXPECT_EQ(owen_scrambled_van_der_corput(i, seed), owen_scramble(sobol_bits(i, 0), seed));
}

}  // namespace
}  // namespace obscura
