// Skins and morph targets (glTF 2.0 §3.7.2.2 and §3.7.3): a primitive's vertices deformed at one
// time. The loader poses each deformed mesh at the render time (its positions, what a still
// shows) and, when the deformation is animated and the shutter open, at kDeformationSteps times
// across the shutter (Mesh::deformation), which both renderers interpolate for motion blur.
//
// Morph targets first: attribute = base + Σ weightᵢ · deltaᵢ (POSITION, NORMAL, TANGENT), with
// the node's weights, else the mesh's, else zeros, or the 'weights' animation channel at the time.
// Then the skin: each vertex by Σ weightₖ · jointMatrix(jointₖ) over JOINTS_n/WEIGHTS_n, where
// jointMatrix(j) = inverse(world of the mesh node) · world of joint j · inverseBindMatrix(j), so
// the result stays in the mesh node's space (and the node's own transform cancels, as the spec
// asks). Normals go by the inverse transpose of the blended matrix, tangents by the matrix.
#pragma once

#include <cstddef>
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

// Poses across a shutter: 8 segments, each interpolated linearly (as Embree does between its
// time steps); a 1/60 s shutter over a walk cycle bends no joint visibly within one segment.
inline constexpr int kDeformationSteps = 9;
// Vertices posed in all (each deformed node's copy and its steps, ~28 bytes each: ~1.9 GB), so
// that many nodes skinning one large mesh cannot multiply it without limit.
inline constexpr size_t kMaxPosedVertices = size_t(1) << 26;

class GltfDeformer {
 public:
  // Times are seconds on the file's animation clock.
  GltfDeformer(const tinygltf::Model& model, std::string file, GltfAccessorReader& accessors,
               const NodeAnimations& animations);

  // Whether the node's mesh changes shape: a skin, or morph targets with a weight ≠ 0 at some
  // time.
  bool deforms(int node);
  // Whether that shape changes with time: a skin in a file with an animation, or a 'weights'
  // channel on the node.
  bool animated(int node) const;
  // `base` (primitive `primitive` of the node's mesh) deformed for node `node` at `time_s`; the
  // node's world transform (the instance's) is `world_from_node`. `where` names the primitive.
  Mesh deform(Mesh base, int node, size_t primitive, const Matrix4& world_from_node,
              const std::string& where, double time_s);
  // The same at kDeformationSteps times from open_s to close_s, as a Mesh::deformation; empty
  // when the shape does not change over them.
  MeshDeformation deformation(const Mesh& base, int node, size_t primitive,
                              const Matrix4& world_from_node, const std::string& where,
                              double open_s, double close_s);

 private:
  std::vector<double> morph_weights(int node, double time_s) const;
  const PrimitiveDeformation& primitive_data(int mesh, size_t primitive, size_t vertex_count,
                                             const std::string& where);
  const std::vector<Matrix4>& inverse_binds(int skin);

  const tinygltf::Model& model_;
  std::string file_;
  GltfAccessorReader& accessors_;
  const NodeAnimations& animations_;
  std::map<std::pair<int, size_t>, PrimitiveDeformation> primitives_;
  std::map<int, std::vector<Matrix4>> inverse_binds_;
};

}  // namespace obscura
