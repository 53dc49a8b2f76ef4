// Which of a glTF file's scenes to show: the one the user names (`--gltf-scene N|NAME`), else
// the file's `scene`, else the first.
#pragma once

#include <string>

namespace tinygltf {
class Model;
}  // namespace tinygltf

namespace obscura {

// The index into model.scenes. `choice` is empty (the default), a decimal index or a scene's
// name (a name made of digits is taken as an index). Throws obscura::Error naming `file` and
// listing the scenes the file has when `choice` matches none of them.
int choose_gltf_scene(const tinygltf::Model& model, const std::string& choice,
                      const std::string& file);

}  // namespace obscura
