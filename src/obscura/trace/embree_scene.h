// The ray-query layer: Obscura's only door to Embree. Later code asks `intersect` and `occluded`;
// nothing else calls Embree directly.
//
// Geometry comes in two forms: triangle meshes placed directly in the world, and prototypes
// (a mesh built once into its own Embree scene) placed any number of times by instances, each
// with its own transform — or, for motion blur, a transform per Embree time step.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "obscura/math/ray.h"
#include "obscura/math/transform.h"
#include "obscura/math/vector.h"

// Embree's handles, declared here so that its headers stay out of ours.
struct RTCDeviceTy;
struct RTCSceneTy;
struct RTCGeometryTy;

namespace obscura {

struct EmbreeMemoryCount;  // embree_scene.cpp

// One Embree device per process is the recommended use; it owns Embree's thread-local state.
class EmbreeDevice {
 public:
  EmbreeDevice();
  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;

  RTCDeviceTy* handle() const { return device_; }
  // Bytes Embree holds now (acceleration structures and its own geometry buffers; not the
  // buffers it shares with the caller), and the most it held at once since the device was made.
  int64_t memory_bytes() const;
  int64_t peak_memory_bytes() const;
  // Throws obscura::Error with Embree's message if an error was reported since the last check.
  void throw_if_error(const char* during) const;

 private:
  RTCDeviceTy* device_ = nullptr;
  std::unique_ptr<EmbreeMemoryCount> memory_;
};

struct RayHit {
  float t;                // distance along the ray, in multiples of its direction
  uint32_t geometry_id;   // as returned by add_triangle_mesh or add_instance
  uint32_t primitive_id;  // triangle index within that mesh (the prototype's, for an instance)
  Point2f barycentric;    // (b1, b2): the hit point is (1−b1−b2)·p0 + b1·p1 + b2·p2
  Vector3f normal;        // the triangle's geometric normal as Embree computed it, not unit;
                          // along (p1 − p0) × (p2 − p0), in the mesh's own space: object space
                          // when `instanced`, world space otherwise
  bool instanced;         // the hit is on an instance (geometry_id is the instance's id)
};

// An affine world_from_object transform at one moment, as Embree interpolates it: row-major,
// the last column the translation.
struct Affine3f {
  float m[3][4];
};

class EmbreeScene {
 public:
  explicit EmbreeScene(std::shared_ptr<const EmbreeDevice> device);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Copies a triangle mesh into Embree; returns its geometry id (0, 1, 2… in call order).
  // `indices` holds three vertex indices per triangle. Precondition: indices < positions.size().
  uint32_t add_triangle_mesh(std::span<const Point3f> positions, std::span<const uint32_t> indices);
  // The same without the copy: Embree reads `positions` and `indices` where they are, so they
  // must stay unchanged until this scene is destroyed, and `positions` must be followed by 4
  // readable bytes (Embree loads the last vertex 16 bytes at a time).
  uint32_t add_shared_triangle_mesh(std::span<const Point3f> positions,
                                    std::span<const uint32_t> indices);
  // Builds a mesh into an acceleration structure of its own, to be placed by add_instance;
  // returns its prototype index (0, 1, 2… in call order). Same preconditions as above.
  uint32_t add_prototype(std::span<const Point3f> positions, std::span<const uint32_t> indices);
  // A deforming prototype: its vertices at n ≥ 2 (at most kMaxTimeSteps) Embree time steps
  // spread evenly over the motion interval, linearly interpolated between.
  uint32_t add_prototype(std::span<const std::span<const Point3f>> steps,
                         std::span<const uint32_t> indices);
  // Places a prototype in the world; returns the instance's geometry id (shared numbering with
  // add_triangle_mesh). One transform is a static instance; n ≥ 2 (at most kMaxTimeSteps) are
  // Embree time steps spread evenly over the motion interval, linearly interpolated between.
  uint32_t add_instance(uint32_t prototype, std::span<const Transform> world_from_object);
  static constexpr int kMaxTimeSteps = 129;  // Embree's limit
  // The interval (s) that time steps span: a ray's time (s) maps to Embree's [0, 1] over it,
  // clamped. Defaults to [0, 0]: every moving instance holds its first time step.
  // Precondition: close_s ≥ open_s, both finite.
  void set_motion_interval(double open_s, double close_s);
  // Builds the acceleration structure; call after adding geometry, before any query, and again
  // after changing geometry in place (below): Embree then rebuilds what changed.
  void commit();

  // Changing committed geometry in place (no query may run until the next commit()):
  // a shared mesh's positions were rewritten where they lie (the same count),
  void shared_positions_changed(uint32_t geometry_id);
  // a prototype's vertices replaced (the count and time steps it was built with), rebuilding its
  // acceleration structure now and its instances' bounds at commit(),
  void set_prototype_positions(uint32_t prototype, std::span<const std::span<const Point3f>> steps);
  // an instance's transforms replaced (as many time steps as it was made with).
  void set_instance_transforms(uint32_t geometry_id, std::span<const Transform> world_from_object);

  // An instance's world_from_object at `time_s` exactly as traversal used it. Thread-safe after
  // commit(). Precondition: `geometry_id` came from add_instance.
  Affine3f instance_transform(uint32_t geometry_id, float time_s) const;

  // The closest hit with t in [ray.t_min, ray.t_max], if any. Thread-safe after commit().
  std::optional<RayHit> intersect(const Ray& ray) const;
  // Whether anything lies on the ray within [t_min, t_max] (any hit; for shadow rays).
  bool occluded(const Ray& ray) const;

 private:
  std::shared_ptr<const EmbreeDevice> device_;
  float embree_time(float time_s) const;
  uint32_t attach(RTCGeometryTy* geometry, const char* during);

  RTCSceneTy* scene_ = nullptr;
  std::vector<RTCSceneTy*> prototypes_;
  std::vector<RTCGeometryTy*> instances_;      // by geometry id; null for meshes placed directly
  std::vector<uint32_t> instance_prototypes_;  // by geometry id: the prototype an instance places
  std::vector<size_t> instance_steps_;         // by geometry id: an instance's transforms
  std::vector<size_t> prototype_steps_;        // by prototype: its vertices' time steps
  std::vector<size_t> prototype_vertices_;     // by prototype: its vertex count
  std::vector<bool> prototype_changed_;        // since the last commit()
  double time_open_s_ = 0, time_scale_ = 0;    // Embree time = (time − open) · scale
  bool committed_ = false;
};

}  // namespace obscura
