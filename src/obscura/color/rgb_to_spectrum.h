// RGB → spectrum lifting for spectral mode: Jakob & Hanika 2019, "A Low-Dimensional Function
// Space for Efficient Spectral Upsampling" (Computer Graphics Forum 38(2)). A reflectance is
// s(λ) = S(c₀t² + c₁t + c₂) with t = (λ − 360 nm) / 470 nm and the sigmoid
// S(x) = ½ + x / (2√(1 + x²)): smooth, and bounded in [0, 1] by construction. The three
// coefficients of each colour come from a table over the RGB cube, fitted by OUR code at first
// use (a second or less; kept in memory, and between runs in the cache folder of
// math/disk_cache.h, keyed by the code and compiler that fitted it): at every grid point,
// Gauss–Newton iterations
// match the spectrum's colour under the working white (D65; spectral_working_space.h), in CIELAB,
// to the grid point's RGB. Between grid points, coefficients are interpolated trilinearly.
//
// Grid (as Jakob & Hanika lay it out): for each choice of largest channel, 32 values of it
// (denser near 0 and 1) × 32 × 32 values of the other two relative to it.
#pragma once

#include <array>
#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/color/sampled_wavelengths.h"

namespace obscura {

// s(λ) for coefficients in the normalised wavelength t = (λ − 360) / 470; c₂ = ±∞ gives 1 or 0.
struct SigmoidPolynomial {
  float c0 = 0, c1 = 0, c2 = 0;
  float operator()(float wavelength_nm) const;
};

class RgbToSpectrumTable {
 public:
  static constexpr int kResolution = 32;

  // The working space's table, on first use (thread-safe) read from the cache folder or else
  // fitted (and stored there), then shared.
  static const RgbToSpectrumTable& working_space();
  // The table fitted now, never read from the cache (what working_space() stores).
  static RgbToSpectrumTable fit();

  // The reflectance spectrum of `rgb`, each channel clamped to [0, 1] first. Greys are exact:
  // the constant spectrum of their value.
  SigmoidPolynomial operator()(Rgb rgb) const;

  // Largest fitting error over the grid, in CIELAB ΔE (1976): how well the fit converged.
  float worst_fit_delta_e() const { return worst_delta_e_; }
  // The fitted coefficients, [largest channel][scale][y][x][3].
  const std::vector<float>& coefficients() const { return coefficients_; }

 private:
  RgbToSpectrumTable() = default;
  static const RgbToSpectrumTable& cached_or_fitted();
  std::array<float, kResolution> scale_{};  // the largest channel's grid values
  std::vector<float> coefficients_;         // [largest channel][scale][y][x][3]
  float worst_delta_e_ = 0;
};

// Values at the path's wavelengths (channel i at w.nm(i)) of the spectra RGB colours stand for.
// Reflectance-like colours (albedos, tints) in [0, 1]; channels clamp to [0, 1].
Rgb lift_reflectance(Rgb rgb, const SampledWavelengths& w);
// Any non-negative colour (an index of refraction, a colour factor above 1): the reflectance lift
// of rgb / (2·max) scaled by 2·max (the unbounded spectra pbrt-v4 builds on Jakob & Hanika's
// table): exact for greys, and a colour scaled by k lifts to its spectrum scaled by k.
// Negatives clamp to 0.
Rgb lift_unbounded(Rgb rgb, const SampledWavelengths& w);
// Emitted light: the unbounded lift times the white illuminant, so that RGB (1, 1, 1) is the
// working white and any colour's XYZ under the observer is its RGB's.
Rgb lift_illuminant(Rgb rgb, const SampledWavelengths& w);

}  // namespace obscura
