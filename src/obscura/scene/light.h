// Lights that are not geometry. (Area lights are emissive surfaces: see Material::emission.)
// Positions and directions are in world space; intensities follow KHR_lights_punctual's units.
#pragma once

#include <numbers>
#include <string>
#include <variant>

#include "obscura/color/rgb.h"
#include "obscura/math/transform.h"
#include "obscura/math/vector.h"

namespace obscura {

// Emits equally in all directions.
struct PointLight {
  Point3f position;
  Rgb intensity{1.f};  // radiant intensity, W/sr
};

// A point light restricted to a cone, with a smooth falloff between the two angles.
struct SpotLight {
  Point3f position;
  Vector3f direction{0, 0, -1};  // unit, where the cone points
  Rgb intensity{1.f};            // W/sr on the axis
  float inner_cone_radians = 0;  // full intensity inside, 0 ≤ inner < outer
  float outer_cone_radians = std::numbers::pi_v<float> / 4;  // none outside, ≤ π/2
};

// Parallel light from infinitely far away (the sun).
struct DirectionalLight {
  Vector3f direction{0, -1, 0};  // unit, the direction light travels
  Rgb irradiance{1.f};           // W/m² on a surface facing the light
};

using LightModel = std::variant<PointLight, SpotLight, DirectionalLight>;

struct Light {
  std::string name;
  LightModel model;
};

// Light arriving from infinitely far away in every direction: an equirectangular (lat-long)
// radiance image, or a constant colour when it has none.
struct Environment {
  int32_t texture = -1;  // index into Scene::textures (linear radiance), or −1
  Rgb color{1.f};        // multiplies the texture; the radiance itself when there is none
  float intensity = 1;   // overall scale
  // Orients the map: the image's centre column looks along world_from_environment(−Z), its top
  // row along +Y.
  Transform world_from_environment;
};

}  // namespace obscura
