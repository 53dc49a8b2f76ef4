// glTF KHR_materials_transmission in the tracer: the thin-walled dielectric and the
// metallic-roughness mixture with a glass lobe, against sampling/pdf consistency, energy
// conservation, reciprocity and the Fresnel values of glass (F0 = ((η − 1)/(η + 1))² = 0.04).
#include <gtest/gtest.h>

#include "bsdf_test_support.h"
#include "obscura/trace/thin_dielectric_bsdf.h"
#include "obscura/trace/transmissive_metallic_roughness_bsdf.h"

namespace obscura {
namespace {

using testing::direction_at;

constexpr float kF0 = 0.04f;  // glass of index 1.5 at normal incidence

// A thin wall alone, through the glTF mixture with transmission 1 and metallic 0 (whose glass
// weight is then exactly 1), as the BSDF test tools take it.
AnyBsdf thin_wall(float roughness) {
  MetallicRoughnessParameters p{.base_color = Rgb(1.f), .metallic = 0, .roughness = roughness};
  return TransmissiveMetallicRoughnessBsdf(p, 1, false);
}

TEST(ThinDielectricBsdf, SmoothWallReflectsF0AndPassesTheRestStraightThrough) {
  ThinDielectricBsdf bsdf(1.5f, 0, Rgb(1.f));
  for (Vector3f wo : {Vector3f(0, 0, 1), Vector3f(0, 0, -1)}) {
    std::optional<BsdfSample> reflected = bsdf.sample(wo, 0.5f * kF0, {0.5f, 0.5f});
    std::optional<BsdfSample> passed = bsdf.sample(wo, 0.5f, {0.5f, 0.5f});
    ASSERT_TRUE(reflected && passed);
    EXPECT_NEAR(reflected->pdf, kF0, 1e-6f);
    EXPECT_NEAR(passed->pdf, 1 - kF0, 1e-6f);
    EXPECT_TRUE(passed->is_transmission);
    EXPECT_NEAR(passed->wi.z, -wo.z, 1e-6f);  // not bent
    EXPECT_NEAR(passed->f.g * std::abs(passed->wi.z) / passed->pdf, 1.f, 1e-6f);
  }
  // Off normal incidence the light still passes undeviated.
  Vector3f wo = direction_at(50);
  std::optional<BsdfSample> passed = bsdf.sample(wo, 0.99f, {0.5f, 0.5f});
  ASSERT_TRUE(passed);
  EXPECT_NEAR(length(passed->wi + wo), 0.f, 1e-6f);
  EXPECT_NEAR(testing::directional_albedo(thin_wall(0), wo, 20000).mean.g, 1.f, 1e-4f);
}

TEST(ThinDielectricBsdf, RoughSamplingMatchesPdfFromBothSides) {
  AnyBsdf bsdf = thin_wall(std::sqrt(0.3f));  // GGX α = 0.3
  for (float theta : {0.f, 40.f, 75.f, 120.f, 170.f}) {
    SCOPED_TRACE(::testing::Message() << "theta " << theta);
    EXPECT_SAMPLING_MATCHES_PDF(bsdf, direction_at(theta));
  }
}

TEST(ThinDielectricBsdf, RoughIsReciprocalAndConservesEnergy) {
  ThinDielectricBsdf bsdf(1.5f, 0.4f, Rgb(1.f));
  for (auto [a, b] : testing::direction_pairs(200, true)) {
    float ab = bsdf.f(a, b).g, ba = bsdf.f(b, a).g;
    EXPECT_NEAR(ab, ba, 1e-4f * std::max(1.f, ab));
  }
  for (float theta : {0.f, 45.f, 80.f, 135.f}) {
    testing::Albedo a =
        testing::directional_albedo(thin_wall(std::sqrt(0.4f)), direction_at(theta), 100000);
    EXPECT_ALBEDO_AT_MOST_ONE(a);
  }
}

MetallicRoughnessParameters white(float metallic, float roughness) {
  return {.base_color = Rgb(1.f), .metallic = metallic, .roughness = roughness};
}

TEST(TransmissiveMetallicRoughnessBsdf, SamplingMatchesPdf) {
  for (bool volume : {false, true}) {
    AnyBsdf bsdf = TransmissiveMetallicRoughnessBsdf(white(0.3f, 0.5f), 0.7f, volume);
    for (float theta : {0.f, 40.f, 60.f, 120.f, 170.f}) {
      SCOPED_TRACE(::testing::Message() << "volume " << volume << " theta " << theta);
      EXPECT_SAMPLING_MATCHES_PDF(bsdf, direction_at(theta));
    }
  }
}

TEST(TransmissiveMetallicRoughnessBsdf, ConservesEnergy) {
  for (bool volume : {false, true})
    for (float roughness : {0.f, 0.3f, 0.8f})
      for (float theta : {0.f, 45.f, 80.f, 135.f}) {
        AnyBsdf bsdf = TransmissiveMetallicRoughnessBsdf(white(0.2f, roughness), 0.8f, volume);
        testing::Albedo a = testing::directional_albedo(bsdf, direction_at(theta), 100000, true);
        EXPECT_ALBEDO_AT_MOST_ONE(a);
      }
}

TEST(TransmissiveMetallicRoughnessBsdf, SmoothClearGlassSplitsByFresnelAndTransmission) {
  // (1 − metallic) · transmission = 0.5 of the light meets the glass: at normal incidence it
  // reflects F0 of it and passes 1 − F0 (tinted by the base colour); the rest meets the opaque
  // material, which never transmits.
  MetallicRoughnessParameters p = white(0, 0);
  p.base_color = Rgb(1.f, 0.5f, 0.25f);
  TransmissiveMetallicRoughnessBsdf bsdf(p, 0.5f, false);
  Vector3f wo(0, 0, 1);
  Rgb transmitted;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    std::optional<BsdfSample> s = bsdf.sample(wo, (i + 0.5f) / n, {0.3f, 0.7f});
    if (s && s->is_transmission) transmitted += s->f * (std::abs(s->wi.z) / s->pdf) / float(n);
  }
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(transmitted[c], 0.5f * (1 - kF0) * p.base_color[c], 2e-3f) << c;
}

}  // namespace
}  // namespace obscura
