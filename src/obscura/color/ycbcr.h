// Y′CbCr: luma and two colour differences of encoded R′G′B′ (ITU-R BT.601, BT.709, BT.2020
// non-constant luminance), in float and as 8…16-bit codes in full or limited (video) range.
#pragma once

#include <cstdint>
#include <string>

#include "obscura/color/matrix3.h"

namespace obscura {

enum class YcbcrMatrix { kBt601, kBt709, kBt2020 };
enum class YcbcrRange { kFull, kLimited };

struct LumaCoefficients {
  double kr, kb;  // Kg = 1 − Kr − Kb
};
LumaCoefficients luma_coefficients(YcbcrMatrix m);

// [Y′, Cb, Cr] with Y′ in [0, 1] and Cb, Cr in [−0.5, 0.5] for R′G′B′ in [0, 1].
Vec3d ycbcr_from_rgb(const Vec3d& rgb, YcbcrMatrix m);
Vec3d rgb_from_ycbcr(const Vec3d& ycbcr, YcbcrMatrix m);

// Integer codes at `bits` (8…16). Limited: Y = round((219·Y′ + 16)·2^(bits−8)), C = round((224·C
// + 128)·2^(bits−8)); full: Y = round(Y′·(2^bits − 1)), C = round(C·(2^bits − 1) + 2^(bits−1)).
// Rounding is half up, results clamped to the code range.
struct YcbcrCodes {
  uint16_t y, cb, cr;
};
YcbcrCodes ycbcr_codes(const Vec3d& ycbcr, YcbcrRange range, int bits = 8);
Vec3d ycbcr_from_codes(const YcbcrCodes& codes, YcbcrRange range, int bits = 8);

std::string ycbcr_matrix_name(YcbcrMatrix m);  // "bt601", "bt709", "bt2020"

}  // namespace obscura
