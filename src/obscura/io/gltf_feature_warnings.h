// glTF 2.0 core features the importer does not apply yet, each named in one warning so that
// nothing a file asks for is dropped silently: alphaMode MASK/BLEND (rendered opaque), normal
// maps, texture coordinate sets other than TEXCOORD_0, skins, morph targets, more than one scene.
#pragma once

#include <string>
#include <vector>

namespace tinygltf {
class Model;
}  // namespace tinygltf

namespace obscura {

// Appends one warning per unapplied feature the file uses to `warnings`, naming `file`, the
// elements that use it (the first few) and what is rendered instead.
void warn_unapplied_gltf_features(const tinygltf::Model& model, const std::string& file,
                                  std::vector<std::string>& warnings);

}  // namespace obscura
