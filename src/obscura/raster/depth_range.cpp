#include "obscura/raster/depth_range.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace obscura::raster {

namespace {

// The nearest and farthest view depths (along −Z) of the bounds' corners.
std::pair<double, double> depth_extent(const Matrix4& camera_from_world, const Bounds3f& bounds) {
  double nearest = HUGE_VAL, farthest = -HUGE_VAL;
  for (int c = 0; c < 8; ++c) {  // view depth is affine, so its extremes are at corners
    const Point3f q((c & 1 ? bounds.max : bounds.min).x, (c & 2 ? bounds.max : bounds.min).y,
                    (c & 4 ? bounds.max : bounds.min).z);
    const double depth = -(camera_from_world[2][0] * q.x + camera_from_world[2][1] * q.y +
                           camera_from_world[2][2] * q.z + camera_from_world[2][3]);
    nearest = std::min(nearest, depth), farthest = std::max(farthest, depth);
  }
  return {nearest, farthest};
}

// glOrtho's limit for a far plane at infinity: the z row (0, 0, 0, −1).
bool infinite_orthographic(const Matrix4& p) {
  return p[3][0] == 0 && p[3][1] == 0 && p[3][2] == 0 && p[3][3] == 1 && p[2][0] == 0 &&
         p[2][1] == 0 && p[2][2] == 0 && p[2][3] == -1;
}

}  // namespace

Matrix4 fit_depth_range(const Matrix4& projection, const Matrix4& camera_from_world,
                        const Bounds3f& bounds, double orthographic_near_m) {
  const Matrix4& p = projection;
  if (infinite_orthographic(p)) {
    const double n = orthographic_near_m;
    double f = n + 1;  // nothing to draw: any finite far plane
    if (!bounds.empty()) {
      const auto [nearest, farthest] = depth_extent(camera_from_world, bounds);
      f = std::max(f, farthest + 0.01 * (farthest - nearest) + 1e-6 * std::abs(farthest));
    }
    Matrix4 fitted = projection;
    fitted[2][2] = -2 / (f - n);
    fitted[2][3] = -(f + n) / (f - n);
    return fitted;
  }
  // glFrustum's z and w rows (lens shifts and crops touch only the x and y rows).
  if (bounds.empty() || p[2][0] != 0 || p[2][1] != 0 || p[3][0] != 0 || p[3][1] != 0 ||
      p[3][2] != -1 || p[3][3] != 0)
    return projection;
  const double a = p[2][2], b = p[2][3];
  if (!(a - 1 < 0) || !(b < 0)) return projection;
  const double near = b / (a - 1), far = a + 1 < 0 ? b / (a + 1) : HUGE_VAL;  // a = −1: infinite
  auto [nearest, farthest] = depth_extent(camera_from_world, bounds);
  farthest = std::max(farthest, 0.0);
  // A margin for motion between keys and float rounding; the planes never move outwards.
  const double margin = 0.01 * (farthest - nearest) + 1e-6 * farthest;
  const double n = std::max(near, nearest - margin), f = std::min(far, farthest + margin);
  if (!(n < f) || !std::isfinite(f) || (n == near && f == far)) return projection;
  Matrix4 fitted = projection;
  fitted[2][2] = -(f + n) / (f - n);
  fitted[2][3] = -2 * f * n / (f - n);
  return fitted;
}

}  // namespace obscura::raster
