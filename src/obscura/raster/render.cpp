#include "obscura/raster/render.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "obscura/camera/lens_system_fit.h"
#include "obscura/math/error.h"
#include "obscura/raster/accumulation.h"
#include "obscura/raster/depth_of_field_post.h"
#include "obscura/raster/lens_warp.h"
#include "obscura/raster/rasterizer_cache.h"
#include "obscura/raster/rolling_shutter.h"
#include "obscura/raster/vignetting_gain.h"

namespace obscura::raster {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Fills `aovs` (replaced by buffers without albedo) from the rasterizer's normal, depth, range
// and id images.
void fill_aovs(AovBuffers& aovs, const Image& normal, const Image& depth, const Image& range,
               const Image& id) {
  aovs = AovBuffers(normal.width, normal.height, false);
  for (int y = 0; y < normal.height; ++y)
    for (int x = 0; x < normal.width; ++x)
      aovs.set_pixel({x, y}, Rgb(), {normal.at(x, y, 0), normal.at(x, y, 1), normal.at(x, y, 2)},
                     depth.at(x, y, 0), range.at(x, y, 0), int32_t(id.at(x, y, 0)));
}

void fill_aovs(AovBuffers& aovs, const RenderTarget& target, const Camera& camera) {
  fill_aovs(aovs, normal_image(target), depth_image(target), range_image(target, camera),
            id_image(target));
}

// Draws one frame of `camera` (a global shutter) into `film` and returns its AOV images (normal,
// depth, range, id) when the rasterizer keeps them: through the camera's matrices, or — for a
// camera without a projection matrix (calibrated lens, fisheye, panorama) — through pinhole views
// resampled along its rays (lens_warp.h).
std::vector<Image> draw_frame(const SceneRasterizer& rasterizer, const Camera& camera, Film& film,
                              const WorkShare& share, std::vector<std::string>& warnings) {
  if (!camera.has_projection_matrix()) {
    LensWarpSettings settings{.part = share.part, .parts = share.parts};
    LensRender lens = render_through_lens(rasterizer, camera, settings, film);
    for (const std::string& w : lens.warnings)
      if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(w);
    if (!lens.normal) return {};
    return {std::move(*lens.normal), std::move(*lens.depth), std::move(*lens.range),
            std::move(*lens.id)};
  }
  RenderTarget target = rasterizer.make_target(camera);
  target.set_share(share.part, share.parts);
  rasterizer.render(camera, film, &target);
  if (!rasterizer.settings().aovs) return {};
  return {normal_image(target), depth_image(target), range_image(target, camera), id_image(target)};
}

// The scene prepared with `settings`: from `prepared` where given, else for this frame alone.
std::shared_ptr<const SceneRasterizer> prepare(const Scene& scene, const RasterSettings& settings,
                                               RasterizerCache* prepared) {
  return prepared ? prepared->get(settings)
                  : std::make_shared<const SceneRasterizer>(scene, settings);
}

// One sharp frame at mid-shutter (or band by band for a rolling shutter).
RenderStats render_sharp(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                         Film& film, AovBuffers* aovs, RasterizerCache* prepared) {
  const std::shared_ptr<const SceneRasterizer> kept =
      prepare(scene, rasterizer_settings(settings, aovs != nullptr), prepared);
  const SceneRasterizer& rasterizer = *kept;
  RenderStats stats;
  stats.warnings = rasterizer.warnings();
  auto draw = [&](const Camera& c, Film& f) {
    return draw_frame(rasterizer, c, f, settings.share, stats.warnings);
  };
  const bool rolling = camera.shutter.line_time_s > 0;
  std::vector<Image> images =
      rolling ? draw_rolling_shutter(camera, rolling_band_count(camera), draw, film)
              : draw(camera, film);
  if (rolling)
    stats.warnings.push_back(
        "rolling shutter: the rasterizer draws " + std::to_string(rolling_band_count(camera)) +
        " bands of lines, each at its middle line's time (the tracer times every line)");
  if ((rolling || !camera.has_projection_matrix()) && has_motion_blur(camera, scene_moves(scene)))
    stats.warnings.push_back(
        "the rasterizer draws this " + std::string(projection_name(camera.projection)) + " camera" +
        (rolling ? " with a rolling shutter" : "") + " without motion blur (the tracer blurs it)");
  stats.frames = stats.frames_requested = 1;
  if (aovs && images.size() == 4) fill_aovs(*aovs, images[0], images[1], images[2], images[3]);
  return stats;
}

// Accumulated frames through jittered lens points and shutter times (one when only the
// post-process asks for effects), and the post-process's view depth.
RenderStats render_effects(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                           Film& film, AovBuffers* aovs, const ProgressCallback& progress,
                           RasterizerCache* prepared) {
  const bool dof = camera.lens.depth_of_field;
  const bool post = settings.depth_of_field == DepthOfFieldMethod::kPost && dof;
  const bool lens_blur = settings.depth_of_field == DepthOfFieldMethod::kAccumulate && dof;
  // Post-process or no depth of field: one frame, unless something moves (then motion blur).
  const bool many = lens_blur || has_motion_blur(camera, scene_moves(scene));
  const bool keep_aovs = aovs != nullptr || post;

  const std::shared_ptr<const SceneRasterizer> kept =
      prepare(scene, rasterizer_settings(settings, keep_aovs), prepared);
  const SceneRasterizer& rasterizer = *kept;
  AccumulationSettings accumulation{.samples = many ? settings.effect_samples : 1,
                                    .seed = settings.seed,
                                    .msaa_samples = settings.msaa_samples,
                                    .aovs = keep_aovs,
                                    .depth_of_field = lens_blur,
                                    .cancel = settings.cancel,
                                    .time_limit_s = settings.time_limit_s,
                                    .share = settings.share};
  RenderTarget middle = rasterizer.make_target(camera);
  AccumulationStats accumulated = accumulate(
      camera, accumulation,
      [&](const FrameParameters& frame, RenderTarget& target) {
        rasterizer.render_frame(
            camera, {frame.sample.time_s, frame.lens.view, frame.lens.projection}, target);
      },
      film, progress, &middle);

  RenderStats stats;
  stats.warnings = rasterizer.warnings();
  stats.frames = accumulated.frames;
  stats.frames_requested = accumulation.samples;
  stats.cancelled = accumulated.cancelled;
  stats.time_limited = accumulated.time_limited;
  if (aovs) fill_aovs(*aovs, middle, camera);
  // The post-process blurs the accumulated (motion-blurred) colour with the depth of the frame
  // nearest mid-shutter; it needs the whole frame.
  if (post) {
    Image view_depth = middle.view_depth_image();
    Image coc = circle_of_confusion_image(view_depth, camera);
    stats.post_dof = {std::move(view_depth), std::move(coc), camera.film.pixel_aspect};
  }
  return stats;
}

// What the rasterizer leaves out of a lens-system camera it draws through its fitted camera.
std::string fitted_lens_note(const Camera& camera, const FittedLensCamera& fitted) {
  const auto& lens = *std::get<LensSystemProjection>(camera.projection).lens;
  char numbers[160];
  std::snprintf(numbers, sizeof numbers,
                "distortion within %.2g px, %.2g px·m of parallax off the focus plane",
                fitted.fit.max_error_px, fitted.fit.parallax_px_m);
  return "lens system '" + lens.name() + "': the rasterizer draws it through a fitted " +
         lens_model_name(fitted.fit.projection.lens) + " camera (" + numbers +
         ") with its measured vignetting; it has no depth of field, chromatic aberration, "
         "aberration blur or ghosts (the tracer traces the lens)";
}

// A lens-system camera's fitted camera; nothing for other cameras, and nothing with `note` saying
// why for a lens no model fits (it is then drawn along its own traced rays, unvignetted).
std::optional<FittedLensCamera> fit_lens_system_camera(const Camera& camera, std::string& note) {
  if (!std::holds_alternative<LensSystemProjection>(camera.projection)) return std::nullopt;
  try {
    return fitted_lens_camera(camera, {.check_illumination = false});
  } catch (const Error& e) {
    note = std::string("no fitted camera (") + e.what() +
           "): the rasterizer draws the lens system along its traced rays, unvignetted";
    return std::nullopt;
  }
}

}  // namespace

std::optional<DepthOfFieldMethod> parse_depth_of_field_method(std::string_view name) {
  if (name == "off") return DepthOfFieldMethod::kOff;
  if (name == "accumulate") return DepthOfFieldMethod::kAccumulate;
  if (name == "post") return DepthOfFieldMethod::kPost;
  return std::nullopt;
}

RasterSettings rasterizer_settings(const RenderSettings& s, bool aovs) {
  RasterSettings r;
  r.msaa_samples = s.msaa_samples;
  r.shading = s.shading;
  r.cull_back_faces = s.cull_back_faces;
  r.wireframe.enabled = s.wireframe;
  r.aovs = aovs;
  r.shadow_map_size = s.shadow_map_size;
  return r;
}

bool scene_moves(const Scene& scene) {
  for (const Instance& instance : scene.instances)
    if (instance.animated() || scene.meshes[instance.mesh].deforms()) return true;
  return false;
}

bool wants_effects(const Scene& scene, const Camera& camera, const RenderSettings& settings) {
  if (!camera.has_projection_matrix() || camera.shutter.line_time_s > 0) return false;
  const bool lens =
      camera.lens.depth_of_field && settings.depth_of_field != DepthOfFieldMethod::kOff;
  return lens || has_motion_blur(camera, scene_moves(scene));
}

RenderStats render(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                   Film& film, AovBuffers* aovs, const ProgressCallback& progress,
                   RasterizerCache* prepared) {
  const auto start = Clock::now();
  const Bounds2i crop = camera.film.crop_pixels();
  if (film.width() != crop.width() || film.height() != crop.height())
    throw Error("raster::render",
                "the film must have the camera's crop size (" + std::to_string(crop.width()) + "x" +
                    std::to_string(crop.height()) + "); got " + std::to_string(film.width()) + "x" +
                    std::to_string(film.height()));
  if (settings.effect_samples < 1)
    throw Error("raster::render", "effect_samples must be a positive number of frames; got " +
                                      std::to_string(settings.effect_samples));
  // A lens system is drawn through its fitted calibrated camera (camera/lens_system_fit.h), at
  // its centre of projection, then darkened by its measured relative illumination.
  std::string unfitted;
  std::optional<FittedLensCamera> fitted = fit_lens_system_camera(camera, unfitted);
  const Camera& drawn = fitted ? fitted->camera : camera;
  const bool effects = wants_effects(scene, drawn, settings);
  RenderStats stats = effects
                          ? render_effects(scene, drawn, settings, film, aovs, progress, prepared)
                          : render_sharp(scene, drawn, settings, film, aovs, prepared);
  // Accumulated depth of field keeps or drops each lens point's frame per pixel at the barrel
  // (accumulate()): the cat-eye bokeh, and the barrel's light loss with it.
  const bool barrel_in_frames = effects && drawn.lens.depth_of_field &&
                                settings.depth_of_field == DepthOfFieldMethod::kAccumulate;
  apply_vignetting(film, drawn, barrel_in_frames);
  if (fitted) {
    apply_relative_illumination(film, *fitted);
    stats.warnings.push_back(fitted_lens_note(camera, *fitted));
  }
  if (!unfitted.empty()) stats.warnings.push_back(unfitted);
  stats.seconds = seconds_since(start);
  return stats;
}

}  // namespace obscura::raster
