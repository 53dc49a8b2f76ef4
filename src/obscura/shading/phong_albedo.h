// How much light the normalized Phong and Blinn-Phong lobes reflect (shading/phong_lobe.h), for
// image-based lighting: the directional albedo
//   E(μ) = ∫ k · c(n) · lobeⁿ(wo, wi) · μi dωi   over the hemisphere, per unit k_s,
// with μ = n·wo. c(n) makes E(1) = 1, but away from normal incidence the lobe follows the mirror
// direction, whose cosine is μ: a narrow Phong lobe reflects E(μ) → μ, a Blinn-Phong lobe about
// μ² · (its normal-incidence value), and the horizon cuts both further near grazing. The tracer
// integrates this by sampling its BSDF; a surround of uniform radiance L reflects k_s·E(μ)·L.
//
// The table is integrated once per process (on first use, a few milliseconds) in lobe-centred
// coordinates (cos α = u^(1/(n+1)) makes lobeⁿ sin α dα = du/(n+1), so what is left is smooth),
// on a 32 × 33 grid of (μ, n/(n+8)), and interpolated bilinearly; exponents past the grid's last
// (n ≈ 10⁴) read its last row.
#pragma once

namespace obscura::shading {

// E(μ) of the lobe with exponent n ≥ 0: Phong's reflection lobe, or Blinn's half-vector lobe.
float phong_lobe_albedo(float mu, float exponent, bool blinn);

}  // namespace obscura::shading
