// The glTF material extensions that change the surface model, read into the metallic-roughness
// material: KHR_materials_unlit, KHR_materials_transmission, KHR_materials_volume,
// KHR_materials_clearcoat and KHR_materials_sheen. Every
// number is checked against the range its specification allows; a bad one is an obscura::Error
// naming the file, material and field.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "obscura/scene/material.h"

namespace tinygltf {
class Value;
}

namespace obscura {

// Resolves a textureInfo object (index, texCoord, extensions) found inside an extension.
using GltfTextureInfoReader = std::function<TextureRef(
    const tinygltf::Value& texture_info, TextureEncoding encoding, const std::string& where)>;

// Reads extension `name` with object `value` into `material` and returns true, or returns false
// when `name` is not one of the extensions above. `where` names the material ("materials[3]").
bool read_gltf_material_extension(const std::string& name, const tinygltf::Value& value,
                                  const std::string& file, const std::string& where,
                                  const GltfTextureInfoReader& texture,
                                  MetallicRoughnessMaterial& material);

// KHR_materials_variants at the file's root: the variant names, in order (empty without it).
std::vector<std::string> read_gltf_material_variants(const tinygltf::Value* root_extension,
                                                     const std::string& file);

// A primitive's KHR_materials_variants mappings as (variant, material) pairs, checked against
// the numbers of variants and materials; `where` names the primitive.
std::vector<std::pair<uint32_t, uint32_t>> read_gltf_variant_mappings(
    const tinygltf::Value& primitive_extension, size_t variant_count, size_t material_count,
    const std::string& file, const std::string& where);

}  // namespace obscura
