// How much light an interface of a lens reflects: bare glass by Fresnel's equations, or glass
// with a single-layer anti-reflection coating by thin-film interference. The reflections are what
// ghost flares are made of (lens_ghosts.h); the coating is what makes them weak and coloured.
//
// Bare interface from index n1 into n2 at angle of incidence θ1 (Snell: n1·sin θ1 = n2·sin θ2),
// the amplitude reflection coefficients of the two polarisations:
//   r_s = (n1·cos θ1 − n2·cos θ2) / (n1·cos θ1 + n2·cos θ2)
//   r_p = (n2·cos θ1 − n1·cos θ2) / (n2·cos θ1 + n1·cos θ2)
// and the reflectances R = |r|² (1 beyond the critical angle: total internal reflection).
//
// A layer of index n_c and physical thickness d between them: the waves reflected at its two
// faces interfere. With r_a the coefficient of the first face (n1 → n_c), r_b of the second
// (n_c → n2) and the phase the layer adds on one pass, δ = 2π·n_c·d·cos θ_c / λ, the multiple
// reflections sum (Airy) to
//   r = (r_a + r_b·e^{2iδ}) / (1 + r_a·r_b·e^{2iδ}),   t = t_a·t_b·e^{iδ} / (1 + r_a·r_b·e^{2iδ})
// per polarisation, R = |r|², T = (n2·cos θ2) / (n1·cos θ1) · |t|² (lossless: R + T = 1).
// Unpolarised light reflects the mean of the two: R = (R_s + R_p) / 2.
//
// A quarter-wave layer (n_c·d = λ0/4) at its design wavelength λ0 and normal incidence reflects
// R = ((n1·n2 − n_c²) / (n1·n2 + n_c²))²: zero when n_c = √(n1·n2). Magnesium fluoride (n = 1.38)
// on glass of n ≈ 1.5 leaves about 1.3 % at 550 nm instead of 4 %, more towards blue and red: the
// purple tint of coated lenses and of their ghosts.
#pragma once

#include <string>

namespace obscura {

// One coating for every air–glass surface of a lens (cemented glass–glass surfaces stay bare).
struct LensCoating {
  double thickness_nm = 0;  // ≥ 0, physical; 0: no coating (bare glass)
  double index = 1.38;      // the layer's refractive index (≥ 1), constant over wavelength

  bool coated() const { return thickness_nm > 0; }
};
bool operator==(const LensCoating& a, const LensCoating& b);

// The single layer a quarter of the design wavelength thick, optically (n_c·d = λ0 / 4).
// Defaults: magnesium fluoride at 550 nm, the classic single coating.
LensCoating quarter_wave_coating(double index = 1.38, double design_wavelength_nm = 550);

// "none", "quarter-wave", "quarter-wave:INDEX" or "quarter-wave:INDEX:NM". Throws
// obscura::Error(`field`, …) saying what was expected.
LensCoating parse_lens_coating(const std::string& text, const std::string& field = "coating");
// The inverse of parse_lens_coating, for listings ("none", "quarter-wave:1.38:550").
std::string lens_coating_text(const LensCoating& coating);

// Throws obscura::Error naming the field: a negative or non-finite thickness, an index below 1.
void validate(const LensCoating& coating);

// Reflectance and transmittance of an interface per polarisation, for light of `wavelength_nm`
// arriving from index n1 into n2 with cos θ1 = `cos_incidence` ∈ (0, 1]. For lossless media
// R + T = 1 in each polarisation.
struct InterfaceOptics {
  double reflect_s = 0, reflect_p = 0, transmit_s = 1, transmit_p = 1;
  double reflectance() const { return 0.5 * (reflect_s + reflect_p); }  // unpolarised
  double transmittance() const { return 0.5 * (transmit_s + transmit_p); }
};
InterfaceOptics bare_interface(double n1, double n2, double cos_incidence);
InterfaceOptics coated_interface(const LensCoating& coating, double n1, double n2,
                                 double cos_incidence, double wavelength_nm);
// The unpolarised reflectance alone, what ghosts need per ray: the same value, but where every
// wave propagates (no total reflection in the layer or beyond) by the real form of the Airy sum,
//   R = (r_a² + r_b² + 2·r_a·r_b·cos 2δ) / (1 + r_a²·r_b² + 2·r_a·r_b·cos 2δ),
// without complex arithmetic (most of a ghost ray's cost otherwise).
double interface_reflectance(const LensCoating& coating, double n1, double n2, double cos_incidence,
                             double wavelength_nm);

}  // namespace obscura
