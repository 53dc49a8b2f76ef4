// The tracer's flat form of a Scene: Embree geometry, per-triangle data for shading, materials
// and the emitters. Compiled once from the authoring Scene; read-only (and thread-safe) after.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "obscura/scene/scene.h"
#include "obscura/trace/embree_scene.h"
#include "obscura/trace/light_set.h"
#include "obscura/trace/surface_hit.h"
#include "obscura/trace/trace_material.h"

namespace obscura {

class TraceScene {
 public:
  TraceScene(const Scene& scene, std::shared_ptr<const EmbreeDevice> device);

  std::optional<SurfaceHit> intersect(const Ray& ray) const;
  // Whether the open segment between two points is blocked.
  bool occluded(Point3f from, Point3f to) const;
  // Whether anything lies along the ray within [t_min, t_max].
  bool occluded(const Ray& ray) const { return embree_.occluded(ray); }

  const TraceMaterial& material(uint32_t index) const { return materials_[index]; }
  const AreaLights& lights() const { return lights_.area_lights(); }
  const LightSet& light_set() const { return lights_; }
  // Distance by which ray origins leave a surface, scaled to the scene's extent.
  float ray_epsilon() const { return ray_epsilon_; }
  float radius() const { return radius_; }  // of a sphere around the scene (m)

  // Replace a material or the environment after compilation (tests, tools), before rendering.
  void set_material(uint32_t index, TraceMaterial material);
  void set_environment(std::optional<EnvironmentLight> environment);
  void set_punctual_lights(std::vector<PunctualLight> lights);

 private:
  EmbreeScene embree_;
  std::vector<Mesh> meshes_;  // one per instance, flattened to world space
  std::vector<Texture> textures_;  // what the materials sample
  std::vector<TraceMaterial> materials_;
  LightSet lights_;
  float ray_epsilon_ = 1e-4f;
  float radius_ = 1;
};

// Points a ray's origin off a surface along its normal, to the side the ray leaves towards.
Point3f offset_ray_origin(Point3f p, Normal3f n, Vector3f w, float epsilon);

// A ray leaving `hit` in direction `w`, its origin moved off the surface to the side it leaves to.
Ray spawn_ray(const TraceScene& scene, const SurfaceHit& hit, Vector3f w);

// The shadow ray from a hit towards a light sample: it leaves the surface on wi's side and stops
// just in front of the light's surface (offset along the light's normal, so grazing rays to
// large lights are not blocked by the light itself), or runs to infinity for distant lights.
Ray shadow_ray(const TraceScene& scene, const SurfaceHit& hit, const LightSample& light);

}  // namespace obscura
