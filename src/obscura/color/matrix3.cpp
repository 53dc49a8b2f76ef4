#include "obscura/color/matrix3.h"

#include "obscura/math/error.h"

namespace obscura {

Matrix3d Matrix3d::inverse() const {
  const auto& a = m;
  double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
  double c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
  double c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
  double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
  if (det == 0) throw Error("colour matrix is singular");
  double s = 1 / det;
  Matrix3d r;
  r.m[0] = {c00 * s, (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * s,
            (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * s};
  r.m[1] = {c01 * s, (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * s,
            (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * s};
  r.m[2] = {c02 * s, (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * s,
            (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * s};
  return r;
}

}  // namespace obscura
