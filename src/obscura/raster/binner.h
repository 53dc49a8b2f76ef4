// Primitive assembly, clipping, culling and binning into screen tiles.
//
// Triangles are processed in fixed-size chunks of consecutive primitives, in parallel. Each chunk
// lists, per tile, the triangles that may touch it, in submission order; the tile stage then walks
// the chunks in order, so every pixel sees its triangles in submission order whatever the thread
// count (deterministic output, and "first drawn wins" on equal depth).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "obscura/raster/clipper.h"
#include "obscura/raster/draw_modes.h"
#include "obscura/raster/fill_rule.h"
#include "obscura/raster/render_target.h"
#include "obscura/raster/shaded_vertex.h"

namespace obscura::raster {

inline constexpr int kChunkTriangles = 2048;

// Vertex references with this bit set index the chunk's own vertices (made by clipping).
inline constexpr uint32_t kChunkVertexBit = 1u << 31;

struct BinnedTriangle {
  uint32_t vertex[3];
  uint32_t primitive;
};

// The rectangle of tiles [x0, x1] × [y0, y1] that a chunk's triangles touch (empty: x0 > x1). The
// tile stage visits every chunk for every tile; this lets it pass over a chunk without reading
// its bins (a dense draw has thousands of chunks, each touching few of the screen's tiles).
struct TileRect {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  bool contains(int x, int y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

struct TileGrid {
  int columns = 0, rows = 0;
  explicit TileGrid(Viewport v)
      : columns((v.width + kTileSize - 1) >> kTileSizeLog2),
        rows((v.height + kTileSize - 1) >> kTileSizeLog2) {}
  int count() const { return columns * rows; }
};

// The pixels whose samples may fall inside the snapped box [lo, hi] (1/256 pixel units) of one
// axis: sample positions are c·256 + 128 + o with o in [−extent, extent].
struct PixelRange {
  int first, last;
};
inline PixelRange pixel_range(int64_t lo, int64_t hi, int extent, int size) {
  int64_t first = ceil_div(lo - kHalfPixel - extent, kSubpixelScale);
  int64_t last = floor_div(hi - kHalfPixel + extent, kSubpixelScale);
  return {int(std::max<int64_t>(first, 0)), int(std::min<int64_t>(last, size - 1))};
}

struct BinSettings {
  Viewport viewport;
  GuardBand guard;
  CullMode cull = CullMode::kNone;
  FrontFace front_face = FrontFace::kCounterClockwise;
  int sample_extent = 0;  // largest |MSAA sample offset| in 1/256 pixel
};

// Whether a triangle of twice-signed-area `area2` (fill_rule.h's convention) faces the viewer.
inline bool is_front_facing(int64_t area2, FrontFace front_face) {
  // area2 > 0 is counter-clockwise in the y-down image's own axes; flipping y to NDC's y-up
  // reverses the winding, so area2 < 0 is counter-clockwise in NDC.
  return front_face == FrontFace::kCounterClockwise ? area2 < 0 : area2 > 0;
}

template <VaryingsType V>
class Chunk {
 public:
  std::vector<BinnedTriangle> triangles;
  std::vector<ShadedVertex<V>> vertices;  // made by clipping
  std::vector<uint32_t> bin_start;        // per tile, into bin_items; tile_count + 1 entries
  std::vector<uint32_t> bin_items;        // triangle indices, grouped by tile, in order
  TileRect tiles;                         // the tiles any of its triangles touches

  const ShadedVertex<V>& vertex(uint32_t ref, const ShadedVertex<V>* shared) const {
    return (ref & kChunkVertexBit) ? vertices[ref & ~kChunkVertexBit] : shared[ref];
  }

  // Assembles triangles [first, last) of the draw: `corner(t, k)` is the shared-vertex index of
  // corner k of triangle t.
  template <class CornerIndex>
  void build(uint32_t first, uint32_t last, CornerIndex corner, const ShadedVertex<V>* shared,
             const BinSettings& settings, TileGrid grid) {
    triangles.clear();
    vertices.clear();
    pairs_.clear();
    tiles = TileRect{grid.columns, grid.rows, -1, -1};
    for (uint32_t t = first; t < last; ++t) {
      uint32_t ref[3] = {corner(t, 0), corner(t, 1), corner(t, 2)};
      const ShadedVertex<V>* v[3] = {&shared[ref[0]], &shared[ref[1]], &shared[ref[2]]};
      if (v[0]->outcode & v[1]->outcode & v[2]->outcode) continue;  // all outside one plane
      if ((v[0]->outcode | v[1]->outcode | v[2]->outcode) == 0) {
        emit(ref, v, t, settings, grid);
      } else {
        clip_and_emit(v, t, settings, grid);
      }
    }
    sort_into_bins(grid.count());
  }

 private:
  void emit(const uint32_t ref[3], const ShadedVertex<V>* const v[3], uint32_t primitive,
            const BinSettings& s, TileGrid grid) {
    int64_t area2 = twice_signed_area(v[0]->x, v[0]->y, v[1]->x, v[1]->y, v[2]->x, v[2]->y);
    if (area2 == 0) return;  // zero-area triangles draw nothing
    if (s.cull != CullMode::kNone) {
      bool front = is_front_facing(area2, s.front_face);
      if (front == (s.cull == CullMode::kFront)) return;
    }
    int32_t min_x = std::min({v[0]->x, v[1]->x, v[2]->x});
    int32_t max_x = std::max({v[0]->x, v[1]->x, v[2]->x});
    int32_t min_y = std::min({v[0]->y, v[1]->y, v[2]->y});
    int32_t max_y = std::max({v[0]->y, v[1]->y, v[2]->y});
    PixelRange xs = pixel_range(min_x, max_x, s.sample_extent, s.viewport.width);
    PixelRange ys = pixel_range(min_y, max_y, s.sample_extent, s.viewport.height);
    if (xs.first > xs.last || ys.first > ys.last) return;  // covers no sample position
    uint32_t index = uint32_t(triangles.size());
    triangles.push_back({{ref[0], ref[1], ref[2]}, primitive});
    const int tx0 = xs.first >> kTileSizeLog2, tx1 = xs.last >> kTileSizeLog2;
    const int ty0 = ys.first >> kTileSizeLog2, ty1 = ys.last >> kTileSizeLog2;
    tiles = {std::min(tiles.x0, tx0), std::min(tiles.y0, ty0), std::max(tiles.x1, tx1),
             std::max(tiles.y1, ty1)};
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx)
        pairs_.push_back({uint32_t(ty * grid.columns + tx), index});
  }

  void clip_and_emit(const ShadedVertex<V>* const v[3], uint32_t primitive, const BinSettings& s,
                     TileGrid grid) {
    VertexOutput<V> poly[kMaxClippedVertices] = {v[0]->out, v[1]->out, v[2]->out};
    uint32_t planes = v[0]->outcode | v[1]->outcode | v[2]->outcode;
    int n = clip_polygon(poly, 3, planes, s.guard);
    if (n < 3) return;
    // Clip coordinates near a float's limit (1e37) overflow in the plane distances, leaving NaN
    // or Inf vertices: such a triangle has no image to draw, and snapping it would be undefined.
    for (int i = 0; i < n; ++i) {
      const Vector4f& c = poly[i].clip;
      if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && c.w > 0 &&
            std::isfinite(c.w)))
        return;
    }
    uint32_t base = uint32_t(vertices.size());
    for (int i = 0; i < n; ++i) {
      ShadedVertex<V> sv;
      sv.out = poly[i];
      sv.outcode = 0;
      project(sv, s.viewport);
      vertices.push_back(sv);
    }
    // A fan over the convex polygon; the fill rule keeps its inner edges seamless.
    for (int i = 1; i + 1 < n; ++i) {
      uint32_t ref[3] = {(base) | kChunkVertexBit, (base + i) | kChunkVertexBit,
                         (base + i + 1) | kChunkVertexBit};
      const ShadedVertex<V>* fan[3] = {&vertices[base], &vertices[base + i],
                                       &vertices[base + i + 1]};
      emit(ref, fan, primitive, s, grid);
    }
  }

  // Counting sort of (tile, triangle) pairs by tile; stable, so each bin stays in order.
  void sort_into_bins(int tile_count) {
    bin_start.assign(size_t(tile_count) + 1, 0);
    for (const Pair& p : pairs_) ++bin_start[p.tile + 1];
    for (int t = 0; t < tile_count; ++t) bin_start[t + 1] += bin_start[t];
    bin_items.resize(pairs_.size());
    cursor_.assign(bin_start.begin(), bin_start.end() - 1);
    for (const Pair& p : pairs_) bin_items[cursor_[p.tile]++] = p.triangle;
  }

  struct Pair {
    uint32_t tile, triangle;
  };
  std::vector<Pair> pairs_;
  std::vector<uint32_t> cursor_;
};

}  // namespace obscura::raster
