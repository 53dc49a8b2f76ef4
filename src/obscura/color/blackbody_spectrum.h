// A blackbody emitter's spectrum for spectral mode: Planck's law (spectral.h) at a temperature,
// scaled to unit luminance (Σ B(λ)·ȳ(λ)·Δλ = 1 over the 1 nm CIE 1931 table), so that an
// emitter's strength sets its luminance whatever its temperature.
#pragma once

#include "obscura/color/rgb.h"

namespace obscura {

class BlackbodySpectrum {
 public:
  // Throws obscura::Error for a temperature that is not positive and finite, or so low that
  // nothing visible is emitted.
  explicit BlackbodySpectrum(float kelvin);

  float kelvin() const { return kelvin_; }
  // Relative spectral radiance at λ (nm), Y = 1.
  float operator()(float wavelength_nm) const;
  // Its colour in the working space (linear Rec.709), Y = 1; negative channels (temperatures
  // whose colour lies outside the gamut) clipped to 0. What RGB mode renders it with.
  Rgb working_rgb() const { return rgb_; }

 private:
  float kelvin_ = 0;
  double scale_ = 0;  // 1 / Σ Planck·ȳ
  Rgb rgb_;
};

}  // namespace obscura
