// The rasterizer's part of `obscura render --renderer raster`: MSAA, shading, culling, wireframe,
// shadows. The render itself is the library's (raster/render.h).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "obscura/raster/render_settings.h"
#include "obscura/render/renderer.h"

namespace obscura::app {

struct RasterOptions {
  int msaa = 1;                          // 1, 4 or 8 samples per pixel
  std::string shading = "phong";         // flat | gouraud | phong | blinn-phong
  bool cull = false;                     // back-face culling
  bool wireframe = false;                // triangle edges over the shaded image
  int shadow_map_size = 1024;            // texels per side; 0: no shadows
  std::vector<CLI::Option*> registered;  // to tell whether any was given
};

void add_raster_options(CLI::App& render, RasterOptions& options);
// Throws UsageError for a bad value, or for raster options given to another renderer.
void validate(const RasterOptions& options, Renderer renderer);
// A usage error naming the first of `registered` given on the command line, unless the renderer
// is the rasterizer.
void reject_unless_raster(const std::vector<CLI::Option*>& registered, Renderer renderer);
// The options' part of the rasterizer's settings (msaa, shading, culling, wireframe, shadows).
void apply_raster_options(const RasterOptions& options, raster::RenderSettings& settings);

}  // namespace obscura::app
