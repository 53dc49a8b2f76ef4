#include "merge_command.h"

#include <cstdio>
#include <memory>

#include "display_options.h"
#include "frame_render.h"
#include "obscura/io/aov_files.h"
#include "obscura/io/image_io.h"
#include "partial_render.h"
#include "shard_file.h"
#include "tracer_options.h"

namespace obscura::app {

namespace {

struct MergeOptions {
  std::vector<std::string> parts;
  RenderOptions render;  // the output, display options and --quiet
};

void run_merge(const MergeOptions& options) {
  check_output_path(options.render.output, "--output");
  check_not_an_input(options.render.output, options.parts);
  // One part read at a time: the frame and one part in memory, not every part. A cancel stops
  // between parts; nothing is written then (no part of the frame is complete without the rest).
  InterruptGuard interrupt;
  ShardMerger merger;
  for (const std::string& path : options.parts) {
    if (InterruptGuard::requested()) {
      std::fprintf(stderr, "obscura: interrupted: %s is not written\n",
                   options.render.output.c_str());
      set_exit_status(interrupted_exit_status());
      return;
    }
    merger.add(read_shard(path));
  }
  RenderedFrame frame = merger.finish();
  if (frame.aovs)
    for (const std::string& aov : aov_paths(options.render.output, frame.aovs->has_albedo()))
      check_not_an_input(aov, options.parts);
  if (!options.render.quiet && frame.progress.partial())
    std::fprintf(stderr, "warning: the parts were stopped early%s\n",
                 partial_note(frame.progress).c_str());
  // Finished as one process finishes it: the parts carry the recipe and its layers.
  write_frame(options.render, options.render.output, frame);
}

}  // namespace

void add_merge_command(CLI::App& app) {
  auto options = std::make_shared<MergeOptions>();
  CLI::App* merge = app.add_subcommand(
      "merge", "Assemble the parts of `obscura render --shard I/N` into the whole image");
  merge->add_option("parts", options->parts, "The N partial films (.exr), in any order")
      ->required()
      ->check(CLI::ExistingFile);
  merge
      ->add_option("-o,--output", options->render.output,
                   "Output image; the format follows the extension: .png, .exr, …")
      ->required();
  merge->add_flag("-q,--quiet", options->render.quiet, "No warnings on stderr");
  add_display_options(merge, options->render.display);
  merge->callback([options] { run_merge(*options); });
}

}  // namespace obscura::app
