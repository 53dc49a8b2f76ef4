// What a REYES frame is asked for (ReyesSettings) and what rendering it counted (ReyesStats).
//
// The knobs are RenderMan's: the shading rate is the area, in pixels, of the micropolygons that
// surfaces are diced into (so 1 shades about once per pixel, 4 once per 2×2 pixels), the grid
// size the most micropolygons one diced grid holds (what is shaded together), the bucket size
// the side of the square pieces of the image the hider samples one at a time, the pixel samples
// the number of jittered visibility samples per pixel (each with its own time and lens point),
// and the eye-split limit how often a surface that crosses the camera's near plane is split
// before what still crosses it is dropped.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "obscura/film/work_share.h"
#include "obscura/math/sampler.h"
#include "obscura/scene/reyes_knobs.h"

namespace obscura::reyes {

// The side of the square tiles a WorkShare deals for REYES (render/reyes_backend.cpp's
// capabilities row): buckets are cut from them, so a bucket is never larger.
inline constexpr int kTileSize = reyes_knobs::kMaxBucketSize;

struct ReyesSettings {
  // Defaults and ranges: scene/reyes_knobs.h.
  double shading_rate = reyes_knobs::kDefaultShadingRate;  // pixels² per micropolygon
  int grid_size = reyes_knobs::kDefaultGridSize;           // micropolygons per grid at most
  int bucket_size = reyes_knobs::kDefaultBucketSize;       // pixels, at most kTileSize
  int pixel_samples = reyes_knobs::kDefaultPixelSamples;   // visibility samples per pixel
  int eye_splits = reyes_knobs::kDefaultEyeSplits;
  uint64_t seed = 0;
  SamplerType sampler = SamplerType::kSobol;
  double time_limit_s = 0;                    // ≥ 0; 0: none (REYES renders in one pass)
  const std::atomic<bool>* cancel = nullptr;  // stops between buckets
  WorkShare share = {};
};

inline constexpr double kMinShadingRate = reyes_knobs::kMinShadingRate;
inline constexpr double kMaxShadingRate = reyes_knobs::kMaxShadingRate;

// Throws obscura::Error naming the first option out of range (its command-line name) and its
// value: NaN, 0, 1e-9 and 1e9 are refused, not rendered for hours or skipped.
void validate(const ReyesSettings& settings);

struct ReyesStats {
  double seconds = 0;
  bool cancelled = false, time_limited = false;
  uint64_t pieces = 0;           // triangles and eye-split pieces diced
  uint64_t grids = 0;            // grids diced and shaded
  uint64_t micropolygons = 0;    // in those grids (degenerate ones included)
  uint64_t shaded_vertices = 0;  // grid vertices shaded (once each per grid)
  double area_min_px = 0, area_mean_px = 0, area_max_px = 0;  // non-degenerate micropolygons
                                                              // at the shading time, pinhole
  uint64_t samples_tested = 0;                                // sample-in-micropolygon tests
  uint64_t samples_hit = 0;            // of which inside (and within the near/far range)
  uint64_t eye_splits = 0;             // splits of pieces crossing the near plane
  uint64_t eye_split_culled = 0;       // pieces dropped at the limit
  uint64_t occlusion_culled = 0;       // bucket visits of grids behind every sample's opaque hit
  uint64_t displacement_overruns = 0;  // vertices displaced beyond their material's bound
  uint64_t peak_grids = 0;             // grids alive at once
  uint64_t peak_grid_bytes = 0;        // their bytes at that moment
  std::vector<std::string> warnings;

  // The counters as lines "name: value" for --stats.
  std::vector<std::string> lines() const;
};

}  // namespace obscura::reyes
