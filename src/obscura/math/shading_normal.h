// The shading normal that a reflection-only surface is lit with, seen from a given direction.
//
// Interpolated (smooth) normals disagree with the triangles they are interpolated over. Near a
// silhouette the viewer sees the front of a triangle while the interpolated normal already
// points away from it. Turning that normal to the viewer (face_forward(ns, wo)) puts its
// hemisphere inside the object: every light and bounce direction is then rejected as being
// below the geometry, and smooth meshes get a dark one-pixel rim that a renderer such as Cycles
// does not show. Instead the normal stays on the viewer's side of the *geometry* and is bent
// toward the viewer just enough that the view direction sits a little above its horizon.
#pragma once

#include <algorithm>
#include <cmath>

#include "obscura/math/vector.h"

namespace obscura {

// How far above the bent normal's horizon the view direction is put (a cosine). Small, so that
// the bend changes as little of the shading as possible; non-zero, so that BSDFs that need
// wo in their upper hemisphere (all reflection models) see it there.
inline constexpr float kMinViewCosine = 0.01f;

// `shading` and `geometric` are unit normals of the same surface point (any orientation);
// `wo` the unit direction toward the viewer. Returns a unit normal on wo's side of the
// geometric surface with dot(n, wo) ≥ kMinViewCosine (up to rounding): the shading normal
// itself where it already faces the viewer, otherwise the shading normal turned toward wo
// within the plane of the two.
// Written without branches so that the rasterizer's per-pixel shaders still vectorize.
[[gnu::always_inline]] inline Vector3f visible_shading_normal(Vector3f shading, Vector3f geometric,
                                                              Vector3f wo) {
  Vector3f g = dot(geometric, wo) < 0 ? -geometric : geometric;
  Vector3f n = dot(shading, g) < 0 ? -shading : shading;
  float c = dot(n, wo);
  // n' = normalize(n + s·wo) has dot(n', wo) = (c + s) / sqrt(1 − c² + (c + s)²); setting it to
  // ε gives c + s = ε·sqrt((1 − c²) / (1 − ε²)). With s > 0, n' stays on g's side (n and wo are).
  const float eps = kMinViewCosine;
  float a = eps * std::sqrt(std::max(0.f, 1 - c * c) / (1 - eps * eps));
  float s = c < eps ? a - c : 0.f;
  Vector3f bent = n + wo * s;
  return bent / std::sqrt(std::max(dot(bent, bent), 1e-30f));
}

}  // namespace obscura
