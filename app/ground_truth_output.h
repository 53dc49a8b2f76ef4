// `obscura render --ground-truth FILE.exr [--flow-times A:B]`: the ground-truth channels of the
// frame (docs/ground_truth.md) in one OpenEXR file, from whichever renderer renders the image.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "obscura/scene/ground_truth.h"
#include "obscura/scene/scene.h"
#include "raster_options.h"

namespace obscura::app {

struct GroundTruthOptions {
  std::string path;                       // empty: no ground truth
  std::optional<std::string> flow_times;  // "A:B" in seconds, fractions allowed
};

void add_ground_truth_options(CLI::App& render, GroundTruthOptions& options);

// The times --flow-times gives, else the shutter's open and close. Throws UsageError for a
// malformed value or --flow-times without --ground-truth.
GroundTruthTimes ground_truth_times(const GroundTruthOptions& options, const Camera& camera);

// Checks before any rendering that the file can be written: an .exr name in a writable
// directory, not the image itself, not an input of the scene. Throws obscura::Error / UsageError.
void check_ground_truth_output(const GroundTruthOptions& options, const std::string& image_output,
                               const Scene& scene);

// Computes the ground truth of `scene` with its camera by `renderer` (the rasterizer, or the
// tracer for any of its integrators) and writes it; returns the path. A cancel (InterruptGuard)
// before the ground truth is computed and written returns nothing and writes nothing.
std::optional<std::string> write_ground_truth_file(const GroundTruthOptions& options,
                                                   Renderer renderer, const RasterOptions& raster,
                                                   const Scene& scene);

}  // namespace obscura::app
