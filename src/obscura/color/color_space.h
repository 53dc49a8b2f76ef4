// Named colour spaces and conversion between any two of them.
//
// The names are the ids of the shared test vectors (`srgb`, `srgb-linear`, `xyz-d65`, `lab-d50`,
// `display-p3`, `acescg`, `ycbcr-float-bt709`, …). Conversion goes through CIE XYZ with a D65
// white (Y = 1 for diffuse white); spaces with another white (D50, ACES) are adapted with the
// linear Bradford transform. Everything here runs in double precision: it is the reference path
// for the CLI and tests. Pixel loops use display_transform.h instead.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "obscura/color/matrix3.h"
#include "obscura/color/primaries.h"
#include "obscura/color/transfer.h"

namespace obscura {

enum class ColorModel {
  kRgb,          // an RGB space: primaries + transfer function
  kXyz,          // CIE XYZ relative to a white (D65 or D50)
  kXyy,          // chromaticity + luminance
  kLab,          // CIE L*a*b* relative to a white
  kOklab,        // OKLab
  kOklch,        // OKLab in polar form
  kHsv,          // of encoded sRGB
  kHsl,          // of encoded sRGB
  kCmy,          // of encoded sRGB
  kCmyk,         // of encoded sRGB; four components
  kLmsBradford,  // Bradford cone-like response of XYZ-D65
  kYcbcrFloat,   // Y′CbCr of encoded sRGB (R′G′B′), float
  kYcbcr8,       // Y′CbCr 8-bit codes of encoded sRGB
};

struct ColorSpaceInfo {
  std::string name;
  ColorModel model;
  int components = 3;
  RgbPrimaries primaries = primaries::kRec709;  // kRgb
  Matrix3d xyz_d65_from_rgb, rgb_from_xyz_d65;  // kRgb: derived from `primaries` at start-up
  TransferFunction transfer = TransferFunction::kLinear;  // kRgb
  double linear_scale = 1;  // kRgb: linear value that means diffuse white (PQ: 203 / 10 000)
  Chromaticity white = white::kD65;  // kXyz, kLab
  int ycbcr_matrix = 0;              // YcbcrMatrix, kYcbcr*
  bool limited_range = false;        // kYcbcr8
  std::string description;
};

// All known spaces, in a stable order (for --help and error messages).
const std::vector<ColorSpaceInfo>& color_spaces();
// The space named `name`; throws obscura::Error listing the known names.
const ColorSpaceInfo& color_space(const std::string& name);
std::optional<ColorSpaceInfo> find_color_space(const std::string& name);

// Converts `values` (as many as the source space has components) from one space to another.
// Throws obscura::Error for a wrong number of values or a non-finite value.
std::vector<double> convert_color(const std::string& from, const std::string& to,
                                  const std::vector<double>& values);

// To and from XYZ-D65 (the hub every conversion passes through).
Vec3d xyz_d65_from(const ColorSpaceInfo& space, const std::vector<double>& values);
std::vector<double> from_xyz_d65(const ColorSpaceInfo& space, const Vec3d& xyz);

// Linear RGB of `to` from linear RGB of `from` (both kRgb), D65-adapted as above.
Matrix3d rgb_to_rgb_matrix(const RgbPrimaries& from, const RgbPrimaries& to);

// Whether XYZ-D65 lies inside an RGB space's gamut: every linear component in [−tolerance,
// 1 + tolerance] once divided by the luminance scale (values above 1 are "too bright", which a
// caller may or may not count as out of gamut: `allow_above_one`).
bool in_gamut(const RgbPrimaries& space, const Vec3d& xyz_d65, double tolerance = 1e-6,
              bool allow_above_one = false);

}  // namespace obscura
