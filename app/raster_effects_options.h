// The rasterizer's camera effects on `obscura render --renderer raster`: depth of field by
// accumulation or as a z-buffer post-process, and motion blur by accumulation whenever the
// shutter is open and something moves (see docs/raster-effects.md).
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "obscura/film/film.h"
#include "obscura/film/tiles.h"
#include "obscura/scene/scene.h"
#include "raster_options.h"

namespace obscura::app {

struct RasterEffectsOptions {
  std::string dof = "accumulate";        // off | accumulate | post
  int samples = 32;                      // frames accumulated for depth of field / motion blur
  std::vector<CLI::Option*> registered;  // to tell whether any was given
};

void add_raster_effects_options(CLI::App& render, RasterEffectsOptions& options);
// Throws UsageError for a bad value, or for these options given to another renderer.
void validate(const RasterEffectsOptions& options, const std::string& renderer);

// Whether the render needs more than one sharp frame at mid-shutter: the camera has depth of
// field (and --raster-dof is not off), or the shutter is open while the camera or an instance
// moves.
// Whether an instance moves or a mesh deforms over the shutter.
bool scene_moves(const Scene& scene);
bool wants_raster_effects(const RasterEffectsOptions& options, const Scene& scene);

// Renders `scene` into `film` (the crop's size) with the effects: `samples` frames through
// jittered lens points and shutter times (one when nothing needs them), drawing the tiles `share`
// owns. With `aovs`, the id/depth/normal images of the frame nearest mid-shutter, as
// render_raster gives them; with --raster-dof post, the view depth for the post-process.
RasterRender render_raster_effects(const Scene& scene, const RasterOptions& raster,
                                   const RasterEffectsOptions& effects, bool aovs, uint64_t seed,
                                   Film& film, const ProgressCallback& progress = {},
                                   const std::atomic<bool>* cancel = nullptr,
                                   double time_limit_s = 0, const WorkShare& share = {});

// The depth-of-field post-process on a whole frame: `film` blurred by the camera's lens with the
// view depth of RasterRender::post_dof_depth.
void apply_depth_of_field_post(Film& film, const Image& view_depth, const Camera& camera);

}  // namespace obscura::app
