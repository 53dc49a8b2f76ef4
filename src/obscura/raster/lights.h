// The lights the rasterizer's shaders understand: directional, point and spot, plus an ambient
// term. Radiometry follows glTF's KHR_lights_punctual: a directional light gives irradiance
// `radiance` on a surface facing it; point and spot lights have intensity falling off as 1/d².
#pragma once

#include <cmath>
#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/math/vector.h"
#include "obscura/raster/varyings.h"

namespace obscura::raster {

struct DirectionalLight {
  Vector3f to_light{0, 1, 0};  // unit vector from the surface toward the light
  Rgb radiance{1, 1, 1};
};

struct PointLight {
  Point3f position;
  Rgb intensity{1, 1, 1};
};

struct SpotLight {
  Point3f position;
  Vector3f direction{0, -1, 0};  // unit vector the spot points along
  Rgb intensity{1, 1, 1};
  float cos_inner = 0.9f, cos_outer = 0.8f;  // full strength inside inner, none outside outer
};

struct LightSet {
  Rgb ambient;  // multiplies the material's ambient colour
  std::vector<DirectionalLight> directional;
  std::vector<PointLight> point;
  std::vector<SpotLight> spot;
};

// The light arriving at p from one light: unit direction toward it and the scale of its colour.
struct IncidentLight {
  Vector3f to_light;
  Rgb strength;
};

OBSCURA_RASTER_INLINE IncidentLight incident(const DirectionalLight& light, Point3f) {
  return {light.to_light, light.radiance};
}
OBSCURA_RASTER_INLINE IncidentLight incident(const PointLight& light, Point3f p) {
  Vector3f d = light.position - p;
  float d2 = std::max(dot(d, d), 1e-12f);
  return {d / std::sqrt(d2), light.intensity / d2};
}
OBSCURA_RASTER_INLINE IncidentLight incident(const SpotLight& light, Point3f p) {
  Vector3f d = light.position - p;
  float d2 = std::max(dot(d, d), 1e-12f);
  Vector3f l = d / std::sqrt(d2);
  float cos_angle = -dot(l, light.direction);
  // glTF's smooth cone falloff, squared as in its reference implementation.
  float t = std::clamp(
      (cos_angle - light.cos_outer) / std::max(light.cos_inner - light.cos_outer, 1e-6f), 0.f, 1.f);
  return {l, light.intensity * (t * t / d2)};
}

}  // namespace obscura::raster
