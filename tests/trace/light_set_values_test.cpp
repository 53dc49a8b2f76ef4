// Light selection with a light of infinite power and no environment: before, the selection's
// CDF went NaN and sample() picked the environment's slot and read the disengaged
// std::optional<EnvironmentLight> (SIGSEGV from Python, garbage from the CLI).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>

#include "obscura/trace/light_set.h"

namespace obscura {
namespace {

TEST(LightSetValues, AnInfinitelyBrightLightNeverSelectsAMissingEnvironment) {
  const float huge = 1e38f;  // × 4π sr: a power of +inf in a float
  LightSet lights(
      AreaLights(), std::nullopt,
      {PunctualLight::point({0, 2, 0}, Rgb(huge)), PunctualLight::point({5, 2, 0}, Rgb(1))}, 10.f);
  const Point3f p(0, 0, 0);
  for (LightSampling which : {LightSampling::kAll, LightSampling::kForMis})
    for (int i = 0; i <= 64; ++i) {
      const float u = std::min(i / 64.f, 0x1.fffffep-1f);
      std::optional<LightSample> s = lights.sample(p, u, {0.5f, 0.5f}, which);
      ASSERT_TRUE(s) << u;
      // Always the bright light straight above, chosen with probability 1 (the other is 1e38
      // times dimmer).
      EXPECT_TRUE(s->is_delta);
      EXPECT_NEAR(s->wi.y, 1, 1e-6) << u;
      EXPECT_NEAR(s->pdf, 1, 1e-6) << u;
      EXPECT_EQ(lights.pdf_environment({0, 1, 0}, which), 0);
    }
}

}  // namespace
}  // namespace obscura
