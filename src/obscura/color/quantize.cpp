#include "obscura/color/quantize.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "obscura/color/blue_noise.h"
#include "obscura/math/error.h"

namespace obscura {

void check_quantize_bits(int bits) {
  if (bits < kMinQuantizeBits || bits > kMaxQuantizeBits)
    throw Error("bits", "expected 1…16 bits per channel; got " + std::to_string(bits));
}

uint32_t quantize(double v, int bits) {
  return quantize_dithered(v, bits, 0);
}

double dequantize(uint32_t q, int bits) {
  check_quantize_bits(bits);
  return double(q) / double((1u << bits) - 1);
}

uint32_t requantize(uint32_t q, int from_bits, int to_bits) {
  check_quantize_bits(from_bits);
  check_quantize_bits(to_bits);
  uint64_t from_max = (1u << from_bits) - 1, to_max = (1u << to_bits) - 1;
  if (q > from_max)
    throw Error("requantize",
                "code " + std::to_string(q) + " exceeds " + std::to_string(from_bits) + " bits");
  // round-half-up(q·to_max/from_max) = floor((2·q·to_max + from_max) / (2·from_max))
  return uint32_t((2 * q * to_max + from_max) / (2 * from_max));
}

std::string dither_name(Dither d) {
  switch (d) {
    case Dither::kNone:
      return "none";
    case Dither::kBayer:
      return "bayer";
    case Dither::kBlueNoise:
      return "blue-noise";
  }
  return "?";
}

Dither parse_dither(const std::string& name) {
  for (Dither d : {Dither::kNone, Dither::kBayer, Dither::kBlueNoise})
    if (dither_name(d) == name) return d;
  throw Error("dither", "unknown method '" + name + "'; expected none, bayer or blue-noise");
}

namespace {

// The 8×8 Bayer index matrix, built by the recursion M₂ₙ = [4M+0, 4M+2; 4M+3, 4M+1].
std::array<uint8_t, 64> make_bayer8() {
  std::array<uint8_t, 64> m{};
  for (int size = 1; size < 8; size *= 2) {
    std::array<uint8_t, 64> next{};
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        uint8_t v = uint8_t(4 * m[y * 8 + x]);
        next[y * 8 + x] = v;
        next[y * 8 + x + size] = v + 2;
        next[(y + size) * 8 + x] = v + 3;
        next[(y + size) * 8 + x + size] = v + 1;
      }
    m = next;
  }
  return m;
}

}  // namespace

float dither_offset(Dither d, int x, int y, int channel) {
  switch (d) {
    case Dither::kNone:
      return 0;
    case Dither::kBayer: {
      static const std::array<uint8_t, 64> bayer = make_bayer8();
      // Shift the pattern per channel so that the three channels do not step together.
      int sx = (x + 3 * channel) & 7, sy = (y + 5 * channel) & 7;
      return (bayer[sy * 8 + sx] + 0.5f) / 64 - 0.5f;
    }
    case Dither::kBlueNoise: {
      const BlueNoiseMask& mask = blue_noise_mask();
      int n = mask.size;
      int sx = (x + 23 * channel) % n, sy = (y + 41 * channel) % n;
      if (sx < 0) sx += n;
      if (sy < 0) sy += n;
      return mask.threshold(sx, sy) - 0.5f;
    }
  }
  return 0;
}

uint32_t quantize_dithered(double v, int bits, float offset) {
  check_quantize_bits(bits);
  if (std::isnan(v)) return 0;
  double max = double((1u << bits) - 1);
  double q = std::floor(std::clamp(v, 0.0, 1.0) * max + 0.5 + offset);
  return uint32_t(std::clamp(q, 0.0, max));
}

}  // namespace obscura
