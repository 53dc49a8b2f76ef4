#include "obscura/color/primaries.h"

#include "obscura/math/error.h"

namespace obscura {

Vec3d xyz_from_chromaticity(Chromaticity c, double Y) {
  if (!(c.y > 0)) throw Error("chromaticity y must be positive; got " + std::to_string(c.y));
  return {c.x * Y / c.y, Y, (1 - c.x - c.y) * Y / c.y};
}

Matrix3d xyz_from_rgb(const RgbPrimaries& p) {
  // Columns: the primaries' XYZ at Y = 1 (AP0's blue has y < 0, so build them directly).
  auto column = [](Chromaticity c) { return Vec3d{c.x / c.y, 1.0, (1 - c.x - c.y) / c.y}; };
  Vec3d r = column(p.red), g = column(p.green), b = column(p.blue);
  Matrix3d primaries_matrix{{{{r[0], g[0], b[0]}, {r[1], g[1], b[1]}, {r[2], g[2], b[2]}}}};
  // Scale each primary so that RGB (1, 1, 1) maps to the white point.
  Vec3d scale = primaries_matrix.inverse() * xyz_from_chromaticity(p.white);
  return primaries_matrix * Matrix3d::diagonal(scale);
}

Matrix3d bradford_lms_from_xyz() {
  return {{{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}}};
}

Matrix3d bradford_adaptation(Chromaticity from, Chromaticity to) {
  Matrix3d lms_from_xyz = bradford_lms_from_xyz();
  Vec3d from_lms = lms_from_xyz * xyz_from_chromaticity(from);
  Vec3d to_lms = lms_from_xyz * xyz_from_chromaticity(to);
  Vec3d gain{to_lms[0] / from_lms[0], to_lms[1] / from_lms[1], to_lms[2] / from_lms[2]};
  return lms_from_xyz.inverse() * Matrix3d::diagonal(gain) * lms_from_xyz;
}

Matrix3d xyz_d65_from_rgb(const RgbPrimaries& p) {
  Matrix3d m = xyz_from_rgb(p);
  if (p.white.x == white::kD65.x && p.white.y == white::kD65.y) return m;
  return bradford_adaptation(p.white, white::kD65) * m;
}

}  // namespace obscura
