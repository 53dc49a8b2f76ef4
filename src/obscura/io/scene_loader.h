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

// The folders the example scenes (and the studio map, assets/envmaps/studio.exr) are looked for
// in, whatever the working directory: $OBSCURA_SCENES_DIR alone when it is set; otherwise, in
// order, beside the binary that holds this library (the executable, or the Python extension
// module) its ../share/obscura/scenes (an installed CLI, bin/obscura) and its scenes/ (an
// installed Python package, obscura/_obscura*.so), then scenes/ of the source tree the library
// was built from.
std::vector<std::string> scenes_search_dirs();

// The path of `relative` (e.g. "bunny.json") in the first of scenes_search_dirs() that holds it;
// empty when none does.
std::string find_scenes_file(const std::string& relative);

// Where find_scenes_file looked for `relative`, and how to point it elsewhere, for the message
// that reports it missing: "looked in A/relative, B/relative; set OBSCURA_SCENES_DIR …".
std::string scenes_search_report(const std::string& relative);

// A built-in scene's name, or a path to a scene file; empty = the default built-in scene.
// Throws obscura::Error listing the built-in names when `name_or_path` is neither.
Scene load_scene(const std::string& name_or_path, const GltfLoadOptions& gltf = {});

}  // namespace obscura
