// Energy-conserving Phong and Blinn-Phong: f = k_d/π + k_s·c(n)·lobeⁿ, with lobe = max(0, R·V)
// (Phong, 1975) or max(0, N·H) (Blinn, 1977). The normalizations and the k_d + k_s ≤ 1 rule
// both renderers use (trace/phong_bsdf, raster/phong.h and raster/surface_material).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include "obscura/color/rgb.h"
#include "obscura/shading/inline.h"

namespace obscura::shading {

// c(n) makes a white lobe reflect exactly all light arriving along the normal: (n+2)/2π for the
// reflection lobe (Lafortune & Willems 1994), (n+2)(n+4)/(8π(2^(−n/2)+n)) for the half-vector
// lobe (its exact normal-incidence integral).
OBSCURA_SHADING_INLINE float phong_lobe_normalization(float n) {
  return (n + 2) * (0.5f * std::numbers::inv_pi_v<float>);
}
OBSCURA_SHADING_INLINE float blinn_phong_lobe_normalization(float n) {
  return (n + 2) * (n + 4) / (8 * std::numbers::pi_v<float> * (std::exp2(-0.5f * n) + n));
}

// Where k_d + k_s exceeds 1 in a channel, both are scaled down by the largest sum, so the
// surface never reflects more than it receives.
OBSCURA_SHADING_INLINE void conserve_energy(Rgb& diffuse, Rgb& specular) {
  float total = std::max({diffuse.r + specular.r, diffuse.g + specular.g, diffuse.b + specular.b});
  if (total > 1) {
    float s = 1 / total;
    diffuse = diffuse * s, specular = specular * s;
  }
}

}  // namespace obscura::shading
