// A 3×3 double-precision matrix and 3-vector for colour transforms. Colour matrices are derived
// in double from published chromaticities (see primaries.h) and only then rounded to float for
// pixel loops, so that the derivation itself adds no error a test could see.
#pragma once

#include <array>

namespace obscura {

using Vec3d = std::array<double, 3>;

struct Matrix3d {
  std::array<std::array<double, 3>, 3> m{};  // m[row][column]

  static constexpr Matrix3d identity() { return {{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}}; }
  static constexpr Matrix3d diagonal(const Vec3d& d) {
    return {{{{d[0], 0, 0}, {0, d[1], 0}, {0, 0, d[2]}}}};
  }

  constexpr Vec3d operator*(const Vec3d& v) const {
    Vec3d r{};
    for (int i = 0; i < 3; ++i) r[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
    return r;
  }
  constexpr Matrix3d operator*(const Matrix3d& o) const {
    Matrix3d r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        r.m[i][j] = m[i][0] * o.m[0][j] + m[i][1] * o.m[1][j] + m[i][2] * o.m[2][j];
    return r;
  }

  // The inverse by cofactors; the colour matrices used here are all well conditioned.
  Matrix3d inverse() const;
};

}  // namespace obscura
