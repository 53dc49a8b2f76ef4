// Affine and projective transforms of 3D space: a matrix with its inverse.
//
// Name transforms by direction, `b_from_a`, so that `c_from_b * b_from_a` reads as `c_from_a`.
// Angles are in radians.
#pragma once

#include "obscura/math/matrix4.h"
#include "obscura/math/vector.h"

namespace obscura {

class Transform {
 public:
  Transform() = default;
  // Precondition: m is invertible (throws obscura::Error otherwise).
  explicit Transform(const Matrix4& m);
  Transform(const Matrix4& m, const Matrix4& m_inverse) : m_(m), m_inv_(m_inverse) {}

  static Transform translate(Vector3d delta);
  static Transform scale(double sx, double sy, double sz);
  static Transform rotate(double angle_radians, Vector3d axis);
  static Transform rotate_x(double angle_radians);
  static Transform rotate_y(double angle_radians);
  static Transform rotate_z(double angle_radians);
  // The view transform camera_from_world of a camera at `eye` looking at `target`: the camera
  // looks down −Z with +Y as close to `up` as possible (as gluLookAt / glm::lookAt).
  // Preconditions: eye ≠ target, up not parallel to the view direction.
  static Transform look_at(Point3d eye, Point3d target, Vector3d up);

  const Matrix4& matrix() const { return m_; }
  const Matrix4& inverse_matrix() const { return m_inv_; }

  Transform operator*(const Transform& b) const { return {m_ * b.m_, b.m_inv_ * m_inv_}; }
  bool operator==(const Transform&) const = default;

  template <typename T>
  Point3<T> operator()(Point3<T> p) const;
  template <typename T>
  Vector3<T> operator()(Vector3<T> v) const;
  // Normals transform by the inverse transpose so that they stay perpendicular to surfaces.
  template <typename T>
  Normal3<T> operator()(Normal3<T> n) const;
  Vector4d operator()(Vector4d v) const { return m_ * v; }

  bool swaps_handedness() const;  // true when the linear part has a negative determinant

 private:
  Matrix4 m_ = Matrix4::identity();
  Matrix4 m_inv_ = Matrix4::identity();
};

inline Transform inverse(const Transform& t) { return {t.inverse_matrix(), t.matrix()}; }

template <typename T>
Point3<T> Transform::operator()(Point3<T> p) const {
  const auto& m = m_.m;
  double x = p.x, y = p.y, z = p.z;
  double xp = m[0][0] * x + m[0][1] * y + m[0][2] * z + m[0][3];
  double yp = m[1][0] * x + m[1][1] * y + m[1][2] * z + m[1][3];
  double zp = m[2][0] * x + m[2][1] * y + m[2][2] * z + m[2][3];
  double wp = m[3][0] * x + m[3][1] * y + m[3][2] * z + m[3][3];
  if (wp == 1) return Point3<T>(T(xp), T(yp), T(zp));
  return Point3<T>(T(xp / wp), T(yp / wp), T(zp / wp));
}

template <typename T>
Vector3<T> Transform::operator()(Vector3<T> v) const {
  const auto& m = m_.m;
  double x = v.x, y = v.y, z = v.z;
  return Vector3<T>(T(m[0][0] * x + m[0][1] * y + m[0][2] * z),
                    T(m[1][0] * x + m[1][1] * y + m[1][2] * z),
                    T(m[2][0] * x + m[2][1] * y + m[2][2] * z));
}

template <typename T>
Normal3<T> Transform::operator()(Normal3<T> n) const {
  const auto& mi = m_inv_.m;  // (M⁻¹)ᵀ · n: index the inverse by columns
  double x = n.x, y = n.y, z = n.z;
  return Normal3<T>(T(mi[0][0] * x + mi[1][0] * y + mi[2][0] * z),
                    T(mi[0][1] * x + mi[1][1] * y + mi[2][1] * z),
                    T(mi[0][2] * x + mi[1][2] * y + mi[2][2] * z));
}

}  // namespace obscura
