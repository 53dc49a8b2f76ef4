// KHR_materials_clearcoat and KHR_materials_sheen over the metallic-roughness BSDF: sampling
// against pdf (chi-square), energy in a white furnace, the plain BSDF bit for bit without
// layers, and the specifications' own formulas in the cases they settle exactly.
#include "obscura/trace/layered_metallic_roughness_bsdf.h"

#include <gtest/gtest.h>

#include "bsdf_test_support.h"
#include "obscura/shading/charlie_sheen.h"
#include "obscura/shading/fresnel.h"
#include "obscura/shading/ggx_energy.h"

namespace obscura {
namespace {

using testing::direction_at;

MetallicRoughnessParameters base(Rgb color, float metallic, float roughness) {
  return {.base_color = color, .metallic = metallic, .roughness = roughness};
}

// A coat normal tilted by `degrees` about the frame's y axis, oriented in the identity frame.
LayeredMetallicRoughnessBsdf tilted(LayeredMetallicRoughnessBsdf bsdf, float degrees) {
  float t = degrees * std::numbers::pi_v<float> / 180;
  bsdf.set_coat_normal({std::sin(t), 0, std::cos(t)}, {0, 0, 1});
  ShadingFrame identity{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  bsdf.orient(identity);
  return bsdf;
}

TEST(LayeredMetallicRoughnessBsdf, SamplingMatchesPdf) {
  struct Case {
    const char* name;
    LayerParameters layers;
    float tilt_degrees;
  };
  const Case cases[] = {
      // Sharper lobes than roughness 0.3 are finer than the test's grid can integrate pdf() on
      // (its midpoint rule misses their peak); the smooth coat is checked through its albedo.
      {"glossy coat", {.clearcoat = 1, .clearcoat_roughness = 0.3f}, 0},
      {"rough half coat", {.clearcoat = 0.5f, .clearcoat_roughness = 0.6f}, 0},
      {"tilted coat", {.clearcoat = 1, .clearcoat_roughness = 0.3f}, 25},
      {"sheen", {.sheen_color = Rgb(0.9f, 0.5f, 0.3f), .sheen_roughness = 0.4f}, 0},
      {"coat over sheen",
       {.clearcoat = 0.8f,
        .clearcoat_roughness = 0.2f,
        .sheen_color = Rgb(1.f),
        .sheen_roughness = 0.8f},
       10},
  };
  for (const Case& c : cases)
    for (float metallic : {0.f, 1.f})
      for (float theta : {0.f, 50.f, 80.f}) {
        SCOPED_TRACE(::testing::Message()
                     << c.name << " metallic " << metallic << " theta " << theta);
        AnyBsdf bsdf = tilted(
            LayeredMetallicRoughnessBsdf(base(Rgb(0.8f, 0.5f, 0.2f), metallic, 0.5f), c.layers),
            c.tilt_degrees);
        EXPECT_SAMPLING_MATCHES_PDF(bsdf, direction_at(theta));
      }
}

TEST(LayeredMetallicRoughnessBsdf, PdfIntegratesToAtMostOne) {
  AnyBsdf bsdf =
      tilted(LayeredMetallicRoughnessBsdf(base(Rgb(0.5f), 0.3f, 0.4f), {.clearcoat = 1,
                                                                        .clearcoat_roughness = 0.1f,
                                                                        .sheen_color = Rgb(0.5f),
                                                                        .sheen_roughness = 0.5f}),
             30);
  for (float theta : {10.f, 70.f}) {
    testing::ChiSquareResult r = testing::bsdf_chi_square(bsdf, direction_at(theta), 1000);
    EXPECT_LE(r.pdf_integral, 1 + 2e-3) << r.report;
    EXPECT_GT(r.pdf_integral, 0.5) << r.report;
  }
}

// The white furnace: albedo ≤ 1 (within 4 standard errors) and at least `expected` less a
// tolerance. 200,000 samples give standard errors of 2e-4 to 1e-3 here.
void expect_furnace(const AnyBsdf& bsdf, Vector3f wo, float expected, float tolerance) {
  testing::Albedo a = testing::directional_albedo(bsdf, wo, 200000);
  EXPECT_ALBEDO_AT_MOST_ONE(a);
  for (int c = 0; c < 3; ++c)
    EXPECT_GE(a.mean[c], expected - tolerance - 4 * a.standard_error[c])
        << "channel " << c << " albedo " << a.mean[c] << " ± " << a.standard_error[c];
  std::printf("    furnace θo = %4.1f°: albedo %.5f ± %.5f (expected ≥ %.3f)\n",
              std::acos(wo.z) * 180 / std::numbers::pi, a.mean.g, a.standard_error.g, expected);
}

TEST(LayeredMetallicRoughnessBsdf, ClearcoatOverWhiteDiffuseLosesNothingAndGainsNothing) {
  // A white dielectric base reflects everything (its diffuse takes exactly what its specular
  // leaves); the coat takes c·E_c(μo) and the base gets the rest: the total stays 1. The
  // tolerance covers the energy tables' interpolation (≤ 0.5 %).
  for (float coat_roughness : {0.f, 0.3f, 1.f})
    for (float theta : {0.f, 45.f, 75.f}) {
      SCOPED_TRACE(::testing::Message()
                   << "coat roughness " << coat_roughness << " theta " << theta);
      AnyBsdf bsdf = LayeredMetallicRoughnessBsdf(
          base(Rgb(1.f), 0, 0.5f), {.clearcoat = 1, .clearcoat_roughness = coat_roughness});
      expect_furnace(bsdf, direction_at(theta), 1, 0.01f);
    }
}

TEST(LayeredMetallicRoughnessBsdf, ClearcoatOverWhiteMetalLosesNothingAndGainsNothing) {
  // The white metal keeps all light by its multiple-scattering lobe: the coated one does too.
  for (float roughness : {0.2f, 0.8f})
    for (float theta : {0.f, 60.f}) {
      SCOPED_TRACE(::testing::Message() << "base roughness " << roughness << " theta " << theta);
      AnyBsdf bsdf = LayeredMetallicRoughnessBsdf(base(Rgb(1.f), 1, roughness),
                                                  {.clearcoat = 1, .clearcoat_roughness = 0.2f});
      expect_furnace(bsdf, direction_at(theta), 1, 0.015f);
    }
}

TEST(LayeredMetallicRoughnessBsdf, SheenOverWhiteBaseNeverGainsEnergy) {
  // The specification's albedo scaling loses some light (the base gets what the sheen leaves on
  // the worse of the two directions), so only the bound is exact; at least 85 % remains here.
  for (float sheen_roughness : {0.f, 0.1f, 0.5f, 1.f})
    for (float theta : {0.f, 60.f, 85.f}) {
      SCOPED_TRACE(::testing::Message()
                   << "sheen roughness " << sheen_roughness << " theta " << theta);
      AnyBsdf bsdf = LayeredMetallicRoughnessBsdf(base(Rgb(1.f), 0, 0.5f),
                                                  {.clearcoat = 1,
                                                   .clearcoat_roughness = 0.1f,
                                                   .sheen_color = Rgb(1.f),
                                                   .sheen_roughness = sheen_roughness});
      expect_furnace(bsdf, direction_at(theta), 0.85f, 0);
    }
}

TEST(LayeredMetallicRoughnessBsdf, WithoutLayersItIsThePlainBsdfBitForBit) {
  MetallicRoughnessParameters p = base(Rgb(0.7f, 0.4f, 0.2f), 0.3f, 0.45f);
  MetallicRoughnessBsdf plain(p);
  LayeredMetallicRoughnessBsdf layered(p, {.clearcoat = 0, .clearcoat_roughness = 0.3f});
  for (auto [a, b] : testing::direction_pairs(200)) {
    Rgb fp = plain.f(a, b), fl = layered.f(a, b);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(fp[c], fl[c]);
    EXPECT_EQ(plain.pdf(a, b), layered.pdf(a, b));
  }
  Pcg32 rng(5);
  for (int i = 0; i < 1000; ++i) {
    Vector3f wo = direction_at(89 * rng.next_float(), 360 * rng.next_float());
    float uc = rng.next_float();
    Point2f u{rng.next_float(), rng.next_float()};
    auto sp = plain.sample(wo, uc, u), sl = layered.sample(wo, uc, u);
    ASSERT_EQ(sp.has_value(), sl.has_value());
    if (!sp) continue;
    EXPECT_EQ(sp->wi, sl->wi);
    EXPECT_EQ(sp->pdf, sl->pdf);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(sp->f[c], sl->f[c]);
  }
}

TEST(LayeredMetallicRoughnessBsdf, SmoothCoatOverBlackReflectsF0AtNormalIncidence) {
  // KHR_materials_clearcoat: a coat of weight c over a base that reflects nothing reflects
  // c · (0.04 + 0.96 (1 − n·v)⁵) of a white surround, c · 0.04 seen along the normal.
  MetallicRoughnessParameters black{
      .base_color = Rgb(0.f), .metallic = 0, .roughness = 0.5f, .specular = 0};
  for (float c : {1.f, 0.5f}) {
    AnyBsdf bsdf = LayeredMetallicRoughnessBsdf(black, {.clearcoat = c, .clearcoat_roughness = 0});
    testing::Albedo a = testing::directional_albedo(bsdf, {0, 0, 1}, 100000);
    EXPECT_NEAR(a.mean.g, c * shading::fresnel_f0(1.5f), 2e-4f) << "clearcoat " << c;
  }
  // At 60° the spec's Fresnel of n·v: 0.04 + 0.96 · 0.5⁵ = 0.07; a smooth coat's microfacets
  // face the normal, so its v·h Fresnel is the same.
  AnyBsdf bsdf = LayeredMetallicRoughnessBsdf(black, {.clearcoat = 1, .clearcoat_roughness = 0});
  testing::Albedo a = testing::directional_albedo(bsdf, direction_at(60), 100000);
  EXPECT_NEAR(a.mean.g, shading::fresnel_schlick(0.04f, 0.5f), 1e-3f);
}

TEST(LayeredMetallicRoughnessBsdf, CoatScalesTheBaseByWhatItReflects) {
  // f = coat + (1 − c·E_c(μo)) · base, term for term, away from the coat's specular peak.
  MetallicRoughnessParameters p = base(Rgb(0.6f, 0.3f, 0.1f), 0, 0.7f);
  MetallicRoughnessBsdf plain(p);
  LayeredMetallicRoughnessBsdf coated(p, {.clearcoat = 0.7f, .clearcoat_roughness = 0});
  Vector3f wo = direction_at(40), wi = direction_at(20, 200);  // far from the mirror direction
  const Ggx coat(2 * Ggx::kSmoothAlpha);
  float scale = 1 - 0.7f * shading::ggx_schlick_albedo(0.04f, wo.z, coat.alpha());
  Vector3f h = normalize(wo + wi);
  float tail = 0.7f * shading::fresnel_schlick(0.04f, dot(wo, h)) * coat.D(h) * coat.G(wo, wi) /
               (4 * wo.z * wi.z);  // the coat's lobe this far from its peak: ~1e-5
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(coated.f(wo, wi)[c], scale * plain.f(wo, wi)[c] + tail, 1e-6f * plain.f(wo, wi)[c]);
}

TEST(LayeredMetallicRoughnessBsdf, SheenFollowsTheSpecificationsFormula) {
  // f = sheen_color · D·V + base · min(1 − m E(μo), 1 − m E(μi)), where E ≤ 1.
  MetallicRoughnessParameters p = base(Rgb(0.2f, 0.3f, 0.8f), 0, 0.6f);
  MetallicRoughnessBsdf plain(p);
  const Rgb sheen(0.9f, 0.6f, 0.3f);
  LayeredMetallicRoughnessBsdf cloth(p, {.sheen_color = sheen, .sheen_roughness = 0.7f});
  const float alpha = 0.49f;
  for (auto [wo, wi] : testing::direction_pairs(50)) {
    float eo = shading::sheen_albedo(wo.z, alpha), ei = shading::sheen_albedo(wi.z, alpha);
    if (eo > 1 || ei > 1) continue;
    float scale = std::min(1 - 0.9f * eo, 1 - 0.9f * ei);
    float lobe = shading::charlie_sheen(wo.z, wi.z, normalize(wo + wi).z, alpha);
    for (int c = 0; c < 3; ++c) {
      float expected = sheen[c] * lobe + plain.f(wo, wi)[c] * scale;
      EXPECT_NEAR(cloth.f(wo, wi)[c], expected, 1e-5f * std::max(1.f, expected));
    }
  }
}

TEST(LayeredMetallicRoughnessBsdf, CoatFollowsItsOwnNormal) {
  // Over a black base, a smooth coat tilted by 20° reflects light arriving along its mirror
  // direction about the tilted normal, not about the shading normal.
  MetallicRoughnessParameters black{
      .base_color = Rgb(0.f), .metallic = 0, .roughness = 0.5f, .specular = 0};
  LayeredMetallicRoughnessBsdf bsdf = tilted(
      LayeredMetallicRoughnessBsdf(black, {.clearcoat = 1, .clearcoat_roughness = 0.1f}), 20);
  float t = 20 * std::numbers::pi_v<float> / 180;
  Vector3f n(std::sin(t), 0, std::cos(t)), wo(0, 0, 1);
  Vector3f mirror_tilted = reflect(wo, n), mirror_flat(0, 0, 1);
  EXPECT_GT(bsdf.f(wo, mirror_tilted).g, 100 * bsdf.f(wo, mirror_flat).g);
}

}  // namespace
}  // namespace obscura
