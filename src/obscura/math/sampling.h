// Warps from the unit square [0,1)² to other domains, each with its density.
//
// Directions on hemispheres are in a local frame whose +Z is the surface normal.
#pragma once

#include <cmath>
#include <numbers>

#include "obscura/math/vector.h"

namespace obscura {

inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr float kInvPi = std::numbers::inv_pi_v<float>;

// Uniform on the unit disk by Shirley–Chiu's concentric mapping (keeps strata compact, so it is
// also the lens-sampling warp). In float for the tracer, in double for the camera's aperture.
template <typename T>
Point2<T> sample_uniform_disk_concentric(Point2<T> u) {
  const T pi = std::numbers::pi_v<T>;
  T ox = 2 * u.x - 1, oy = 2 * u.y - 1;
  if (ox == 0 && oy == 0) return {0, 0};
  T r, theta;
  if (std::abs(ox) > std::abs(oy)) {
    r = ox;
    theta = (pi / 4) * (oy / ox);
  } else {
    r = oy;
    theta = pi / 2 - (pi / 4) * (ox / oy);
  }
  return {r * std::cos(theta), r * std::sin(theta)};
}
// Uniform on the unit disk by polar mapping r = √u₀, φ = 2π·u₁.
Point2f sample_uniform_disk_polar(Point2f u);
inline constexpr float uniform_disk_pdf() {
  return kInvPi;
}

Vector3f sample_uniform_hemisphere(Point2f u);
inline constexpr float uniform_hemisphere_pdf() {
  return 0.5f * kInvPi;
}

Vector3f sample_uniform_sphere(Point2f u);
inline constexpr float uniform_sphere_pdf() {
  return 0.25f * kInvPi;
}

// Cosine-weighted hemisphere (Malley's method: project the concentric disk up).
Vector3f sample_cosine_hemisphere(Point2f u);
inline float cosine_hemisphere_pdf(float cos_theta) {
  return cos_theta * kInvPi;
}

// Uniform barycentric coordinates (b0, b1) on a triangle; b2 = 1 − b0 − b1.
Point2f sample_uniform_triangle(Point2f u);

}  // namespace obscura
