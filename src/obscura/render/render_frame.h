// One frame by any renderer, through one call: what the command line and the Python module
// share. The tracer's integrators go through obscura::render (trace/render.h), the rasterizer
// through raster::render (raster/render.h); this picks and sets them up.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "obscura/camera/camera.h"
#include "obscura/film/aov_buffers.h"
#include "obscura/film/film.h"
#include "obscura/film/glare.h"
#include "obscura/film/image.h"
#include "obscura/film/tiles.h"
#include "obscura/film/work_share.h"
#include "obscura/math/sampler.h"
#include "obscura/raster/render.h"
#include "obscura/render/frame_finish.h"
#include "obscura/render/lens_flare.h"
#include "obscura/render/renderer.h"
#include "obscura/scene/scene.h"

namespace obscura {

struct FrameSettings {
  Renderer renderer = Renderer::kPath;
  int samples_per_pixel = 16;  // tracer: samples per pixel (> 0); the most a time limit takes
  uint64_t seed = 0;
  SamplerType sampler = SamplerType::kSobol;
  int max_depth = 0;  // 0: the integrator's default (path 65, whitted 8); direct ignores it
  // Spectral light transport (trace/render.h). Only the path tracer has it: with any other
  // renderer render_frame throws obscura::Error rather than render in RGB.
  bool spectral = false;
  double time_limit_s = 0;                    // 0: none
  const std::atomic<bool>* cancel = nullptr;  // set from another thread to stop early
  WorkShare share = {};                       // MPI/--shard parts; default alone
  // The rasterizer's own settings; its seed, time limit, cancel and share are the ones above.
  raster::RenderSettings raster = {};
  // Finishing (render/frame_finish.h), by the RenderedFrame overload below: diffraction glare
  // (a perspective or lens-system camera) and ghost flares (a lens-system camera).
  std::optional<GlareSettings> glare = std::nullopt;
  std::optional<FlareSettings> flare = std::nullopt;
};

struct FrameStats {
  double seconds = 0;
  double rays = 0;                               // tracer only
  int done = 0, requested = 0;                   // samples per pixel (tracer) or frames (raster)
  bool cancelled = false, time_limited = false;  // partial = cancelled || time_limited
  std::vector<std::string> warnings;
  // The rasterizer's post-process depth of field: what finishing blurs the film with (the film
  // render_frame fills is sharp).
  std::optional<raster::PostDepthOfFieldInputs> post_dof;

  bool partial() const { return cancelled || time_limited; }
};

// Renders `camera` over `scene` into `film` (the camera's crop size) and, if given, `aovs` (same
// size; the rasterizer replaces them by buffers without albedo): the film as the renderer leaves
// it, before finishing. Throws obscura::Error for invalid settings (samples or max depth out of
// range) or sizes.
FrameStats render_frame(const Scene& scene, const Camera& camera, const FrameSettings& settings,
                        Film& film, AovBuffers* aovs = nullptr,
                        const ProgressCallback& progress = {});

// A frame as rendered, with what finishes it: every door (the command line, MPI ranks, shards,
// sequences, Python) renders through this and finishes through finished().
struct RenderedFrame {
  Renderer renderer = Renderer::kPath;
  Image film_sums;  // Film::sums(): Σ w·L and Σ w per pixel
  std::optional<AovBuffers> aovs;
  std::vector<AovImage> layers;  // finishing's per-pixel inputs (render/frame_finish.h)
  FrameFinish finish;
  FrameStats stats;
  FlareStats flare_stats;

  // The finished frame, linear RGB (finish_frame): only on the whole frame, not a part.
  Image finished() const { return finish_frame(film_sums, layers, finish); }
};

// Renders the frame and prepares its finishing: the post-process depth of field's layer, the
// flare's (computed before rendering, so that a camera without a lens system fails first) and the
// glare's optics. With `aovs`, the frame's AOVs. Throws obscura::Error as above, and for glare or
// flare on a camera that has none.
RenderedFrame render_frame(const Scene& scene, const Camera& camera, const FrameSettings& settings,
                           bool aovs, const ProgressCallback& progress = {});

}  // namespace obscura
