// What a frame is, beyond its camera (render/camera_request.h), resolved in one place for every
// door: a setting the caller gives (the command line's option, Python's argument) wins over the
// scene file's render block, which wins over the default. docs/architecture.md, "Settings", has
// the whole table.
#pragma once

#include <cstdint>
#include <optional>

#include "obscura/film/glare.h"
#include "obscura/render/lens_flare.h"
#include "obscura/render/renderer.h"
#include "obscura/reyes/reyes_settings.h"
#include "obscura/scene/scene.h"

namespace obscura {

inline constexpr int kDefaultSamplesPerPixel = 32;

// Each field set only when the caller gave it.
struct FrameRequest {
  std::optional<int> samples_per_pixel = std::nullopt;
  std::optional<uint64_t> seed = std::nullopt;
  std::optional<bool> spectral = std::nullopt;  // the path tracer's spectral transport
  bool glare = false;                           // --glare: the aperture's own strength unless given
  std::optional<double> glare_strength = std::nullopt;  // implies glare
  std::optional<int> glare_radius_px = std::nullopt;
  std::optional<bool> flare = std::nullopt;
  // REYES's knobs (--reyes-*; Python's reyes_* arguments).
  std::optional<double> reyes_shading_rate = std::nullopt;
  std::optional<int> reyes_grid_size = std::nullopt, reyes_bucket_size = std::nullopt,
                     reyes_pixel_samples = std::nullopt, reyes_eye_splits = std::nullopt;
};

struct ResolvedFrameRequest {
  int samples_per_pixel = kDefaultSamplesPerPixel;
  uint64_t seed = 0;
  bool spectral = false;
  std::optional<GlareSettings> glare;
  std::optional<FlareSettings> flare;
  reyes::ReyesSettings reyes;  // its knobs; the rest of it is FrameSettings'
};

// The request over the scene file's render settings over the defaults. The scene's wish for
// spectral transport applies where it can, to the path tracer; a caller's is kept as given (the
// renderer refuses it). Glare and flare are validated where they are used (render_frame).
ResolvedFrameRequest resolve_frame_request(const FrameRequest& request,
                                           const SceneRenderSettings& scene, Renderer renderer);

}  // namespace obscura
