// Fixed-point edge functions and the top-left fill rule.
//
// Vertices are snapped to 1/256 pixel (kSubpixelBits = 8) in y-down image space. A triangle is
// oriented so that all three edge functions are positive inside; a pixel centre is covered when
// every edge function is positive there, or zero on an edge that "owns" its boundary:
//   - a horizontal edge owns the centres on it when the triangle lies below it (a top edge);
//   - any other edge owns them when the triangle lies to its right (a left edge).
// Two triangles sharing an edge see it with opposite orientations, so exactly one of them owns
// each centre on it: no gaps, no pixel written twice. All arithmetic is exact (int64).
#pragma once

#include <cmath>
#include <cstdint>

namespace obscura::raster {

inline constexpr int kSubpixelBits = 8;
inline constexpr int32_t kSubpixelScale = 1 << kSubpixelBits;  // units per pixel
inline constexpr int32_t kHalfPixel = kSubpixelScale / 2;      // pixel centres at c·256 + 128

// Snaps an image coordinate in pixels to the nearest 1/256 pixel (ties round up).
inline int32_t snap_to_subpixel(double pixels) {
  return int32_t(std::floor(pixels * kSubpixelScale + 0.5));
}

// E(P) = step_x·(Px − Xa) + step_y·(Py − Ya) for the directed edge a → b, in subpixel² units;
// with the triangle oriented positive, the interior lies where E > 0.
struct EdgeFunction {
  int64_t step_x = 0, step_y = 0;  // ∂E/∂Px = −(Yb − Ya), ∂E/∂Py = Xb − Xa
  int64_t origin_x = 0, origin_y = 0;
  int64_t bias = 0;  // 0 when the edge owns centres on it, −1 otherwise: covered ⇔ E + bias ≥ 0

  EdgeFunction() = default;
  EdgeFunction(int32_t xa, int32_t ya, int32_t xb, int32_t yb)
      : step_x(-(int64_t(yb) - ya)), step_y(int64_t(xb) - xa), origin_x(xa), origin_y(ya) {
    // Interior to the right (∂E/∂x > 0), or straight below for a horizontal edge.
    bool owns_boundary = step_x > 0 || (step_x == 0 && step_y > 0);
    bias = owns_boundary ? 0 : -1;
  }

  int64_t operator()(int64_t px, int64_t py) const {
    return step_x * (px - origin_x) + step_y * (py - origin_y);
  }
  bool covers(int64_t px, int64_t py) const { return (*this)(px, py) + bias >= 0; }
};

// Twice the signed area of triangle (a, b, c) in subpixel² units, positive when the edge
// functions as defined above are positive inside (clockwise on screen in y-down space, which is
// counter-clockwise in OpenGL's y-up NDC).
inline int64_t twice_signed_area(int32_t xa, int32_t ya, int32_t xb, int32_t yb, int32_t xc,
                                 int32_t yc) {
  return (int64_t(xb) - xa) * (int64_t(yc) - ya) - (int64_t(yb) - ya) * (int64_t(xc) - xa);
}

inline int64_t floor_div(int64_t a, int64_t b) {  // b > 0
  int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}
inline int64_t ceil_div(int64_t a, int64_t b) {  // b > 0
  int64_t q = a / b;
  return (a % b != 0 && a > 0) ? q + 1 : q;
}

// Narrows the pixel span [*first, *last] of one row to the pixels k = first..last whose
// value value_at_first + k_offset·step (+ bias already included) is ≥ 0, where k_offset is the
// pixel's distance from `first`. Solving per row keeps the inner pixel loop free of coverage tests.
inline void clip_span_to_edge(int64_t value_at_first, int64_t step, int* first, int* last) {
  if (step > 0) {
    if (value_at_first < 0) {
      int64_t k = ceil_div(-value_at_first, step);
      if (k > int64_t(*last) - *first)
        *last = *first - 1;
      else
        *first += int(k);
    }
  } else if (step < 0) {
    if (value_at_first < 0) {
      *last = *first - 1;
    } else {
      int64_t k = floor_div(value_at_first, -step);
      if (k < int64_t(*last) - *first) *last = *first + int(k);
    }
  } else if (value_at_first < 0) {
    *last = *first - 1;
  }
}

}  // namespace obscura::raster
