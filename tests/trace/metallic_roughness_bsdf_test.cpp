#include "obscura/trace/metallic_roughness_bsdf.h"

#include <gtest/gtest.h>

#include "bsdf_test_support.h"
#include "obscura/shading/fresnel.h"

namespace obscura {
namespace {

using testing::direction_at;

TEST(MetallicRoughnessBsdf, SamplingMatchesPdf) {
  for (float metallic : {0.f, 0.5f, 1.f})
    for (float roughness : {0.4f, 0.8f}) {
      AnyBsdf bsdf = MetallicRoughnessBsdf(
          {.base_color = Rgb(0.8f, 0.5f, 0.2f), .metallic = metallic, .roughness = roughness});
      for (float theta : {0.f, 60.f}) {
        SCOPED_TRACE(::testing::Message() << "metallic " << metallic << " roughness " << roughness
                                          << " theta " << theta);
        EXPECT_SAMPLING_MATCHES_PDF(bsdf, direction_at(theta));
      }
    }
}

TEST(MetallicRoughnessBsdf, ConservesEnergy) {
  for (float metallic : {0.f, 1.f})
    for (float roughness : {0.1f, 0.5f, 1.f})
      for (float theta : {0.f, 45.f, 80.f}) {
        AnyBsdf bsdf = MetallicRoughnessBsdf(
            {.base_color = Rgb(1.f), .metallic = metallic, .roughness = roughness});
        SCOPED_TRACE(::testing::Message() << "metallic " << metallic << " roughness " << roughness
                                          << " theta " << theta);
        EXPECT_ALBEDO_AT_MOST_ONE(testing::directional_albedo(bsdf, direction_at(theta)));
      }
}

TEST(MetallicRoughnessBsdf, WithoutSpecularADielectricIsLambertian) {
  // KHR_materials_specular with specular = 0 (what Blender writes for a Diffuse BSDF).
  MetallicRoughnessBsdf bsdf(
      {.base_color = Rgb(0.8f), .metallic = 0, .roughness = 0.5f, .specular = 0});
  for (auto [a, b] : testing::direction_pairs(50))
    EXPECT_NEAR(bsdf.f(a, b).g, 0.8f / std::numbers::pi_v<float>, 1e-6f);
}

TEST(MetallicRoughnessBsdf, SmoothMetalAtNormalIncidenceReflectsItsBaseColor) {
  // F(0°) of the metal is its base colour; a nearly smooth GGX lobe keeps nearly all of it.
  Rgb base(0.9f, 0.6f, 0.3f);
  AnyBsdf bsdf = MetallicRoughnessBsdf({.base_color = base, .metallic = 1, .roughness = 0.05f});
  testing::Albedo a = testing::directional_albedo(bsdf, {0, 0, 1});
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.mean[c], base[c], 0.01f);
}

TEST(MetallicRoughnessBsdf, DielectricDefaultReflectsFourPercentAtNormalIncidence) {
  // Black base colour, ior 1.5: only the specular layer with F0 = 0.04 remains.
  AnyBsdf bsdf = MetallicRoughnessBsdf({.base_color = Rgb(0.f), .metallic = 0, .roughness = 0.05f});
  testing::Albedo a = testing::directional_albedo(bsdf, {0, 0, 1});
  EXPECT_NEAR(a.mean.g, shading::fresnel_f0(1.5f), 0.003f);
}

TEST(MetallicRoughnessBsdf, IsReciprocal) {
  MetallicRoughnessBsdf bsdf(
      {.base_color = Rgb(0.7f, 0.4f, 0.2f), .metallic = 0.3f, .roughness = 0.5f});
  for (auto [a, b] : testing::direction_pairs(200)) {
    Rgb ab = bsdf.f(a, b), ba = bsdf.f(b, a);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ab[c], ba[c], 1e-4f * std::max(1.f, ab[c]));
  }
}

}  // namespace
}  // namespace obscura
