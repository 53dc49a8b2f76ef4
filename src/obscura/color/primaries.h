// Chromaticities, white points and RGB primaries, and the matrices derived from them.
//
// Every RGB↔XYZ matrix in Obscura is computed here from the published xy chromaticities of the
// primaries and the white point (the standard construction: scale the primaries' XYZ so that
// RGB (1, 1, 1) lands on the white), never typed in, so that each space is exactly what its
// standard defines. Chromatic adaptation between white points uses the linear Bradford transform.
#pragma once

#include "obscura/color/matrix3.h"

namespace obscura {

struct Chromaticity {
  double x = 0, y = 0;
};

// XYZ of a chromaticity with luminance Y (Y = 1 for a white point). Precondition: y > 0.
Vec3d xyz_from_chromaticity(Chromaticity c, double Y = 1);

namespace white {
inline constexpr Chromaticity kD65{0.3127, 0.3290};     // sRGB, Rec.709, Rec.2020, Display P3
inline constexpr Chromaticity kD50{0.3457, 0.3585};     // ICC profile connection space, Lab-D50
inline constexpr Chromaticity kAces{0.32168, 0.33767};  // ACES (≈ D60)
}  // namespace white

struct RgbPrimaries {
  Chromaticity red, green, blue, white;
};

namespace primaries {
inline constexpr RgbPrimaries kRec709{{0.640, 0.330}, {0.300, 0.600}, {0.150, 0.060}, white::kD65};
inline constexpr RgbPrimaries kDisplayP3{
    {0.680, 0.320}, {0.265, 0.690}, {0.150, 0.060}, white::kD65};
inline constexpr RgbPrimaries kRec2020{{0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}, white::kD65};
inline constexpr RgbPrimaries kAcesAp1{
    {0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}, white::kAces};
inline constexpr RgbPrimaries kAcesAp0{
    {0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770}, white::kAces};
}  // namespace primaries

// XYZ (relative to the space's own white, Y = 1 for RGB white) from linear RGB.
Matrix3d xyz_from_rgb(const RgbPrimaries& p);

// The Bradford cone-like response matrix (Lam 1985), the basis of the adaptation below.
Matrix3d bradford_lms_from_xyz();

// Linear Bradford chromatic adaptation: XYZ seen under white `from` → XYZ under white `to`.
Matrix3d bradford_adaptation(Chromaticity from, Chromaticity to);

// XYZ-D65 from linear RGB, adapting the space's white to D65 with Bradford where it differs.
Matrix3d xyz_d65_from_rgb(const RgbPrimaries& p);

}  // namespace obscura
