// How many electrons a sensor's channels collect from the light an RGB film records: the
// documented projection from the renderers' linear Rec.709 film to the sensor's spectral quantum
// efficiency, and the colour matrices a raw developer needs to undo it.
//
// A film value v = (r, g, b) stands for a spectrum: each primary is lifted to the smooth
// spectrum Obscura's spectral mode gives it (rgb_to_spectrum.h: Jakob & Hanika, times the D65
// white), so that (1, 1, 1) is D65 and every spectrum has the XYZ of its RGB. A film value of
// (1, 1, 1) on a pixel exposed to H lux·s delivers, per square metre,
//   n_k = H · ∫ QE_k(λ) · S(λ) · λ / (h c) dλ / (683 lm/W · ∫ S(λ) ȳ(λ) dλ)
// photoelectrons to channel k, with S the D65 spectrum; per primary the same with its lift. The
// integrals run over 360–830 nm at 1 nm on the CIE tables. The result is a 3 × 3 matrix:
// electrons per (lux·s · m²) of channel k per unit of film channel c.
#pragma once

#include <array>

#include "obscura/color/matrix3.h"
#include "obscura/sensor/sensor_spec.h"

namespace obscura {

// Photons per (lux·s · m²) of light with the spectrum of `relative_spd` at 1 nm from 360 nm
// (any scale): n = ∫ S λ/(hc) dλ / (683 ∫ S ȳ dλ). For D65 it is about 1.2e16 (a published
// rule of thumb for daylight); for 555 nm light exactly 1/683 W/m² per lux over hc/λ = 4.09e15.
double photons_per_lux_second(const std::array<double, 471>& relative_spd);

struct SensorResponse {
  // electrons per (lux·s · m²) in sensor channel k (row; 0 red, 1 green, 2 blue filter; a
  // monochrome sensor's one channel is row 1 and rows 0, 2 are equal to it) per unit of film
  // channel c (column) — before the pixel's area, fill factor and PRNU.
  Matrix3d electrons_per_lux_s_m2;
  // DNG's ColorMatrix1: XYZ → camera (raw DN less black, any common scale) under D65,
  // normalised so that D65's XYZ (Y = 1) maps to a neutral whose largest component is 1. It
  // inverts the projection above exactly.
  Matrix3d color_matrix_d65;
  // DNG's ColorMatrix2 under CIE illuminant A: the least-squares (Luther) fit of the QE curves
  // by the colour-matching functions, weighted by A's spectrum, normalised likewise.
  Matrix3d color_matrix_a;
  // The camera's response to D65 white, divided by its largest component (DNG AsShotNeutral
  // for a D65-lit scene).
  Vec3d neutral_d65{1, 1, 1};
};

// The response of `spec`'s colour filters (or its monochrome QE). Precondition: spec valid.
SensorResponse sensor_response(const SensorSpec& spec);

}  // namespace obscura
