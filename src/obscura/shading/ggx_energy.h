// How much light the GGX microfacet lobe reflects, and the multiple-scattering lobe that puts
// back what single scattering loses (Kulla & Conty, "Revisiting Physically Based Shading at
// Imageworks", SIGGRAPH 2017 course). Shared by both renderers.
//
// A GGX lobe f = D·G / (4 μo μi) (Smith height-correlated G, no Fresnel) reflects the
// directional albedo E(μo) = ∫ f μi dωi < 1: light that a real surface would scatter between
// its microfacets more than once is lost, up to ~40 % for a rough white metal. The lobe
//   f_ms(μo, μi) = (1 − E(μo)) (1 − E(μi)) / (π (1 − E_avg)),   E_avg = 2 ∫ E(μ) μ dμ,
// is reciprocal and reflects exactly 1 − E(μo), so f + f_ms reflects everything; a coloured
// Fresnel F scales it by F_ms = F_avg² E_avg / (1 − F_avg (1 − E_avg)) (the light that survives
// the extra bounces), F_avg = 2 ∫ F(μ) μ dμ.
//
// The same integrals weighted by Schlick's (1 − v·h)⁵ give the albedo of a Fresnel-weighted
// lobe, E_F(μ) = f0·E(μ) + (1 − f0)·E₅(μ), which lets a layered material (glTF's dielectric:
// specular over diffuse) give the diffuse layer exactly the energy the specular one leaves.
//
// The tables are integrated once per process (~30 ms, on first use) by Gauss–Legendre quadrature
// over the GGX normal distribution, on a 64 × 32 grid of (μ, √α), and interpolated bilinearly.
#pragma once

#include "obscura/color/rgb.h"

namespace obscura::shading {

// E(μ): directional albedo of the GGX lobe without Fresnel, α the GGX width (roughness²).
float ggx_albedo(float mu, float alpha);
// E_avg: its cosine-weighted hemispherical average.
float ggx_average_albedo(float alpha);
// E_F(μ) and its average for Schlick's Fresnel with normal reflectance f0.
float ggx_schlick_albedo(float f0, float mu, float alpha);
float ggx_schlick_average_albedo(float f0, float alpha);

// Kulla–Conty's multiple-scattering lobe f_ms(μo, μi) for F = 1 (sr⁻¹).
float ggx_multiple_scattering(float mu_o, float mu_i, float alpha);
// Its colour for a Fresnel whose hemispherical average is f_avg: F_avg² E_avg / (1 − F_avg (1 −
// E_avg)).
Rgb multiple_scattering_color(Rgb f_avg, float alpha);
// F_avg of Schlick's Fresnel: f0 + (1 − f0) / 21.
Rgb schlick_average(Rgb f0);
// F_avg = 2 ∫ F(μ) μ dμ of any Fresnel term `fresnel(μ) → Rgb`, by 6-point Gauss–Legendre on
// (0, 1) (F is smooth in μ: the error is far below the tables' own).
template <typename Fresnel>
Rgb fresnel_average(const Fresnel& fresnel) {
  constexpr float x[6] = {0.0337652429f, 0.1693953068f, 0.3806904070f,
                          0.6193095930f, 0.8306046932f, 0.9662347571f};
  constexpr float w[6] = {0.0856622462f, 0.1803807865f, 0.2339569673f,
                          0.2339569673f, 0.1803807865f, 0.0856622462f};
  Rgb sum;
  for (int i = 0; i < 6; ++i) sum += fresnel(x[i]) * (2 * w[i] * x[i]);
  return sum;
}

}  // namespace obscura::shading
