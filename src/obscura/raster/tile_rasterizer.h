// Rasterizing one triangle into one tile: setup, coverage by rows, depth test, perspective-
// correct interpolation, fragment shading and output.
//
// Coverage is exact (fill_rule.h): each row's covered span is solved from the integer edge
// functions, so the pixel loop needs no coverage test and runs in batches of eight pixels that
// the compiler can vectorize. Depth is interpolated linearly in screen space (window z is affine
// there); attributes perspective-correctly: f_i = λ_i / w_i is affine in screen space, and the
// perspective-correct weights are f_i / Σ f_j (Σ f_j = 1/w at the pixel).
#pragma once

#include <algorithm>
#include <concepts>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <utility>

#include "obscura/color/rgb.h"
#include "obscura/raster/binner.h"
#include "obscura/raster/depth_test.h"
#include "obscura/raster/fill_rule.h"
#include "obscura/raster/msaa.h"
#include "obscura/raster/render_target.h"
#include "obscura/raster/shaded_vertex.h"
#include "obscura/raster/varyings.h"

namespace obscura::raster {

// A program: a vertex shader and a fragment shader sharing a Varyings type. The fragment shader
// is either fragment(varyings, info), or fragment(varyings, d/dx, d/dy, info) when it needs the
// screen-space derivatives of its varyings (texture level of detail), which the rasterizer then
// computes by interpolating at the neighbouring pixel centres, as a GPU's 2×2 quads do.
template <class P>
concept PlainFragmentShader = requires(const P& p, const typename P::Varyings& var,
                                       FragmentInfo info) {
  { p.fragment(var, info) } -> std::convertible_to<Rgb>;
};
template <class P>
concept DerivativeFragmentShader = requires(const P& p, const typename P::Varyings& var,
                                            FragmentInfo info) {
  { p.fragment(var, var, var, info) } -> std::convertible_to<Rgb>;
};
template <class P>
concept Program = VaryingsType<typename P::Varyings> &&
    requires(const P& p, const typename P::Vertex& v) {
  { p.vertex(v) } -> std::same_as<VertexOutput<typename P::Varyings>>;
} &&(PlainFragmentShader<P> || DerivativeFragmentShader<P>);

// Programs may also say which shading normal a fragment has (for the normal output).
template <class P>
concept HasNormalOutput = requires(const P& p, const typename P::Varyings& var) {
  { p.normal(var) } -> std::convertible_to<Vector3f>;
};

// Edges drawn over the shaded surface, measured in pixels from each triangle's edges.
struct Wireframe {
  bool enabled = false;
  float width_pixels = 1.f;
  Rgb color{1.f, 1.f, 1.f};
};

struct FragmentSettings {
  bool depth_write = true;
  BlendMode blend = BlendMode::kReplace;
  FrontFace front_face = FrontFace::kCounterClockwise;
  uint32_t object_id = 1;
  Wireframe wireframe;
};

struct PixelRect {  // [x0, x1) × [y0, y1)
  int x0, y0, x1, y1;
};

// Clamps to [0, 1] by value (a vector select), NaN to 0.
OBSCURA_RASTER_INLINE float clamp_unit(float x) {
  return x > 0.f ? (x < 1.f ? x : 1.f) : 0.f;
}

template <Program P, DepthFunc F>
class TriangleRasterizer {
 public:
  using V = typename P::Varyings;
  static constexpr int kN = kVaryingFloats<V>;
  static constexpr int kBlockLog2 = 3;
  static constexpr int kBlock = 1 << kBlockLog2;  // 8×8-pixel blocks; rows go 8 lanes at a time
  static_assert(kBlock == kRowAlignment && kTileSize % kBlock == 0);
  static constexpr bool kHierarchicalZ = F == DepthFunc::kLess || F == DepthFunc::kLessEqual;

  TriangleRasterizer(const P& program, RenderTarget& target, const FragmentSettings& settings)
      : program_(program),
        target_(target),
        settings_(settings),
        offsets_(msaa_sample_offsets(target.samples())) {
    for (auto& row : depth_bound_) std::fill(std::begin(row), std::end(row), kNoBound);
    for (Vector2i o : offsets_)
      sample_extent_ = std::max({sample_extent_, std::abs(o.x), std::abs(o.y)});
  }

  OBSCURA_RASTER_INLINE void draw(const ShadedVertex<V>& a, const ShadedVertex<V>& b,
                                  const ShadedVertex<V>& c, uint32_t primitive, PixelRect tile) {
    if (!setup(a, b, c, primitive, tile)) return;
    if (target_.samples() == 1) {
      rasterize_blocks(tile);
    } else {
      setup_planes();
      for (int row = rows_.first; row <= rows_.last; ++row) shade_row_multisampled(row);
    }
  }

 private:
  OBSCURA_RASTER_INLINE bool setup(const ShadedVertex<V>& a, const ShadedVertex<V>& b,
                                   const ShadedVertex<V>& c, uint32_t primitive, PixelRect tile) {
    const ShadedVertex<V>* v[3] = {&a, &b, &c};
    int64_t area2 = twice_signed_area(a.x, a.y, b.x, b.y, c.x, c.y);
    if (area2 == 0) return false;
    front_facing_ = is_front_facing(area2, settings_.front_face);
    if (area2 < 0) std::swap(v[1], v[2]), area2 = -area2;
    // Start at the topmost-leftmost vertex: the same triangle given in any vertex order then
    // gets bit-identical planes (equal depths compare equal).
    int first = 0;
    for (int i = 1; i < 3; ++i)
      if (std::pair(v[i]->y, v[i]->x) < std::pair(v[first]->y, v[first]->x)) first = i;
    std::rotate(v, v + first, v + 3);
    primitive_ = primitive;

    const int extent = sample_extent_;
    int32_t min_x = std::min({v[0]->x, v[1]->x, v[2]->x}),
            max_x = std::max({v[0]->x, v[1]->x, v[2]->x});
    int32_t min_y = std::min({v[0]->y, v[1]->y, v[2]->y}),
            max_y = std::max({v[0]->y, v[1]->y, v[2]->y});
    cols_ = pixel_range(min_x, max_x, extent, target_.width());
    rows_ = pixel_range(min_y, max_y, extent, target_.height());
    cols_ = {std::max(cols_.first, tile.x0), std::min(cols_.last, tile.x1 - 1)};
    rows_ = {std::max(rows_.first, tile.y0), std::min(rows_.last, tile.y1 - 1)};
    if (cols_.first > cols_.last || rows_.first > rows_.last) return false;

    // Everything below is relative to the centre of the first pixel of the box.
    const int64_t ox = int64_t(cols_.first) * kSubpixelScale + kHalfPixel;
    const int64_t oy = int64_t(rows_.first) * kSubpixelScale + kHalfPixel;
    for (int i = 0; i < 3; ++i) {
      const ShadedVertex<V>& p = *v[(i + 1) % 3];
      const ShadedVertex<V>& q = *v[(i + 2) % 3];
      edge_[i] = EdgeFunction(p.x, p.y, q.x, q.y);  // the edge opposite vertex i
      edge_at_origin_[i] = edge_[i](ox, oy);
    }
    for (int i = 0; i < 3; ++i)
      for (int lane = 0; lane < kRowAlignment; ++lane)
        lane_step_[i][lane] = edge_[i].step_x * kSubpixelScale * lane;
    for (int i = 0; i < 3; ++i) vertex_[i] = v[i];
    area2_ = area2;
    planes_ready_ = false;
    return true;
  }

  // The depth and interpolation planes, set up only once a triangle is known to reach a pixel
  // centre: most triangles of a dense mesh cover few pixels, many none, in most of their tiles.
  OBSCURA_RASTER_INLINE void setup_planes() {
    if (planes_ready_) return;
    planes_ready_ = true;
    const ShadedVertex<V>* const* v = vertex_;
    const double inv_area = 1.0 / double(area2_);
    double zc = 0, zx = 0, zy = 0;
    for (int i = 0; i < 3; ++i) {
      double e0 = double(edge_at_origin_[i]) * inv_area;                // λ_i at the origin
      double ex = double(edge_[i].step_x * kSubpixelScale) * inv_area;  // per pixel
      double ey = double(edge_[i].step_y * kSubpixelScale) * inv_area;
      zc += v[i]->z * e0, zx += v[i]->z * ex, zy += v[i]->z * ey;
      double w = v[i]->inv_w;
      f0_[i] = float(e0 * w), fx_[i] = float(ex * w), fy_[i] = float(ey * w);
    }
    z0_ = float(zc), zx_ = float(zx), zy_ = float(zy);
    auto v0 = to_floats(v[0]->out.varyings), v1 = to_floats(v[1]->out.varyings),
         v2 = to_floats(v[2]->out.varyings);
    for (int k = 0; k < kN; ++k) base_[k] = v0[k], d1_[k] = v1[k] - v0[k], d2_[k] = v2[k] - v0[k];
    if (settings_.wireframe.enabled) {
      for (int i = 0; i < 3; ++i) {
        // Distance in pixels = E / |∇E|, with E in subpixel² and ∇E in subpixels.
        double g = std::hypot(double(edge_[i].step_x), double(edge_[i].step_y));
        wire_scale_[i] = float(1.0 / (g * kSubpixelScale));
      }
    }
  }

  OBSCURA_RASTER_INLINE V interpolate(float l1, float l2) const {
    VaryingArray<V> r;
    for (int k = 0; k < kN; ++k) r[k] = base_[k] + d1_[k] * l1 + d2_[k] * l2;
    return from_floats<V>(r);
  }

  // Perspective-correct weights of vertices 1 and 2 at (dx, dy) pixels from the box origin.
  void weights(float dx, float dy, float* l1, float* l2, float* w) const {
    float f0 = f0_[0] + fx_[0] * dx + fy_[0] * dy, f1 = f0_[1] + fx_[1] * dx + fy_[1] * dy,
          f2 = f0_[2] + fx_[2] * dx + fy_[2] * dy;
    *w = 1.f / (f0 + f1 + f2);
    *l1 = f1 * *w, *l2 = f2 * *w;
  }

  OBSCURA_RASTER_INLINE Rgb shade(float l1, float l2, float dx, float dy, int x, int row) const {
    FragmentInfo info{x, row, primitive_, front_facing_};
    if constexpr (PlainFragmentShader<P>) {
      return program_.fragment(interpolate(l1, l2), info);
    } else {
      float a1, a2, b1, b2, w;
      weights(dx + 1, dy, &a1, &a2, &w);
      weights(dx, dy + 1, &b1, &b2, &w);
      VaryingArray<V> d_dx, d_dy;
      for (int k = 0; k < kN; ++k) {
        d_dx[k] = d1_[k] * (a1 - l1) + d2_[k] * (a2 - l2);
        d_dy[k] = d1_[k] * (b1 - l1) + d2_[k] * (b2 - l2);
      }
      return program_.fragment(interpolate(l1, l2), from_floats<V>(d_dx), from_floats<V>(d_dy),
                               info);
    }
  }

  // Single sample per pixel. The box is walked in 8×8 blocks aligned to the tile. Each edge
  // function is affine, so its extremes over a block lie at the block's corners: a block outside
  // one edge is skipped, and edges a block lies wholly inside are not tested per pixel. With a
  // LESS/LEQUAL depth test, a block whose nearest depth cannot pass against the block's depth
  // bound (hierarchical z) is skipped before any per-pixel work.
  OBSCURA_RASTER_INLINE void rasterize_blocks(PixelRect tile) {
    int64_t step_x[3], step_y[3];  // per pixel
    for (int i = 0; i < 3; ++i)
      step_x[i] = edge_[i].step_x * kSubpixelScale, step_y[i] = edge_[i].step_y * kSubpixelScale;
    const int bx0 = (cols_.first - tile.x0) >> kBlockLog2,
              bx1 = (cols_.last - tile.x0) >> kBlockLog2;
    const int by0 = (rows_.first - tile.y0) >> kBlockLog2,
              by1 = (rows_.last - tile.y0) >> kBlockLog2;
    for (int by = by0; by <= by1; ++by) {
      const int block_y = tile.y0 + (by << kBlockLog2);
      const int y_lo = std::max(rows_.first, block_y),
                y_hi = std::min(rows_.last, block_y + kBlock - 1);
      for (int bx = bx0; bx <= bx1; ++bx) {
        const int block_x = tile.x0 + (bx << kBlockLog2);
        const int x_lo = std::max(cols_.first, block_x);
        const int x_hi = std::min(cols_.last, block_x + kBlock - 1);
        bool partial = false, outside = false;
        for (int i = 0; i < 3; ++i) {
          int64_t e = edge_at_origin_[i] + edge_[i].bias + step_x[i] * (x_lo - cols_.first) +
                      step_y[i] * (y_lo - rows_.first);
          int64_t ex = step_x[i] * (x_hi - x_lo), ey = step_y[i] * (y_hi - y_lo);
          int64_t lo = e + std::min<int64_t>(ex, 0) + std::min<int64_t>(ey, 0);
          int64_t hi = e + std::max<int64_t>(ex, 0) + std::max<int64_t>(ey, 0);
          outside |= hi < 0;
          partial |= lo < 0;
        }
        if (outside) continue;
        float& bound = depth_bound_[by][bx];
        if constexpr (kHierarchicalZ) {
          if (bound != kNoBound) {
            setup_planes();
            // Depth is monotone in x and y (see pixel_depth), so its minimum over the block is
            // the smallest of the corner values.
            float z_min = std::min({pixel_depth(x_lo, y_lo), pixel_depth(x_hi, y_lo),
                                    pixel_depth(x_lo, y_hi), pixel_depth(x_hi, y_hi)});
            if (F == DepthFunc::kLess ? z_min >= bound : z_min > bound) continue;
          }
        }
        const bool whole = !partial && x_lo == block_x && x_hi == block_x + kBlock - 1 &&
                           y_lo == block_y && y_hi == block_y + kBlock - 1;
        bool all_written = whole;
        for (int row = y_lo; row <= y_hi; ++row)
          shade_segment(row, block_x, x_lo, x_hi, partial, &all_written);
        // Every pixel of the block now holds a depth written here: the bound tightens to the
        // largest, at a corner. The margin (far above one rounding) keeps it an upper bound even
        // if a compiler contracted the pixel loop's arithmetic differently. Otherwise the bound
        // stays valid, as LESS/LEQUAL with depth writes only ever lower stored depths.
        if (kHierarchicalZ && all_written && settings_.depth_write)
          bound = std::max({pixel_depth(x_lo, y_lo), pixel_depth(x_hi, y_lo),
                            pixel_depth(x_lo, y_hi), pixel_depth(x_hi, y_hi)}) *
                  (1.f + 0x1p-20f);
      }
    }
  }

  // The window depth the pixel loop computes at pixel (x, y) of the box: z_row + zx·k, each step
  // rounded, is monotone in k and in the row, so extremes over a rectangle lie at its corners.
  OBSCURA_RASTER_INLINE float pixel_depth(int x, int y) const {
    const float z_row = z0_ + zy_ * float(y - rows_.first);
    return clamp_unit(z_row + zx_ * float(x - cols_.first));
  }

  // One row of one block: pixels [x_lo, x_hi] of the aligned run of kBlock pixels starting at x0,
  // each lane masked by coverage (only when `test_edges`) and the depth test. Every loop below
  // has a fixed trip count, so the compiler vectorizes them; lanes outside the span recompute but
  // never store (the row stride is padded to whole blocks, so a block never reaches into
  // another tile). `*all_written` is cleared unless every lane in the span passed.
  OBSCURA_RASTER_INLINE void shade_segment(int row, int x0, int x_lo, int x_hi, bool test_edges,
                                           bool* all_written) {
    const int dy = row - rows_.first;
    const int64_t k0 = x0 - cols_.first;
    float* depth = target_.depth() + target_.sample_index(0, row);
    Rgb* color = target_.color() + target_.sample_index(0, row);

    // Bitwise rather than short-circuit logic throughout: no branch in the loops, so they
    // vectorize (the depth load is always in bounds, the row being padded).
    bool covered[kBlock];
    if (test_edges) {
      int64_t e_block[3];
      for (int i = 0; i < 3; ++i)
        e_block[i] = edge_at_origin_[i] + edge_[i].bias + edge_[i].step_y * kSubpixelScale * dy +
                     edge_[i].step_x * kSubpixelScale * k0;
      for (int i = 0; i < kBlock; ++i)
        covered[i] = (e_block[0] + lane_step_[0][i] >= 0) & (e_block[1] + lane_step_[1][i] >= 0) &
                     (e_block[2] + lane_step_[2][i] >= 0);
    } else {
      for (int i = 0; i < kBlock; ++i) covered[i] = true;
    }
    int any = 0;
    for (int i = 0; i < kBlock; ++i) {
      const int x = x0 + i;
      covered[i] = covered[i] & (x >= x_lo) & (x <= x_hi);
      any |= covered[i];
    }
    if (!any) {
      *all_written = false;
      return;
    }
    setup_planes();
    const float z_row = z0_ + zy_ * float(dy);
    bool lane[kBlock];
    float z[kBlock];
    int live = 0;
    for (int i = 0; i < kBlock; ++i) {
      z[i] = clamp_unit(z_row + zx_ * float(k0 + i));
      lane[i] = covered[i] & depth_passes<F>(z[i], depth[x0 + i]);
      live += lane[i];
    }
    if (live != x_hi - x_lo + 1) *all_written = false;
    if (live == 0) return;  // early depth rejection of the whole run
    if (live <= 2) {        // small triangles: shade only the live pixels
      for (int i = 0; i < kBlock; ++i) {
        if (!lane[i]) continue;
        float l1, l2, w;
        weights(float(k0 + i), float(dy), &l1, &l2, &w);
        write(target_.sample_index(x0 + i, row), z[i],
              shade(l1, l2, float(k0 + i), float(dy), x0 + i, row), l1, l2, w, x0 + i, row);
      }
      return;
    }

    const float f_row[3] = {f0_[0] + fy_[0] * float(dy), f0_[1] + fy_[1] * float(dy),
                            f0_[2] + fy_[2] * float(dy)};
    float l1[kBlock], l2[kBlock], w[kBlock], r[kBlock], g[kBlock], b[kBlock];
    for (int i = 0; i < kBlock; ++i) {
      const float dx = float(k0 + i);
      float f0 = f_row[0] + fx_[0] * dx, f1 = f_row[1] + fx_[1] * dx, f2 = f_row[2] + fx_[2] * dx;
      w[i] = 1.f / (f0 + f1 + f2);
      l1[i] = f1 * w[i], l2[i] = f2 * w[i];
    }
    shade_block(l1, l2, float(k0), float(dy), x0, row, r, g, b);
    if (settings_.wireframe.enabled)
      for (int i = 0; i < kBlock; ++i) {
        Rgb c = apply_wireframe({r[i], g[i], b[i]}, x0 + i, row);
        r[i] = c.r, g[i] = c.g, b[i] = c.b;
      }
    if (live == kBlock && settings_.blend == BlendMode::kReplace) {
      // The common case inside large triangles: plain stores, which vectorize.
      if (settings_.depth_write)
        for (int i = 0; i < kBlock; ++i) depth[x0 + i] = z[i];
      store_colors(color + x0, r, g, b);
      if (target_.has_aovs())
        for (int i = 0; i < kBlock; ++i)
          write_aovs(target_.sample_index(x0 + i, row), l1[i], l2[i], w[i]);
      return;
    }
    if (settings_.depth_write)
      for (int i = 0; i < kBlock; ++i) depth[x0 + i] = lane[i] ? z[i] : depth[x0 + i];
    if (settings_.blend == BlendMode::kAdd) {
      for (int i = 0; i < kBlock; ++i)
        if (lane[i]) color[x0 + i] += Rgb(r[i], g[i], b[i]);
    } else {
      for (int i = 0; i < kBlock; ++i)
        if (lane[i]) color[x0 + i] = Rgb(r[i], g[i], b[i]);
    }
    if (target_.has_aovs())
      for (int i = 0; i < kBlock; ++i)
        if (lane[i]) write_aovs(target_.sample_index(x0 + i, row), l1[i], l2[i], w[i]);
  }

  // The fragment shader on a run of kBlock pixels (weights l1, l2 per lane), colours out as
  // planes. Varyings are interpolated plane by plane (one vector per varying), then each lane's
  // struct is gathered from the planes: with no loop left over the varyings, the loop over lanes
  // is what the vectorizer sees, and it turns the whole shader into vector code.
  OBSCURA_RASTER_INLINE void shade_block(const float* l1, const float* l2, float k0, float dy,
                                         int x0, int row, float* r, float* g, float* b) const {
    if constexpr (PlainFragmentShader<P>) {
      float planes[kN][kBlock];
      for (int k = 0; k < kN; ++k)
        for (int i = 0; i < kBlock; ++i) planes[k][i] = base_[k] + d1_[k] * l1[i] + d2_[k] * l2[i];
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC ivdep
#endif
      for (int i = 0; i < kBlock; ++i) {
        Rgb c = program_.fragment(gather_lane(planes, i, std::make_index_sequence<kN>()),
                                  FragmentInfo{x0 + i, row, primitive_, front_facing_});
        r[i] = c.r, g[i] = c.g, b[i] = c.b;
      }
    } else {
      for (int i = 0; i < kBlock; ++i) {
        Rgb c = shade(l1[i], l2[i], k0 + float(i), dy, x0 + i, row);
        r[i] = c.r, g[i] = c.g, b[i] = c.b;
      }
    }
  }

  template <size_t... K>
  OBSCURA_RASTER_INLINE static V gather_lane(const float (&planes)[kN][kBlock], int i,
                                             std::index_sequence<K...>) {
    return from_floats<V>(VaryingArray<V>{planes[K][i]...});
  }

  // Interleaves planes into kBlock RGB pixels, four at a time with explicit shuffles (written as
  // a loop over lanes, the interleave compiles to one scalar insert per float).
  OBSCURA_RASTER_INLINE static void store_colors(Rgb* dst, const float* r, const float* g,
                                                 const float* b) {
    using F4 = float __attribute__((vector_size(16)));
    using I4 = int __attribute__((vector_size(16)));
    static_assert(kBlock % 4 == 0 && sizeof(Rgb) == 3 * sizeof(float));
    for (int i = 0; i < kBlock; i += 4) {
      F4 vr, vg, vb;
      std::memcpy(&vr, r + i, sizeof vr);
      std::memcpy(&vg, g + i, sizeof vg);
      std::memcpy(&vb, b + i, sizeof vb);
      const F4 rg01 = __builtin_shuffle(vr, vg, I4{0, 4, 1, 5});        // r0 g0 r1 g1
      const F4 gb12 = __builtin_shuffle(vg, vb, I4{1, 5, 2, 6});        // g1 b1 g2 b2
      const F4 rg33 = __builtin_shuffle(vr, vg, I4{3, 7, 3, 7});        // r3 g3 r3 g3
      const F4 out[3] = {__builtin_shuffle(rg01, vb, I4{0, 1, 4, 2}),   // r0 g0 b0 r1
                         __builtin_shuffle(gb12, vr, I4{0, 1, 6, 2}),   // g1 b1 r2 g2
                         __builtin_shuffle(rg33, vb, I4{6, 0, 1, 7})};  // b2 r3 g3 b3
      std::memcpy(static_cast<void*>(dst + i), out, sizeof out);
    }
  }

  // MSAA: coverage and depth per sample, the fragment shader once per pixel at its centre.
  void shade_row_multisampled(int row) {
    const int samples = target_.samples();
    const int dy = row - rows_.first;
    int first[8], last[8];
    int lo = cols_.last + 1, hi = cols_.first - 1;
    for (int s = 0; s < samples; ++s) {
      first[s] = cols_.first, last[s] = cols_.last;
      // Each edge narrows the span the previous ones left: its value is taken at first[s].
      for (int i = 0; i < 3; ++i)
        clip_span_to_edge(
            edge_at_origin_[i] + edge_[i].step_y * (kSubpixelScale * dy + offsets_[s].y) +
                edge_[i].step_x *
                    (offsets_[s].x + kSubpixelScale * int64_t(first[s] - cols_.first)) +
                edge_[i].bias,
            edge_[i].step_x * kSubpixelScale, &first[s], &last[s]);
      if (first[s] <= last[s]) lo = std::min(lo, first[s]), hi = std::max(hi, last[s]);
    }
    for (int x = lo; x <= hi; ++x) {
      const float dx = float(x - cols_.first);
      bool shaded = false;
      Rgb color;
      float l1 = 0, l2 = 0, w = 0;
      for (int s = 0; s < samples; ++s) {
        if (x < first[s] || x > last[s]) continue;
        float z = std::clamp(z0_ + zx_ * (dx + offsets_[s].x / float(kSubpixelScale)) +
                                 zy_ * (float(dy) + offsets_[s].y / float(kSubpixelScale)),
                             0.f, 1.f);
        size_t index = target_.sample_index(x, row, s);
        if (!depth_passes<F>(z, target_.depth()[index])) continue;
        if (!shaded) {
          weights(dx, float(dy), &l1, &l2, &w);
          color = shade(l1, l2, dx, float(dy), x, row);
          shaded = true;
        }
        write(index, z, color, l1, l2, w, x, row);
      }
    }
  }

  void write(size_t index, float z, Rgb color, float l1, float l2, float w, int x, int row) {
    if (settings_.depth_write) target_.depth()[index] = z;
    if (settings_.wireframe.enabled) color = apply_wireframe(color, x, row);
    Rgb& dst = target_.color()[index];
    dst = settings_.blend == BlendMode::kAdd ? dst + color : color;
    if (target_.has_aovs()) write_aovs(index, l1, l2, w);
  }

  void write_aovs(size_t index, float l1, float l2, float w) {
    target_.object_ids()[index] = settings_.object_id;
    target_.primitive_ids()[index] = primitive_;
    target_.view_depth()[index] = w;
    if constexpr (HasNormalOutput<P>)
      target_.normals()[index] = program_.normal(interpolate(l1, l2));
  }

  // Blends the wire colour in where the pixel centre lies within half the line width of an edge,
  // with a one-pixel ramp so lines stay smooth.
  Rgb apply_wireframe(Rgb color, int x, int row) const {
    const int64_t px = int64_t(x) * kSubpixelScale + kHalfPixel;
    const int64_t py = int64_t(row) * kSubpixelScale + kHalfPixel;
    float d = 1e30f;
    for (int i = 0; i < 3; ++i) d = std::min(d, float(edge_[i](px, py)) * wire_scale_[i]);
    float half = 0.5f * settings_.wireframe.width_pixels;
    float t = std::clamp(half + 0.5f - d, 0.f, 1.f);
    return color * (1.f - t) + settings_.wireframe.color * t;
  }

  const P& program_;
  RenderTarget& target_;
  const FragmentSettings& settings_;
  std::span<const Vector2i> offsets_;
  int sample_extent_ = 0;  // largest |sample offset| in 1/256 pixel
  // The triangle: vertices in setup order, twice its area, whether the planes are set up.
  const ShadedVertex<V>* vertex_[3] = {};
  int64_t area2_ = 0;
  bool planes_ready_ = false;
  // Per-triangle setup.
  EdgeFunction edge_[3];
  int64_t edge_at_origin_[3];
  PixelRange cols_{}, rows_{};
  float z0_, zx_, zy_;
  float f0_[3], fx_[3], fy_[3];
  float base_[kN], d1_[kN], d2_[kN];
  float wire_scale_[3] = {};
  int64_t lane_step_[3][kRowAlignment];  // edge step × lane index, to add without multiplying
  uint32_t primitive_ = 0;
  bool front_facing_ = true;
  // Hierarchical z, per 8×8 block of the tile: no stored depth in the block exceeds its bound.
  // The rasterizer lives for one tile of one draw, so the bounds start unknown (+∞ admits
  // anything) and tighten as triangles overwrite whole blocks.
  static constexpr float kNoBound = std::numeric_limits<float>::infinity();
  float depth_bound_[kTileSize / kBlock][kTileSize / kBlock];
};

}  // namespace obscura::raster
