// A lens prescription: the optical designer's table of a lens, surface by surface from the object
// side to the sensor side. Each surface has a signed radius of curvature (positive: its centre
// lies towards the sensor; 0: flat), the axial thickness to the next surface, the medium after
// it (refractive index n_d at the d line and, for dispersion, its Abbe number V_d), a clear
// aperture, and optionally an even-asphere profile. One flat surface is the aperture stop.
//
// An even asphere's sag (the surface's axial departure from its vertex plane, positive towards
// the sensor) at height r from the axis, with curvature c = 1 / radius and conic constant k:
//   z(r) = c·r² / (1 + √(1 − (1 + k)·c²·r²)) + A4·r⁴ + A6·r⁶ + … + A16·r¹⁶
// (k = 0 and every A zero: the sphere; k = −1: the paraboloid).
//
// Dispersion (a glass's index at other wavelengths) comes from n_d and V_d through a two-term
// Cauchy law n(λ) = A + B / λ², fitted so that n(λ_d) = n_d exactly and n_F − n_C equals the
// Abbe definition (n_d − 1) / V_d:
//   B = (n_d − 1) / V_d / (1/λ_F² − 1/λ_C²),   A = n_d − B / λ_d²
// with the Fraunhofer lines λ_F = 486.13 nm, λ_d = 587.56 nm, λ_C = 656.27 nm. Over the visible
// range this matches catalogue glasses to about 1e-4 in n (N-BK7, n_d 1.5168, V_d 64.17: Schott's
// Sellmeier formula gives n(450 nm) = 1.52532, this law 1.52541; at 700 nm 1.51306 and 1.51319);
// without V_d a medium does not disperse.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace obscura {

// The Fraunhofer lines that define the Abbe number, in nanometres.
inline constexpr double kWavelengthF_nm = 486.1327;  // hydrogen F (blue)
inline constexpr double kWavelengthD_nm = 587.5618;  // helium d (yellow): n_d's wavelength
inline constexpr double kWavelengthC_nm = 656.2725;  // hydrogen C (red)

struct LensSurface {
  double radius_mm = 0;              // signed; 0: flat
  double thickness_mm = 0;           // ≥ 0, to the next surface along the axis (the last: 0)
  double n_d = 1;                    // index of the medium after the surface at the d line (1: air)
  double abbe_number = 0;            // V_d of that medium; 0: no dispersion
  double aperture_diameter_mm = 0;   // > 0: the clear aperture (the stop: its full opening)
  bool is_stop = false;              // the aperture stop (flat, air after it)
  double conic = 0;                  // k of the even asphere
  std::array<double, 7> aspheric{};  // A4, A6, …, A16 (mm^(1 − 2i))

  bool is_aspheric() const;
};

struct LensPrescription {
  std::string name;                   // what the lens is called ("double-gauss-50mm")
  std::vector<LensSurface> surfaces;  // object side first
};

// n(λ) of a medium with index n_d and Abbe number V_d (0: n_d at every wavelength), by the Cauchy
// fit above. λ in nanometres, > 0.
double refractive_index(double n_d, double abbe_number, double wavelength_nm = kWavelengthD_nm);

// The surface's sag z(r) in mm (positive towards the sensor) and its derivative dz/dr, at height
// r. Nothing beyond where a conic's square root turns negative.
struct Sag {
  double z = 0, slope = 0;
};
bool surface_sag(const LensSurface& s, double r_mm, Sag& out);

// The index of the stop among the surfaces.
int stop_index(const LensPrescription& p);

// Throws obscura::Error(field, message) for the first invalid field of one surface: a
// non-positive aperture, a negative thickness, an index below 1, a negative Abbe number, a stop
// that is not flat or has glass after it, non-finite values.
void validate(const LensSurface& s);
// Throws obscura::Error naming the surface (1-based, as the table's rows) and the field: no
// surfaces, no stop or more than one, a stop that is not flat, a non-positive aperture, a
// negative thickness, an index below 1, a negative Abbe number, non-finite values.
void validate(const LensPrescription& p);

}  // namespace obscura
