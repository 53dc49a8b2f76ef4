#include "obscura/trace/conductor_bsdf.h"

#include <gtest/gtest.h>

#include "bsdf_test_support.h"
#include "obscura/shading/fresnel.h"

namespace obscura {
namespace {

using testing::direction_at;

const Rgb kGoldEta(0.2f, 0.92f, 1.1f), kGoldK(3.9f, 2.45f, 2.14f);

TEST(ConductorBsdf, SamplingMatchesPdf) {
  for (float alpha : {0.15f, 0.4f, 0.9f}) {
    AnyBsdf bsdf = ConductorBsdf(kGoldEta, kGoldK, alpha);
    for (float theta : {0.f, 45.f, 80.f}) {
      SCOPED_TRACE(::testing::Message() << "alpha " << alpha << " theta " << theta);
      EXPECT_SAMPLING_MATCHES_PDF(bsdf, direction_at(theta));
    }
  }
}

TEST(ConductorBsdf, ConservesEnergy) {
  // A perfect reflector (F ≈ 1: a huge extinction coefficient) loses energy only to masking
  // (single scattering), which is negligible for a nearly smooth surface seen from above.
  for (float alpha : {0.05f, 0.3f, 1.0f})
    for (float theta : {0.f, 50.f, 85.f}) {
      AnyBsdf bsdf = ConductorBsdf(Rgb(1.f), Rgb(1e4f), alpha);
      testing::Albedo a = testing::directional_albedo(bsdf, direction_at(theta));
      EXPECT_ALBEDO_AT_MOST_ONE(a);
      if (alpha < 0.1f && theta < 60) {
        EXPECT_GT(a.mean.g, 0.99f);
      }
    }
}

TEST(ConductorBsdf, SmoothIsAMirrorWeightedByFresnel) {
  ConductorBsdf bsdf(kGoldEta, kGoldK, 0);
  Vector3f wo = direction_at(30);
  std::optional<BsdfSample> s = bsdf.sample(wo, 0.5f, {0.3f, 0.7f});
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->is_delta);
  EXPECT_NEAR(s->wi.x, -wo.x, 1e-6f);
  EXPECT_NEAR(s->wi.z, wo.z, 1e-6f);
  Rgb weight = s->f * (s->wi.z / s->pdf);
  Rgb fresnel = shading::fresnel_conductor(wo.z, kGoldEta, kGoldK);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(weight[c], fresnel[c], 1e-5f);
  EXPECT_TRUE(bsdf.f(wo, s->wi).is_black());
}

TEST(ConductorBsdf, IsReciprocal) {
  ConductorBsdf bsdf(kGoldEta, kGoldK, 0.3f);
  for (auto [a, b] : testing::direction_pairs(200)) {
    Rgb ab = bsdf.f(a, b), ba = bsdf.f(b, a);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ab[c], ba[c], 1e-4f * std::max(1.f, ab[c]));
  }
}

}  // namespace
}  // namespace obscura
