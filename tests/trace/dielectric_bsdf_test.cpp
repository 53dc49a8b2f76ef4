#include "obscura/trace/dielectric_bsdf.h"

#include <gtest/gtest.h>

#include "bsdf_test_support.h"
#include "obscura/shading/fresnel.h"

namespace obscura {
namespace {

using testing::direction_at;

TEST(DielectricBsdf, RoughSamplingMatchesPdfFromBothSides) {
  for (float alpha : {0.2f, 0.5f}) {
    AnyBsdf bsdf = DielectricBsdf(1.5f, alpha);
    // > 90°: arriving from inside. (Near grazing outside incidence the transmitted density has
    // an integrable singularity at the edge of its support that the midpoint quadrature of the
    // expected counts cannot resolve, so 75° is left to the energy and reciprocity tests.)
    for (float theta : {0.f, 40.f, 60.f, 120.f, 170.f}) {
      SCOPED_TRACE(::testing::Message() << "alpha " << alpha << " theta " << theta);
      EXPECT_SAMPLING_MATCHES_PDF(bsdf, direction_at(theta));
    }
  }
}

TEST(DielectricBsdf, SmoothSplitsEnergyByFresnel) {
  DielectricBsdf bsdf(1.5f, 0);
  Vector3f wo = direction_at(50);
  float r = shading::fresnel_dielectric(wo.z, 1.5f);
  std::optional<BsdfSample> reflected = bsdf.sample(wo, 0.5f * r, {0.5f, 0.5f});
  std::optional<BsdfSample> refracted = bsdf.sample(wo, 0.5f + 0.5f * r, {0.5f, 0.5f});
  ASSERT_TRUE(reflected && refracted);
  EXPECT_FALSE(reflected->is_transmission);
  EXPECT_TRUE(refracted->is_transmission);
  EXPECT_NEAR(reflected->pdf, r, 1e-6f);
  EXPECT_NEAR(refracted->pdf, 1 - r, 1e-6f);
  // Snell: sin θt = sin θi / η, on the other side, in the plane of incidence.
  float sin_i = std::sqrt(1 - wo.z * wo.z),
        sin_t = std::sqrt(1 - refracted->wi.z * refracted->wi.z);
  EXPECT_NEAR(sin_t, sin_i / 1.5f, 1e-5f);
  EXPECT_LT(refracted->wi.z, 0.f);
  EXPECT_NEAR(refracted->wi.y * wo.x, refracted->wi.x * wo.y, 1e-6f);
  // Energy: reflected + transmitted (importance, η² undone) = 1.
  testing::Albedo a = testing::directional_albedo(bsdf, wo, 20000, true);
  EXPECT_NEAR(a.mean.g, 1.f, 1e-4f);
}

TEST(DielectricBsdf, SmoothTotalInternalReflection) {
  DielectricBsdf bsdf(1.5f, 0);
  Vector3f wo = direction_at(180 - 60);  // inside, beyond the 41.8° critical angle
  for (float uc : {0.1f, 0.9f}) {
    std::optional<BsdfSample> s = bsdf.sample(wo, uc, {0.5f, 0.5f});
    ASSERT_TRUE(s);
    EXPECT_FALSE(s->is_transmission);
    EXPECT_NEAR(s->pdf, 1.f, 1e-6f);
  }
}

TEST(DielectricBsdf, RoughConservesEnergy) {
  for (float alpha : {0.1f, 0.4f, 0.8f})
    for (float theta : {0.f, 45.f, 80.f, 135.f}) {
      AnyBsdf bsdf = DielectricBsdf(1.5f, alpha);
      testing::Albedo a = testing::directional_albedo(bsdf, direction_at(theta), 200000, true);
      EXPECT_ALBEDO_AT_MOST_ONE(a);
    }
}

TEST(DielectricBsdf, RoughObeysGeneralizedReciprocity) {
  // Light scattered from wi to wo obeys f_s(wi→wo) / η_o² = f_s(wo→wi) / η_i² (Veach 1997,
  // §5.2), η being the index of the medium each direction lies in; f(wo, wi) is f_s(wi→wo).
  DielectricBsdf bsdf(1.5f, 0.3f);
  auto eta_of = [](Vector3f w) { return w.z > 0 ? 1.f : 1.5f; };
  for (auto [a, b] : testing::direction_pairs(300, true)) {
    float ab = bsdf.f(a, b).g / (eta_of(a) * eta_of(a));
    float ba = bsdf.f(b, a).g / (eta_of(b) * eta_of(b));
    EXPECT_NEAR(ab, ba, 1e-3f * std::max(1.f, ab));
  }
}

}  // namespace
}  // namespace obscura
