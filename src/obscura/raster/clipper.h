// Homogeneous clipping (Sutherland–Hodgman in clip space, before the perspective divide).
//
// Triangles are clipped against the near and far planes (−w ≤ z ≤ w), against w > 0, and
// against a guard band in x and y far outside the viewport: the rasterizer scissors to the
// viewport anyway, and the guard band only keeps fixed-point coordinates within range, so
// nearly every triangle that pokes out of the screen is rasterized without being cut.
// Attributes are interpolated linearly in clip space, which is exact for perspective-correct
// interpolation afterwards.
#pragma once

#include <cstdint>
#include <utility>

#include "obscura/raster/varyings.h"

namespace obscura::raster {

enum ClipPlaneBit : uint32_t {
  kClipLeft = 1u << 0,
  kClipRight = 1u << 1,
  kClipBottom = 1u << 2,
  kClipTop = 1u << 3,
  kClipNear = 1u << 4,
  kClipFar = 1u << 5,
  kClipPositiveW = 1u << 6,
};
inline constexpr int kClipPlaneCount = 7;
// A convex polygon clipped by 7 planes has at most 3 + 7 vertices.
inline constexpr int kMaxClippedVertices = 3 + kClipPlaneCount;

// |x| ≤ guard_x·w and |y| ≤ guard_y·w keep image coordinates within ±2^20 pixels.
struct GuardBand {
  float x = 1, y = 1;
  static GuardBand for_viewport(int width, int height) {
    constexpr double kGuardPixels = 1 << 20;
    return {float(kGuardPixels / (0.5 * width)), float(kGuardPixels / (0.5 * height))};
  }
};

// Signed distance of p to plane `i` (≥ 0 inside).
inline float clip_plane_distance(int i, const Vector4f& p, GuardBand g) {
  constexpr float kMinW = 1e-30f;
  switch (i) {
    case 0:
      return p.x + g.x * p.w;
    case 1:
      return g.x * p.w - p.x;
    case 2:
      return p.y + g.y * p.w;
    case 3:
      return g.y * p.w - p.y;
    case 4:
      return p.z + p.w;
    case 5:
      return p.w - p.z;
    default:
      return p.w - kMinW;
  }
}

inline uint32_t outcode(const Vector4f& p, GuardBand g) {
  uint32_t code = 0;
  for (int i = 0; i < kClipPlaneCount; ++i)
    if (!(clip_plane_distance(i, p, g) >= 0)) code |= 1u << i;  // NaN counts as outside
  return code;
}

// The point a fraction t from `inside` toward `outside`. Always interpolating from the inside
// vertex makes an edge shared by two triangles clip to bit-identical points: no cracks.
template <VaryingsType V>
VertexOutput<V> clip_lerp(const VertexOutput<V>& inside, const VertexOutput<V>& outside, float t) {
  VertexOutput<V> r;
  r.clip = inside.clip + (outside.clip - inside.clip) * t;
  auto a = to_floats(inside.varyings), b = to_floats(outside.varyings), c = a;
  for (size_t i = 0; i < c.size(); ++i) c[i] = a[i] + (b[i] - a[i]) * t;
  r.varyings = from_floats<V>(c);
  return r;
}

// Clips the convex polygon `poly` (n vertices, room for kMaxClippedVertices) against the planes
// in `planes`; returns the new vertex count (0 when nothing is left).
template <VaryingsType V>
int clip_polygon(VertexOutput<V>* poly, int n, uint32_t planes, GuardBand guard) {
  VertexOutput<V> scratch[kMaxClippedVertices];
  VertexOutput<V>* in = poly;
  VertexOutput<V>* out = scratch;
  for (int plane = 0; plane < kClipPlaneCount && n > 0; ++plane) {
    if (!(planes & (1u << plane))) continue;
    int m = 0;
    for (int i = 0; i < n; ++i) {
      const VertexOutput<V>& a = in[i];
      const VertexOutput<V>& b = in[(i + 1) % n];
      float da = clip_plane_distance(plane, a.clip, guard);
      float db = clip_plane_distance(plane, b.clip, guard);
      bool a_in = da >= 0, b_in = db >= 0;
      if (a_in) out[m++] = a;
      if (a_in != b_in) {
        // The crossing, computed from the inside end (see clip_lerp).
        out[m++] = a_in ? clip_lerp(a, b, da / (da - db)) : clip_lerp(b, a, db / (db - da));
      }
    }
    n = m;
    std::swap(in, out);
  }
  if (in != poly)
    for (int i = 0; i < n; ++i) poly[i] = in[i];
  return n;
}

}  // namespace obscura::raster
