// The rasterizer's part of `obscura render --renderer raster`: MSAA, shading, culling, wireframe;
// and the render itself (scene → SceneRasterizer → film, plus the id/depth/normal outputs).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "aov_images.h"
#include "obscura/film/film.h"
#include "obscura/film/work_share.h"
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
  double seconds = 0;            // compiling the scene and drawing the frame(s)
  std::vector<NamedImage> aovs;  // with aovs: normal, depth, id
  // --raster-dof post: the view depth the post-process blurs with. It needs the whole frame, so
  // it is applied once the frame is assembled (apply_depth_of_field_post).
  std::optional<Image> post_dof_depth;
  std::vector<std::string> warnings;
  RenderProgress progress;  // frames drawn of those asked for, and how the render ended
};
// Renders one frame of `scene` with its camera into `film` (the crop's size), drawing the tiles
// `share` owns; with `aovs`, also the normal, depth and id images, as the tracer's.
RasterRender render_raster(const Scene& scene, const RasterOptions& options, bool aovs, Film& film,
                           const WorkShare& share = {});
// The target's normal, depth (distance from the eye) and id images.
std::vector<NamedImage> raster_aov_images(const raster::RenderTarget& target, const Camera& camera);

}  // namespace obscura::app
