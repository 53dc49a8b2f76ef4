// `obscura camera`: print a scene's camera after command-line overrides, in every vocabulary a
// user may need: angles, lens and sensor, intrinsics K, glTF and Blender settings.
#pragma once

#include <CLI/CLI.hpp>

namespace obscura::app {

void add_camera_command(CLI::App& app);

}  // namespace obscura::app
