#include "obscura/trace/environment_light.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "obscura/math/error.h"
#include "obscura/math/rng.h"
#include "obscura/trace/light_set.h"

namespace obscura {
namespace {

// A 16 × 8 lat-long map, dim everywhere but for one bright texel.
Image sun_map(int sun_x, int sun_y) {
  Image map(16, 8, 3);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) map.set_rgb(x, y, Rgb(0.1f));
  map.set_rgb(sun_x, sun_y, Rgb(100.f));
  return map;
}

TEST(EnvironmentLight, MapOrientation) {
  // Row 0 is up, the centre column looks along −Z, u grows towards +X.
  Image map(4, 2, 3);
  map.set_rgb(2, 0, {1, 0, 0});  // upper half, the column just right of centre
  map.set_rgb(0, 1, {0, 1, 0});  // lower half, the left edge (behind: +Z side, towards −X)
  EnvironmentLight env(map, Rgb(1.f), Transform());
  EXPECT_EQ(env.radiance(normalize(Vector3f(0.3f, 0.5f, -1))).r, 1.f);
  EXPECT_EQ(env.radiance(normalize(Vector3f(-0.3f, -0.5f, 1))).g, 1.f);
  // A rotation of the frame rotates the map: 180° about Y brings +Z to −Z.
  EnvironmentLight turned(map, Rgb(1.f), Transform::rotate(3.14159265, {0, 1, 0}));
  EXPECT_EQ(turned.radiance(normalize(Vector3f(-0.3f, 0.5f, 1))).r, 1.f);
}

TEST(EnvironmentLight, ImportanceSamplingIsUnbiasedAndFindsTheSun) {
  EnvironmentLight env(sun_map(5, 2), Rgb(2.f), Transform::rotate(0.3, {1, 0, 0}));
  // ∫ L dω by the map's own sampling vs. exactly: Σ texels L · Δφ · (cos θ₀ − cos θ₁).
  double exact = 0;
  Image map = sun_map(5, 2);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x)
      exact += 2 * map.at(x, y, 1) * (2 * std::numbers::pi / 16) *
               (std::cos(std::numbers::pi * y / 8) - std::cos(std::numbers::pi * (y + 1) / 8));
  Pcg32 rng(4);
  double importance = 0;
  int towards_sun = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    EnvironmentSample s = env.sample({rng.next_float(), rng.next_float()});
    ASSERT_GT(s.pdf, 0.f);
    EXPECT_NEAR(s.pdf, env.pdf(s.wi), 1e-3f * s.pdf);
    importance += s.radiance.g / s.pdf;
    towards_sun += s.radiance.g > 100;
  }
  EXPECT_NEAR(importance / n, exact, 0.01 * exact);
  EXPECT_GT(towards_sun, n / 2);  // the one bright texel carries most of the light
}

TEST(EnvironmentLight, ConstantIsSampledUniformly) {
  EnvironmentLight env(Rgb(0.5f));
  EnvironmentSample s = env.sample({0.3f, 0.6f});
  EXPECT_NEAR(s.pdf, 1 / (4 * 3.14159265f), 1e-6f);
  EXPECT_EQ(s.radiance, Rgb(0.5f));
  EXPECT_FLOAT_EQ(env.average_luminance(), 0.5f);
}

TEST(EnvironmentLight, RejectsAnImageWithoutColour) {
  EXPECT_THROW(EnvironmentLight(Image(4, 2, 1), Rgb(1.f), Transform()), Error);
}

}  // namespace
}  // namespace obscura

namespace obscura {
namespace {

// A path tracer's light samples (LightSampling::kForMis) leave a constant environment to the
// BSDF; a map stays in, and so does everything for integrators that only sample lights.
TEST(LightSet, AConstantEnvironmentIsLeftOutOfSamplingForMisOnly) {
  LightSet constant_only({}, EnvironmentLight(Rgb(1.f)), {}, 1);
  EXPECT_FALSE(constant_only.empty(LightSampling::kAll));
  EXPECT_TRUE(constant_only.empty(LightSampling::kForMis));
  EXPECT_FALSE(constant_only.sample({0, 0, 0}, 0.5f, {0.5f, 0.5f}, LightSampling::kForMis));
  EXPECT_EQ(constant_only.pdf_environment({0, 0, 1}, LightSampling::kForMis), 0.f);
  EXPECT_NEAR(constant_only.pdf_environment({0, 0, 1}, LightSampling::kAll),
              1 / (4 * std::numbers::pi), 1e-6);

  // With a point light beside it, the point light is the only one sampled for MIS, with
  // probability 1; both are sampled otherwise.
  LightSet with_point({}, EnvironmentLight(Rgb(1.f)), {PunctualLight::point({0, 2, 0}, Rgb(10.f))},
                      1);
  for (float u : {0.01f, 0.5f, 0.99f}) {
    std::optional<LightSample> s =
        with_point.sample({0, 0, 0}, u, {0.3f, 0.7f}, LightSampling::kForMis);
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->is_delta);
    EXPECT_EQ(s->pdf, 1.f);
  }
  EXPECT_GT(with_point.pdf_environment({0, 0, 1}, LightSampling::kAll), 0.f);

  Image map(8, 4, 3);
  map.data.assign(map.data.size(), 1.f);
  LightSet mapped({}, EnvironmentLight(map, Rgb(1.f), Transform()), {}, 1);
  EXPECT_FALSE(mapped.empty(LightSampling::kForMis));
  EXPECT_GT(mapped.pdf_environment({0, 0, 1}, LightSampling::kForMis), 0.f);
}

}  // namespace
}  // namespace obscura
