#include "scene_choice_options.h"

#include "option_ranges.h"

namespace obscura::app {

namespace {

// Far beyond any animation, near enough that a shutter around it keeps its length in doubles.
constexpr double kMaxTimeS = 1e9;

}  // namespace

void add_scene_choice_options(CLI::App& command, SceneChoiceOptions& options) {
  command
      .add_option("--time", options.time_s,
                  "The moment shown, in seconds of the file's animation: the exposure is centred "
                  "on it and skins and morph targets are posed at it")
      ->check(number_in(-kMaxTimeS, kMaxTimeS));
  command.add_option("--gltf-scene", options.gltf_scene,
                     "The glTF scene to show, by index or name (default: the file's own choice, "
                     "else the first)");
  command.add_option("--gltf-animation", options.gltf_animation,
                     "The glTF animation that plays, by index or name (default: the first); "
                     "--time says when in it");
}

Shutter shutter_at_time(const SceneChoiceOptions& options, const Shutter& shutter) {
  if (!options.time_s) return shutter;
  const double half = shutter.duration_s() / 2;
  Shutter at = shutter;  // the rolling readout stays
  at.open_s = *options.time_s - half;
  at.close_s = *options.time_s + half;
  return at;
}

GltfLoadOptions gltf_load_options(const SceneChoiceOptions& options, const Shutter& shutter) {
  const Shutter at = shutter_at_time(options, shutter);
  return {.scene = options.gltf_scene,
          .animation = options.gltf_animation,
          .time_s = at.time_at(0.5),
          .exposure_s = at.duration_s()};
}

}  // namespace obscura::app
