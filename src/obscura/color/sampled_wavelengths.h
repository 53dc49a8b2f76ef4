// The wavelengths one path carries in spectral mode. Hero-wavelength sampling (Wilkie, Nawaz,
// Droske, Weidlich, Hanika 2014, "Hero Wavelength Spectral Sampling", EGSR): a hero wavelength
// is drawn from a density over the visible range and its companions sit at equal steps of that
// density's CDF from it (wrapping around), so each of them is distributed as the hero is and
// together they cover the spectrum evenly. The path's estimate is the average of the
// per-wavelength estimates L(λᵢ)·x̄ȳz̄(λᵢ)/p(λᵢ).
//
// The density is matched to what the film needs: p(λ) ∝ D65(λ)·(|r̄(λ)| + |ḡ(λ)| + |b̄(λ)|), where
// r̄ḡb̄ = M·x̄ȳz̄ are the working space's (linear Rec.709's) colour-matching functions (M its matrix
// from XYZ, spectral_working_space.h) and D65 its white illuminant, which every RGB light is
// lifted to (rgb_to_spectrum.h). Tabulated per 1 nm, constant within each nm, sampled by CDF
// inversion. For white light it cuts the per-sample standard deviation of the film's R, G, B from
// 0.42, 0.07, 0.88 (Radziszewski et al. 2009's 1/cosh² density, used before) to 0.32, 0.12, 0.31:
// the sum of the three variances falls 4.5×. (Measured in docs/tracer.md, "Spectral mode".)
//
// Three wavelengths, one per channel of the Rgb triple the BSDFs compute with: in spectral mode a
// path's Rgb values hold its radiance and throughput at nm(0), nm(1), nm(2).
#pragma once

#include <array>

#include "obscura/color/rgb.h"

namespace obscura {

inline constexpr double kMinSampledWavelengthNm = 360, kMaxSampledWavelengthNm = 830;

// The density above (nm⁻¹), normalised over 360–830 nm; 0 outside.
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
