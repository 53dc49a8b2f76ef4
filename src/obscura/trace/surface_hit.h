// Where a ray met a surface, with what the integrators shade with.
#pragma once

#include <cstdint>

#include "obscura/color/rgb.h"
#include "obscura/math/shading_normal.h"
#include "obscura/math/vector.h"

namespace obscura {

struct SurfaceHit {
  Point3f position;
  Normal3f geometric_normal;  // unit, on the front side of the triangle's winding
  Normal3f shading_normal;    // unit, on the same side as geometric_normal; normal-mapped
  // KHR_materials_clearcoat: the coat's own unit normal, where it differs from shading_normal
  // (a normal map on the base or on the coat); zero otherwise.
  Vector3f coat_normal;
  Point2f uv;              // texture coordinates (0 where the mesh has none)
  Point2f uv1;             // the second set (TEXCOORD_1), likewise
  Rgb vertex_color{1.f};   // interpolated COLOR_0 (white where the mesh has none)
  float vertex_alpha = 1;  // interpolated COLOR_0 alpha: multiplies the alpha coverage
  uint32_t material = 0;
  uint32_t mesh = 0;       // the Embree geometry id: which mesh (instance) was hit
  uint32_t primitive = 0;  // triangle index within it
  float t = 0;
  float time = 0;  // of the ray that found it (s): the moment secondary rays share
};

// The coordinates a texture reference reads: its UV set (sets past 1 are not kept: set 0).
inline Point2f texture_uv(const SurfaceHit& hit, uint32_t uv_set) {
  return uv_set == 1 ? hit.uv1 : hit.uv;
}

// The normal a reflection-only BSDF is evaluated with, seen from wo (unit, toward the viewer):
// on the viewer's side of the geometry, bent toward the viewer where an interpolated normal
// has turned away from it (math/shading_normal.h says why).
inline Normal3f reflection_normal(const SurfaceHit& hit, Vector3f wo) {
  return Normal3f(
      visible_shading_normal(to_vector(hit.shading_normal), to_vector(hit.geometric_normal), wo));
}

}  // namespace obscura
