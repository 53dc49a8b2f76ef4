#include "obscura/trace/trace_scene.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace obscura {

namespace {

// Instances flattened into world-space copies of their meshes (positions, normals and UVs).
std::vector<Mesh> flatten_instances(const Scene& scene) {
  std::vector<Mesh> flat;
  flat.reserve(scene.instances.size());
  for (const Instance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes[instance.mesh];
    Mesh& world = flat.emplace_back();
    world.name = instance.name;
    world.material = scene.material_of(instance);
    world.indices = mesh.indices;
    world.uvs = mesh.uvs;
    world.positions.reserve(mesh.positions.size());
    for (Point3f p : mesh.positions) world.positions.push_back(instance.world_from_object(p));
    for (Normal3f n : mesh.normals)
      world.normals.push_back(normalize(instance.world_from_object(n)));
    // A mirroring transform turns counter-clockwise faces clockwise; restore the winding.
    if (instance.world_from_object.swaps_handedness())
      for (size_t t = 0; t < world.indices.size(); t += 3)
        std::swap(world.indices[t + 1], world.indices[t + 2]);
  }
  return flat;
}

PunctualLight compile_light(const Light& light) {
  struct Visitor {
    PunctualLight operator()(const PointLight& l) const {
      return PunctualLight::point(l.position, l.intensity);
    }
    PunctualLight operator()(const SpotLight& l) const {
      return PunctualLight::spot(l.position, l.direction, l.intensity, l.inner_cone_radians,
                                 l.outer_cone_radians);
    }
    PunctualLight operator()(const DirectionalLight& l) const {
      return PunctualLight::directional(l.direction, l.irradiance);
    }
  };
  return std::visit(Visitor{}, light.model);
}

std::optional<EnvironmentLight> compile_environment(const Scene& scene) {
  if (!scene.environment) return std::nullopt;
  const Environment& env = *scene.environment;
  Rgb scale = env.color * env.intensity;
  if (env.texture < 0) return EnvironmentLight(scale);
  const Texture& t = scene.textures[env.texture];
  Image map(t.width, t.height, 3);
  for (int y = 0; y < t.height; ++y)
    for (int x = 0; x < t.width; ++x) {
      Vector4f v = sample_texture(t, {(x + 0.5f) / t.width, (y + 0.5f) / t.height});
      map.set_rgb(x, y, {v.x, v.y, v.z});
    }
  return EnvironmentLight(map, scale, env.world_from_environment);
}

}  // namespace

TraceScene::TraceScene(const Scene& scene, std::shared_ptr<const EmbreeDevice> device)
    : embree_(std::move(device)), textures_(scene.textures) {
  scene.validate();
  meshes_ = flatten_instances(scene);
  for (const Mesh& mesh : meshes_) embree_.add_triangle_mesh(mesh.positions, mesh.indices);
  embree_.commit();
  for (const Material& m : scene.materials) materials_.emplace_back(m, &textures_);
  Bounds3f b = scene.bounds();
  if (!b.empty()) {
    float extent = std::max({std::abs(b.min.x), std::abs(b.min.y), std::abs(b.min.z),
                             std::abs(b.max.x), std::abs(b.max.y), std::abs(b.max.z)});
    ray_epsilon_ = std::max(1e-6f, 1e-5f * extent);
    radius_ = std::max(1e-3f, 0.5f * distance(b.min, b.max));
  }
  std::vector<PunctualLight> punctual;
  for (const Light& light : scene.lights) punctual.push_back(compile_light(light));
  lights_ = LightSet(AreaLights(meshes_, scene.materials), compile_environment(scene),
                     std::move(punctual), radius_);
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
  const Mesh& mesh = meshes_[hit->geometry_id];
  s.material = mesh.material;
  if (!mesh.normals.empty() || !mesh.uvs.empty()) {
    // Interpolated attributes: only meshes that carry them pay for the vertex reads.
    const uint32_t* tri = &mesh.indices[3 * size_t(hit->primitive_id)];
    float b1 = hit->barycentric.x, b2 = hit->barycentric.y, b0 = 1 - b1 - b2;
    if (!mesh.normals.empty()) {
      Vector3f n = to_vector(mesh.normals[tri[0]]) * b0 + to_vector(mesh.normals[tri[1]]) * b1 +
                   to_vector(mesh.normals[tri[2]]) * b2;
      if (length_squared(n) > 0)
        s.shading_normal = face_forward(Normal3f(normalize(n)), to_vector(s.geometric_normal));
    }
    if (!mesh.uvs.empty()) {
      Point2f t0 = mesh.uvs[tri[0]], t1 = mesh.uvs[tri[1]], t2 = mesh.uvs[tri[2]];
      s.uv = {t0.x * b0 + t1.x * b1 + t2.x * b2, t0.y * b0 + t1.y * b1 + t2.y * b2};
    }
  }
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

Ray spawn_ray(const TraceScene& scene, const SurfaceHit& hit, Vector3f w) {
  Ray ray;
  ray.origin = offset_ray_origin(hit.position, hit.geometric_normal, w, scene.ray_epsilon());
  ray.direction = w;
  return ray;
}

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
