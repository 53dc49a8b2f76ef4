// Shadow maps (Williams 1978) for directional and spot lights: the scene's depth seen from the
// light; a point is lit where it lies no deeper than what the map recorded there. Lookups are
// filtered over 3×3 texels (percentage-closer filtering, Reeves et al. 1987), and the point is
// first pushed off its surface along the geometric normal by two texels' footprint (normal-offset
// bias), which removes self-shadowing ("acne") without detaching shadows from their casters.
#pragma once

#include <cmath>

#include "obscura/math/bounds.h"
#include "obscura/math/matrix4.h"
#include "obscura/raster/clip_transform.h"
#include "obscura/raster/render_target.h"
#include "obscura/raster/varyings.h"

namespace obscura::raster {

struct ShadowMap {
  Matrix4f clip_from_world;
  RenderTarget depth;  // window depth of the nearest surface per texel (1 sample)
  // World size of one texel at unit distance along the light's axis (spot), or everywhere
  // (directional).
  float texel_world = 0;
  bool perspective = false;
  Point3f light_position;  // spot
  Vector3f light_axis;     // spot: unit, where the cone points

  ShadowMap(const Matrix4& clip_from_world, int size, float texel_world, bool perspective);

  // The fraction of the light reaching world point p on a surface with unit geometric normal
  // n_geometric (facing the light or not), in [0, 1].
  float visibility(Point3f p, Vector3f n_geometric) const;
};

// The light's clip_from_world for a directional light travelling along unit `direction` over a
// scene inside `bounds`, and the texel footprint (m) of a `size`² map.
Matrix4 directional_shadow_projection(Vector3f direction, const Bounds3f& bounds, int size,
                                      float* texel_world);
// The same for a spot light at `position` pointing along unit `axis` with a cone of half-angle
// `outer_radians` (≤ 85°); the footprint is per metre along the axis.
Matrix4 spot_shadow_projection(Point3f position, Vector3f axis, float outer_radians,
                               const Bounds3f& bounds, int size, float* texel_world);

// A program that writes only depth (for shadow maps).
template <class V>
struct DepthOnlyProgram {
  using Vertex = V;
  struct Varyings {
    float unused;
  };
  Matrix4f clip_from_object;
  VertexOutput<Varyings> vertex(const V& v) const { return {clip_from_object(v.position), {0.f}}; }
  Rgb fragment(const Varyings&, FragmentInfo) const { return {}; }
};

}  // namespace obscura::raster
