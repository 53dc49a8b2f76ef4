#include "obscura/math/sampler.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace obscura {
namespace {

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

}  // namespace
}  // namespace obscura
