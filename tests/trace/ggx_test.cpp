#include "obscura/trace/ggx.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "obscura/math/rng.h"

namespace obscura {
namespace {

constexpr double kPiD = std::numbers::pi;

// ∫ g(ω) dω over the sphere by the midpoint rule in (cos θ, φ).
template <class F>
double integrate_sphere(F g, int nz = 2000, int nphi = 64) {
  double sum = 0, dz = 2.0 / nz, dphi = 2 * kPiD / nphi;
  for (int i = 0; i < nz; ++i)
    for (int j = 0; j < nphi; ++j) {
      double z = -1 + (i + 0.5) * dz, phi = (j + 0.5) * dphi, r = std::sqrt(1 - z * z);
      sum += g(Vector3f(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)));
    }
  return sum * dz * dphi;
}

TEST(Ggx, ProjectedNormalDensityIntegratesToOne) {
  for (float alpha : {0.05f, 0.2f, 0.5f, 1.0f}) {
    Ggx ggx(alpha);
    double total = integrate_sphere([&](Vector3f m) { return ggx.D(m) * std::max(0.f, m.z); },
                                    alpha < 0.1f ? 40000 : 4000);
    EXPECT_NEAR(total, 1.0, 2e-3) << "alpha " << alpha;
  }
}

TEST(Ggx, AlphaOneIsTheCosineDistribution) {
  // With α = 1, D(m) = 1/π everywhere on the hemisphere.
  Ggx ggx(1);
  EXPECT_NEAR(ggx.D({0, 0, 1}), 1 / kPiD, 1e-6);
  EXPECT_NEAR(ggx.D(normalize(Vector3f(1, 0, 1))), 1 / kPiD, 1e-6);
}

TEST(Ggx, VisibleNormalDensityIntegratesToOne) {
  // ∫ G1(w) max(0, w·m) D(m) / cos θw dm = 1: the Smith masking function's defining property.
  for (float alpha : {0.1f, 0.4f, 0.9f})
    for (float theta : {0.f, 0.7f, 1.3f, 1.5f}) {
      Ggx ggx(alpha);
      Vector3f w(std::sin(theta), 0, std::cos(theta));
      double total = integrate_sphere([&](Vector3f m) { return ggx.visible_D(w, m); }, 8000, 256);
      EXPECT_NEAR(total, 1.0, 3e-3) << "alpha " << alpha << " theta " << theta;
    }
}

TEST(Ggx, NoMaskingAlongTheNormal) {
  Ggx ggx(0.5f);
  EXPECT_NEAR(ggx.G1({0, 0, 1}), 1.f, 1e-6f);
  EXPECT_LT(ggx.G1(normalize(Vector3f(1, 0, 0.1f))), 1.f);
}

TEST(Ggx, SampledVisibleNormalsFaceTheViewer) {
  Ggx ggx(0.6f);
  Pcg32 rng(5);
  Vector3f w = normalize(Vector3f(0.8f, 0.1f, 0.3f));
  for (int i = 0; i < 10000; ++i) {
    Vector3f m = ggx.sample_visible_normal(w, {rng.next_float(), rng.next_float()});
    EXPECT_NEAR(length(m), 1.f, 1e-4f);
    EXPECT_GE(dot(w, m), -1e-5f);
    EXPECT_GT(m.z, 0.f);
  }
}

}  // namespace
}  // namespace obscura
