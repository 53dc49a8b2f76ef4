#include "obscura/trace/direct_lighting.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "trace_test_scenes.h"

namespace obscura {
namespace {

// Form factor from a point to a parallel rectangle X·h by Y·h whose corner lies straight above
// it at height h (the standard closed form, e.g. Howell's catalogue of configuration factors).
double corner_form_factor(double X, double Y) {
  double sx = std::sqrt(1 + X * X), sy = std::sqrt(1 + Y * Y);
  return (X / sx * std::atan(Y / sx) + Y / sy * std::atan(X / sy)) / (2 * std::numbers::pi);
}

Material lambertian(const char* name, float albedo, float radiance) {
  Material m;
  m.name = name;
  m.model = DiffuseMaterial{.reflectance = Rgb(albedo), .reflectance_texture = {}};
  m.emission = Rgb(radiance);
  return m;
}

struct LitFloor {
  static constexpr float kHalfSide = 0.5f, kHeight = 1.0f, kAlbedo = 0.5f, kRadiance = 3.0f;
  Scene scene;
  LitFloor(bool with_blocker) {
    scene.name = "lit-floor";
    scene.materials = {lambertian("floor", kAlbedo, 0), lambertian("light", 0, kRadiance)};
    // Floor facing up; light facing down (its winding is clockwise seen from below... i.e. the
    // normal (p1 − p0) × (p2 − p0) points to −Y).
    scene.add_mesh(testing::make_quad("floor", 0, {-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}));
    const float a = kHalfSide, h = kHeight;
    scene.add_mesh(testing::make_quad("light", 1, {-a, h, -a}, {a, h, -a}, {a, h, a}, {-a, h, a}));
    if (with_blocker)
      scene.add_mesh(testing::make_quad("blocker", 0, {-2, 0.5f, -2}, {-2, 0.5f, 2}, {2, 0.5f, 2},
                                        {2, 0.5f, -2}));
  }
};

TEST(DirectLighting, FloorUnderASquareLightMatchesTheFormFactor) {
  LitFloor setup(false);
  auto device = std::make_shared<EmbreeDevice>();
  TraceScene scene(setup.scene, device);
  DirectLightingIntegrator integrator;
  Ray down;
  down.origin = {0, 0.5f, 0};
  down.direction = {0, -1, 0};

  constexpr int kN = 40000;
  double sum = 0, sum2 = 0;
  RayCounts counts;
  for (int i = 0; i < kN; ++i) {
    Sampler sampler(SamplerType::kIndependent, 1, {0, 0}, uint32_t(i));
    double v = integrator.radiance(scene, down, sampler, counts).g;
    sum += v, sum2 += v * v;
  }
  double mean = sum / kN;
  double sigma = std::sqrt((sum2 / kN - mean * mean) / kN);
  // Lo = ρ/π · E and E = π·L·F, so Lo = ρ·L·F with F the sum of four corner rectangles.
  double X = LitFloor::kHalfSide / LitFloor::kHeight;
  double expected = LitFloor::kAlbedo * LitFloor::kRadiance * 4 * corner_form_factor(X, X);
  EXPECT_NEAR(mean, expected, 5 * sigma + 1e-6) << "sigma " << sigma;
  EXPECT_LT(sigma / expected, 0.01);  // the test has the power to see a 5 % error
  EXPECT_EQ(counts.camera, uint64_t(kN));
}

TEST(DirectLighting, BlockedLightCastsShadowAndEmittersAreSeenOneSided) {
  LitFloor setup(true);
  auto device = std::make_shared<EmbreeDevice>();
  TraceScene scene(setup.scene, device);
  DirectLightingIntegrator integrator;
  RayCounts counts;
  Sampler sampler(SamplerType::kIndependent, 1, {0, 0}, 0);

  Ray under_blocker;
  under_blocker.origin = {0, 0.25f, 0};
  under_blocker.direction = {0, -1, 0};
  for (int i = 0; i < 100; ++i) {
    Sampler s(SamplerType::kIndependent, 1, {0, 0}, uint32_t(i));
    EXPECT_EQ(integrator.radiance(scene, under_blocker, s, counts), Rgb());
  }

  Ray up_at_light;  // sees the light's emitting face from below
  up_at_light.origin = {0, 0.75f, 0};
  up_at_light.direction = {0, 1, 0};
  EXPECT_EQ(integrator.radiance(scene, up_at_light, sampler, counts), Rgb(LitFloor::kRadiance));

  Ray down_at_light;  // sees its back: no emission
  down_at_light.origin = {0, 2, 0};
  down_at_light.direction = {0, -1, 0};
  EXPECT_EQ(integrator.radiance(scene, down_at_light, sampler, counts), Rgb());
}

}  // namespace
}  // namespace obscura
