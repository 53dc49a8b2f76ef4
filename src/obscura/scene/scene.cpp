#include "obscura/scene/scene.h"

#include <cmath>
#include <variant>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"
#include "obscura/math/value_limits.h"

namespace obscura {

namespace {

bool finite(Point3f p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

template <typename T>
void check_attribute_size(const std::string& where, const char* attribute,
                          const std::vector<T>& values, size_t vertex_count) {
  if (!values.empty() && values.size() != vertex_count)
    throw Error(where, std::string(attribute) + " has " + std::to_string(values.size()) +
                           " entries for " + std::to_string(vertex_count) + " vertices");
}

bool within_world(Point3d p) {
  auto in = [](double c) { return std::abs(c) <= kMaxWorldCoordinateM; };  // NaN: false
  return in(p.x) && in(p.y) && in(p.z);
}

// A world-space point must be one single-precision ray tracing can resolve (math/value_limits.h).
void check_world_point(Point3d p, const std::string& where, const std::string& field) {
  if (within_world(p)) return;
  double worst = std::isnan(p.x) || std::abs(p.x) > kMaxWorldCoordinateM   ? p.x
                 : std::isnan(p.y) || std::abs(p.y) > kMaxWorldCoordinateM ? p.y
                                                                           : p.z;
  throw Error(where, field + " " + world_coordinate_message(worst));
}

// Where an instance puts its mesh: the corners of the mesh's object-space box (every pose of a
// deforming mesh) through each of its transforms, which bound the transformed mesh.
Bounds3f object_box(const Mesh& mesh) {
  Bounds3f box;
  for (Point3f p : mesh.positions) box = unite(box, p);
  for (const auto& step : mesh.deformation.positions)
    for (Point3f p : step) box = unite(box, p);
  return box;
}

void check_instance_extent(const Instance& instance, const Bounds3f& box,
                           const std::string& where) {
  if (box.empty()) return;
  auto check = [&](const Transform& t, const std::string& field) {
    for (int c = 0; c < 8; ++c) {
      Point3d corner((c & 1 ? box.max : box.min).x, (c & 2 ? box.max : box.min).y,
                     (c & 4 ? box.max : box.min).z);
      check_world_point(t(corner), where, field + " places a vertex at a coordinate that");
    }
  };
  check(instance.world_from_object, "world_from_object");
  for (size_t k = 0; k < instance.motion.size(); ++k)
    check(instance.motion[k].world_from_object, "motion key " + std::to_string(k));
}

// Light values: finite, non-negative and at most kMaxLightValue (math/value_limits.h).
void check_light_value(Rgb v, const std::string& where, const std::string& field,
                       const char* unit) {
  for (float c : {v.r, v.g, v.b})
    if (!(c >= 0 && c <= kMaxLightValue))
      throw Error(where, field + " must be finite, non-negative and at most " +
                             number_text(kMaxLightValue) + " " + unit + "; got " + number_text(c));
}

void check_direction(Vector3f d, const std::string& where) {
  if (!(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z)) ||
      (d.x == 0 && d.y == 0 && d.z == 0))
    throw Error(where, "direction must be finite and non-zero");
}

void validate_light(const Light& light, const std::string& where) {
  auto position = [&](Point3f p) { check_world_point(Point3d(p.x, p.y, p.z), where, "position"); };
  if (auto* point = std::get_if<PointLight>(&light.model)) {
    position(point->position);
    check_light_value(point->intensity, where, "intensity", "W/sr");
  } else if (auto* spot = std::get_if<SpotLight>(&light.model)) {
    position(spot->position);
    check_direction(spot->direction, where);
    check_light_value(spot->intensity, where, "intensity", "W/sr");
  } else if (auto* sun = std::get_if<DirectionalLight>(&light.model)) {
    check_direction(sun->direction, where);
    check_light_value(sun->irradiance, where, "irradiance", "W/m²");
  }
}

void validate_mesh(const Mesh& m, const std::string& where, size_t material_count) {
  if (m.indices.size() % 3 != 0)
    throw Error(where,
                "index count " + std::to_string(m.indices.size()) + " is not a multiple of 3");
  for (size_t i = 0; i < m.indices.size(); ++i)
    if (m.indices[i] >= m.positions.size())
      throw Error(where, "index " + std::to_string(i) + " = " + std::to_string(m.indices[i]) +
                             " is past the vertex count " + std::to_string(m.positions.size()));
  for (size_t i = 0; i < m.positions.size(); ++i)
    if (!finite(m.positions[i]))
      throw Error(where, "vertex " + std::to_string(i) + " position is not finite");
  check_attribute_size(where, "normals", m.normals, m.positions.size());
  check_attribute_size(where, "uvs", m.uvs, m.positions.size());
  check_attribute_size(where, "uvs1", m.uvs1, m.positions.size());
  check_attribute_size(where, "tangents", m.tangents, m.positions.size());
  check_attribute_size(where, "colors", m.colors, m.positions.size());
  check_attribute_size(where, "color_alphas", m.color_alphas, m.positions.size());
  if (m.analytic_sphere && !(finite(m.analytic_sphere->center) && m.analytic_sphere->radius > 0 &&
                             std::isfinite(m.analytic_sphere->radius)))
    throw Error(where, "analytic sphere: needs a finite centre and a finite radius > 0");
  const MeshDeformation& d = m.deformation;
  if (!d.positions.empty() && (!(d.open_s <= d.close_s) || d.positions.size() < 2 ||
                               (!d.normals.empty() && d.normals.size() != d.positions.size())))
    throw Error(where, "deformation: needs open ≤ close and ≥ 2 time steps, normals for each");
  for (size_t s = 0; s < d.positions.size(); ++s) {
    if (d.positions[s].size() != m.positions.size() ||
        (!d.normals.empty() && d.normals[s].size() != m.normals.size()))
      throw Error(where, "deformation step " + std::to_string(s) + " has " +
                             std::to_string(d.positions[s].size()) + " positions for " +
                             std::to_string(m.positions.size()) +
                             " vertices (or its normals differ)");
    for (size_t i = 0; i < d.positions[s].size(); ++i)
      if (!finite(d.positions[s][i]))
        throw Error(where, "deformation step " + std::to_string(s) + " vertex " +
                               std::to_string(i) + " is not finite");
  }
  if (m.material >= material_count)
    throw Error(where, "material index " + std::to_string(m.material) +
                           " is past the material count " + std::to_string(material_count));
}

void check_texture(const TextureRef& ref, const std::string& where, const char* slot,
                   size_t texture_count) {
  if (ref.texture < -1 || (ref.texture >= 0 && size_t(ref.texture) >= texture_count))
    throw Error(where, std::string(slot) + " texture index " + std::to_string(ref.texture) +
                           " is past the texture count " + std::to_string(texture_count));
}

void validate_material(const Material& m, const std::string& where, size_t texture_count) {
  check_texture(m.emission_texture, where, "emission", texture_count);
  check_texture(m.normal_texture, where, "normal", texture_count);
  check_texture(m.displacement_texture, where, "displacement", texture_count);
  if (!std::isfinite(m.displacement) ||
      (m.displacement_bound && !(*m.displacement_bound >= 0 && *m.displacement_bound < 1e30f)))
    throw Error(where, "displacement: needs a finite displacement and a finite bound ≥ 0");
  if (auto* d = std::get_if<DiffuseMaterial>(&m.model))
    check_texture(d->reflectance_texture, where, "reflectance", texture_count);
  if (auto* p = std::get_if<PhongMaterial>(&m.model))
    check_texture(p->diffuse_texture, where, "diffuse", texture_count);
  if (auto* mr = std::get_if<MetallicRoughnessMaterial>(&m.model)) {
    check_texture(mr->base_color_texture, where, "base colour", texture_count);
    check_texture(mr->metallic_roughness_texture, where, "metallic-roughness", texture_count);
    check_texture(mr->occlusion_texture, where, "occlusion", texture_count);
    check_texture(mr->clearcoat_texture, where, "clearcoat", texture_count);
    check_texture(mr->clearcoat_roughness_texture, where, "clearcoat roughness", texture_count);
    check_texture(mr->clearcoat_normal_texture, where, "clearcoat normal", texture_count);
    check_texture(mr->sheen_color_texture, where, "sheen colour", texture_count);
    check_texture(mr->sheen_roughness_texture, where, "sheen roughness", texture_count);
    check_texture(mr->specular_texture, where, "specular", texture_count);
    check_texture(mr->specular_color_texture, where, "specular colour", texture_count);
  }
  // Emission includes KHR_materials_emissive_strength, which glTF leaves unbounded.
  check_light_value(m.emission, where, "emission (strength included)", "W·sr⁻¹·m⁻²");
}

}  // namespace

uint32_t Scene::add_mesh(Mesh mesh, const Transform& world_from_object) {
  auto index = uint32_t(meshes.size());
  Instance instance;
  instance.name = mesh.name;
  instance.mesh = index;
  instance.world_from_object = world_from_object;
  meshes.push_back(std::move(mesh));
  instances.push_back(std::move(instance));
  return index;
}

void Scene::add_meshes(std::vector<Mesh> new_meshes) {
  for (Mesh& mesh : new_meshes) add_mesh(std::move(mesh));
}

SceneStats Scene::stats() const {
  SceneStats s;
  s.meshes = meshes.size();
  s.instances = instances.size();
  s.materials = materials.size();
  s.textures = textures.size();
  s.lights = lights.size();
  s.cameras = cameras.size();
  for (const Mesh& m : meshes) {
    s.unique_triangles += m.triangle_count();
    s.vertices += m.vertex_count();
    s.memory_bytes += sizeof(Mesh) + m.memory_bytes();
  }
  for (const Instance& instance : instances) {
    if (instance.mesh >= meshes.size()) continue;
    const Mesh& m = meshes[instance.mesh];
    s.triangles += m.triangle_count();
    uint32_t material = material_of(instance);
    if (material < materials.size() && !materials[material].emission.is_black())
      ++s.emissive_meshes;
    s.memory_bytes += sizeof(Instance) + instance.motion.capacity() * sizeof(TransformKey);
  }
  for (const Texture& t : textures) s.memory_bytes += sizeof(Texture) + t.memory_bytes();
  s.memory_bytes += materials.capacity() * sizeof(Material);
  return s;
}

std::vector<uint32_t> Scene::pose(double time_s, double exposure_s) {
  if (!std::isfinite(time_s) || !(exposure_s >= 0) || !std::isfinite(exposure_s))
    throw Error("scene '" + name + "'",
                "posed at a finite time over a finite, non-negative exposure; got " +
                    number_text(time_s) + " s and " + number_text(exposure_s) + " s");
  if (!poser) return {};
  poser->pose(meshes, time_s, exposure_s);
  return {poser->meshes().begin(), poser->meshes().end()};
}

Bounds3f Scene::bounds() const {
  Bounds3f b;
  for (const Instance& instance : instances) {
    if (instance.mesh >= meshes.size()) continue;
    for (Point3f p : meshes[instance.mesh].positions) b = unite(b, instance.world_from_object(p));
  }
  return b;
}

void Scene::validate() const {
  std::string scene_where = "scene '" + name + "'";
  for (const Mesh& m : meshes)
    validate_mesh(m, scene_where + ", mesh '" + m.name + "'", materials.size());
  for (size_t i = 0; i < instances.size(); ++i)
    if (instances[i].mesh >= meshes.size())
      throw Error(scene_where + ", instance '" + instances[i].name + "'",
                  "mesh index " + std::to_string(instances[i].mesh) + " is past the mesh count " +
                      std::to_string(meshes.size()));
  for (const Instance& instance : instances)
    if (instance.material >= 0 && size_t(instance.material) >= materials.size())
      throw Error(scene_where + ", instance '" + instance.name + "'",
                  "material index " + std::to_string(instance.material) +
                      " is past the material count " + std::to_string(materials.size()));
  for (const Material& m : materials)
    validate_material(m, scene_where + ", material '" + m.name + "'", textures.size());
  std::vector<Bounds3f> mesh_boxes;  // once per mesh: instances may share one many times
  for (const Mesh& m : meshes) mesh_boxes.push_back(object_box(m));
  for (const Instance& instance : instances)
    check_instance_extent(instance, mesh_boxes[instance.mesh],
                          scene_where + ", instance '" + instance.name + "'");
  for (const Light& light : lights)
    validate_light(light, scene_where + ", light '" + light.name + "'");
  if (environment && environment->texture >= 0 && size_t(environment->texture) >= textures.size())
    throw Error(scene_where + ", environment", "texture index is past the texture count");
  if (environment) {
    if (!(environment->intensity >= 0 && environment->intensity <= kMaxLightValue))
      throw Error(scene_where + ", environment",
                  "intensity must be finite, non-negative and at most " +
                      number_text(kMaxLightValue) + "; got " + number_text(environment->intensity));
    check_light_value(environment->color * environment->intensity, scene_where + ", environment",
                      "colour × intensity", "W·sr⁻¹·m⁻²");
  }
  camera.validate();
}

}  // namespace obscura
