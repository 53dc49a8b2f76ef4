// The rasterization pipeline: one draw call from vertices to pixels.
//
//   1. vertex shader, once per vertex (parallel);
//   2. primitive assembly, clipping, culling, snapping and binning into 64×64 tiles, in chunks of
//      consecutive triangles (parallel);
//   3. per tile, the tile's triangles in submission order: rasterization, depth test,
//      perspective-correct interpolation, fragment shader, output (parallel over tiles).
// Every pixel sees its triangles in submission order, so the image is identical for any number
// of threads. A Program is a plain C++ type (see tile_rasterizer.h's concept); it is a template
// argument, so shaders inline into the pixel loop: no virtual call per pixel or vertex.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>

#include "obscura/math/error.h"
#include "obscura/raster/binner.h"
#include "obscura/raster/clipper.h"
#include "obscura/raster/draw_modes.h"
#include "obscura/raster/msaa.h"
#include "obscura/raster/render_target.h"
#include "obscura/raster/shaded_vertex.h"
#include "obscura/raster/tile_rasterizer.h"

namespace obscura::raster {

struct DrawState {
  DepthFunc depth_func = DepthFunc::kLess;
  bool depth_write = true;
  CullMode cull = CullMode::kNone;
  FrontFace front_face = FrontFace::kCounterClockwise;
  BlendMode blend = BlendMode::kReplace;
  // Alpha test: fragments whose coverage (see CoverageProgram) is below the cutoff are discarded,
  // per sample under MSAA. Programs without coverage have coverage 1.
  bool alpha_test = false;
  float alpha_cutoff = 0.5f;
  uint32_t object_id = 1;  // written to the id output; 0 (kNoObject) is the background
  Wireframe wireframe;
};

namespace detail {

template <Program P>
struct TileJob {
  const P& program;
  RenderTarget& target;
  FragmentSettings settings;
  const std::vector<Chunk<typename P::Varyings>>& chunks;
  const TileRect* chunk_tiles;  // chunks[c].tiles, gathered into one array (cache-friendly)
  const ShadedVertex<typename P::Varyings>* shared;
  TileGrid grid;
};

// One tile: its triangles from every chunk, in submission order.
template <Program P, DepthFunc F, class Isa>
OBSCURA_RASTER_INLINE void rasterize_tile(const TileJob<P>& job, int tile) {
  PixelRect rect{(tile % job.grid.columns) * kTileSize, (tile / job.grid.columns) * kTileSize, 0,
                 0};
  rect.x1 = std::min(rect.x0 + kTileSize, job.target.width());
  rect.y1 = std::min(rect.y0 + kTileSize, job.target.height());
  TriangleRasterizer<P, F, Isa> rasterizer(job.program, job.target, job.settings);
  constexpr uint32_t kLookahead = 4;  // triangles: the vertices of dense meshes come from L3
  const int tile_x = tile % job.grid.columns, tile_y = tile / job.grid.columns;
  for (size_t c = 0; c < job.chunks.size(); ++c) {
    if (!job.chunk_tiles[c].contains(tile_x, tile_y)) continue;
    const auto& chunk = job.chunks[c];
    const uint32_t end = chunk.bin_start[tile + 1];
    for (uint32_t k = chunk.bin_start[tile]; k < end; ++k) {
      if (k + kLookahead < end) {
        const BinnedTriangle& ahead = chunk.triangles[chunk.bin_items[k + kLookahead]];
        for (uint32_t ref : ahead.vertex) __builtin_prefetch(&chunk.vertex(ref, job.shared));
      }
      const BinnedTriangle& t = chunk.triangles[chunk.bin_items[k]];
      rasterizer.draw(chunk.vertex(t.vertex[0], job.shared), chunk.vertex(t.vertex[1], job.shared),
                      chunk.vertex(t.vertex[2], job.shared), t.primitive, rect);
    }
  }
}

// flatten: the program's own helper functions inline too, whatever the compiler's heuristics.
template <Program P, DepthFunc F>
[[gnu::flatten]] void rasterize_tile_baseline(const TileJob<P>& job, int tile) {
  rasterize_tile<P, F, simd::Baseline>(job, tile);
}

#if defined(__x86_64__) && defined(__GNUC__)
// The same code compiled for AVX2 and FMA (8-wide float vectors), used when the CPU has both. Only
// this function carries the target, so nothing compiled for AVX2 can run on a CPU without it.
template <Program P, DepthFunc F>
[[gnu::target("avx2,fma"), gnu::flatten]] void rasterize_tile_avx2(const TileJob<P>& job,
                                                                   int tile) {
  rasterize_tile<P, F, simd::Avx2>(job, tile);
}
#endif

}  // namespace detail

// Whether draws run the tile loop's AVX2 + FMA copy: on where the CPU has both. Tests switch it
// off to run the baseline copy on any machine.
inline std::atomic<bool>& use_avx2() {
#if defined(__x86_64__) && defined(__GNUC__)
  static std::atomic<bool> on = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
  static std::atomic<bool> on = false;
#endif
  return on;
}

namespace detail {

template <Program P, DepthFunc F>
void rasterize_tiles(const TileJob<P>& job) {
  [[maybe_unused]] const bool avx2 = use_avx2().load(std::memory_order_relaxed);
  tbb::parallel_for(0, job.grid.count(), [&](int tile) {
    if (!job.target.draws_tile(tile)) return;
#if defined(__x86_64__) && defined(__GNUC__)
    if (avx2) return rasterize_tile_avx2<P, F>(job, tile);
#endif
    rasterize_tile_baseline<P, F>(job, tile);
  });
}

// The per-draw buffers (shaded vertices, bins), kept per thread between draws: a frame of a
// million triangles would otherwise allocate and page in tens of MB for each draw. A draw takes
// the thread's buffers and gives them back when done, so a draw nested on the same thread (a
// task stolen while waiting) simply allocates its own.
template <VaryingsType V>
struct DrawScratch {
  std::vector<ShadedVertex<V>> shared;
  std::vector<Chunk<V>> chunks;
  std::vector<TileRect> chunk_tiles;

  static DrawScratch take() { return std::exchange(cache(), DrawScratch()); }
  static void give_back(DrawScratch&& scratch) { cache() = std::move(scratch); }

 private:
  static DrawScratch& cache() {
    thread_local DrawScratch scratch;
    return scratch;
  }
};

}  // namespace detail

namespace detail {

// The largest index, as a branch-free reduction the compiler vectorizes: this check runs serially
// over every index of every draw (12 M for a 4 M-triangle mesh), and a compare-and-throw loop
// cannot be vectorized. Only a draw that fails it searches for the offending index.
inline uint32_t largest_index(std::span<const uint32_t> indices) {
  uint32_t largest = 0;
  for (uint32_t i : indices) largest = std::max(largest, i);
  return largest;
}

// Stages 1 and 2 of a draw, then `rasterize(job)` for stage 3.
template <Program P, class Rasterize>
void draw_with(RenderTarget& target, const DrawState& state, const P& program,
               std::span<const typename P::Vertex> vertices, std::span<const uint32_t> indices,
               Rasterize&& rasterize) {
  using V = typename P::Varyings;
  const bool indexed = !indices.empty();
  const size_t corner_count = indexed ? indices.size() : vertices.size();
  if (corner_count % 3 != 0)
    throw Error("draw", "the number of " + std::string(indexed ? "indices" : "vertices") + " (" +
                            std::to_string(corner_count) + ") is not a multiple of 3");
  if (indexed && largest_index(indices) >= vertices.size())
    for (size_t i = 0; i < indices.size(); ++i)
      if (indices[i] >= vertices.size())
        throw Error("draw", "index " + std::to_string(i) + " is " + std::to_string(indices[i]) +
                                " but there are only " + std::to_string(vertices.size()) +
                                " vertices");
  const uint32_t triangle_count = uint32_t(corner_count / 3);
  if (triangle_count == 0) return;

  const Viewport viewport{target.width(), target.height()};
  const GuardBand guard = GuardBand::for_viewport(viewport.width, viewport.height);

  detail::DrawScratch<V> scratch = detail::DrawScratch<V>::take();
  // Grown only (never value-initialized again once there): every element used is written below.
  if (scratch.shared.size() < vertices.size()) scratch.shared.resize(vertices.size());
  ShadedVertex<V>* shared = scratch.shared.data();

  // 1. Vertex shader.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, vertices.size(), 4096),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t i = r.begin(); i < r.end(); ++i)
                        shared[i] =
                            make_shaded_vertex(program.vertex(vertices[i]), viewport, guard);
                    });

  // 2. Assembly, clipping, culling, binning.
  int extent = 0;
  for (Vector2i o : msaa_sample_offsets(target.samples()))
    extent = std::max({extent, std::abs(o.x), std::abs(o.y)});
  const BinSettings bin{.viewport = viewport,
                        .guard = guard,
                        .cull = state.cull,
                        .front_face = state.front_face,
                        .sample_extent = extent};
  const TileGrid grid(viewport);
  std::vector<Chunk<V>>& chunks = scratch.chunks;
  chunks.resize((triangle_count + kChunkTriangles - 1) / kChunkTriangles);
  auto corner = [&](uint32_t t, int k) { return indexed ? indices[3 * t + k] : 3 * t + k; };
  tbb::parallel_for(size_t(0), chunks.size(), [&](size_t c) {
    uint32_t first = uint32_t(c) * kChunkTriangles;
    uint32_t last = std::min(triangle_count, first + kChunkTriangles);
    chunks[c].build(first, last, corner, shared, bin, grid);
  });
  scratch.chunk_tiles.resize(chunks.size());
  for (size_t c = 0; c < chunks.size(); ++c) scratch.chunk_tiles[c] = chunks[c].tiles;

  // 3. Tiles: the depth function is a template argument (see draw()), so the pixel loop has no
  // switch where it matters.
  FragmentSettings settings;
  settings.depth_func = state.depth_func;
  settings.depth_write = state.depth_write;
  settings.blend = state.blend;
  settings.alpha_test = state.alpha_test;
  settings.alpha_cutoff = state.alpha_cutoff;
  settings.front_face = state.front_face;
  settings.object_id = state.object_id;
  settings.wireframe = state.wireframe;
  rasterize(detail::TileJob<P>{program, target, settings, chunks, scratch.chunk_tiles.data(),
                               shared, grid});
  detail::DrawScratch<V>::give_back(std::move(scratch));
}

}  // namespace detail

// Draws triangles: with `indices` empty, vertices 3t, 3t+1, 3t+2 form triangle t; otherwise
// indices 3t..3t+2 do. Throws obscura::Error for an index out of range or a count not a multiple
// of three.
template <Program P>
void draw(RenderTarget& target, const DrawState& state, const P& program,
          std::span<const typename P::Vertex> vertices, std::span<const uint32_t> indices = {}) {
  detail::draw_with(target, state, program, vertices, indices, [&](const detail::TileJob<P>& job) {
    // LESS, what scenes draw with, gets its own loop (and the hierarchical depth test); the
    // other seven share one that reads the function from the settings.
    if (state.depth_func == DepthFunc::kLess)
      detail::rasterize_tiles<P, DepthFunc::kLess>(job);
    else
      detail::rasterize_tiles<P, kDepthFuncFromSettings>(job);
  });
}

// The same for callers that only ever draw with depth function F (state.depth_func must be F):
// the tile loop is compiled for F alone instead of all eight functions.
template <DepthFunc F, Program P>
void draw_with_depth_func(RenderTarget& target, const DrawState& state, const P& program,
                          std::span<const typename P::Vertex> vertices,
                          std::span<const uint32_t> indices = {}) {
  if (state.depth_func != F) throw Error("draw", "the draw state's depth function is not F");
  detail::draw_with(target, state, program, vertices, indices,
                    [](const detail::TileJob<P>& job) { detail::rasterize_tiles<P, F>(job); });
}

// The same for a std::vector or any contiguous range.
template <Program P>
void draw(RenderTarget& target, const DrawState& state, const P& program,
          const std::vector<typename P::Vertex>& vertices,
          const std::vector<uint32_t>& indices = {}) {
  draw(target, state, program, std::span<const typename P::Vertex>(vertices),
       std::span<const uint32_t>(indices));
}

}  // namespace obscura::raster
