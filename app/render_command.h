// `obscura render`: load a scene, render it, write the image.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "obscura/scene/scene.h"

namespace obscura::app {

void add_render_command(CLI::App& app);

// A built-in scene by name (empty: the default); throws obscura::Error for unknown names.
Scene load_scene(const std::string& name);

}  // namespace obscura::app
