// `obscura render`: load a scene, render it, write the image.
#pragma once

#include <CLI/CLI.hpp>

namespace obscura::app {

void add_render_command(CLI::App& app);

}  // namespace obscura::app
