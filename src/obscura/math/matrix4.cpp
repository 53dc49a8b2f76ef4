#include "obscura/math/matrix4.h"

#include <cmath>
#include <utility>

namespace obscura {

Matrix4 transpose(const Matrix4& a) {
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = a.m[j][i];
  return r;
}

double determinant(const Matrix4& a) {
  // Laplace expansion by 2×2 minors of the top two and bottom two rows.
  const auto& m = a.m;
  double s0 = m[0][0] * m[1][1] - m[1][0] * m[0][1];
  double s1 = m[0][0] * m[1][2] - m[1][0] * m[0][2];
  double s2 = m[0][0] * m[1][3] - m[1][0] * m[0][3];
  double s3 = m[0][1] * m[1][2] - m[1][1] * m[0][2];
  double s4 = m[0][1] * m[1][3] - m[1][1] * m[0][3];
  double s5 = m[0][2] * m[1][3] - m[1][2] * m[0][3];
  double c5 = m[2][2] * m[3][3] - m[3][2] * m[2][3];
  double c4 = m[2][1] * m[3][3] - m[3][1] * m[2][3];
  double c3 = m[2][1] * m[3][2] - m[3][1] * m[2][2];
  double c2 = m[2][0] * m[3][3] - m[3][0] * m[2][3];
  double c1 = m[2][0] * m[3][2] - m[3][0] * m[2][2];
  double c0 = m[2][0] * m[3][1] - m[3][0] * m[2][1];
  return s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0;
}

std::optional<Matrix4> inverse(const Matrix4& a) {
  // Gauss–Jordan elimination with partial pivoting, in double precision.
  Matrix4 lhs = a;
  Matrix4 rhs = Matrix4::identity();
  double scale = 0;
  for (const auto& row : a.m)
    for (double v : row) scale = std::max(scale, std::abs(v));
  if (scale == 0) return std::nullopt;
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 4; ++r)
      if (std::abs(lhs.m[r][col]) > std::abs(lhs.m[pivot][col])) pivot = r;
    if (std::abs(lhs.m[pivot][col]) <= 1e-14 * scale) return std::nullopt;
    std::swap(lhs.m[pivot], lhs.m[col]);
    std::swap(rhs.m[pivot], rhs.m[col]);
    double inv_pivot = 1.0 / lhs.m[col][col];
    for (int j = 0; j < 4; ++j) {
      lhs.m[col][j] *= inv_pivot;
      rhs.m[col][j] *= inv_pivot;
    }
    for (int r = 0; r < 4; ++r) {
      if (r == col) continue;
      double f = lhs.m[r][col];
      if (f == 0) continue;
      for (int j = 0; j < 4; ++j) {
        lhs.m[r][j] -= f * lhs.m[col][j];
        rhs.m[r][j] -= f * rhs.m[col][j];
      }
    }
  }
  return rhs;
}

}  // namespace obscura
