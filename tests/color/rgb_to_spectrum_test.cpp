// The RGB → spectrum lifting against the CIE tables, integrated here directly (not through the
// lifting's own fit data or the film's conversion), and against the RGB → XYZ matrix derived from
// the Rec.709 primaries.
#include "obscura/color/rgb_to_spectrum.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "obscura/color/primaries.h"
#include "obscura/color/spectral.h"

namespace obscura {
namespace {

// XYZ of reflectance s under D65 at unit luminance, summed at 1 nm over the CIE 1931 table.
Vec3d xyz_under_d65(const SigmoidPolynomial& s) {
  double white_y = 0;
  Vec3d xyz{};
  for (int nm = 360; nm <= 830; ++nm) {
    Vec3d cmf = cmf_xyz(nm);
    double light = d65_spd(nm);
    white_y += light * cmf[1];
    for (int i = 0; i < 3; ++i) xyz[i] += s(float(nm)) * light * cmf[i];
  }
  for (double& v : xyz) v /= white_y;
  return xyz;
}

// CIE 1976 ΔE between two XYZ under the D65 white (0.3127, 0.3290).
double delta_e(const Vec3d& a, const Vec3d& b) {
  Vec3d white = xyz_from_chromaticity(white::kD65);
  auto lab = [&](const Vec3d& xyz) {
    auto f = [](double t) {
      return t > 216.0 / 24389 ? std::cbrt(t) : (24389.0 / 27 * t + 16) / 116;
    };
    double fx = f(xyz[0] / white[0]), fy = f(xyz[1] / white[1]), fz = f(xyz[2] / white[2]);
    return Vec3d{116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
  };
  Vec3d la = lab(a), lb = lab(b);
  return std::hypot(la[0] - lb[0], la[1] - lb[1], la[2] - lb[2]);
}

std::vector<Rgb> test_colors() {
  return {{1, 0, 0},
          {0, 1, 0},
          {0, 0, 1},
          {1, 1, 0},
          {0, 1, 1},
          {1, 0, 1},
          {0.8f, 0.2f, 0.1f},
          {0.1f, 0.5f, 0.9f},
          {0.63f, 0.065f, 0.05f},
          {0.14f, 0.45f, 0.091f},
          {0.05f, 0.04f, 0.02f},
          {0.9f, 0.85f, 0.2f},
          {0.5f, 0.5f, 0.5f},
          {0.3f, 0.7f, 0.35f},
          {0.97f, 0.02f, 0.6f}};
}

TEST(RgbToSpectrum, WhiteReflectanceIsOneAtEveryWavelength) {
  SigmoidPolynomial s = RgbToSpectrumTable::working_space()(Rgb(1.f));
  for (int nm = 360; nm <= 830; ++nm) ASSERT_EQ(s(float(nm)), 1.f) << nm;
  SigmoidPolynomial black = RgbToSpectrumTable::working_space()(Rgb(0.f));
  for (int nm = 360; nm <= 830; ++nm) ASSERT_EQ(black(float(nm)), 0.f) << nm;
  SigmoidPolynomial grey = RgbToSpectrumTable::working_space()(Rgb(0.18f));
  for (int nm = 360; nm <= 830; nm += 10) ASSERT_NEAR(grey(float(nm)), 0.18f, 1e-6f) << nm;
}

TEST(RgbToSpectrum, LiftedColoursComeBackUnderD65) {
  // Saturated primaries included: the round trip's error stays below what the eye can tell
  // (ΔE 1), though the colours lie between the table's grid points.
  const Matrix3d xyz_from_rec709 = xyz_from_rgb(primaries::kRec709);
  for (Rgb rgb : test_colors()) {
    Vec3d expected = xyz_from_rec709 * Vec3d{rgb.r, rgb.g, rgb.b};
    Vec3d lifted = xyz_under_d65(RgbToSpectrumTable::working_space()(rgb));
    EXPECT_LT(delta_e(lifted, expected), 0.5) << rgb.r << " " << rgb.g << " " << rgb.b;
  }
}

TEST(RgbToSpectrum, TheFitConvergedEverywhere) {
  // Fitted here, whatever the cache folder holds: the fitting code itself runs in this test.
  const RgbToSpectrumTable fitted = RgbToSpectrumTable::fit();
  EXPECT_LT(fitted.worst_fit_delta_e(), 1e-2);
  // The shared table (from the cache folder when a run before stored it) is that fit, bit for
  // bit: a cached table never differs from what this build fits.
  const RgbToSpectrumTable& shared = RgbToSpectrumTable::working_space();
  EXPECT_EQ(shared.coefficients(), fitted.coefficients());
  EXPECT_EQ(shared.worst_fit_delta_e(), fitted.worst_fit_delta_e());
}

TEST(RgbToSpectrum, ReflectancesAreBoundedAndSmooth) {
  // Over a lattice of the RGB cube: every value in [0, 1], and a sigmoid of a quadratic, so at
  // most one turn (the first difference changes sign at most once) and no jumps: no step above
  // 0.1 per nm (the steepest, dark saturated colours' edges, rise over some 20 nm).
  for (int r = 0; r <= 10; ++r)
    for (int g = 0; g <= 10; ++g)
      for (int b = 0; b <= 10; ++b) {
        SigmoidPolynomial s =
            RgbToSpectrumTable::working_space()(Rgb(r / 10.f, g / 10.f, b / 10.f));
        int turns = 0;
        float previous_step = 0, previous = s(360);
        for (int nm = 361; nm <= 830; ++nm) {
          float v = s(float(nm));
          ASSERT_GE(v, 0.f);
          ASSERT_LE(v, 1.f);
          float step = v - previous;
          ASSERT_LT(std::abs(step), 0.1f) << r << g << b << " at " << nm;
          if (step * previous_step < 0 && std::abs(step) > 1e-6f) ++turns;
          if (std::abs(step) > 1e-6f) previous_step = step;
          previous = v;
        }
        EXPECT_LE(turns, 1) << r << " " << g << " " << b;
      }
}

TEST(RgbToSpectrum, UnboundedAndIlluminantLiftsScaleWithTheColour) {
  SampledWavelengths w = SampledWavelengths::sample(0.3f);
  Rgb colour(0.9f, 0.4f, 0.1f);
  Rgb once = lift_unbounded(colour, w), scaled = lift_unbounded(colour * 7.f, w);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(scaled[i], 7 * once[i], 1e-5f * scaled[i]);
  // White light is the white illuminant: D65 at unit luminance.
  Rgb white = lift_illuminant(Rgb(1.f), w);
  double d65_y = 0;
  for (int nm = 360; nm <= 830; ++nm) d65_y += d65_spd(nm) * cmf_xyz(nm)[1];
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(white[i], d65_spd(w.nm(i)) / d65_y, 1e-6);
  // Reflectances clamp to [0, 1].
  Rgb clamped = lift_reflectance(Rgb(2.f, -1.f, 0.5f), w);
  Rgb expected = lift_reflectance(Rgb(1.f, 0.f, 0.5f), w);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(clamped[i], expected[i]);
}

}  // namespace
}  // namespace obscura
