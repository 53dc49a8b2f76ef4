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

// D, Λ and G themselves are tested in tests/shading/ggx_test.cpp; here what only the tracer
// needs: the visible-normal density and its sampling.
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
