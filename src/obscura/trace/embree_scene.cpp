#include "obscura/trace/embree_scene.h"

#include <cstring>
#include <limits>
#include <mutex>
#include <string>

#include <embree3/rtcore.h>

#include "obscura/math/error.h"

namespace obscura {

namespace {

// Embree reports errors through a callback; keep the first message until it is checked.
struct ErrorSlot {
  std::mutex mutex;
  std::string message;
};

void on_embree_error(void* user, RTCError code, const char* message) {
  auto* slot = static_cast<ErrorSlot*>(user);
  std::lock_guard lock(slot->mutex);
  if (slot->message.empty())
    slot->message = "Embree error " + std::to_string(int(code)) + ": " + (message ? message : "");
}

ErrorSlot& error_slot() {
  static ErrorSlot slot;
  return slot;
}

RTCRay to_rtc_ray(const Ray& ray) {
  RTCRay r;
  r.org_x = ray.origin.x, r.org_y = ray.origin.y, r.org_z = ray.origin.z;
  r.dir_x = ray.direction.x, r.dir_y = ray.direction.y, r.dir_z = ray.direction.z;
  r.tnear = ray.t_min;
  r.tfar = ray.t_max;
  r.time = ray.time;
  r.mask = std::numeric_limits<unsigned>::max();
  r.id = 0;
  r.flags = 0;
  return r;
}

}  // namespace

EmbreeDevice::EmbreeDevice() {
  device_ = rtcNewDevice(nullptr);
  if (!device_)
    throw Error("cannot create the Embree device (error " +
                std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
  rtcSetDeviceErrorFunction(device_, on_embree_error, &error_slot());
}

EmbreeDevice::~EmbreeDevice() {
  rtcReleaseDevice(device_);
}

void EmbreeDevice::throw_if_error(const char* during) const {
  ErrorSlot& slot = error_slot();
  std::lock_guard lock(slot.mutex);
  if (slot.message.empty()) return;
  std::string message = std::move(slot.message);
  slot.message.clear();
  throw Error(std::string(during) + ": " + message);
}

EmbreeScene::EmbreeScene(std::shared_ptr<const EmbreeDevice> device) : device_(std::move(device)) {
  scene_ = rtcNewScene(device_->handle());
  // Robust traversal: watertight against rays through shared edges and vertices.
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  device_->throw_if_error("creating the Embree scene");
}

EmbreeScene::~EmbreeScene() {
  rtcReleaseScene(scene_);
}

uint32_t EmbreeScene::add_triangle_mesh(std::span<const Point3f> positions,
                                        std::span<const uint32_t> indices) {
  if (committed_) throw Error("EmbreeScene: geometry added after commit()");
  if (indices.size() % 3 != 0)
    throw Error("triangle mesh index count " + std::to_string(indices.size()) +
                " is not a multiple of 3");
  for (uint32_t i : indices)
    if (i >= positions.size())
      throw Error("triangle mesh index " + std::to_string(i) + " is past the vertex count " +
                  std::to_string(positions.size()));
  RTCGeometry geometry = rtcNewGeometry(device_->handle(), RTC_GEOMETRY_TYPE_TRIANGLE);
  // Embree may read 16 bytes at the last vertex, so its own buffers (padded) are used.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), positions.size()));
  auto* triangles = static_cast<uint32_t*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(uint32_t), indices.size() / 3));
  device_->throw_if_error("allocating Embree geometry buffers");
  for (size_t i = 0; i < positions.size(); ++i) {
    vertices[3 * i + 0] = positions[i].x;
    vertices[3 * i + 1] = positions[i].y;
    vertices[3 * i + 2] = positions[i].z;
  }
  std::memcpy(triangles, indices.data(), indices.size_bytes());
  rtcCommitGeometry(geometry);
  uint32_t id = rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
  device_->throw_if_error("adding a triangle mesh");
  return id;
}

void EmbreeScene::commit() {
  rtcCommitScene(scene_);
  device_->throw_if_error("building the Embree scene");
  committed_ = true;
}

std::optional<RayHit> EmbreeScene::intersect(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query;
  query.ray = to_rtc_ray(ray);
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  // Embree's Ng is e2 × e1 with e1 = p0 − p1, e2 = p2 − p0, i.e. (p1 − p0) × (p2 − p0).
  return RayHit{query.ray.tfar,
                query.hit.geomID,
                query.hit.primID,
                {query.hit.u, query.hit.v},
                {query.hit.Ng_x, query.hit.Ng_y, query.hit.Ng_z}};
}

bool EmbreeScene::occluded(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay query = to_rtc_ray(ray);
  rtcOccluded1(scene_, &context, &query);
  return query.tfar < 0;  // Embree sets tfar to −∞ on a hit
}

}  // namespace obscura
