// The rasterizer's part of `obscura render --renderer raster`: MSAA, shading, culling, wireframe;
// and the render itself (scene → SceneRasterizer → film, plus the id/depth/normal outputs).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "obscura/film/film.h"
#include "obscura/raster/scene_rasterizer.h"
#include "obscura/scene/scene.h"
#include "partial_render.h"

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
void validate(const RasterOptions& options, const std::string& renderer);
// A usage error naming the first of `registered` given on the command line, unless the renderer
// is the rasterizer.
void reject_unless_raster(const std::vector<CLI::Option*>& registered, const std::string& renderer);
raster::RasterSettings raster_settings(const RasterOptions& options, bool aovs);

struct RasterRender {
  double seconds = 0;  // compiling the scene and drawing the frame
  std::vector<std::string> aov_paths;
  std::vector<std::string> warnings;
  RenderProgress progress;  // frames drawn of those asked for, and how the render ended
};
// Renders one frame of `scene` with its camera into `film` (the crop's size); with `aovs`,
// writes <output>.depth.exr, .normal.exr and .id.exr beside `output`, as the tracer does.
RasterRender render_raster(const Scene& scene, const RasterOptions& options, bool aovs, Film& film,
                           const std::string& output);
// Writes the target's normal, depth and id images beside `output`; returns their paths.
std::vector<std::string> write_raster_aovs(const raster::RenderTarget& target, const Camera& camera,
                                           const std::string& output,
                                           const ImageMetadata& metadata = {});

}  // namespace obscura::app
