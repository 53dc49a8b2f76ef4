#include "obscura/camera/animated_transform.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {

struct Quaternion {
  double w = 1, x = 0, y = 0, z = 0;
};

struct Decomposed {
  Vector3d translation;
  Quaternion rotation;
  Vector3d scale;
};

// A rotation matrix (orthonormal, determinant +1) as a unit quaternion (Shepperd's method: take
// the largest of the four candidates to stay away from cancellation).
Quaternion quaternion_from_rotation(const double r[3][3]) {
  double trace = r[0][0] + r[1][1] + r[2][2];
  Quaternion q;
  if (trace > 0) {
    double s = 2 * std::sqrt(trace + 1);
    q = {0.25 * s, (r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s};
  } else if (r[0][0] > r[1][1] && r[0][0] > r[2][2]) {
    double s = 2 * std::sqrt(1 + r[0][0] - r[1][1] - r[2][2]);
    q = {(r[2][1] - r[1][2]) / s, 0.25 * s, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s};
  } else if (r[1][1] > r[2][2]) {
    double s = 2 * std::sqrt(1 + r[1][1] - r[0][0] - r[2][2]);
    q = {(r[0][2] - r[2][0]) / s, (r[0][1] + r[1][0]) / s, 0.25 * s, (r[1][2] + r[2][1]) / s};
  } else {
    double s = 2 * std::sqrt(1 + r[2][2] - r[0][0] - r[1][1]);
    q = {(r[1][0] - r[0][1]) / s, (r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, 0.25 * s};
  }
  double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

Decomposed decompose(const Transform& t, size_t key_index) {
  const auto& m = t.matrix().m;
  auto where = "camera motion key " + number_text(key_index);
  if (m[3][0] != 0 || m[3][1] != 0 || m[3][2] != 0 || m[3][3] != 1)
    throw Error(where, "must be an affine transform (last row 0 0 0 1)");
  Decomposed d;
  d.translation = {m[0][3], m[1][3], m[2][3]};
  Vector3d columns[3];
  for (int c = 0; c < 3; ++c) {
    columns[c] = {m[0][c], m[1][c], m[2][c]};
    d.scale[c] = length(columns[c]);
    if (!(d.scale[c] > 0)) throw Error(where, "has a zero scale");
    columns[c] = columns[c] / d.scale[c];
  }
  if (dot(cross(columns[0], columns[1]), columns[2]) < 0) {  // a mirror: fold it into the scale
    d.scale[2] = -d.scale[2];
    columns[2] = -columns[2];
  }
  constexpr double kShearTolerance = 1e-6;
  if (std::abs(dot(columns[0], columns[1])) > kShearTolerance ||
      std::abs(dot(columns[0], columns[2])) > kShearTolerance ||
      std::abs(dot(columns[1], columns[2])) > kShearTolerance)
    throw Error(where, "has shear; expected translation · rotation · scale");
  double r[3][3];
  for (int row = 0; row < 3; ++row)
    for (int c = 0; c < 3; ++c) r[row][c] = columns[c][row];
  d.rotation = quaternion_from_rotation(r);
  return d;
}

Quaternion slerp(double s, Quaternion a, Quaternion b) {
  double cos_theta = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
  if (cos_theta < 0) {  // q and −q are the same rotation: take the shorter arc
    b = {-b.w, -b.x, -b.y, -b.z};
    cos_theta = -cos_theta;
  }
  double wa, wb;
  if (cos_theta > 0.9995) {  // nearly parallel: lerp, then normalize below
    wa = 1 - s;
    wb = s;
  } else {
    double theta = std::acos(std::min(1.0, cos_theta));
    double sin_theta = std::sin(theta);
    wa = std::sin((1 - s) * theta) / sin_theta;
    wb = std::sin(s * theta) / sin_theta;
  }
  Quaternion q{wa * a.w + wb * b.w, wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z};
  double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

Transform compose(const Decomposed& d) {
  const Quaternion& q = d.rotation;
  double r[3][3] = {
      {1 - 2 * (q.y * q.y + q.z * q.z), 2 * (q.x * q.y - q.w * q.z), 2 * (q.x * q.z + q.w * q.y)},
      {2 * (q.x * q.y + q.w * q.z), 1 - 2 * (q.x * q.x + q.z * q.z), 2 * (q.y * q.z - q.w * q.x)},
      {2 * (q.x * q.z - q.w * q.y), 2 * (q.y * q.z + q.w * q.x), 1 - 2 * (q.x * q.x + q.y * q.y)}};
  Matrix4 m = Matrix4::identity(), m_inv = Matrix4::identity();
  for (int row = 0; row < 3; ++row) {
    for (int c = 0; c < 3; ++c) {
      m[row][c] = r[row][c] * d.scale[c];
      m_inv[c][row] = r[row][c] / d.scale[c];  // (R·S)⁻¹ = S⁻¹·Rᵀ
    }
    m[row][3] = d.translation[row];
  }
  for (int row = 0; row < 3; ++row)
    m_inv[row][3] = -(m_inv[row][0] * d.translation.x + m_inv[row][1] * d.translation.y +
                      m_inv[row][2] * d.translation.z);
  return {m, m_inv};
}

}  // namespace

AnimatedTransform::AnimatedTransform(std::vector<Key> keys) : keys_(std::move(keys)) {
  if (keys_.empty()) throw Error("camera motion", "needs at least one key");
  for (size_t i = 0; i < keys_.size(); ++i) {
    if (!std::isfinite(keys_[i].time_s))
      throw Error("camera motion key " + number_text(i), "time is not finite");
    if (i > 0 && !(keys_[i].time_s > keys_[i - 1].time_s))
      throw Error("camera motion key " + number_text(i),
                  "times must increase; got " + number_text(keys_[i].time_s) + " after " +
                      number_text(keys_[i - 1].time_s));
  }
  if (keys_.size() > 1) {
    for (size_t i = 0; i < keys_.size(); ++i) {
      Decomposed d = decompose(keys_[i].transform, i);  // rejects shear up front
      parts_.push_back(
          {d.translation, {d.rotation.w, d.rotation.x, d.rotation.y, d.rotation.z}, d.scale});
    }
  }
}

Transform AnimatedTransform::at(double time_s) const {
  if (keys_.size() == 1 || time_s <= keys_.front().time_s) return keys_.front().transform;
  if (time_s >= keys_.back().time_s) return keys_.back().transform;
  auto after = std::upper_bound(keys_.begin(), keys_.end(), time_s,
                                [](double t, const Key& k) { return t < k.time_s; });
  size_t i = size_t(after - keys_.begin()) - 1;
  double s = (time_s - keys_[i].time_s) / (keys_[i + 1].time_s - keys_[i].time_s);
  const Parts &a = parts_[i], &b = parts_[i + 1];
  Decomposed d;
  d.translation = a.translation * (1 - s) + b.translation * s;
  d.scale = a.scale * (1 - s) + b.scale * s;
  d.rotation = slerp(s, {a.rotation[0], a.rotation[1], a.rotation[2], a.rotation[3]},
                     {b.rotation[0], b.rotation[1], b.rotation[2], b.rotation[3]});
  return compose(d);
}

}  // namespace obscura
