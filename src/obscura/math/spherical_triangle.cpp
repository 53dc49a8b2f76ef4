#include "obscura/math/spherical_triangle.h"

#include <algorithm>
#include <cmath>

namespace obscura {

namespace {

// The part of v perpendicular to unit n, made unit (zero if v ∥ n).
Vector3d orthonormal_part(Vector3d v, Vector3d n) {
  Vector3d w = v - n * dot(v, n);
  double l = length(w);
  return l > 0 ? w / l : Vector3d();
}

}  // namespace

SphericalTriangle::SphericalTriangle(Point3d p, Point3d p0, Point3d p1, Point3d p2) {
  Vector3d a = p0 - p, b = p1 - p, c = p2 - p;
  double la = length(a), lb = length(b), lc = length(c);
  if (la == 0 || lb == 0 || lc == 0) return;
  a_ = a / la, b_ = b / lb, c_ = c / lc;
  triple_ = std::abs(dot(a_, cross(b_, c_)));
  // atan2 keeps the branch right when the denominator is negative (Ω > π).
  solid_angle_ = 2 * std::atan2(triple_, 1 + dot(a_, b_) + dot(b_, c_) + dot(c_, a_));
}

Vector3d SphericalTriangle::sample(Point2d u) const {
  // The interior angle α at a, between the great circles a–b and a–c, from the planes' normals
  // a × b and a × c without any inverse trigonometry: their dot product is b·c − (a·b)(a·c)
  // (Binet–Cauchy) and their cross product's length |a·(b × c)|.
  const Vector3d &a = a_, &b = b_, &c = c_;
  double ab = dot(a, b), ac = dot(a, c);
  double norms = length(cross(a, b)) * length(cross(a, c));
  if (!(norms > 0)) return a;
  double cos_alpha = (dot(b, c) - ab * ac) / norms, sin_alpha = triple_ / norms;

  // 1. Choose the sub-triangle (a, b, ĉ) with area u₀·Ω: ĉ moves along the arc from a to c.
  //    With s, t = sin, cos of (area − α), Arvo's q is the cosine of the arc a–ĉ.
  double sub_area = u.x * solid_angle_;
  double sin_area = std::sin(sub_area), cos_area = std::cos(sub_area);
  double s = sin_area * cos_alpha - cos_area * sin_alpha;
  double t = cos_area * cos_alpha + sin_area * sin_alpha;
  double uu = t - cos_alpha, vv = s + sin_alpha * ab;  // ab: cosine of the arc a–b
  double denominator = (vv * s + uu * t) * sin_alpha;
  double q = denominator != 0 ? ((vv * t - uu * s) * cos_alpha - vv) / denominator : 1;
  q = std::clamp(q, -1.0, 1.0);
  Vector3d c_hat = a * q + orthonormal_part(c, a) * std::sqrt(std::max(0.0, 1 - q * q));

  // 2. Along the arc from b to ĉ, with the cosine to b uniform in u₁: uniform in solid angle.
  double z = std::clamp(1 - u.y * (1 - dot(c_hat, b)), -1.0, 1.0);
  return normalize(b * z + orthonormal_part(c_hat, b) * std::sqrt(std::max(0.0, 1 - z * z)));
}

double triangle_solid_angle(Point3d p, Point3d p0, Point3d p1, Point3d p2) {
  return SphericalTriangle(p, p0, p1, p2).solid_angle();
}

}  // namespace obscura
