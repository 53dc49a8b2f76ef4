// The command-line options of calibrated cameras, shared by `obscura render` and
// `obscura camera` (docs/camera.md, "Calibrated cameras"):
//   --projection calibrated, --intrinsics fx,fy,cx,cy[,skew], --calibration-size WxH,
//   --distortion MODEL[:c1,c2,...], --max-field-angle DEG,
//   --calibration FILE [--calibration-image NAME].
#pragma once

#include <CLI/CLI.hpp>

#include "camera_options.h"

namespace obscura::app {

void add_calibrated_camera_options(CLI::App& command, CameraOverrides& overrides);

}  // namespace obscura::app
