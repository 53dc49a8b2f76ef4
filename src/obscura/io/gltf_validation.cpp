#include "obscura/io/gltf_validation.h"

#include <tiny_gltf.h>

#include <cmath>
#include <numbers>

#include "obscura/math/error.h"

namespace obscura {

namespace {

std::string element(const std::string& array, size_t index) {
  return array + "[" + std::to_string(index) + "]";
}

// "2.0" → {2, 0}; false when the text is not MAJOR.MINOR (glTF 2.0 §5.2, asset.version).
bool parse_version(const std::string& text, long* major, long* minor) {
  size_t dot = text.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == text.size() || dot > 9 ||
      text.size() - dot > 10)
    return false;
  for (size_t i = 0; i < text.size(); ++i)
    if (i != dot && (text[i] < '0' || text[i] > '9')) return false;
  *major = std::stol(text.substr(0, dot));
  *minor = std::stol(text.substr(dot + 1));
  return true;
}

void check_version(const tinygltf::Model& model, const std::string& file) {
  long major = 0, minor = 0;
  const std::string& version = model.asset.version;
  if (!parse_version(version, &major, &minor))
    throw Error(file + ": asset.version",
                "'" + version + "' is not a glTF version (expected \"2.0\" or another 2.x)");
  if (major != 2)
    throw Error(file + ": asset.version",
                "glTF " + version + " is not supported (Obscura reads glTF 2.x)");
  const std::string& min_version = model.asset.minVersion;
  if (min_version.empty()) return;
  long min_major = 0, min_minor = 0;
  if (!parse_version(min_version, &min_major, &min_minor))
    throw Error(file + ": asset.minVersion", "'" + min_version + "' is not a glTF version");
  if (min_major != 2 || min_minor > 0)
    throw Error(file + ": asset.minVersion",
                "the file requires glTF " + min_version + "; Obscura reads glTF 2.0");
  if (min_minor > minor)
    throw Error(file + ": asset.minVersion",
                min_version + " is newer than asset.version " + version);
}

std::set<std::string> check_extensions(const tinygltf::Model& model, const std::string& file,
                                       std::vector<std::string>& warnings) {
  const std::set<std::string>& supported = supported_gltf_extensions();
  for (size_t i = 0; i < model.extensionsRequired.size(); ++i)
    if (!supported.count(model.extensionsRequired[i]))
      throw Error(file + ": " + element("extensionsRequired", i),
                  "the file requires extension " + model.extensionsRequired[i] +
                      ", which Obscura does not support");
  std::set<std::string> unsupported;
  for (const std::string& name : model.extensionsUsed)
    if (!supported.count(name) && unsupported.insert(name).second)
      warnings.push_back(file + ": extension " + name +
                         " (extensionsUsed) is not supported; it is ignored");
  return unsupported;
}

void check_numbers(const std::vector<double>& values, std::initializer_list<size_t> sizes,
                   const std::string& at) {
  if (values.empty()) return;
  bool size_ok = false;
  for (size_t s : sizes) size_ok = size_ok || values.size() == s;
  if (!size_ok)
    throw Error(at, "has " + std::to_string(values.size()) + " numbers, expected " +
                        std::to_string(*sizes.begin()));
  for (size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw Error(at, "number " + std::to_string(i) + " is not finite");
}

void check_nodes(const tinygltf::Model& model, const std::string& file) {
  const size_t count = model.nodes.size();
  std::vector<int> parent(count, -1);
  for (size_t n = 0; n < count; ++n) {
    const tinygltf::Node& node = model.nodes[n];
    const std::string at = file + ": " + element("nodes", n);
    // (tinygltf drops translation/rotation/scale when a matrix is given, so "both" never
    // reaches here.)
    check_numbers(node.matrix, {16}, at + ".matrix");
    check_numbers(node.translation, {3}, at + ".translation");
    check_numbers(node.rotation, {4}, at + ".rotation");
    check_numbers(node.scale, {3}, at + ".scale");
    for (size_t c = 0; c < node.children.size(); ++c) {
      int child = node.children[c];
      const std::string child_at = at + "." + element("children", c);
      if (child < 0 || size_t(child) >= count)
        throw Error(child_at, "node index " + std::to_string(child) +
                                  " is out of range (the file has " + std::to_string(count) + ")");
      if (size_t(child) == n) throw Error(child_at, "a node cannot be its own child");
      if (parent[size_t(child)] >= 0)
        throw Error(child_at, "node " + std::to_string(child) + " already has parent node " +
                                  std::to_string(parent[size_t(child)]) +
                                  " (a node has at most one parent)");
      parent[size_t(child)] = int(n);
    }
  }
  // With one parent per node, the nodes reachable from the roots are all nodes unless some
  // lie on (or hang below) a cycle. Walk down from the roots without recursion.
  std::vector<char> reached(count, 0);
  std::vector<size_t> stack;
  for (size_t n = 0; n < count; ++n)
    if (parent[n] < 0) stack.push_back(n);
  while (!stack.empty()) {
    size_t n = stack.back();
    stack.pop_back();
    reached[n] = 1;
    for (int child : model.nodes[n].children) stack.push_back(size_t(child));
  }
  for (size_t n = 0; n < count; ++n)
    if (!reached[n])
      throw Error(file + ": " + element("nodes", n),
                  "the node hierarchy has a cycle through this node");

  for (size_t s = 0; s < model.scenes.size(); ++s) {
    std::vector<char> listed(count, 0);
    const std::vector<int>& roots = model.scenes[s].nodes;
    for (size_t i = 0; i < roots.size(); ++i) {
      const std::string at = file + ": " + element("scenes", s) + "." + element("nodes", i);
      int root = roots[i];
      if (root < 0 || size_t(root) >= count)
        throw Error(at, "node index " + std::to_string(root) + " is out of range (the file has " +
                            std::to_string(count) + ")");
      if (parent[size_t(root)] >= 0)
        throw Error(at, "node " + std::to_string(root) + " is a child of node " +
                            std::to_string(parent[size_t(root)]) + "; a scene lists root nodes");
      if (listed[size_t(root)])
        throw Error(at, "node " + std::to_string(root) + " is listed twice");
      listed[size_t(root)] = 1;
    }
  }
}

void check_lights(const tinygltf::Model& model, const std::string& file) {
  // tinygltf reads an absent range as 0; the raw extension tells absent from an explicit 0.
  const tinygltf::Value* raw_lights = nullptr;
  auto ext = model.extensions.find("KHR_lights_punctual");
  if (ext != model.extensions.end() && ext->second.Has("lights") &&
      ext->second.Get("lights").IsArray())
    raw_lights = &ext->second.Get("lights");
  for (size_t i = 0; i < model.lights.size(); ++i) {
    const tinygltf::Light& light = model.lights[i];
    const std::string at = file + ": extensions.KHR_lights_punctual." + element("lights", i);
    if (light.type != "point" && light.type != "spot" && light.type != "directional")
      throw Error(at + ".type",
                  "unknown light type '" + light.type + "' (expected point, spot or directional)");
    if (!std::isfinite(light.intensity) || light.intensity < 0)
      throw Error(at + ".intensity",
                  std::to_string(light.intensity) + " must be a finite number ≥ 0");
    check_numbers(light.color, {3}, at + ".color");
    for (double c : light.color)
      if (c < 0) throw Error(at + ".color", "components must be ≥ 0");
    bool has_range = raw_lights && i < raw_lights->ArrayLen() &&
                     raw_lights->Get(int(i)).IsObject() && raw_lights->Get(int(i)).Has("range");
    if ((has_range || light.range != 0) && !(light.range > 0 && std::isfinite(light.range)))
      throw Error(at + ".range", std::to_string(light.range) + " must be > 0");
    if (light.type != "spot") continue;
    double inner = light.spot.innerConeAngle, outer = light.spot.outerConeAngle;
    const double quarter_turn = std::numbers::pi / 2;
    if (!(outer > 0 && outer <= quarter_turn))
      throw Error(at + ".spot.outerConeAngle",
                  std::to_string(outer) + " must be in (0, π/2] radians");
    if (!(inner >= 0 && inner < outer))
      throw Error(at + ".spot.innerConeAngle", std::to_string(inner) +
                                                   " must be ≥ 0 and less than outerConeAngle " +
                                                   std::to_string(outer));
  }
}

}  // namespace

const std::set<std::string>& supported_gltf_extensions() {
  static const std::set<std::string> names = {
      "EXT_mesh_gpu_instancing", "EXT_meshopt_compression", "KHR_draco_mesh_compression",
      "KHR_lights_punctual", "KHR_materials_clearcoat", "KHR_materials_emissive_strength",
      "KHR_materials_ior", "KHR_materials_sheen", "KHR_materials_specular",
      "KHR_materials_transmission", "KHR_materials_unlit", "KHR_materials_variants",
      "KHR_materials_volume",
      // Quantized attributes (integer POSITION, TEXCOORD,
      // NORMAL, TANGENT) are read like any other accessor.
      "KHR_mesh_quantization", "KHR_texture_transform",
      // Metadata (XMP licence and authoring records): nothing in them changes the picture.
      "KHR_xmp", "KHR_xmp_json_ld"};
  return names;
}

std::set<std::string> validate_gltf_model(const tinygltf::Model& model, const std::string& file,
                                          std::vector<std::string>& warnings) {
  check_version(model, file);
  std::set<std::string> unsupported = check_extensions(model, file, warnings);
  check_nodes(model, file);
  check_lights(model, file);
  return unsupported;
}

}  // namespace obscura
