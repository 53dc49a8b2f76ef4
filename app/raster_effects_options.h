// The options of the rasterizer's camera effects on `obscura render --renderer raster`: depth of
// field by accumulation or as a z-buffer post-process, and the frames accumulated for it and for
// motion blur (see docs/raster-effects.md; the composition is raster/render.h's).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "obscura/raster/render_settings.h"
#include "obscura/render/renderer.h"

namespace obscura::app {

struct RasterEffectsOptions {
  std::string dof = "accumulate";        // off | accumulate | post
  int samples = 32;                      // frames accumulated for depth of field / motion blur
  std::vector<CLI::Option*> registered;  // to tell whether any was given
};

void add_raster_effects_options(CLI::App& render, RasterEffectsOptions& options);
// Throws UsageError for a bad value, or for these options given to another renderer.
void validate(const RasterEffectsOptions& options, Renderer renderer);

// The options' part of the rasterizer's settings (the depth-of-field method, frames accumulated).
void apply_raster_effects_options(const RasterEffectsOptions& options,
                                  raster::RenderSettings& settings);

}  // namespace obscura::app
