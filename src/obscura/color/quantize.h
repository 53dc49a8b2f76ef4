// Quantization of encoded values in [0, 1] to N-bit integer codes, and dithering.
//
// q = floor(clamp(v, 0, 1)·(2ᴺ − 1) + 0.5): round half up, so v = (k + ½)/(2ᴺ − 1) goes to k + 1.
// Dithering adds a threshold d ∈ (−½, ½) before the floor, chosen per pixel from an ordered
// pattern. For a flat field the mean of the codes then equals v·(2ᴺ − 1) up to the pattern's
// resolution, which is what turns banding into fine noise the eye averages away.
#pragma once

#include <cstdint>
#include <string>

namespace obscura {

inline constexpr int kMinQuantizeBits = 1;
inline constexpr int kMaxQuantizeBits = 16;

// Throws obscura::Error unless 1 ≤ bits ≤ 16.
void check_quantize_bits(int bits);

// NaN quantizes to 0 (a defined value, never garbage).
uint32_t quantize(double v, int bits);
double dequantize(uint32_t q, int bits);
// An N-bit code at M bits: round-half-up(q·(2ᴹ − 1)/(2ᴺ − 1)) in exact integer arithmetic (not
// bit replication).
uint32_t requantize(uint32_t q, int from_bits, int to_bits);

enum class Dither { kNone, kBayer, kBlueNoise };
std::string dither_name(Dither d);             // "none", "bayer", "blue-noise"
Dither parse_dither(const std::string& name);  // throws obscura::Error

// The dither offset for a pixel, in (−½, ½); 0 for kNone. Patterns tile the image: Bayer 8×8,
// blue noise 64×64. `channel` decorrelates the channels by shifting the pattern.
float dither_offset(Dither d, int x, int y, int channel = 0);

// Quantize with a dither offset (in LSB): floor(clamp(v)·(2ᴺ − 1) + 0.5 + offset), clamped.
uint32_t quantize_dithered(double v, int bits, float offset);

}  // namespace obscura
