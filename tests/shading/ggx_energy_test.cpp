// The GGX energy tables (integrated by quadrature over the normal distribution) against Monte
// Carlo estimates made a different way: visible normals drawn with the tracer's own sampler
// (Heitz 2018), where E(μo) is the mean of G2(wo, wi) / G1(wo). And the property the tables
// exist for: with the multiple-scattering lobe, a white GGX surface reflects everything.
#include "obscura/shading/ggx_energy.h"

#include <gtest/gtest.h>

#include <cmath>

#include "obscura/math/rng.h"
#include "obscura/trace/ggx.h"

namespace obscura {
namespace {

struct Estimate {
  double e1 = 0, e5 = 0;
};

Estimate monte_carlo_albedo(float mu, float alpha, int samples, uint64_t seed) {
  Ggx ggx(alpha);
  Vector3f wo(std::sqrt(1 - mu * mu), 0, mu);
  Pcg32 rng(seed);
  Estimate e;
  for (int i = 0; i < samples; ++i) {
    Vector3f m = ggx.sample_visible_normal(wo, {rng.next_float(), rng.next_float()});
    float o_m = dot(wo, m);
    Vector3f wi = m * (2 * o_m) - wo;
    if (wi.z <= 0 || o_m <= 0) continue;
    double weight = ggx.G(wo, wi) / ggx.G1(wo);
    e.e1 += weight, e.e5 += weight * std::pow(1.0 - o_m, 5);
  }
  e.e1 /= samples, e.e5 /= samples;
  return e;
}

TEST(GgxEnergy, DirectionalAlbedoMatchesMonteCarlo) {
  // Off the table's nodes, so interpolation error is included. 200,000 samples: standard error
  // below 1e-3; the tolerance adds the bilinear interpolation error.
  for (float alpha : {0.013f, 0.09f, 0.27f, 0.55f, 0.83f, 1.f})
    for (float mu : {0.07f, 0.21f, 0.48f, 0.77f, 0.995f}) {
      Estimate mc = monte_carlo_albedo(mu, alpha, 200000, uint64_t(1000 * mu + 7 * alpha * 1000));
      EXPECT_NEAR(shading::ggx_albedo(mu, alpha), mc.e1, 6e-3) << "α " << alpha << " μ " << mu;
      float schlick = shading::ggx_schlick_albedo(0.04f, mu, alpha);
      EXPECT_NEAR(schlick, 0.04 * mc.e1 + 0.96 * mc.e5, 4e-3) << "α " << alpha << " μ " << mu;
    }
}

TEST(GgxEnergy, LimitsByHand) {
  // A near-mirror reflects everything (away from grazing, where even a tiny width masks), and
  // its (1 − v·h)⁵ weighted albedo is Schlick's term at the mirror direction, (1 − μ)⁵.
  for (float mu : {0.3f, 0.6f, 0.9f}) {
    EXPECT_NEAR(shading::ggx_albedo(mu, 1e-4f), 1, 2e-3);
    EXPECT_NEAR(shading::ggx_schlick_albedo(0, mu, 1e-4f), std::pow(1 - mu, 5), 2e-3);
  }
  // At normal incidence with α = 1, by hand: D cos θh dωh = d(sin²θh) dφ / 2π, wi = reflect(n)
  // at 2θh is above the surface only for sin²θh = s < ½, Λ(c) = (1/c − 1)/2 so G = 2c / (1 + c)
  // with c = cos 2θh = 1 − 2s, and E = ∫₀^½ (1 − 2s)/(1 − s) ds = 1 − ln 2. Half of all
  // reflections leave below the horizon: the roughest GGX keeps under a third of the light.
  EXPECT_NEAR(shading::ggx_albedo(1, 1), 1 - std::log(2.0), 2e-3);
  // The same integral weighted by (1 − cos θh)⁵, cos θh = √(1 − s), by Simpson's rule.
  double e5 = 0;
  const int n = 2000;
  for (int i = 0; i <= n; ++i) {
    double s = 0.5 * i / n, g = (1 - 2 * s) / (1 - s) * std::pow(1 - std::sqrt(1 - s), 5);
    e5 += g * (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2));
  }
  e5 *= 0.5 / n / 3;
  EXPECT_NEAR(shading::ggx_schlick_albedo(0, 1, 1), e5, 1e-3);
  // Schlick's average: f0 + (1 − f0) · 2∫(1 − μ)⁵ μ dμ = f0 + (1 − f0)/21.
  EXPECT_NEAR(shading::schlick_average(Rgb(0.04f)).g, 0.04 + 0.96 / 21, 1e-6);
  Rgb f_avg = shading::fresnel_average([](float mu) {
    float m = 1 - mu;
    return Rgb(0.04f + 0.96f * m * m * m * m * m);
  });
  EXPECT_NEAR(f_avg.g, 0.04 + 0.96 / 21, 1e-4);
}

TEST(GgxEnergy, AverageAlbedoMatchesMonteCarlo) {
  // E_avg = 2 ∫ E(μ) μ dμ: μ drawn with density 2μ (μ = √u), one visible normal per μ.
  for (float alpha : {0.05f, 0.3f, 0.7f, 1.f}) {
    Ggx ggx(alpha);
    Pcg32 rng(uint64_t(alpha * 100));
    const int n = 400000;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      float mu = std::sqrt(std::max(rng.next_float(), 1e-12f));
      Vector3f wo(std::sqrt(1 - mu * mu), 0, mu);
      Vector3f m = ggx.sample_visible_normal(wo, {rng.next_float(), rng.next_float()});
      Vector3f wi = m * (2 * dot(wo, m)) - wo;
      if (wi.z > 0) sum += ggx.G(wo, wi) / ggx.G1(wo);
    }
    EXPECT_NEAR(shading::ggx_average_albedo(alpha), sum / n, 4e-3) << "α " << alpha;
  }
}

TEST(GgxEnergy, WhiteSurfaceWithMultipleScatteringReflectsEverything) {
  // ∫ (f + f_ms) μi dωi over the hemisphere, f by visible-normal sampling (as above) and f_ms
  // (diffuse-like) by cosine sampling: 1 for F = 1, at every angle and roughness.
  for (float alpha : {0.1f, 0.4f, 0.8f, 1.f})
    for (float mu : {0.15f, 0.5f, 0.9f}) {
      Estimate single = monte_carlo_albedo(mu, alpha, 200000, 99);
      Pcg32 rng(5);
      double multiple = 0;
      const int n = 100000;
      for (int i = 0; i < n; ++i) {
        float mu_i = std::sqrt(std::max(rng.next_float(), 1e-12f));  // pdf = μi/π per sr
        multiple += shading::ggx_multiple_scattering(mu, mu_i, alpha) * 3.14159265;
      }
      EXPECT_NEAR(single.e1 + multiple / n, 1, 8e-3) << "α " << alpha << " μ " << mu;
    }
  // The colour of the extra bounces: F_avg² E_avg / (1 − F_avg (1 − E_avg)); 1 for F = 1,
  // and for a darker metal less than F_avg (each bounce absorbs).
  EXPECT_NEAR(shading::multiple_scattering_color(Rgb(1.f), 0.5f).g, 1, 1e-6);
  EXPECT_LT(shading::multiple_scattering_color(Rgb(0.6f), 0.5f).g, 0.6f);
}

}  // namespace
}  // namespace obscura
