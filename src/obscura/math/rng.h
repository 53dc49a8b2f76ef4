// Deterministic random numbers.
//
// Renderers draw every random number as a pure function of (seed, pixel, sample index,
// dimension), so an image does not depend on which thread rendered which pixel or in what order.
// `PixelSampler` walks the dimensions of one sample; `Pcg32` is a sequential generator for work
// that has no pixel (scene preprocessing, tests).
#pragma once

#include <cstdint>

#include "obscura/math/vector.h"

namespace obscura {

// A 64-bit finalizer with full avalanche (the splitmix64 / Stafford "Mix13" constants).
constexpr uint64_t mix_bits(uint64_t v) {
  v ^= v >> 30;
  v *= 0xbf58476d1ce4e5b9ULL;
  v ^= v >> 27;
  v *= 0x94d049bb133111ebULL;
  v ^= v >> 31;
  return v;
}

// Hash of a key made of several 64-bit words; each word passes the mixer before the next enters.
// In two halves, so that callers hashing many (c, d) under one (a, b) mix the first two words
// once: hash_words(a, b, c, d) = hash_words_last(hash_words_first(a, b), c, d).
constexpr uint64_t hash_words_first(uint64_t a, uint64_t b) {
  uint64_t h = mix_bits(a + 0x9e3779b97f4a7c15ULL);
  return mix_bits(h ^ (b + 0x632be59bd9b4e019ULL));
}
constexpr uint64_t hash_words_last(uint64_t first, uint64_t c, uint64_t d) {
  uint64_t h = mix_bits(first ^ (c + 0x8cb92ba72f3d8dd7ULL));
  return mix_bits(h ^ (d + 0xd6e8feb86659fd93ULL));
}
constexpr uint64_t hash_words(uint64_t a, uint64_t b, uint64_t c = 0, uint64_t d = 0) {
  return hash_words_last(hash_words_first(a, b), c, d);
}

// The top 24 bits of a hash as a float uniformly in [0, 1): every value is exactly representable.
constexpr float bits_to_unit_float(uint64_t bits) {
  return float(bits >> 40) * 0x1p-24f;
}

// The random number for one (seed, pixel, sample, dimension).
constexpr float sample_uniform(uint64_t seed, Point2i pixel, uint32_t sample_index,
                               uint32_t dimension) {
  uint64_t pixel_key = (uint64_t(uint32_t(pixel.y)) << 32) | uint32_t(pixel.x);
  return bits_to_unit_float(hash_words(seed, pixel_key, sample_index, dimension));
}

// The random numbers of one sample of one pixel, dimension after dimension.
class PixelSampler {
 public:
  PixelSampler(uint64_t seed, Point2i pixel, uint32_t sample_index)
      : seed_(seed), pixel_(pixel), sample_index_(sample_index) {}

  float next_1d() { return sample_uniform(seed_, pixel_, sample_index_, dimension_++); }
  Point2f next_2d() {
    float u = next_1d();
    return {u, next_1d()};
  }
  uint32_t dimension() const { return dimension_; }

 private:
  uint64_t seed_;
  Point2i pixel_;
  uint32_t sample_index_;
  uint32_t dimension_ = 0;
};

// PCG32 (O'Neill 2014): 64-bit state, 32-bit output, selectable stream.
class Pcg32 {
 public:
  explicit Pcg32(uint64_t seed = 0x853c49e6748fea9bULL, uint64_t stream = 0xda3e39cb94b95bdbULL) {
    set_sequence(seed, stream);
  }
  void set_sequence(uint64_t seed, uint64_t stream) {
    state_ = 0;
    increment_ = (stream << 1u) | 1u;
    next_uint32();
    state_ += seed;
    next_uint32();
  }
  uint32_t next_uint32() {
    uint64_t old = state_;
    state_ = old * 0x5851f42d4c957f2dULL + increment_;
    uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
  }
  float next_float() { return float(next_uint32() >> 8) * 0x1p-24f; }  // in [0, 1)

 private:
  uint64_t state_ = 0, increment_ = 0;
};

}  // namespace obscura
