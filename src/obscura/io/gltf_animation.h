// glTF node transforms and their animation: local TRS/matrix → Matrix4, keyframed world
// transforms for motion blur from the first animation's translation/rotation/scale channels, and
// the node transforms and morph weights at one time (for skins and morph targets).
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "obscura/math/matrix4.h"
#include "obscura/math/transform.h"
#include "obscura/scene/instance.h"

namespace tinygltf {
class Model;
class Node;
}  // namespace tinygltf

namespace obscura {

class GltfAccessorReader;

struct Quaternion {
  double x = 0, y = 0, z = 0, w = 1;
};

// Translation · rotation · scale, as glTF composes a node's local transform.
Matrix4 trs_matrix(Vector3d translation, Quaternion rotation, Vector3d scale);
// Spherical linear interpolation along the shorter arc; the result is unit length.
Quaternion slerp(Quaternion a, Quaternion b, double t);
// The node's local transform (its matrix, or its TRS).
Matrix4 node_matrix(const tinygltf::Node& node);
// The transform for an invertible matrix, nothing for a singular one (a node scaled to zero).
std::optional<Transform> invertible(const Matrix4& m);
// Rotation and translation only (cameras and lights ignore scale).
Transform without_scale(const Matrix4& m);
// The most morph targets any primitive of the node's mesh has (0 without a mesh).
int morph_target_count(const tinygltf::Model& model, int node);

class NodeAnimations {
 public:
  // Key times read from all channels together, and world keys handed out to all instances and
  // cameras together (~270 bytes each): far above a real animation, bounded against hostile ones.
  static constexpr size_t kMaxAnimationKeys = size_t(1) << 20;
  static constexpr size_t kMaxWorldKeys = size_t(1) << 20;

  NodeAnimations() = default;
  // Reads animations[animation_index] (none when it is −1, gltf_scene_choice.h chooses it);
  // unsupported channels are reported in `warnings`.
  // Every accessor is read through `accessors` (which bounds and checks them); throws
  // obscura::Error for inconsistent samplers (counts, times that are not finite or do not
  // increase) and out-of-range node or sampler references.
  NodeAnimations(const tinygltf::Model& model, const std::string& file, int animation_index,
                 GltfAccessorReader& accessors, std::vector<std::string>& warnings);

  // The node's local transform at `time` (its static TRS where no channel animates it).
  Matrix4 local_at(int node, double time) const;
  // The node's object→world transform at `time` (through its ancestors).
  Matrix4 world_at(int node, double time) const;
  // The node's morph target weights at `time` when a 'weights' channel animates them.
  std::optional<std::vector<double>> weights_at(int node, double time) const;
  // Keyframes of the node's object→world transform at every key time of it and its ancestors;
  // empty when nothing on its path to the root is animated. Throws obscura::Error past
  // kMaxWorldKeys keys over all calls.
  std::vector<TransformKey> world_keys(int node);

 private:
  struct Channel {
    std::vector<double> times;
    std::vector<double> values;  // `width` per key
    int width = 3;               // 3 (translation, scale), 4 (rotation) or the morph targets
    bool rotation = false;       // quaternions: slerp between keys
    bool step = false;
  };
  struct NodeChannels {
    std::optional<Channel> translation, rotation, scale, weights;
  };
  static std::vector<double> sample(const Channel& channel, double time);
  const tinygltf::Model* model_ = nullptr;
  std::string file_;
  size_t read_keys_ = 0;
  size_t emitted_keys_ = 0;
  std::map<int, NodeChannels> channels_;
  std::vector<int> parent_;  // −1 for roots
};

}  // namespace obscura
