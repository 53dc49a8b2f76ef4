// The tracer's flat form of a Scene: Embree geometry, per-triangle data for shading, materials
// and the emitters. Compiled once from the authoring Scene; read-only (and thread-safe) after.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "obscura/scene/scene.h"
#include "obscura/trace/area_lights.h"
#include "obscura/trace/embree_scene.h"

namespace obscura {

struct SurfaceHit {
  Point3f position;
  Normal3f geometric_normal;  // unit, on the front side of the triangle's winding
  uint32_t material = 0;
  float t = 0;
};

// What the direct-lighting integrator shades with: a Lambertian albedo and emitted radiance.
struct TraceMaterial {
  Rgb diffuse;
  Rgb emission;
};

class TraceScene {
 public:
  TraceScene(const Scene& scene, std::shared_ptr<const EmbreeDevice> device);

  std::optional<SurfaceHit> intersect(const Ray& ray) const;
  // Whether the open segment between two points is blocked.
  bool occluded(Point3f from, Point3f to) const;

  const TraceMaterial& material(uint32_t index) const { return materials_[index]; }
  const AreaLights& lights() const { return lights_; }
  // Distance by which ray origins leave a surface, scaled to the scene's extent.
  float ray_epsilon() const { return ray_epsilon_; }

 private:
  EmbreeScene embree_;
  std::vector<Mesh> meshes_;  // one per instance, flattened to world space (positions only)
  std::vector<TraceMaterial> materials_;
  AreaLights lights_;
  float ray_epsilon_ = 1e-4f;
};

// Points a ray's origin off a surface along its normal, to the side the ray leaves towards.
Point3f offset_ray_origin(Point3f p, Normal3f n, Vector3f w, float epsilon);

}  // namespace obscura
