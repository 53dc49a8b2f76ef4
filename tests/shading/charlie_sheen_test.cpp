// The Charlie sheen lobe: its distribution's normalization, and the albedo table (integrated by
// quadrature over the incoming hemisphere) against a brute-force Monte Carlo integral of the
// lobe drawn uniformly over the hemisphere, a different method with independent errors.
#include "obscura/shading/charlie_sheen.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "obscura/math/rng.h"

namespace obscura {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(CharlieSheen, DistributionIsNormalized) {
  // ∫ D cos θh dωh = 2π ∫₀¹ D(μ) μ dμ, by the midpoint rule on a fine grid.
  for (float alpha : {shading::kMinSheenAlpha, 0.01f, 0.1f, 0.5f, 1.f}) {
    const int n = 200000;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      double mu = (i + 0.5) / n;
      sum += shading::charlie_distribution(float(mu), alpha) * mu;
    }
    EXPECT_NEAR(2 * kPi * sum / n, 1, 2e-3) << "α " << alpha;
  }
}

TEST(CharlieSheen, LambdaFitIsContinuousAtOneHalf) {
  // The fit is mirrored about μ = ½: both branches meet there.
  for (float alpha : {0.01f, 0.3f, 1.f})
    EXPECT_NEAR(shading::charlie_lambda(0.4999f, alpha), shading::charlie_lambda(0.5001f, alpha),
                1e-3f * shading::charlie_lambda(0.5f, alpha));
}

double monte_carlo_albedo(float mu, float alpha, int samples, uint64_t seed) {
  Pcg32 rng(seed);
  const double sin_o = std::sqrt(1.0 - double(mu) * mu);
  double sum = 0;
  for (int i = 0; i < samples; ++i) {
    double z = rng.next_float(), phi = 2 * kPi * rng.next_float();  // uniform hemisphere
    double r = std::sqrt(std::max(0.0, 1 - z * z));
    double hx = sin_o + r * std::cos(phi), hy = r * std::sin(phi), hz = mu + z;
    double cos_h = hz / std::sqrt(hx * hx + hy * hy + hz * hz);
    sum += shading::charlie_sheen(mu, float(z), float(cos_h), alpha) * z * 2 * kPi;
  }
  return sum / samples;
}

TEST(CharlieSheen, AlbedoTableMatchesMonteCarlo) {
  // Off the table's nodes, so interpolation is included: 400,000 samples give standard errors
  // below 1.5e-3; the tolerance adds the table's bilinear error (steepest at low roughness).
  for (float roughness : {0.25f, 0.43f, 0.61f, 0.87f, 1.f})
    for (float mu : {0.06f, 0.23f, 0.51f, 0.78f, 0.97f}) {
      float alpha = shading::sheen_alpha(roughness);
      double mc = monte_carlo_albedo(mu, alpha, 400000, uint64_t(1000 * mu + 100 * roughness));
      EXPECT_NEAR(shading::sheen_albedo(mu, alpha), mc, 6e-3 + 0.01 * mc)
          << "roughness " << roughness << " μ " << mu;
    }
}

TEST(CharlieSheen, EnergyBoundOnlyActsWhereTheLobeGainsEnergy) {
  EXPECT_EQ(shading::sheen_energy_bound(0.3f, 0.99f), 1.f);
  EXPECT_FLOAT_EQ(shading::sheen_energy_bound(0.3f, 2.f), 0.5f);
  // The fitted lobe does reflect more than arrives at grazing angles for low roughness.
  EXPECT_GT(shading::sheen_albedo(0.02f, shading::sheen_alpha(0)), 1.5f);
}

}  // namespace
}  // namespace obscura
