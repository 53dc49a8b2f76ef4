// The "Charlie" sheen lobe of KHR_materials_sheen (Estevez & Kulla, "Production Friendly
// Microfacet Sheen BRDF", SIGGRAPH 2017), and its directional albedo. Shared by both renderers.
//
// Fibres standing up from a cloth reflect light mostly at grazing angles. With α = roughness²
// (floored at kMinSheenAlpha) and h the half vector,
//   D(h) = (2 + 1/α) sin(θh)^(1/α) / 2π,
//   f    = D(h) / ((1 + Λ(μo) + Λ(μi)) · 4 μo μi),
// where Λ is Estevez & Kulla's fit of their masking term (the coefficients their paper
// publishes, the ones the glTF specification repeats). f carries no Fresnel, as the extension
// allows; the sheen colour multiplies it.
//
// The layering under glTF's albedo scaling needs E(μ) = ∫ f μi dωi, the light the lobe
// reflects when seen from μ. It is integrated here once per process (on first use, ~20 ms) by
// Gauss–Legendre quadrature over the incoming hemisphere, on a 32 × 32 grid of (μ, roughness),
// and interpolated bilinearly; tests/shading/charlie_sheen_test.cpp checks it against a Monte
// Carlo integral of the same lobe.
#pragma once

namespace obscura::shading {

// Below this width the fibres reflect only at grazing angles so narrow that float precision of
// D fails; roughness 0 (glTF's default) shades as this.
inline constexpr float kMinSheenAlpha = 1e-3f;
float sheen_alpha(float roughness);

// D(h) for cos θh = cos_h (sr⁻¹); ∫ D cos θh dωh = 1.
float charlie_distribution(float cos_h, float alpha);
// Estevez & Kulla's Λ(μ).
float charlie_lambda(float mu, float alpha);
// The lobe f(μo, μi, cos θh) (sr⁻¹), zero below the surface.
float charlie_sheen(float mu_o, float mu_i, float cos_h, float alpha);
// E(μ) = ∫ f μi dωi, from the table.
float sheen_albedo(float mu, float alpha);

// The fitted Λ is poor at low roughness: there the lobe reflects more than arrives at grazing
// angles (E(0.05) ≈ 1.04 at roughness 0.1, E(0.01) ≈ 4 at roughness 0). Both renderers scale
// the lobe by this factor, min(1, 1/E(μo), 1/E(μi)): reciprocal, exactly 1 wherever E ≤ 1, and
// it keeps the lobe's albedo ≤ 1 everywhere. e_o, e_i: sheen_albedo at μo and μi.
inline float sheen_energy_bound(float e_o, float e_i) {
  float e = e_o > e_i ? e_o : e_i;
  return e > 1 ? 1 / e : 1.f;
}

}  // namespace obscura::shading
