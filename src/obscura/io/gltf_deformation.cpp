#include "obscura/io/gltf_deformation.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>

#include "obscura/io/gltf_accessor.h"
#include "obscura/io/gltf_animation.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

Vector3d apply_linear(const Matrix4& m, Vector3d v) {
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
          m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

// The cofactor matrix of the upper 3×3: det · inverse transpose, defined even when singular,
// so normals follow a blended joint matrix without an inversion that could fail.
Vector3d apply_cofactor(const Matrix4& m, Vector3d n) {
  Vector3d c0(m[0][0], m[1][0], m[2][0]), c1(m[0][1], m[1][1], m[2][1]),
      c2(m[0][2], m[1][2], m[2][2]);
  Vector3d r0 = cross(c1, c2), r1 = cross(c2, c0), r2 = cross(c0, c1);
  Vector3d out = r0 * n.x + r1 * n.y + r2 * n.z;
  return dot(c0, r0) < 0 ? -out : out;  // a mirroring matrix would turn the normal inside out
}

Vector3d unit_or(Vector3d v, Vector3d fallback) {
  double l = length(v);
  return l > 0 && std::isfinite(l) ? v / l : fallback;
}

}  // namespace

void apply_morph_targets(Mesh& mesh, const PrimitiveDeformation& d,
                         std::span<const double> weights) {
  const size_t n = mesh.positions.size();
  std::vector<Vector3d> normal_sum(mesh.normals.size()), tangent_sum(mesh.tangents.size());
  for (size_t i = 0; i < normal_sum.size(); ++i)
    normal_sum[i] = {mesh.normals[i].x, mesh.normals[i].y, mesh.normals[i].z};
  for (size_t i = 0; i < tangent_sum.size(); ++i)
    tangent_sum[i] = {mesh.tangents[i].x, mesh.tangents[i].y, mesh.tangents[i].z};
  for (size_t t = 0; t < d.targets.size() && t < weights.size(); ++t) {
    const float w = float(weights[t]);
    if (w == 0) continue;
    const PrimitiveDeformation::Target& target = d.targets[t];
    if (!target.positions.empty())
      for (size_t i = 0; i < n; ++i)
        mesh.positions[i] += Vector3f(target.positions[3 * i], target.positions[3 * i + 1],
                                      target.positions[3 * i + 2]) *
                             w;
    if (!target.normals.empty())
      for (size_t i = 0; i < normal_sum.size(); ++i)
        normal_sum[i] +=
            Vector3d(target.normals[3 * i], target.normals[3 * i + 1], target.normals[3 * i + 2]) *
            double(w);
    if (!target.tangents.empty())
      for (size_t i = 0; i < tangent_sum.size(); ++i)
        tangent_sum[i] += Vector3d(target.tangents[3 * i], target.tangents[3 * i + 1],
                                   target.tangents[3 * i + 2]) *
                          double(w);
  }
  for (size_t i = 0; i < normal_sum.size(); ++i) {
    Normal3f& out = mesh.normals[i];
    Vector3d u = unit_or(normal_sum[i], {out.x, out.y, out.z});
    out = Normal3f(float(u.x), float(u.y), float(u.z));
  }
  for (size_t i = 0; i < tangent_sum.size(); ++i) {
    Vector4f& out = mesh.tangents[i];
    Vector3d u = unit_or(tangent_sum[i], {out.x, out.y, out.z});
    out = {float(u.x), float(u.y), float(u.z), out.w};
  }
}

void apply_skin(Mesh& mesh, const PrimitiveDeformation& d, std::span<const Matrix4> joints) {
  const size_t k = size_t(d.influences);
  if (k == 0) return;
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    Matrix4 blend;  // zeros
    double total = 0;
    for (size_t j = 0; j < k; ++j) {
      const double w = d.weights[i * k + j];
      if (w == 0) continue;
      const Matrix4& m = joints[d.joints[i * k + j]];
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) blend.m[r][c] += w * m.m[r][c];
      total += w;
    }
    if (total == 0) continue;  // no influence: the vertex stays where the mesh put it
    const Point3f p = mesh.positions[i];
    Vector4d moved = blend * Vector4d(p.x, p.y, p.z, 1);
    mesh.positions[i] = Point3f(float(moved.x), float(moved.y), float(moved.z));
    if (!mesh.normals.empty()) {
      Normal3f& n = mesh.normals[i];
      Vector3d u = unit_or(apply_cofactor(blend, {n.x, n.y, n.z}), {n.x, n.y, n.z});
      n = Normal3f(float(u.x), float(u.y), float(u.z));
    }
    if (!mesh.tangents.empty()) {
      Vector4f& t = mesh.tangents[i];
      Vector3d u = unit_or(apply_linear(blend, {t.x, t.y, t.z}), {t.x, t.y, t.z});
      t = {float(u.x), float(u.y), float(u.z), t.w};
    }
  }
}

GltfDeformer::GltfDeformer(const tinygltf::Model& model, std::string file,
                           GltfAccessorReader& accessors, const NodeAnimations& animations)
    : model_(model), file_(std::move(file)), accessors_(accessors), animations_(animations) {}

std::vector<double> GltfDeformer::morph_weights(int node, double time_s) const {
  if (std::optional<std::vector<double>> animated = animations_.weights_at(node, time_s))
    return *animated;
  const tinygltf::Node& n = model_.nodes[size_t(node)];
  if (!n.weights.empty()) return n.weights;
  return model_.meshes[size_t(n.mesh)].weights;
}

bool GltfDeformer::deforms(int node) {
  const tinygltf::Node& n = model_.nodes[size_t(node)];
  if (n.mesh < 0 || size_t(n.mesh) >= model_.meshes.size()) return false;
  if (n.skin >= 0) return true;
  if (morph_target_count(model_, node) == 0) return false;
  if (animations_.weights_at(node, 0)) return true;
  std::vector<double> w = morph_weights(node, 0);
  return std::any_of(w.begin(), w.end(), [](double x) { return x != 0; });
}

bool GltfDeformer::animated(int node) const {
  const tinygltf::Node& n = model_.nodes[size_t(node)];
  return (n.skin >= 0 && !model_.animations.empty()) || animations_.weights_at(node, 0).has_value();
}

MeshDeformation GltfDeformer::deformation(const Mesh& base, int node, size_t primitive,
                                          const Matrix4& world_from_node, const std::string& where,
                                          double open_s, double close_s) {
  MeshDeformation d{.open_s = open_s, .close_s = close_s, .positions = {}, .normals = {}};
  bool changes = false;
  for (int k = 0; k < kDeformationSteps; ++k) {
    double t = open_s + (close_s - open_s) * k / (kDeformationSteps - 1);
    Mesh posed = deform(base, node, primitive, world_from_node, where, t);
    changes = changes || (k > 0 && posed.positions != d.positions.front());
    d.positions.push_back(std::move(posed.positions));
    if (!posed.normals.empty()) d.normals.push_back(std::move(posed.normals));
  }
  return changes ? d : MeshDeformation{};
}

const PrimitiveDeformation& GltfDeformer::primitive_data(int mesh, size_t primitive,
                                                         size_t vertex_count,
                                                         const std::string& where) {
  auto key = std::make_pair(mesh, primitive);
  auto found = primitives_.find(key);
  if (found != primitives_.end()) return found->second;
  const tinygltf::Primitive& p = model_.meshes[size_t(mesh)].primitives[primitive];
  PrimitiveDeformation d;
  auto vec3 = [&](int accessor, const std::string& at) {
    if (uint64_t count = accessors_.count(accessor, at); count != vertex_count)
      throw Error(file_ + ": " + at, std::to_string(count) + " elements for " +
                                         std::to_string(vertex_count) + " positions");
    std::vector<float> v =
        accessors_.floats(accessor, {3}, AccessorNumbers::kFloatOrSmallInteger, at);
    for (size_t i = 0; i < v.size(); ++i)
      if (!std::isfinite(v[i]))
        throw Error(file_ + ": " + at, "element " + std::to_string(i / 3) + " is not finite");
    return v;
  };
  for (size_t t = 0; t < p.targets.size(); ++t) {
    PrimitiveDeformation::Target target;
    for (const auto& [attribute, accessor] : p.targets[t]) {
      std::string at = where + ".targets[" + std::to_string(t) + "]." + attribute;
      if (attribute == "POSITION") target.positions = vec3(accessor, at);
      if (attribute == "NORMAL") target.normals = vec3(accessor, at);
      if (attribute == "TANGENT") target.tangents = vec3(accessor, at);
    }
    d.targets.push_back(std::move(target));
  }
  // JOINTS_n with WEIGHTS_n, four influences per set, interleaved per vertex.
  std::vector<std::vector<float>> joint_sets, weight_sets;
  for (int set = 0;; ++set) {
    auto joints = p.attributes.find("JOINTS_" + std::to_string(set));
    auto weights = p.attributes.find("WEIGHTS_" + std::to_string(set));
    if (joints == p.attributes.end() && weights == p.attributes.end()) break;
    std::string at = where + ".attributes.";
    if (joints == p.attributes.end() || weights == p.attributes.end())
      throw Error(file_ + ": " + at + (joints == p.attributes.end() ? "JOINTS_" : "WEIGHTS_") +
                      std::to_string(set),
                  "is missing; JOINTS_n and WEIGHTS_n come in pairs");
    for (auto [it, name] : {std::pair{joints, "JOINTS_"}, std::pair{weights, "WEIGHTS_"}})
      if (uint64_t count = accessors_.count(it->second, at + name + std::to_string(set));
          count != vertex_count)
        throw Error(
            file_ + ": " + at + name + std::to_string(set),
            std::to_string(count) + " elements for " + std::to_string(vertex_count) + " positions");
    joint_sets.push_back(accessors_.floats(joints->second, {4},
                                           AccessorNumbers::kFloatOrSmallInteger,
                                           at + "JOINTS_" + std::to_string(set)));
    weight_sets.push_back(accessors_.floats(weights->second, {4},
                                            AccessorNumbers::kFloatOrNormalized,
                                            at + "WEIGHTS_" + std::to_string(set)));
  }
  d.influences = int(4 * joint_sets.size());
  const size_t k = size_t(d.influences);
  d.joints.resize(vertex_count * k);
  d.weights.resize(vertex_count * k);
  for (size_t s = 0; s < joint_sets.size(); ++s)
    for (size_t i = 0; i < vertex_count; ++i)
      for (size_t j = 0; j < 4; ++j) {
        float joint = joint_sets[s][4 * i + j], weight = weight_sets[s][4 * i + j];
        std::string at = where + ".attributes.";
        if (!(joint >= 0) || joint != std::floor(joint) || joint > 65535)
          throw Error(file_ + ": " + at + "JOINTS_" + std::to_string(s),
                      "vertex " + std::to_string(i) + " names joint " + std::to_string(joint) +
                          "; expected an unsigned integer");
        if (!std::isfinite(weight) || weight < 0)
          throw Error(file_ + ": " + at + "WEIGHTS_" + std::to_string(s),
                      "vertex " + std::to_string(i) + " has weight " + std::to_string(weight) +
                          "; expected a finite number ≥ 0");
        d.joints[i * k + 4 * s + j] = uint32_t(joint);
        d.weights[i * k + 4 * s + j] = weight;
      }
  return primitives_.emplace(key, std::move(d)).first->second;
}

const std::vector<Matrix4>& GltfDeformer::inverse_binds(int skin) {
  auto found = inverse_binds_.find(skin);
  if (found != inverse_binds_.end()) return found->second;
  const tinygltf::Skin& s = model_.skins[size_t(skin)];
  const std::string where = "skins[" + std::to_string(skin) + "]";
  std::vector<Matrix4> binds(s.joints.size(), Matrix4::identity());  // absent: identities
  if (s.inverseBindMatrices >= 0) {
    const std::string at = where + ".inverseBindMatrices";
    if (uint64_t count = accessors_.count(s.inverseBindMatrices, at); count < s.joints.size())
      throw Error(file_ + ": " + at, std::to_string(count) + " matrices for " +
                                         std::to_string(s.joints.size()) + " joints");
    std::vector<float> v =
        accessors_.floats(s.inverseBindMatrices, {16}, AccessorNumbers::kFloat, at);
    for (size_t j = 0; j < binds.size(); ++j)
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
          float x = v[16 * j + 4 * size_t(c) + size_t(r)];  // column-major
          if (!std::isfinite(x))
            throw Error(file_ + ": " + at, "matrix " + std::to_string(j) + " is not finite");
          binds[j].m[r][c] = x;
        }
  }
  return inverse_binds_.emplace(skin, std::move(binds)).first->second;
}

Mesh GltfDeformer::deform(Mesh base, int node, size_t primitive, const Matrix4& world_from_node,
                          const std::string& where, double time_s) {
  const tinygltf::Node& n = model_.nodes[size_t(node)];
  const PrimitiveDeformation& d = primitive_data(n.mesh, primitive, base.positions.size(), where);
  if (!d.targets.empty()) apply_morph_targets(base, d, morph_weights(node, time_s));
  if (n.skin < 0) return base;
  const std::string skin_at = "nodes[" + std::to_string(node) + "].skin";
  if (size_t(n.skin) >= model_.skins.size())
    throw Error(file_ + ": " + skin_at,
                "skin index " + std::to_string(n.skin) + " is out of range");
  if (d.influences == 0)
    throw Error(file_ + ": " + where,
                "is skinned by " + skin_at + " but has no JOINTS_0/WEIGHTS_0");
  const tinygltf::Skin& skin = model_.skins[size_t(n.skin)];
  const std::vector<Matrix4>& binds = inverse_binds(n.skin);
  std::optional<Matrix4> node_from_world = inverse(world_from_node);
  if (!node_from_world) return base;  // not rendered anyway (scaled to zero)
  std::vector<Matrix4> joints(skin.joints.size());
  for (size_t j = 0; j < joints.size(); ++j) {
    int joint = skin.joints[j];
    if (joint < 0 || size_t(joint) >= model_.nodes.size())
      throw Error(
          file_ + ": skins[" + std::to_string(n.skin) + "].joints[" + std::to_string(j) + "]",
          "node index " + std::to_string(joint) + " is out of range");
    joints[j] = *node_from_world * animations_.world_at(joint, time_s) * binds[j];
  }
  // Exporters fill unused influences with joint 0 and weight 0: only weighted ones must exist.
  for (size_t i = 0; i < d.joints.size(); ++i)
    if (d.weights[i] != 0 && d.joints[i] >= joints.size())
      throw Error(file_ + ": " + where + ".attributes.JOINTS_" +
                      std::to_string(i % size_t(d.influences) / 4),
                  "vertex " + std::to_string(i / size_t(d.influences)) + " names joint " +
                      std::to_string(d.joints[i]) + " but the skin has " +
                      std::to_string(joints.size()));
  apply_skin(base, d, joints);
  return base;
}

}  // namespace obscura
