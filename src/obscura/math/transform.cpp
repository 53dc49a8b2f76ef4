#include "obscura/math/transform.h"

#include <cmath>

#include "obscura/math/error.h"

namespace obscura {

Transform::Transform(const Matrix4& m) : m_(m) {
  auto inv = inverse(m);
  if (!inv) throw Error("transform matrix is singular; expected an invertible 4x4 matrix");
  m_inv_ = *inv;
}

Transform Transform::translate(Vector3d d) {
  Matrix4 m = Matrix4::identity(), mi = Matrix4::identity();
  m[0][3] = d.x, m[1][3] = d.y, m[2][3] = d.z;
  mi[0][3] = -d.x, mi[1][3] = -d.y, mi[2][3] = -d.z;
  return {m, mi};
}

Transform Transform::scale(double sx, double sy, double sz) {
  if (sx == 0 || sy == 0 || sz == 0)
    throw Error("scale factors must be non-zero; got (" + std::to_string(sx) + ", " +
                std::to_string(sy) + ", " + std::to_string(sz) + ")");
  Matrix4 m = Matrix4::identity(), mi = Matrix4::identity();
  m[0][0] = sx, m[1][1] = sy, m[2][2] = sz;
  mi[0][0] = 1 / sx, mi[1][1] = 1 / sy, mi[2][2] = 1 / sz;
  return {m, mi};
}

Transform Transform::rotate(double angle, Vector3d axis) {
  // Rodrigues' rotation formula, counter-clockwise about `axis` when it points at the viewer.
  Vector3d a = normalize(axis);
  double s = std::sin(angle), c = std::cos(angle), t = 1 - c;
  Matrix4 m = Matrix4::identity();
  m[0][0] = a.x * a.x * t + c;
  m[0][1] = a.x * a.y * t - a.z * s;
  m[0][2] = a.x * a.z * t + a.y * s;
  m[1][0] = a.x * a.y * t + a.z * s;
  m[1][1] = a.y * a.y * t + c;
  m[1][2] = a.y * a.z * t - a.x * s;
  m[2][0] = a.x * a.z * t - a.y * s;
  m[2][1] = a.y * a.z * t + a.x * s;
  m[2][2] = a.z * a.z * t + c;
  return {m, transpose(m)};  // a rotation's inverse is its transpose
}

Transform Transform::rotate_x(double angle) { return rotate(angle, {1, 0, 0}); }
Transform Transform::rotate_y(double angle) { return rotate(angle, {0, 1, 0}); }
Transform Transform::rotate_z(double angle) { return rotate(angle, {0, 0, 1}); }

Transform Transform::look_at(Point3d eye, Point3d target, Vector3d up) {
  Vector3d view = target - eye;
  if (length(view) == 0) throw Error("look-at: eye and target are the same point");
  Vector3d forward = normalize(view);
  Vector3d right_unnormalized = cross(forward, up);
  if (length(right_unnormalized) < 1e-12 * length(up) || length(up) == 0)
    throw Error("look-at: the up vector is zero or parallel to the view direction");
  Vector3d right = normalize(right_unnormalized);
  Vector3d true_up = cross(right, forward);
  // world_from_camera has the camera axes as columns: X = right, Y = up, Z = −forward.
  Matrix4 world_from_camera = Matrix4::from_rows({{{right.x, true_up.x, -forward.x, eye.x},
                                                   {right.y, true_up.y, -forward.y, eye.y},
                                                   {right.z, true_up.z, -forward.z, eye.z},
                                                   {0, 0, 0, 1}}});
  Matrix4 camera_from_world = Matrix4::from_rows(
      {{{right.x, right.y, right.z, -dot(right, to_vector(eye))},
        {true_up.x, true_up.y, true_up.z, -dot(true_up, to_vector(eye))},
        {-forward.x, -forward.y, -forward.z, dot(forward, to_vector(eye))},
        {0, 0, 0, 1}}});
  return {camera_from_world, world_from_camera};
}

bool Transform::swaps_handedness() const {
  const auto& m = m_.m;
  double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return det < 0;
}

}  // namespace obscura
