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
#include <bit>
#include <concepts>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <limits>
#include <type_traits>
#include <utility>

#include "obscura/color/rgb.h"
#include "obscura/raster/binner.h"
#include "obscura/raster/draw_modes.h"
#include "obscura/raster/fill_rule.h"
#include "obscura/raster/msaa.h"
#include "obscura/raster/render_target.h"
#include "obscura/raster/shaded_vertex.h"
#include "obscura/raster/simd.h"
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

// Programs may also give a fragment a coverage α in [0, 1] (glTF alpha: the alpha test discards
// below a cutoff, "over" blending weighs by it), from varyings at any point of the pixel and
// their screen-space derivatives. Only programs that have one pay for it.
template <class P>
concept CoverageProgram = requires(const P& p, const typename P::Varyings& var) {
  { p.coverage(var, var, var) } -> std::convertible_to<float>;
};

// Edges drawn over the shaded surface, measured in pixels from each triangle's edges.
struct Wireframe {
  bool enabled = false;
  float width_pixels = 1.f;
  Rgb color{1.f, 1.f, 1.f};

  bool operator==(const Wireframe&) const = default;
};

// Not a comparison of its own: the tile loop compiled with it as its depth function reads
// FragmentSettings::depth_func per block instead. draw() uses it for the functions other than
// LESS (the one scenes draw with), so the loop is compiled twice for a program, not eight times.
inline constexpr DepthFunc kDepthFuncFromSettings = DepthFunc(-1);

struct FragmentSettings {
  DepthFunc depth_func = DepthFunc::kLess;  // read only by the kDepthFuncFromSettings loop
  bool depth_write = true;
  BlendMode blend = BlendMode::kReplace;
  bool alpha_test = false;  // discard fragments whose coverage is below alpha_cutoff
  float alpha_cutoff = 0.5f;
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

template <Program P, DepthFunc F, class Isa = simd::Baseline>
class TriangleRasterizer {
 public:
  using V = typename P::Varyings;
  static constexpr int kN = kVaryingFloats<V>;
  static constexpr int kBlockLog2 = 3;
  static constexpr int kBlock = 1 << kBlockLog2;  // 8×8-pixel blocks; rows go 8 lanes at a time
  static_assert(kBlock == kRowAlignment && kTileSize % kBlock == 0);  // colour groups = rows
  static constexpr bool kHierarchicalZ = F == DepthFunc::kLess || F == DepthFunc::kLessEqual;

  // The depth and interpolation planes, relative to the centre of the box's first pixel: window
  // depth z0 + zx·dx + zy·dy; f_i = λ_i/w_i likewise; varyings base + d1·l1 + d2·l2.
  struct Planes {
    float z0, zx, zy;
    float f0[3], fx[3], fy[3];
    float base[kN], d1[kN], d2[kN];
  };

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
    const ShadedVertex<V>* u[3] = {&a, &b, &c};
    int64_t area2 = twice_signed_area(a.x, a.y, b.x, b.y, c.x, c.y);
    if (area2 == 0) return false;
    front_facing_ = is_front_facing(area2, settings_.front_face);
    if (area2 < 0) std::swap(u[1], u[2]), area2 = -area2;
    // Start at the topmost-leftmost vertex: the same triangle given in any vertex order then
    // gets bit-identical planes (equal depths compare equal).
    auto above = [](const ShadedVertex<V>* p, const ShadedVertex<V>* q) {
      return p->y < q->y || (p->y == q->y && p->x < q->x);
    };
    const int first = above(u[1], u[0]) ? (above(u[2], u[1]) ? 2 : 1) : (above(u[2], u[0]) ? 2 : 0);
    const ShadedVertex<V>* v[3] = {u[first], u[first == 2 ? 0 : first + 1],
                                   u[first == 0 ? 2 : first - 1]};
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
    // Edges spanning under 2^18 subpixels (1,024 pixels) per axis vary by under 2^30 over a
    // block, so where a block straddles one its values fit 32-bit lanes.
    narrow_ = true;
    for (int i = 0; i < 3; ++i) {
      sx_[i] = edge_[i].step_x * kSubpixelScale, sy_[i] = edge_[i].step_y * kSubpixelScale;
      e0_[i] = edge_at_origin_[i] + edge_[i].bias;
      narrow_ &= std::abs(edge_[i].step_x) < (1 << 18) && std::abs(edge_[i].step_y) < (1 << 18);
    }
    if (narrow_)
      for (int i = 0; i < 3; ++i) {
        lane_sx_[i] = simd::splat(int32_t(sx_[i])) * simd::kLaneIndex;
        row_sy_[i] = simd::splat(int32_t(sy_[i]));
      }
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
      p_.f0[i] = float(e0 * w), p_.fx[i] = float(ex * w), p_.fy[i] = float(ey * w);
    }
    p_.z0 = float(zc), p_.zx = float(zx), p_.zy = float(zy);
    auto v0 = to_floats(v[0]->out.varyings), v1 = to_floats(v[1]->out.varyings),
         v2 = to_floats(v[2]->out.varyings);
    for (int k = 0; k < kN; ++k)
      p_.base[k] = v0[k], p_.d1[k] = v1[k] - v0[k], p_.d2[k] = v2[k] - v0[k];
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
    for (int k = 0; k < kN; ++k) r[k] = p_.base[k] + p_.d1[k] * l1 + p_.d2[k] * l2;
    return from_floats<V>(r);
  }

  // Perspective-correct weights of vertices 1 and 2 at (dx, dy) pixels from the box origin.
  void weights(float dx, float dy, float* l1, float* l2, float* w) const {
    float f0 = p_.f0[0] + p_.fx[0] * dx + p_.fy[0] * dy,
          f1 = p_.f0[1] + p_.fx[1] * dx + p_.fy[1] * dy,
          f2 = p_.f0[2] + p_.fx[2] * dx + p_.fy[2] * dy;
    *w = 1.f / (f0 + f1 + f2);
    *l1 = f1 * *w, *l2 = f2 * *w;
  }

  // The varyings' differences to the neighbouring pixel centres (weights l1, l2 at (dx, dy)).
  OBSCURA_RASTER_INLINE void derivatives(float l1, float l2, float dx, float dy, V* d_dx,
                                         V* d_dy) const {
    float a1, a2, b1, b2, w;
    weights(dx + 1, dy, &a1, &a2, &w);
    weights(dx, dy + 1, &b1, &b2, &w);
    VaryingArray<V> x, y;
    for (int k = 0; k < kN; ++k) {
      x[k] = p_.d1[k] * (a1 - l1) + p_.d2[k] * (a2 - l2);
      y[k] = p_.d1[k] * (b1 - l1) + p_.d2[k] * (b2 - l2);
    }
    *d_dx = from_floats<V>(x), *d_dy = from_floats<V>(y);
  }

  OBSCURA_RASTER_INLINE Rgb shade(float l1, float l2, float dx, float dy, int x, int row) const {
    FragmentInfo info{x, row, primitive_, front_facing_};
    if constexpr (PlainFragmentShader<P>) {
      return program_.fragment(interpolate(l1, l2), info);
    } else {
      V d_dx, d_dy;
      derivatives(l1, l2, dx, dy, &d_dx, &d_dy);
      return program_.fragment(interpolate(l1, l2), d_dx, d_dy, info);
    }
  }

  // The program's coverage at (dx, dy) pixels from the box origin (any point, not only a centre).
  float coverage_at(float dx, float dy) const {
    if constexpr (CoverageProgram<P>) {
      float l1, l2, w;
      weights(dx, dy, &l1, &l2, &w);
      V d_dx, d_dy;
      derivatives(l1, l2, dx, dy, &d_dx, &d_dy);
      return program_.coverage(interpolate(l1, l2), d_dx, d_dy);
    }
    return 1.f;
  }
  bool discarded(float alpha) const {
    return settings_.alpha_test && !(alpha >= settings_.alpha_cutoff);
  }

  // Single sample per pixel. The box is walked in 8×8 blocks aligned to the tile, a block row
  // being one eight-lane vector. Each edge function is affine, so its extremes over a block lie
  // at the block's corners: a block outside one edge is skipped, and edges a block lies wholly
  // inside are not tested per pixel. With a LESS/LEQUAL depth test, a block whose nearest depth
  // cannot pass against the block's depth bound (hierarchical z) is skipped before any per-pixel
  // work.
  OBSCURA_RASTER_INLINE void rasterize_blocks(PixelRect tile) {
    // A local copy of the planes, made once they are set up: stores into the target cannot
    // alias a local, so the compiler keeps its values in registers across the pixel loop.
    Planes local{};
    bool have_planes = false;
    auto planes = [&]() -> const Planes& {
      if (!have_planes) setup_planes(), local = p_, have_planes = true;
      return local;
    };
    const int bx0 = (cols_.first - tile.x0) >> kBlockLog2,
              bx1 = (cols_.last - tile.x0) >> kBlockLog2;
    const int by0 = (rows_.first - tile.y0) >> kBlockLog2,
              by1 = (rows_.last - tile.y0) >> kBlockLog2;
    int64_t corner_lo[3], corner_hi[3];  // extremes over a block of E − E(block's first pixel)
    for (int i = 0; i < 3; ++i) {
      const int64_t ex = sx_[i] * (kBlock - 1), ey = sy_[i] * (kBlock - 1);
      corner_lo[i] = std::min<int64_t>(ex, 0) + std::min<int64_t>(ey, 0);
      corner_hi[i] = std::max<int64_t>(ex, 0) + std::max<int64_t>(ey, 0);
    }
    for (int by = by0; by <= by1; ++by) {
      const int block_y = tile.y0 + (by << kBlockLog2);
      const int y_lo = std::max(rows_.first, block_y),
                y_hi = std::min(rows_.last, block_y + kBlock - 1);
      for (int bx = bx0; bx <= bx1; ++bx) {
        const int block_x = tile.x0 + (bx << kBlockLog2);
        const int x_lo = std::max(cols_.first, block_x);
        const int x_hi = std::min(cols_.last, block_x + kBlock - 1);
        int64_t e[3];  // edge values (bias included) at the block's first pixel centre
        uint32_t partial = 0;
        bool outside = false;
        for (int i = 0; i < 3; ++i) {
          e[i] = e0_[i] + sx_[i] * (block_x - cols_.first) + sy_[i] * (block_y - rows_.first);
          outside |= e[i] + corner_hi[i] < 0;
          partial |= uint32_t(e[i] + corner_lo[i] < 0) << i;
        }
        if (outside) continue;
        float& bound = depth_bound_[by][bx];
        if constexpr (kHierarchicalZ) {
          if (bound != kNoBound) {
            const Planes& p = planes();
            // Depth is monotone in x and y (see pixel_depth), so its minimum over the block is
            // the smallest of the corner values.
            float z_min = std::min({pixel_depth(p, x_lo, y_lo), pixel_depth(p, x_hi, y_lo),
                                    pixel_depth(p, x_lo, y_hi), pixel_depth(p, x_hi, y_hi)});
            if (F == DepthFunc::kLess ? z_min >= bound : z_min > bound) continue;
          }
        }
        bool all_written = partial == 0 && x_lo == block_x && x_hi == block_x + kBlock - 1 &&
                           y_lo == block_y && y_hi == block_y + kBlock - 1;
        const simd::Mask8 span =
            (simd::kLaneIndex >= x_lo - block_x) & (simd::kLaneIndex <= x_hi - block_x);
        if (narrow_) {
          // All three edges as 32-bit lanes, stepped row by row, without branches. An edge the
          // block lies inside may be far larger than 32 bits: clamped to 2^30, it stays positive
          // over the block (it varies by under 2^30 there, see setup).
          simd::Int8 ev[3];
          for (int i = 0; i < 3; ++i)
            ev[i] = simd::splat(int32_t(
                        std::min<int64_t>(e[i] + sy_[i] * (y_lo - block_y), int64_t(1) << 30))) +
                    lane_sx_[i];
          for (int row = y_lo; row <= y_hi; ++row) {
            const simd::Mask8 m = span & ((ev[0] | ev[1] | ev[2]) >= 0);
            for (int i = 0; i < 3; ++i) ev[i] += row_sy_[i];
            const uint32_t live = simd::bits<Isa>(m);
            all_written &= live == 0xFF;
            if (live) shade_row(planes(), row, block_x, m, &all_written);
          }
        } else {
          for (int row = y_lo; row <= y_hi; ++row) {
            simd::Mask8 m = span;
            if (partial) m &= coverage(e, partial, row - block_y);
            const uint32_t live = simd::bits<Isa>(m);
            all_written &= live == 0xFF;
            if (live) shade_row(planes(), row, block_x, m, &all_written);
          }
        }
        // Every pixel of the block now holds a depth written here: the bound tightens to the
        // largest, at a corner. The margin (far above one rounding) keeps it an upper bound even
        // if a compiler contracted the pixel loop's arithmetic differently. Otherwise the bound
        // stays valid, as LESS/LEQUAL with depth writes only ever lower stored depths.
        if (kHierarchicalZ && all_written && settings_.depth_write) {
          const Planes& p = planes();
          bound = std::max({pixel_depth(p, x_lo, y_lo), pixel_depth(p, x_hi, y_lo),
                            pixel_depth(p, x_lo, y_hi), pixel_depth(p, x_hi, y_hi)}) *
                  (1.f + 0x1p-20f);
        }
      }
    }
  }

  // The window depth the pixel loop computes at pixel (x, y) of the box: z_row + zx·k, each step
  // rounded, is monotone in k and in the row, so extremes over a rectangle lie at its corners.
  OBSCURA_RASTER_INLINE float pixel_depth(const Planes& p, int x, int y) const {
    const float z_row = p.z0 + p.zy * float(y - rows_.first);
    return clamp_unit(z_row + p.zx * float(x - cols_.first));
  }

  // Coverage of row j of a block by the edges flagged in `partial` (a triangle with long edges);
  // e: the edge values at the block's first pixel.
  OBSCURA_RASTER_INLINE simd::Mask8 coverage(const int64_t e[3], uint32_t partial, int j) const {
    simd::Mask8 m = simd::splat(int32_t(-1));
    for (int i = 0; i < 3; ++i) {
      if (!(partial & (1u << i))) continue;
      const int64_t e_row = e[i] + sy_[i] * j;
      simd::Mask8 c;
      for (int lane = 0; lane < kBlock; ++lane) c[lane] = -int32_t(e_row + sx_[i] * lane >= 0);
      m &= c;
    }
    return m;
  }

  // One row of one block: the pixels of lanes set in `m` (covered, inside the box; at least one),
  // then the depth test, shading and output. `*all_written` is cleared unless every lane passed.
  OBSCURA_RASTER_INLINE void shade_row(const Planes& p, int row, int x0, simd::Mask8 m,
                                       bool* all_written) {
    using simd::Float8;
    const int dy = row - rows_.first;
    const int k0 = x0 - cols_.first;
    const size_t index = target_.sample_index(x0, row);
    float* depth = target_.depth() + index;
    const Float8 k = simd::splat(float(k0)) + simd::kLaneOffset;  // exact: small integers
    const Float8 z = simd::clamp_unit(simd::splat(p.z0 + p.zy * float(dy)) + p.zx * k);
    const Float8 stored = simd::load(depth);
    m &= depth_mask(z, stored);
    const uint32_t live = simd::bits<Isa>(m);
    *all_written &= live == 0xFF;
    if (live == 0) return;  // early depth rejection of the whole run
    if constexpr (CoverageProgram<P>) {
      // Materials with alpha, pixel by pixel: test, shade and blend each live lane.
      for (uint32_t rest = live; rest; rest &= rest - 1) {
        const int i = std::countr_zero(rest);
        const float dx = float(k0 + i), alpha = coverage_at(dx, float(dy));
        if (discarded(alpha)) {
          *all_written = false;
          continue;
        }
        float l1, l2, w;
        weights(dx, float(dy), &l1, &l2, &w);
        write(index + size_t(i), z[i], shade(l1, l2, dx, float(dy), x0 + i, row), l1, l2, w, x0 + i,
              row, alpha);
      }
      return;
    }
    // Shaders that need derivatives run per pixel: for small triangles only the live ones.
    if (DerivativeFragmentShader<P> && std::popcount(live) <= 2) {
      for (uint32_t rest = live; rest; rest &= rest - 1) {
        const int i = std::countr_zero(rest);
        float l1, l2, w;
        weights(float(k0 + i), float(dy), &l1, &l2, &w);
        write(index + size_t(i), z[i], shade(l1, l2, float(k0 + i), float(dy), x0 + i, row), l1, l2,
              w, x0 + i, row);
      }
      return;
    }
    const Float8 f0 = simd::splat(p.f0[0] + p.fy[0] * float(dy)) + p.fx[0] * k;
    const Float8 f1 = simd::splat(p.f0[1] + p.fy[1] * float(dy)) + p.fx[1] * k;
    const Float8 f2 = simd::splat(p.f0[2] + p.fy[2] * float(dy)) + p.fx[2] * k;
    const Float8 w = 1.f / (f0 + f1 + f2);
    const Float8 l1 = f1 * w, l2 = f2 * w;
    Float8 r, g, b;
    shade_block(p, l1, l2, float(k0), float(dy), x0, row, &r, &g, &b);
    if (settings_.wireframe.enabled)
      for (int i = 0; i < kBlock; ++i) {
        Rgb c = apply_wireframe({r[i], g[i], b[i]}, x0 + i, row);
        r[i] = c.r, g[i] = c.g, b[i] = c.b;
      }
    if (settings_.depth_write) simd::store(depth, live == 0xFF ? z : simd::select(m, z, stored));
    float* color = target_.color_group(index);
    if (settings_.blend == BlendMode::kAdd) {
      r += simd::load(color), g += simd::load(color + kBlock), b += simd::load(color + 2 * kBlock);
    }
    if (live != 0xFF) {
      r = simd::select(m, r, simd::load(color));
      g = simd::select(m, g, simd::load(color + kBlock));
      b = simd::select(m, b, simd::load(color + 2 * kBlock));
    }
    simd::store(color, r), simd::store(color + kBlock, g), simd::store(color + 2 * kBlock, b);
    if (target_.has_aovs())
      for (int i = 0; i < kBlock; ++i)
        if (live & (1u << i)) write_aovs(index + size_t(i), l1[i], l2[i], w[i]);
  }

  template <DepthFunc G>
  OBSCURA_RASTER_INLINE static simd::Mask8 depth_mask_for(simd::Float8 z, simd::Float8 stored) {
    if constexpr (G == DepthFunc::kNever) return simd::Mask8{};
    if constexpr (G == DepthFunc::kLess) return z < stored;
    if constexpr (G == DepthFunc::kEqual) return z == stored;
    if constexpr (G == DepthFunc::kLessEqual) return z <= stored;
    if constexpr (G == DepthFunc::kGreater) return z > stored;
    if constexpr (G == DepthFunc::kNotEqual) return z != stored;
    if constexpr (G == DepthFunc::kGreaterEqual) return z >= stored;
    if constexpr (G == DepthFunc::kAlways) return simd::splat(int32_t(-1));
  }

  // Calls `test` with std::integral_constant<DepthFunc, G>: G is the loop's depth function F, or
  // in the kDepthFuncFromSettings loop the settings' function, chosen at each call.
  template <class Test>
  OBSCURA_RASTER_INLINE auto with_depth_func(Test&& test) const {
    using C = DepthFunc;
    if constexpr (F != kDepthFuncFromSettings) {
      return test(std::integral_constant<C, F>{});
    } else {
      switch (settings_.depth_func) {
        case C::kNever:
          return test(std::integral_constant<C, C::kNever>{});
        case C::kLess:
          return test(std::integral_constant<C, C::kLess>{});
        case C::kEqual:
          return test(std::integral_constant<C, C::kEqual>{});
        case C::kLessEqual:
          return test(std::integral_constant<C, C::kLessEqual>{});
        case C::kGreater:
          return test(std::integral_constant<C, C::kGreater>{});
        case C::kNotEqual:
          return test(std::integral_constant<C, C::kNotEqual>{});
        case C::kGreaterEqual:
          return test(std::integral_constant<C, C::kGreaterEqual>{});
        case C::kAlways:
          break;
      }
      return test(std::integral_constant<C, C::kAlways>{});
    }
  }

  OBSCURA_RASTER_INLINE simd::Mask8 depth_mask(simd::Float8 z, simd::Float8 stored) const {
    return with_depth_func([&](auto g) { return depth_mask_for<decltype(g)::value>(z, stored); });
  }

  // The same for one sample.
  OBSCURA_RASTER_INLINE bool sample_passes_depth(float z, float stored) const {
    return with_depth_func([&](auto g) { return depth_passes<decltype(g)::value>(z, stored); });
  }

  // The fragment shader on a run of kBlock pixels (weights l1, l2 per lane), colours out as
  // planes. Varyings are interpolated plane by plane (one vector per varying), then each lane's
  // struct is gathered from the planes: with no loop left over the varyings, the loop over lanes
  // is what the vectorizer sees, and it turns the whole shader into vector code.
  OBSCURA_RASTER_INLINE void shade_block(const Planes& p, simd::Float8 l1, simd::Float8 l2,
                                         float k0, float dy, int x0, int row, simd::Float8* r,
                                         simd::Float8* g, simd::Float8* b) const {
    float rs[kBlock], gs[kBlock], bs[kBlock];
    if constexpr (PlainFragmentShader<P>) {
      float planes[kN][kBlock];
      for (int k = 0; k < kN; ++k) simd::store(planes[k], p.base[k] + p.d1[k] * l1 + p.d2[k] * l2);
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC ivdep
#endif
      for (int i = 0; i < kBlock; ++i) {
        Rgb c = program_.fragment(gather_lane(planes, i, std::make_index_sequence<kN>()),
                                  FragmentInfo{x0 + i, row, primitive_, front_facing_});
        rs[i] = c.r, gs[i] = c.g, bs[i] = c.b;
      }
    } else {
      for (int i = 0; i < kBlock; ++i) {
        Rgb c = shade(l1[i], l2[i], k0 + float(i), dy, x0 + i, row);
        rs[i] = c.r, gs[i] = c.g, bs[i] = c.b;
      }
    }
    *r = simd::load(rs), *g = simd::load(gs), *b = simd::load(bs);
  }

  template <size_t... K>
  OBSCURA_RASTER_INLINE static V gather_lane(const float (&planes)[kN][kBlock], int i,
                                             std::index_sequence<K...>) {
    return from_floats<V>(VaryingArray<V>{planes[K][i]...});
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
      float l1 = 0, l2 = 0, w = 0, alpha = 1;
      for (int s = 0; s < samples; ++s) {
        if (x < first[s] || x > last[s]) continue;
        const float sx = dx + offsets_[s].x / float(kSubpixelScale),
                    sy = float(dy) + offsets_[s].y / float(kSubpixelScale);
        float z = std::clamp(p_.z0 + p_.zx * sx + p_.zy * sy, 0.f, 1.f);
        size_t index = target_.sample_index(x, row, s);
        if (!sample_passes_depth(z, target_.depth()[index])) continue;
        // The alpha test per sample, so that cut-outs get anti-aliased edges.
        if (CoverageProgram<P> && settings_.alpha_test && discarded(coverage_at(sx, sy))) continue;
        if (!shaded) {
          weights(dx, float(dy), &l1, &l2, &w);
          color = shade(l1, l2, dx, float(dy), x, row);
          if (CoverageProgram<P> && settings_.blend == BlendMode::kOver)
            alpha = coverage_at(dx, float(dy));
          shaded = true;
        }
        write(index, z, color, l1, l2, w, x, row, alpha);
      }
    }
  }

  // `alpha`: the coverage "over" blending weighs the colour by. A blended fragment names the
  // surface in the aovs only where it covers at least half of what lies behind.
  void write(size_t index, float z, Rgb color, float l1, float l2, float w, int x, int row,
             float alpha = 1) {
    if (settings_.depth_write) target_.depth()[index] = z;
    if (settings_.wireframe.enabled) color = apply_wireframe(color, x, row);
    if (settings_.blend == BlendMode::kAdd) color = target_.color(index) + color;
    if (settings_.blend == BlendMode::kOver) {
      alpha = clamp_unit(alpha);  // at an MSAA edge pixel's centre, varyings are extrapolated
      color = color * alpha + target_.color(index) * (1 - alpha);
    }
    target_.set_color(index, color);
    if (target_.has_aovs() && (settings_.blend != BlendMode::kOver || alpha >= 0.5f))
      write_aovs(index, l1, l2, w);
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
  Planes p_;
  float wire_scale_[3] = {};
  // The single-sample block walk's view of the edges: values at the box origin with the bias
  // folded in, steps per pixel, and for narrow edges (see setup) the step times each lane.
  int64_t e0_[3], sx_[3], sy_[3];
  bool narrow_ = false;
  simd::Int8 lane_sx_[3], row_sy_[3];
  uint32_t primitive_ = 0;
  bool front_facing_ = true;
  // Hierarchical z, per 8×8 block of the tile: no stored depth in the block exceeds its bound.
  // The rasterizer lives for one tile of one draw, so the bounds start unknown (+∞ admits
  // anything) and tighten as triangles overwrite whole blocks.
  static constexpr float kNoBound = std::numeric_limits<float>::infinity();
  float depth_bound_[kTileSize / kBlock][kTileSize / kBlock];
};

}  // namespace obscura::raster
