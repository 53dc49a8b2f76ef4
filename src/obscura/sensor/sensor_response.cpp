#include "obscura/sensor/sensor_response.h"

#include <algorithm>
#include <cmath>

#include "obscura/color/cie_tables.h"
#include "obscura/color/rgb_to_spectrum.h"
#include "obscura/color/spectral_working_space.h"

namespace obscura {

namespace {

constexpr int kFirstNm = 360, kSamples = 471;  // 360–830 nm at 1 nm, the CIE table's span
constexpr double kPlanck = 6.62607015e-34, kLightSpeed = 299792458;  // SI, exact
constexpr double kLuminousEfficacy = 683;                            // lm/W at 555 nm

using Spectrum = std::array<double, kSamples>;

double nm_at(int i) {
  return kFirstNm + i;
}

double qe_at(const QeBand& band, double nm) {
  const double d = (nm - band.center_nm) / band.width_nm;
  return band.peak * std::exp(-0.5 * d * d);
}

// The QE curve of sensor channel k (a monochrome sensor's one curve for each).
Spectrum qe_curve(const SensorSpec& spec, int k) {
  const QeBand& band = spec.cfa == CfaPattern::kMonochrome ? spec.mono_qe : spec.qe[size_t(k)];
  Spectrum q{};
  for (int i = 0; i < kSamples; ++i) q[size_t(i)] = qe_at(band, nm_at(i));
  return q;
}

// CIE illuminant A by its defining formula (CIE 15:2004): Planck's law at 2856 K with the
// second radiation constant of 1.435e7 nm·K, 100 at 560 nm.
double illuminant_a(double nm) {
  const double c2 = 1.435e7, t = 2848;
  return 100 * std::pow(560 / nm, 5) * (std::exp(c2 / (t * 560)) - 1) /
         (std::exp(c2 / (t * nm)) - 1);
}

Vec3d cmf_at(int i) {
  const SpectralTable& cmf = cie1931_cmf();
  const int row = kFirstNm + i - cmf.first_nm;
  return {cmf.at(row, 0), cmf.at(row, 1), cmf.at(row, 2)};
}

// Electrons per (lux·s · m²) in each channel from light of spectrum `spd` (any scale).
Vec3d electrons_per_lux_s(const SensorSpec& spec, const Spectrum& spd) {
  double luminance = 0;
  for (int i = 0; i < kSamples; ++i) luminance += spd[size_t(i)] * cmf_at(i)[1];
  Vec3d electrons{};
  for (int k = 0; k < 3; ++k) {
    const Spectrum q = qe_curve(spec, k);
    double sum = 0;
    for (int i = 0; i < kSamples; ++i)
      sum += q[size_t(i)] * spd[size_t(i)] * nm_at(i) * 1e-9 / (kPlanck * kLightSpeed);
    electrons[size_t(k)] = sum / (kLuminousEfficacy * luminance);
  }
  return electrons;
}

// Scales a camera-from-XYZ matrix so that `white` (XYZ, Y = 1) maps to a neutral of largest
// component 1, as the DNG specification normalises its ColorMatrix tags.
Matrix3d normalised(const Matrix3d& camera_from_xyz, const Vec3d& white) {
  const Vec3d n = camera_from_xyz * white;
  const double largest = std::max({n[0], n[1], n[2]});
  Matrix3d m = camera_from_xyz;
  for (auto& row : m.m)
    for (double& v : row) v /= largest;
  return m;
}

}  // namespace

double photons_per_lux_second(const std::array<double, 471>& spd) {
  double luminance = 0, photons = 0;
  for (int i = 0; i < kSamples; ++i) {
    luminance += spd[size_t(i)] * cmf_at(i)[1];
    photons += spd[size_t(i)] * nm_at(i) * 1e-9 / (kPlanck * kLightSpeed);
  }
  return photons / (kLuminousEfficacy * luminance);
}

SensorResponse sensor_response(const SensorSpec& spec) {
  SensorResponse r;
  // Each film primary's spectrum: the unbounded lift of (½, 0, 0) etc. doubled, times the
  // working white (rgb_to_spectrum.h's lift_illuminant, evaluated on the 1 nm grid).
  const RgbToSpectrumTable& table = RgbToSpectrumTable::working_space();
  Spectrum white{};
  for (int i = 0; i < kSamples; ++i) white[size_t(i)] = working_illuminant(nm_at(i));
  for (int c = 0; c < 3; ++c) {
    Rgb half{0, 0, 0};
    (c == 0 ? half.r : c == 1 ? half.g : half.b) = 0.5f;
    const SigmoidPolynomial lift = table(half);
    Spectrum primary{};
    for (int i = 0; i < kSamples; ++i)
      primary[size_t(i)] = 2 * double(lift(float(nm_at(i)))) * white[size_t(i)];
    // Light of the primary's spectrum at film value 1 carries the primary's luminance, not 1
    // lux per lux of white: scale by Y(primary) / Y(white) = ∫primary·ȳ (white has ∫ = 1).
    double luminance = 0;
    for (int i = 0; i < kSamples; ++i) luminance += primary[size_t(i)] * cmf_at(i)[1];
    const Vec3d e = electrons_per_lux_s(spec, primary);
    for (int k = 0; k < 3; ++k)
      r.electrons_per_lux_s_m2.m[size_t(k)][size_t(c)] = e[size_t(k)] * luminance;
  }
  // XYZ of film RGB is the working space's; the camera from XYZ inverts it.
  const Matrix3d xyz_from_film = working_rgb_from_xyz().inverse();
  const Vec3d d65 = xyz_from_film * Vec3d{1, 1, 1};
  const Matrix3d camera_from_xyz = r.electrons_per_lux_s_m2 * working_rgb_from_xyz();
  r.color_matrix_d65 = normalised(camera_from_xyz, d65);
  r.neutral_d65 = r.color_matrix_d65 * d65;

  // ColorMatrix2: the Luther fit C = (Σ w q xyzᵀ)(Σ w xyz xyzᵀ)⁻¹ with w = A(λ) and q the
  // camera's response per unit of spectral energy (QE · λ, photons per joule up to hc).
  Matrix3d qx{}, xx{};
  Spectrum q[3] = {qe_curve(spec, 0), qe_curve(spec, 1), qe_curve(spec, 2)};
  Vec3d a_white{};
  for (int i = 0; i < kSamples; ++i) {
    const double w = illuminant_a(nm_at(i));
    const Vec3d x = cmf_at(i);
    for (int row = 0; row < 3; ++row) {
      a_white[size_t(row)] += w * x[size_t(row)];
      for (int col = 0; col < 3; ++col) {
        qx.m[size_t(row)][size_t(col)] += w * q[row][size_t(i)] * nm_at(i) * x[size_t(col)];
        xx.m[size_t(row)][size_t(col)] += w * x[size_t(row)] * x[size_t(col)];
      }
    }
  }
  const double a_luminance = a_white[1];
  for (double& v : a_white) v /= a_luminance;
  if (spec.cfa == CfaPattern::kMonochrome) {
    r.color_matrix_a = r.color_matrix_d65;  // one channel: no colour to fit
  } else {
    r.color_matrix_a = normalised(qx * xx.inverse(), a_white);
  }
  return r;
}

}  // namespace obscura
