// The wavelengths one path carries in spectral mode. Hero-wavelength sampling (Wilkie, Nawaz,
// Droske, Weidlich, Hanika 2014, "Hero Wavelength Spectral Sampling", EGSR): a hero wavelength
// is drawn from a density over the visible range and its companions sit at equal steps of that
// density's CDF from it (wrapping around), so each of them is distributed as the hero is and
// together they cover the spectrum evenly. The path's estimate is the average of the
// per-wavelength estimates L(λᵢ)·x̄ȳz̄(λᵢ)/p(λᵢ).
//
// The density is Radziszewski, Boryczko & Alda's (2009, "An improved technique for full spectral
// rendering", Journal of WSCG 17), p(λ) ∝ 1/cosh²(0.0072·(λ − 538 nm)) over 360–830 nm: roughly
// the shape of the eye's response, so wavelengths the eye barely sees are seldom drawn.
//
// Three wavelengths, one per channel of the Rgb triple the BSDFs compute with: in spectral mode a
// path's Rgb values hold its radiance and throughput at nm(0), nm(1), nm(2).
#pragma once

#include <array>

#include "obscura/color/rgb.h"

namespace obscura {

inline constexpr double kMinSampledWavelengthNm = 360, kMaxSampledWavelengthNm = 830;

// Radziszewski et al.'s density (nm⁻¹), normalised over 360–830 nm; 0 outside.
double visible_wavelength_pdf(double wavelength_nm);
// Its inverse CDF: u ∈ [0, 1] → a wavelength in [360, 830] nm.
double sample_visible_wavelength(double u);

class SampledWavelengths {
 public:
  static constexpr int kCount = 3;

  // The hero from u ∈ [0, 1), its companions at u + i/kCount (mod 1).
  static SampledWavelengths sample(float u);

  float nm(int i) const { return nm_[i]; }
  float hero_nm() const { return nm_[0]; }
  // p(λᵢ), nm⁻¹; 0 for a companion that was terminated.
  float pdf(int i) const { return pdf_[i]; }
  // working_illuminant(λᵢ): the white illuminant at each wavelength (spectral_working_space.h).
  float illuminant(int i) const { return illuminant_[i]; }

  // Keeps only the hero: what a path does once its direction depends on the wavelength (a
  // dispersive refraction), since the companions would have gone elsewhere. Their radiance no
  // longer counts and the hero's estimate stands alone.
  void terminate_secondary();
  bool secondary_terminated() const { return pdf_[1] == 0; }

  // Working (linear Rec.709) RGB of a sample whose radiance at nm(i) is channel i: the
  // estimate of ∫ L(λ)·x̄ȳz̄(λ) dλ, then working_rgb_from_xyz().
  Rgb to_working_rgb(Rgb radiance) const;

 private:
  std::array<float, kCount> nm_{}, pdf_{}, illuminant_{};
  std::array<float, kCount> rgb_weights_[3]{};  // per channel of RGB, per wavelength: M·x̄ȳz̄/p
};

}  // namespace obscura
