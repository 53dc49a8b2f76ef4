// `obscura render`: load a scene, render it, write the image.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "obscura/scene/scene.h"

namespace obscura::app {

void add_render_command(CLI::App& app);

struct RenderOptions;
// The options `render` and `dataset` share: size, samples, threads, seed, quiet, environment,
// glTF variant, the camera, scene choice, display, image limit, tracer, rasterizer, glare and
// flare options.
void add_frame_options(CLI::App& command, RenderOptions& options);

// A built-in scene by name (empty: the default) or a scene file (obscura::load_scene); throws
// obscura::Error for unknown names and unreadable files.
Scene load_scene(const std::string& name);

}  // namespace obscura::app
