// The Phong and Blinn-Phong lobes' directional albedo against a brute-force integral of the
// lobe as written (f = c(n)·lobeⁿ, shading/phong_lobe.h) over the hemisphere in (cos θ, φ), and
// against its two closed-form limits: E(1) = 1 (what c(n) is defined by) and E(μ) → μ for a
// narrow Phong lobe (its mirror direction's cosine).
#include "obscura/shading/phong_albedo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "obscura/shading/phong_lobe.h"

namespace obscura::shading {
namespace {

constexpr double kPi = std::numbers::pi;

// ∫ c(n)·lobeⁿ·cos θi dωi by the midpoint rule over (cos θi, φ), wo = (sin θo, 0, μ).
double brute_force_albedo(double mu, double n, bool blinn) {
  const double sin_o = std::sqrt(1 - mu * mu);
  const double c =
      blinn ? blinn_phong_lobe_normalization(float(n)) : phong_lobe_normalization(float(n));
  const int nz = 1500, nphi = 500;
  double sum = 0;
  for (int i = 0; i < nz; ++i)
    for (int j = 0; j < nphi; ++j) {
      const double z = (i + 0.5) / nz, phi = 2 * kPi * (j + 0.5) / nphi, r = std::sqrt(1 - z * z);
      const double x = r * std::cos(phi), y = r * std::sin(phi);
      double lobe = 0;
      if (!blinn) {
        lobe = -sin_o * x + mu * z;  // r · wi, r = (−sin θo, 0, μ)
      } else {
        const double hx = sin_o + x, hy = y, hz = mu + z,
                     len = std::sqrt(hx * hx + hy * hy + hz * hz);
        lobe = hz / len;
      }
      if (lobe > 0) sum += c * std::pow(lobe, n) * z;
    }
  return sum * (1.0 / nz) * (2 * kPi / nphi);
}

TEST(PhongAlbedo, MatchesTheLobeIntegratedByBruteForce) {
  for (bool blinn : {false, true})
    for (double n : {1.0, 6.0, 30.0, 100.0})
      for (double mu : {0.15, 0.4, 0.75, 0.95}) {
        const double want = brute_force_albedo(mu, n, blinn);
        EXPECT_NEAR(phong_lobe_albedo(float(mu), float(n), blinn), want, 0.01 + 0.01 * want)
            << (blinn ? "Blinn" : "Phong") << " n " << n << " mu " << mu;
      }
}

TEST(PhongAlbedo, ReflectsEverythingAtNormalIncidence) {
  for (bool blinn : {false, true})
    for (float n : {0.f, 1.f, 10.f, 100.f, 1000.f})
      EXPECT_NEAR(phong_lobe_albedo(1, n, blinn), 1, 5e-3) << blinn << " n " << n;
}

TEST(PhongAlbedo, ANarrowPhongLobeReflectsTheCosineOfItsMirrorDirection) {
  for (float mu : {0.2f, 0.5f, 0.8f}) EXPECT_NEAR(phong_lobe_albedo(mu, 2000, false), mu, 0.01);
}

TEST(PhongAlbedo, NonFiniteInputsReadTheGrid) {
  EXPECT_TRUE(std::isfinite(phong_lobe_albedo(NAN, 10, false)));
  EXPECT_TRUE(std::isfinite(phong_lobe_albedo(0.5f, NAN, true)));
  EXPECT_TRUE(std::isfinite(phong_lobe_albedo(0.5f, INFINITY, false)));
}

}  // namespace
}  // namespace obscura::shading
