#include "obscura/scene/surface_motion.h"

#include <string>
#include <utility>

#include "obscura/math/error.h"
#include "obscura/scene/deformation_step.h"

namespace obscura {

namespace {

Point3d to_double(Point3f p) {
  return {p.x, p.y, p.z};
}

// Vertex `v` of `mesh` at `time_s`, object space: interpolated between the deformation's time
// steps exactly as Mesh::posed_at does.
Point3d vertex_at(const Mesh& mesh, uint32_t v, double time_s) {
  if (!mesh.deforms()) return to_double(mesh.positions[v]);
  const MeshDeformation& d = mesh.deformation;
  const auto [i, f] = deformation_step(d, d.positions.size(), time_s);
  Point3f a = d.positions[i][v], b = d.positions[i + 1][v];
  return to_double(a + (b - a) * f);
}

}  // namespace

SurfaceMotion::SurfaceMotion(const Scene& scene) : scene_(&scene) {
  motion_.reserve(scene.instances.size());
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    if (!instance.animated()) {
      motion_.emplace_back(instance.world_from_object);
      continue;
    }
    std::vector<AnimatedTransform::Key> keys;
    for (const TransformKey& k : instance.motion)
      keys.push_back({k.time_seconds, k.world_from_object});
    try {
      motion_.emplace_back(std::move(keys));
    } catch (const Error& e) {
      throw Error("instance " + std::to_string(i) + " '" + instance.name + "' motion", e.what());
    }
  }
}

Transform SurfaceMotion::world_from_object(uint32_t instance, double time_s) const {
  return motion_[instance].at(time_s);
}

std::array<Point3d, 3> SurfaceMotion::world_triangle(uint32_t instance, uint32_t triangle,
                                                     double time_s) const {
  const Mesh& mesh = scene_->meshes[scene_->instances[instance].mesh];
  const Transform to_world = world_from_object(instance, time_s);
  std::array<Point3d, 3> world;
  for (int k = 0; k < 3; ++k)
    world[k] = to_world(vertex_at(mesh, mesh.indices[3 * size_t(triangle) + k], time_s));
  return world;
}

Vector3d SurfaceMotion::geometric_normal(uint32_t instance, uint32_t triangle,
                                         double time_s) const {
  const std::array<Point3d, 3> t = world_triangle(instance, triangle, time_s);
  Vector3d n = cross(t[1] - t[0], t[2] - t[0]);
  if (world_from_object(instance, time_s).swaps_handedness()) n = -n;
  const double len = length(n);
  return len > 0 ? n / len : Vector3d();
}

Point3d SurfaceMotion::follow(uint32_t instance, uint32_t triangle, Point3d world, double from_s,
                              double to_s) const {
  const Mesh& mesh = scene_->meshes[scene_->instances[instance].mesh];
  if (!mesh.deforms()) {
    // Rigid: the same object-space point, placed at the other time.
    const Point3d object = inverse(world_from_object(instance, from_s))(world);
    return world_from_object(instance, to_s)(object);
  }
  const std::array<double, 3> b = barycentric(world_triangle(instance, triangle, from_s), world);
  const std::array<Point3d, 3> later = world_triangle(instance, triangle, to_s);
  return Point3d(0, 0, 0) +
         (to_vector(later[0]) * b[0] + to_vector(later[1]) * b[1] + to_vector(later[2]) * b[2]);
}

std::array<double, 3> barycentric(const std::array<Point3d, 3>& t, Point3d p) {
  // Solve p − p0 ≈ b1·e1 + b2·e2 in the least-squares sense (the normal equations).
  const Vector3d e1 = t[1] - t[0], e2 = t[2] - t[0], d = p - t[0];
  const double a11 = dot(e1, e1), a12 = dot(e1, e2), a22 = dot(e2, e2);
  const double r1 = dot(d, e1), r2 = dot(d, e2);
  const double det = a11 * a22 - a12 * a12;
  if (!(det > 0)) return {0, 0, 0};
  const double b1 = (r1 * a22 - r2 * a12) / det, b2 = (r2 * a11 - r1 * a12) / det;
  return {1 - b1 - b2, b1, b2};
}

}  // namespace obscura
