// Model files (glTF, OBJ, PLY, STL and whatever else Assimp reads) → meshes, chosen by
// extension. Both scene front doors use it: scene_loader for a model given on its own, and the
// JSON scene file for the models it includes, so neither has to call the other.
#pragma once

#include <string>

#include "obscura/io/gltf_loader.h"
#include "obscura/scene/scene.h"

namespace obscura {

// A model file (glTF, OBJ, PLY, STL or an Assimp format) as it is, without a render camera or
// validation: what the JSON scene file includes. Prepends `path` to Scene::input_files.
Scene load_model_file(const std::string& path, const GltfLoadOptions& gltf = {});

// The file's extension in lower case, with its dot (".glb"); empty if it has none.
std::string lower_extension(const std::string& path);

// --gltf-scene and --gltf-animation choose inside a glTF file: for anything else (`where` names
// it) a choice is an obscura::Error.
void refuse_gltf_choices(const std::string& where, const GltfLoadOptions& gltf);

}  // namespace obscura
