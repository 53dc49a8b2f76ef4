#include "obscura/math/distribution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "obscura/math/rng.h"

namespace obscura {
namespace {

TEST(Distribution1D, DiscreteProbabilitiesFollowTheWeights) {
  std::vector<float> w = {1, 0, 3, 4};
  Distribution1D d(w);
  EXPECT_FLOAT_EQ(d.probability(0), 0.125f);
  EXPECT_FLOAT_EQ(d.probability(1), 0.f);
  EXPECT_FLOAT_EQ(d.probability(2), 0.375f);
  EXPECT_EQ(d.sample_discrete(0.1f), 0u);
  EXPECT_EQ(d.sample_discrete(0.125f), 2u);  // the empty cell is never chosen
  EXPECT_EQ(d.sample_discrete(0.99f), 3u);
  EXPECT_DOUBLE_EQ(d.integral(), 2.0);  // (1 + 0 + 3 + 4) / 4 cells
}

TEST(Distribution1D, ContinuousSamplesHaveTheStatedDensity) {
  std::vector<float> w = {2, 1, 0, 1};
  Distribution1D d(w);
  Pcg32 rng(1);
  std::vector<int> counts(4, 0);
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    float pdf;
    float x = d.sample_continuous(rng.next_float(), &pdf);
    ASSERT_GE(x, 0.f);
    ASSERT_LT(x, 1.f);
    EXPECT_FLOAT_EQ(pdf, d.pdf_continuous(x));
    ++counts[int(x * 4)];
  }
  EXPECT_NEAR(counts[0] / double(n), 0.5, 0.01);
  EXPECT_EQ(counts[2], 0);
  EXPECT_FLOAT_EQ(d.pdf_continuous(0.1f), 2.f);  // 0.5 probability over a cell of width 0.25
}

TEST(Distribution1D, AllZeroIsUniform) {
  std::vector<float> w = {0, 0};
  Distribution1D d(w);
  EXPECT_FLOAT_EQ(d.probability(0), 0.5f);
}

TEST(Distribution2D, PdfIntegratesToOneAndMatchesSampling) {
  std::vector<float> w = {1, 2, 3, 0, 0, 0};  // 3 × 2
  Distribution2D d(w, 3, 2);
  double integral = 0;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) integral += d.pdf({(x + 0.5f) / 3, (y + 0.5f) / 2}) / 6;
  EXPECT_NEAR(integral, 1.0, 1e-6);
  Pcg32 rng(2);
  for (int i = 0; i < 1000; ++i) {
    float pdf;
    Point2f p = d.sample({rng.next_float(), rng.next_float()}, &pdf);
    EXPECT_NEAR(pdf, d.pdf(p), 1e-4f);
    EXPECT_LT(p.y, 0.5f);  // the second row is empty
  }
}

}  // namespace
}  // namespace obscura

namespace obscura {
namespace {

// A light of power inf (emission 1e38 over an area) once made the CDF ∞/∞ = NaN, and every
// sample fell through to a cell of no weight.
TEST(Distribution1D, InfiniteAndNaNWeightsGiveAFiniteDistribution) {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> w = {0, nan, inf, 2};
  Distribution1D d(w);
  float total = 0;
  for (size_t i = 0; i < w.size(); ++i) {
    EXPECT_TRUE(std::isfinite(d.probability(i))) << i;
    total += d.probability(i);
  }
  EXPECT_NEAR(total, 1, 1e-6);
  EXPECT_EQ(d.probability(0), 0);
  EXPECT_EQ(d.probability(1), 0);  // NaN: no weight
  EXPECT_NEAR(d.probability(2), 1, 1e-6);
  for (float u : {0.f, 0.25f, 0.5f, 0.999f, nan}) {
    float p = -1;
    size_t i = d.sample_discrete(u, &p);
    EXPECT_LT(i, w.size());
    EXPECT_TRUE(p >= 0 && p <= 1) << u;
    if (!std::isnan(u)) {
      EXPECT_EQ(i, 2u) << u;
    }
  }
  EXPECT_TRUE(std::isfinite(d.pdf_continuous(nan)));
}

}  // namespace
}  // namespace obscura
