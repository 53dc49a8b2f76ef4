// The render target: the buffers the pipeline writes, per sample, and their resolve.
//
// Colour is linear, scene-referred RGB (floats, no clamping) so the same colour pipeline applies
// as for the tracer. Depth is window depth (ndc_z·0.5 + 0.5). With `aovs` on, each sample also
// keeps the object and primitive id of the visible fragment, its view depth (clip w, the distance
// along the view axis for a perspective projection) and a shading normal.
// Storage is sample-major inside each pixel: element (x, y, s) is at (y·stride + x)·samples + s,
// where the row stride is the width rounded up to a multiple of kRowAlignment pixels, so that the
// pixel loop can always work on whole aligned blocks of a row. Colour is planar in groups of
// kRowAlignment elements (eight reds, eight greens, eight blues), so that the pixel loop stores
// one vector per channel.
#pragma once

#include <cstdint>
#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/film/film.h"
#include "obscura/film/image.h"
#include "obscura/math/vector.h"

namespace obscura::raster {

inline constexpr uint32_t kNoObject = 0;  // object id of the background
inline constexpr int kRowAlignment = 8;   // pixels
// The pipeline bins triangles into square tiles of the target, rasterized in parallel.
inline constexpr int kTileSizeLog2 = 6;
inline constexpr int kTileSize = 1 << kTileSizeLog2;  // 64 × 64 pixels

class RenderTarget {
 public:
  // Preconditions: width, height > 0; samples ∈ {1, 4, 8} (throws obscura::Error otherwise).
  RenderTarget(int width, int height, int samples = 1, bool aovs = false);

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  int stride() const { return stride_; }
  bool has_aovs() const { return aovs_; }

  // When several processes draw one frame together (film/work_share.h): draws rasterize only the
  // tiles of the pipeline's grid (kTileSize pixels, numbered row by row) that `part` of `parts`
  // owns, and leave the others as clear() made them. Every pixel drawn is bit-identical to the
  // same pixel drawn alone. Default: part 0 of 1, every tile.
  // clear() still covers every pixel; the scene's background and accumulate_into() only the
  // drawn tiles'.
  void set_share(int part, int parts);
  bool draws_tile(int tile) const { return tile % share_parts_ == share_part_; }
  bool draws_pixel(int x, int y) const {
    const int columns = (width_ + kTileSize - 1) >> kTileSizeLog2;
    return draws_tile((y >> kTileSizeLog2) * columns + (x >> kTileSizeLog2));
  }

  // Sets every sample's colour and depth; ids to kNoObject, view depth to +∞, normals to zero.
  void clear(Rgb color = {}, float depth = 1.f);

  size_t sample_index(int x, int y, int s = 0) const {
    return (size_t(y) * stride_ + x) * samples_ + s;
  }
  Rgb color_at(int x, int y, int s = 0) const { return color(sample_index(x, y, s)); }
  float depth_at(int x, int y, int s = 0) const { return depth_[sample_index(x, y, s)]; }
  // Need aovs.
  uint32_t object_id_at(int x, int y, int s = 0) const { return object_id_[sample_index(x, y, s)]; }
  uint32_t primitive_id_at(int x, int y, int s = 0) const {
    return primitive_id_[sample_index(x, y, s)];
  }
  float view_depth_at(int x, int y, int s = 0) const { return view_depth_[sample_index(x, y, s)]; }

  // Colour of element `i` (a sample_index).
  Rgb color(size_t i) const {
    const float* g = color_group(i);
    const size_t lane = i % kRowAlignment;
    return {g[lane], g[kRowAlignment + lane], g[2 * kRowAlignment + lane]};
  }
  void set_color(size_t i, Rgb c) {
    float* g = color_group(i);
    const size_t lane = i % kRowAlignment;
    g[lane] = c.r, g[kRowAlignment + lane] = c.g, g[2 * kRowAlignment + lane] = c.b;
  }
  // The group of kRowAlignment elements holding element `i`: its reds, then greens, then blues.
  float* color_group(size_t i) { return color_.data() + i / kRowAlignment * 3 * kRowAlignment; }
  const float* color_group(size_t i) const {
    return color_.data() + i / kRowAlignment * 3 * kRowAlignment;
  }
  float* depth() { return depth_.data(); }
  uint32_t* object_ids() { return object_id_.data(); }
  uint32_t* primitive_ids() { return primitive_id_.data(); }
  float* view_depth() { return view_depth_.data(); }
  Vector3f* normals() { return normal_.data(); }
  const float* depth() const { return depth_.data(); }
  const uint32_t* object_ids() const { return object_id_.data(); }
  const uint32_t* primitive_ids() const { return primitive_id_.data(); }
  const Vector3f* normals() const { return normal_.data(); }

  // The colour with samples averaged (a box filter over the pixel): width × height RGB.
  Image resolve_color() const;
  // Adds the resolved colour to `film` as one sample per pixel of weight `weight`, so several
  // renders (jittered lens, shutter times) accumulate into their average.
  void accumulate_into(Film& film, float weight = 1.f) const;
  // The same with each pixel's colour times gain[y · width + x] (a frame's per-pixel share of
  // light, e.g. whether the lens barrel lets this lens point's ray reach the pixel).
  void accumulate_into(Film& film, const std::vector<float>& gain) const;
  // Per-pixel outputs of sample 0 (one channel; normals three): window depth, view depth,
  // normals. View depth and normals need aovs.
  Image depth_image() const;
  Image view_depth_image() const;
  Image normal_image() const;

 private:
  // accumulate_into's work: each pixel's resolved colour, times gain[pixel] when there is one.
  void accumulate(Film& film, float weight, const float* gain) const;

  int width_, height_, samples_, stride_;
  bool aovs_;
  int share_part_ = 0, share_parts_ = 1;
  std::vector<float> color_;  // planar groups, see above
  std::vector<float> depth_;
  std::vector<uint32_t> object_id_, primitive_id_;
  std::vector<float> view_depth_;
  std::vector<Vector3f> normal_;
};

}  // namespace obscura::raster
