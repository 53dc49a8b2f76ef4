// The glTF 2.0 rules tinygltf parses but does not enforce, checked before the importer walks the
// file: asset.version and minVersion, extensionsRequired/extensionsUsed against what Obscura
// reads, node transforms (matrix of 16 numbers, TRS of 3/4/3, not both), a node hierarchy that
// is a forest (no cycle, no node with two parents, scenes list roots), and KHR_lights_punctual
// values (intensity, range, cone angles).
#pragma once

#include <set>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}  // namespace tinygltf

namespace obscura {

// The glTF extensions the loader reads (and so may be in extensionsRequired).
const std::set<std::string>& supported_gltf_extensions();

// Throws obscura::Error naming `file` and the JSON path of the first violation. Appends one
// warning per unsupported extension in extensionsUsed to `warnings` and returns their names, so
// that the importer does not warn about them again for every material that uses them.
std::set<std::string> validate_gltf_model(const tinygltf::Model& model, const std::string& file,
                                          std::vector<std::string>& warnings);

}  // namespace obscura
