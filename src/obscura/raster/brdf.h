// Reflectance models the rasterizer shades scenes with. The formulas (GGX, Fresnel, the
// normalized Phong lobes) live in shading/ and are the very ones the tracer's BSDFs evaluate;
// tests/raster/scene_agreement_test.cpp checks that both renderers give the same direct light.
//
// All directions are world-space unit vectors: n the shading normal, v towards the eye, l towards
// the light. Values are BRDFs (sr⁻¹); the caller multiplies by cos θ_l and the light's irradiance.
#pragma once

#include <numbers>

#include "obscura/shading/fresnel.h"
#include "obscura/shading/ggx.h"
#include "obscura/shading/phong_lobe.h"

namespace obscura::raster {

inline constexpr float kBrdfPi = std::numbers::pi_v<float>;
inline constexpr float kBrdfInvPi = std::numbers::inv_pi_v<float>;

}  // namespace obscura::raster
