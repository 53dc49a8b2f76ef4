#include "obscura/scene/tangents.h"

#include <algorithm>
#include <cmath>

namespace obscura {

namespace {

// Angle at corner p0 of triangle p0 p1 p2 (radians); 0 for a degenerate corner.
float corner_angle(Point3f p0, Point3f p1, Point3f p2) {
  Vector3f a = p1 - p0, b = p2 - p0;
  float la = length(a), lb = length(b);
  if (!(la > 0 && lb > 0)) return 0;
  return std::acos(std::clamp(dot(a, b) / (la * lb), -1.f, 1.f));
}

// The part of `v` perpendicular to unit `n`, normalized; zero when none is left.
Vector3f perpendicular_unit(Vector3f v, Vector3f n) {
  Vector3f p = v - n * dot(n, v);
  float l2 = length_squared(p);
  return l2 > 1e-20f ? p / std::sqrt(l2) : Vector3f();
}

}  // namespace

std::vector<Vector4f> generate_tangents(const Mesh& mesh, uint32_t uv_set) {
  const std::vector<Point2f>& uv = mesh.uv_set(uv_set);
  if (uv.size() != mesh.positions.size() || uv.empty()) return {};
  const size_t n = mesh.positions.size();
  // Per vertex, the sums of the two handednesses separately, with their weights.
  std::vector<Vector3f> sum_right(n), sum_left(n);
  std::vector<float> weight_right(n, 0.f), weight_left(n, 0.f);
  const bool smooth = mesh.normals.size() == n;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const uint32_t* v = &mesh.indices[t];
    Point3f p[3] = {mesh.positions[v[0]], mesh.positions[v[1]], mesh.positions[v[2]]};
    Vector3f e1 = p[1] - p[0], e2 = p[2] - p[0];
    Vector2f d1 = uv[v[1]] - uv[v[0]], d2 = uv[v[2]] - uv[v[0]];
    float det = d1.x * d2.y - d2.x * d1.y;
    Vector3f face = cross(e1, e2);
    float face_length = length(face);
    if (!(std::abs(det) > 1e-20f) || !(face_length > 0)) continue;
    // Solve e = du · ∂p/∂u + dv · ∂p/∂v for the two edges.
    Vector3f dp_du = (e1 * d2.y - e2 * d1.y) / det;
    Vector3f dp_dv = (e2 * d1.x - e1 * d2.x) / det;
    Vector3f face_normal = face / face_length;
    // Right-handed when cross(N, T) runs along −∂p/∂v (image up), as an unmirrored layout.
    bool right = dot(cross(face_normal, dp_du), dp_dv) <= 0;
    for (int k = 0; k < 3; ++k) {
      Vector3f normal = smooth ? to_vector(mesh.normals[v[k]]) : face_normal;
      float l2 = length_squared(normal);
      normal = l2 > 0 ? normal / std::sqrt(l2) : face_normal;
      Vector3f tangent = perpendicular_unit(dp_du, normal);
      float angle = corner_angle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
      if (right) {
        sum_right[v[k]] += tangent * angle;
        weight_right[v[k]] += angle;
      } else {
        sum_left[v[k]] += tangent * angle;
        weight_left[v[k]] += angle;
      }
    }
  }
  std::vector<Vector4f> tangents(n);
  for (size_t i = 0; i < n; ++i) {
    bool right = weight_right[i] >= weight_left[i];
    Vector3f sum = right ? sum_right[i] : sum_left[i];
    Vector3f normal = smooth ? to_vector(mesh.normals[i]) : Vector3f();
    float l2 = length_squared(normal);
    Vector3f t;
    if (l2 > 0) {
      normal = normal / std::sqrt(l2);
      t = perpendicular_unit(sum, normal);
      if (t == Vector3f()) {
        Vector3f other;
        coordinate_system(normal, &t, &other);
      }
    } else {
      float s2 = length_squared(sum);
      t = s2 > 0 ? sum / std::sqrt(s2) : Vector3f(1, 0, 0);
    }
    tangents[i] = {t.x, t.y, t.z, right ? 1.f : -1.f};
  }
  return tangents;
}

}  // namespace obscura
