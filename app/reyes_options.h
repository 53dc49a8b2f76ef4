// The knobs of `obscura render --renderer reyes`: shading rate, grid size, bucket size, pixel
// samples and eye-split limit (docs/reyes.md). Given on the command line they win over the scene
// file's render.reyes block (render/frame_request.h).
#pragma once

#include <vector>

#include <CLI/CLI.hpp>

#include "obscura/render/frame_request.h"
#include "obscura/render/renderer.h"

namespace obscura::app {

struct ReyesOptions {
  double shading_rate = 1;
  int grid_size = 256, bucket_size = 16, pixel_samples = 16, eye_splits = 8;
  // In the order above: to tell which were given.
  std::vector<CLI::Option*> registered;
};

void add_reyes_options(CLI::App& render, ReyesOptions& options);
// Throws UsageError for these options given to another renderer; their ranges are checked with
// the rest of the frame's settings (reyes/reyes_settings.h), which name the option.
void validate(const ReyesOptions& options, Renderer renderer);
// The options given, into the frame request.
void request_reyes_options(const ReyesOptions& options, FrameRequest& request);

}  // namespace obscura::app
