// What of an animated or multi-scene file is shown, for `render` and `info`: the moment
// (--time T) and, for glTF, the scene (--gltf-scene N|NAME).
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "obscura/camera/shutter.h"
#include "obscura/io/gltf_loader.h"

namespace obscura::app {

struct SceneChoiceOptions {
  std::optional<double> time_s;  // --time: the middle of the exposure
  std::string gltf_scene;        // --gltf-scene: an index or a name; empty = the file's default
  std::string gltf_animation;    // --gltf-animation: an index or a name; empty = the first
};

void add_scene_choice_options(CLI::App& command, SceneChoiceOptions& options);

// The shutter centred on --time when given (its length kept), else `shutter` as it is.
Shutter shutter_at_time(const SceneChoiceOptions& options, const Shutter& shutter);

// What the glTF loader needs: the scene, and the time skins and morph targets are posed at —
// the middle of the shutter the render will use, where the rasterizer draws a still frame —
// with the shutter's length, across which animated ones are posed again for motion blur.
GltfLoadOptions gltf_load_options(const SceneChoiceOptions& options, const Shutter& shutter);

}  // namespace obscura::app
