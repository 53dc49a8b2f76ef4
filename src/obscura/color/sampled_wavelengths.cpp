#include "obscura/color/sampled_wavelengths.h"

#include <algorithm>
#include <cmath>

#include "obscura/color/spectral.h"
#include "obscura/color/spectral_working_space.h"

namespace obscura {

namespace {

// p(λ) = a / (norm · cosh²(a·(λ − centre))); its CDF is (tanh(a·(λ − centre)) − t₀) / norm.
constexpr double kSharpness = 0.0072, kCentreNm = 538;

double tanh_at(double nm) {
  return std::tanh(kSharpness * (nm - kCentreNm));
}

double cdf_span() {
  static const double span = tanh_at(kMaxSampledWavelengthNm) - tanh_at(kMinSampledWavelengthNm);
  return span;
}

}  // namespace

double visible_wavelength_pdf(double nm) {
  if (!(nm >= kMinSampledWavelengthNm && nm <= kMaxSampledWavelengthNm)) return 0;
  double c = std::cosh(kSharpness * (nm - kCentreNm));
  return kSharpness / (cdf_span() * c * c);
}

double sample_visible_wavelength(double u) {
  double t = tanh_at(kMinSampledWavelengthNm) + std::clamp(u, 0.0, 1.0) * cdf_span();
  double nm = kCentreNm + std::atanh(t) / kSharpness;
  return std::clamp(nm, kMinSampledWavelengthNm, kMaxSampledWavelengthNm);
}

SampledWavelengths SampledWavelengths::sample(float u) {
  SampledWavelengths w;
  const Matrix3d& rgb_from_xyz = working_rgb_from_xyz();
  for (int i = 0; i < kCount; ++i) {
    double ui = u + double(i) / kCount;
    if (ui >= 1) ui -= 1;
    double nm = sample_visible_wavelength(ui);
    double pdf = visible_wavelength_pdf(nm);
    w.nm_[i] = float(nm);
    w.pdf_[i] = float(pdf);
    w.illuminant_[i] = float(working_illuminant(nm));
    Vec3d rgb = rgb_from_xyz * cmf_xyz(nm);
    for (int c = 0; c < 3; ++c) w.rgb_weights_[c][i] = float(rgb[c] / (pdf * kCount));
  }
  return w;
}

void SampledWavelengths::terminate_secondary() {
  if (secondary_terminated()) return;
  for (int c = 0; c < 3; ++c) {
    rgb_weights_[c][0] *= kCount;  // the hero's estimate is no longer averaged with others
    for (int i = 1; i < kCount; ++i) rgb_weights_[c][i] = 0;
  }
  for (int i = 1; i < kCount; ++i) pdf_[i] = 0;
}

Rgb SampledWavelengths::to_working_rgb(Rgb radiance) const {
  Rgb rgb;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < kCount; ++i) rgb[c] += rgb_weights_[c][i] * radiance[i];
  return rgb;
}

}  // namespace obscura
