#include "obscura/shading/ggx.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "obscura/math/vector.h"

namespace obscura::shading {
namespace {

constexpr double kPiD = std::numbers::pi;

// ∫ g(ω) dω over the upper hemisphere by the midpoint rule in (cos θ, φ).
template <class F>
double integrate_hemisphere(F g, int nz = 2000, int nphi = 64) {
  double sum = 0, dz = 1.0 / nz, dphi = 2 * kPiD / nphi;
  for (int i = 0; i < nz; ++i)
    for (int j = 0; j < nphi; ++j) {
      double z = (i + 0.5) * dz, phi = (j + 0.5) * dphi, r = std::sqrt(1 - z * z);
      sum += g(Vector3f(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)));
    }
  return sum * dz * dphi;
}

TEST(ShadingGgx, ProjectedNormalDensityIntegratesToOne) {
  for (float alpha : {0.05f, 0.2f, 0.5f, 1.0f}) {
    double total = integrate_hemisphere([&](Vector3f m) { return ggx_d(m.z, alpha) * m.z; },
                                        alpha < 0.1f ? 20000 : 2000);
    EXPECT_NEAR(total, 1.0, 2e-3) << "alpha " << alpha;
  }
}

TEST(ShadingGgx, AlphaOneIsTheUniformDistributionOverTheHemisphere) {
  // With α = 1, D(m) = 1/π for every normal above the surface, none below.
  for (float c : {1.f, 0.7f, 0.2f}) EXPECT_NEAR(ggx_d(c, 1), 1 / kPiD, 1e-6) << c;
  EXPECT_EQ(ggx_d(-0.3f, 1), 0.f);
  EXPECT_EQ(ggx_d(0.f, 0.5f), 0.f);
}

TEST(ShadingGgx, SmithLambdaMakesTheVisibleProjectedAreaTheMacroSurfaces) {
  // Smith's defining property: the microfacets seen from w cover the macro-surface's projected
  // area, ∫ G1(w) max(0, w·m) D(m) dm = cos θw, with G1 = 1/(1 + Λ).
  for (float alpha : {0.1f, 0.4f, 0.9f})
    for (float theta : {0.f, 0.7f, 1.3f, 1.5f}) {
      Vector3f w(std::sin(theta), 0, std::cos(theta));
      float g1 = 1 / (1 + ggx_lambda(w.z * w.z, alpha));
      double seen = integrate_hemisphere(
          [&](Vector3f m) { return g1 * std::max(0.f, dot(w, m)) * ggx_d(m.z, alpha); }, 8000, 256);
      EXPECT_NEAR(seen, w.z, 3e-3) << "alpha " << alpha << " theta " << theta;
    }
}

TEST(ShadingGgx, NoMaskingAlongTheNormalAndFullMaskingAtGrazing) {
  EXPECT_EQ(ggx_lambda(1, 0.5f), 0.f);
  EXPECT_EQ(ggx_g(0, 0), 1.f);
  EXPECT_GT(ggx_lambda(0.01f, 0.5f), 0.f);
  EXPECT_NEAR(1 / (1 + ggx_lambda(0.f, 0.5f)), 0.f, 1e-20f);
}

TEST(ShadingGgx, SpecularLobeIsReciprocal) {
  for (float alpha : {0.1f, 0.5f})
    EXPECT_FLOAT_EQ(ggx_specular(0.3f, 0.8f, 0.9f, alpha), ggx_specular(0.8f, 0.3f, 0.9f, alpha));
}

TEST(ShadingGgx, SmoothLobeReflectsAlmostAllLightAtNormalIncidence) {
  // A nearly smooth surface loses almost nothing to masking: the lobe's albedo
  // ∫ f cos θi dωi seen from the normal tends to 1 as α → 0 (Kulla & Conty's E(μ = 1) is
  // above 0.99 for α = 0.1²).
  const float alpha = 0.01f;
  const Vector3f wo(0, 0, 1);
  double albedo = integrate_hemisphere(
      [&](Vector3f wi) {
        Vector3f h = normalize(wo + wi);
        return ggx_specular(wo.z, wi.z, h.z, alpha) * wi.z;
      },
      200000, 16);
  EXPECT_NEAR(albedo, 1.0, 1e-2);
}

}  // namespace
}  // namespace obscura::shading
