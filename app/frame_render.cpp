#include "frame_render.h"

#include <cstdio>
#include <memory>

#include "image_limit_option.h"
#include "obscura/film/aov_buffers.h"
#include "obscura/film/film.h"
#include "obscura/io/aov_files.h"
#include "obscura/io/default_environment.h"
#include "obscura/io/image_io.h"
#include "obscura/io/scene_loader.h"
#include "obscura/math/error.h"
#include "obscura/raster/ground_truth_render.h"
#include "obscura/render/camera_glare.h"
#include "obscura/render/frame_request.h"
#include "obscura/render/lens_flare.h"
#include "obscura/render/render_session.h"
#include "obscura/render/renderer_backend.h"
#include "obscura/scene/material_variants.h"
#include "option_ranges.h"
#include "sensor_frame.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

// The scene file's suggested settings, where the command line did not give them.
// What the command line asked of the frame beyond the camera: the options given.
FrameRequest frame_request(const RenderOptions& o) {
  FrameRequest r;
  if (o.spp_given) r.samples_per_pixel = o.spp;
  if (o.seed_given) r.seed = o.seed;
  if (o.tracer.spectral_option && o.tracer.spectral_option->count() > 0)
    r.spectral = o.tracer.spectral;
  r.glare = o.glare.on;
  r.glare_strength = o.glare.strength;
  r.glare_radius_px = o.glare.radius_px;
  if (o.flare) r.flare = true;
  request_reyes_options(o.reyes, r);
  return r;
}

// The scene file's settings where the command line did not give them (render/frame_request.h;
// the film's size is resolve_camera's).
void apply_scene_settings(const SceneRenderSettings& s, RenderOptions& o) {
  const ResolvedFrameRequest r = resolve_frame_request(frame_request(o), s, o.tracer.renderer);
  o.spp = r.samples_per_pixel;
  o.seed = r.seed;
  o.tracer.spectral = r.spectral;
}

void validate(const RenderOptions& o) {
  if (o.width <= 0)
    throw UsageError("--width must be a positive number of pixels; got " + std::to_string(o.width));
  if (o.height <= 0)
    throw UsageError("--height must be a positive number of pixels; got " +
                     std::to_string(o.height));
  if (o.spp <= 0)
    throw UsageError("--spp must be a positive number of samples per pixel; got " +
                     std::to_string(o.spp));
  // The sides were range-checked as they were parsed; their product is checked here.
  if (o.width_given && o.height_given) check_image_size(o.width, o.height, true);
  if (o.threads < 0)
    throw UsageError("--threads must be 0 (all cores) or positive; got " +
                     std::to_string(o.threads));
  if (o.environment.empty())
    throw UsageError("--environment: expected auto, none, studio, white or a file");
  if (!(o.environment_intensity >= 0 && o.environment_intensity <= 1e6))
    throw UsageError("--environment-intensity must be in [0, 1e6]; got " +
                     std::to_string(o.environment_intensity));
}

}  // namespace

bool flare_requested(const RenderOptions& options, const SceneRenderSettings& scene) {
  return resolve_frame_request(frame_request(options), scene, options.tracer.renderer)
      .flare.has_value();
}

namespace {

// Before rendering: the output can be written and replaces no input (the scene file, a model,
// buffer or texture).
void check_outputs(const RenderOptions& options, const Scene& scene) {
  check_output_path(options.output, "--output");
  check_not_an_input(options.output, scene.input_files);
  if (options.tracer.aovs)
    for (const std::string& aov :
         aov_paths(options.output, options.tracer.renderer.capabilities().albedo))
      check_not_an_input(aov, scene.input_files);
}

}  // namespace

void resolve_render_options(RenderOptions& options) {
  validate(options);
  validate(options.tracer);
  validate(options.raster, options.tracer.renderer);
  validate(options.raster_effects, options.tracer.renderer);
  validate(options.reyes, options.tracer.renderer);
}

Scene load_render_scene(RenderOptions& options, bool writes_output) {
  resolve_render_options(options);
  if (writes_output)
    check_output_path(options.output, "--output");  // fail before loading, not after

  // Skins and morph targets are posed at the shutter's middle (io/scene_loader.h).
  const Shutter shutter = requested_shutter(options.camera);
  Scene scene = obscura::load_scene(options.scene, gltf_load_options(options.choice, shutter));
  if (!options.gltf_variant.empty()) select_material_variant(scene, options.gltf_variant);
  EnvironmentChoice environment = parse_environment_choice(options.environment);
  environment.intensity = float(options.environment_intensity);
  apply_environment(scene, environment);
  if (writes_output) check_outputs(options, scene);
  apply_scene_settings(scene.render, options);
  return scene;
}

Camera resolve_render_camera(const Scene& scene, RenderOptions& options, bool writes_output,
                             std::vector<std::string>* notes) {
  if (writes_output) check_outputs(options, scene);
  apply_scene_settings(scene.render, options);
  CameraRequest camera_request = options.camera;
  camera_request.time_s = options.choice.time_s;
  Camera camera = resolve_camera(
      scene, camera_request, options.width_given ? std::optional(options.width) : std::nullopt,
      options.height_given ? std::optional(options.height) : std::nullopt, notes);
  options.width = camera.film.width_px;
  options.height = camera.film.height_px;
  check_image_size(options.width, options.height, options.width_given || options.height_given);
  if (flare_requested(options, scene.render) &&
      !std::holds_alternative<LensSystemProjection>(camera.projection)) {
    const std::string message =
        "ghost flares need a lens-system camera (--lens, --lens-file or a lens_system camera in "
        "the scene), whose surfaces reflect";
    if (options.flare) throw UsageError("--flare: " + message);
    throw obscura::Error("render.flare", message);
  }
  if (auto glare =
          resolve_frame_request(frame_request(options), scene.render, options.tracer.renderer)
              .glare) {
    validate(*glare);  // a camera without a sensor fails here, before rendering
    diffraction_optics(camera);
  }
  if (!options.ground_truth.path.empty() || options.ground_truth.flow_times) {
    ground_truth_times(options.ground_truth, camera);  // a bad value fails here, early
    if (writes_output) check_ground_truth_output(options.ground_truth, options.output, scene);
    if (!options.ground_truth.path.empty())  // before rendering, not after
      options.tracer.renderer.backend().check_ground_truth_camera(camera);
  }
  return camera;
}

Scene prepare_scene(RenderOptions& options, bool writes_output) {
  Scene scene = load_render_scene(options, writes_output);
  Camera camera = resolve_render_camera(scene, options, writes_output, &scene.warnings);
  scene.camera = std::move(camera);
  scene.validate();
  return scene;
}

TileDeal tile_deal(Renderer renderer, int width, int height, int parts) {
  return {.width = width,
          .height = height,
          .tile_size = renderer.capabilities().tile_size,
          .parts = parts};
}

FrameSettings frame_settings(const RenderOptions& options, const SceneRenderSettings& scene,
                             const WorkShare& share) {
  FrameSettings settings{.renderer = options.tracer.renderer,
                         .samples_per_pixel = samples_per_pixel(options.tracer, options.spp),
                         .seed = options.seed,
                         .sampler = sampler_type(options.tracer),
                         .max_depth = max_depth(options.tracer),
                         .spectral = options.tracer.spectral,
                         .time_limit_s = options.tracer.time_limit_s,
                         .cancel = &InterruptGuard::requested(),
                         .share = share,
                         .raster = {},
                         .glare = std::nullopt,
                         .flare = std::nullopt};
  apply_raster_options(options.raster, settings.raster);
  apply_raster_effects_options(options.raster_effects, settings.raster);
  const ResolvedFrameRequest finishing =
      resolve_frame_request(frame_request(options), scene, options.tracer.renderer);
  settings.glare = finishing.glare;
  settings.flare = finishing.flare;
  settings.reyes = finishing.reyes;
  return settings;
}

RenderedFrame render_frame(RenderSession& session, const Camera& camera,
                           const RenderOptions& options, const WorkShare& share,
                           const ProgressCallback& progress) {
  const FrameSettings settings = frame_settings(options, session.scene().render, share);
  RenderedFrame frame;
  static_cast<obscura::RenderedFrame&>(frame) =
      session.render(camera, settings, options.tracer.aovs, progress);
  const FrameStats& stats = frame.stats;
  // Without --spp, a time limit asks the tracer for as many samples as fit: reaching it
  // completes the render.
  const RendererCapabilities& renderer = settings.renderer.capabilities();
  const bool open_ended =
      renderer.takes_samples_per_pixel && settings.samples_per_pixel != options.spp;
  frame.progress = {.end = stats.cancelled                     ? RenderEnd::kInterrupted
                           : stats.time_limited && !open_ended ? RenderEnd::kTimeLimit
                                                               : RenderEnd::kComplete,
                    .done = stats.done,
                    .requested = stats.requested,
                    .unit = renderer.progress_unit,
                    .left_out = {}};
  if (frame.flare_stats.cancelled) interrupt_leaving_out(frame.progress, "flare of some lights");
  frame.time_limit_reached = open_ended && stats.time_limited;
  frame.warnings = stats.warnings;
  frame.seconds = stats.seconds;
  frame.rays = stats.rays;
  return frame;
}

RenderedFrame render_frame(const Scene& scene, const RenderOptions& options, const WorkShare& share,
                           const ProgressCallback& progress) {
  RenderSession session(scene);
  return render_frame(session, scene.camera, options, share, progress);
}

void gather_frame(Team& team, RenderedFrame& frame) {
  if (team.alone()) return;
  const TileDeal deal =
      tile_deal(frame.renderer, frame.film_sums.width, frame.film_sums.height, team.size());
  team.gather(deal, frame.film_sums);
  if (frame.aovs) {
    std::vector<AovImage> images = frame.aovs->images();
    for (AovImage& aov : images) team.gather(deal, aov.image);
    frame.aovs = AovBuffers::from_images(images);
  }
  for (AovImage& layer : frame.layers) team.gather(deal, layer.image);
}

RenderEnd write_frame(const RenderOptions& options, const std::string& output,
                      const RenderedFrame& frame) {
  // A cancel during the finishing leaves the glare out: the frame is written without it, marked
  // interrupted.
  bool unfinished = false;
  const Image finished = frame.finished(&InterruptGuard::requested(), &unfinished);
  RenderProgress progress = frame.progress;
  if (unfinished) interrupt_leaving_out(progress, "glare");
  ImageWriteOptions write_options = image_write_options(options.display);
  write_options.metadata = partial_metadata(progress);
  SensorOptions sensor = options.sensor;
  if (sensor.metering_mode) {
    meter_finished(sensor, finished, options.sensor.exposure_scale);
    if (!options.quiet && sensor.exposure_note.empty())
      std::fprintf(stderr, "metered EV100 %.2f (%s)\n", *sensor.metered_ev100,
                   std::string(metering_mode_name(*sensor.metering_mode)).c_str());
  }
  add_metering_metadata(sensor, write_options.metadata);
  if (sensor.spec) {
    for (const std::string& path : write_sensor_frame(options, output, finished, write_options))
      std::printf("%s\n", path.c_str());
  } else {
    report_write(output, write_image(output, finished, write_options), options.quiet);
    warn_if_unmarked(output, progress, options.quiet);
    std::printf("%s\n", output.c_str());
  }
  if (frame.aovs)
    for (const std::string& path : write_aovs(output, *frame.aovs, partial_metadata(progress)))
      std::printf("%s\n", path.c_str());
  // A cancel that came while the (complete) frame was written still ends the command as
  // interrupted.
  const RenderEnd end = InterruptGuard::requested() ? RenderEnd::kInterrupted : progress.end;
  set_exit_status(exit_status_for(end));
  return end;
}

}  // namespace obscura::app
