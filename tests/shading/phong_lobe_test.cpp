#include "obscura/shading/phong_lobe.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace obscura::shading {
namespace {

// ∫ lobe(wo = normal, wi)·cos θi dωi by quadrature over θ (the lobe is symmetric about the
// normal at normal incidence): the reciprocal of the normalization. Light and viewer along the
// normal: R·V = cos θ, N·H = cos(θ/2).
double lobe_integral_at_normal(float n, bool blinn) {
  const int steps = 200000;
  double sum = 0, dtheta = std::numbers::pi / 2 / steps;
  for (int i = 0; i < steps; ++i) {
    double t = (i + 0.5) * dtheta;
    double c = blinn ? std::cos(t / 2) : std::cos(t);
    sum += std::pow(c, n) * std::cos(t) * std::sin(t) * 2 * std::numbers::pi * dtheta;
  }
  return sum;
}

TEST(PhongLobe, NormalizationsMakeAWhiteLobeReflectAllLightAlongTheNormal) {
  for (float n : {0.f, 1.f, 10.f, 100.f, 1000.f}) {
    EXPECT_NEAR(phong_lobe_normalization(n) * lobe_integral_at_normal(n, false), 1.0, 1e-4) << n;
    EXPECT_NEAR(blinn_phong_lobe_normalization(n) * lobe_integral_at_normal(n, true), 1.0, 1e-4)
        << n;
  }
}

TEST(PhongLobe, ConstantLobeNormalizationIsLambert) {
  // n = 0: both lobes are constant and must reflect like a Lambertian surface, 1/π.
  EXPECT_FLOAT_EQ(phong_lobe_normalization(0), std::numbers::inv_pi_v<float>);
  EXPECT_FLOAT_EQ(blinn_phong_lobe_normalization(0), std::numbers::inv_pi_v<float>);
}

TEST(PhongLobe, EnergyConservationScalesByTheLargestChannelSum) {
  Rgb kd(0.9f, 0.5f, 0.1f), ks(0.6f);
  conserve_energy(kd, ks);  // the red sum, 1.5, is the largest
  EXPECT_NEAR(kd.r + ks.r, 1.f, 1e-6f);
  EXPECT_NEAR(kd.g, 0.5f / 1.5f, 1e-6f);
  EXPECT_NEAR(ks.b, 0.6f / 1.5f, 1e-6f);
}

TEST(PhongLobe, EnergyConservationLeavesPlausibleMaterialsAlone) {
  Rgb kd(0.5f, 0.2f, 0.1f), ks(0.5f, 0.3f, 0.2f);
  conserve_energy(kd, ks);
  EXPECT_EQ(kd.r, 0.5f);
  EXPECT_EQ(ks.g, 0.3f);
}

}  // namespace
}  // namespace obscura::shading
