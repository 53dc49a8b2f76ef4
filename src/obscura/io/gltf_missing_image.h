// What the glTF loader does about an image it cannot use: look for the file where users' files
// usually put it (next to the model, under its base name, as Blender does for a path from
// another machine), and otherwise stand in a placeholder that cannot be mistaken for the real
// texture.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "obscura/scene/texture.h"

namespace tinygltf {
class Model;
}  // namespace tinygltf

namespace obscura {

// The last path component of an image URI (after the last '/' or '\', percent-escapes
// decoded), e.g. "C:\Users\me\textures\wood%20oak.png" → "wood oak.png"; empty when none.
std::string image_uri_base_name(const std::string& uri);

// `base_dir`/base name of `uri` when that is an existing regular file other than the path the
// URI itself resolves to; nothing otherwise.
std::optional<std::string> find_image_next_to_model(const std::string& uri,
                                                    const std::string& base_dir);

// A magenta/black checker of 8 × 8 squares (sRGB, nearest filtering, repeating): what a missing
// base colour texture shows, visibly wrong in both renderers.
Texture missing_image_placeholder();

// For each image of `model` not in `decoded`: an external file tinygltf could not find is looked
// for under its base name in `base_dir` (decoded when found, its path added to `files_read`,
// one warning saying so); an image still unusable gets one warning naming it, why (`failed`
// holds the decoder's reason, by image index) and what renders instead. `file` prefixes the
// warnings.
void resolve_unusable_gltf_images(const tinygltf::Model& model, std::map<int, Texture>& decoded,
                                  const std::map<int, std::string>& failed, const std::string& file,
                                  const std::string& base_dir, std::vector<std::string>& files_read,
                                  std::vector<std::string>& warnings);

}  // namespace obscura
