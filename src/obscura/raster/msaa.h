// Multisample anti-aliasing: where in a pixel the coverage and depth samples lie.
//
// The standard Direct3D 10.1+ patterns (rotated grids, in 1/16 pixel from the pixel centre),
// which every desktop GPU uses; 1 sample is the pixel centre itself.
#pragma once

#include <span>

#include "obscura/math/vector.h"

namespace obscura::raster {

inline bool is_valid_sample_count(int samples) {
  return samples == 1 || samples == 4 || samples == 8;
}

// Offsets from the pixel centre in 1/256 pixel (the rasterizer's fixed-point unit).
// Precondition: is_valid_sample_count(samples).
inline std::span<const Vector2i> msaa_sample_offsets(int samples) {
  static constexpr Vector2i kOne[] = {{0, 0}};
  static constexpr Vector2i kFour[] = {
      {-2 * 16, -6 * 16}, {6 * 16, -2 * 16}, {-6 * 16, 2 * 16}, {2 * 16, 6 * 16}};
  static constexpr Vector2i kEight[] = {{1 * 16, -3 * 16},  {-1 * 16, 3 * 16}, {5 * 16, 1 * 16},
                                        {-3 * 16, -5 * 16}, {-5 * 16, 5 * 16}, {-7 * 16, -1 * 16},
                                        {3 * 16, 7 * 16},   {7 * 16, -7 * 16}};
  if (samples == 8) return kEight;
  if (samples == 4) return kFour;
  return kOne;
}

}  // namespace obscura::raster
