// Tools for testing a BSDF against the physics it promises (shared by the *_bsdf_test.cpp files):
// a chi-square goodness-of-fit test of sample() against pdf(), Monte Carlo albedo, reciprocity.
// Written for these tests after the method of pbrt-v4's bsdfs_test and Mitsuba 3's chi2 test.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "obscura/math/rng.h"
#include "obscura/trace/any_bsdf.h"

namespace obscura::testing {

// Regularized upper incomplete gamma Q(a, x) (series for x < a + 1, Lentz's continued fraction
// otherwise), from which the chi-square tail P(X² > x | k dof) = Q(k/2, x/2).
inline double upper_incomplete_gamma_q(double a, double x) {
  if (x <= 0) return 1;
  double log_prefactor = -x + a * std::log(x) - std::lgamma(a);
  if (x < a + 1) {
    double term = 1 / a, sum = term;
    for (int n = 1; n < 1000 && std::abs(term) > 1e-15 * std::abs(sum); ++n) {
      term *= x / (a + n);
      sum += term;
    }
    return 1 - sum * std::exp(log_prefactor);
  }
  const double tiny = 1e-300;
  double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
  for (int i = 1; i < 1000; ++i) {
    double an = -i * (i - a);
    b += 2;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1 / d;
    double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1) < 1e-15) break;
  }
  return std::exp(log_prefactor) * h;
}

inline double chi_square_p_value(double statistic, int dof) {
  return upper_incomplete_gamma_q(0.5 * dof, 0.5 * statistic);
}

struct ChiSquareResult {
  double statistic = 0, p_value = 1;
  int dof = 0;
  double pdf_integral = 0;      // ∫ pdf over the sphere: the probability that sample() succeeds
  double failure_fraction = 0;  // of samples that failed or were delta
  std::string report;
};

// Bins sample()'s non-delta directions over the whole sphere in (θ, φ); expected counts
// integrate pdf() over each cell (midpoint rule on a sub-grid, fine enough for narrow lobes near
// the poles). Cells expecting fewer than 5 samples are pooled. Failed and delta samples are
// counted apart: their share must match 1 − ∫pdf.
inline ChiSquareResult bsdf_chi_square(const AnyBsdf& bsdf, Vector3f wo, int samples = 400000,
                                       int theta_bins = 36, int phi_bins = 48, int sub = 12,
                                       uint64_t seed = 7) {
  const double pi = std::numbers::pi, two_pi = 2 * pi;
  std::vector<double> observed(size_t(theta_bins) * phi_bins, 0.0);
  double failures = 0;
  Pcg32 rng(seed);
  for (int i = 0; i < samples; ++i) {
    float uc = rng.next_float();
    Point2f u{rng.next_float(), rng.next_float()};
    std::optional<BsdfSample> s = bsdf.sample(wo, uc, u);
    if (!s || s->is_delta || s->pdf <= 0) {
      failures += 1;
      continue;
    }
    double theta = std::acos(std::clamp(double(s->wi.z), -1.0, 1.0));
    double phi = std::atan2(double(s->wi.y), double(s->wi.x));
    if (phi < 0) phi += two_pi;
    int ti = std::min(theta_bins - 1, int(theta / pi * theta_bins));
    int pi_ = std::min(phi_bins - 1, int(phi / two_pi * phi_bins));
    observed[size_t(ti) * phi_bins + pi_] += 1;
  }
  std::vector<double> expected(observed.size(), 0.0);
  double dtheta = pi / theta_bins, dphi = two_pi / phi_bins;
  ChiSquareResult result;
  for (int ti = 0; ti < theta_bins; ++ti)
    for (int pj = 0; pj < phi_bins; ++pj) {
      double sum = 0;
      for (int a = 0; a < sub; ++a)
        for (int b = 0; b < sub; ++b) {
          double theta = (ti + (a + 0.5) / sub) * dtheta;
          double phi = (pj + (b + 0.5) / sub) * dphi;
          double r = std::sin(theta);
          Vector3f wi(float(r * std::cos(phi)), float(r * std::sin(phi)), float(std::cos(theta)));
          sum += bsdf.pdf(wo, wi) * r;
        }
      sum *= dtheta * dphi / (sub * sub);
      expected[size_t(ti) * phi_bins + pj] = sum * samples;
      result.pdf_integral += sum;
    }

  // Pool the sparse cells (as Mitsuba does), then sum the statistic.
  double pooled_observed = 0, pooled_expected = 0;
  int cells = 0;
  for (size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] < 5) {
      pooled_observed += observed[i];
      pooled_expected += expected[i];
      continue;
    }
    double d = observed[i] - expected[i];
    result.statistic += d * d / expected[i];
    ++cells;
  }
  if (pooled_expected >= 5) {
    double d = pooled_observed - pooled_expected;
    result.statistic += d * d / pooled_expected;
    ++cells;
  } else if (pooled_observed > pooled_expected + 5 + 4 * std::sqrt(pooled_expected)) {
    result.statistic = 1e30;  // samples where the pdf says (almost) none can land
  }
  result.dof = cells - 1;
  result.p_value = chi_square_p_value(result.statistic, result.dof);
  result.failure_fraction = failures / samples;
  result.report = "chi2 = " + std::to_string(result.statistic) +
                  ", dof = " + std::to_string(result.dof) +
                  ", p = " + std::to_string(result.p_value) +
                  ", integral of pdf = " + std::to_string(result.pdf_integral) +
                  ", failed or delta = " + std::to_string(result.failure_fraction);
  return result;
}

// A direction at polar angle θ (degrees) from +Z in the x–z plane, slightly off-plane so that
// no symmetry hides a bug.
inline Vector3f direction_at(float theta_degrees, float phi_degrees = 20) {
  float t = theta_degrees * std::numbers::pi_v<float> / 180;
  float p = phi_degrees * std::numbers::pi_v<float> / 180;
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

// The significance level per test: a false alarm in one run of the whole suite is 1 in 1000.
inline constexpr double kChiSquareSignificance = 1e-4;

#define EXPECT_SAMPLING_MATCHES_PDF(bsdf, wo)                                               \
  do {                                                                                      \
    ::obscura::testing::ChiSquareResult r_ = ::obscura::testing::bsdf_chi_square(bsdf, wo); \
    EXPECT_GT(r_.p_value, ::obscura::testing::kChiSquareSignificance) << r_.report;         \
    EXPECT_NEAR(r_.failure_fraction, 1 - r_.pdf_integral, 3e-3) << r_.report;               \
  } while (0)

struct Albedo {
  Rgb mean;
  Rgb standard_error;
};

// ∫ f(wo, wi) |cos θi| dωi by sampling the BSDF (delta lobes included). With
// `undo_radiance_scaling` transmitted samples are multiplied by η² (importance transport), so
// the result is the fraction of energy kept.
inline Albedo directional_albedo(const AnyBsdf& bsdf, Vector3f wo, int samples = 40000,
                                 bool undo_radiance_scaling = false, uint64_t seed = 11) {
  Pcg32 rng(seed);
  double sum[3] = {}, sum2[3] = {};
  for (int i = 0; i < samples; ++i) {
    float uc = rng.next_float();
    Point2f u{rng.next_float(), rng.next_float()};
    std::optional<BsdfSample> s = bsdf.sample(wo, uc, u);
    if (!s || s->pdf <= 0) continue;
    Rgb w = s->f * (std::abs(s->wi.z) / s->pdf);
    if (undo_radiance_scaling && s->is_transmission) w *= s->eta * s->eta;
    for (int c = 0; c < 3; ++c) sum[c] += w[c], sum2[c] += double(w[c]) * w[c];
  }
  Albedo albedo;
  for (int c = 0; c < 3; ++c) {
    double mean = sum[c] / samples, variance = std::max(0.0, sum2[c] / samples - mean * mean);
    albedo.mean[c] = float(mean);
    albedo.standard_error[c] = float(std::sqrt(variance / samples));
  }
  return albedo;
}

// Energy conservation within 4 standard errors (plus float slack).
#define EXPECT_ALBEDO_AT_MOST_ONE(albedo)                                       \
  do {                                                                          \
    for (int c_ = 0; c_ < 3; ++c_)                                              \
      EXPECT_LE((albedo).mean[c_], 1 + 4 * (albedo).standard_error[c_] + 1e-4f) \
          << "channel " << c_;                                                  \
  } while (0)

// A reproducible set of direction pairs on the upper hemisphere.
inline std::vector<std::pair<Vector3f, Vector3f>> direction_pairs(int n, bool both_sides = false) {
  Pcg32 rng(3);
  std::vector<std::pair<Vector3f, Vector3f>> pairs;
  auto random_direction = [&](bool lower) {
    float z = 0.02f + 0.98f * rng.next_float(),
          phi = 2 * std::numbers::pi_v<float> * rng.next_float();
    float r = std::sqrt(1 - z * z);
    return Vector3f(r * std::cos(phi), r * std::sin(phi), lower ? -z : z);
  };
  for (int i = 0; i < n; ++i) {
    Vector3f a = random_direction(false);
    Vector3f b = random_direction(both_sides && (i % 2 == 1));
    pairs.push_back({a, b});
  }
  return pairs;
}

}  // namespace obscura::testing
