#include "raster_options.h"

#include <algorithm>
#include <chrono>

#include "obscura/raster/accumulation.h"
#include "obscura/raster/lens_warp.h"
#include "obscura/raster/rolling_shutter.h"
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

// Draws one frame of `camera` (a global shutter) into `film` and returns its AOV images (normal,
// depth, id) when asked: through the camera's matrices, or — for a camera without a projection
// matrix (calibrated lens, fisheye, panorama) — through pinhole views resampled along its rays
// (raster/lens_warp.h).
std::vector<Image> draw_frame(const raster::SceneRasterizer& rasterizer, const Camera& camera,
                              Film& film, const WorkShare& share,
                              std::vector<std::string>& warnings) {
  const bool aovs = rasterizer.settings().aovs;
  if (!camera.has_projection_matrix()) {
    raster::LensWarpSettings settings{.part = share.part, .parts = share.parts};
    raster::LensRender lens = raster::render_through_lens(rasterizer, camera, settings, film);
    for (const std::string& w : lens.warnings)
      if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(w);
    if (!lens.normal) return {};
    return {std::move(*lens.normal), std::move(*lens.distance), std::move(*lens.id)};
  }
  raster::RenderTarget target = rasterizer.make_target(camera);
  target.set_share(share.part, share.parts);
  rasterizer.render(camera, film, &target);
  if (!aovs) return {};
  return {raster::normal_image(target), raster::distance_image(target, camera),
          raster::id_image(target)};
}

}  // namespace

RasterRender render_raster(const Scene& scene, const RasterOptions& options, bool aovs, Film& film,
                           const WorkShare& share) {
  auto start = std::chrono::steady_clock::now();
  raster::SceneRasterizer rasterizer(scene, raster_settings(options, aovs));
  const Camera& camera = scene.camera;
  RasterRender result;
  result.warnings = rasterizer.warnings();
  auto draw = [&](const Camera& c, Film& f) {
    return draw_frame(rasterizer, c, f, share, result.warnings);
  };
  const bool rolling = camera.shutter.line_time_s > 0;
  std::vector<Image> images =
      rolling ? raster::draw_rolling_shutter(camera, raster::rolling_band_count(camera), draw, film)
              : draw(camera, film);
  if (rolling)
    result.warnings.push_back(
        "rolling shutter: the rasterizer draws " +
        std::to_string(raster::rolling_band_count(camera)) +
        " bands of lines, each at its middle line's time (the tracer times every line)");
  // Effects (motion blur, depth of field by accumulation) come through render_raster_effects;
  // a camera drawn through lens views or band by band is drawn here, sharp.
  if ((rolling || !camera.has_projection_matrix()) &&
      raster::has_motion_blur(camera, scene_moves(scene)))
    result.warnings.push_back(
        "the rasterizer draws this " + std::string(projection_name(camera.projection)) + " camera" +
        (rolling ? " with a rolling shutter" : "") + " without motion blur (the tracer blurs it)");
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.progress = {.end = RenderEnd::kComplete, .done = 1, .requested = 1, .unit = "frames"};
  if (aovs && images.size() == 3)
    result.aovs = {{"normal", std::move(images[0])},
                   {"depth", std::move(images[1])},
                   {"id", std::move(images[2])}};
  return result;
}

std::vector<NamedImage> raster_aov_images(const raster::RenderTarget& target,
                                          const Camera& camera) {
  return {{"normal", raster::normal_image(target)},
          {"depth", raster::distance_image(target, camera)},
          {"id", raster::id_image(target)}};
}

}  // namespace obscura::app
