// The front door for scenes: a file of any supported format, or a built-in scene by name.
#pragma once

#include <string>
#include <vector>

#include "obscura/io/gltf_loader.h"
#include "obscura/scene/scene.h"

namespace obscura {

// Loads a scene file, choosing the loader by extension: .gltf/.glb (glTF 2.0), .json (Obscura's
// scene file), .obj/.ply/.stl (Obscura's own readers), anything else Assimp reads (.fbx, .dae,
// .3ds, …). The result
// is validated and has a render camera (the file's first, or one framing the scene). `gltf`
// applies to a glTF file (its scene and pose time); naming a scene for another format is an error.
Scene load_scene_file(const std::string& path, const GltfLoadOptions& gltf = {});

struct BuiltinScene {
  std::string name;
  std::string description;
  std::string file;  // path of its JSON file, relative to the scenes folder; empty = built in code
};

// The built-in scenes; the first is the default.
const std::vector<BuiltinScene>& builtin_scenes();

// The folder holding the example scenes: $OBSCURA_SCENES_DIR, else `share/obscura/scenes` beside
// an installed executable, else `scenes/` of the source tree the executable was built in.
std::string scenes_directory();

// A built-in scene's name, or a path to a scene file; empty = the default built-in scene.
// Throws obscura::Error listing the built-in names when `name_or_path` is neither.
Scene load_scene(const std::string& name_or_path, const GltfLoadOptions& gltf = {});

}  // namespace obscura
