// What one frame is asked for (FrameSettings) and what rendering it did (FrameStats): the
// language between the doors (command line, Python, sequences, shards) and the renderers' back
// ends (render/renderer_backend.h).
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "obscura/film/glare.h"
#include "obscura/film/work_share.h"
#include "obscura/math/sampler.h"
#include "obscura/raster/render_settings.h"
#include "obscura/render/lens_flare.h"
#include "obscura/render/renderer.h"
#include "obscura/reyes/reyes_settings.h"

namespace obscura {

struct FrameSettings {
  Renderer renderer = {};  // a row of the table (render/renderer.h); the path tracer by default
  // Samples per pixel (> 0; the most a time limit takes), for renderers whose capabilities say
  // they take them (render/renderer_backend.h); the rasterizer accumulates raster.effect_samples.
  int samples_per_pixel = 16;
  uint64_t seed = 0;
  SamplerType sampler = SamplerType::kSobol;
  int max_depth = 0;  // 0: the integrator's default (path 65, whitted 8); direct ignores it
  // Spectral light transport (trace/render.h), for renderers whose capabilities say so: any
  // other throws obscura::Error rather than render in RGB.
  bool spectral = false;
  double time_limit_s = 0;                    // 0: none
  const std::atomic<bool>* cancel = nullptr;  // set from another thread to stop early
  WorkShare share = {};                       // MPI/--shard parts; default alone
  // The rasterizer's own settings; its seed, time limit, cancel and share are the ones above.
  raster::RenderSettings raster = {};
  // REYES's own settings (shading rate, grid and bucket size, pixel samples, eye splits); its
  // seed, sampler, time limit, cancel and share are the ones above.
  reyes::ReyesSettings reyes = {};
  // Finishing (render/frame_finish.h), prepared by RenderSession::render's RenderedFrame:
  // diffraction glare (a perspective or lens-system camera) and ghost flares (a lens system).
  std::optional<GlareSettings> glare = std::nullopt;
  std::optional<FlareSettings> flare = std::nullopt;
};

struct FrameStats {
  double seconds = 0;
  double rays = 0;              // rays traced, where a renderer counts them
  int done = 0, requested = 0;  // in the renderer's progress unit (RendererCapabilities)
  bool cancelled = false, time_limited = false;  // partial = cancelled || time_limited
  std::vector<std::string> warnings;
  // A renderer's own counters, one "name: value" a line (REYES: grids, micropolygons, …), for
  // the command line's --stats.
  std::vector<std::string> details;
  // Post-process depth of field (the rasterizer's --raster-dof post): what finishing blurs the
  // film with; the film the renderer fills is sharp.
  std::optional<raster::PostDepthOfFieldInputs> post_dof;

  bool partial() const { return cancelled || time_limited; }
};

}  // namespace obscura
