#include "obscura/raster/shadow_map.h"

#include <algorithm>
#include <numbers>

#include "obscura/math/safe_index.h"

namespace obscura::raster {

namespace {

// camera_from_world for an eye at `eye` looking along unit `forward` (−Z in light space).
Matrix4 light_view(Point3f eye, Vector3f forward) {
  Vector3f up = std::abs(forward.y) < 0.99f ? Vector3f(0, 1, 0) : Vector3f(1, 0, 0);
  Vector3f right = normalize(cross(forward, up));
  up = cross(right, forward);
  Vector3f e = to_vector(eye);
  return Matrix4::from_rows({{{right.x, right.y, right.z, -dot(right, e)},
                              {up.x, up.y, up.z, -dot(up, e)},
                              {-forward.x, -forward.y, -forward.z, dot(forward, e)},
                              {0, 0, 0, 1}}});
}

struct Sphere {
  Point3f centre;
  float radius;
};
Sphere bounding_sphere(const Bounds3f& b) {
  Point3f c((b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2, (b.min.z + b.max.z) / 2);
  return {c, std::max(1e-3f, 0.5f * length(b.max - b.min))};
}

}  // namespace

ShadowMap::ShadowMap(const Matrix4& clip_from_world_, int size, float texel_world_,
                     bool perspective_)
    : clip_from_world(clip_from_world_),
      depth(size, size),
      texel_world(texel_world_),
      perspective(perspective_) {
  depth.clear();
}

float ShadowMap::visibility(Point3f p, Vector3f n) const {
  float footprint = texel_world;
  if (perspective) footprint *= std::max(1e-4f, dot(p - light_position, light_axis));
  Point3f q = p + n * (2 * footprint);
  Vector4f clip = clip_from_world(q);
  if (clip.w <= 0) return 1;
  float x = (clip.x / clip.w + 1) * 0.5f * float(depth.width());
  float y = (1 - clip.y / clip.w) * 0.5f * float(depth.height());
  float z = (clip.z / clip.w) * 0.5f + 0.5f;
  if (z >= 1) return 1;
  // 3×3 texels around the one containing (x, y); outside the map counts as lit.
  // NaN-safe (math/safe_index.h); anything clamped far outside the map counts as lit below.
  const int cx = floor_to_index(x), cy = floor_to_index(y);
  int lit = 0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      int tx = cx + dx, ty = cy + dy;
      if (tx < 0 || ty < 0 || tx >= depth.width() || ty >= depth.height() ||
          depth.depth_at(tx, ty) >= z - 1e-5f)
        ++lit;
    }
  return float(lit) / 9;
}

Matrix4 directional_shadow_projection(Vector3f direction, const Bounds3f& bounds, int size,
                                      float* texel_world) {
  Sphere s = bounding_sphere(bounds);
  Point3f eye = s.centre - direction * (2 * s.radius);
  double r = s.radius, near = s.radius, far = 3 * s.radius;
  Matrix4 projection = Matrix4::from_rows({{{1 / r, 0, 0, 0},
                                            {0, 1 / r, 0, 0},
                                            {0, 0, -2 / (far - near), -(far + near) / (far - near)},
                                            {0, 0, 0, 1}}});
  *texel_world = float(2 * r / size);
  return projection * light_view(eye, direction);
}

Matrix4 spot_shadow_projection(Point3f position, Vector3f axis, float outer_radians,
                               const Bounds3f& bounds, int size, float* texel_world) {
  Sphere s = bounding_sphere(bounds);
  double half = std::min<double>(outer_radians, 85 * std::numbers::pi / 180);
  double f = 1 / std::tan(half);
  double far = std::max(1e-2, double(length(s.centre - position)) + s.radius);
  double near = std::max(far * 1e-4, 1e-3 * s.radius);
  Matrix4 projection =
      Matrix4::from_rows({{{f, 0, 0, 0},
                           {0, f, 0, 0},
                           {0, 0, (far + near) / (near - far), 2 * far * near / (near - far)},
                           {0, 0, -1, 0}}});
  *texel_world = float(2 * std::tan(half) / size);
  return projection * light_view(position, axis);
}

}  // namespace obscura::raster
