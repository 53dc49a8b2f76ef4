// Hero-wavelength sampling against numerical integration of its density and the CIE tables.
#include "obscura/color/sampled_wavelengths.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "obscura/color/primaries.h"
#include "obscura/color/spectral.h"

namespace obscura {
namespace {

// ∫ p from 360 nm to `nm` by the midpoint rule, 100 steps per nanometre, each step inside one
// whole nanometre (the density may jump there).
double integrated_pdf(double nm) {
  double sum = 0;
  for (double start = 360; start < nm; start += 1) {
    double end = std::min(start + 1, nm), h = (end - start) / 100;
    for (int i = 0; i < 100; ++i) sum += visible_wavelength_pdf(start + (i + 0.5) * h) * h;
  }
  return sum;
}

TEST(SampledWavelengths, TheDensityIsNormalised) {
  EXPECT_NEAR(integrated_pdf(830), 1.0, 1e-6);
  EXPECT_EQ(visible_wavelength_pdf(359.9), 0);
  EXPECT_EQ(visible_wavelength_pdf(830.1), 0);
  for (double nm = 360; nm < 830; nm += 0.5) EXPECT_GT(visible_wavelength_pdf(nm), 0) << nm;
}

TEST(SampledWavelengths, TheDensityFollowsD65TimesTheRec709MatchingFunctions) {
  // p(λ) ∝ D65(λ)·Σ|r̄ḡb̄(λ)| with r̄ḡb̄ from the standard Rec.709 matrix (the code's working
  // matrix differs from it by ≤ 1e-4 per channel): the ratio is one constant, at the middle of
  // each nanometre where the table holds its value.
  Matrix3d rgb_from_xyz = xyz_from_rgb(primaries::kRec709).inverse();
  auto shape = [&](double nm) {
    Vec3d rgb = rgb_from_xyz * cmf_xyz(nm);
    return d65_spd(nm) * (std::abs(rgb[0]) + std::abs(rgb[1]) + std::abs(rgb[2]));
  };
  double ratio_at_555 = visible_wavelength_pdf(555.5) / shape(555.5);
  for (double nm = 360.5; nm < 830; nm += 7)
    EXPECT_NEAR(visible_wavelength_pdf(nm) / shape(nm), ratio_at_555, 3e-4 * ratio_at_555) << nm;
  // Where the film is most sensitive per unit of white light: b̄'s peak near 450 nm, above ȳ's
  // 555 nm; the far ends, which the eye barely sees, seldom.
  EXPECT_GT(visible_wavelength_pdf(450.5), 1.2 * visible_wavelength_pdf(555.5));
  EXPECT_LT(visible_wavelength_pdf(700.5), 0.05 * visible_wavelength_pdf(600.5));
}

TEST(SampledWavelengths, SamplingInvertsTheCdf) {
  for (double u : {0.0, 0.05, 0.25, 0.5, 0.75, 0.95, 1.0}) {
    double nm = sample_visible_wavelength(u);
    EXPECT_NEAR(integrated_pdf(nm), u, 1e-5) << u;
  }
  EXPECT_NEAR(sample_visible_wavelength(0), 360, 1e-9);
  EXPECT_NEAR(sample_visible_wavelength(1), 830, 1e-6);
}

TEST(SampledWavelengths, CompanionsAreAThirdOfTheCdfApart) {
  SampledWavelengths w = SampledWavelengths::sample(0.8f);
  EXPECT_NEAR(integrated_pdf(w.nm(0)), 0.8, 1e-5);
  EXPECT_NEAR(integrated_pdf(w.nm(1)), 0.8 + 1.0 / 3 - 1, 1e-5);
  EXPECT_NEAR(integrated_pdf(w.nm(2)), 0.8 + 2.0 / 3 - 1, 1e-5);
  for (int i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(w.pdf(i), float(visible_wavelength_pdf(w.nm(i))));
}

// The mean of to_working_rgb over stratified hero numbers for radiance `spd`.
template <class Spd>
Rgb estimate(const Spd& spd, bool terminate) {
  const int n = 4000;
  double sum[3] = {};
  for (int k = 0; k < n; ++k) {
    SampledWavelengths w = SampledWavelengths::sample((k + 0.5f) / n);
    if (terminate) w.terminate_secondary();
    Rgb L;
    for (int i = 0; i < 3; ++i) L[i] = float(spd(w.nm(i)));
    Rgb rgb = w.to_working_rgb(L);
    for (int c = 0; c < 3; ++c) sum[c] += rgb[c];
  }
  return Rgb(float(sum[0] / n), float(sum[1] / n), float(sum[2] / n));
}

TEST(SampledWavelengths, TheFilmEstimateIsTheObserversIntegral) {
  // D65 at unit luminance is the working white, (1, 1, 1), whether or not companions survive.
  double d65_y = spectrum_to_xyz(d65_spd)[1];
  for (bool terminate : {false, true}) {
    Rgb white = estimate([&](double nm) { return d65_spd(nm) / d65_y; }, terminate);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(white[c], 1.0, 2e-3) << terminate;
  }
  // Equal energy: its XYZ summed from the table, through the standard Rec.709 matrix.
  Vec3d xyz = spectrum_to_xyz([](double) { return 0.01; });
  Vec3d expected = xyz_from_rgb(primaries::kRec709).inverse() * xyz;
  Rgb e = estimate([](double) { return 0.01; }, false);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(e[c], expected[c], 2e-3 * expected[1]);
}

TEST(SampledWavelengths, WhiteLightsColourNoiseIsSmall) {
  // The film estimate of D65 at unit luminance, sample by sample: its standard deviation per
  // channel over uniformly spread hero numbers. The expected values come from a separate numpy
  // computation with the 1 nm CIE tables (0.32, 0.12, 0.31; Radziszewski et al.'s density, used
  // before, gave 0.42, 0.07, 0.88); bounds a little above them.
  const int n = 6000;
  double d65_y = spectrum_to_xyz(d65_spd)[1];
  double sum[3] = {}, sum2[3] = {};
  for (int k = 0; k < n; ++k) {
    SampledWavelengths w = SampledWavelengths::sample((k + 0.5f) / n);
    Rgb L;
    for (int i = 0; i < 3; ++i) L[i] = float(d65_spd(w.nm(i)) / d65_y);
    Rgb rgb = w.to_working_rgb(L);
    for (int c = 0; c < 3; ++c) sum[c] += rgb[c], sum2[c] += double(rgb[c]) * rgb[c];
  }
  double bound[3] = {0.34, 0.14, 0.33}, variance_sum = 0;
  for (int c = 0; c < 3; ++c) {
    double mean = sum[c] / n, sd = std::sqrt(sum2[c] / n - mean * mean);
    EXPECT_LT(sd, bound[c]) << c;
    variance_sum += sd * sd;
  }
  EXPECT_LT(variance_sum, 0.23);
}

}  // namespace
}  // namespace obscura
