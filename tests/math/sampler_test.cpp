#include "obscura/math/sampler.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace obscura {
namespace {

// The Sobol sampler mixes the (seed, pixel) half of each pair's key once per sample; its numbers
// must stay those of the one-piece hash of (seed, pixel, pair), which images depend on.
TEST(Sampler, SobolNumbersAreThoseOfTheFullPairHash) {
  for (uint64_t seed : {0ull, 7ull, 0x123456789abcull})
    for (Point2i pixel : {Point2i(0, 0), Point2i(31, 7), Point2i(-2, 1000)})
      for (uint32_t index : {0u, 1u, 5u, 1023u}) {
        Sampler sampler(SamplerType::kSobol, seed, pixel, index);
        uint64_t pixel_key = (uint64_t(uint32_t(pixel.y)) << 32) | uint32_t(pixel.x);
        for (uint32_t pair = 0; pair < 4; ++pair) {
          uint64_t key = hash_words(seed, pixel_key, pair, 0x50b01u);
          uint32_t shuffled = owen_scramble(index, uint32_t(key));
          float u0 = fraction_to_float(owen_scramble(sobol_bits(shuffled, 0), uint32_t(key >> 32)));
          float u1 =
              fraction_to_float(owen_scramble(sobol_bits(shuffled, 1), uint32_t(mix_bits(key))));
          Point2f u = sampler.next_2d();
          EXPECT_EQ(u.x, u0) << "pair " << pair;
          EXPECT_EQ(u.y, u1) << "pair " << pair;
        }
      }
}

TEST(Sampler, SameKeyGivesTheSameNumbers) {
  for (SamplerType type : {SamplerType::kSobol, SamplerType::kIndependent}) {
    Sampler a(type, 7, {3, 4}, 5), b(type, 7, {3, 4}, 5);
    for (int i = 0; i < 20; ++i) EXPECT_EQ(a.next_1d(), b.next_1d());
  }
}

TEST(Sampler, SobolPixelSamplesFormZeroNetsInEveryPair) {
  // For 2^k samples of one pixel, each 2D draw is a (0, k, 2)-net: one sample in each of the
  // 2^k elementary intervals of every shape 2^−a × 2^−(k−a).
  for (int k : {4, 6, 8}) {
    int n = 1 << k;
    std::vector<std::vector<Point2f>> draws(4);
    for (int s = 0; s < n; ++s) {
      Sampler sampler(SamplerType::kSobol, 42, {17, 9}, uint32_t(s));
      draws[0].push_back(sampler.next_2d());
      float u = sampler.next_1d();                 // a 1D draw uses half a pair …
      draws[1].push_back({u, sampler.next_1d()});  // … and this one the other half
      draws[2].push_back(sampler.next_2d());
      sampler.next_1d();
      draws[3].push_back(sampler.next_2d());  // realigned to a fresh pair
    }
    for (size_t d = 0; d < draws.size(); ++d)
      for (int a = 0; a <= k; ++a) {
        std::set<std::pair<int, int>> cells;
        for (Point2f p : draws[d]) cells.insert({int(p.x * (1 << a)), int(p.y * (1 << (k - a)))});
        EXPECT_EQ(cells.size(), size_t(n)) << "draw " << d << " 2^" << k << " a " << a;
      }
  }
}

TEST(Sampler, PixelsAreDecorrelated) {
  // The same sample index in neighbouring pixels gets unrelated points (scrambling per pixel).
  int equal = 0;
  for (int x = 0; x < 100; ++x) {
    Sampler a(SamplerType::kSobol, 1, {x, 0}, 0), b(SamplerType::kSobol, 1, {x + 1, 0}, 0);
    equal += a.next_1d() == b.next_1d();
  }
  EXPECT_LT(equal, 3);
}

TEST(Sampler, ValuesAreUniform) {
  // Chi-square over 64 bins of many pixels' samples (63 dof; 99.9 % quantile 103.4).
  for (SamplerType type : {SamplerType::kSobol, SamplerType::kIndependent}) {
    std::vector<int> bins(64, 0);
    int n = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x)
        for (uint32_t s = 0; s < 4; ++s) {
          Sampler sampler(type, 3, {x, y}, s);
          for (int d = 0; d < 5; ++d) {
            float u = sampler.next_1d();
            ASSERT_GE(u, 0.f);
            ASSERT_LT(u, 1.f);
            ++bins[int(u * 64)];
            ++n;
          }
        }
    double expected = n / 64.0, chi2 = 0;
    for (int c : bins) chi2 += (c - expected) * (c - expected) / expected;
    EXPECT_LT(chi2, 103.4) << sampler_type_name(type);
  }
}

TEST(Sampler, SobolMeanConvergesFasterThanIndependent) {
  // ∫₀¹∫₀¹ x·y = 1/4 with 256 samples of one pixel: stratified points land far closer.
  auto error = [](SamplerType type) {
    double worst = 0;
    for (int pixel = 0; pixel < 16; ++pixel) {
      double sum = 0;
      for (uint32_t s = 0; s < 256; ++s) {
        Point2f u = Sampler(type, 5, {pixel, 0}, s).next_2d();
        sum += u.x * u.y;
      }
      worst = std::max(worst, std::abs(sum / 256 - 0.25));
    }
    return worst;
  };
  EXPECT_LT(error(SamplerType::kSobol), 0.004);
  EXPECT_LT(error(SamplerType::kSobol) * 3, error(SamplerType::kIndependent));
}

// Skipping numbers nobody reads must leave every later number as drawing them would: images
// stay the same whether or not a camera or a vertex skips its unused numbers.
TEST(Sampler, SkippedNumbersLeaveTheLaterOnesUnchanged) {
  for (SamplerType type : {SamplerType::kSobol, SamplerType::kIndependent})
    for (uint32_t index : {0u, 3u, 200u}) {
      Sampler drawn(type, 11, {5, 9}, index), skipped(type, 11, {5, 9}, index);
      for (int vertex = 0; vertex < 6; ++vertex) {
        // As the path tracer's vertex: 1d, 2d, 1d, 2d, 1d; odd vertices skip their first three.
        float a = drawn.next_1d();
        Point2f b = drawn.next_2d();
        if (vertex % 2) {
          skipped.skip_1d();
          skipped.skip_2d();
        } else {
          EXPECT_EQ(skipped.next_1d(), a);
          EXPECT_EQ(skipped.next_2d(), b);
        }
        EXPECT_EQ(skipped.next_1d(), drawn.next_1d());
        Point2f c = drawn.next_2d();
        EXPECT_EQ(skipped.next_2d(), c);
        EXPECT_EQ(skipped.dimension(), drawn.dimension());
      }
    }
}

// A pixel's cached pair hashes, shared by its samples, give the numbers the sampler computes on
// its own: past the cache's pairs too.
TEST(Sampler, CachedPixelKeysGiveTheSameNumbers) {
  for (Point2i pixel : {Point2i(0, 0), Point2i(17, -3)}) {
    SobolPixelKeys keys(42, pixel);
    for (uint32_t index : {0u, 1u, 2u, 77u}) {
      Sampler cached(SamplerType::kSobol, 42, pixel, index, keys);
      Sampler own(SamplerType::kSobol, 42, pixel, index);
      for (uint32_t d = 0; d < 2 * SobolPixelKeys::kPairs + 9; ++d)
        EXPECT_EQ(cached.next_1d(), own.next_1d()) << "dimension " << d;
    }
  }
}

}  // namespace
}  // namespace obscura
