// Varyings: what a vertex shader hands to the fragment shader, interpolated across a triangle.
//
// A program's Varyings type is any plain struct made only of floats (Vector3f, Rgb, float, …).
// The pipeline treats it as an array of floats to clip and interpolate it, so programs stay
// readable (`v.normal`, `v.color`) and the hot loop stays free of per-attribute dispatch.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <type_traits>

#include "obscura/math/vector.h"

// The tile loop is compiled twice on x86-64 (baseline and AVX2, chosen at run time; see
// pipeline.h). Per-pixel code must inline into each copy to be compiled for its target, and
// compilers do not inline across targets on their own: shader helper functions called per pixel
// should be declared OBSCURA_RASTER_INLINE (members defined in the class body are inlined).
#if defined(__GNUC__)
#define OBSCURA_RASTER_INLINE [[gnu::always_inline]] inline
#define OBSCURA_RASTER_OUTLINE [[gnu::noinline]]
#else
#define OBSCURA_RASTER_INLINE inline
#define OBSCURA_RASTER_OUTLINE
#endif

namespace obscura::raster {

template <class V>
concept VaryingsType = std::is_trivially_copyable_v<V> && sizeof(V) % sizeof(float) == 0 &&
                       alignof(V) == alignof(float) && sizeof(V) >= sizeof(float);

template <VaryingsType V>
inline constexpr int kVaryingFloats = int(sizeof(V) / sizeof(float));

template <VaryingsType V>
using VaryingArray = std::array<float, kVaryingFloats<V>>;

template <VaryingsType V>
VaryingArray<V> to_floats(const V& v) {
  return std::bit_cast<VaryingArray<V>>(v);
}
template <VaryingsType V>
V from_floats(const VaryingArray<V>& a) {
  return std::bit_cast<V>(a);
}

// What a vertex shader returns: the clip-space position (OpenGL conventions: visible iff
// −w ≤ x, y, z ≤ w) and the varyings.
template <VaryingsType V>
struct VertexOutput {
  Vector4f clip;
  V varyings;
};

// What a fragment shader knows besides its varyings.
struct FragmentInfo {
  int x = 0, y = 0;        // pixel
  uint32_t primitive = 0;  // index of the triangle in its draw call
  bool front_facing = true;
};

}  // namespace obscura::raster
