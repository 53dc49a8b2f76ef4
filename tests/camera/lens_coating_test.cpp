// Reflectance of bare and coated interfaces against optics written here independently: the
// closed forms at normal incidence, Fresnel's sine and tangent forms at oblique incidence,
// Brewster's angle, and the characteristic-matrix (Abelès) method for a thin film, which the
// code's Airy summation must agree with.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "obscura/camera/lens_coating.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

constexpr double kPi = std::numbers::pi;

double squared(double x) {
  return x * x;
}

TEST(LensCoating, BareNormalIncidenceIsTheFresnelClosedForm) {
  for (auto [n1, n2] : {std::pair{1.0, 1.5}, {1.5, 1.0}, {1.0, 1.9}, {1.62, 1.52}}) {
    const double expected = squared((n2 - n1) / (n2 + n1));
    const InterfaceOptics o = bare_interface(n1, n2, 1);
    EXPECT_NEAR(o.reflectance(), expected, 1e-14) << n1 << " → " << n2;
    EXPECT_NEAR(interface_reflectance({}, n1, n2, 1, 550), expected, 1e-14);
    EXPECT_NEAR(o.reflectance() + o.transmittance(), 1, 1e-14);
  }
}

// Fresnel's equations in their angle forms: r_s = −sin(θ1 − θ2) / sin(θ1 + θ2),
// r_p = tan(θ1 − θ2) / tan(θ1 + θ2).
TEST(LensCoating, BareObliqueIncidenceMatchesFresnelsAngleForms) {
  const double n1 = 1, n2 = 1.7;
  for (double degrees : {10.0, 30.0, 50.0, 70.0, 85.0}) {
    const double t1 = degrees * kPi / 180, t2 = std::asin(n1 * std::sin(t1) / n2);
    const double rs = -std::sin(t1 - t2) / std::sin(t1 + t2);
    const double rp = std::tan(t1 - t2) / std::tan(t1 + t2);
    const InterfaceOptics o = bare_interface(n1, n2, std::cos(t1));
    EXPECT_NEAR(o.reflect_s, rs * rs, 1e-12) << degrees;
    EXPECT_NEAR(o.reflect_p, rp * rp, 1e-12) << degrees;
  }
}

TEST(LensCoating, BrewstersAngleReflectsNoPPolarisedLight) {
  for (auto [n1, n2] : {std::pair{1.0, 1.5}, {1.5, 1.0}, {1.0, 1.8}}) {
    const double brewster = std::atan(n2 / n1);
    const InterfaceOptics o = bare_interface(n1, n2, std::cos(brewster));
    EXPECT_NEAR(o.reflect_p, 0, 1e-14);
    EXPECT_GT(o.reflect_s, 0.01);
  }
}

TEST(LensCoating, QuarterWaveAtItsDesignWavelengthIsTheClosedForm) {
  for (auto [n1, n2, nc] :
       {std::tuple{1.0, 1.52, 1.38}, {1.0, 1.8, 1.38}, {1.52, 1.0, 1.38}, {1.0, 1.5, 1.2247}}) {
    const LensCoating coating = quarter_wave_coating(nc, 550);
    const double expected = squared((n1 * n2 - nc * nc) / (n1 * n2 + nc * nc));
    EXPECT_NEAR(coated_interface(coating, n1, n2, 1, 550).reflectance(), expected, 1e-12);
    EXPECT_NEAR(interface_reflectance(coating, n1, n2, 1, 550), expected, 1e-12);
  }
  // MgF2 on crown glass: about 1.3 % rather than the bare 4.3 %.
  EXPECT_NEAR(interface_reflectance(quarter_wave_coating(), 1, 1.52, 1, 550), 0.0126, 2e-4);
}

// At half the design wavelength the layer is a half wave thick: it is "absent", and the
// interface reflects as bare glass.
TEST(LensCoating, AtTheHalfWaveWavelengthTheLayerIsAbsent) {
  const LensCoating coating = quarter_wave_coating(1.38, 600);
  for (auto [n1, n2] : {std::pair{1.0, 1.52}, {1.7, 1.0}}) {
    const double bare = squared((n2 - n1) / (n2 + n1));
    EXPECT_NEAR(coated_interface(coating, n1, n2, 1, 300).reflectance(), bare, 1e-12);
    EXPECT_NEAR(interface_reflectance(coating, n1, n2, 1, 300), bare, 1e-12);
  }
}

// The characteristic matrix of a layer of index n_c and phase thickness δ, per polarisation
// with tilted admittances η = n·cos θ (s) or n / cos θ (p):
//   [B, C] = [[cos δ, i·sin δ / η_c], [i·η_c·sin δ, cos δ]] · [1, η_2],  Y = C / B,
//   r = (η_1 − Y) / (η_1 + Y).
double matrix_reflectance(double n1, double nc, double n2, double theta1, double thickness_nm,
                          double wavelength_nm, bool p) {
  using C = std::complex<double>;
  const double s = n1 * std::sin(theta1);
  auto cosine = [&](double n) { return std::sqrt(C(1 - s * s / (n * n), 0)); };
  auto eta = [&](double n) { return p ? C(n, 0) / cosine(n) : n * cosine(n); };
  const C delta = 2 * kPi * nc * cosine(nc) * thickness_nm / wavelength_nm;
  const C i(0, 1);
  const C b = std::cos(delta) + i * std::sin(delta) / eta(nc) * eta(n2);
  const C c = i * eta(nc) * std::sin(delta) + std::cos(delta) * eta(n2);
  const C y = c / b;
  return std::norm((eta(n1) - y) / (eta(n1) + y));
}

TEST(LensCoating, SingleLayerMatchesTheCharacteristicMatrixAtAnyAngleAndWavelength) {
  const LensCoating coating = quarter_wave_coating(1.38, 550);
  for (auto [n1, n2] : {std::pair{1.0, 1.62}, {1.62, 1.0}})
    for (double degrees : {0.0, 20.0, 35.0})
      for (double nm : {420.0, 550.0, 680.0}) {
        const double t1 = degrees * kPi / 180;
        const InterfaceOptics o = coated_interface(coating, n1, n2, std::cos(t1), nm);
        const double rs = matrix_reflectance(n1, 1.38, n2, t1, coating.thickness_nm, nm, false);
        const double rp = matrix_reflectance(n1, 1.38, n2, t1, coating.thickness_nm, nm, true);
        EXPECT_NEAR(o.reflect_s, rs, 1e-12) << n1 << " " << degrees << "° " << nm;
        EXPECT_NEAR(o.reflect_p, rp, 1e-12) << n1 << " " << degrees << "° " << nm;
        EXPECT_NEAR(interface_reflectance(coating, n1, n2, std::cos(t1), nm), 0.5 * (rs + rp),
                    1e-12);
      }
}

TEST(LensCoating, ReflectanceIsBoundedAndConservesEnergyEverywhere) {
  for (const LensCoating& coating :
       {LensCoating{}, quarter_wave_coating(), quarter_wave_coating(2.1, 450)})
    for (auto [n1, n2] : {std::pair{1.0, 1.5}, {1.5, 1.0}, {1.9, 1.0}, {1.5, 1.7}})
      for (double cos_i = 0.02; cos_i <= 1; cos_i += 0.07)
        for (double nm = 380; nm <= 780; nm += 37) {
          const InterfaceOptics o = coated_interface(coating, n1, n2, cos_i, nm);
          for (double r : {o.reflect_s, o.reflect_p}) {
            EXPECT_GE(r, 0);
            EXPECT_LE(r, 1 + 1e-12);
          }
          EXPECT_NEAR(o.reflect_s + o.transmit_s, 1, 1e-10);
          EXPECT_NEAR(o.reflect_p + o.transmit_p, 1, 1e-10);
          EXPECT_NEAR(interface_reflectance(coating, n1, n2, cos_i, nm), o.reflectance(), 1e-10);
        }
  // Beyond the critical angle from glass into air: everything reflects, coated or not.
  const double cos_beyond = std::cos(std::asin(1 / 1.5) + 0.05);
  EXPECT_NEAR(coated_interface(quarter_wave_coating(), 1.5, 1, cos_beyond, 550).reflectance(), 1,
              1e-12);
}

TEST(LensCoating, ParsesItsTextAndNamesTheFieldOnErrors) {
  EXPECT_FALSE(parse_lens_coating("none").coated());
  EXPECT_EQ(parse_lens_coating("quarter-wave"), quarter_wave_coating());
  EXPECT_EQ(parse_lens_coating("quarter-wave:1.25"), quarter_wave_coating(1.25, 550));
  EXPECT_EQ(parse_lens_coating("quarter-wave:1.25:500"), quarter_wave_coating(1.25, 500));
  EXPECT_EQ(parse_lens_coating(lens_coating_text(quarter_wave_coating(1.3, 480))),
            quarter_wave_coating(1.3, 480));
  for (const char* bad : {"", "quarterwave", "quarter-wave:", "quarter-wave:x", "quarter-wave:0.5",
                          "quarter-wave:1.38:9000", "quarter-wave:1.38:550:1", "none:1"}) {
    try {
      parse_lens_coating(bad, "--lens-coating");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const Error& e) {
      EXPECT_EQ(e.where(), "--lens-coating") << bad;
    }
  }
  EXPECT_THROW(validate(LensCoating{.thickness_nm = -1}), Error);
  EXPECT_THROW(validate(LensCoating{.thickness_nm = 100, .index = 0.9}), Error);
}

}  // namespace
}  // namespace obscura
