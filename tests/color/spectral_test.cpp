// Spectral colour against the CIE's published checks and physics.
#include "obscura/color/spectral.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "obscura/color/cie_tables.h"
#include "obscura/color/color_space.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

TEST(Spectral, TablesCoverTheirPublishedRanges) {
  EXPECT_EQ(cie1931_cmf().first_nm, 360);
  EXPECT_EQ(cie1931_cmf().last_nm(), 830);
  EXPECT_EQ(cie_d65_spd().first_nm, 300);
  EXPECT_EQ(cie_d65_spd().last_nm(), 830);
  EXPECT_EQ(stockman_sharpe_lms().first_nm, 390);
  EXPECT_EQ(stockman_sharpe_lms().last_nm(), 830);
  EXPECT_DOUBLE_EQ(cmf_xyz(555)[1], 1.0);  // ȳ peaks at 1 at 555 nm
  EXPECT_DOUBLE_EQ(d65_spd(560), 100.0);
}

TEST(Spectral, SumOfYbarIs106_857) {
  Vec3d sum = spectrum_to_xyz([](double) { return 1.0; });
  EXPECT_NEAR(sum[1], 106.857, 1e-3);  // CIE 015: Σȳ(λ)Δλ at 1 nm, 360–830 nm
}

TEST(Spectral, D65HasItsPublishedChromaticity) {
  Chromaticity xy = chromaticity_of(spectrum_to_xyz(d65_spd));
  EXPECT_NEAR(xy.x, 0.3127, 1e-4);
  EXPECT_NEAR(xy.y, 0.3290, 1e-4);
}

TEST(Spectral, EqualEnergyIsOneThird) {
  Chromaticity xy = chromaticity_of(spectrum_to_xyz([](double) { return 1.0; }));
  EXPECT_NEAR(xy.x, 1.0 / 3, 1e-4);
  EXPECT_NEAR(xy.y, 1.0 / 3, 1e-4);
}

TEST(Spectral, Blackbody6504KIsNearD65) {
  // D65 was defined from a 6504 K correlated colour temperature; it lies just off the Planckian
  // locus (Δuv ≈ 0.003), so its xy is close but not equal.
  Chromaticity xy = chromaticity_of(blackbody_xyz(6504));
  EXPECT_LT(std::hypot(xy.x - 0.3127, xy.y - 0.3290), 0.01);
}

TEST(Spectral, BlackbodyPeakFollowsWiensLaw) {
  // λ_max·T = b = 2.897771955e-3 m·K (CODATA): the radiance peak found by scanning.
  for (double kelvin : {3000.0, 5778.0}) {
    double best = 0, best_nm = 0;
    for (double nm = 300; nm <= 1500; nm += 0.5)
      if (double r = planck_radiance(nm, kelvin); r > best) best = r, best_nm = nm;
    EXPECT_NEAR(best_nm, 2.897771955e-3 / kelvin * 1e9, 0.5) << kelvin << " K";
  }
}

TEST(Spectral, HotterIsBluer) {
  auto blue_over_red = [](double k) {
    std::vector<double> rgb = from_xyz_d65(color_space("srgb-linear"), blackbody_xyz(k));
    return rgb[2] / rgb[0];
  };
  EXPECT_LT(blue_over_red(2000), blue_over_red(4000));
  EXPECT_LT(blue_over_red(4000), blue_over_red(10000));
}

TEST(Spectral, DandelionYellowFiresLAndMCones) {
  // 570 nm: L and M cones respond strongly, S hardly; it shows as yellow (R ≈ G, no B) and is
  // outside the sRGB gamut (blue < 0), as every spectral colour is.
  Vec3d lms = cone_lms(570);
  EXPECT_GT(lms[0], 0.9);
  EXPECT_GT(lms[1], 0.7);
  EXPECT_LT(lms[2], 0.01);
  std::vector<double> rgb = from_xyz_d65(color_space("srgb-linear"), cmf_xyz(570));
  EXPECT_NEAR(rgb[0] / rgb[1], 1, 0.1);
  EXPECT_LT(rgb[2], 0);
  EXPECT_FALSE(in_gamut(primaries::kRec709, cmf_xyz(570), 1e-9, true));
}

TEST(Spectral, OutsideTheTablesIsDark) {
  EXPECT_EQ(cmf_xyz(300)[1], 0);
  EXPECT_EQ(cmf_xyz(900)[0], 0);
  EXPECT_EQ(cone_lms(1000)[0], 0);
}

TEST(Spectral, BadInputIsAClearError) {
  EXPECT_THROW(cmf_xyz(-570), Error);
  EXPECT_THROW(cmf_xyz(0), Error);
  EXPECT_THROW(cmf_xyz(std::nan("")), Error);
  EXPECT_THROW(cone_lms(-1), Error);
  EXPECT_THROW(planck_radiance(500, -10), Error);
  EXPECT_THROW(blackbody_xyz(0), Error);
  EXPECT_THROW(blackbody_xyz(std::numeric_limits<double>::infinity()), Error);
}

}  // namespace
}  // namespace obscura
