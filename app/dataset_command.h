// `obscura dataset SCENE --views SPEC -o DIR`: a calibrated dataset in one command — every view
// (render/dataset_views.h) rendered with the images, ground truth and AOVs asked for, and one
// COLMAP model, one transforms.json and an OpenCV file per view (render/dataset.h). Finished
// views are skipped (resume); under mpirun the ranks take views one at a time from a shared
// counter, as a sequence's frames (docs/distributed.md).
#pragma once

#include <CLI/CLI.hpp>

namespace obscura::app {

void add_dataset_command(CLI::App& app);

}  // namespace obscura::app
