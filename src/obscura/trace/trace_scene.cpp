#include "obscura/trace/trace_scene.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <variant>

#include "obscura/camera/animated_transform.h"
#include "obscura/math/error.h"
#include "obscura/math/rng.h"
#include "obscura/scene/deformation_step.h"
#include "obscura/scene/tangents.h"
#include "obscura/shading/normal_map.h"

namespace obscura {

namespace {

// A world-space copy of `mesh` placed by `world_from_object` (positions, normals, UVs, colours,
// and `tangents`: the mesh's own, or generated for it). The positions have capacity for one more
// vertex, the padding Embree needs past the last one (see add_static).
Mesh flatten(const Mesh& mesh, std::span<const Vector4f> tangents,
             const Transform& world_from_object) {
  Mesh world;
  world.name = mesh.name;
  world.material = mesh.material;
  world.indices = mesh.indices;
  world.uvs = mesh.uvs;
  world.uvs1 = mesh.uvs1;
  world.colors = mesh.colors;
  world.color_alphas = mesh.color_alphas;
  world.positions.reserve(mesh.positions.size() + 1);
  for (Point3f p : mesh.positions) world.positions.push_back(world_from_object(p));
  world.normals.reserve(mesh.normals.size());
  for (Normal3f n : mesh.normals) world.normals.push_back(normalize(world_from_object(n)));
  // Tangents lie in the surface: they move as vectors. A mirror turns the bitangent's side of
  // cross(N, T) over, so the handedness flips with it.
  const bool mirror = world_from_object.swaps_handedness();
  world.tangents.reserve(tangents.size());
  for (Vector4f t : tangents) {
    Vector3f v = world_from_object(Vector3f(t.x, t.y, t.z));
    world.tangents.emplace_back(v.x, v.y, v.z, mirror ? -t.w : t.w);
  }
  // A mirroring transform turns counter-clockwise faces clockwise; restore the winding.
  if (mirror)
    for (size_t t = 0; t < world.indices.size(); t += 3)
      std::swap(world.indices[t + 1], world.indices[t + 2]);
  return world;
}

// What the shading code keeps of a mesh: Embree holds the positions. Tangents are kept only
// where a normal map needs them (`normal_map_uv_set` ≥ 0), generated from that UV set where the
// mesh has none (scene/tangents.h).
Mesh shading_attributes(Mesh mesh, int normal_map_uv_set) {
  if (normal_map_uv_set < 0)
    mesh.tangents = {};
  else if (mesh.tangents.empty())
    mesh.tangents = generate_tangents(mesh, uint32_t(normal_map_uv_set));
  mesh.positions = {};
  mesh.deformation.positions = {};
  return mesh;
}

// A deforming mesh's normal of vertex `v` at `time_s`, linear between its time steps.
Vector3f deformed_normal(const MeshDeformation& d, uint32_t v, float time_s) {
  const auto [i, f] = deformation_step(d, d.normals.size(), time_s);
  return to_vector(d.normals[i][v]) * (1 - f) + to_vector(d.normals[i + 1][v]) * f;
}

// The inverse transpose of a linear map's columns c0, c1, c2, up to a positive factor: the
// cofactor matrix (columns c1×c2, c2×c0, c0×c1) signed by the determinant, so a mirror keeps
// normals on the side the flattened (re-wound) triangles would give them.
void normal_matrix(const double linear[3][3], float out[3][3]) {
  Vector3d c[3];
  for (int j = 0; j < 3; ++j) c[j] = {linear[0][j], linear[1][j], linear[2][j]};
  Vector3d k[3] = {cross(c[1], c[2]), cross(c[2], c[0]), cross(c[0], c[1])};
  double sign = dot(c[0], k[0]) < 0 ? -1 : 1;
  for (int r = 0; r < 3; ++r)
    for (int j = 0; j < 3; ++j) out[r][j] = float(sign * k[j][r]);
}

Vector3f apply(const float m[3][3], Vector3f v) {
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
          m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

// The instance's motion keys as an AnimatedTransform, with errors naming the instance.
AnimatedTransform motion_of(const Instance& instance, size_t index) {
  std::vector<AnimatedTransform::Key> keys;
  for (const TransformKey& k : instance.motion)
    keys.push_back({k.time_seconds, k.world_from_object});
  try {
    return AnimatedTransform(std::move(keys));
  } catch (const Error& e) {
    throw Error("instance " + std::to_string(index) + " '" + instance.name + "' motion", e.what());
  }
}

// Transforms at n + 1 evenly spaced times over the shutter, with n (a power of two, ≤ 128) the
// fewest segments whose linear interpolation (what Embree does between time steps) keeps the
// object's bounding-box corners within 10⁻³ of its diagonal of the true path, checked at segment
// midpoints and quarter points and at every key inside the shutter.
std::vector<Transform> time_steps(const AnimatedTransform& motion, const Shutter& shutter,
                                  const Bounds3f& object_bounds) {
  Point3f corners[8];
  for (int i = 0; i < 8; ++i)
    corners[i] = {i & 1 ? object_bounds.max.x : object_bounds.min.x,
                  i & 2 ? object_bounds.max.y : object_bounds.min.y,
                  i & 4 ? object_bounds.max.z : object_bounds.min.z};
  auto world_corners = [&](const Transform& t, Point3d out[8]) {
    for (int i = 0; i < 8; ++i) out[i] = t(Point3d(corners[i].x, corners[i].y, corners[i].z));
  };
  const double duration = shutter.duration_s();
  std::vector<Transform> steps;
  for (int segments = 1;; segments *= 2) {
    steps.clear();
    for (int i = 0; i <= segments; ++i)
      steps.push_back(motion.at(shutter.time_at(double(i) / segments)));
    if (segments * 2 >= EmbreeScene::kMaxTimeSteps) return steps;
    double tolerance = 1e-3 * distance(object_bounds.min, object_bounds.max);
    std::vector<double> checks;  // as fractions of the shutter
    for (int i = 0; i < segments; ++i)
      for (double f : {0.25, 0.5, 0.75}) checks.push_back((i + f) / segments);
    for (const auto& key : motion.keys())
      if (key.time_s > shutter.open_s && key.time_s < shutter.close_s)
        checks.push_back((key.time_s - shutter.open_s) / duration);
    double worst = 0;
    for (double f : checks) {
      auto i = std::min(segments - 1, int(f * segments));
      double s = f * segments - i;
      Point3d truth[8], a[8], b[8];
      world_corners(motion.at(shutter.time_at(f)), truth);
      world_corners(steps[i], a);
      world_corners(steps[i + 1], b);
      for (int c = 0; c < 8; ++c)
        worst = std::max(worst, distance(truth[c], a[c] + (b[c] - a[c]) * s));
    }
    if (worst <= tolerance) return steps;
  }
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

TraceScene::TraceScene(const Scene& scene, std::shared_ptr<const EmbreeDevice> device,
                       const TraceSceneOptions& options)
    : embree_(std::move(device)), textures_(scene.textures) {
  scene.validate();
  shutter_ = options.shutter.value_or(scene.camera.exposure_interval());
  validate(shutter_);
  embree_.set_motion_interval(shutter_.open_s, shutter_.close_s);
  // The UV set of the normal map each mesh is drawn with, if any (the first one found, should
  // instances draw one mesh with normal maps on different sets).
  normal_map_uv_set_.assign(scene.meshes.size(), -1);
  for (const Instance& instance : scene.instances) {
    const TextureRef& normal_map =
        tangent_space_texture(scene.materials[scene.material_of(instance)]);
    if (normal_map.valid() && normal_map_uv_set_[instance.mesh] < 0)
      normal_map_uv_set_[instance.mesh] = int(normal_map.uv_set);
  }
  // Filled by shading_mesh() for the meshes that instances use; a mesh flattened into world
  // space keeps only its world-space copy. Sized once: placements point into it.
  meshes_.resize(scene.meshes.size());
  has_shading_mesh_.assign(scene.meshes.size(), false);
  prototype_of_mesh_.assign(scene.meshes.size(), -1);
  std::vector<int> uses(scene.meshes.size(), 0);
  for (const Instance& instance : scene.instances) ++uses[instance.mesh];

  // Emitters for light sampling: static emissive instances as world-space triangles (moving ones
  // are left to BSDF sampling, see docs/tracer.md).
  std::vector<Mesh> emitters(scene.instances.size());
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    has_animation_ = has_animation_ || instance.animated();
    // A deforming mesh is a moving instance too: Embree interpolates its vertices in time.
    bool moving =
        (instance.animated() || scene.meshes[instance.mesh].deforms()) && shutter_.duration_s() > 0;
    Transform pose = instance.animated() ? motion_of(instance, i).at(shutter_.open_s)
                                         : instance.world_from_object;
    if (moving)
      add_moving(scene, i);
    else
      add_static(scene, i, pose,
                 options.instancing == Instancing::kAlways ||
                     (options.instancing == Instancing::kAuto && uses[instance.mesh] > 1));
    uint32_t material = scene.material_of(instance);
    if (!moving && !scene.materials[material].emission.is_black()) {
      emitters[i] = flatten(scene.meshes[instance.mesh], {}, pose);
      emitters[i].material = material;
    }
  }
  embree_.commit();
  for (const Mesh& mesh : scene.meshes) shapes_.push_back(shape_of(mesh));
  for (const Material& m : scene.materials) materials_.emplace_back(m, &textures_);
  has_alpha_ = std::any_of(materials_.begin(), materials_.end(),
                           [](const TraceMaterial& m) { return m.has_alpha(); });
  set_scene_extent(scene);
  std::vector<PunctualLight> punctual;
  for (const Light& light : scene.lights) punctual.push_back(compile_light(light));
  lights_ = LightSet(AreaLights(emitters, scene.materials, options.area_light_sampling, &textures_),
                     compile_environment(scene), std::move(punctual), radius_);
}

const Mesh& TraceScene::shading_mesh(const Scene& scene, uint32_t mesh) {
  if (!has_shading_mesh_[mesh]) {
    meshes_[mesh] = shading_attributes(scene.meshes[mesh], normal_map_uv_set_[mesh]);
    has_shading_mesh_[mesh] = true;
  }
  return meshes_[mesh];
}

uint32_t TraceScene::prototype_of(const Scene& scene, uint32_t mesh) {
  if (prototype_of_mesh_[mesh] < 0) {
    const Mesh& m = scene.meshes[mesh];
    prototype_of_mesh_[mesh] = int32_t(embree_.add_prototype(m.positions, m.indices));
    ++prototypes_;
  }
  return uint32_t(prototype_of_mesh_[mesh]);
}

void TraceScene::set_static_matrices(Placement& p, const Transform& world_from_object) {
  double linear[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      linear[r][c] = world_from_object.matrix().m[r][c];
      p.vector_from_object[r][c] = float(linear[r][c]);
    }
  normal_matrix(linear, p.normal_from_object);
  p.handedness = world_from_object.swaps_handedness() ? -1.f : 1.f;
}

void TraceScene::flatten_into(const Scene& scene, uint32_t instance,
                              const Transform& world_from_object, size_t slot) {
  // The object-space tangents (generated where a normal map needs them) go along into world
  // space.
  const uint32_t mesh = scene.instances[instance].mesh;
  const Mesh& object = scene.meshes[mesh];
  const int uv_set = normal_map_uv_set_[mesh];
  std::vector<Vector4f> generated;
  std::span<const Vector4f> tangents;
  if (uv_set >= 0 && !object.tangents.empty())
    tangents = object.tangents;
  else if (uv_set >= 0)
    tangents = generated = generate_tangents(object, uint32_t(uv_set));
  Mesh world = flatten(object, tangents, world_from_object);
  if (slot == flattened_.size()) {
    // Embree reads the vertex buffer 16 bytes at a time: the last vertex needs 4 bytes of
    // padding after it (flatten reserved room for it, so the buffer is not copied here).
    std::vector<Point3f>& positions = world_positions_.emplace_back(std::move(world.positions));
    positions.emplace_back();
    flattened_.push_back(std::make_unique<Mesh>(shading_attributes(std::move(world), uv_set)));
    return;
  }
  // Again, where Embree reads them: the positions rewritten in their buffer, the shading
  // attributes replaced around the triangle indices Embree shares (the same as before).
  std::copy(world.positions.begin(), world.positions.end(), world_positions_[slot].begin());
  Mesh& kept = *flattened_[slot];
  std::vector<uint32_t> shared_indices = std::move(kept.indices);
  kept = shading_attributes(std::move(world), uv_set);
  kept.indices = std::move(shared_indices);
}

void TraceScene::add_static(const Scene& scene, uint32_t instance,
                            const Transform& world_from_object, bool instanced) {
  const Instance& in = scene.instances[instance];
  Placement p{.instance = instance, .material = scene.material_of(in)};
  Source source;
  uint32_t id;
  if (instanced) {
    Transform steps[1] = {world_from_object};
    id = embree_.add_instance(prototype_of(scene, in.mesh), steps);
    ++embree_instances_;
    p.attributes = &shading_mesh(scene, in.mesh);
    p.object_space = true;
    set_static_matrices(p, world_from_object);
    source.how = Placed::kInstanced;
  } else {
    source.slot = uint32_t(flattened_.size());
    flatten_into(scene, instance, world_from_object, flattened_.size());
    p.attributes = flattened_.back().get();
    // Embree shares the world-space buffers rather than copying them.
    const std::vector<Point3f>& positions = world_positions_.back();
    id = embree_.add_shared_triangle_mesh(
        std::span<const Point3f>(positions.data(), positions.size() - 1), p.attributes->indices);
  }
  if (placements_.size() <= id) {
    placements_.resize(id + 1);
    sources_.resize(id + 1);
  }
  placements_[id] = p;
  sources_[id] = source;
}

std::vector<std::vector<Point3f>> TraceScene::deforming_poses(const Mesh& mesh) const {
  // As many evenly spaced shutter times as the mesh has steps: the steps themselves when they
  // span the shutter.
  const size_t count = std::min(mesh.deformation.positions.size(), size_t(kMaxTimeSteps));
  std::vector<std::vector<Point3f>> poses;
  for (size_t k = 0; k < count; ++k)
    poses.push_back(mesh.posed_at(shutter_.time_at(double(k) / double(count - 1))).positions);
  return poses;
}

void TraceScene::add_moving(const Scene& scene, uint32_t instance) {
  const Instance& in = scene.instances[instance];
  const Mesh& mesh = scene.meshes[in.mesh];
  std::vector<Transform> steps = {in.world_from_object};
  if (in.animated()) steps = time_steps(motion_of(in, instance), shutter_, mesh.bounds());
  uint32_t prototype = 0;
  const MeshDeformation* deformation = nullptr;
  if (mesh.deforms()) {
    // Its own prototype: deforming meshes are not shared.
    std::vector<std::vector<Point3f>> poses = deforming_poses(mesh);
    std::vector<std::span<const Point3f>> views(poses.begin(), poses.end());
    prototype = embree_.add_prototype(views, mesh.indices);
    ++prototypes_;
    const Mesh& shading = shading_mesh(scene, in.mesh);
    if (!shading.deformation.normals.empty()) deformation = &shading.deformation;
  } else {
    prototype = prototype_of(scene, in.mesh);
  }
  uint32_t id = embree_.add_instance(prototype, steps);
  ++embree_instances_;
  has_motion_ = true;
  if (placements_.size() <= id) {
    placements_.resize(id + 1);
    sources_.resize(id + 1);
  }
  sources_[id] = {.how = Placed::kMoving,
                  .slot = prototype,
                  .steps = uint32_t(steps.size()),
                  .deforming = mesh.deforms()};
  placements_[id] = {.instance = instance,
                     .material = scene.material_of(in),
                     .attributes = &shading_mesh(scene, in.mesh),
                     .object_space = true,
                     .moving = true,
                     .deformation = deformation};
}

void TraceScene::set_scene_extent(const Scene& scene) {
  Bounds3f b = scene.bounds();
  if (!b.empty()) {
    float extent = std::max({std::abs(b.min.x), std::abs(b.min.y), std::abs(b.min.z),
                             std::abs(b.max.x), std::abs(b.max.y), std::abs(b.max.z)});
    ray_epsilon_ = std::max(1e-6f, 1e-5f * extent);
    radius_ = std::max(1e-3f, 0.5f * distance(b.min, b.max));
  }
}

bool TraceScene::serves(const Shutter& exposure) const {
  const bool same = shutter_.open_s == exposure.open_s && shutter_.close_s == exposure.close_s;
  return same || (!has_motion_ && !has_animation_);
}

bool TraceScene::update(const Scene& scene, std::span<const uint32_t> changed,
                        const Shutter& shutter) {
  const bool same_shutter =
      shutter_.open_s == shutter.open_s && shutter_.close_s == shutter.close_s;
  const bool open = shutter.duration_s() > 0;
  if (scene.meshes.size() != shapes_.size() || !std::isfinite(shutter.open_s) ||
      !std::isfinite(shutter.close_s) || !(shutter.close_s >= shutter.open_s))
    return false;
  std::vector<bool> mesh_changed(scene.meshes.size(), false);
  for (uint32_t mesh : changed) {
    if (mesh >= scene.meshes.size()) return false;
    const Shape now = shape_of(scene.meshes[mesh]), was = shapes_[mesh];
    if (now.vertices != was.vertices || now.indices != was.indices ||
        now.deformation_steps != was.deformation_steps)
      return false;
    mesh_changed[mesh] = true;
  }
  // Checked before anything changes: every placement keeps its form (what moved over the old
  // shutter moves over the new one, with as many time steps), and no static emitter moves (its
  // triangles are a light's).
  std::vector<std::vector<Transform>> new_steps(placements_.size());
  auto moves = [&](uint32_t id) {
    const Instance& in = scene.instances[placements_[id].instance];
    return mesh_changed[in.mesh] ||
           (!same_shutter && (sources_[id].how == Placed::kMoving || in.animated()));
  };
  for (uint32_t id = 0; id < placements_.size(); ++id) {
    if (!placements_[id].attributes) continue;  // an id no placement took
    const uint32_t instance = placements_[id].instance;
    if (instance >= scene.instances.size()) return false;
    const Instance& in = scene.instances[instance];
    if (in.mesh >= scene.meshes.size()) return false;
    const Mesh& mesh = scene.meshes[in.mesh];
    const bool moving = (in.animated() || mesh.deforms()) && open;
    if (moving != (sources_[id].how == Placed::kMoving)) return false;
    if (moving && in.animated() && !same_shutter) {
      new_steps[id] = time_steps(motion_of(in, instance), shutter, mesh.bounds());
      if (new_steps[id].size() != sources_[id].steps) return false;
    }
    if (!moving && moves(id) && !scene.materials[placements_[id].material].emission.is_black())
      return false;
  }

  shutter_ = shutter;
  embree_.set_motion_interval(shutter_.open_s, shutter_.close_s);
  std::vector<bool> prototype_done(prototype_of_mesh_.size(), false);
  auto rebuild_shared_prototype = [&](uint32_t mesh) {
    if (prototype_done[mesh]) return;
    prototype_done[mesh] = true;
    const std::span<const Point3f> steps[1] = {scene.meshes[mesh].positions};
    embree_.set_prototype_positions(uint32_t(prototype_of_mesh_[mesh]), steps);
  };
  for (uint32_t mesh = 0; mesh < scene.meshes.size(); ++mesh)
    if (mesh_changed[mesh] && has_shading_mesh_[mesh])
      meshes_[mesh] = shading_attributes(scene.meshes[mesh], normal_map_uv_set_[mesh]);
  for (uint32_t id = 0; id < placements_.size(); ++id) {
    Placement& p = placements_[id];
    if (!p.attributes || !moves(id)) continue;
    const Instance& in = scene.instances[p.instance];
    const Source& source = sources_[id];
    if (source.how == Placed::kMoving) {
      if (source.deforming) {
        std::vector<std::vector<Point3f>> poses = deforming_poses(scene.meshes[in.mesh]);
        std::vector<std::span<const Point3f>> views(poses.begin(), poses.end());
        embree_.set_prototype_positions(source.slot, views);
        const Mesh& shading = meshes_[in.mesh];
        p.deformation = shading.deformation.normals.empty() ? nullptr : &shading.deformation;
      } else if (mesh_changed[in.mesh]) {
        rebuild_shared_prototype(in.mesh);
      }
      if (!new_steps[id].empty()) embree_.set_instance_transforms(id, new_steps[id]);
      continue;
    }
    const Transform pose =
        in.animated() ? motion_of(in, p.instance).at(shutter_.open_s) : in.world_from_object;
    if (source.how == Placed::kFlattened) {
      flatten_into(scene, p.instance, pose, source.slot);
      embree_.shared_positions_changed(id);
      continue;
    }
    if (mesh_changed[in.mesh]) rebuild_shared_prototype(in.mesh);
    if (in.animated()) {
      const Transform steps[1] = {pose};
      embree_.set_instance_transforms(id, steps);
      set_static_matrices(p, pose);
    }
  }
  embree_.commit();
  // The scene's extent sizes ray offsets and the disk distant light enters through.
  const float radius = radius_;
  set_scene_extent(scene);
  if (radius_ != radius) {
    std::optional<EnvironmentLight> environment;
    if (lights_.environment()) environment = *lights_.environment();
    lights_ = LightSet(lights_.area_lights(), std::move(environment), lights_.punctual(), radius_);
  }
  return true;
}

void TraceScene::set_material(uint32_t index, TraceMaterial material) {
  materials_.at(index) = std::move(material);
  has_alpha_ = has_alpha_ || materials_[index].has_alpha();
}

void TraceScene::set_environment(std::optional<EnvironmentLight> environment) {
  lights_ = LightSet(lights_.area_lights(), std::move(environment), lights_.punctual(), radius_);
}

void TraceScene::set_punctual_lights(std::vector<PunctualLight> lights) {
  std::optional<EnvironmentLight> environment;
  if (lights_.environment()) environment = *lights_.environment();
  lights_ = LightSet(lights_.area_lights(), std::move(environment), std::move(lights), radius_);
}

namespace {

// The uniform number that decides whether a ray passes an alpha-blended surface: a hash of the
// ray and of what it hit, so that it is the same for any thread count and tile order, and
// independent between rays, layers and surfaces.
float alpha_sample(const Ray& ray, const RayHit& hit, int layer) {
  auto bits = [](float a, float b) {
    return (uint64_t(std::bit_cast<uint32_t>(a)) << 32) | std::bit_cast<uint32_t>(b);
  };
  uint64_t where = (uint64_t(hit.geometry_id) << 32) | hit.primitive_id;
  return bits_to_unit_float(
      hash_words(bits(ray.origin.x, ray.origin.y), bits(ray.origin.z, ray.direction.x),
                 bits(ray.direction.y, ray.direction.z), where ^ (uint64_t(layer) << 56)));
}

}  // namespace

std::optional<SurfaceHit> TraceScene::intersect(const Ray& ray) const {
  if (!has_alpha_) {
    std::optional<RayHit> hit = embree_.intersect(ray);
    if (!hit) return std::nullopt;
    return surface_hit(ray, *hit);
  }
  // Surfaces with alpha coverage: continue past each one the ray passes through, from just
  // beyond it along the same ray (so t stays measured from the original origin).
  Ray rest = ray;
  for (int layer = 0;; ++layer) {
    std::optional<RayHit> hit = embree_.intersect(rest);
    if (!hit) return std::nullopt;
    SurfaceHit s = surface_hit(ray, *hit);
    if (layer + 1 >= kMaxAlphaLayers ||
        !materials_[s.material].passes_through(s, alpha_sample(ray, *hit, layer)))
      return s;
    rest.t_min = std::nextafter(hit->t, std::numeric_limits<float>::infinity());
    if (!(rest.t_min < rest.t_max)) return std::nullopt;
  }
}

bool TraceScene::occluded(const Ray& ray) const {
  return has_alpha_ ? intersect(ray).has_value() : embree_.occluded(ray);
}

SurfaceHit TraceScene::surface_hit(const Ray& ray, const RayHit& hit) const {
  // Everything here comes with Embree's answer; mesh data is read only for meshes that carry
  // shading normals or UVs (a cache miss per incoherent ray on large scenes).
  const Placement& place = placements_[hit.geometry_id];
  // Object-space normals go to the world by the inverse transpose, at the ray's time if moving.
  float moving_normal_matrix[3][3], moving_vector_matrix[3][3];
  const float(*to_world)[3] = place.normal_from_object;
  const float(*vector_to_world)[3] = place.vector_from_object;
  float handedness = place.handedness;
  if (place.moving) {
    Affine3f a = embree_.instance_transform(hit.geometry_id, ray.time);
    double linear[3][3];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        linear[r][c] = a.m[r][c];
        moving_vector_matrix[r][c] = a.m[r][c];
      }
    normal_matrix(linear, moving_normal_matrix);
    to_world = moving_normal_matrix;
    vector_to_world = moving_vector_matrix;
    Vector3d c0(linear[0][0], linear[1][0], linear[2][0]),
        c1(linear[0][1], linear[1][1], linear[2][1]), c2(linear[0][2], linear[1][2], linear[2][2]);
    handedness = dot(c0, cross(c1, c2)) < 0 ? -1.f : 1.f;
  }
  SurfaceHit s;
  s.t = hit.t;
  s.time = ray.time;
  s.position = ray.at(hit.t);
  Vector3f ng = place.object_space ? apply(to_world, hit.normal) : hit.normal;
  s.geometric_normal = Normal3f(normalize(ng));
  s.shading_normal = s.geometric_normal;
  s.mesh = place.instance;
  s.primitive = hit.primitive_id;
  s.material = place.material;
  const Mesh& mesh = *place.attributes;
  if (mesh.normals.empty() && mesh.uvs.empty() && mesh.uvs1.empty() && mesh.colors.empty() &&
      mesh.color_alphas.empty())
    return s;
  // Interpolated attributes: only meshes that carry them pay for the vertex reads.
  const uint32_t* tri = &mesh.indices[3 * size_t(hit.primitive_id)];
  float b1 = hit.barycentric.x, b2 = hit.barycentric.y, b0 = 1 - b1 - b2;
  auto interpolate_uv = [&](const std::vector<Point2f>& uv) {
    Point2f t0 = uv[tri[0]], t1 = uv[tri[1]], t2 = uv[tri[2]];
    return Point2f(t0.x * b0 + t1.x * b1 + t2.x * b2, t0.y * b0 + t1.y * b1 + t2.y * b2);
  };
  if (!mesh.uvs.empty()) s.uv = interpolate_uv(mesh.uvs);
  if (!mesh.uvs1.empty()) s.uv1 = interpolate_uv(mesh.uvs1);
  if (!mesh.colors.empty())
    s.vertex_color = mesh.colors[tri[0]] * b0 + mesh.colors[tri[1]] * b1 + mesh.colors[tri[2]] * b2;
  if (!mesh.color_alphas.empty())
    s.vertex_alpha = mesh.color_alphas[tri[0]] * b0 + mesh.color_alphas[tri[1]] * b1 +
                     mesh.color_alphas[tri[2]] * b2;
  // The unperturbed normal (world, unit) and whether it runs against the winding's side.
  Vector3f n = to_vector(s.geometric_normal);
  if (!mesh.normals.empty()) {
    // A deforming mesh's normals at the ray's time.
    auto normal = [&](uint32_t v) {
      return place.deformation ? deformed_normal(*place.deformation, v, ray.time)
                               : to_vector(mesh.normals[v]);
    };
    Vector3f interpolated = normal(tri[0]) * b0 + normal(tri[1]) * b1 + normal(tri[2]) * b2;
    if (place.object_space) interpolated = apply(to_world, interpolated);
    if (length_squared(interpolated) > 0) n = normalize(interpolated);
  }
  const TraceMaterial& material = materials_[place.material];
  if (!mesh.tangents.empty() && (material.has_normal_map() || material.has_coat_normal())) {
    Vector4f t =
        mesh.tangents[tri[0]] * b0 + mesh.tangents[tri[1]] * b1 + mesh.tangents[tri[2]] * b2;
    Vector3f tw(t.x, t.y, t.z);
    if (place.object_space) tw = apply(vector_to_world, tw);
    Vector3f g = to_vector(s.geometric_normal);
    Vector3f side = dot(n, g) < 0 ? -g : g;  // the interpolated normal's side of the surface
    Vector4f tangent(tw.x, tw.y, tw.z, t.w * handedness);
    // A clear coat ignores the base's normal map (KHR_materials_clearcoat): its own, or none.
    if (material.has_coat_normal())
      s.coat_normal = to_vector(face_forward(
          Normal3f(shading::keep_above_surface(material.coat_normal_mapped(s, n, tangent), side)),
          g));
    if (material.has_normal_map()) {
      n = material.normal_mapped(s, n, tangent);
      // Shading below the geometric surface is kept just above it (shading/normal_map.h says
      // how); rays still leave along the geometric normal.
      n = shading::keep_above_surface(n, side);
    }
  }
  s.shading_normal = face_forward(Normal3f(n), to_vector(s.geometric_normal));
  return s;
}

bool TraceScene::occluded(Point3f from, Point3f to, float time_s) const {
  Ray ray;
  ray.origin = from;
  ray.direction = to - from;
  ray.t_min = 0;
  ray.t_max = 1 - 1e-4f;  // stop just short of the target surface
  ray.time = time_s;
  return occluded(ray);
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
  ray.time = hit.time;
  return ray;
}

Ray shadow_ray(const TraceScene& scene, const SurfaceHit& hit, const LightSample& light) {
  Ray ray;
  ray.origin = offset_ray_origin(hit.position, hit.geometric_normal, light.wi, scene.ray_epsilon());
  ray.time = hit.time;  // the same moment as the path it belongs to
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
