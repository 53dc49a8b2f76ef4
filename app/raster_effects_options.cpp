#include "raster_effects_options.h"

#include <chrono>

#include "obscura/raster/accumulation.h"
#include "obscura/raster/depth_of_field_post.h"
#include "obscura/raster/scene_rasterizer.h"
#include "option_ranges.h"
#include "usage_error.h"

namespace obscura::app {

namespace {}  // namespace

bool scene_moves(const Scene& scene) {
  for (const Instance& instance : scene.instances)
    if (instance.animated() || scene.meshes[instance.mesh].deforms()) return true;
  return false;
}

void add_raster_effects_options(CLI::App& render, RasterEffectsOptions& o) {
  o.registered = {
      render.add_option("--raster-dof", o.dof,
                        "raster: depth of field by 'accumulate' (renders through jittered lens "
                        "points; default), 'post' (one render blurred by the z-buffer's circle "
                        "of confusion) or 'off'"),
      render
          .add_option("--raster-samples", o.samples,
                      "raster: frames accumulated for depth of field and motion blur "
                      "(default 32)")
          ->check(integer_in(1, kMaxRasterSamples))};
}

void validate(const RasterEffectsOptions& o, const std::string& renderer) {
  reject_unless_raster(o.registered, renderer);
  if (renderer != "raster") return;
  if (o.dof != "off" && o.dof != "accumulate" && o.dof != "post")
    throw UsageError("--raster-dof must be off, accumulate or post; got '" + o.dof + "'");
  if (o.samples < 1)
    throw UsageError("--raster-samples must be a positive number of frames; got " +
                     std::to_string(o.samples));
}

bool wants_raster_effects(const RasterEffectsOptions& o, const Scene& scene) {
  // Cameras without a projection matrix (drawn through lens views) and rolling shutters (drawn
  // band by band) are drawn sharp by render_raster, which says so when something moves.
  if (!scene.camera.has_projection_matrix() || scene.camera.shutter.line_time_s > 0) return false;
  bool lens = scene.camera.lens.depth_of_field && o.dof != "off";
  return lens || raster::has_motion_blur(scene.camera, scene_moves(scene));
}

RasterRender render_raster_effects(const Scene& scene, const RasterOptions& raster,
                                   const RasterEffectsOptions& effects, bool aovs, uint64_t seed,
                                   Film& film, const ProgressCallback& progress,
                                   const std::atomic<bool>* cancel, double time_limit_s,
                                   const WorkShare& share) {
  auto start = std::chrono::steady_clock::now();
  const Camera& camera = scene.camera;
  const bool post = effects.dof == "post" && camera.lens.depth_of_field;
  const bool lens_blur = effects.dof == "accumulate" && camera.lens.depth_of_field;
  // --raster-dof post/off render one frame unless something moves (then it is motion blur).
  const bool many = lens_blur || raster::has_motion_blur(camera, scene_moves(scene));

  raster::SceneRasterizer rasterizer(scene, raster_settings(raster, aovs || post));
  raster::AccumulationSettings settings{.samples = many ? effects.samples : 1,
                                        .seed = seed,
                                        .msaa_samples = raster.msaa,
                                        .aovs = aovs || post,
                                        .depth_of_field = lens_blur,
                                        .cancel = cancel,
                                        .time_limit_s = time_limit_s,
                                        .share = share};
  raster::RenderTarget middle = rasterizer.make_target(camera);
  raster::AccumulationStats stats = raster::accumulate(
      camera, settings,
      [&](const raster::FrameParameters& frame, raster::RenderTarget& target) {
        rasterizer.render_frame(
            camera, {frame.sample.time_s, frame.lens.view, frame.lens.projection}, target);
      },
      film, progress, &middle);

  RasterRender result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.warnings = rasterizer.warnings();
  result.progress = {.end = stats.cancelled      ? RenderEnd::kInterrupted
                            : stats.time_limited ? RenderEnd::kTimeLimit
                                                 : RenderEnd::kComplete,
                     .done = stats.frames,
                     .requested = settings.samples,
                     .unit = "frames"};
  if (aovs) result.aovs = raster_aov_images(middle, camera);
  // The post-process works on the accumulated (motion-blurred) colour with the depth of the
  // frame nearest mid-shutter, once the frame is whole.
  if (post) result.post_dof_depth = middle.view_depth_image();
  return result;
}

void apply_depth_of_field_post(Film& film, const Image& view_depth, const Camera& camera) {
  Image blurred = raster::depth_of_field_post(film.to_image(), view_depth, camera);
  film = Film(film.width(), film.height());
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) film.add_sample({x, y}, blurred.rgb(x, y));
}

}  // namespace obscura::app
