// EXT_mesh_gpu_instancing: a node that draws its mesh many times, each copy placed by its own
// TRANSLATION / ROTATION / SCALE (accessors with one element per copy), relative to the node.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "obscura/math/matrix4.h"

namespace tinygltf {
class Node;
}  // namespace tinygltf

namespace obscura {

class GltfAccessorReader;

// Copies of instanced meshes a file may ask for in all (each becomes an Instance of ~300 bytes).
inline constexpr size_t kMaxGpuInstances = size_t(1) << 20;

// The node's per-copy transforms (node space ← copy), or nothing when the node does not use the
// extension. Throws obscura::Error naming `where` (the node) for attributes whose counts differ,
// values that are not finite, or more than `budget` copies; `budget` is decreased by the count.
std::vector<Matrix4> gpu_instance_transforms(const tinygltf::Node& node,
                                             GltfAccessorReader& accessors, const std::string& file,
                                             const std::string& where, size_t& budget);

}  // namespace obscura
