#include "obscura/trace/trace_scene.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace obscura {

namespace {

// The Lambertian part of each material model, for the direct-lighting integrator until full
// BSDFs arrive: metals, glass and pure emitters reflect no diffuse light.
Rgb diffuse_albedo(const MaterialModel& model) {
  if (auto* d = std::get_if<DiffuseMaterial>(&model)) return d->reflectance;
  if (auto* p = std::get_if<PhongMaterial>(&model)) return p->diffuse;
  if (auto* m = std::get_if<MetallicRoughnessMaterial>(&model))
    return m->base_color * (1 - m->metallic);
  return {};
}

// Instances flattened into world-space copies of their meshes (positions and indices only):
// Embree instancing comes with the path tracer.
std::vector<Mesh> flatten_instances(const Scene& scene) {
  std::vector<Mesh> flat;
  flat.reserve(scene.instances.size());
  for (const Instance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes[instance.mesh];
    Mesh& world = flat.emplace_back();
    world.name = instance.name;
    world.material = scene.material_of(instance);
    world.indices = mesh.indices;
    world.positions.reserve(mesh.positions.size());
    for (Point3f p : mesh.positions) world.positions.push_back(instance.world_from_object(p));
    // A mirroring transform turns counter-clockwise faces clockwise; restore the winding.
    if (instance.world_from_object.swaps_handedness())
      for (size_t t = 0; t < world.indices.size(); t += 3)
        std::swap(world.indices[t + 1], world.indices[t + 2]);
  }
  return flat;
}

}  // namespace

TraceScene::TraceScene(const Scene& scene, std::shared_ptr<const EmbreeDevice> device)
    : embree_(std::move(device)) {
  scene.validate();
  meshes_ = flatten_instances(scene);
  for (const Material& m : scene.materials)
    materials_.push_back({diffuse_albedo(m.model), m.emission});
  for (const Mesh& mesh : meshes_) embree_.add_triangle_mesh(mesh.positions, mesh.indices);
  embree_.commit();
  lights_ = AreaLights(meshes_, scene.materials);
  Bounds3f b = scene.bounds();
  if (!b.empty()) {
    float extent = std::max({std::abs(b.min.x), std::abs(b.min.y), std::abs(b.min.z),
                             std::abs(b.max.x), std::abs(b.max.y), std::abs(b.max.z)});
    ray_epsilon_ = std::max(1e-6f, 1e-5f * extent);
  }
}

std::optional<SurfaceHit> TraceScene::intersect(const Ray& ray) const {
  std::optional<RayHit> hit = embree_.intersect(ray);
  if (!hit) return std::nullopt;
  const Mesh& mesh = meshes_[hit->geometry_id];
  const uint32_t* tri = &mesh.indices[3 * size_t(hit->primitive_id)];
  Point3f p0 = mesh.positions[tri[0]], p1 = mesh.positions[tri[1]], p2 = mesh.positions[tri[2]];
  SurfaceHit s;
  s.t = hit->t;
  s.position = ray.at(hit->t);
  s.geometric_normal = Normal3f(normalize(cross(p1 - p0, p2 - p0)));
  s.material = mesh.material;
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
