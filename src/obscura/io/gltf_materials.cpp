// The glTF importer's materials: the core metallic-roughness model and its textures, samplers and
// KHR_texture_transform, with the material extensions read by gltf_material_extensions.h.
#include <tiny_gltf.h>

#include <cmath>

#include "obscura/io/gltf_importer.h"
#include "obscura/io/gltf_material_extensions.h"
#include "obscura/io/gltf_missing_image.h"

namespace obscura {

namespace {

TextureWrap wrap(int gl) {
  if (gl == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return TextureWrap::kClampToEdge;
  if (gl == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return TextureWrap::kMirroredRepeat;
  return TextureWrap::kRepeat;
}

TextureFilter filter(int min_filter, int mag_filter) {
  if (min_filter == TINYGLTF_TEXTURE_FILTER_NEAREST ||
      (min_filter == -1 && mag_filter == TINYGLTF_TEXTURE_FILTER_NEAREST))
    return TextureFilter::kNearest;
  if (min_filter == TINYGLTF_TEXTURE_FILTER_LINEAR) return TextureFilter::kBilinear;
  return TextureFilter::kTrilinear;  // mipmapped or unspecified: the renderer chooses
}

}  // namespace

TextureRef GltfImporter::texture(int texture_index, int uv_set, TextureEncoding encoding,
                                 const std::string& where, bool placeholder_if_missing) {
  if (texture_index < 0) return {};
  if (size_t(texture_index) >= model_.textures.size())
    fail(where, "texture index " + std::to_string(texture_index) + " is out of range");
  auto key = std::make_pair(texture_index, encoding);
  auto found = textures_.find(key);
  if (found != textures_.end()) return {found->second, uint32_t(std::max(uv_set, 0)), {}};
  const tinygltf::Texture& gt = model_.textures[texture_index];
  if (gt.source < 0 || size_t(gt.source) >= model_.images.size())
    fail(element("textures", texture_index),
         "image index " + std::to_string(gt.source) + " is out of range");
  auto image = images_.decoded.find(gt.source);
  if (image == images_.decoded.end()) {  // warned about once, at load
    if (!placeholder_if_missing) return {};
    if (placeholder_texture_ < 0) {
      placeholder_texture_ = int32_t(scene_.textures.size());
      scene_.textures.push_back(missing_image_placeholder());
    }
    return {placeholder_texture_, uint32_t(std::max(uv_set, 0)), {}};
  }
  Texture t = image->second;  // a copy: one glTF image may be used with two encodings
  t.name = !gt.name.empty() ? gt.name : model_.images[gt.source].name;
  if (t.name.empty()) t.name = model_.images[gt.source].uri;
  if (t.name.empty() || t.name.rfind("data:", 0) == 0) t.name = element("images", gt.source);
  t.encoding = encoding;
  if (gt.sampler >= 0 && size_t(gt.sampler) < model_.samplers.size()) {
    const tinygltf::Sampler& s = model_.samplers[gt.sampler];
    t.wrap_u = wrap(s.wrapS);
    t.wrap_v = wrap(s.wrapT);
    t.filter = filter(s.minFilter, s.magFilter);
  }
  auto index = int32_t(scene_.textures.size());
  scene_.textures.push_back(std::move(t));
  textures_[key] = index;
  return {index, uint32_t(std::max(uv_set, 0)), {}};
}

TextureRef GltfImporter::texture(const tinygltf::Value& info, TextureEncoding encoding,
                                 const std::string& where) {
  tinygltf::TextureInfo ti;
  if (!info.Has("index") || !info.Get("index").IsInt())
    fail(where + ".index", "expected a texture index");
  ti.index = info.Get("index").GetNumberAsInt();
  if (info.Has("texCoord")) {
    const tinygltf::Value& set = info.Get("texCoord");
    if (!set.IsInt() || set.GetNumberAsInt() < 0)
      fail(where + ".texCoord", "expected a non-negative integer");
    ti.texCoord = set.GetNumberAsInt();
  }
  if (info.Has("extensions") && info.Get("extensions").IsObject()) {
    const tinygltf::Value& extensions = info.Get("extensions");
    for (const std::string& key : extensions.Keys()) ti.extensions[key] = extensions.Get(key);
  }
  return texture(ti, encoding, where);
}

UvTransform GltfImporter::uv_transform(const tinygltf::Value& value,
                                       const std::string& where) const {
  // KHR_texture_transform: offset [0, 0], rotation 0 (radians), scale [1, 1].
  auto pair = [&](const char* key, Point2f fallback) {
    if (!value.Has(key)) return fallback;
    const tinygltf::Value& v = value.Get(key);
    if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
      fail(where + "." + key, "expected an array of 2 numbers");
    Point2f p(float(v.Get(0).GetNumberAsDouble()), float(v.Get(1).GetNumberAsDouble()));
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail(where + "." + key, "must be finite");
    return p;
  };
  float rotation = 0;
  if (value.Has("rotation")) {
    const tinygltf::Value& r = value.Get("rotation");
    if (!r.IsNumber() || !std::isfinite(r.GetNumberAsDouble()))
      fail(where + ".rotation", "expected a finite number (radians)");
    rotation = float(r.GetNumberAsDouble());
  }
  return UvTransform::offset_rotation_scale(pair("offset", {0, 0}), rotation,
                                            pair("scale", {1, 1}));
}

void GltfImporter::import_materials() {
  for (size_t i = 0; i < model_.materials.size(); ++i) {
    const tinygltf::Material& gm = model_.materials[i];
    std::string where = element("materials", i);
    const tinygltf::PbrMetallicRoughness& pbr = gm.pbrMetallicRoughness;
    MetallicRoughnessMaterial mr;
    mr.base_color = rgb(pbr.baseColorFactor, Rgb(1.f));
    mr.alpha = pbr.baseColorFactor.size() == 4 ? float(pbr.baseColorFactor[3]) : 1.f;
    mr.base_color_texture =
        texture(pbr.baseColorTexture, TextureEncoding::kSrgb, where + ".baseColorTexture",
                /*placeholder_if_missing=*/true);
    mr.metallic = float(pbr.metallicFactor);
    mr.roughness = float(pbr.roughnessFactor);
    mr.metallic_roughness_texture = texture(pbr.metallicRoughnessTexture, TextureEncoding::kLinear,
                                            where + ".metallicRoughnessTexture");
    mr.occlusion_texture =
        texture(gm.occlusionTexture, TextureEncoding::kLinear, where + ".occlusionTexture");
    float emissive_strength = 1;
    for (const auto& [name, value] : gm.extensions) {
      if (name == "KHR_materials_emissive_strength") {
        emissive_strength = float(number(value, "emissiveStrength", 1));
      } else if (name == "KHR_materials_specular") {
        mr.specular = float(number(value, "specularFactor", 1));
        if (value.Has("specularColorFactor") && value.Get("specularColorFactor").IsArray() &&
            value.Get("specularColorFactor").ArrayLen() == 3) {
          const tinygltf::Value& c = value.Get("specularColorFactor");
          mr.specular_color =
              Rgb(float(c.Get(0).GetNumberAsDouble()), float(c.Get(1).GetNumberAsDouble()),
                  float(c.Get(2).GetNumberAsDouble()));
        }
        const std::string at = where + ".extensions.KHR_materials_specular.";
        if (value.Has("specularTexture"))
          mr.specular_texture = texture(value.Get("specularTexture"), TextureEncoding::kLinear,
                                        at + "specularTexture");
        if (value.Has("specularColorTexture"))
          mr.specular_color_texture = texture(value.Get("specularColorTexture"),
                                              TextureEncoding::kSrgb, at + "specularColorTexture");
      } else if (name == "KHR_materials_ior") {
        mr.ior = float(number(value, "ior", 1.5));
      } else if (read_gltf_material_extension(
                     name, value, file_, where,
                     [this](const tinygltf::Value& info, TextureEncoding encoding,
                            const std::string& at) { return texture(info, encoding, at); },
                     mr)) {
      } else if (ignored_extensions_.insert(name).second) {
        scene_.warnings.push_back(file_ + ": " + where + ": extension " + name +
                                  " is not supported; it is ignored");
      }
    }
    Material m;
    m.name = gm.name.empty() ? where : gm.name;
    m.model = mr;
    m.emission = rgb(gm.emissiveFactor, Rgb()) * emissive_strength;
    m.emission_texture =
        texture(gm.emissiveTexture, TextureEncoding::kSrgb, where + ".emissiveTexture");
    m.normal_texture =
        texture(gm.normalTexture, TextureEncoding::kLinear, where + ".normalTexture");
    m.normal_scale = float(gm.normalTexture.scale);
    m.double_sided = gm.doubleSided;
    if (mr.unlit) {  // KHR_materials_unlit: only the base colour (and its alpha) counts
      m.emission = {};
      m.emission_texture = {};
      m.normal_texture = {};
    }
    if (gm.alphaMode == "MASK") {
      m.alpha_mode = AlphaMode::kMask;
      if (!std::isfinite(gm.alphaCutoff) || gm.alphaCutoff < 0)
        fail(where + ".alphaCutoff",
             std::to_string(gm.alphaCutoff) + " must be a finite number ≥ 0");
      m.alpha_cutoff = float(gm.alphaCutoff);
    } else if (gm.alphaMode == "BLEND") {
      m.alpha_mode = AlphaMode::kBlend;
    } else if (gm.alphaMode != "OPAQUE" && !gm.alphaMode.empty()) {
      fail(where + ".alphaMode", "'" + gm.alphaMode + "' is not OPAQUE, MASK or BLEND");
    }
    scene_.materials.push_back(std::move(m));
  }
}

uint32_t GltfImporter::default_material() {
  // glTF's default material: white, fully metallic and rough.
  if (default_material_ < 0) {
    default_material_ = int(scene_.materials.size());
    Material m;
    m.name = "default";
    m.model = MetallicRoughnessMaterial{};
    scene_.materials.push_back(m);
  }
  return uint32_t(default_material_);
}

}  // namespace obscura
