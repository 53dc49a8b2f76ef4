// Reflectance models the rasterizer shades scenes with: the same BRDFs the tracer evaluates
// (trace/phong_bsdf, metallic_roughness_bsdf, conductor_bsdf, ggx, fresnel), written again here
// because raster/ and trace/ never include each other. tests/raster/scene_agreement_test.cpp
// checks that both renderers give the same direct light.
//
// All directions are world-space unit vectors: n the shading normal, v towards the eye, l towards
// the light. Values are BRDFs (sr⁻¹); the caller multiplies by cos θ_l and the light's irradiance.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "obscura/color/rgb.h"
#include "obscura/math/vector.h"
#include "obscura/raster/varyings.h"

namespace obscura::raster {

inline constexpr float kBrdfPi = std::numbers::pi_v<float>;
inline constexpr float kBrdfInvPi = std::numbers::inv_pi_v<float>;

// --- Phong and Blinn-Phong, energy-conserving: f = k_d/π + k_s·c(n)·lobeⁿ -------------------
// c(n) makes a white lobe reflect exactly all light arriving along the normal: (n+2)/2π for the
// reflection lobe (Lafortune & Willems 1994), (n+2)(n+4)/(8π(2^(−n/2)+n)) for the half-vector
// lobe (its exact normal-incidence integral).
OBSCURA_RASTER_INLINE float phong_lobe_normalization(float n) {
  return (n + 2) * (0.5f * kBrdfInvPi);
}
OBSCURA_RASTER_INLINE float blinn_phong_lobe_normalization(float n) {
  return (n + 2) * (n + 4) / (8 * kBrdfPi * (std::exp2(-0.5f * n) + n));
}

// Where k_d + k_s exceeds 1 in a channel, both are scaled down by the largest sum, so the
// surface never reflects more than it receives (the tracer's PhongBsdf does the same).
OBSCURA_RASTER_INLINE void conserve_energy(Rgb& diffuse, Rgb& specular) {
  float total = std::max({diffuse.r + specular.r, diffuse.g + specular.g, diffuse.b + specular.b});
  if (total > 1) {
    float s = 1 / total;
    diffuse = diffuse * s, specular = specular * s;
  }
}

// --- GGX (Trowbridge–Reitz) with Smith's height-correlated masking-shadowing -----------------
// D(h) with ∫D cos θ_h dω = 1; α is the GGX width (α = roughness²).
OBSCURA_RASTER_INLINE float ggx_d(float n_dot_h, float alpha) {
  if (n_dot_h <= 0) return 0;
  float a2 = alpha * alpha;
  float t = n_dot_h * n_dot_h * (a2 - 1) + 1;
  return a2 / (kBrdfPi * t * t);
}
// Smith's Λ for a direction at cos θ = c from the normal.
OBSCURA_RASTER_INLINE float ggx_lambda(float c, float alpha) {
  float c2 = c * c;
  if (c2 <= 0) return 1e30f;
  float tan2 = std::max(0.f, 1 - c2) / c2;
  return 0.5f * (std::sqrt(1 + alpha * alpha * tan2) - 1);
}
// The specular microfacet lobe D·G/(4 cos θ_v cos θ_l), without Fresnel.
OBSCURA_RASTER_INLINE float ggx_specular(float n_dot_v, float n_dot_l, float n_dot_h, float alpha) {
  float g = 1 / (1 + ggx_lambda(n_dot_v, alpha) + ggx_lambda(n_dot_l, alpha));
  return ggx_d(n_dot_h, alpha) * g / (4 * n_dot_v * n_dot_l);
}

// --- Fresnel --------------------------------------------------------------------------------
OBSCURA_RASTER_INLINE float schlick(float f0, float cos_theta) {
  float m = std::clamp(1 - std::abs(cos_theta), 0.f, 1.f);
  float m2 = m * m;
  return f0 + (1 - f0) * (m2 * m2 * m);
}
OBSCURA_RASTER_INLINE Rgb schlick(Rgb f0, float cos_theta) {
  return {schlick(f0.r, cos_theta), schlick(f0.g, cos_theta), schlick(f0.b, cos_theta)};
}
// Reflectance of a dielectric of relative index eta, light arriving from outside.
OBSCURA_RASTER_INLINE float fresnel_dielectric_reflectance(float cos_i, float eta) {
  cos_i = std::clamp(cos_i, 0.f, 1.f);
  float sin2_t = (1 - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1) return 1;
  float cos_t = std::sqrt(1 - sin2_t);
  float rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  float rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return 0.5f * (rp * rp + rs * rs);
}
// Reflectance of a conductor of complex index η + ik, from a medium of index 1.
inline float fresnel_conductor_reflectance(float cos_i, float eta, float k) {
  using Complex = std::complex<float>;
  cos_i = std::clamp(cos_i, 0.f, 1.f);
  Complex n(eta, k);
  Complex cos_t = std::sqrt(Complex(1) - (1 - cos_i * cos_i) / (n * n));
  Complex rp = (n * cos_i - cos_t) / (n * cos_i + cos_t);
  Complex rs = (cos_i - n * cos_t) / (cos_i + n * cos_t);
  return 0.5f * (std::norm(rp) + std::norm(rs));
}
inline Rgb fresnel_conductor_reflectance(float cos_i, Rgb eta, Rgb k) {
  return {fresnel_conductor_reflectance(cos_i, eta.r, k.r),
          fresnel_conductor_reflectance(cos_i, eta.g, k.g),
          fresnel_conductor_reflectance(cos_i, eta.b, k.b)};
}

}  // namespace obscura::raster
