#include "ground_truth_output.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <sstream>
#include <vector>

#include "camera_options.h"
#include "obscura/io/ground_truth_file.h"
#include "obscura/io/image_io.h"
#include "obscura/math/number_list.h"
#include "obscura/render/ground_truth_frame.h"
#include "tracer_options.h"
#include "usage_error.h"

namespace obscura::app {

void add_ground_truth_options(CLI::App& render, GroundTruthOptions& options) {
  render.add_option("--ground-truth", options.path,
                    "Also write per-pixel ground truth (depth, range, position, normals, "
                    "instance and material ids, forward and backward optical flow, time) and the "
                    "exact camera to this .exr file (docs/ground_truth.md)");
  render.add_option("--flow-times", options.flow_times,
                    "The two times A:B (seconds, fractions allowed) of --ground-truth: values at "
                    "A, optical flow from A to B and back; default: the shutter's open and close");
}

GroundTruthTimes ground_truth_times(const GroundTruthOptions& options, const Camera& camera) {
  if (!options.flow_times) return default_ground_truth_times(camera);
  if (options.path.empty())
    throw UsageError("--flow-times sets the times of --ground-truth: give --ground-truth FILE.exr");
  std::vector<double> times =
      parse_list(*options.flow_times, ':', 2, "--flow-times", "A:B in seconds (0:1/60)");
  return {times[0], times[1]};
}

void check_ground_truth_output(const GroundTruthOptions& options, const std::string& image_output,
                               const Scene& scene) {
  if (options.path.empty()) return;
  if (image_format_for_path(options.path) != ImageFormat::kExr)
    throw UsageError("--ground-truth writes an OpenEXR file: the name must end in .exr; got '" +
                     options.path + "'");
  check_output_path(options.path, "--ground-truth");
  std::error_code error;
  if (options.path == image_output || std::filesystem::weakly_canonical(options.path, error) ==
                                          std::filesystem::weakly_canonical(image_output, error))
    throw UsageError("--ground-truth '" + options.path + "' is the image's own output (-o)");
  check_not_an_input(options.path, scene.input_files);
}

std::optional<std::string> write_ground_truth_file(const GroundTruthOptions& options,
                                                   Renderer renderer, const RasterOptions& raster,
                                                   const Scene& scene) {
  if (InterruptGuard::requested()) return std::nullopt;
  const Camera& camera = scene.camera;
  const GroundTruthTimes times = ground_truth_times(options, camera);
  // The cancel reaches inside: the tracer stops between tiles, the rasterizer between rows.
  FrameSettings settings{.renderer = renderer, .cancel = &InterruptGuard::requested()};
  apply_raster_options(raster, settings.raster);
  const GroundTruthBuffer buffer = render_ground_truth_frame(scene, camera, settings, times);
  if (InterruptGuard::requested()) return std::nullopt;
  write_ground_truth(options.path, buffer, camera, times);
  return options.path;
}

}  // namespace obscura::app
