// The lights the rasterizer's shaders understand: the scene's lights as REYES shades with them
// too (shading/punctual_lights.h), plus the environment as image-based lighting.
#pragma once

#include "obscura/raster/varyings.h"
#include "obscura/shading/punctual_lights.h"

namespace obscura::raster {

// The light types and their incident light are shared with REYES (shading/punctual_lights.h).
using shading::DirectionalLight;
using shading::incident;
using shading::IncidentLight;
using shading::PointLight;
using shading::positive_cosine;
using shading::SpotLight;
using shading::SurfaceLight;

class EnvironmentLighting;  // environment_lighting.h

struct LightSet : shading::PunctualLights {
  // The environment as image-based lighting (null: `ambient` from every direction).
  const EnvironmentLighting* environment = nullptr;
};

}  // namespace obscura::raster
