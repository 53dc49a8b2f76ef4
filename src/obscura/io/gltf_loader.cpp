#include "obscura/io/gltf_loader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>

#include "obscura/io/camera_mapping.h"
#include "obscura/io/gltf_accessor.h"
#include "obscura/io/gltf_animation.h"
#include "obscura/io/gltf_compression_prepass.h"
#include "obscura/io/gltf_decompressed_buffers.h"
#include "obscura/io/gltf_deformation.h"
#include "obscura/io/gltf_draco.h"
#include "obscura/io/gltf_feature_warnings.h"
#include "obscura/io/gltf_gpu_instancing.h"
#include "obscura/io/gltf_material_extensions.h"
#include "obscura/io/gltf_meshopt.h"
#include "obscura/io/gltf_missing_image.h"
#include "obscura/io/gltf_scene_choice.h"
#include "obscura/io/gltf_validation.h"
#include "obscura/io/input_file.h"
#include "obscura/io/texture_loader.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

std::string element(const char* array, size_t index) {
  return std::string(array) + "[" + std::to_string(index) + "]";
}

// Decoded images, filled by tinygltf's image callback (which we route to OpenImageIO). An image
// that cannot be read is a warning, not an error: its material renders with the factor alone.
struct ImageStore {
  std::string file;
  const tinygltf::Model* model = nullptr;  // filled by tinygltf while it parses
  std::map<int, Texture> decoded;          // by glTF image index
  std::map<int, std::string> failed;       // by glTF image index: why it could not be decoded
};

bool decode_image(tinygltf::Image* image, const int image_index, std::string*, std::string*, int,
                  int, const unsigned char* bytes, int size, void* user) {
  auto* store = static_cast<ImageStore*>(user);
  std::string source = store->file + ": " + element("images", size_t(image_index));
  if (!image->uri.empty() && image->uri.rfind("data:", 0) != 0) source = image->uri;
  // tinygltf hands over a bufferView's bytes without checking that the view lies inside its
  // buffer: check it here, before reading them.
  if (image->bufferView >= 0) {
    const tinygltf::Model& model = *store->model;
    bool inside = false;
    if (size_t(image->bufferView) < model.bufferViews.size()) {
      const tinygltf::BufferView& view = model.bufferViews[size_t(image->bufferView)];
      uint64_t end = 0;
      inside =
          view.buffer >= 0 && size_t(view.buffer) < model.buffers.size() &&
          !__builtin_add_overflow(uint64_t(view.byteOffset), uint64_t(view.byteLength), &end) &&
          end <= model.buffers[size_t(view.buffer)].data.size() &&
          view.byteLength <= size_t(std::numeric_limits<int>::max());
    }
    if (!inside) {
      store->failed[image_index] =
          "bufferView " + std::to_string(image->bufferView) + " runs past the end of its buffer";
      return true;
    }
  }
  try {
    std::string hint = image->mimeType;
    if (hint.empty() && !image->uri.empty()) {
      hint = std::filesystem::path(image->uri).extension().string();
      if (!hint.empty()) hint = hint.substr(1);
    }
    store->decoded[image_index] =
        decode_texture(std::span<const uint8_t>(bytes, size_t(std::max(size, 0))), source, hint,
                       TextureEncoding::kSrgb);
  } catch (const Error& e) {
    store->failed[image_index] = e.what();
    return true;
  }
  // tinygltf wants the image described; keep no pixels in its copy.
  image->width = store->decoded[image_index].width;
  image->height = store->decoded[image_index].height;
  image->component = store->decoded[image_index].channels;
  return true;
}

// Everything the loader builds while walking the file.
class GltfImporter {
 public:
  GltfImporter(const tinygltf::Model& model, std::string file, ImageStore& images,
               std::vector<std::string> warnings, std::set<std::string> ignored_extensions,
               GltfLoadOptions options)
      : model_(model),
        file_(std::move(file)),
        images_(images),
        accessors_(model_, file_),
        ignored_extensions_(std::move(ignored_extensions)),
        options_(std::move(options)) {
    scene_.warnings = std::move(warnings);
  }

  Scene import();

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& message) const {
    throw Error(file_ + ": " + where, message);
  }
  // An image that cannot be used gives no texture (the material's factor alone), or with
  // `placeholder_if_missing` (base colour) the visible missing-image checker.
  TextureRef texture(int texture_index, int uv_set, TextureEncoding encoding,
                     const std::string& where, bool placeholder_if_missing = false);
  // The texture with the textureInfo's KHR_texture_transform, when it has one.
  template <class Info>
  TextureRef texture(const Info& info, TextureEncoding encoding, const std::string& where,
                     bool placeholder_if_missing = false) {
    TextureRef ref = texture(info.index, info.texCoord, encoding, where, placeholder_if_missing);
    auto found = info.extensions.find("KHR_texture_transform");
    if (found == info.extensions.end() || !ref.valid()) return ref;
    const std::string ext_where = where + ".extensions.KHR_texture_transform";
    ref.transform = uv_transform(found->second, ext_where);
    // The extension may also name the UV set, overriding the textureInfo's own texCoord.
    if (found->second.Has("texCoord")) {
      const tinygltf::Value& set = found->second.Get("texCoord");
      if (!set.IsInt() || set.GetNumberAsInt() < 0)
        fail(ext_where + ".texCoord", "expected a non-negative integer");
      ref.uv_set = uint32_t(set.GetNumberAsInt());
    }
    return ref;
  }
  // A textureInfo given as a JSON value (inside a material extension).
  TextureRef texture(const tinygltf::Value& info, TextureEncoding encoding,
                     const std::string& where);
  UvTransform uv_transform(const tinygltf::Value& value, const std::string& where) const;
  void import_materials();
  uint32_t default_material();
  // One glTF primitive as our mesh, with the material it is drawn with.
  struct PrimitiveMesh {
    uint32_t mesh = 0, material = 0;
    size_t primitive = 0;  // index in the glTF mesh's primitives
  };
  std::vector<PrimitiveMesh> import_mesh(int mesh_index);
  void add_mesh_instances(int node_index, const Matrix4& world_from_node,
                          const Transform& world_from_object);
  Mesh import_primitive(const tinygltf::Primitive& primitive, const std::string& where,
                        const std::string& name);
  void import_light(int light_index, const Transform& world_from_light, const std::string& where);
  void visit_node(int node_index, const Matrix4& world_from_parent, int depth);

  const tinygltf::Model& model_;
  std::string file_;
  ImageStore& images_;
  GltfAccessorReader accessors_;
  Scene scene_;
  std::map<std::pair<int, TextureEncoding>, int32_t> textures_;  // (glTF texture, encoding) → ours
  // Per glTF mesh, its primitives as our meshes.
  std::map<int, std::vector<PrimitiveMesh>> meshes_;
  // Primitives that read the same accessors share one Mesh (instancing across glTF meshes).
  std::map<std::string, uint32_t> geometry_;
  int default_material_ = -1;
  int32_t placeholder_texture_ = -1;  // the missing-image checker, added on first use
  NodeAnimations animations_;
  std::set<std::string> ignored_extensions_;  // warned about already
  // KHR_materials_variants: per (our mesh, default material), its (variant, material) pairs.
  std::map<std::pair<uint32_t, uint32_t>, std::vector<std::pair<uint32_t, uint32_t>>>
      variant_materials_;
  GltfLoadOptions options_;
  std::optional<GltfDeformer> deformer_;
  size_t gpu_instance_budget_ = kMaxGpuInstances;
  size_t placed_copies_ = 0;
  size_t posed_vertices_ = 0;
};

double number(const tinygltf::Value& v, const char* key, double fallback) {
  if (!v.Has(key) || !v.Get(key).IsNumber()) return fallback;
  return v.Get(key).GetNumberAsDouble();
}

Rgb rgb(const std::vector<double>& v, Rgb fallback) {
  if (v.size() < 3) return fallback;
  return {float(v[0]), float(v[1]), float(v[2])};
}

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
    if (gm.primitives.size() > 1) name += "/" + std::to_string(j);
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

void GltfImporter::import_light(int light_index, const Transform& world_from_light,
                                const std::string& where) {
  if (light_index < 0 || size_t(light_index) >= model_.lights.size())
    fail(where,
         "KHR_lights_punctual light index " + std::to_string(light_index) + " is out of range");
  const tinygltf::Light& gl = model_.lights[light_index];
  Rgb color = rgb(gl.color, Rgb(1.f)) * float(gl.intensity);
  Point3f position = world_from_light(Point3f(0, 0, 0));
  Vector3f direction = normalize(world_from_light(Vector3f(0, 0, -1)));  // lights point down −Z
  Light light;
  light.name = gl.name.empty() ? element("lights", light_index) : gl.name;
  if (gl.type == "point") {
    light.model = PointLight{position, color};
  } else if (gl.type == "spot") {
    light.model = SpotLight{position, direction, color, float(gl.spot.innerConeAngle),
                            float(gl.spot.outerConeAngle)};
  } else if (gl.type == "directional") {
    light.model = DirectionalLight{direction, color};
  } else {
    fail(element("lights", light_index), "unknown light type '" + gl.type + "'");
  }
  scene_.lights.push_back(std::move(light));
}

void GltfImporter::add_mesh_instances(int node_index, const Matrix4& world_from_node,
                                      const Transform& world_from_object) {
  const tinygltf::Node& node = model_.nodes[size_t(node_index)];
  const std::string where = element("nodes", node_index);
  std::vector<TransformKey> motion = animations_.world_keys(node_index);
  // A skinned mesh is posed by its joints alone: the node's own motion cancels out.
  const bool skinned = node.skin >= 0;
  if (skinned) motion.clear();
  std::vector<Matrix4> copies =
      gpu_instance_transforms(node, accessors_, file_, where, gpu_instance_budget_);
  const bool instanced = !copies.empty();
  if (!instanced) copies.push_back(Matrix4::identity());
  const bool deformed = deformer_->deforms(node_index);
  const std::vector<PrimitiveMesh> primitives = import_mesh(node.mesh);
  // Copies × primitives instances, against the same bound as the copies alone.
  if (instanced && copies.size() * primitives.size() > kMaxGpuInstances - placed_copies_)
    fail(where + ".extensions.EXT_mesh_gpu_instancing",
         std::to_string(copies.size()) + " copies of " + std::to_string(primitives.size()) +
             " primitives; a file may place at most " + std::to_string(kMaxGpuInstances) +
             " instanced copies in all");
  if (instanced) placed_copies_ += copies.size() * primitives.size();
  for (const PrimitiveMesh& p : primitives) {
    uint32_t mesh = p.mesh;
    if (deformed) {  // a shape of its own, for this node at the pose time
      std::string at = element("meshes", node.mesh) + "." + element("primitives", p.primitive);
      const Mesh& base = scene_.meshes[p.mesh];
      // Each posed node holds its own copy (and poses across the shutter): bounded in all.
      posed_vertices_ += base.positions.size() * size_t(1 + kDeformationSteps);
      if (posed_vertices_ > kMaxPosedVertices)
        fail(where, "skinned or morphed meshes need more than " +
                        std::to_string(kMaxPosedVertices) + " posed vertices in all");
      Mesh posed =
          deformer_->deform(base, node_index, p.primitive, world_from_node, at, options_.time_s);
      if (options_.exposure_s > 0 && deformer_->animated(node_index))
        posed.deformation = deformer_->deformation(base, node_index, p.primitive, world_from_node,
                                                   at, options_.time_s - options_.exposure_s / 2,
                                                   options_.time_s + options_.exposure_s / 2);
      posed.name.append(" (").append(node.name.empty() ? where : node.name).append(")");
      mesh = uint32_t(scene_.meshes.size());
      scene_.meshes.push_back(std::move(posed));
    }
    for (size_t c = 0; c < copies.size(); ++c) {
      std::optional<Transform> object_from_copy = invertible(copies[c]);
      if (!object_from_copy) continue;  // a copy scaled to zero draws nothing
      Instance instance;
      instance.name = node.name.empty() ? where : node.name;
      if (instanced) instance.name.append("#").append(std::to_string(c));
      instance.mesh = mesh;
      instance.material = int32_t(p.material);
      // Keyed by the file's primitive: a posed copy of it takes the same variants.
      auto variants = variant_materials_.find({p.mesh, p.material});
      if (variants != variant_materials_.end()) instance.variant_materials = variants->second;
      instance.world_from_object = world_from_object * *object_from_copy;
      for (const TransformKey& key : motion)
        instance.motion.push_back({key.time_seconds, key.world_from_object * *object_from_copy});
      if (!instance.motion.empty())
        instance.world_from_object = instance.motion.front().world_from_object;
      scene_.instances.push_back(std::move(instance));
    }
  }
}

void GltfImporter::visit_node(int node_index, const Matrix4& world_from_parent, int depth) {
  std::string where = element("nodes", node_index);
  if (node_index < 0 || size_t(node_index) >= model_.nodes.size())
    fail(where, "node index is out of range");
  if (depth > 256) fail(where, "node hierarchy is deeper than 256 levels (a cycle?)");
  const tinygltf::Node& node = model_.nodes[node_index];
  Matrix4 world_from_node = world_from_parent * node_matrix(node);
  std::optional<Transform> world_from_object = invertible(world_from_node);
  if (node.mesh >= 0 && !world_from_object)
    scene_.warnings.push_back(file_ + ": " + where + ": scaled to zero; not rendered");
  if (node.mesh >= 0 && world_from_object) {
    if (size_t(node.mesh) >= model_.meshes.size())
      fail(where + ".mesh", "mesh index " + std::to_string(node.mesh) + " is out of range");
    add_mesh_instances(node_index, world_from_node, *world_from_object);
  }
  if (node.camera >= 0) {
    if (size_t(node.camera) >= model_.cameras.size())
      fail(where + ".camera", "camera index " + std::to_string(node.camera) + " is out of range");
    const tinygltf::Camera& gc = model_.cameras[node.camera];
    std::string name = gc.name.empty() ? (node.name.empty() ? where : node.name) : gc.name;
    std::string at = file_ + ": " + element("cameras", node.camera);
    // Cameras ignore scale: keep only the node's rotation and translation.
    Transform world_from_camera = without_scale(world_from_node);
    Camera camera;
    if (gc.type == "orthographic") {
      GltfOrthographic o{.xmag_m = gc.orthographic.xmag,
                         .ymag_m = gc.orthographic.ymag,
                         .znear_m = gc.orthographic.znear,
                         .zfar_m = gc.orthographic.zfar};
      camera = gltf_orthographic_camera(name, world_from_camera, o, at);
    } else {
      GltfPerspective p;
      p.yfov_radians = gc.perspective.yfov;
      if (gc.perspective.aspectRatio > 0) p.aspect_ratio = gc.perspective.aspectRatio;
      p.znear_m = gc.perspective.znear;
      if (gc.perspective.zfar > 0) p.zfar_m = gc.perspective.zfar;
      camera = gltf_perspective_camera(name, world_from_camera, p, at);
    }
    std::vector<TransformKey> keys = animations_.world_keys(node_index);
    if (!keys.empty()) {
      std::vector<AnimatedTransform::Key> camera_keys;
      for (const TransformKey& k : keys)
        camera_keys.push_back({k.time_seconds, without_scale(k.world_from_object.matrix())});
      camera.world_from_camera = AnimatedTransform(camera_keys);
    }
    scene_.cameras.push_back(std::move(camera));
  }
  auto light = node.extensions.find("KHR_lights_punctual");
  if (light != node.extensions.end())
    import_light(int(number(light->second, "light", -1)), without_scale(world_from_node),
                 where + ".extensions.KHR_lights_punctual");
  for (int child : node.children) visit_node(child, world_from_node, depth + 1);
}

Scene GltfImporter::import() {
  scene_.name = std::filesystem::path(file_).stem().string();
  import_materials();
  auto variants = model_.extensions.find("KHR_materials_variants");
  scene_.material_variants = read_gltf_material_variants(
      variants != model_.extensions.end() ? &variants->second : nullptr, file_);
  animations_ = NodeAnimations(model_, file_, accessors_, scene_.warnings);
  deformer_.emplace(model_, file_, accessors_, animations_);
  int scene_index = choose_gltf_scene(model_, options_.scene, file_);
  if (!model_.scenes.empty()) {
    for (int root : model_.scenes[scene_index].nodes) visit_node(root, Matrix4::identity(), 0);
  } else {
    // No scene: show every mesh once, untransformed (the spec leaves this to the application).
    for (size_t m = 0; m < model_.meshes.size(); ++m)
      for (const PrimitiveMesh& p : import_mesh(int(m))) {
        Instance instance;
        instance.name = scene_.meshes[p.mesh].name;
        instance.mesh = p.mesh;
        instance.material = int32_t(p.material);
        auto variants = variant_materials_.find({p.mesh, p.material});
        if (variants != variant_materials_.end()) instance.variant_materials = variants->second;
        scene_.instances.push_back(instance);
      }
  }
  return std::move(scene_);
}

// tinygltf's file access, bounded: only regular files (not a directory, FIFO or device, which
// its own reader sizes with tellg and then tries to allocate), at most kMaxGltfFileBytes each.
// Each file read (buffers, images) is recorded in `files_read`, a std::vector<std::string>.
bool read_bounded(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                  void* files_read) {
  try {
    *out = read_gltf_file(path);
    static_cast<std::vector<std::string>*>(files_read)->push_back(path);
    return true;
  } catch (const Error& e) {
    if (err) *err += e.what();
    return false;
  }
}

bool file_exists(const std::string& path, void*) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

std::string keep_path(const std::string& path, void*) {
  return path;
}

// tinygltf quotes whole data URIs in its messages: keep each line short.
std::string shorten(const std::string& message) {
  std::string out, line;
  for (size_t i = 0; i <= message.size(); ++i) {
    if (i == message.size() || message[i] == '\n') {
      if (line.size() > 200) line = line.substr(0, 200) + "…";
      if (!line.empty()) out += (out.empty() ? "" : "; ") + line;
      line.clear();
    } else {
      line += message[i];
    }
  }
  return out;
}

}  // namespace

std::vector<unsigned char> read_gltf_file(const std::string& path) {
  uint64_t size = check_input_file(path, kMaxGltfFileBytes, "glTF files and buffers");
  if (size == 0) throw Error(path, "file is empty");
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> bytes(size);
  if (!in || !in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)) ||
      in.gcount() != std::streamsize(size))
    throw Error(path, "cannot read the whole file");
  return bytes;
}

Scene load_gltf_bytes(std::span<const uint8_t> bytes, const std::string& name,
                      const std::string& base_dir, const GltfLoadOptions& options) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  ImageStore images{name, &model, {}, {}};
  loader.SetImageLoader(decode_image, &images);
  std::vector<std::string> files_read;
  loader.SetFsCallbacks({file_exists, keep_path, read_bounded, nullptr, &files_read});
  std::string err, warn;
  std::optional<std::vector<uint8_t>> prepared = prepare_compressed_gltf(bytes);
  if (prepared) bytes = *prepared;
  // The content decides, not the extension: binary glTF starts with the magic "glTF".
  bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  bool ok = false;
  if (binary) {
    uint32_t version = 0;
    if (bytes.size() >= 8) std::memcpy(&version, bytes.data() + 4, 4);
    if (version != 2)
      throw Error(name, "GLB container version " + std::to_string(version) +
                            " is not supported (expected 2)");
    if (bytes.size() > kMaxGltfFileBytes) throw Error(name, "GLB file is too large");
    ok = loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()),
                                     base_dir);
  } else {
    ok = loader.LoadASCIIFromString(
        &model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
        unsigned(std::min<size_t>(bytes.size(), kMaxGltfFileBytes)), base_dir);
  }
  if (!ok || !err.empty()) {
    err = shorten(err);
    throw Error(name,
                "not a valid glTF file: " + (err.empty() ? std::string("unknown error") : err));
  }
  std::vector<std::string> warnings;
  std::set<std::string> unsupported = validate_gltf_model(model, name, warnings);
  GltfDecompressedBuffers decompressed(model);
  decode_meshopt_buffer_views(model, name, decompressed);
  decode_draco_primitives(model, name, decompressed);
  warn_unapplied_gltf_features(model, name, warnings);
  // A texture that cannot be read is not worth failing the render for: warn once per image.
  resolve_unusable_gltf_images(model, images.decoded, images.failed, name, base_dir, files_read,
                               warnings);
  Scene scene =
      GltfImporter(model, name, images, std::move(warnings), std::move(unsupported), options)
          .import();
  scene.input_files = std::move(files_read);
  return scene;
}

Scene load_gltf(const std::string& path, const GltfLoadOptions& options) {
  std::vector<unsigned char> bytes = read_gltf_file(path);
  std::string base_dir = std::filesystem::path(path).parent_path().string();
  return load_gltf_bytes(bytes, path, base_dir, options);
}

}  // namespace obscura
