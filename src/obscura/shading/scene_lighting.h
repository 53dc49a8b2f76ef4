// What a scene's emitters and environment give the shading that both the rasterizer and REYES
// do: every emissive instance as a surface light, and the environment's mean radiance as the
// uniform surround (`PunctualLights::ambient`).
#pragma once

#include "obscura/color/rgb.h"
#include "obscura/scene/scene.h"
#include "obscura/shading/punctual_lights.h"

namespace obscura::shading {

// Every emissive instance of the scene as a SurfaceLight (punctual_lights.h), appended in
// instance order.
void add_emissive_surface_lights(const Scene& scene, PunctualLights& lights);

// The scene environment's mean radiance over the sphere (a map's texels weighted by the solid
// angle of their row, ∝ sin θ, times its colour and intensity). Black without an environment.
Rgb environment_mean_radiance(const Scene& scene);

}  // namespace obscura::shading
