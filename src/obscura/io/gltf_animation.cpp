#include "obscura/io/gltf_animation.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>

#include "obscura/io/gltf_accessor.h"
#include "obscura/math/error.h"

namespace obscura {

Matrix4 trs_matrix(Vector3d t, Quaternion q, Vector3d s) {
  double x = q.x, y = q.y, z = q.z, w = q.w;
  // The rotation matrix of a unit quaternion, columns scaled by s.
  return Matrix4::from_rows({{
      {(1 - 2 * (y * y + z * z)) * s.x, 2 * (x * y - z * w) * s.y, 2 * (x * z + y * w) * s.z, t.x},
      {2 * (x * y + z * w) * s.x, (1 - 2 * (x * x + z * z)) * s.y, 2 * (y * z - x * w) * s.z, t.y},
      {2 * (x * z - y * w) * s.x, 2 * (y * z + x * w) * s.y, (1 - 2 * (x * x + y * y)) * s.z, t.z},
      {0, 0, 0, 1},
  }});
}

Quaternion slerp(Quaternion a, Quaternion b, double t) {
  double d = a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
  if (d < 0) b = {-b.x, -b.y, -b.z, -b.w}, d = -d;
  double wa = 1 - t, wb = t;
  if (d < 0.9995) {
    double theta = std::acos(d), sin_theta = std::sin(theta);
    wa = std::sin((1 - t) * theta) / sin_theta;
    wb = std::sin(t * theta) / sin_theta;
  }
  Quaternion r{wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z, wa * a.w + wb * b.w};
  double n = std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z + r.w * r.w);
  return {r.x / n, r.y / n, r.z / n, r.w / n};
}

Matrix4 node_matrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    Matrix4 m;  // glTF stores column-major
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m.m[r][c] = node.matrix[4 * c + r];
    return m;
  }
  Vector3d t, s(1, 1, 1);
  Quaternion q;
  if (node.translation.size() == 3)
    t = {node.translation[0], node.translation[1], node.translation[2]};
  if (node.scale.size() == 3) s = {node.scale[0], node.scale[1], node.scale[2]};
  if (node.rotation.size() == 4)
    q = {node.rotation[0], node.rotation[1], node.rotation[2], node.rotation[3]};
  return trs_matrix(t, q, s);
}

std::optional<Transform> invertible(const Matrix4& m) {
  std::optional<Matrix4> inv = inverse(m);
  if (!inv) return std::nullopt;
  return Transform(m, *inv);
}

Transform without_scale(const Matrix4& m) {
  // Normalize the three basis columns; Gram-Schmidt keeps them orthonormal under shear.
  Vector3d x(m.m[0][0], m.m[1][0], m.m[2][0]), y(m.m[0][1], m.m[1][1], m.m[2][1]);
  if (length(x) == 0 || length(y) == 0)
    return Transform::translate({m.m[0][3], m.m[1][3], m.m[2][3]});
  x = normalize(x);
  y = normalize(y - x * dot(x, y));
  Vector3d z = cross(x, y);
  Matrix4 r = Matrix4::from_rows({{{x.x, y.x, z.x, m.m[0][3]},
                                   {x.y, y.y, z.y, m.m[1][3]},
                                   {x.z, y.z, z.z, m.m[2][3]},
                                   {0, 0, 0, 1}}});
  return Transform(r);
}

int morph_target_count(const tinygltf::Model& model, int node) {
  if (node < 0 || size_t(node) >= model.nodes.size()) return 0;
  int mesh = model.nodes[size_t(node)].mesh;
  if (mesh < 0 || size_t(mesh) >= model.meshes.size()) return 0;
  size_t count = 0;
  for (const tinygltf::Primitive& p : model.meshes[size_t(mesh)].primitives)
    count = std::max(count, p.targets.size());
  return int(std::min<size_t>(count, 1 << 16));
}

NodeAnimations::NodeAnimations(const tinygltf::Model& model, const std::string& file,
                               int animation_index, GltfAccessorReader& accessors,
                               std::vector<std::string>& warnings)
    : model_(&model), file_(file), parent_(model.nodes.size(), -1) {
  for (size_t n = 0; n < model.nodes.size(); ++n)
    for (int child : model.nodes[n].children)
      if (child >= 0 && size_t(child) < parent_.size()) parent_[child] = int(n);
  if (animation_index < 0 || size_t(animation_index) >= model.animations.size()) return;
  const tinygltf::Animation& animation = model.animations[size_t(animation_index)];
  const std::string animation_path = "animations[" + std::to_string(animation_index) + "]";
  for (size_t c = 0; c < animation.channels.size(); ++c) {
    const tinygltf::AnimationChannel& ch = animation.channels[c];
    std::string channel_path = animation_path + ".channels[" + std::to_string(c) + "]";
    std::string where = file + ": " + channel_path;
    if (ch.target_node < 0 || size_t(ch.target_node) >= model.nodes.size())
      throw Error(where + ".target.node", "node index " + std::to_string(ch.target_node) +
                                              " is out of range (the file has " +
                                              std::to_string(model.nodes.size()) + ")");
    if (ch.sampler < 0 || size_t(ch.sampler) >= animation.samplers.size())
      throw Error(where + ".sampler", "sampler index " + std::to_string(ch.sampler) +
                                          " is out of range (the animation has " +
                                          std::to_string(animation.samplers.size()) + ")");
    const bool weights = ch.target_path == "weights";
    if (ch.target_path != "translation" && ch.target_path != "rotation" &&
        ch.target_path != "scale" && !weights) {
      warnings.push_back(where + ": '" + ch.target_path + "' animation is not supported");
      continue;
    }
    if (!weights && model.nodes[size_t(ch.target_node)].matrix.size() != 0)
      throw Error(where + ".target.node", "node " + std::to_string(ch.target_node) +
                                              " has a matrix; an animated node must use TRS");
    // Morph weights: one number per morph target of the node's mesh, per key.
    const int width = weights                        ? morph_target_count(model, ch.target_node)
                      : ch.target_path == "rotation" ? 4
                                                     : 3;
    if (width == 0) {
      warnings.push_back(where + ": 'weights' animation of node " + std::to_string(ch.target_node) +
                         ", which has no mesh with morph targets; ignored");
      continue;
    }
    const tinygltf::AnimationSampler& s = animation.samplers[size_t(ch.sampler)];
    std::string sampler_path = animation_path + ".samplers[" + std::to_string(ch.sampler) + "]";
    if (s.interpolation != "LINEAR" && s.interpolation != "STEP" &&
        s.interpolation != "CUBICSPLINE")
      throw Error(
          file + ": " + sampler_path + ".interpolation",
          "unknown interpolation '" + s.interpolation + "' (expected LINEAR, STEP or CUBICSPLINE)");
    const bool cubic = s.interpolation == "CUBICSPLINE";
    // Counts first, so that a mismatch is reported before either array is decoded.
    uint64_t keys = accessors.count(s.input, sampler_path + ".input");
    uint64_t outputs = accessors.count(s.output, sampler_path + ".output");
    // Weights are SCALAR outputs, `width` per key; the other paths are one VEC3/VEC4 per key.
    const uint64_t per_key = (cubic ? 3 : 1) * uint64_t(weights ? width : 1);
    if (keys > std::numeric_limits<uint32_t>::max() || outputs != keys * per_key)
      throw Error(file + ": " + sampler_path,
                  "input has " + std::to_string(keys) + " key times but output has " +
                      std::to_string(outputs) + " values (expected " +
                      std::to_string(keys * per_key) + " for " + s.interpolation +
                      (weights ? " and " + std::to_string(width) + " morph targets" : "") + ")");
    Channel channel;
    std::vector<float> times =
        accessors.floats(s.input, {1}, AccessorNumbers::kFloat, sampler_path + ".input");
    for (size_t k = 0; k < times.size(); ++k) {
      if (!std::isfinite(times[k]) || times[k] < 0)
        throw Error(file + ": " + sampler_path + ".input", "key time " + std::to_string(k) + " = " +
                                                               std::to_string(times[k]) +
                                                               " is not a finite time ≥ 0");
      if (k > 0 && !(times[k] > times[k - 1]))
        throw Error(file + ": " + sampler_path + ".input",
                    "key times must increase (time " + std::to_string(k) + " = " +
                        std::to_string(times[k]) + " after " + std::to_string(times[k - 1]) + ")");
    }
    read_keys_ += times.size();
    if (read_keys_ > kMaxAnimationKeys)
      throw Error(
          file + ": " + sampler_path + ".input",
          "the animation has more than " + std::to_string(kMaxAnimationKeys) + " key times in all");
    channel.times.assign(times.begin(), times.end());
    std::vector<float> values = accessors.floats(
        s.output, {weights ? 1 : width},
        weights || width == 4 ? AccessorNumbers::kFloatOrNormalized : AccessorNumbers::kFloat,
        sampler_path + ".output");
    for (size_t k = 0; k < values.size(); ++k)
      if (!std::isfinite(values[k]))
        throw Error(file + ": " + sampler_path + ".output",
                    "value " + std::to_string(k / width) + " is not finite");
    channel.step = s.interpolation == "STEP";
    channel.width = width;
    channel.rotation = ch.target_path == "rotation";
    if (cubic) {
      // Keep each key's value, dropping the tangents: linear between keys.
      warnings.push_back(where + ": CUBICSPLINE interpolation is approximated as LINEAR");
      for (size_t k = 0; k < channel.times.size(); ++k)
        channel.values.insert(channel.values.end(), values.begin() + (3 * k + 1) * width,
                              values.begin() + (3 * k + 2) * width);
    } else {
      channel.values.assign(values.begin(), values.end());
    }
    NodeChannels& node = channels_[ch.target_node];
    (ch.target_path == "translation" ? node.translation
     : ch.target_path == "rotation"  ? node.rotation
     : weights                       ? node.weights
                                     : node.scale) = std::move(channel);
  }
}

// The value of a channel at `time`, `width` numbers, clamped outside the key range; rotations
// (quaternions) by slerp, everything else linearly.
std::vector<double> NodeAnimations::sample(const Channel& c, double time) {
  const std::vector<double>& times = c.times;
  const std::vector<double>& values = c.values;
  const size_t width = size_t(c.width);
  const bool step = c.step;
  size_t hi = std::upper_bound(times.begin(), times.end(), time) - times.begin();
  if (hi == 0) return {values.begin(), values.begin() + width};
  if (hi == times.size() || step)
    return {values.begin() + (hi - 1) * width, values.begin() + hi * width};
  double t = (time - times[hi - 1]) / (times[hi] - times[hi - 1]);
  const double* a = &values[(hi - 1) * width];
  const double* b = &values[hi * width];
  if (c.rotation) {
    Quaternion q = slerp({a[0], a[1], a[2], a[3]}, {b[0], b[1], b[2], b[3]}, t);
    return {q.x, q.y, q.z, q.w};
  }
  std::vector<double> r(width);
  for (size_t i = 0; i < width; ++i) r[i] = a[i] + (b[i] - a[i]) * t;
  return r;
}

Matrix4 NodeAnimations::local_at(int node, double time) const {
  const tinygltf::Node& n = model_->nodes[node];
  auto found = channels_.find(node);
  if (found == channels_.end()) return node_matrix(n);
  const NodeChannels& c = found->second;
  if (!c.translation && !c.rotation && !c.scale) return node_matrix(n);  // weights only
  Vector3d t, s(1, 1, 1);
  Quaternion q;
  if (n.translation.size() == 3) t = {n.translation[0], n.translation[1], n.translation[2]};
  if (n.scale.size() == 3) s = {n.scale[0], n.scale[1], n.scale[2]};
  if (n.rotation.size() == 4) q = {n.rotation[0], n.rotation[1], n.rotation[2], n.rotation[3]};
  if (c.translation) {
    auto v = sample(*c.translation, time);
    t = {v[0], v[1], v[2]};
  }
  if (c.rotation) {
    auto v = sample(*c.rotation, time);
    q = {v[0], v[1], v[2], v[3]};
  }
  if (c.scale) {
    auto v = sample(*c.scale, time);
    s = {v[0], v[1], v[2]};
  }
  return trs_matrix(t, q, s);
}

std::vector<TransformKey> NodeAnimations::world_keys(int node) {
  std::set<double> times;
  int depth = 0;
  for (int n = node; n >= 0 && depth < 256; n = parent_[n], ++depth) {
    auto found = channels_.find(n);
    if (found == channels_.end()) continue;
    for (const auto* c :
         {&found->second.translation, &found->second.rotation, &found->second.scale})
      if (*c) times.insert((*c)->times.begin(), (*c)->times.end());
  }
  // Every instance under an animated node gets its own keys: bound them all together, so that
  // many nodes below one long animation cannot multiply it without limit.
  emitted_keys_ += times.size();
  if (emitted_keys_ > kMaxWorldKeys)
    throw Error(file_ + ": " + "nodes[" + std::to_string(node) + "]",
                "animated instances need more than " + std::to_string(kMaxWorldKeys) +
                    " transform keys in all (" + std::to_string(times.size()) + " for this node)");
  std::vector<TransformKey> keys;
  for (double time : times) {
    Matrix4 m = Matrix4::identity();
    depth = 0;
    for (int n = node; n >= 0 && depth < 256; n = parent_[n], ++depth) m = local_at(n, time) * m;
    std::optional<Transform> t = invertible(m);
    if (t) keys.push_back({time, *t});
  }
  return keys;
}

Matrix4 NodeAnimations::world_at(int node, double time) const {
  Matrix4 m = Matrix4::identity();
  int depth = 0;
  for (int n = node; n >= 0 && depth < 256; n = parent_[size_t(n)], ++depth)
    m = local_at(n, time) * m;
  return m;
}

std::optional<std::vector<double>> NodeAnimations::weights_at(int node, double time) const {
  auto found = channels_.find(node);
  if (found == channels_.end() || !found->second.weights) return std::nullopt;
  return sample(*found->second.weights, time);
}

}  // namespace obscura
