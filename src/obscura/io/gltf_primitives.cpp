// The glTF importer's primitives: triangles (strips and fans converted), their attributes read
// through the bounds-checked accessors, and primitives that share accessors sharing one Mesh.
#include <tiny_gltf.h>

#include "obscura/io/gltf_importer.h"
#include "obscura/io/gltf_material_extensions.h"

namespace obscura {

namespace {

// Triangle indices of a strip or fan, keeping counter-clockwise winding.
std::vector<uint32_t> triangulate(const std::vector<uint32_t>& v, int mode) {
  std::vector<uint32_t> out;
  for (size_t i = 2; i < v.size(); ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
      out.insert(out.end(), {v[0], v[i - 1], v[i]});
    else if (i % 2 == 0)
      out.insert(out.end(), {v[i - 2], v[i - 1], v[i]});
    else
      out.insert(out.end(), {v[i - 1], v[i - 2], v[i]});
  }
  return out;
}

}  // namespace

Mesh GltfImporter::import_primitive(const tinygltf::Primitive& p, const std::string& where,
                                    const std::string& name) {
  Mesh mesh;
  mesh.name = name;
  auto attribute = [&](const char* key) {
    auto it = p.attributes.find(key);
    return it == p.attributes.end() ? -1 : it->second;
  };
  int position = attribute("POSITION");
  if (position < 0) fail(where, "primitive has no POSITION attribute");
  std::vector<float> xyz = accessors_.floats(position, {3}, AccessorNumbers::kFloatOrSmallInteger,
                                             where + ".attributes.POSITION");
  mesh.positions.resize(xyz.size() / 3);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    mesh.positions[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
    if (!std::isfinite(xyz[3 * i]) || !std::isfinite(xyz[3 * i + 1]) ||
        !std::isfinite(xyz[3 * i + 2]))
      fail(where + ".attributes.POSITION",
           "vertex " + std::to_string(i) + " is not finite (NaN or infinity)");
  }
  xyz = {};
  size_t n = mesh.positions.size();
  // Every other attribute has one element per position; checked before it is read.
  auto read = [&](const char* key, std::initializer_list<int> components, AccessorNumbers numbers,
                  int* got_components = nullptr) {
    std::string at = where + ".attributes." + key;
    int a = attribute(key);
    if (a < 0) return std::vector<float>{};
    if (uint64_t count = accessors_.count(a, at); count != n)
      fail(at, std::to_string(count) + " elements for " + std::to_string(n) + " positions");
    if (got_components) *got_components = accessors_.components(a, at);
    return accessors_.floats(a, components, numbers, at);
  };
  std::vector<float> v = read("NORMAL", {3}, AccessorNumbers::kFloatOrNormalized);
  for (size_t i = 0; i < v.size() / 3; ++i)
    mesh.normals.emplace_back(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
  v = read("TEXCOORD_0", {2}, AccessorNumbers::kFloatOrSmallInteger);
  for (size_t i = 0; i < v.size() / 2; ++i) mesh.uvs.emplace_back(v[2 * i], v[2 * i + 1]);
  v = read("TEXCOORD_1", {2}, AccessorNumbers::kFloatOrSmallInteger);
  for (size_t i = 0; i < v.size() / 2; ++i) mesh.uvs1.emplace_back(v[2 * i], v[2 * i + 1]);
  v = read("TANGENT", {4}, AccessorNumbers::kFloatOrNormalized);
  for (size_t i = 0; i < v.size() / 4; ++i) {
    // w is the handedness, ±1; a file's 0 or rounding is read by its sign.
    mesh.tangents.emplace_back(v[4 * i], v[4 * i + 1], v[4 * i + 2], v[4 * i + 3] < 0 ? -1 : 1);
    if (!std::isfinite(v[4 * i]) || !std::isfinite(v[4 * i + 1]) || !std::isfinite(v[4 * i + 2])) {
      scene_.warnings.push_back(file_ + ": " + where + ".attributes.TANGENT: vertex " +
                                std::to_string(i) +
                                " is not finite (NaN or infinity); tangents are generated instead");
      mesh.tangents = {};
      break;
    }
  }
  int c = 0;
  v = read("COLOR_0", {3, 4}, AccessorNumbers::kFloatOrNormalized, &c);
  for (size_t i = 0; c > 0 && i < v.size() / size_t(c); ++i)
    mesh.colors.emplace_back(v[c * i], v[c * i + 1], v[c * i + 2]);
  // RGBA colours: their alpha multiplies the material's coverage. Kept only where some vertex is
  // not fully opaque, so that opaque RGBA colours cost the renderers nothing.
  bool translucent = false;
  for (size_t i = 0; c == 4 && i < v.size() / 4; ++i) translucent |= v[4 * i + 3] < 1;
  if (translucent)
    for (size_t i = 0; i < v.size() / 4; ++i) mesh.color_alphas.push_back(v[4 * i + 3]);
  v = {};
  std::vector<uint32_t> indices;
  if (p.indices >= 0) {
    indices = accessors_.indices(p.indices, n, where + ".indices");
  } else {
    indices.resize(n);
    for (size_t i = 0; i < n; ++i) indices[i] = uint32_t(i);
  }
  if (p.mode == TINYGLTF_MODE_TRIANGLES) {
    indices.resize(indices.size() / 3 * 3);
    mesh.indices = std::move(indices);
  } else {
    mesh.indices = triangulate(indices, p.mode);
  }
  if (p.material >= 0 && size_t(p.material) >= model_.materials.size())
    fail(where + ".material", "material index " + std::to_string(p.material) + " is out of range");
  mesh.material = p.material >= 0 ? uint32_t(p.material) : default_material();
  return mesh;
}

std::vector<GltfImporter::PrimitiveMesh> GltfImporter::import_mesh(int mesh_index) {
  auto found = meshes_.find(mesh_index);
  if (found != meshes_.end()) return found->second;
  const tinygltf::Mesh& gm = model_.meshes[mesh_index];
  std::vector<PrimitiveMesh>& ours = meshes_[mesh_index];
  for (size_t j = 0; j < gm.primitives.size(); ++j) {
    const tinygltf::Primitive& p = gm.primitives[j];
    std::string where = element("meshes", mesh_index) + "." + element("primitives", j);
    if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        p.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      scene_.warnings.push_back(file_ + ": " + where +
                                ": points and lines are not rendered; primitive skipped");
      continue;
    }
    std::string name = gm.name.empty() ? element("meshes", mesh_index) : gm.name;
    if (gm.primitives.size() > 1) name.append("/").append(std::to_string(j));
    std::string key = std::to_string(p.mode) + " " + std::to_string(p.indices);
    for (const auto& [attribute, accessor] : p.attributes)
      key += " " + attribute + "=" + std::to_string(accessor);
    auto shared = geometry_.find(key);
    if (shared == geometry_.end()) {
      shared = geometry_.emplace(key, uint32_t(scene_.meshes.size())).first;
      scene_.meshes.push_back(import_primitive(p, where, name));
    }
    if (p.material >= 0 && size_t(p.material) >= model_.materials.size())
      fail(where + ".material",
           "material index " + std::to_string(p.material) + " is out of range");
    ours.push_back(
        {shared->second, p.material >= 0 ? uint32_t(p.material) : default_material(), j});
    auto variants = p.extensions.find("KHR_materials_variants");
    if (variants != p.extensions.end())
      variant_materials_[{ours.back().mesh, ours.back().material}] = read_gltf_variant_mappings(
          variants->second, scene_.material_variants.size(), model_.materials.size(), file_, where);
  }
  return ours;
}

}  // namespace obscura
