#include "obscura/trace/lambertian_bsdf.h"

#include <gtest/gtest.h>

#include "bsdf_test_support.h"

namespace obscura {
namespace {

using testing::direction_at;

TEST(LambertianBsdf, SamplingMatchesPdf) {
  AnyBsdf bsdf = LambertianBsdf{Rgb(0.5f)};
  for (float theta : {0.f, 45.f, 85.f}) EXPECT_SAMPLING_MATCHES_PDF(bsdf, direction_at(theta));
}

TEST(LambertianBsdf, WhiteReflectsEverything) {
  // ∫ (1/π) cos θ dω = 1 exactly; cosine sampling makes every sample weigh exactly ρ.
  AnyBsdf bsdf = LambertianBsdf{Rgb(1.f)};
  for (float theta : {0.f, 60.f, 89.f}) {
    testing::Albedo a = testing::directional_albedo(bsdf, direction_at(theta), 20000);
    EXPECT_NEAR(a.mean.g, 1.f, 1e-5f) << theta;
  }
}

TEST(LambertianBsdf, ValueIsAlbedoOverPiAndReciprocal) {
  LambertianBsdf bsdf{Rgb(0.3f, 0.6f, 0.9f)};
  for (auto [a, b] : testing::direction_pairs(100)) {
    EXPECT_EQ(bsdf.f(a, b), bsdf.f(b, a));
    EXPECT_NEAR(bsdf.f(a, b).g, 0.6f / std::numbers::pi_v<float>, 1e-7f);
  }
  EXPECT_TRUE(bsdf.f({0, 0, 1}, {0, 0, -1}).is_black());  // no transmission
}

}  // namespace
}  // namespace obscura
