#include "obscura/trace/trace_scene.h"

#include <algorithm>
#include <cmath>

namespace obscura {

TraceScene::TraceScene(const Scene& scene, std::shared_ptr<const EmbreeDevice> device)
    : embree_(std::move(device)), meshes_(scene.meshes) {
  scene.validate();
  for (const Mesh& mesh : meshes_) embree_.add_triangle_mesh(mesh.positions, mesh.indices);
  embree_.commit();
  for (const Material& m : scene.materials) materials_.push_back(TraceMaterial::from_scene(m));
  Bounds3f b = scene.bounds();
  if (!b.empty()) {
    float extent = std::max({std::abs(b.min.x), std::abs(b.min.y), std::abs(b.min.z),
                             std::abs(b.max.x), std::abs(b.max.y), std::abs(b.max.z)});
    ray_epsilon_ = std::max(1e-6f, 1e-5f * extent);
    radius_ = std::max(1e-3f, 0.5f * distance(b.min, b.max));
  }
  lights_ = LightSet(AreaLights(meshes_, scene.materials), std::nullopt, {}, radius_);
}

void TraceScene::set_material(uint32_t index, TraceMaterial material) {
  materials_.at(index) = std::move(material);
}

void TraceScene::set_environment(std::optional<EnvironmentLight> environment) {
  lights_ = LightSet(lights_.area_lights(), std::move(environment), lights_.punctual(), radius_);
}

void TraceScene::set_punctual_lights(std::vector<PunctualLight> lights) {
  std::optional<EnvironmentLight> environment;
  if (lights_.environment()) environment = *lights_.environment();
  lights_ = LightSet(lights_.area_lights(), std::move(environment), std::move(lights), radius_);
}

std::optional<SurfaceHit> TraceScene::intersect(const Ray& ray) const {
  std::optional<RayHit> hit = embree_.intersect(ray);
  if (!hit) return std::nullopt;
  // Everything here comes with Embree's answer: no mesh data is touched (it would be a cache
  // miss per incoherent ray on large scenes).
  SurfaceHit s;
  s.t = hit->t;
  s.position = ray.at(hit->t);
  s.geometric_normal = Normal3f(normalize(hit->normal));
  s.shading_normal = s.geometric_normal;
  s.mesh = hit->geometry_id;
  s.primitive = hit->primitive_id;
  s.material = meshes_[hit->geometry_id].material;
  return s;
}

bool TraceScene::occluded(Point3f from, Point3f to) const {
  Ray ray;
  ray.origin = from;
  ray.direction = to - from;
  ray.t_min = 0;
  ray.t_max = 1 - 1e-4f;  // stop just short of the target surface
  return embree_.occluded(ray);
}

Point3f offset_ray_origin(Point3f p, Normal3f n, Vector3f w, float epsilon) {
  Vector3f offset = to_vector(n) * epsilon;
  return dot(n, w) < 0 ? p - offset : p + offset;
}

}  // namespace obscura

namespace obscura {

Ray shadow_ray(const TraceScene& scene, const SurfaceHit& hit, const LightSample& light) {
  Ray ray;
  ray.origin = offset_ray_origin(hit.position, hit.geometric_normal, light.wi, scene.ray_epsilon());
  if (std::isinf(light.distance)) {
    ray.direction = light.wi;
    return ray;
  }
  Point3f target = light.position;
  if (light.normal != Normal3f())
    target = offset_ray_origin(target, light.normal, -light.wi, scene.ray_epsilon());
  ray.direction = target - ray.origin;
  ray.t_max = 1 - 1e-4f;
  return ray;
}

}  // namespace obscura
