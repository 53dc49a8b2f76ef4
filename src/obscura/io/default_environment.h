// The light a scene gets from far away when the user chooses it (`render --environment`), and the
// default model viewers have: a file that brings no light of its own is lit by a neutral studio
// environment instead of rendering black.
#pragma once

#include <string>

#include "obscura/scene/scene.h"

namespace obscura {

enum class EnvironmentSource {
  kAuto,    // the studio environment when the scene has no light of its own; else the scene's
  kNone,    // no environment, even where the scene file has one
  kStudio,  // the studio map (scenes/assets/envmaps/studio.exr), normalised to mean radiance 1
  kWhite,   // uniform radiance 1 in every direction (the furnace test's light)
  kFile,    // an equirectangular radiance map from a file (EXR, HDR, …)
};

struct EnvironmentChoice {
  EnvironmentSource source = EnvironmentSource::kAuto;
  std::string file;     // for kFile
  float intensity = 1;  // multiplies the chosen environment (not the scene's own, under kAuto)
};

// "auto", "none", "studio", "white", or a file name. Throws obscura::Error for an empty text.
EnvironmentChoice parse_environment_choice(const std::string& text);

// Whether the scene brings its own light: a punctual light, an environment, or an emissive
// surface whose emission is not textured. (Textured emission — screens, labels, indicator lamps —
// is decoration in the files users bring; it does not light a scene the way an area light does.)
bool scene_has_own_light(const Scene& scene);

// Applies the choice to the scene. Under kAuto, a scene without its own light gets the studio
// environment and a line in Scene::warnings saying so (and how to turn it off); when the studio
// map cannot be found (an installation without the example scenes), the uniform white one, and
// the warning says where the map was looked for (io/scene_loader.h: scenes_search_dirs).
// Throws obscura::Error naming the file when a chosen map is missing or cannot be read (for
// kStudio, every place it was looked for).
void apply_environment(Scene& scene, const EnvironmentChoice& choice);

}  // namespace obscura
