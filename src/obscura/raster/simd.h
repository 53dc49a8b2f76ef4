// Eight-lane vectors for the pixel loop: one row of an 8×8 block per vector.
//
// GCC/Clang vector extensions rather than intrinsics: the same source compiles to one AVX2
// register per vector in the tile loop's AVX2 copy and to SSE pairs in the baseline copy (see
// pipeline.h), and arithmetic reads as arithmetic. Comparisons give lane masks (all bits set or
// clear) of type Mask8.
#pragma once

#include <cstdint>
#include <cstring>
#include <type_traits>

#include "obscura/raster/varyings.h"

namespace obscura::raster::simd {

using Float8 = float __attribute__((vector_size(32)));
using Int8 = int32_t __attribute__((vector_size(32)));
using Mask8 = Int8;
using Float4 = float __attribute__((vector_size(16)));
using Int4 = int32_t __attribute__((vector_size(16)));

inline constexpr Int8 kLaneIndex = {0, 1, 2, 3, 4, 5, 6, 7};
inline constexpr Float8 kLaneOffset = {0, 1, 2, 3, 4, 5, 6, 7};

OBSCURA_RASTER_INLINE Float8 splat(float x) {
  return Float8{x, x, x, x, x, x, x, x};
}
OBSCURA_RASTER_INLINE Int8 splat(int32_t x) {
  return Int8{x, x, x, x, x, x, x, x};
}

OBSCURA_RASTER_INLINE Float8 load(const float* p) {
  Float8 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
OBSCURA_RASTER_INLINE void store(float* p, Float8 v) {
  std::memcpy(p, &v, sizeof v);
}

// The instruction set a copy of the pixel loop is compiled for (see pipeline.h): a tag type, so
// that helpers can use target-specific builtins in the copy compiled for that target.
struct Baseline {};
struct Avx2 {};

// One bit per lane, lane 0 in bit 0. The AVX2 copy uses vmovmskps, through inline assembly:
// a builtin would need the target attribute on every inlined caller, while assembly only needs
// the copy it lands in to be compiled for AVX (compilers do not turn the portable form into it).
template <class Isa>
OBSCURA_RASTER_INLINE uint32_t bits(Mask8 m) {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
  // (Clang checks the operand against the baseline target and refuses it; its builds, used for
  // the sanitizers and fuzzing, take the portable form below.)
  if constexpr (std::is_same_v<Isa, Avx2>) {
    uint32_t b;
    asm("vmovmskps %1, %0" : "=r"(b) : "x"(m));
    return b;
  }
#endif
  // An OR reduction, written so that it stays in vector registers.
  const Int8 w = m & Int8{1, 2, 4, 8, 16, 32, 64, 128};
  Int4 lo, hi;
  std::memcpy(&lo, &w, sizeof lo);
  std::memcpy(&hi, reinterpret_cast<const char*>(&w) + sizeof lo, sizeof hi);
  Int4 s = lo | hi;
#if defined(__clang__)
  s |= __builtin_shufflevector(s, s, 2, 3, 0, 1);
  s |= __builtin_shufflevector(s, s, 1, 0, 3, 2);
#else
  s |= __builtin_shuffle(s, Int4{2, 3, 0, 1});
  s |= __builtin_shuffle(s, Int4{1, 0, 3, 2});
#endif
  return uint32_t(s[0]);
}

OBSCURA_RASTER_INLINE Float8 select(Mask8 m, Float8 a, Float8 b) {
  return m ? a : b;
}

// Clamps to [0, 1], NaN to 0 (as clamp_unit does per lane).
OBSCURA_RASTER_INLINE Float8 clamp_unit(Float8 x) {
  Float8 one = splat(1.f), zero = Float8{};
  return x > zero ? (x < one ? x : one) : zero;
}

}  // namespace obscura::raster::simd
