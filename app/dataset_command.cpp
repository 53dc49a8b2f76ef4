#include "dataset_command.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>

#include <tbb/global_control.h>

#include "frame_render.h"
#include "obscura/io/scene_loader.h"
#include "obscura/math/error.h"
#include "obscura/math/request_error.h"
#include "obscura/render/dataset.h"
#include "obscura/render/render_session.h"
#include "obscura/render/renderer_backend.h"
#include "partial_render.h"
#include "render_command.h"
#include "render_options.h"
#include "team.h"
#include "tracer_options.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

struct DatasetOptions {
  std::string views;
  bool ground_truth = false;
  std::string image_format = "png";
  std::string formats = "colmap,nerf,opencv";
};

std::vector<std::string> format_list(const std::string& text) {
  std::vector<std::string> out;
  if (text == "none") return out;
  std::stringstream in(text);
  for (std::string name; std::getline(in, name, ',');) {
    if (name != "colmap" && name != "nerf" && name != "opencv")
      throw UsageError(
          "--formats expects colmap, nerf and opencv, comma-separated, or none; got '" + text +
          "'");
    out.push_back(name);
  }
  return out;
}

void run_dataset(RenderOptions options, const DatasetOptions& d) {
  Team& team = app::team();
  if (d.views.empty())
    throw UsageError("--views is required (orbit:N, sphere:N, path:N:FILE, cameras)");
  if (options.tracer.time_limit_s > 0)
    throw UsageError(
        "--time-limit: a dataset's views are rendered whole, each with --spp samples (a view "
        "stopped early would not be written)");
  std::optional<tbb::global_control> thread_limit;
  if (options.threads > 0)
    thread_limit.emplace(tbb::global_control::max_allowed_parallelism, size_t(options.threads));
  const bool speaks = team.leads() && !options.quiet;

  // Every rank loads the scene, resolves the views and checks the plan; rank 0 writes the
  // model files, every rank the views it takes.
  Scene scene;
  DatasetPlan plan;
  std::vector<std::string> notes, warnings;
  team.run_phase([&] {
    scene = load_render_scene(options, false);
    const Camera base = resolve_render_camera(scene, options, false, &notes);
    plan.directory = options.output;
    plan.views =
        dataset_views(scene, options.camera, d.views, options.width, options.height, &notes);
    plan.settings = frame_settings(options, scene.render, WorkShare{});
    plan.outputs.image_format = d.image_format;
    plan.outputs.image = image_write_options(options.display);
    plan.outputs.ground_truth = d.ground_truth;
    plan.outputs.aovs = options.tracer.aovs;
    plan.outputs.formats = format_list(d.formats);
    if (d.ground_truth)
      for (const DatasetView& view : plan.views)
        options.tracer.renderer.backend().check_ground_truth_camera(view.camera);
    warnings = check_dataset_plan(plan);
    (void)base;
  });
  if (speaks) {
    for (const std::string& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    for (const std::string& w : notes) std::fprintf(stderr, "warning: %s\n", w.c_str());
  }
  // What the calibration files leave out is said even with --quiet: the files are incomplete.
  if (team.leads())
    for (const std::string& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());

  InterruptGuard interrupt;
  RenderSession session(scene);
  team.open_counter();
  DatasetReport report = render_dataset(
      session, plan, [&] { return team.take_ticket(); },
      [&](size_t view, bool rendered) {
        if (rendered && !options.quiet)
          std::fprintf(stderr, "%s%s rendered\n", rank_prefix().c_str(),
                       plan.views[view].name.c_str());
      },
      team.leads());
  team.close_counter();
  const StopVerdict verdict =
      team.settle(report.stopped ? StopVerdict::kCancelled : StopVerdict::kGoOn);
  const double rendered = team.sum(report.rendered), skipped = team.sum(report.skipped);
  if (speaks) {
    for (const std::string& w : report.warnings)
      if (std::find(warnings.begin(), warnings.end(), w) == warnings.end())
        std::fprintf(stderr, "warning: %s\n", w.c_str());
    std::fprintf(stderr,
                 "dataset: %zu views, %.0f rendered, %.0f already there%s; the scene "
                 "compiled %d time(s)%s\n",
                 plan.views.size(), rendered, skipped,
                 team.alone() ? "" : (" on " + std::to_string(team.size()) + " ranks").c_str(),
                 session.compilations(),
                 verdict == StopVerdict::kCancelled ? " [interrupted]" : "");
  }
  if (team.leads()) std::printf("%s\n", plan.directory.c_str());
  set_exit_status(exit_status_for(verdict == StopVerdict::kCancelled ? RenderEnd::kInterrupted
                                                                     : RenderEnd::kComplete));
}

}  // namespace

void add_dataset_command(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  auto d = std::make_shared<DatasetOptions>();
  CLI::App* command = app.add_subcommand(
      "dataset",
      "Render a calibrated dataset: every view with its image (and ground truth, AOVs), one "
      "COLMAP model, one transforms.json, an OpenCV file per view");
  command->add_option("scene", options->scene,
                      "A scene file or a built-in scene name (default: the Cornell box)");
  command->add_option("-o,--output", options->output, "The dataset's folder (created)")->required();
  command
      ->add_option("--views", d->views,
                   "orbit:N[:ELEVATION] (N views around the scene's bounds, ELEVATION degrees "
                   "up, default 20), sphere:N (a Fibonacci lattice), path:N:FILE (N views along "
                   "keyframes 'X Y Z TX TY TZ', one a line) or cameras (the scene's own)")
      ->required();
  command->add_flag("--ground-truth", d->ground_truth,
                    "Also write each view's ground truth to ground_truth/VIEW.exr, its flow "
                    "channels between consecutive views");
  command
      ->add_option("--image-format", d->image_format,
                   "The images' format by extension: png (default), exr, jpg, tif, hdr, pfm")
      ->capture_default_str();
  command
      ->add_option("--formats", d->formats,
                   "The calibration files: colmap, nerf, opencv (comma-separated) or none")
      ->capture_default_str();
  add_frame_options(*command, *options);
  command->callback([options, d, command] {
    options->width_given = command->count("--width") > 0;
    options->height_given = command->count("--height") > 0;
    options->spp_given = command->count("--spp") > 0;
    options->seed_given = command->count("--seed") > 0;
    run_dataset(*options, *d);
  });
}

}  // namespace obscura::app
