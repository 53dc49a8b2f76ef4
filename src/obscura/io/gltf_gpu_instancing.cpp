#include "obscura/io/gltf_gpu_instancing.h"

#include <tiny_gltf.h>

#include <cmath>
#include <optional>

#include "obscura/io/gltf_accessor.h"
#include "obscura/io/gltf_animation.h"
#include "obscura/math/error.h"

namespace obscura {

std::vector<Matrix4> gpu_instance_transforms(const tinygltf::Node& node,
                                             GltfAccessorReader& accessors, const std::string& file,
                                             const std::string& where, size_t& budget) {
  auto found = node.extensions.find("EXT_mesh_gpu_instancing");
  if (found == node.extensions.end()) return {};
  const std::string at = where + ".extensions.EXT_mesh_gpu_instancing.attributes";
  if (!found->second.Has("attributes") || !found->second.Get("attributes").IsObject())
    throw Error(file + ": " + at, "expected an object of TRANSLATION, ROTATION and/or SCALE");
  const tinygltf::Value& attributes = found->second.Get("attributes");
  std::optional<uint64_t> count;
  // Reads one attribute, checking its count against the others' before decoding it.
  auto read = [&](const char* name, int components, AccessorNumbers numbers) {
    if (!attributes.Has(name)) return std::vector<float>{};
    const tinygltf::Value& index = attributes.Get(name);
    const std::string here = at + "." + name;
    if (!index.IsInt()) throw Error(file + ": " + here, "expected an accessor index");
    uint64_t n = accessors.count(index.GetNumberAsInt(), here);
    if (count && n != *count)
      throw Error(file + ": " + here, std::to_string(n) +
                                          " elements where the other attributes have " +
                                          std::to_string(*count));
    if (n > budget)
      throw Error(file + ": " + here, std::to_string(n) + " instances; a file may have at most " +
                                          std::to_string(kMaxGpuInstances) + " in all");
    count = n;
    std::vector<float> v = accessors.floats(index.GetNumberAsInt(), {components}, numbers, here);
    for (size_t i = 0; i < v.size(); ++i)
      if (!std::isfinite(v[i]))
        throw Error(file + ": " + here,
                    "instance " + std::to_string(i / size_t(components)) + " is not finite");
    return v;
  };
  // Quantized forms as KHR_mesh_quantization allows for the same roles of vertex attributes.
  std::vector<float> t = read("TRANSLATION", 3, AccessorNumbers::kFloatOrSmallInteger);
  std::vector<float> r = read("ROTATION", 4, AccessorNumbers::kFloatOrNormalized);
  std::vector<float> s = read("SCALE", 3, AccessorNumbers::kFloatOrSmallInteger);
  if (!count) throw Error(file + ": " + at, "names none of TRANSLATION, ROTATION and SCALE");
  budget -= size_t(*count);
  std::vector<Matrix4> copies(static_cast<size_t>(*count));
  for (size_t i = 0; i < copies.size(); ++i) {
    Vector3d translation, scale(1, 1, 1);
    Quaternion rotation;
    if (!t.empty()) translation = {t[3 * i], t[3 * i + 1], t[3 * i + 2]};
    if (!s.empty()) scale = {s[3 * i], s[3 * i + 1], s[3 * i + 2]};
    if (!r.empty()) {
      rotation = {r[4 * i], r[4 * i + 1], r[4 * i + 2], r[4 * i + 3]};
      double norm = std::sqrt(rotation.x * rotation.x + rotation.y * rotation.y +
                              rotation.z * rotation.z + rotation.w * rotation.w);
      if (!(norm > 0))
        throw Error(file + ": " + at + ".ROTATION",
                    "instance " + std::to_string(i) + " is not a unit quaternion");
      rotation = {rotation.x / norm, rotation.y / norm, rotation.z / norm, rotation.w / norm};
    }
    copies[i] = trs_matrix(translation, rotation, scale);
  }
  return copies;
}

}  // namespace obscura
