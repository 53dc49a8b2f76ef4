// The ray-query layer: Obscura's only door to Embree. Later code asks `intersect` and `occluded`;
// nothing else calls Embree directly.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include "obscura/math/ray.h"
#include "obscura/math/vector.h"

// Embree's handles, declared here so that its headers stay out of ours.
struct RTCDeviceTy;
struct RTCSceneTy;

namespace obscura {

// One Embree device per process is the recommended use; it owns Embree's thread-local state.
class EmbreeDevice {
 public:
  EmbreeDevice();
  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;

  RTCDeviceTy* handle() const { return device_; }
  // Throws obscura::Error with Embree's message if an error was reported since the last check.
  void throw_if_error(const char* during) const;

 private:
  RTCDeviceTy* device_ = nullptr;
};

struct RayHit {
  float t;                // distance along the ray, in multiples of its direction
  uint32_t geometry_id;   // as returned by add_triangle_mesh
  uint32_t primitive_id;  // triangle index within that mesh
  Point2f barycentric;    // (b1, b2): the hit point is (1−b1−b2)·p0 + b1·p1 + b2·p2
  Vector3f normal;        // the triangle's geometric normal as Embree computed it, not unit;
                          // along (p1 − p0) × (p2 − p0)
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
  // Builds the acceleration structure; call once after adding geometry, before any query.
  void commit();

  // The closest hit with t in [ray.t_min, ray.t_max], if any. Thread-safe after commit().
  std::optional<RayHit> intersect(const Ray& ray) const;
  // Whether anything lies on the ray within [t_min, t_max] (any hit; for shadow rays).
  bool occluded(const Ray& ray) const;

 private:
  std::shared_ptr<const EmbreeDevice> device_;
  RTCSceneTy* scene_ = nullptr;
  bool committed_ = false;
};

}  // namespace obscura
