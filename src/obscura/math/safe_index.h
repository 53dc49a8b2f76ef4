// Table and texel indices from floats that may be NaN or huge.
//
// std::clamp, std::min and std::max pass a NaN through (every comparison with it is false), and
// converting a NaN or an out-of-range float to int is undefined behaviour: in practice INT_MIN,
// an index far outside the table. A NaN roughness from a texture, or a NaN direction from a light
// placed at 1e308, reached the shading tables that way. These helpers decide NaN explicitly (it
// goes to the low end), so a lookup built on them stays inside its table for every input.
#pragma once

#include <cmath>

namespace obscura {

// x clamped to [lo, hi]; NaN gives lo.
inline float clamp_or_low(float x, float lo, float hi) {
  return x >= lo ? (x <= hi ? x : hi) : lo;
}
inline double clamp_or_low(double x, double lo, double hi) {
  return x >= lo ? (x <= hi ? x : hi) : lo;
}

// The cell of x on a grid of `cells` unit cells starting at 0: int(x) clamped to
// [0, cells − 1]; NaN and −∞ give 0, +∞ gives cells − 1.
inline int cell_index(float x, int cells) {
  float c = clamp_or_low(x, 0.f, float(cells - 1));
  return int(c);
}

// floor(x) as an int, for texel coordinates that wrap afterwards: NaN gives 0, and values beyond
// ±2^30 (far past any texture's size, where a float has no fraction left) are clamped there, so
// that neighbours (index + 1) and wrapping arithmetic cannot overflow.
inline int floor_to_index(float x) {
  constexpr float kLimit = 1 << 30;
  if (std::isnan(x)) return 0;
  return int(clamp_or_low(std::floor(x), -kLimit, kLimit));
}

}  // namespace obscura
