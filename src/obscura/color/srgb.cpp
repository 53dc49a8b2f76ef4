#include "obscura/color/srgb.h"

#include <cmath>

namespace obscura {

float srgb_encode(float linear) {
  float a = std::abs(linear);
  float e = a <= 0.0031308f ? 12.92f * a : 1.055f * std::pow(a, 1 / 2.4f) - 0.055f;
  return std::copysign(e, linear);
}

float srgb_decode(float encoded) {
  float a = std::abs(encoded);
  float l = a <= 0.04045f ? a / 12.92f : std::pow((a + 0.055f) / 1.055f, 2.4f);
  return std::copysign(l, encoded);
}

}  // namespace obscura
