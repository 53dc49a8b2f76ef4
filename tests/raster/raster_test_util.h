// Shared helpers for the rasterizer tests: triangles given in clip space or in image pixels, and
// renders that count coverage or record which triangle is visible.
#pragma once

#include <cstdint>
#include <vector>

#include "obscura/raster/pipeline.h"

namespace obscura::raster::test {

// Clip positions in, one constant colour per triangle out (index = primitive).
struct ClipSpaceProgram {
  using Vertex = Vector4f;
  struct Varyings {
    float unused;
  };
  const std::vector<Rgb>* colors = nullptr;  // null: white
  VertexOutput<Varyings> vertex(const Vector4f& clip) const { return {clip, {0.f}}; }
  Rgb fragment(const Varyings&, FragmentInfo f) const {
    return colors ? (*colors)[f.primitive] : Rgb(1.f);
  }
};

// A point in image pixels (y down) as a clip-space position with w = 1 and the given NDC z.
inline Vector4f pixel_to_clip(double x, double y, int width, int height, double z = 0) {
  return {float(2 * x / width - 1), float(1 - 2 * y / height), float(z), 1.f};
}

// How many triangles cover each pixel (depth test off, additive blending).
inline std::vector<int> coverage_counts(int width, int height, const std::vector<Vector4f>& clip,
                                        CullMode cull = CullMode::kNone) {
  RenderTarget target(width, height);
  target.clear();
  DrawState state;
  state.depth_func = DepthFunc::kAlways;
  state.depth_write = false;
  state.blend = BlendMode::kAdd;
  state.cull = cull;
  draw(target, state, ClipSpaceProgram{}, clip);
  std::vector<int> counts(size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) counts[size_t(y) * width + x] = int(target.color_at(x, y).r);
  return counts;
}

// The primitive index + 1 visible at each pixel (0 = none), with the given depth function.
inline std::vector<uint32_t> visible_ids(int width, int height, const std::vector<Vector4f>& clip,
                                         DepthFunc func = DepthFunc::kLess) {
  RenderTarget target(width, height, 1, /*aovs=*/true);
  target.clear();
  DrawState state;
  state.depth_func = func;
  draw(target, state, ClipSpaceProgram{}, clip);
  std::vector<uint32_t> ids(size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      ids[size_t(y) * width + x] =
          target.object_id_at(x, y) == kNoObject ? 0 : target.primitive_id_at(x, y) + 1;
  return ids;
}

// Exact orientation test in double (coordinates here are multiples of 1/256 below 2^20, so the
// products are exact): > 0 when p is to the left of a→b in a y-up frame.
inline double orient(double ax, double ay, double bx, double by, double px, double py) {
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

// +1 strictly inside triangle (a, b, c), −1 strictly outside, 0 on its boundary.
inline int classify(const double a[2], const double b[2], const double c[2], double px, double py) {
  double d0 = orient(a[0], a[1], b[0], b[1], px, py), d1 = orient(b[0], b[1], c[0], c[1], px, py),
         d2 = orient(c[0], c[1], a[0], a[1], px, py);
  bool neg = d0 < 0 || d1 < 0 || d2<0, pos = d0> 0 || d1 > 0 || d2 > 0;
  if (neg && pos) return -1;
  if (d0 == 0 || d1 == 0 || d2 == 0) return 0;
  return 1;
}

}  // namespace obscura::raster::test
