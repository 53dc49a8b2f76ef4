// Obscura's own scene file (JSON): models included from glTF/OBJ/PLY… files with a transform,
// generated shapes, materials, lights, cameras, the environment and render settings. The format
// is documented in docs/scene-format.md. Reading is strict: unknown keys, wrong types and
// out-of-range values are errors naming the file and the JSON path.
#pragma once

#include <string>

#include "obscura/scene/scene.h"

namespace obscura {

Scene load_json_scene(const std::string& path);
// The same for a document in memory; `path` names it in messages, and relative file names in it
// (models, textures) resolve against its directory.
Scene load_json_scene_text(const std::string& text, const std::string& path);

}  // namespace obscura
