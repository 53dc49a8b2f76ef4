#include "obscura/io/gltf_material_extensions.h"

#include <tiny_gltf.h>

#include <cmath>
#include <limits>

#include "obscura/math/error.h"

namespace obscura {

namespace {

class ExtensionReader {
 public:
  ExtensionReader(const tinygltf::Value& value, const std::string& file, std::string where)
      : value_(value), file_(file), where_(std::move(where)) {
    if (!value_.IsObject()) throw Error(file_ + ": " + where_, "expected a JSON object");
  }

  // The number under `key`, or `fallback` where there is none; it must lie in [lo, hi].
  float number(const char* key, float fallback, float lo, float hi) const {
    if (!value_.Has(key)) return fallback;
    const tinygltf::Value& v = value_.Get(key);
    double x = v.IsNumber() ? v.GetNumberAsDouble() : std::nan("");
    if (!(x >= lo && x <= hi))
      throw Error(file_ + ": " + where_ + "." + key, std::string("expected a number in [")
                                                         .append(text(lo))
                                                         .append(", ")
                                                         .append(text(hi))
                                                         .append("]"));
    return float(x);
  }
  // The RGB array under `key`, each component in [0, 1].
  Rgb color(const char* key, Rgb fallback) const {
    if (!value_.Has(key)) return fallback;
    const tinygltf::Value& v = value_.Get(key);
    Rgb c;
    bool ok = v.IsArray() && v.ArrayLen() == 3;
    for (int i = 0; ok && i < 3; ++i) {
      double x = v.Get(i).IsNumber() ? v.Get(i).GetNumberAsDouble() : std::nan("");
      ok = x >= 0 && x <= 1;
      c[i] = float(x);
    }
    if (!ok) throw Error(file_ + ": " + where_ + "." + key, "expected 3 numbers in [0, 1]");
    return c;
  }
  TextureRef texture(const char* key, TextureEncoding encoding,
                     const GltfTextureInfoReader& read) const {
    if (!value_.Has(key)) return {};
    const tinygltf::Value& info = value_.Get(key);
    std::string at = where_ + "." + key;
    if (!info.IsObject()) throw Error(file_ + ": " + at, "expected a textureInfo object");
    return read(info, encoding, at);
  }

 private:
  static std::string text(float x) {
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    std::string s = std::to_string(x);
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    return s;
  }

  const tinygltf::Value& value_;
  const std::string& file_;
  std::string where_;
};

constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr float kLargest = std::numeric_limits<float>::max();

}  // namespace

bool read_gltf_material_extension(const std::string& name, const tinygltf::Value& value,
                                  const std::string& file, const std::string& where,
                                  const GltfTextureInfoReader& texture,
                                  MetallicRoughnessMaterial& material) {
  ExtensionReader read(value, file, where + ".extensions." + name);
  if (name == "KHR_materials_unlit") {
    material.unlit = true;  // the extension has no properties
  } else if (name == "KHR_materials_transmission") {
    material.transmission = read.number("transmissionFactor", 0, 0, 1);
    material.transmission_texture =
        read.texture("transmissionTexture", TextureEncoding::kLinear, texture);
  } else if (name == "KHR_materials_volume") {
    material.thickness = read.number("thicknessFactor", 0, 0, kLargest);
    // The thickness texture only tells a rasterizer how far light travels inside; a tracer
    // measures the distance, so it is read for validation and otherwise unused.
    read.texture("thicknessTexture", TextureEncoding::kLinear, texture);
    // The spec allows any positive distance; +infinity is its default (no absorption).
    material.attenuation_distance =
        read.number("attenuationDistance", kInfinity, std::numeric_limits<float>::min(), kInfinity);
    material.attenuation_color = read.color("attenuationColor", Rgb(1.f));
  } else if (name == "KHR_materials_clearcoat") {
    material.clearcoat = read.number("clearcoatFactor", 0, 0, 1);
    material.clearcoat_texture =
        read.texture("clearcoatTexture", TextureEncoding::kLinear, texture);
    material.clearcoat_roughness = read.number("clearcoatRoughnessFactor", 0, 0, 1);
    material.clearcoat_roughness_texture =
        read.texture("clearcoatRoughnessTexture", TextureEncoding::kLinear, texture);
    material.clearcoat_normal_texture =
        read.texture("clearcoatNormalTexture", TextureEncoding::kLinear, texture);
    if (material.clearcoat_normal_texture.valid())  // a normalTextureInfo: it has a scale
      material.clearcoat_normal_scale =
          ExtensionReader(value.Get("clearcoatNormalTexture"), file,
                          where + ".extensions." + name + ".clearcoatNormalTexture")
              .number("scale", 1, -kLargest, kLargest);
  } else if (name == "KHR_materials_sheen") {
    material.sheen_color = read.color("sheenColorFactor", Rgb(0.f));
    material.sheen_color_texture =
        read.texture("sheenColorTexture", TextureEncoding::kSrgb, texture);
    material.sheen_roughness = read.number("sheenRoughnessFactor", 0, 0, 1);
    material.sheen_roughness_texture =
        read.texture("sheenRoughnessTexture", TextureEncoding::kLinear, texture);
  } else {
    return false;
  }
  return true;
}

std::vector<std::string> read_gltf_material_variants(const tinygltf::Value* root_extension,
                                                     const std::string& file) {
  if (!root_extension) return {};
  const std::string where = file + ": extensions.KHR_materials_variants.variants";
  if (!root_extension->IsObject() || !root_extension->Has("variants") ||
      !root_extension->Get("variants").IsArray())
    throw Error(where, "expected an array of variants");
  const tinygltf::Value& variants = root_extension->Get("variants");
  std::vector<std::string> names;
  for (int i = 0; i < int(variants.ArrayLen()); ++i) {
    const tinygltf::Value& v = variants.Get(i);
    if (!v.IsObject() || !v.Has("name") || !v.Get("name").IsString())
      throw Error(std::string(where).append("[").append(std::to_string(i)).append("].name"),
                  "expected a string");
    names.push_back(v.Get("name").Get<std::string>());
  }
  return names;
}

std::vector<std::pair<uint32_t, uint32_t>> read_gltf_variant_mappings(
    const tinygltf::Value& primitive_extension, size_t variant_count, size_t material_count,
    const std::string& file, const std::string& where) {
  const std::string at = file + ": " + where + ".extensions.KHR_materials_variants.mappings";
  if (!primitive_extension.IsObject() || !primitive_extension.Has("mappings") ||
      !primitive_extension.Get("mappings").IsArray())
    throw Error(at, "expected an array of mappings");
  const tinygltf::Value& mappings = primitive_extension.Get("mappings");
  auto index = [&](const tinygltf::Value& v, size_t count, const std::string& field) {
    if (!v.IsInt() || v.GetNumberAsInt() < 0 || size_t(v.GetNumberAsInt()) >= count)
      throw Error(at + field, "expected an index below " + std::to_string(count));
    return uint32_t(v.GetNumberAsInt());
  };
  std::vector<std::pair<uint32_t, uint32_t>> pairs;
  for (int i = 0; i < int(mappings.ArrayLen()); ++i) {
    const tinygltf::Value& m = mappings.Get(i);
    const std::string element = std::string("[").append(std::to_string(i)).append("]");
    if (!m.IsObject() || !m.Has("material") || !m.Has("variants") || !m.Get("variants").IsArray())
      throw Error(at + element, "expected an object with material and variants");
    uint32_t material = index(m.Get("material"), material_count, element + ".material");
    const tinygltf::Value& variants = m.Get("variants");
    for (int j = 0; j < int(variants.ArrayLen()); ++j)
      pairs.emplace_back(
          index(variants.Get(j), variant_count,
                std::string(element).append(".variants[").append(std::to_string(j)).append("]")),
          material);
  }
  return pairs;
}

}  // namespace obscura
