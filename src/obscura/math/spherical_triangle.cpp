#include "obscura/math/spherical_triangle.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace obscura {

namespace {

// The angle between two vectors, by atan2 (accurate near 0 and π, unlike acos of a dot).
double angle_between(Vector3d a, Vector3d b) {
  return std::atan2(length(cross(a, b)), dot(a, b));
}

// The part of v perpendicular to unit n, made unit (zero if v ∥ n).
Vector3d orthonormal_part(Vector3d v, Vector3d n) {
  Vector3d w = v - n * dot(v, n);
  double l = length(w);
  return l > 0 ? w / l : Vector3d();
}

}  // namespace

double triangle_solid_angle(Point3d p, Point3d p0, Point3d p1, Point3d p2) {
  Vector3d a = p0 - p, b = p1 - p, c = p2 - p;
  double la = length(a), lb = length(b), lc = length(c);
  if (la == 0 || lb == 0 || lc == 0) return 0;
  a = a / la, b = b / lb, c = c / lc;
  double numerator = std::abs(dot(a, cross(b, c)));
  double denominator = 1 + dot(a, b) + dot(b, c) + dot(c, a);
  // atan2 keeps the branch right when the denominator is negative (Ω > π).
  return 2 * std::atan2(numerator, denominator);
}

Vector3d sample_spherical_triangle(Point3d p, Point3d p0, Point3d p1, Point3d p2, Point2d u) {
  const Vector3d a = normalize(p0 - p), b = normalize(p1 - p), c = normalize(p2 - p);
  // Interior angles at the vertices: between the great circles' planes through each vertex.
  Vector3d n_ab = cross(a, b), n_bc = cross(b, c), n_ca = cross(c, a);
  double alpha = angle_between(n_ab, -n_ca);              // at a: planes (a, b) and (a, c)
  double beta = angle_between(n_bc, -n_ab);               // at b: planes (b, c) and (b, a)
  double gamma = angle_between(n_ca, -n_bc);              // at c: planes (c, a) and (c, b)
  double area = alpha + beta + gamma - std::numbers::pi;  // Girard's theorem

  // 1. Choose the sub-triangle (a, b, ĉ) with area u₀·Ω: ĉ moves along the arc from a to c.
  double sub_area = u.x * area;
  double s = std::sin(sub_area - alpha), t = std::cos(sub_area - alpha);
  double cos_alpha = std::cos(alpha), sin_alpha = std::sin(alpha);
  double uu = t - cos_alpha;
  double vv = s + sin_alpha * dot(a, b);  // dot(a, b): cosine of the arc a–b
  double denominator = (vv * s + uu * t) * sin_alpha;
  double q = denominator != 0 ? ((vv * t - uu * s) * cos_alpha - vv) / denominator : 1;
  q = std::clamp(q, -1.0, 1.0);
  Vector3d c_hat = a * q + orthonormal_part(c, a) * std::sqrt(std::max(0.0, 1 - q * q));

  // 2. Along the arc from b to ĉ, with the cosine to b uniform: uniform in solid angle.
  double z = 1 - u.y * (1 - dot(c_hat, b));
  z = std::clamp(z, -1.0, 1.0);
  return normalize(b * z + orthonormal_part(c_hat, b) * std::sqrt(std::max(0.0, 1 - z * z)));
}

}  // namespace obscura
