// A vertex after the vertex shader: clip position, varyings, and — when it lies inside every clip
// plane — its snapped image position, window depth and 1/w, computed once per vertex (a mesh
// shares each vertex among about six triangles).
#pragma once

#include <cstdint>

#include "obscura/raster/clipper.h"
#include "obscura/raster/fill_rule.h"
#include "obscura/raster/varyings.h"

namespace obscura::raster {

struct Viewport {
  int width = 0, height = 0;
};

template <VaryingsType V>
struct ShadedVertex {
  VertexOutput<V> out;
  int32_t x, y;      // image position in 1/256 pixel, y down (valid when outcode == 0)
  float z;           // window depth: ndc_z·0.5 + 0.5
  float inv_w;       // 1 / clip w
  uint32_t outcode;  // ClipPlaneBits of the planes it lies outside
};

// Perspective divide and viewport transform, then snapping; the divide is done in double so
// that conformance inputs given as exact fractions land exactly.
template <VaryingsType V>
void project(ShadedVertex<V>& v, Viewport viewport) {
  const Vector4f& p = v.out.clip;
  double inv_w = 1.0 / double(p.w);
  double x_image = (double(p.x) * inv_w + 1.0) * 0.5 * viewport.width;
  double y_image = (1.0 - double(p.y) * inv_w) * 0.5 * viewport.height;
  v.x = snap_to_subpixel(x_image);
  v.y = snap_to_subpixel(y_image);
  v.z = float(double(p.z) * inv_w * 0.5 + 0.5);
  v.inv_w = float(inv_w);
}

template <VaryingsType V>
ShadedVertex<V> make_shaded_vertex(const VertexOutput<V>& out, Viewport viewport, GuardBand guard) {
  ShadedVertex<V> v;
  v.out = out;
  v.outcode = outcode(out.clip, guard);
  if (v.outcode == 0) project(v, viewport);
  return v;
}

}  // namespace obscura::raster
