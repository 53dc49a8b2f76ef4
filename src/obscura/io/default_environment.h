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

// A scene lit only by emissive surfaces: how brightly they light it, as the power they emit
// (π · luminance of the emitted radiance · area, one side) over the power a surround of radiance
// 1 — the studio environment's mean — sends into the scene's bounding sphere (4π²R²). The
// measured Cornell box's ceiling light gives 0.06; a lantern's two bulbs, a few 10⁻³.
struct EmitterLight {
  size_t emitters = 0;  // emissive instances (untextured)
  double power_w = 0;   // their emitted power (luminance-weighted, W)
  double relative = 0;  // over the surround's, as above
};
EmitterLight emitter_light(const Scene& scene);
// Below this, emitters alone leave a scene too dark to see: the automatic environment is added.
inline constexpr double kFaintEmitterLight = 0.01;

// Applies the choice to the scene. Under kAuto, a scene without its own light — or whose only
// light is emitters too faint to see it by (emitter_light) — gets the studio environment and a
// line in Scene::warnings saying so (and how to turn it off); when the studio
// map cannot be found (an installation without the example scenes), the uniform white one, and
// the warning says where the map was looked for (io/scene_loader.h: scenes_search_dirs).
// Throws obscura::Error naming the file when a chosen map is missing or cannot be read (for
// kStudio, every place it was looked for).
void apply_environment(Scene& scene, const EnvironmentChoice& choice);

}  // namespace obscura
