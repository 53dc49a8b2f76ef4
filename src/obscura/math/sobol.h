// The Sobol' low-discrepancy sequence in base 2 and Owen scrambling of its points.
//
// Direction numbers come from Joe and Kuo's primitive polynomials and initial direction numbers
// ("new-joe-kuo-6.21201", S. Joe and F. Y. Kuo, "Constructing Sobol sequences with better
// two-dimensional projections", SIAM J. Sci. Comput. 30, 2008); the first rows of their table are
// reproduced as numbers in sobol.cpp. Points are 32-bit fixed-point fractions: value / 2³².
#pragma once

#include <cstdint>

namespace obscura {

// Dimensions 0 … kSobolDimensions−1 are available; dimension 0 is the van der Corput sequence.
inline constexpr int kSobolDimensions = 10;

// Component `dimension` of the `index`-th Sobol point, as a 32-bit fraction.
// Precondition: 0 ≤ dimension < kSobolDimensions.
uint32_t sobol_bits(uint32_t index, int dimension);

constexpr uint32_t reverse_bits(uint32_t v) {
  // The bits within each byte, then the bytes by one byte swap (a single instruction): the
  // samplers reverse several words per random number.
  v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
  v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
  v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
  return __builtin_bswap32(v);
}

// The core of owen_scramble below, on a bit-reversed fraction (least significant bit = the
// fraction's first bit): each multiply carries a bit's flip into higher bits only, i.e. into the
// fraction's later bits.
constexpr uint32_t owen_permute_reversed(uint32_t v, uint32_t seed) {
  v += seed;
  v ^= v * 0x6c50b47cu;
  v ^= v * 0xb82f1e52u;
  v ^= v * 0xc7afe638u;
  v ^= v * 0x8d22f6e6u;
  return v;
}

// A hash-based nested uniform (Owen) scramble of a 32-bit fraction (Burley 2020, "Practical
// Hash-based Owen Scrambling", JCGT 9(4)): every bit is flipped or not depending on a hash of the
// bits above it, so the scramble keeps the elementary-interval structure of (t,m,s)-nets while
// randomizing the points. The per-bit hash is Laine and Karras's multiply-xor permutation applied
// to the bit-reversed value, where multiplication carries information from low to high bits.
constexpr uint32_t owen_scramble(uint32_t v, uint32_t seed) {
  return reverse_bits(owen_permute_reversed(reverse_bits(v), seed));
}

// owen_scramble(sobol_bits(index, 0), seed) without building the point: dimension 0 is
// reverse_bits(index), and the scramble's first reversal undoes it.
constexpr uint32_t owen_scrambled_van_der_corput(uint32_t index, uint32_t seed) {
  return reverse_bits(owen_permute_reversed(index, seed));
}

// 32-bit fraction → float in [0, 1), keeping the top 24 bits (exactly representable).
constexpr float fraction_to_float(uint32_t bits) {
  return float(bits >> 8) * 0x1p-24f;
}

}  // namespace obscura
