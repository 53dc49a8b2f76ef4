#include "obscura/color/ycbcr.h"

#include <algorithm>
#include <cmath>

#include "obscura/math/error.h"

namespace obscura {

LumaCoefficients luma_coefficients(YcbcrMatrix m) {
  switch (m) {
    case YcbcrMatrix::kBt601:
      return {0.299, 0.114};
    case YcbcrMatrix::kBt709:
      return {0.2126, 0.0722};
    case YcbcrMatrix::kBt2020:
      return {0.2627, 0.0593};
  }
  return {0.2126, 0.0722};
}

Vec3d ycbcr_from_rgb(const Vec3d& rgb, YcbcrMatrix m) {
  auto [kr, kb] = luma_coefficients(m);
  double y = kr * rgb[0] + (1 - kr - kb) * rgb[1] + kb * rgb[2];
  return {y, (rgb[2] - y) / (2 * (1 - kb)), (rgb[0] - y) / (2 * (1 - kr))};
}

Vec3d rgb_from_ycbcr(const Vec3d& ycbcr, YcbcrMatrix m) {
  auto [kr, kb] = luma_coefficients(m);
  double y = ycbcr[0];
  double r = y + 2 * (1 - kr) * ycbcr[2];
  double b = y + 2 * (1 - kb) * ycbcr[1];
  double g = (y - kr * r - kb * b) / (1 - kr - kb);
  return {r, g, b};
}

namespace {

void check_bits(int bits) {
  if (bits < 8 || bits > 16)
    throw Error("YCbCr bit depth", "expected 8…16 bits; got " + std::to_string(bits));
}

uint16_t round_code(double v, int bits) {
  // Round half up; a tiny allowance keeps exact rational ties (x.5) from falling below .5 through
  // binary rounding of the coefficients.
  double q = std::floor(v + 0.5 + 1e-9);
  return uint16_t(std::clamp(q, 0.0, double((1 << bits) - 1)));
}

}  // namespace

YcbcrCodes ycbcr_codes(const Vec3d& c, YcbcrRange range, int bits) {
  check_bits(bits);
  if (range == YcbcrRange::kLimited) {
    double scale = std::ldexp(1.0, bits - 8);
    return {round_code((219 * c[0] + 16) * scale, bits),
            round_code((224 * c[1] + 128) * scale, bits),
            round_code((224 * c[2] + 128) * scale, bits)};
  }
  double max = (1 << bits) - 1, mid = 1 << (bits - 1);
  return {round_code(c[0] * max, bits), round_code(c[1] * max + mid, bits),
          round_code(c[2] * max + mid, bits)};
}

Vec3d ycbcr_from_codes(const YcbcrCodes& q, YcbcrRange range, int bits) {
  check_bits(bits);
  if (range == YcbcrRange::kLimited) {
    double scale = std::ldexp(1.0, bits - 8);
    return {(q.y / scale - 16) / 219, (q.cb / scale - 128) / 224, (q.cr / scale - 128) / 224};
  }
  double max = (1 << bits) - 1, mid = 1 << (bits - 1);
  return {q.y / max, (q.cb - mid) / max, (q.cr - mid) / max};
}

std::string ycbcr_matrix_name(YcbcrMatrix m) {
  switch (m) {
    case YcbcrMatrix::kBt601:
      return "bt601";
    case YcbcrMatrix::kBt709:
      return "bt709";
    case YcbcrMatrix::kBt2020:
      return "bt2020";
  }
  return "?";
}

}  // namespace obscura
