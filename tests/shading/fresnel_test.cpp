#include "obscura/shading/fresnel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace obscura {
namespace {

constexpr float kDegree = std::numbers::pi_v<float> / 180;

TEST(Fresnel, DielectricAtNormalIncidenceIsTheSquaredIndexRatio) {
  // ((n − 1)/(n + 1))²: 0.04 for n = 1.5 (crown glass), 0.0200 for water (n = 1.333).
  EXPECT_NEAR(shading::fresnel_dielectric(1, 1.5f), 0.04f, 1e-6f);
  EXPECT_NEAR(shading::fresnel_dielectric(1, 1.333f), 0.02037f, 1e-5f);
  EXPECT_NEAR(shading::fresnel_f0(1.5f), 0.04f, 1e-7f);
  // Seen from inside, normal incidence reflects the same.
  EXPECT_NEAR(shading::fresnel_dielectric(-1, 1.5f), 0.04f, 1e-6f);
}

TEST(Fresnel, DielectricAtBrewsterAngleReflectsOnlyThePerpendicularPolarization) {
  // At tan θB = n, R∥ = 0 and R⊥ = sin²(θi − θt) with θi + θt = 90°: R = R⊥ / 2.
  float n = 1.5f;
  float theta_b = std::atan(n), theta_t = std::numbers::pi_v<float> / 2 - theta_b;
  float r_perpendicular = std::pow(std::sin(theta_b - theta_t), 2.f);
  EXPECT_NEAR(shading::fresnel_dielectric(std::cos(theta_b), n), 0.5f * r_perpendicular, 1e-6f);
}

TEST(Fresnel, DielectricTotalInternalReflectionBeyondTheCriticalAngle) {
  float critical = std::asin(1 / 1.5f);  // 41.8°
  EXPECT_EQ(shading::fresnel_dielectric(-std::cos(critical + 0.01f), 1.5f), 1.f);
  EXPECT_LT(shading::fresnel_dielectric(-std::cos(critical - 0.05f), 1.5f), 1.f);
  EXPECT_NEAR(shading::fresnel_dielectric(0.f, 1.5f), 1.f, 1e-6f);  // grazing reflects everything
}

TEST(Fresnel, FromOutsideTreatsDirectionsBelowTheSurfaceAsGrazing) {
  EXPECT_NEAR(shading::fresnel_dielectric_from_outside(1, 1.5f), 0.04f, 1e-6f);
  EXPECT_EQ(shading::fresnel_dielectric_from_outside(-0.5f, 1.5f), 1.f);
  EXPECT_NEAR(shading::fresnel_dielectric_from_outside(0, 1.5f), 1.f, 1e-6f);
}

TEST(Fresnel, SchlickStaysCloseToExactForGlass) {
  // For n = 1.5 Schlick's error, computed offline in double precision from the exact
  // formula, is below 0.0015 up to 30°, peaks near 0.036 around 85° and vanishes at 90°.
  for (float deg = 0; deg <= 90; deg += 1) {
    float c = std::cos(deg * kDegree);
    float tolerance = deg <= 30 ? 0.0016f : 0.037f;
    EXPECT_NEAR(shading::fresnel_schlick(0.04f, c), shading::fresnel_dielectric(c, 1.5f), tolerance)
        << deg;
  }
  EXPECT_FLOAT_EQ(shading::fresnel_schlick(0.04f, 1), 0.04f);
  EXPECT_FLOAT_EQ(shading::fresnel_schlick(0.04f, 0), 1.f);
}

TEST(Fresnel, ConductorAtNormalIncidenceMatchesTheClosedForm) {
  // R = ((n − 1)² + k²) / ((n + 1)² + k²); gold at 550 nm: n ≈ 0.43, k ≈ 2.46 → R ≈ 0.78.
  auto closed = [](float n, float k) {
    return ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
  };
  EXPECT_NEAR(shading::fresnel_conductor(1, 0.43f, 2.46f), closed(0.43f, 2.46f), 1e-5f);
  EXPECT_NEAR(closed(0.43f, 2.46f), 0.78f, 0.01f);
  EXPECT_NEAR(shading::fresnel_conductor(1, 0.2f, 3.9f), closed(0.2f, 3.9f), 1e-5f);
}

TEST(Fresnel, ConductorWithoutAbsorptionIsADielectric) {
  for (float deg = 0; deg < 90; deg += 7) {
    float c = std::cos(deg * kDegree);
    EXPECT_NEAR(shading::fresnel_conductor(c, 1.5f, 0.f), shading::fresnel_dielectric(c, 1.5f),
                1e-5f)
        << deg;
  }
}

TEST(Fresnel, ConductorReflectsEverythingAtGrazingIncidence) {
  EXPECT_NEAR(shading::fresnel_conductor(0.f, 0.2f, 3.9f), 1.f, 1e-5f);
  Rgb r = shading::fresnel_conductor(0.5f, Rgb(0.2f, 0.92f, 1.1f), Rgb(3.9f, 2.45f, 2.14f));
  for (int c = 0; c < 3; ++c) EXPECT_TRUE(r[c] > 0 && r[c] < 1);
}

}  // namespace
}  // namespace obscura
