// A diced and shaded grid: (nu + 1) × (nv + 1) vertices, row-major, each shaded once at the
// frame's shading time with the shared reflection formulas, the nu × nv micropolygons between
// them sampled by the hider (hider.h) at every time and lens point its samples carry.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/math/vector.h"
#include "obscura/reyes/dicing.h"
#include "obscura/reyes/frame_view.h"

namespace obscura::reyes {

class ReyesScene;

// Grid::triangle of a grid diced from an analytic surface (Mesh::analytic_sphere), not a triangle.
inline constexpr uint32_t kAnalyticSurface = 0xffffffffu;

enum class Coverage : uint8_t {
  kOpaque,  // every sample it covers is hit
  kMask,    // hit where the interpolated α reaches the cut-off (glTF MASK)
  kBlend,   // composited by α in the sample's visible-point list (glTF BLEND)
};

struct Grid {
  uint64_t key = 0;  // its block's index: the order grids are sampled in
  int nu = 0, nv = 0;
  std::vector<Point3d> open, close;  // camera space; `close` empty when nothing moves
  std::vector<Point2d> raster;       // pinhole raster positions (a still, sharp frame only)
  std::vector<Rgb> color;            // reflected + emitted radiance, unexposed
  std::vector<float> alpha;          // coverage α (kMask, kBlend), else empty
  std::vector<Vector3f> normal;      // world shading normal facing the viewer (the AOV)
  Coverage coverage = Coverage::kOpaque;
  float alpha_cutoff = 0.5f;
  uint32_t mesh = 0;  // the id AOV: the instance index, as the other renderers write it
  uint32_t instance = 0, triangle = 0;  // the scene triangle it was diced from, or
                                        // kAnalyticSurface

  int row() const { return nu + 1; }
  size_t vertices() const { return size_t(nu + 1) * size_t(nv + 1); }
  size_t bytes() const;
};

// What dicing and shading a grid adds to the frame's statistics.
struct GridCounts {
  uint64_t grids = 0, micropolygons = 0, shaded_vertices = 0, measured = 0;
  uint64_t displacement_overruns = 0;  // vertices displaced beyond their material's bound
  double area_min = 1e300, area_max = 0, area_sum = 0;
  void add(const GridCounts& o);
};

// Dices `block` of `plan` and shades its vertices at the shading time.
Grid dice_and_shade(const ReyesScene& scene, const FrameView& view, const DicePlan& plan,
                    const Block& block, uint64_t key, GridCounts& counts);

}  // namespace obscura::reyes
