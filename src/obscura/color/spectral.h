// Spectral colour: what the CIE 1931 2° observer and the cones make of light given as power per
// wavelength. Wavelengths are in nm; tables are sampled at 1 nm and interpolated linearly
// between samples; outside a table's range its functions are 0 (the eye does not respond).
#pragma once

#include <functional>

#include "obscura/color/matrix3.h"
#include "obscura/color/primaries.h"

namespace obscura {

// x̄ȳz̄ of a single wavelength (the XYZ of unit power at λ). Throws obscura::Error for a
// negative, zero or non-finite wavelength.
Vec3d cmf_xyz(double wavelength_nm);
// Stockman & Sharpe 2° cone fundamentals l̄ m̄ s̄ (each peaking at 1).
Vec3d cone_lms(double wavelength_nm);

// XYZ of a spectral power distribution: Σ S(λ)·x̄(λ)·Δλ over 360–830 nm at 1 nm (rectangle
// rule; no normalisation).
Vec3d spectrum_to_xyz(const std::function<double(double)>& spd_of_nm);
// LMS cone responses Σ S(λ)·l̄(λ) over 390–830 nm at 1 nm.
Vec3d spectrum_to_lms(const std::function<double(double)>& spd_of_nm);

// CIE D65 relative SPD (100 at 560 nm), 0 outside 300–830 nm.
double d65_spd(double wavelength_nm);

// Planck's law: spectral radiance of a blackbody in W·sr⁻¹·m⁻²·nm⁻¹, with the exact SI 2019
// constants h, c, k. Preconditions (throw): wavelength > 0, temperature > 0.
double planck_radiance(double wavelength_nm, double kelvin);
// The blackbody's XYZ normalised to Y = 1. Uses the CIE 15 convention c₂ = 1.4388e-2 m·K
// (ITS-90) for the colour of a temperature, as colour-temperature tables do.
Vec3d blackbody_xyz(double kelvin);

// A colour's chromaticity (x, y); black gives (0, 0).
Chromaticity chromaticity_of(const Vec3d& xyz);

}  // namespace obscura
