// The non-linear colour models: xyY, CIE L*a*b*, OKLab/OKLCh, HSV, HSL, CMY and CMYK.
//
// Each is a pair of plain functions on a triple, with its reference white or source space in the
// name. They are the building blocks that color_space.h chains together.
#pragma once

#include <array>

#include "obscura/color/matrix3.h"

namespace obscura {

// xyY from XYZ; black (X + Y + Z = 0) gets the chromaticity `black_xy` (the white's) and Y = 0.
Vec3d xyy_from_xyz(const Vec3d& xyz, double black_x, double black_y);
Vec3d xyz_from_xyy(const Vec3d& xyy);  // y = 0 gives black

// CIE 1976 L*a*b* (CIE 15): L in 0..100, relative to the XYZ white `white_xyz` (Y = 1).
Vec3d lab_from_xyz(const Vec3d& xyz, const Vec3d& white_xyz);
Vec3d xyz_from_lab(const Vec3d& lab, const Vec3d& white_xyz);

// OKLab (Ottosson 2020) from XYZ-D65 with Y = 1 for white; L in 0..1. Its two matrices are its
// definition (there are no primaries to derive them from); the values are the double-precision
// ones of CSS Color 4, and the inverses are computed.
Vec3d oklab_from_xyz_d65(const Vec3d& xyz);
Vec3d xyz_d65_from_oklab(const Vec3d& lab);
// OKLCh: lightness, chroma, hue in degrees [0, 360).
Vec3d oklch_from_oklab(const Vec3d& lab);
Vec3d oklab_from_oklch(const Vec3d& lch);

// HSV and HSL of encoded R'G'B' in [0, 1]: hue in degrees [0, 360) (0 for greys, where it is
// undefined), saturation and value/lightness in [0, 1].
Vec3d hsv_from_rgb(const Vec3d& rgb);
Vec3d rgb_from_hsv(const Vec3d& hsv);
Vec3d hsl_from_rgb(const Vec3d& rgb);
Vec3d rgb_from_hsl(const Vec3d& hsl);

// Subtractive models of encoded R'G'B': a cyan ink absorbs red, so C = 1 − R'. CMYK pulls the
// common part into black: K = 1 − max(R', G', B'); white has no ink, black is K = 1 alone.
Vec3d cmy_from_rgb(const Vec3d& rgb);
Vec3d rgb_from_cmy(const Vec3d& cmy);
std::array<double, 4> cmyk_from_rgb(const Vec3d& rgb);
Vec3d rgb_from_cmyk(const std::array<double, 4>& cmyk);

}  // namespace obscura
