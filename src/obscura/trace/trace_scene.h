// The tracer's flat form of a Scene: Embree geometry, per-triangle data for shading, materials
// and the emitters. Compiled once from the authoring Scene; read-only (and thread-safe) after.
//
// Meshes shared by several instances are built once and placed by Embree instances; a mesh
// placed once and not moving is copied into world space instead (one traversal level less).
// Moving instances (motion keys) are Embree instances with a transform per time step over the
// shutter; deforming meshes (Mesh::deformation) are prototypes with vertices per time step; rays
// carry their time.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "obscura/scene/scene.h"
#include "obscura/trace/embree_scene.h"
#include "obscura/trace/light_set.h"
#include "obscura/trace/surface_hit.h"
#include "obscura/trace/trace_material.h"

namespace obscura {

enum class Instancing {
  kAuto,    // instance meshes used more than once and moving instances; flatten the rest
  kAlways,  // every instance through Embree instancing
  kNever,   // flatten every static instance into world space (moving ones stay instances)
};

struct TraceSceneOptions {
  Instancing instancing = Instancing::kAuto;
  AreaLightSampling area_light_sampling = AreaLightSampling::kSolidAngle;
  // The interval object motion is compiled for; the camera's exposure interval (its shutter,
  // lengthened by a rolling shutter's readout) must match it at render time. Default: the scene
  // camera's.
  std::optional<Shutter> shutter = std::nullopt;
};

class TraceScene {
 public:
  TraceScene(const Scene& scene, std::shared_ptr<const EmbreeDevice> device,
             const TraceSceneOptions& options = {});

  // The closest surface the ray meets, passing through alpha-masked and (stochastically)
  // alpha-blended surfaces where their coverage lets it.
  std::optional<SurfaceHit> intersect(const Ray& ray) const;
  // Whether the open segment between two points is blocked at time `time_s`.
  bool occluded(Point3f from, Point3f to, float time_s = 0) const;
  // Whether anything lies along the ray within [t_min, t_max].
  bool occluded(const Ray& ray) const;
  // How many alpha-covered surfaces one ray may pass; the next one is treated as opaque.
  static constexpr int kMaxAlphaLayers = 256;

  const TraceMaterial& material(uint32_t index) const { return materials_[index]; }
  const AreaLights& lights() const { return lights_.area_lights(); }
  const LightSet& light_set() const { return lights_; }
  // Distance by which ray origins leave a surface, scaled to the scene's extent.
  float ray_epsilon() const { return ray_epsilon_; }
  float radius() const { return radius_; }  // of a sphere around the scene (m)
  // Whether some instance moves during the shutter, and the shutter motion was compiled for.
  bool has_motion() const { return has_motion_; }
  const Shutter& shutter() const { return shutter_; }
  // Whether frames exposed over `exposure` render from this compilation: those over the shutter
  // it was compiled for, and any where nothing is animated (an animated instance still over a
  // zero-length shutter is placed where it is at that moment).
  bool serves(const Shutter& exposure) const;

  // Brings the compilation up to date, in place, after the scene's meshes `changed` were posed
  // again (skins and morph targets at another moment: the same vertex and triangle counts) and
  // for frames exposed over `shutter`: those meshes are rebuilt, and where the shutter moved, the
  // animated instances take their transforms over it (a still shutter: their pose at that moment;
  // an open one: as many time steps as before) and deforming meshes their steps; materials,
  // textures, lights and every other mesh's acceleration structure are kept. The result traces as
  // a new compilation would. Returns false, changing nothing, where only a new compilation will
  // do: a mesh whose counts or deformation steps changed, an emissive surface that moved (the
  // light's triangles), motion that needs another number of time steps, or something that starts
  // or stops moving (a shutter opened or closed).
  bool update(const Scene& scene, std::span<const uint32_t> changed, const Shutter& shutter);
  // How many instances went through Embree instancing, and how many meshes were built for them.
  size_t embree_instance_count() const { return embree_instances_; }
  size_t prototype_count() const { return prototypes_; }

  // Replace a material or the environment after compilation (tests, tools), before rendering.
  void set_material(uint32_t index, TraceMaterial material);
  void set_environment(std::optional<EnvironmentLight> environment);
  void set_punctual_lights(std::vector<PunctualLight> lights);

 private:
  // What shading needs of each Embree geometry (by geometry id).
  struct Placement {
    uint32_t instance = 0;  // index into Scene::instances: SurfaceHit::mesh, the id AOV
    uint32_t material = 0;
    const Mesh* attributes = nullptr;  // indices, normals, uvs (no positions)
    bool object_space = false;         // attributes and Embree's normal are in object space
    bool moving = false;               // the transform depends on the ray's time
    const MeshDeformation* deformation = nullptr;  // shading normals over time, if deforming
    float normal_from_object[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // static instances
    float vector_from_object[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // tangents, likewise
    float handedness = 1;  // −1 where the placement mirrors (tangent w flips)
  };
  static constexpr int kMaxTimeSteps = EmbreeScene::kMaxTimeSteps;
  // How each Embree geometry was made from its instance, for update().
  enum class Placed : uint8_t { kFlattened, kInstanced, kMoving };
  struct Source {
    Placed how = Placed::kFlattened;
    uint32_t slot = 0;   // kFlattened: index into flattened_; kMoving and deforming: its prototype
    uint32_t steps = 1;  // kMoving: the instance's transforms over the shutter
    bool deforming = false;
  };
  struct Shape {  // a mesh as compiled
    size_t vertices = 0, indices = 0, deformation_steps = 0;
  };
  static Shape shape_of(const Mesh& mesh) {
    return {mesh.positions.size(), mesh.indices.size(), mesh.deformation.positions.size()};
  }
  static void set_static_matrices(Placement& p, const Transform& world_from_object);
  void flatten_into(const Scene& scene, uint32_t instance, const Transform& world_from_object,
                    size_t slot);
  std::vector<std::vector<Point3f>> deforming_poses(const Mesh& mesh) const;
  void set_scene_extent(const Scene& scene);
  void add_static(const Scene& scene, uint32_t instance, const Transform& world_from_object,
                  bool instanced);
  void add_moving(const Scene& scene, uint32_t instance);
  SurfaceHit surface_hit(const Ray& ray, const RayHit& hit) const;
  uint32_t prototype_of(const Scene& scene, uint32_t mesh);
  const Mesh& shading_mesh(const Scene& scene, uint32_t mesh);

  // Declared before embree_, which shares them: destroyed after it.
  std::vector<std::unique_ptr<Mesh>> flattened_;       // world-space copies of meshes placed once
  std::vector<std::vector<Point3f>> world_positions_;  // their positions, one vertex of padding
  EmbreeScene embree_;
  std::vector<Mesh> meshes_;            // the scene's meshes, object space, as instances share them
  std::vector<bool> has_shading_mesh_;  // per mesh: whether meshes_ holds it yet
  std::vector<int> normal_map_uv_set_;  // per mesh: the UV set its tangents follow, −1 none
  std::vector<int32_t> prototype_of_mesh_;  // Embree prototype per mesh, −1 until built
  std::vector<Placement> placements_;
  std::vector<Source> sources_;  // by geometry id, as placements_
  std::vector<Shape> shapes_;    // by mesh
  Shutter shutter_;
  bool has_motion_ = false;
  bool has_animation_ = false;  // some instance has motion keys
  size_t embree_instances_ = 0, prototypes_ = 0;
  std::vector<Texture> textures_;  // what the materials sample
  std::vector<TraceMaterial> materials_;
  LightSet lights_;
  float ray_epsilon_ = 1e-4f;
  float radius_ = 1;
  bool has_alpha_ = false;  // some material lets rays through (alphaMode MASK or BLEND)
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
