// A 4×4 matrix of doubles, row-major: m[row][column], acting on column vectors (M · v).
#pragma once

#include <array>
#include <optional>

#include "obscura/math/vector.h"

namespace obscura {

struct Matrix4 {
  std::array<std::array<double, 4>, 4> m{};

  static constexpr Matrix4 identity() {
    Matrix4 r;
    for (int i = 0; i < 4; ++i) r.m[i][i] = 1;
    return r;
  }
  static constexpr Matrix4 from_rows(std::array<std::array<double, 4>, 4> rows) {
    Matrix4 r;
    r.m = rows;
    return r;
  }

  constexpr const std::array<double, 4>& operator[](int row) const { return m[row]; }
  constexpr std::array<double, 4>& operator[](int row) { return m[row]; }
  constexpr bool operator==(const Matrix4&) const = default;

  constexpr Matrix4 operator*(const Matrix4& b) const {
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        r.m[i][j] = m[i][0] * b.m[0][j] + m[i][1] * b.m[1][j] + m[i][2] * b.m[2][j] +
                    m[i][3] * b.m[3][j];
    return r;
  }
  constexpr Vector4d operator*(const Vector4d& v) const {
    Vector4d r;
    for (int i = 0; i < 4; ++i)
      r[i] = m[i][0] * v.x + m[i][1] * v.y + m[i][2] * v.z + m[i][3] * v.w;
    return r;
  }
};

Matrix4 transpose(const Matrix4& a);
double determinant(const Matrix4& a);
// The inverse, or nothing when the matrix is singular (|det| below a relative threshold).
std::optional<Matrix4> inverse(const Matrix4& a);

}  // namespace obscura
