#include "obscura/trace/phong_bsdf.h"

#include <gtest/gtest.h>

#include "bsdf_test_support.h"

namespace obscura {
namespace {

using testing::direction_at;

TEST(PhongBsdf, SamplingMatchesPdf) {
  for (bool blinn : {false, true})
    for (float n : {1.f, 20.f}) {
      AnyBsdf bsdf = PhongBsdf(Rgb(0.4f), Rgb(0.5f), n, blinn);
      for (float theta : {0.f, 40.f, 75.f}) {
        SCOPED_TRACE(::testing::Message() << "blinn " << blinn << " n " << n << " theta " << theta);
        EXPECT_SAMPLING_MATCHES_PDF(bsdf, direction_at(theta));
      }
    }
}

TEST(PhongBsdf, ConservesEnergy) {
  for (bool blinn : {false, true})
    for (float n : {0.f, 5.f, 50.f, 500.f}) {
      // A white lobe: reflects exactly everything at normal incidence, less elsewhere.
      AnyBsdf specular = PhongBsdf(Rgb(0.f), Rgb(1.f), n, blinn);
      testing::Albedo at_normal = testing::directional_albedo(specular, {0, 0, 1}, 100000);
      EXPECT_NEAR(at_normal.mean.g, 1.f, 5 * at_normal.standard_error.g + 2e-3f)
          << "blinn " << blinn << " n " << n;
      AnyBsdf mixed = PhongBsdf(Rgb(0.7f), Rgb(0.7f), n, blinn);  // scaled down to sum 1
      for (float theta : {0.f, 45.f, 85.f}) {
        EXPECT_ALBEDO_AT_MOST_ONE(testing::directional_albedo(specular, direction_at(theta)));
        EXPECT_ALBEDO_AT_MOST_ONE(testing::directional_albedo(mixed, direction_at(theta)));
      }
    }
}

TEST(PhongBsdf, IsReciprocal) {
  for (bool blinn : {false, true}) {
    PhongBsdf bsdf(Rgb(0.2f), Rgb(0.6f), 12, blinn);
    for (auto [a, b] : testing::direction_pairs(200)) {
      Rgb ab = bsdf.f(a, b), ba = bsdf.f(b, a);
      EXPECT_NEAR(ab.g, ba.g, 1e-4f * std::max(1.f, ab.g));
    }
  }
}

TEST(PhongBsdf, ZeroShininessBlinnIsLambertian) {
  // n = 0: the lobe is constant; with c(0) = 1/π the specular part is a white Lambertian.
  PhongBsdf bsdf(Rgb(0.f), Rgb(1.f), 0, true);
  EXPECT_NEAR(bsdf.f(direction_at(10), direction_at(70, 200)).g, 1 / std::numbers::pi, 1e-6);
}

}  // namespace
}  // namespace obscura
