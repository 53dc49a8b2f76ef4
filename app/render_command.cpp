#include "render_command.h"

#include <cstdio>
#include <memory>
#include <optional>

#include <tbb/global_control.h>

#include "camera_options.h"
#include "display_options.h"
#include "display_server.h"
#include "frame_render.h"
#include "glare_options.h"
#include "image_limit_option.h"
#include "obscura/io/atomic_file.h"
#include "obscura/io/default_environment.h"
#include "obscura/io/image_io.h"
#include "obscura/io/scene_loader.h"
#include "obscura/math/error.h"
#include "obscura/raster/render.h"
#include "obscura/render/renderer_backend.h"
#include "obscura/scene/material_variants.h"
#include "option_ranges.h"
#include "partial_render.h"
#include "progress_bar.h"
#include "raster_effects_options.h"
#include "raster_options.h"
#include "render_options.h"
#include "scene_choice_options.h"
#include "sensor_frame.h"
#include "sensor_options.h"
#include "sequence.h"
#include "shard_file.h"
#include "team.h"
#include "tracer_options.h"
#include "usage_error.h"

namespace obscura::app {

namespace {}  // namespace

Scene load_scene(const std::string& name) {
  return obscura::load_scene(name);
}

namespace {

// A key of everything on the command line that changes the pixels (all but the output, the
// thread count and the messages): the parts of a --shard render must share it to be merged.
std::string job_key(const CLI::App& render) {
  std::string settings;
  for (const CLI::Option* option : render.get_options()) {
    const std::string name = option->get_name();
    if (option->count() == 0 || name == "--shard" || name == "-o,--output" || name == "--output" ||
        name == "--threads" || name == "-q,--quiet" || name == "--quiet")
      continue;
    settings += name + "=";
    for (const std::string& value : option->as<std::vector<std::string>>()) settings += value + ";";
    settings += "\n";
  }
  // FNV-1a, 64 bits: a fingerprint to catch parts of different renders, not a secret.
  uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : settings) hash = (hash ^ c) * 1099511628211ull;
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

// `ranks`: "" alone, else " on N ranks, X MB to rank 0".
void print_summary(const RenderOptions& options, const Scene& scene, const RenderedFrame& frame,
                   const std::string& ranks, double rays, double seconds) {
  if (!frame.renderer.capabilities().takes_samples_per_pixel) {
    std::fprintf(stderr, "rendered %s: %dx%d (%s%s) in %s%s\n", scene.name.c_str(), options.width,
                 options.height, frame.renderer.name(), ranks.c_str(),
                 format_seconds(seconds).c_str(), partial_note(frame.progress).c_str());
  } else {
    std::fprintf(stderr, "rendered %s: %dx%d, %lld spp (%s%s) in %s (%.2f Mrays/s)%s\n",
                 scene.name.c_str(), options.width, options.height, frame.progress.done,
                 frame.renderer.name(), ranks.c_str(), format_seconds(seconds).c_str(),
                 seconds > 0 ? rays / seconds * 1e-6 : 0.0,
                 frame.progress.partial()   ? partial_note(frame.progress).c_str()
                 : frame.time_limit_reached ? " [time limit reached]"
                                            : "");
  }
  if (options.stats)
    for (const std::string& line : frame.stats.details) std::fprintf(stderr, "%s\n", line.c_str());
  if (frame.finish.flare) {
    const FlareStats& f = frame.flare_stats;
    std::fprintf(stderr,
                 "flare: %d sources, %d ghosts imaged, %d faint or missing, %.2f Mrays in %s\n",
                 f.sources, f.ghosts_traced, f.ghosts_skipped, f.rays * 1e-6,
                 format_seconds(f.seconds).c_str());
  }
}

void run_render(RenderOptions options, const std::string& job) {
  if (options.list_scenes) {
    if (!team().leads()) return;
    for (const BuiltinScene& b : builtin_scenes())
      std::printf("%-20s %s\n", b.name.c_str(), b.description.c_str());
    return;
  }
  Team& team = app::team();
  if (!options.ground_truth.path.empty() && !options.frames.empty())
    throw UsageError(
        "--ground-truth writes one frame's file; it does not take --frames (render each "
        "frame with its own --ground-truth file)");
  if (!options.display_server.empty()) {
    if (!options.frames.empty() || !options.shard.empty())
      throw UsageError(
          "--display-server shows one whole frame: it does not take --frames or --shard");
    check_display_server_address(options.display_server);
  }
  if ((options.sensor.sensor || options.sensor.metering ||
       (options.camera.exposure_mode && *options.camera.exposure_mode == "auto")) &&
      (!options.frames.empty() || !options.shard.empty()))
    throw UsageError(
        "--raw-sensor, --metering and --exposure-mode auto capture one whole frame: they do not "
        "take --frames or --shard yet (render under mpirun to share the frame)");
  if (!options.frames.empty()) return run_sequence(options, team);
  take_sensor_requests(options);
  validate(options.tracer);  // the renderer, parsed before the checks below use it
  std::optional<ShardSpec> shard;
  if (!options.shard.empty()) {
    shard = parse_shard(options.shard);
    if (!team.alone())
      throw UsageError(
          "--shard splits a frame between separate processes; under mpirun the "
          "ranks share the frame already (leave --shard out)");
    if (!options.ground_truth.path.empty())
      throw UsageError(
          "--ground-truth is not written by --shard parts: render the ground truth in one "
          "process (it costs one ray per pixel), or under mpirun");
    if (image_format_for_path(options.output) != ImageFormat::kExr)
      throw UsageError(
          "--shard writes a partial film, an OpenEXR file: give -o PART.exr (then "
          "`obscura merge` writes the image in any format)");
  }

  std::optional<tbb::global_control> thread_limit;
  if (options.threads > 0)
    thread_limit.emplace(tbb::global_control::max_allowed_parallelism, size_t(options.threads));

  // Every rank loads the scene; only rank 0 (or a lone process) writes.
  Scene scene;
  team.run_phase([&] {
    scene = prepare_scene(options, team.leads());
    resolve_sensor(options, scene);
  });
  const bool speaks = team.leads() && !options.quiet;
  if (speaks)
    for (const std::string& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());

  // Ctrl-C stops either renderer between passes (samples or frames); the image so far is written.
  InterruptGuard interrupt;
  WorkShare share;
  if (shard) {
    share = {.part = shard->part, .parts = shard->parts, .settle = {}};
  } else if (!team.alone()) {
    share = {.part = team.rank(), .parts = team.size(), .settle = [&team](StopVerdict own) {
               return team.settle(own);
             }};
  }
  // The tracer always shows progress; the rasterizer only when it accumulates several frames.
  const bool bar_wanted =
      options.tracer.renderer.capabilities().takes_samples_per_pixel ||
      raster::wants_effects(scene, scene.camera,
                            frame_settings(options, scene.render, share).raster);
  ProgressBar bar("render", !speaks || !bar_wanted);
  RenderedFrame frame =
      render_frame(scene, options, share, [&](int done, int total) { bar.update(done, total); });
  bar.finish();
  const double rays = team.sum(frame.rays), seconds = frame.seconds;
  gather_frame(team, frame);
  std::string ranks;
  if (!team.alone()) {
    char note[96];
    std::snprintf(note, sizeof note, " on %d ranks, %.2f MB to rank 0", team.size(),
                  team.sum(double(team.bytes_sent())) * 1e-6);
    ranks = note;
  }

  if (shard) {
    write_shard(options.output, frame, *shard, job);
    if (!options.quiet)
      std::fprintf(stderr, "rendered part %d of %d of %s%s; `obscura merge` assembles the parts\n",
                   shard->part, shard->parts, scene.name.c_str(),
                   partial_note(frame.progress).c_str());
    std::printf("%s\n", options.output.c_str());
    set_exit_status(exit_status_for(frame.progress.end));
    return;
  }
  if (team.leads()) {
    if (speaks) {
      for (const std::string& w : frame.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
      print_summary(options, scene, frame, ranks, rays, seconds);
      if (!options.sensor.exposure_note.empty())
        std::fprintf(stderr, "auto exposure: metered EV100 %.2f (%s): %s\n",
                     *options.sensor.metered_ev100,
                     std::string(metering_mode_name(*options.sensor.metering_mode)).c_str(),
                     options.sensor.exposure_note.c_str());
    }
    // The frame and its ground truth are a pair: both replaced, or (a full disk) neither. The
    // ground truth comes first: a cancel before it is done leaves it out, and the frame written
    // after it says so (marked interrupted, the ground truth left out).
    OutputTransaction outputs;
    // Rank 0 alone: the ground truth is one ray per pixel, not worth dealing out.
    std::optional<std::string> ground_truth;
    if (!options.ground_truth.path.empty()) {
      ground_truth =
          write_ground_truth_file(options.ground_truth, frame.renderer, options.raster, scene);
      if (!ground_truth) interrupt_leaving_out(frame.progress, "ground truth");
    }
    write_frame(options, options.output, frame);
    outputs.commit();
    if (ground_truth) std::printf("%s\n", ground_truth->c_str());
    // The image is written whatever tev says: a display that cannot be reached is a warning.
    if (!options.display_server.empty()) {
      try {
        const std::vector<AovImage> aovs =
            frame.aovs ? frame.aovs->images() : std::vector<AovImage>{};
        push_to_display_server(options.display_server,
                               display_image(options.output, frame.finished(), aovs));
      } catch (const Error& e) {
        std::fprintf(stderr, "warning: %s\n", e.what());
      }
    }
  } else {
    set_exit_status(exit_status_for(frame.progress.end));
  }
}

}  // namespace

void add_frame_options(CLI::App& command, RenderOptions& o) {
  CLI::App* render = &command;
  RenderOptions* options = &o;
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
  add_reyes_options(*render, options->reyes);
  render->add_flag("--stats", options->stats,
                   "Print the renderer's own counters after the summary (reyes: grids, "
                   "micropolygons and their area, samples tested and hit, eye splits, peak grids)");
  add_glare_options(*render, options->glare);
  render->add_flag("--flare", options->flare,
                   "Ghost flares: the images of bright lights that reflections between a lens "
                   "system's surfaces form (--lens, --lens-coating); added to the HDR frame before "
                   "glare, either renderer");
}

void add_render_command(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* render = app.add_subcommand("render", "Render a scene to an image file");
  render->add_option("scene", options->scene,
                     "A scene file (.json, .gltf, .glb, .obj, .ply, …) or a built-in scene name "
                     "(see --scene-list); default: the Cornell box");
  render
      ->add_option("-o,--output", options->output,
                   "Output image; the format follows the extension: .png, .exr, .pfm, .dng (a "
                   "raw sensor's DNG: see --raw-sensor)")
      ->capture_default_str();
  render->add_flag("--scene-list", options->list_scenes, "List the built-in scenes and exit");
  add_frame_options(*render, *options);
  add_ground_truth_options(*render, options->ground_truth);
  add_sensor_options(*render, options->sensor);
  render->add_option("--shard", options->shard,
                     "Render part I of N of the frame (I counted from 0) to a partial film, an "
                     ".exr file; `obscura merge` assembles the N parts into the image one "
                     "process would have made (for farm managers; see docs/distributed.md)");
  render->add_option("--display-server", options->display_server,
                     "Also send the finished frame and its AOVs to a running tev (HOST:PORT, tev's "
                     "default 127.0.0.1:14158), as pbrt-v4 and Mitsuba do");
  render->add_option("--frames", options->frames,
                     "Render a sequence: frames FIRST:LAST[:STEP] (inclusive), frame n exposed "
                     "around n/fps seconds, to a numbered output (out_%04d.exr; finished frames "
                     "are skipped, so a sequence resumes) or one .y4m video");
  auto* fps = render->add_option("--fps", options->fps, "Frames per second of --frames")
                  ->check(number_in(1e-6, 1e6))
                  ->capture_default_str();
  render->callback([options, render, fps] {
    if (fps->count() > 0 && options->frames.empty())
      throw UsageError("--fps sets the frame rate of a sequence: give --frames FIRST:LAST too");
    options->width_given = render->count("--width") > 0;
    options->height_given = render->count("--height") > 0;
    options->spp_given = render->count("--spp") > 0;
    options->seed_given = render->count("--seed") > 0;
    run_render(*options, job_key(*render));
  });
}

}  // namespace obscura::app
