// Which of a glTF file's scenes to show: the one the user names (`--gltf-scene N|NAME`), else
// the file's `scene`, else the first. Which animation plays: the one the user names
// (`--gltf-animation N|NAME`), else the first.
#pragma once

#include <string>
#include <vector>

namespace tinygltf {
class Model;
}  // namespace tinygltf

namespace obscura {

// The index into model.scenes. `choice` is empty (the default), a decimal index or a scene's
// name (a name made of digits is taken as an index). Throws obscura::Error naming `file` and
// listing the scenes the file has when `choice` matches none of them.
int choose_gltf_scene(const tinygltf::Model& model, const std::string& choice,
                      const std::string& file);

// The index into model.animations (−1 when the file has none), chosen the same way; with no
// choice and several animations, a warning names them and the option.
int choose_gltf_animation(const tinygltf::Model& model, const std::string& choice,
                          const std::string& file, std::vector<std::string>& warnings);

}  // namespace obscura
