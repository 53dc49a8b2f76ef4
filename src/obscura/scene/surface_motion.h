// Where surface points of a scene are at any time: each instance's motion keys (interpolated as
// the renderers interpolate them, camera/animated_transform.h) and each deforming mesh's time
// steps (scene/deformation_step.h). Ground truth (optical flow) needs it to follow the point a
// pixel sees from one time to another, independently of how a renderer drew it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "obscura/camera/animated_transform.h"
#include "obscura/math/transform.h"
#include "obscura/math/vector.h"
#include "obscura/scene/scene.h"

namespace obscura {

class SurfaceMotion {
 public:
  // Refers to `scene`, which must outlive it and not change. Throws obscura::Error naming the
  // instance whose motion keys are invalid.
  explicit SurfaceMotion(const Scene& scene);

  const Scene& scene() const { return *scene_; }
  // The instance's object→world transform at `time_s`.
  Transform world_from_object(uint32_t instance, double time_s) const;
  // Triangle `triangle` of the instance's mesh in world space at `time_s` (deformation included).
  std::array<Point3d, 3> world_triangle(uint32_t instance, uint32_t triangle, double time_s) const;
  // The triangle's unit geometric normal at `time_s`: the front side of its winding in object
  // space, carried to the world as normals are (so a mirroring placement keeps the side).
  Vector3d geometric_normal(uint32_t instance, uint32_t triangle, double time_s) const;
  // The point `world` on the instance's triangle `triangle` at time `from_s`, carried to time
  // `to_s`: rigidly with the instance, and, for a deforming mesh, at the same barycentric
  // coordinates of the triangle (so it stays the same material point).
  Point3d follow(uint32_t instance, uint32_t triangle, Point3d world, double from_s,
                 double to_s) const;

 private:
  const Scene* scene_;
  std::vector<AnimatedTransform> motion_;  // per instance (a fixed transform when it is static)
};

// Barycentric coordinates (b0, b1, b2) of the point of triangle (p0, p1, p2)'s plane nearest to
// `p`; all zero for a degenerate triangle.
std::array<double, 3> barycentric(const std::array<Point3d, 3>& triangle, Point3d p);

}  // namespace obscura
