// Skins and morph targets (glTF 2.0 §3.7.2.2 and §3.7.3): a primitive's vertices deformed at one
// time. The loader poses each deformed mesh once, at the render time; both renderers then see an
// ordinary mesh.
//
// Morph targets first: attribute = base + Σ weightᵢ · deltaᵢ (POSITION, NORMAL, TANGENT), with
// the node's weights, else the mesh's, else zeros, or the 'weights' animation channel at the time.
// Then the skin: each vertex by Σ weightₖ · jointMatrix(jointₖ) over JOINTS_n/WEIGHTS_n, where
// jointMatrix(j) = inverse(world of the mesh node) · world of joint j · inverseBindMatrix(j), so
// the result stays in the mesh node's space (and the node's own transform cancels, as the spec
// asks). Normals go by the inverse transpose of the blended matrix, tangents by the matrix.
#pragma once

#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "obscura/math/matrix4.h"
#include "obscura/scene/mesh.h"

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace obscura {

class GltfAccessorReader;
class NodeAnimations;

// What a primitive brings to deform its vertices, read and checked once.
struct PrimitiveDeformation {
  struct Target {
    std::vector<float> positions, normals, tangents;  // 3 per vertex, or empty
  };
  std::vector<Target> targets;
  std::vector<uint32_t> joints;  // `influences` per vertex: indices into the skin's joints
  std::vector<float> weights;    // `influences` per vertex
  int influences = 0;            // 4 per JOINTS_n/WEIGHTS_n pair
};

// Applies the morph targets with `weights` (one per target; missing ones count as 0).
void apply_morph_targets(Mesh& mesh, const PrimitiveDeformation& d,
                         std::span<const double> weights);
// Applies the skin with one matrix per joint of the skin (mesh node space ← bind space).
void apply_skin(Mesh& mesh, const PrimitiveDeformation& d, std::span<const Matrix4> joint_matrices);

class GltfDeformer {
 public:
  // Poses everything at `time_s` (seconds on the file's animation clock).
  GltfDeformer(const tinygltf::Model& model, std::string file, GltfAccessorReader& accessors,
               const NodeAnimations& animations, double time_s);

  // Whether the node's mesh changes shape: a skin, or morph targets with a weight ≠ 0.
  bool deforms(int node);
  // `base` (primitive `primitive` of the node's mesh) deformed for node `node`, whose world
  // transform (the instance's) is `world_from_node`. `where` names the primitive in messages.
  Mesh deform(Mesh base, int node, size_t primitive, const Matrix4& world_from_node,
              const std::string& where);

 private:
  std::vector<double> morph_weights(int node) const;
  const PrimitiveDeformation& primitive_data(int mesh, size_t primitive, size_t vertex_count,
                                             const std::string& where);
  const std::vector<Matrix4>& inverse_binds(int skin);

  const tinygltf::Model& model_;
  std::string file_;
  GltfAccessorReader& accessors_;
  const NodeAnimations& animations_;
  double time_s_;
  std::map<std::pair<int, size_t>, PrimitiveDeformation> primitives_;
  std::map<int, std::vector<Matrix4>> inverse_binds_;
};

}  // namespace obscura
