// Camera options shared by `obscura render` and `obscura camera`: pick a scene camera by name and
// override its parameters from the command line. What they ask for is a CameraRequest, which the
// library resolves (render/camera_request.h) as it does Python's.
#pragma once

#include <CLI/CLI.hpp>

#include "obscura/render/camera_request.h"

namespace obscura::app {

using CameraOverrides = CameraRequest;

void add_camera_options(CLI::App& command, CameraOverrides& overrides);

}  // namespace obscura::app
