#include "raster_options.h"

#include <chrono>

#include "obscura/raster/accumulation.h"
#include "obscura/raster/lens_warp.h"
#include "option_ranges.h"
#include "raster_effects_options.h"
#include "usage_error.h"

namespace obscura::app {

void add_raster_options(CLI::App& render, RasterOptions& o) {
  o.registered = {
      render.add_option("--msaa", o.msaa, "raster: multisample anti-aliasing, 1, 4 or 8 samples")
          ->check(integer_in(1, 8)),
      render.add_option("--shading", o.shading,
                        "raster: flat, gouraud, phong (per pixel; default) or blinn-phong "
                        "(per pixel, half-vector lobe for Phong materials)"),
      render.add_flag("--cull", o.cull, "raster: cull back faces"),
      render.add_flag("--wireframe", o.wireframe, "raster: draw triangle edges over the image"),
      render
          .add_option("--shadow-map", o.shadow_map_size,
                      "raster: shadow map size (texels per side) for directional and spot "
                      "lights; 0: no shadows (default 1024)")
          ->check(integer_in(0, 16384))};
}

void reject_unless_raster(const std::vector<CLI::Option*>& registered,
                          const std::string& renderer) {
  if (renderer == "raster") return;
  for (const CLI::Option* option : registered)
    if (option && option->count() > 0)
      throw UsageError(option->get_name() +
                       " applies to --renderer raster only (the renderer is '" + renderer + "')");
}

void validate(const RasterOptions& o, const std::string& renderer) {
  reject_unless_raster(o.registered, renderer);
  if (renderer != "raster") return;
  if (o.msaa != 1 && o.msaa != 4 && o.msaa != 8)
    throw UsageError("--msaa must be 1, 4 or 8 samples; got " + std::to_string(o.msaa));
  if (o.shadow_map_size < 0 || o.shadow_map_size > 16384)
    throw UsageError("--shadow-map must be 0 (no shadows) to 16384 texels; got " +
                     std::to_string(o.shadow_map_size));
  if (o.shading != "flat" && o.shading != "gouraud" && o.shading != "phong" &&
      o.shading != "blinn-phong")
    throw UsageError("--shading must be flat, gouraud, phong or blinn-phong; got '" + o.shading +
                     "'");
}

raster::RasterSettings raster_settings(const RasterOptions& o, bool aovs) {
  raster::RasterSettings s;
  s.msaa_samples = o.msaa;
  s.shading = o.shading == "flat"          ? raster::ShadingMode::kFlat
              : o.shading == "gouraud"     ? raster::ShadingMode::kGouraud
              : o.shading == "blinn-phong" ? raster::ShadingMode::kBlinnPhong
                                           : raster::ShadingMode::kPhong;
  s.cull_back_faces = o.cull;
  s.wireframe.enabled = o.wireframe;
  s.aovs = aovs;
  s.shadow_map_size = o.shadow_map_size;
  return s;
}

namespace {

// A camera without a projection matrix (calibrated lens, fisheye, panorama): pinhole views
// resampled along its rays (raster/lens_warp.h), at mid-shutter.
RasterRender render_through_lens(const Scene& scene, const raster::SceneRasterizer& rasterizer,
                                 Film& film, const WorkShare& share,
                                 std::chrono::steady_clock::time_point start) {
  raster::LensWarpSettings settings{.part = share.part, .parts = share.parts};
  raster::LensRender lens = raster::render_through_lens(rasterizer, scene.camera, settings, film);
  RasterRender result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.warnings = rasterizer.warnings();
  result.warnings.insert(result.warnings.end(), lens.warnings.begin(), lens.warnings.end());
  if (raster::has_motion_blur(scene.camera, scene_moves(scene)))
    result.warnings.push_back("the rasterizer draws a " +
                              std::string(projection_name(scene.camera.projection)) +
                              " camera at mid-shutter, without motion blur (the tracer blurs it)");
  result.progress = {.end = RenderEnd::kComplete, .done = 1, .requested = 1, .unit = "frames"};
  if (lens.normal)
    result.aovs = {{"normal", std::move(*lens.normal)},
                   {"depth", std::move(*lens.distance)},
                   {"id", std::move(*lens.id)}};
  return result;
}

}  // namespace

RasterRender render_raster(const Scene& scene, const RasterOptions& options, bool aovs, Film& film,
                           const WorkShare& share) {
  auto start = std::chrono::steady_clock::now();
  raster::SceneRasterizer rasterizer(scene, raster_settings(options, aovs));
  if (!scene.camera.has_projection_matrix())
    return render_through_lens(scene, rasterizer, film, share, start);
  raster::RenderTarget target = rasterizer.make_target(scene.camera);
  target.set_share(share.part, share.parts);
  rasterizer.render(scene.camera, film, &target);
  RasterRender result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.warnings = rasterizer.warnings();
  result.progress = {.end = RenderEnd::kComplete, .done = 1, .requested = 1, .unit = "frames"};
  if (aovs) result.aovs = raster_aov_images(target, scene.camera);
  return result;
}

std::vector<NamedImage> raster_aov_images(const raster::RenderTarget& target,
                                          const Camera& camera) {
  return {{"normal", raster::normal_image(target)},
          {"depth", raster::distance_image(target, camera)},
          {"id", raster::id_image(target)}};
}

}  // namespace obscura::app
