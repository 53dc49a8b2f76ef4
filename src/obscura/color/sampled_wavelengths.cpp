#include "obscura/color/sampled_wavelengths.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "obscura/color/spectral.h"
#include "obscura/color/spectral_working_space.h"

namespace obscura {

namespace {

constexpr int kBins = int(kMaxSampledWavelengthNm - kMinSampledWavelengthNm);  // 1 nm each
// Guide cells for the inverse CDF: each holds the bin where its stretch of u begins, so sampling
// walks a bin or two instead of binary-searching all 470.
constexpr int kGuideCells = 512;

struct WavelengthTable {
  // The density, constant over each 1 nm bin [360 + k, 361 + k), and its CDF at the bins' edges.
  std::array<double, kBins> pdf{};
  std::array<double, kBins + 1> cdf{};
  std::array<double, kBins> inverse_pdf{};
  std::array<int, kGuideCells> guide{};
  // At each whole nanometre 360 … 830, the working illuminant; and at the two ends of each bin,
  // the film's weights M·x̄ȳz̄ / (p · 3) of its wavelengths. Between whole nanometres both are
  // interpolated linearly, as the CIE tables themselves are.
  std::array<double, kBins + 1> illuminant{};
  std::array<Vec3d, kBins> weight_at_start{}, weight_at_end{};
};

const WavelengthTable& wavelength_table() {
  static const WavelengthTable table = [] {
    WavelengthTable t;
    const Matrix3d& rgb_from_xyz = working_rgb_from_xyz();
    for (int k = 0; k <= kBins; ++k)
      t.illuminant[k] = working_illuminant(kMinSampledWavelengthNm + k);
    for (int k = 0; k < kBins; ++k) {
      double nm = kMinSampledWavelengthNm + k + 0.5;
      Vec3d rgb = rgb_from_xyz * cmf_xyz(nm);
      t.pdf[k] = working_illuminant(nm) * (std::abs(rgb[0]) + std::abs(rgb[1]) + std::abs(rgb[2]));
      t.cdf[k + 1] = t.cdf[k] + t.pdf[k];
    }
    const double total = t.cdf[kBins];
    for (double& p : t.pdf) p /= total;
    for (double& c : t.cdf) c /= total;
    t.cdf[kBins] = 1;
    for (int k = 0; k < kBins; ++k) {
      t.inverse_pdf[k] = 1 / t.pdf[k];
      Vec3d start = rgb_from_xyz * cmf_xyz(kMinSampledWavelengthNm + k);
      Vec3d end = rgb_from_xyz * cmf_xyz(kMinSampledWavelengthNm + k + 1);
      for (int c = 0; c < 3; ++c) {
        t.weight_at_start[k][c] = start[c] / (t.pdf[k] * SampledWavelengths::kCount);
        t.weight_at_end[k][c] = end[c] / (t.pdf[k] * SampledWavelengths::kCount);
      }
    }
    for (int j = 0, bin = 0; j < kGuideCells; ++j) {
      while (bin < kBins - 1 && t.cdf[bin + 1] <= double(j) / kGuideCells) ++bin;
      t.guide[j] = bin;
    }
    return t;
  }();
  return table;
}

double sample_from(const WavelengthTable& t, double u) {
  u = std::clamp(u, 0.0, 1.0);
  // The last bin whose CDF starts at or below u, then linearly within it (the density is flat).
  int bin = t.guide[std::min(int(u * kGuideCells), kGuideCells - 1)];
  while (bin < kBins - 1 && t.cdf[bin + 1] <= u) ++bin;
  const double within = std::clamp((u - t.cdf[bin]) * t.inverse_pdf[bin], 0.0, 1.0);
  return kMinSampledWavelengthNm + bin + within;
}

double pdf_from(const WavelengthTable& t, double nm) {
  if (!(nm >= kMinSampledWavelengthNm && nm <= kMaxSampledWavelengthNm)) return 0;
  return t.pdf[std::min(int(nm - kMinSampledWavelengthNm), kBins - 1)];
}

}  // namespace

double visible_wavelength_pdf(double nm) {
  return pdf_from(wavelength_table(), nm);
}

double sample_visible_wavelength(double u) {
  return sample_from(wavelength_table(), u);
}

SampledWavelengths SampledWavelengths::sample(float u) {
  const WavelengthTable& t = wavelength_table();
  SampledWavelengths w;
  for (int i = 0; i < kCount; ++i) {
    double ui = u + double(i) / kCount;
    if (ui >= 1) ui -= 1;
    w.nm_[i] = float(sample_from(t, ui));
    // The density and the tables at the wavelength as the path will see it (in float).
    const double nm = w.nm_[i];
    const int bin = std::min(int(nm - kMinSampledWavelengthNm), kBins - 1);
    const double f = nm - kMinSampledWavelengthNm - bin;
    w.pdf_[i] = float(t.pdf[bin]);
    w.illuminant_[i] = float(t.illuminant[bin] * (1 - f) + t.illuminant[bin + 1] * f);
    for (int c = 0; c < 3; ++c)
      w.rgb_weights_[c][i] =
          float(t.weight_at_start[bin][c] * (1 - f) + t.weight_at_end[bin][c] * f);
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
