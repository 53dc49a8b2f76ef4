// REYES's knobs as a scene file, the command line and Python name them: their defaults and
// ranges, kept below both the scene loaders (io/) and the renderer (reyes/reyes_settings.h),
// which read them from here so that a value the file accepts is one the renderer takes.
#pragma once

#include <optional>

namespace obscura::reyes_knobs {

inline constexpr double kDefaultShadingRate = 1;  // pixels² per micropolygon
inline constexpr double kMinShadingRate = 1.0 / 64, kMaxShadingRate = 1024;
inline constexpr int kDefaultGridSize = 256, kMaxGridSize = 65536;  // micropolygons per grid
inline constexpr int kDefaultBucketSize = 16, kMaxBucketSize = 64;  // pixels (a work-share tile)
inline constexpr int kDefaultPixelSamples = 16, kMaxPixelSamples = 4096;
inline constexpr int kDefaultEyeSplits = 8, kMaxEyeSplits = 32;

}  // namespace obscura::reyes_knobs

namespace obscura {

// The knobs a scene file's `render.reyes` block suggests (each set only when the file gives it;
// the caller's options win over them, render/frame_request.h).
struct SceneReyesSettings {
  std::optional<double> shading_rate;
  std::optional<int> grid_size, bucket_size, pixel_samples, eye_splits;
};

}  // namespace obscura
