// Tangent-space normal mapping as glTF defines it, for both renderers.
//
// A normal map texel (r, g, b) in [0, 1] encodes the unit normal (2r − 1, 2g − 1, 2b − 1) in
// the frame (T, B, N): T the tangent along +u, B = w · cross(N, T) along "up" in the image, N the
// interpolated normal. normalTexture.scale multiplies its x and y before normalizing.
#pragma once

#include <algorithm>
#include <cmath>

#include "obscura/math/vector.h"

namespace obscura::shading {

// How far above the geometric surface a perturbed normal is kept (a cosine).
inline constexpr float kMinPerturbedCosine = 0.01f;

// The perturbed unit normal: n' = normalize(T·x·s + B·y·s + N·z) with (x, y, z) = 2·texel − 1.
// `normal` is the unit interpolated normal, `tangent` the interpolated tangent (xyz in the same
// space as `normal`, not necessarily unit or perpendicular to it: it is orthogonalised here, as
// interpolation leaves it; w's sign is the handedness). Where the tangent is degenerate (parallel
// to the normal or zero), returns `normal` unchanged.
// Written without branches so that the rasterizer's per-pixel shaders still vectorize.
[[gnu::always_inline]] inline Vector3f perturbed_normal(Vector3f normal, Vector4f tangent,
                                                        Vector3f texel, float scale) {
  Vector3f t(tangent.x, tangent.y, tangent.z);
  t = t - normal * dot(normal, t);
  float t2 = dot(t, t);
  bool usable = t2 > 1e-12f;
  t = t * (1 / std::sqrt(std::max(t2, 1e-30f)));
  Vector3f b = cross(normal, t) * (tangent.w < 0 ? -1.f : 1.f);
  float x = (2 * texel.x - 1) * scale, y = (2 * texel.y - 1) * scale, z = 2 * texel.z - 1;
  Vector3f n = t * x + b * y + normal * z;
  float n2 = dot(n, n);
  n = n * (1 / std::sqrt(std::max(n2, 1e-30f)));
  return usable && n2 > 1e-12f ? n : normal;
}

// A perturbed normal may point below the surface it decorates (a steep texel, a large scale, or
// a normal map drawn for another mesh): light would then reach the shading hemisphere from
// inside the object. `geometric` is the unit geometric normal on the side of the unperturbed
// shading normal; where n leaves less than kMinPerturbedCosine above that plane it is turned
// towards `geometric` within the plane of the two, to exactly that cosine. The tangential
// direction of the bump is kept, so steep bumps still shade as steep, just not past the horizon.
[[gnu::always_inline]] inline Vector3f keep_above_surface(Vector3f n, Vector3f geometric) {
  float c = dot(n, geometric);
  Vector3f tangential = n - geometric * c;
  float l2 = dot(tangential, tangential);
  constexpr float eps = kMinPerturbedCosine;
  const float sine = std::sqrt(1 - eps * eps);
  Vector3f lifted = l2 > 1e-20f
                        ? tangential * (sine / std::sqrt(std::max(l2, 1e-30f))) + geometric * eps
                        : geometric;
  return c < eps ? lifted : n;
}

}  // namespace obscura::shading
