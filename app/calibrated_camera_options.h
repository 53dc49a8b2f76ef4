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

// Loads --calibration into `camera` (projection, image size as the film's, pose when the file
// has one). A file that cannot be read or is malformed throws obscura::Error (exit 1).
void apply_calibration_file(Camera& camera, const CameraOverrides& overrides);

// Applies --projection calibrated, --intrinsics, --calibration-size, --distortion and
// --max-field-angle: any of them makes the camera calibrated (a perspective camera keeps its
// framing as K; pose, clipping, shutter and exposure stay). Malformed values throw UsageError
// naming the option and the value.
void apply_calibrated_overrides(Camera& camera, const CameraOverrides& overrides);

}  // namespace obscura::app
