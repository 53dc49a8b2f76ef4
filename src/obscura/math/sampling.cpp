#include "obscura/math/sampling.h"

#include <algorithm>
#include <cmath>

namespace obscura {

Point2f sample_uniform_disk_polar(Point2f u) {
  float r = std::sqrt(u.x), phi = 2 * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi)};
}

Vector3f sample_uniform_hemisphere(Point2f u) {
  float z = u.x;
  float r = std::sqrt(std::max(0.f, 1 - z * z));
  float phi = 2 * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

Vector3f sample_uniform_sphere(Point2f u) {
  float z = 1 - 2 * u.x;
  float r = std::sqrt(std::max(0.f, 1 - z * z));
  float phi = 2 * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

Vector3f sample_cosine_hemisphere(Point2f u) {
  Point2f d = sample_uniform_disk_concentric(u);
  float z = std::sqrt(std::max(0.f, 1 - d.x * d.x - d.y * d.y));
  return {d.x, d.y, z};
}

Point2f sample_uniform_triangle(Point2f u) {
  // Heitz 2019, "A Low-Distortion Map Between Triangle and Square": no square root, and
  // neighbouring samples stay neighbours.
  float b0, b1;
  if (u.x < u.y) {
    b0 = u.x / 2;
    b1 = u.y - b0;
  } else {
    b1 = u.y / 2;
    b0 = u.x - b1;
  }
  return {b0, b1};
}

}  // namespace obscura
