// The working colour space (linear Rec.709, D65 white: what the film holds) seen spectrally: its
// white illuminant as a spectrum and the matrix that turns the CIE XYZ of a spectrum into working
// RGB. Spectral mode and the RGB → spectrum lifting both go through these two, so that a
// spectrum lifted from RGB comes back to the same RGB.
#pragma once

#include "obscura/color/matrix3.h"

namespace obscura {

// CIE D65 scaled to unit luminance: Σ D65(λ)·ȳ(λ)·Δλ = 1 over the 1 nm CIE 1931 table
// (360–830 nm). Light whose spectrum this is has XYZ = the D65 white with Y = 1.
double working_illuminant(double wavelength_nm);

// Working (linear Rec.709) RGB from XYZ: the Rec.709 matrix derived from its primaries, with a
// per-channel gain (≤ 1e-4 from 1) that maps the tabulated D65 — whose chromaticity differs from
// the rounded (0.3127, 0.3290) the standard names in the fifth decimal — exactly to (1, 1, 1).
const Matrix3d& working_rgb_from_xyz();

}  // namespace obscura
