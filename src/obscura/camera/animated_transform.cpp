#include "obscura/camera/animated_transform.h"

#include <algorithm>
#include <array>
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
  // A key with shear: M = T · R · S with S the full stretch matrix (row-major; scale unused).
  bool sheared = false;
  double stretch[3][3] = {};
};

using Matrix3 = std::array<std::array<double, 3>, 3>;

double determinant(const Matrix3& a) {
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
         a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

// The inverse through cofactors; the caller has checked the determinant.
Matrix3 inverse(const Matrix3& a) {
  const double inv_det = 1 / determinant(a);
  Matrix3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
      r[i][j] = (a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]) * inv_det;
    }
  return r;
}

// The rotation of M's polar decomposition M = R · S (S symmetric, positive definite for
// det M > 0), by Higham's iteration R ← (R + R⁻ᵀ) / 2, which converges quadratically from R = M.
Matrix3 polar_rotation(Matrix3 r) {
  for (int iteration = 0; iteration < 100; ++iteration) {
    const Matrix3 inv = inverse(r);
    double change = 0;
    Matrix3 next;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        next[i][j] = 0.5 * (r[i][j] + inv[j][i]);
        change = std::max(change, std::abs(next[i][j] - r[i][j]));
      }
    r = next;
    if (change < 1e-15) break;
  }
  return r;
}

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
  auto where = "motion key " + number_text(key_index);
  if (m[3][0] != 0 || m[3][1] != 0 || m[3][2] != 0 || m[3][3] != 1)
    throw Error(where, "must be an affine transform (last row 0 0 0 1)");
  Decomposed d;
  d.translation = {m[0][3], m[1][3], m[2][3]};
  Vector3d columns[3];
  for (int c = 0; c < 3; ++c) {
    columns[c] = {m[0][c], m[1][c], m[2][c]};
    d.scale[c] = length(columns[c]);
    if (!(d.scale[c] > 0) || !std::isfinite(d.scale[c]))
      throw Error(where, "has a zero or non-finite scale");
    columns[c] = columns[c] / d.scale[c];
  }
  if (dot(cross(columns[0], columns[1]), columns[2]) < 0) {  // a mirror: fold it into the scale
    d.scale[2] = -d.scale[2];
    columns[2] = -columns[2];
  }
  // Columns at right angles: M = T · R · diag(scale), the common case. Otherwise the key has
  // shear — a non-uniform scale under a rotation in a node hierarchy makes some, and exporters'
  // float noise (scales of 0.99997) makes a little — and M = T · R · S with the full stretch S of
  // the polar decomposition (as Shoemake and Duff interpolate).
  constexpr double kShearTolerance = 1e-6;
  const bool square = std::abs(dot(columns[0], columns[1])) <= kShearTolerance &&
                      std::abs(dot(columns[0], columns[2])) <= kShearTolerance &&
                      std::abs(dot(columns[1], columns[2])) <= kShearTolerance;
  double r[3][3];
  if (square) {
    for (int row = 0; row < 3; ++row)
      for (int c = 0; c < 3; ++c) r[row][c] = columns[c][row];
  } else {
    Matrix3 linear;
    for (int row = 0; row < 3; ++row)
      for (int c = 0; c < 3; ++c) linear[row][c] = m[row][c];
    const double det = determinant(linear);
    if (!(std::abs(det) > 0) || !std::isfinite(det)) throw Error(where, "is singular");
    // A mirror is kept out of the rotation: decompose M · diag(1, 1, −1), whose stretch takes
    // the mirror back below (S = Rᵀ · M).
    Matrix3 proper = linear;
    if (det < 0)
      for (int row = 0; row < 3; ++row) proper[row][2] = -proper[row][2];
    const Matrix3 rotation = polar_rotation(proper);
    for (int row = 0; row < 3; ++row)
      for (int c = 0; c < 3; ++c) {
        r[row][c] = rotation[row][c];
        double s = 0;
        for (int k = 0; k < 3; ++k) s += rotation[k][row] * linear[k][c];
        d.stretch[row][c] = s;
      }
    d.sheared = true;
  }
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
  if (d.sheared) {
    // M = R · S and M⁻¹ = S⁻¹ · Rᵀ.
    Matrix3 stretch;
    for (int row = 0; row < 3; ++row)
      for (int c = 0; c < 3; ++c) stretch[row][c] = d.stretch[row][c];
    const Matrix3 stretch_inv = inverse(stretch);
    for (int row = 0; row < 3; ++row)
      for (int c = 0; c < 3; ++c) {
        double v = 0, v_inv = 0;
        for (int k = 0; k < 3; ++k) {
          v += r[row][k] * stretch[k][c];
          v_inv += stretch_inv[row][k] * r[c][k];
        }
        m[row][c] = v;
        m_inv[row][c] = v_inv;
      }
  } else {
    for (int row = 0; row < 3; ++row)
      for (int c = 0; c < 3; ++c) {
        m[row][c] = r[row][c] * d.scale[c];
        m_inv[c][row] = r[row][c] / d.scale[c];  // (R·S)⁻¹ = S⁻¹·Rᵀ
      }
  }
  for (int row = 0; row < 3; ++row) m[row][3] = d.translation[row];
  for (int row = 0; row < 3; ++row)
    m_inv[row][3] = -(m_inv[row][0] * d.translation.x + m_inv[row][1] * d.translation.y +
                      m_inv[row][2] * d.translation.z);
  return {m, m_inv};
}

}  // namespace

AnimatedTransform::AnimatedTransform(std::vector<Key> keys) : keys_(std::move(keys)) {
  if (keys_.empty()) throw Error("motion", "needs at least one key");
  for (size_t i = 0; i < keys_.size(); ++i) {
    if (!std::isfinite(keys_[i].time_s))
      throw Error("motion key " + number_text(i), "time is not finite");
    if (i > 0 && !(keys_[i].time_s > keys_[i - 1].time_s))
      throw Error("motion key " + number_text(i), "times must increase; got " +
                                                      number_text(keys_[i].time_s) + " after " +
                                                      number_text(keys_[i - 1].time_s));
  }
  if (keys_.size() > 1) {
    for (size_t i = 0; i < keys_.size(); ++i) {
      const Decomposed d = decompose(keys_[i].transform, i);
      Parts parts{d.translation,
                  {d.rotation.w, d.rotation.x, d.rotation.y, d.rotation.z},
                  d.scale,
                  d.sheared,
                  {}};
      for (int row = 0; row < 3; ++row)
        for (int c = 0; c < 3; ++c)
          parts.stretch[row][c] = d.sheared ? d.stretch[row][c] : (row == c ? d.scale[c] : 0.0);
      parts_.push_back(parts);
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
  // Between keys of which one has shear, the stretch matrices interpolate entry by entry (a
  // shear-free key's is its diagonal scale).
  d.sheared = a.sheared || b.sheared;
  if (d.sheared)
    for (int row = 0; row < 3; ++row)
      for (int c = 0; c < 3; ++c)
        d.stretch[row][c] = a.stretch[row][c] * (1 - s) + b.stretch[row][c] * s;
  d.rotation = slerp(s, {a.rotation[0], a.rotation[1], a.rotation[2], a.rotation[3]},
                     {b.rotation[0], b.rotation[1], b.rotation[2], b.rotation[3]});
  return compose(d);
}

}  // namespace obscura
