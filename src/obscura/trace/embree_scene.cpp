#include "obscura/trace/embree_scene.h"

#include <algorithm>
#include <atomic>
#include <cmath>
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

RTCRay to_rtc_ray(const Ray& ray, float embree_time) {
  RTCRay r;
  r.org_x = ray.origin.x, r.org_y = ray.origin.y, r.org_z = ray.origin.z;
  r.dir_x = ray.direction.x, r.dir_y = ray.direction.y, r.dir_z = ray.direction.z;
  r.tnear = ray.t_min;
  r.tfar = ray.t_max;
  r.time = embree_time;
  r.mask = std::numeric_limits<unsigned>::max();
  r.id = 0;
  r.flags = 0;
  return r;
}

}  // namespace

struct EmbreeMemoryCount {
  std::atomic<int64_t> now{0}, peak{0};
};

namespace {

// Embree reports each allocation (bytes > 0) and release (bytes < 0) of its own memory.
bool on_embree_memory(void* user, ssize_t bytes, bool /*post*/) {
  auto* count = static_cast<EmbreeMemoryCount*>(user);
  int64_t now = count->now.fetch_add(int64_t(bytes), std::memory_order_relaxed) + int64_t(bytes);
  int64_t peak = count->peak.load(std::memory_order_relaxed);
  while (now > peak && !count->peak.compare_exchange_weak(peak, now, std::memory_order_relaxed)) {
  }
  return true;  // never refuse an allocation
}

}  // namespace

EmbreeDevice::EmbreeDevice() : memory_(std::make_unique<EmbreeMemoryCount>()) {
  device_ = rtcNewDevice(nullptr);
  if (!device_)
    throw Error("cannot create the Embree device (error " +
                std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
  rtcSetDeviceErrorFunction(device_, on_embree_error, &error_slot());
  rtcSetDeviceMemoryMonitorFunction(device_, on_embree_memory, memory_.get());
}

int64_t EmbreeDevice::memory_bytes() const {
  return memory_->now.load();
}

int64_t EmbreeDevice::peak_memory_bytes() const {
  return memory_->peak.load();
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

namespace {

static_assert(sizeof(Point3f) == 3 * sizeof(float), "Embree reads Point3f arrays as FLOAT3");

void check_triangle_indices(size_t vertex_count, std::span<const uint32_t> indices) {
  if (indices.size() % 3 != 0)
    throw Error("triangle mesh index count " + std::to_string(indices.size()) +
                " is not a multiple of 3");
  for (uint32_t i : indices)
    if (i >= vertex_count)
      throw Error("triangle mesh index " + std::to_string(i) + " is past the vertex count " +
                  std::to_string(vertex_count));
}

// A committed triangle geometry holding copies of the mesh (not yet attached to a scene), with
// one vertex buffer per Embree time step (one for a still mesh).
RTCGeometry new_triangle_geometry(const EmbreeDevice& device,
                                  std::span<const std::span<const Point3f>> steps,
                                  std::span<const uint32_t> indices) {
  if (steps.empty() || steps.size() > size_t(EmbreeScene::kMaxTimeSteps))
    throw Error("a triangle mesh needs 1 to " + std::to_string(EmbreeScene::kMaxTimeSteps) +
                " time steps; got " + std::to_string(steps.size()));
  const std::span<const Point3f> positions = steps.front();
  for (std::span<const Point3f> step : steps)
    if (step.size() != positions.size())
      throw Error("triangle mesh time steps differ in vertex count");
  check_triangle_indices(positions.size(), indices);
  RTCGeometry geometry = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetGeometryTimeStepCount(geometry, unsigned(steps.size()));
  // Embree may read 16 bytes at the last vertex, so its own buffers (padded) are used.
  for (size_t s = 0; s < steps.size(); ++s) {
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, unsigned(s), RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), positions.size()));
    device.throw_if_error("allocating Embree geometry buffers");
    for (size_t i = 0; i < positions.size(); ++i) {
      vertices[3 * i + 0] = steps[s][i].x;
      vertices[3 * i + 1] = steps[s][i].y;
      vertices[3 * i + 2] = steps[s][i].z;
    }
  }
  auto* triangles = static_cast<uint32_t*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(uint32_t), indices.size() / 3));
  device.throw_if_error("allocating Embree geometry buffers");
  std::memcpy(triangles, indices.data(), indices.size_bytes());
  rtcCommitGeometry(geometry);
  return geometry;
}

RTCScene new_scene(const EmbreeDevice& device) {
  RTCScene scene = rtcNewScene(device.handle());
  // Robust traversal: watertight against rays through shared edges and vertices.
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  return scene;
}

}  // namespace

EmbreeScene::EmbreeScene(std::shared_ptr<const EmbreeDevice> device) : device_(std::move(device)) {
  scene_ = new_scene(*device_);
  device_->throw_if_error("creating the Embree scene");
}

EmbreeScene::~EmbreeScene() {
  for (RTCGeometry g : instances_)
    if (g) rtcReleaseGeometry(g);
  rtcReleaseScene(scene_);
  for (RTCScene s : prototypes_) rtcReleaseScene(s);
}

uint32_t EmbreeScene::attach(RTCGeometry geometry, const char* during) {
  uint32_t id = rtcAttachGeometry(scene_, geometry);
  device_->throw_if_error(during);
  if (instances_.size() <= id) {
    instances_.resize(id + 1, nullptr);
    instance_prototypes_.resize(id + 1, 0);
    instance_steps_.resize(id + 1, 0);
  }
  return id;
}

uint32_t EmbreeScene::add_triangle_mesh(std::span<const Point3f> positions,
                                        std::span<const uint32_t> indices) {
  if (committed_) throw Error("EmbreeScene: geometry added after commit()");
  const std::span<const Point3f> steps[1] = {positions};
  RTCGeometry geometry = new_triangle_geometry(*device_, steps, indices);
  uint32_t id = attach(geometry, "adding a triangle mesh");
  rtcReleaseGeometry(geometry);
  return id;
}

uint32_t EmbreeScene::add_shared_triangle_mesh(std::span<const Point3f> positions,
                                               std::span<const uint32_t> indices) {
  if (committed_) throw Error("EmbreeScene: geometry added after commit()");
  check_triangle_indices(positions.size(), indices);
  RTCGeometry geometry = rtcNewGeometry(device_->handle(), RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                             positions.data(), 0, sizeof(Point3f), positions.size());
  rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, indices.data(),
                             0, 3 * sizeof(uint32_t), indices.size() / 3);
  device_->throw_if_error("sharing buffers with Embree");
  rtcCommitGeometry(geometry);
  uint32_t id = attach(geometry, "adding a triangle mesh");
  rtcReleaseGeometry(geometry);
  return id;
}

uint32_t EmbreeScene::add_prototype(std::span<const Point3f> positions,
                                    std::span<const uint32_t> indices) {
  const std::span<const Point3f> steps[1] = {positions};
  return add_prototype(steps, indices);
}

uint32_t EmbreeScene::add_prototype(std::span<const std::span<const Point3f>> steps,
                                    std::span<const uint32_t> indices) {
  if (committed_) throw Error("EmbreeScene: geometry added after commit()");
  RTCGeometry geometry = new_triangle_geometry(*device_, steps, indices);
  RTCScene prototype = new_scene(*device_);
  prototypes_.push_back(prototype);
  prototype_changed_.push_back(false);
  prototype_steps_.push_back(steps.size());
  prototype_vertices_.push_back(steps.front().size());
  rtcAttachGeometry(prototype, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(prototype);  // instances need their scene built before the top level is
  device_->throw_if_error("building an instanced mesh");
  return uint32_t(prototypes_.size() - 1);
}

uint32_t EmbreeScene::add_instance(uint32_t prototype,
                                   std::span<const Transform> world_from_object) {
  if (committed_) throw Error("EmbreeScene: geometry added after commit()");
  if (prototype >= prototypes_.size())
    throw Error("instance of prototype " + std::to_string(prototype) + " of " +
                std::to_string(prototypes_.size()));
  if (world_from_object.empty() || world_from_object.size() > size_t(kMaxTimeSteps))
    throw Error("an instance needs 1 to " + std::to_string(kMaxTimeSteps) + " transforms; got " +
                std::to_string(world_from_object.size()));
  RTCGeometry geometry = rtcNewGeometry(device_->handle(), RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(geometry, prototypes_[prototype]);
  rtcSetGeometryTimeStepCount(geometry, unsigned(world_from_object.size()));
  for (size_t step = 0; step < world_from_object.size(); ++step) {
    const auto& m = world_from_object[step].matrix().m;
    float rows[3][4];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) rows[r][c] = float(m[r][c]);
    rtcSetGeometryTransform(geometry, unsigned(step), RTC_FORMAT_FLOAT3X4_ROW_MAJOR, rows);
  }
  rtcCommitGeometry(geometry);
  uint32_t id = attach(geometry, "adding an instance");
  instances_[id] = geometry;  // kept (not released) for instance_transform()
  instance_prototypes_[id] = prototype;
  instance_steps_[id] = world_from_object.size();
  return id;
}

void EmbreeScene::set_motion_interval(double open_s, double close_s) {
  if (!(std::isfinite(open_s) && std::isfinite(close_s) && close_s >= open_s))
    throw Error("motion interval", "needs finite open ≤ close; got [" + std::to_string(open_s) +
                                       ", " + std::to_string(close_s) + "] s");
  time_open_s_ = open_s;
  time_scale_ = close_s > open_s ? 1 / (close_s - open_s) : 0;
}

float EmbreeScene::embree_time(float time_s) const {
  return std::clamp(float((time_s - time_open_s_) * time_scale_), 0.f, 1.f);
}

void EmbreeScene::commit() {
  // Instances of a prototype rebuilt since the last commit take its new bounds.
  for (size_t id = 0; id < instances_.size(); ++id)
    if (instances_[id] && prototype_changed_[instance_prototypes_[id]])
      rtcCommitGeometry(instances_[id]);
  std::fill(prototype_changed_.begin(), prototype_changed_.end(), false);
  rtcCommitScene(scene_);
  device_->throw_if_error("building the Embree scene");
  committed_ = true;
}

void EmbreeScene::shared_positions_changed(uint32_t geometry_id) {
  RTCGeometry geometry = rtcGetGeometry(scene_, geometry_id);
  device_->throw_if_error("finding a changed mesh");
  if (!geometry || instances_[geometry_id])
    throw Error("EmbreeScene: geometry " + std::to_string(geometry_id) + " is no shared mesh");
  rtcUpdateGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0);
  rtcCommitGeometry(geometry);
}

void EmbreeScene::set_prototype_positions(uint32_t prototype,
                                          std::span<const std::span<const Point3f>> steps) {
  if (prototype >= prototypes_.size())
    throw Error("EmbreeScene: prototype " + std::to_string(prototype) + " of " +
                std::to_string(prototypes_.size()));
  RTCGeometry geometry = rtcGetGeometry(prototypes_[prototype], 0);
  if (prototype_steps_[prototype] != steps.size())
    throw Error("EmbreeScene: a prototype's new vertices have another number of time steps");
  for (size_t s = 0; s < steps.size(); ++s) {
    auto* vertices = static_cast<float*>(
        rtcGetGeometryBufferData(geometry, RTC_BUFFER_TYPE_VERTEX, unsigned(s)));
    // The buffer was made for the prototype's vertex count; a count that differs cannot go in.
    if (steps[s].size() != prototype_vertices_[prototype])
      throw Error("EmbreeScene: a prototype's new vertices differ in count");
    for (size_t i = 0; i < steps[s].size(); ++i) {
      vertices[3 * i + 0] = steps[s][i].x;
      vertices[3 * i + 1] = steps[s][i].y;
      vertices[3 * i + 2] = steps[s][i].z;
    }
    rtcUpdateGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, unsigned(s));
  }
  rtcCommitGeometry(geometry);
  rtcCommitScene(prototypes_[prototype]);
  device_->throw_if_error("rebuilding an instanced mesh");
  prototype_changed_[prototype] = true;
}

void EmbreeScene::set_instance_transforms(uint32_t geometry_id,
                                          std::span<const Transform> world_from_object) {
  if (geometry_id >= instances_.size() || !instances_[geometry_id] ||
      instance_steps_[geometry_id] != world_from_object.size())
    throw Error("EmbreeScene: geometry " + std::to_string(geometry_id) + " is no instance of " +
                std::to_string(world_from_object.size()) + " time steps");
  for (size_t step = 0; step < world_from_object.size(); ++step) {
    const auto& m = world_from_object[step].matrix().m;
    float rows[3][4];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) rows[r][c] = float(m[r][c]);
    rtcSetGeometryTransform(instances_[geometry_id], unsigned(step), RTC_FORMAT_FLOAT3X4_ROW_MAJOR,
                            rows);
  }
  rtcCommitGeometry(instances_[geometry_id]);
}

Affine3f EmbreeScene::instance_transform(uint32_t geometry_id, float time_s) const {
  Affine3f a;
  rtcGetGeometryTransform(instances_[geometry_id], embree_time(time_s),
                          RTC_FORMAT_FLOAT3X4_ROW_MAJOR, a.m);
  return a;
}

std::optional<RayHit> EmbreeScene::intersect(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query;
  query.ray = to_rtc_ray(ray, embree_time(ray.time));
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  // Embree's Ng is e2 × e1 with e1 = p0 − p1, e2 = p2 − p0, i.e. (p1 − p0) × (p2 − p0), in the
  // space of the mesh hit (object space inside an instance). Instances are one level deep.
  bool instanced = query.hit.instID[0] != RTC_INVALID_GEOMETRY_ID;
  return RayHit{query.ray.tfar,
                instanced ? query.hit.instID[0] : query.hit.geomID,
                query.hit.primID,
                {query.hit.u, query.hit.v},
                {query.hit.Ng_x, query.hit.Ng_y, query.hit.Ng_z},
                instanced};
}

bool EmbreeScene::occluded(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay query = to_rtc_ray(ray, embree_time(ray.time));
  rtcOccluded1(scene_, &context, &query);
  return query.tfar < 0;  // Embree sets tfar to −∞ on a hit
}

}  // namespace obscura
