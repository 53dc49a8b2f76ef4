#include "render_command.h"

#include <cstdio>
#include <memory>
#include <optional>

#include <tbb/global_control.h>

#include "camera_options.h"
#include "display_options.h"
#include "image_limit_option.h"
#include "obscura/io/default_environment.h"
#include "obscura/io/image_io.h"
#include "obscura/io/scene_loader.h"
#include "obscura/math/error.h"
#include "obscura/scene/material_variants.h"
#include "obscura/trace/render.h"
#include "option_ranges.h"
#include "partial_render.h"
#include "progress_bar.h"
#include "raster_effects_options.h"
#include "raster_options.h"
#include "scene_choice_options.h"
#include "tracer_options.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

struct RenderOptions {
  std::string scene;
  std::string output = "render.png";
  int width = 512, height = 512;
  int spp = 32;
  int threads = 0;
  uint64_t seed = 0;
  bool quiet = false;
  bool list_scenes = false;
  std::string environment = "auto";
  double environment_intensity = 1;
  std::string gltf_variant;  // KHR_materials_variants: a variant's name; empty = the defaults
  CameraOverrides camera;
  SceneChoiceOptions choice;
  DisplayOptions display;
  TracerOptions tracer;
  RasterOptions raster;
  RasterEffectsOptions raster_effects;
  // Which options were given on the command line: those override the scene file's settings.
  bool width_given = false, height_given = false, spp_given = false, seed_given = false;
};

// The scene file's suggested settings, where the command line did not give them.
void apply_scene_settings(const SceneRenderSettings& s, RenderOptions& o) {
  if (s.width && !o.width_given) o.width = *s.width;
  if (s.height && !o.height_given) o.height = *s.height;
  if (s.samples_per_pixel && !o.spp_given) o.spp = *s.samples_per_pixel;
  if (s.seed && !o.seed_given) o.seed = *s.seed;
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

Scene load_scene(const std::string& name) {
  return obscura::load_scene(name);
}

namespace {

// Writes the image (marked partial when it is) and sets the exit status that says how it ended.
void finish_render(const RenderOptions& options, const Film& film, const RenderProgress& progress) {
  ImageWriteOptions write_options = image_write_options(options.display);
  write_options.metadata = partial_metadata(progress);
  report_write(options.output, write_image(options.output, film.to_image(), write_options),
               options.quiet);
  warn_if_unmarked(options.output, progress, options.quiet);
  set_exit_status(exit_status_for(progress.end));
}

void run_render(RenderOptions options) {
  if (options.list_scenes) {
    for (const BuiltinScene& b : builtin_scenes())
      std::printf("%-20s %s\n", b.name.c_str(), b.description.c_str());
    return;
  }
  validate(options);
  validate(options.tracer);
  validate(options.raster, options.tracer.renderer);
  validate(options.raster_effects, options.tracer.renderer);
  check_output_path(options.output);  // fail before rendering, not after

  std::optional<tbb::global_control> thread_limit;
  if (options.threads > 0)
    thread_limit.emplace(tbb::global_control::max_allowed_parallelism, size_t(options.threads));

  // Skins and morph targets are posed when the file is read, at the shutter's middle.
  const Shutter shutter = shutter_option(options.camera);
  Scene scene = obscura::load_scene(options.scene, gltf_load_options(options.choice, shutter));
  if (!options.gltf_variant.empty()) select_material_variant(scene, options.gltf_variant);
  EnvironmentChoice environment = parse_environment_choice(options.environment);
  environment.intensity = float(options.environment_intensity);
  apply_environment(scene, environment);
  // Before rendering: no output may replace the scene file, a model, buffer or texture.
  check_not_an_input(options.output, scene.input_files);
  if (options.tracer.aovs)
    for (const std::string& aov : aov_paths(options.output, options.tracer.renderer))
      check_not_an_input(aov, scene.input_files);
  apply_scene_settings(scene.render, options);
  check_image_size(options.width, options.height, options.width_given || options.height_given);
  if (!options.quiet)
    for (const std::string& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  scene.camera = resolve_camera(scene, options.camera, options.width, options.height);
  scene.camera.shutter = shutter_at_time(options.choice, scene.camera.shutter);
  scene.validate();

  Bounds2i crop = scene.camera.film.crop_pixels();
  Film film(crop.width(), crop.height());
  // Ctrl-C stops either renderer between passes (samples or frames); the image so far is written.
  InterruptGuard interrupt;
  if (options.tracer.renderer == "raster") {
    const bool effects = wants_raster_effects(options.raster_effects, scene);
    ProgressBar bar("render", options.quiet || !effects);
    RasterRender r =
        effects
            ? render_raster_effects(
                  scene, options.raster, options.raster_effects, options.tracer.aovs, options.seed,
                  film, options.output, [&](int done, int total) { bar.update(done, total); },
                  &InterruptGuard::requested(), options.tracer.time_limit_s)
            : render_raster(scene, options.raster, options.tracer.aovs, film, options.output);
    bar.finish();
    finish_render(options, film, r.progress);
    if (!options.quiet) {
      for (const std::string& w : r.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
      std::fprintf(stderr, "rendered %s: %dx%d (raster) in %s%s\n", scene.name.c_str(),
                   options.width, options.height, format_seconds(r.seconds).c_str(),
                   partial_note(r.progress).c_str());
    }
    std::printf("%s\n", options.output.c_str());
    for (const std::string& path : r.aov_paths) std::printf("%s\n", path.c_str());
    return;
  }
  auto device = std::make_shared<EmbreeDevice>();
  TraceScene trace_scene(scene, device);
  const int requested_spp = samples_per_pixel(options.tracer, options.spp);
  RenderSettings settings{.samples_per_pixel = requested_spp,
                          .seed = options.seed,
                          .sampler = sampler_type(options.tracer),
                          .time_limit_s = options.tracer.time_limit_s,
                          .cancel = &InterruptGuard::requested()};
  std::optional<AovBuffers> aovs;
  if (options.tracer.aovs) aovs.emplace(crop.width(), crop.height());
  ProgressBar bar("render", options.quiet);
  RenderStats stats = render(
      trace_scene, scene.camera, *make_integrator(options.tracer), settings, film,
      [&](int done, int total) { bar.update(done, total); }, aovs ? &*aovs : nullptr);
  bar.finish();

  // Without --spp, a time limit asks for as many samples as fit: reaching it completes the render.
  const bool open_ended = requested_spp != options.spp;
  RenderProgress progress{.end = stats.cancelled                ? RenderEnd::kInterrupted
                                 : stats.partial && !open_ended ? RenderEnd::kTimeLimit
                                                                : RenderEnd::kComplete,
                          .done = stats.samples_per_pixel,
                          .requested = requested_spp,
                          .unit = "samples per pixel"};
  finish_render(options, film, progress);
  if (!options.quiet)
    std::fprintf(stderr, "rendered %s: %dx%d, %d spp (%s) in %s (%.2f Mrays/s)%s\n",
                 scene.name.c_str(), options.width, options.height, stats.samples_per_pixel,
                 options.tracer.renderer.c_str(), format_seconds(stats.seconds).c_str(),
                 stats.seconds > 0 ? stats.rays.total() / stats.seconds * 1e-6 : 0.0,
                 progress.partial()            ? partial_note(progress).c_str()
                 : open_ended && stats.partial ? " [time limit reached]"
                                               : "");
  std::printf("%s\n", options.output.c_str());
  if (aovs)
    for (const std::string& path : write_aovs(options.output, *aovs, partial_metadata(progress)))
      std::printf("%s\n", path.c_str());
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* render = app.add_subcommand("render", "Render a scene to an image file");
  render->add_option("scene", options->scene,
                     "A scene file (.json, .gltf, .glb, .obj, .ply, …) or a built-in scene name "
                     "(see --scene-list); default: the Cornell box");
  render
      ->add_option("-o,--output", options->output,
                   "Output image; the format follows the extension: .png, .exr, .pfm")
      ->capture_default_str();
  render->add_option("--width", options->width, "Image width in pixels")
      ->check(integer_in(1, kMaxImageSidePx))
      ->capture_default_str();
  render->add_option("--height", options->height, "Image height in pixels")
      ->check(integer_in(1, kMaxImageSidePx))
      ->capture_default_str();
  options->tracer.spp_option = render->add_option("--spp", options->spp, "Samples per pixel")
                                   ->check(integer_in(1, kMaxSamplesPerPixel))
                                   ->capture_default_str();
  render->add_option("--threads", options->threads, "Worker threads (0 = all cores)")
      ->check(integer_in(0, kMaxThreads))
      ->capture_default_str();
  render->add_option("--seed", options->seed, "Random seed: same seed, same image")
      ->check(unsigned_64())
      ->capture_default_str();
  render->add_flag("-q,--quiet", options->quiet, "No progress or summary on stderr");
  render->add_flag("--scene-list", options->list_scenes, "List the built-in scenes and exit");
  render
      ->add_option("--environment", options->environment,
                   "Light from far away: auto (the studio environment when the scene has no "
                   "light of its own), none, studio, white (uniform radiance 1) or an "
                   "equirectangular map file")
      ->capture_default_str();
  render
      ->add_option("--environment-intensity", options->environment_intensity,
                   "Scale of the environment --environment chooses")
      ->check(number_in(0, 1e6))
      ->capture_default_str();
  render->add_option("--gltf-variant", options->gltf_variant,
                     "Render a glTF file's material variant (KHR_materials_variants) by name; "
                     "`obscura info` lists them");
  add_camera_options(*render, options->camera);
  add_scene_choice_options(*render, options->choice);
  add_display_options(render, options->display);
  add_max_image_pixels_option(render);
  add_tracer_options(*render, options->tracer);
  add_raster_options(*render, options->raster);
  add_raster_effects_options(*render, options->raster_effects);
  render->callback([options, render] {
    options->width_given = render->count("--width") > 0;
    options->height_given = render->count("--height") > 0;
    options->spp_given = render->count("--spp") > 0;
    options->seed_given = render->count("--seed") > 0;
    run_render(*options);
  });
}

}  // namespace obscura::app
