// The lights the rasterizer's formulas shade with, which REYES shares: directional, point, spot
// and surface lights (area lights seen as points), plus an ambient term. Radiometry follows
// glTF's KHR_lights_punctual: a directional light gives irradiance `radiance` on a surface facing
// it; point and spot lights have intensity falling off as 1/d². Moved down from raster/ with
// their compilation from a scene (the rasterizer adds image-based lighting, raster/lights.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/math/transform.h"
#include "obscura/math/vector.h"
#include "obscura/scene/mesh.h"
#include "obscura/scene/scene.h"
#include "obscura/shading/inline.h"

namespace obscura::shading {

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

// An emitting surface seen as one point: a flat Lambertian emitter of radiance L and area A has
// intensity L·A·cos θ about its normal (`one_sided`), a convex closed one about L·A/4 in every
// direction (its mean projected area is A/4). The rasterizer approximates area lights (emissive
// meshes) this way: exact in the far field, without the soft shadows of a real area light. Near
// the emitter, d² becomes d² + r² (one-sided; r² = A/π: the exact on-axis irradiance of a disk
// of that area) or max(d², r²) (a sphere of radius r, exact outside it).
struct SurfaceLight {
  Point3f position;
  Vector3f normal{0, -1, 0};  // unit, the emitting side (one_sided only)
  Rgb intensity{1, 1, 1};     // W/sr along the normal (one-sided) or in every direction
  float radius2 = 0;          // r² (m²)
  bool one_sided = true;
};

// The scene's lights, compiled: `ambient` multiplies the material's ambient colour (a uniform
// surround: the environment's mean radiance).
struct PunctualLights {
  Rgb ambient;
  std::vector<DirectionalLight> directional;
  std::vector<PointLight> point;
  std::vector<SpotLight> spot;
  std::vector<SurfaceLight> surface;
};

// The scene's point, spot and directional lights, appended.
void add_scene_lights(const Scene& scene, PunctualLights& lights);
// An emissive instance as one SurfaceLight (at its time-0 pose): at the area-weighted centroid;
// flat emitters (all faces within ~2.5° of one normal) emit a cosine lobe, others uniformly.
// Nothing for a mesh without area.
std::optional<SurfaceLight> surface_light(const Mesh& mesh, const Transform& world_from_object,
                                          Rgb radiance);

OBSCURA_SHADING_INLINE float positive_cosine(float c) {
  return c > 0.f ? c : 0.f;
}

// The light arriving at p from one light: unit direction toward it and the scale of its colour.
struct IncidentLight {
  Vector3f to_light;
  Rgb strength;
};

OBSCURA_SHADING_INLINE IncidentLight incident(const DirectionalLight& light, Point3f) {
  return {light.to_light, light.radiance};
}
OBSCURA_SHADING_INLINE IncidentLight incident(const PointLight& light, Point3f p) {
  Vector3f d = light.position - p;
  float d2 = std::max(dot(d, d), 1e-12f);
  return {d / std::sqrt(d2), light.intensity / d2};
}
OBSCURA_SHADING_INLINE IncidentLight incident(const SpotLight& light, Point3f p) {
  Vector3f d = light.position - p;
  float d2 = std::max(dot(d, d), 1e-12f);
  Vector3f l = d / std::sqrt(d2);
  float cos_angle = -dot(l, light.direction);
  // glTF's smooth cone falloff, squared as in its reference implementation.
  // (The 10⁻³ floor on the cone width is the tracer's, so both agree on hard-edged spots.)
  float t = std::clamp(
      (cos_angle - light.cos_outer) / std::max(light.cos_inner - light.cos_outer, 1e-3f), 0.f, 1.f);
  return {l, light.intensity * (t * t / d2)};
}
OBSCURA_SHADING_INLINE IncidentLight incident(const SurfaceLight& light, Point3f p) {
  Vector3f d = light.position - p;
  float d2 = std::max(dot(d, d), 1e-12f);
  Vector3f l = d / std::sqrt(d2);
  if (!light.one_sided) return {l, light.intensity / std::max(d2, light.radius2)};
  return {l, light.intensity * (positive_cosine(-dot(l, light.normal)) / (d2 + light.radius2))};
}

}  // namespace obscura::shading
