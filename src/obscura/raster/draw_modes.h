// The modes a draw call is set to: depth comparison, face culling, front-face winding and
// blending (the values DrawState in pipeline.h holds, and their parsers).
#pragma once

#include <cstdint>
#include <string>

namespace obscura::raster {

// The OpenGL comparison functions: a fragment passes when `fragment <op> stored` holds.
enum class DepthFunc {
  kNever,
  kLess,
  kEqual,
  kLessEqual,
  kGreater,
  kNotEqual,
  kGreaterEqual,
  kAlways
};

template <DepthFunc F>
inline bool depth_passes(float fragment, float stored) {
  if constexpr (F == DepthFunc::kNever) return false;
  if constexpr (F == DepthFunc::kLess) return fragment < stored;
  if constexpr (F == DepthFunc::kEqual) return fragment == stored;
  if constexpr (F == DepthFunc::kLessEqual) return fragment <= stored;
  if constexpr (F == DepthFunc::kGreater) return fragment > stored;
  if constexpr (F == DepthFunc::kNotEqual) return fragment != stored;
  if constexpr (F == DepthFunc::kGreaterEqual) return fragment >= stored;
  if constexpr (F == DepthFunc::kAlways) return true;
}

// "LESS", "LEQUAL", … (the OpenGL names without GL_); throws obscura::Error on anything else.
DepthFunc parse_depth_func(const std::string& name);

enum class CullMode { kNone, kBack, kFront };
// "none", "back", "front"; throws obscura::Error on anything else.
CullMode parse_cull_mode(const std::string& name);

// Which winding is the front face, seen in OpenGL's y-up NDC (OpenGL's default: CCW).
enum class FrontFace { kCounterClockwise, kClockwise };

enum class BlendMode {
  kReplace,  // the fragment's colour replaces the stored one
  kAdd,      // added to it (accumulation, overdraw counts)
  kOver,     // "over": colour·α + stored·(1 − α), α the program's coverage (1 without one)
};

}  // namespace obscura::raster
