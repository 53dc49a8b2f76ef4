// The GGX (Trowbridge–Reitz) microfacet distribution, isotropic, with Smith's height-correlated
// masking-shadowing: the formulas the tracer's BSDFs (trace/ggx, metallic_roughness_bsdf, …) and
// the rasterizer's per-pixel BRDFs (raster/surface_material.h) both evaluate.
//
// Arguments are cosines against the macro-surface normal; α is the GGX width (α = roughness²).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include "obscura/shading/inline.h"

namespace obscura::shading {

// Microfacet normal density D(m) (sr⁻¹) for a normal at cos θm from the macro normal:
// ∫ D(m) cos θm dωm = 1. Zero for normals below the surface.
OBSCURA_SHADING_INLINE float ggx_d(float cos_theta_m, float alpha) {
  if (cos_theta_m <= 0) return 0;
  float a2 = alpha * alpha;
  float t = cos_theta_m * cos_theta_m * (a2 - 1) + 1;
  return a2 / (std::numbers::pi_v<float> * t * t);
}

// Smith's auxiliary Λ for a direction with cos² θ = cos2_theta; G1 = 1 / (1 + Λ). A grazing
// direction is fully masked.
OBSCURA_SHADING_INLINE float ggx_lambda(float cos2_theta, float alpha) {
  if (cos2_theta <= 0) return 1e30f;
  float sin2_theta = std::max(0.f, 1 - cos2_theta);
  float a2_tan2 = alpha * alpha * sin2_theta / cos2_theta;
  return 0.5f * (std::sqrt(1 + a2_tan2) - 1);
}

// Height-correlated masking-shadowing of a pair of directions from their Λ.
OBSCURA_SHADING_INLINE float ggx_g(float lambda_o, float lambda_i) {
  return 1 / (1 + lambda_o + lambda_i);
}

// The single-scattering microfacet lobe D·G / (4 cos θo cos θi) (sr⁻¹), without Fresnel, for
// directions on the normal's side (cos θo, cos θi > 0) and the half vector at cos θh.
OBSCURA_SHADING_INLINE float ggx_specular(float cos_theta_o, float cos_theta_i, float cos_theta_h,
                                          float alpha) {
  float g = ggx_g(ggx_lambda(cos_theta_o * cos_theta_o, alpha),
                  ggx_lambda(cos_theta_i * cos_theta_i, alpha));
  return ggx_d(cos_theta_h, alpha) * g / (4 * cos_theta_o * cos_theta_i);
}

}  // namespace obscura::shading
