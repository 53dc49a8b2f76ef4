#include "obscura/io/gltf_loader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>

#include "obscura/io/camera_mapping.h"
#include "obscura/io/gltf_animation.h"
#include "obscura/io/texture_loader.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

std::string element(const char* array, size_t index) {
  return std::string(array) + "[" + std::to_string(index) + "]";
}

// Decoded images, filled by tinygltf's image callback (which we route to OpenImageIO).
struct ImageStore {
  std::string file;
  std::map<int, Texture> decoded;  // by glTF image index
};

bool decode_image(tinygltf::Image* image, const int image_index, std::string* err, std::string*,
                  int, int, const unsigned char* bytes, int size, void* user) {
  auto* store = static_cast<ImageStore*>(user);
  std::string source = store->file + "#" + element("images", image_index);
  if (!image->uri.empty() && image->uri.rfind("data:", 0) != 0) source = image->uri;
  try {
    std::string hint = image->mimeType;
    if (hint.empty() && !image->uri.empty())
      hint = std::filesystem::path(image->uri).extension().string().substr(1);
    store->decoded[image_index] =
        decode_texture(std::span<const uint8_t>(bytes, size_t(std::max(size, 0))), source, hint,
                       TextureEncoding::kSrgb);
  } catch (const Error& e) {
    if (err) *err += e.what();
    return false;
  }
  // tinygltf wants the image described; keep no pixels in its copy.
  image->width = store->decoded[image_index].width;
  image->height = store->decoded[image_index].height;
  image->component = store->decoded[image_index].channels;
  return true;
}

// Reads glTF accessors with full range checks: every element must lie inside its buffer view,
// and the view inside its buffer.
class AccessorReader {
 public:
  AccessorReader(const tinygltf::Model& model, std::string file)
      : model_(model), file_(std::move(file)) {}

  const tinygltf::Accessor& accessor(int index, const std::string& where) const {
    if (index < 0 || size_t(index) >= model_.accessors.size())
      throw Error(file_ + ": " + where, "accessor index " + std::to_string(index) +
                                            " is out of range (the file has " +
                                            std::to_string(model_.accessors.size()) + ")");
    return model_.accessors[index];
  }

  // `components` floats per element; normalized integers map to [0, 1] (or [−1, 1]).
  std::vector<float> floats(int index, int components, const std::string& where) const {
    const tinygltf::Accessor& a = accessor(index, where);
    std::string at = where + " (" + element("accessors", index) + ")";
    int n = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    if (n != components)
      throw Error(file_ + ": " + at, "expected " + std::to_string(components) +
                                         " components per element, got " + std::to_string(n));
    std::vector<float> out(a.count * size_t(n));
    read(a, at, [&](const uint8_t* p, size_t i) {
      for (int c = 0; c < n; ++c) out[i * n + c] = component(a, p, c);
    });
    return out;
  }

  std::vector<uint32_t> indices(int index, const std::string& where) const {
    const tinygltf::Accessor& a = accessor(index, where);
    std::string at = where + " (" + element("accessors", index) + ")";
    if (a.type != TINYGLTF_TYPE_SCALAR) throw Error(file_ + ": " + at, "indices must be scalars");
    std::vector<uint32_t> out(a.count);
    read(a, at, [&](const uint8_t* p, size_t i) {
      switch (a.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
          out[i] = *p;
          break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
          out[i] = load<uint16_t>(p);
          break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
          out[i] = load<uint32_t>(p);
          break;
        default:
          throw Error(file_ + ": " + at, "indices must be unsigned integers");
      }
    });
    return out;
  }

 private:
  template <typename T>
  static T load(const uint8_t* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }

  float component(const tinygltf::Accessor& a, const uint8_t* p, int c) const {
    switch (a.componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return load<float>(p + 4 * c);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
        float v = p[c];
        return a.normalized ? v / 255.f : v;
      }
      case TINYGLTF_COMPONENT_TYPE_BYTE: {
        float v = float(int8_t(p[c]));
        return a.normalized ? std::max(v / 127.f, -1.f) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        float v = load<uint16_t>(p + 2 * c);
        return a.normalized ? v / 65535.f : v;
      }
      case TINYGLTF_COMPONENT_TYPE_SHORT: {
        float v = load<int16_t>(p + 2 * c);
        return a.normalized ? std::max(v / 32767.f, -1.f) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return float(load<uint32_t>(p + 4 * c));
      default:
        throw Error(file_, "unsupported accessor component type");
    }
  }

  template <typename F>
  void read(const tinygltf::Accessor& a, const std::string& at, F&& per_element) const {
    if (a.sparse.isSparse) throw Error(file_ + ": " + at, "sparse accessors are not supported");
    if (a.count == 0) return;
    if (a.bufferView < 0) {  // no data: all zeros, as glTF specifies
      std::vector<uint8_t> zeros(64, 0);
      for (size_t i = 0; i < a.count; ++i) per_element(zeros.data(), i);
      return;
    }
    if (size_t(a.bufferView) >= model_.bufferViews.size())
      throw Error(file_ + ": " + at,
                  "bufferView " + std::to_string(a.bufferView) + " is out of range");
    const tinygltf::BufferView& view = model_.bufferViews[a.bufferView];
    if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size())
      throw Error(file_ + ": " + element("bufferViews", a.bufferView),
                  "buffer index is out of range");
    const std::vector<unsigned char>& buffer = model_.buffers[view.buffer].data;
    int component_size = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
    int components = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    if (component_size <= 0 || components <= 0)
      throw Error(file_ + ": " + at, "invalid component type or element type");
    size_t element_size = size_t(component_size) * components;
    size_t stride = view.byteStride ? view.byteStride : element_size;
    size_t first = view.byteOffset + a.byteOffset;
    size_t end = first + stride * (a.count - 1) + element_size;
    if (view.byteOffset + view.byteLength > buffer.size() ||
        end > view.byteOffset + view.byteLength)
      throw Error(file_ + ": " + at,
                  "data runs past the end of its buffer (" + std::to_string(end) + " > " +
                      std::to_string(buffer.size()) + " bytes): truncated file?");
    for (size_t i = 0; i < a.count; ++i) per_element(buffer.data() + first + i * stride, i);
  }

  const tinygltf::Model& model_;
  std::string file_;
};

// Everything the loader builds while walking the file.
class GltfImporter {
 public:
  GltfImporter(const tinygltf::Model& model, std::string file, ImageStore& images)
      : model_(model), file_(std::move(file)), images_(images), accessors_(model_, file_) {}

  Scene import();

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& message) const {
    throw Error(file_ + ": " + where, message);
  }
  TextureRef texture(int texture_index, int uv_set, TextureEncoding encoding,
                     const std::string& where);
  void import_materials();
  uint32_t default_material();
  std::vector<std::pair<uint32_t, uint32_t>> import_mesh(int mesh_index);
  Mesh import_primitive(const tinygltf::Primitive& primitive, const std::string& where,
                        const std::string& name);
  void import_light(int light_index, const Transform& world_from_light, const std::string& where);
  void visit_node(int node_index, const Matrix4& world_from_parent, int depth);

  const tinygltf::Model& model_;
  std::string file_;
  ImageStore& images_;
  AccessorReader accessors_;
  Scene scene_;
  std::map<std::pair<int, TextureEncoding>, int32_t> textures_;  // (glTF texture, encoding) → ours
  // Per glTF mesh, its primitives as (our mesh, material) pairs.
  std::map<int, std::vector<std::pair<uint32_t, uint32_t>>> meshes_;
  // Primitives that read the same accessors share one Mesh (instancing across glTF meshes).
  std::map<std::string, uint32_t> geometry_;
  int default_material_ = -1;
  NodeAnimations animations_;
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
                                 const std::string& where) {
  if (texture_index < 0) return {};
  if (size_t(texture_index) >= model_.textures.size())
    fail(where, "texture index " + std::to_string(texture_index) + " is out of range");
  auto key = std::make_pair(texture_index, encoding);
  auto found = textures_.find(key);
  if (found != textures_.end()) return {found->second, uint32_t(std::max(uv_set, 0))};
  const tinygltf::Texture& gt = model_.textures[texture_index];
  if (gt.source < 0 || size_t(gt.source) >= model_.images.size())
    fail(element("textures", texture_index),
         "image index " + std::to_string(gt.source) + " is out of range");
  auto image = images_.decoded.find(gt.source);
  if (image == images_.decoded.end())
    fail(element("images", gt.source),
         "image '" + model_.images[gt.source].uri + "' could not be loaded (missing file?)");
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
  return {index, uint32_t(std::max(uv_set, 0))};
}

void GltfImporter::import_materials() {
  for (size_t i = 0; i < model_.materials.size(); ++i) {
    const tinygltf::Material& gm = model_.materials[i];
    std::string where = element("materials", i);
    const tinygltf::PbrMetallicRoughness& pbr = gm.pbrMetallicRoughness;
    MetallicRoughnessMaterial mr;
    mr.base_color = rgb(pbr.baseColorFactor, Rgb(1.f));
    mr.alpha = pbr.baseColorFactor.size() == 4 ? float(pbr.baseColorFactor[3]) : 1.f;
    mr.base_color_texture = texture(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                                    TextureEncoding::kSrgb, where + ".baseColorTexture");
    mr.metallic = float(pbr.metallicFactor);
    mr.roughness = float(pbr.roughnessFactor);
    mr.metallic_roughness_texture =
        texture(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                TextureEncoding::kLinear, where + ".metallicRoughnessTexture");
    mr.occlusion_texture = texture(gm.occlusionTexture.index, gm.occlusionTexture.texCoord,
                                   TextureEncoding::kLinear, where + ".occlusionTexture");
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
      } else {
        scene_.warnings.push_back(file_ + ": " + where + ": extension " + name + " is ignored");
      }
    }
    Material m;
    m.name = gm.name.empty() ? where : gm.name;
    m.model = mr;
    m.emission = rgb(gm.emissiveFactor, Rgb()) * emissive_strength;
    m.emission_texture = texture(gm.emissiveTexture.index, gm.emissiveTexture.texCoord,
                                 TextureEncoding::kSrgb, where + ".emissiveTexture");
    m.normal_texture = texture(gm.normalTexture.index, gm.normalTexture.texCoord,
                               TextureEncoding::kLinear, where + ".normalTexture");
    m.normal_scale = float(gm.normalTexture.scale);
    m.double_sided = gm.doubleSided;
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
  std::vector<float> xyz = accessors_.floats(position, 3, where + ".attributes.POSITION");
  mesh.positions.resize(xyz.size() / 3);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    mesh.positions[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
    if (!std::isfinite(xyz[3 * i]) || !std::isfinite(xyz[3 * i + 1]) ||
        !std::isfinite(xyz[3 * i + 2]))
      fail(where + ".attributes.POSITION",
           "vertex " + std::to_string(i) + " is not finite (NaN or infinity)");
  }
  size_t n = mesh.positions.size();
  auto check_count = [&](size_t count, const char* key) {
    if (count != n)
      fail(where + ".attributes." + key,
           std::to_string(count) + " elements for " + std::to_string(n) + " positions");
  };
  if (int a = attribute("NORMAL"); a >= 0) {
    std::vector<float> v = accessors_.floats(a, 3, where + ".attributes.NORMAL");
    check_count(v.size() / 3, "NORMAL");
    for (size_t i = 0; i < n; ++i) mesh.normals.emplace_back(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
  }
  if (int a = attribute("TEXCOORD_0"); a >= 0) {
    std::vector<float> v = accessors_.floats(a, 2, where + ".attributes.TEXCOORD_0");
    check_count(v.size() / 2, "TEXCOORD_0");
    for (size_t i = 0; i < n; ++i) mesh.uvs.emplace_back(v[2 * i], v[2 * i + 1]);
  }
  if (int a = attribute("TANGENT"); a >= 0) {
    std::vector<float> v = accessors_.floats(a, 4, where + ".attributes.TANGENT");
    check_count(v.size() / 4, "TANGENT");
    for (size_t i = 0; i < n; ++i)
      mesh.tangents.emplace_back(v[4 * i], v[4 * i + 1], v[4 * i + 2], v[4 * i + 3]);
  }
  if (int a = attribute("COLOR_0"); a >= 0) {
    int components = tinygltf::GetNumComponentsInType(
        uint32_t(accessors_.accessor(a, where + ".attributes.COLOR_0").type));
    if (components != 3 && components != 4)
      fail(where + ".attributes.COLOR_0", "expected VEC3 or VEC4 colours");
    std::vector<float> v = accessors_.floats(a, components, where + ".attributes.COLOR_0");
    check_count(v.size() / components, "COLOR_0");
    for (size_t i = 0; i < n; ++i)
      mesh.colors.emplace_back(v[components * i], v[components * i + 1], v[components * i + 2]);
  }
  std::vector<uint32_t> indices;
  if (p.indices >= 0) {
    indices = accessors_.indices(p.indices, where + ".indices");
  } else {
    indices.resize(n);
    for (size_t i = 0; i < n; ++i) indices[i] = uint32_t(i);
  }
  for (size_t i = 0; i < indices.size(); ++i)
    if (indices[i] >= n)
      fail(where + ".indices", "index " + std::to_string(i) + " = " + std::to_string(indices[i]) +
                                   " is past the vertex count " + std::to_string(n));
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

std::vector<std::pair<uint32_t, uint32_t>> GltfImporter::import_mesh(int mesh_index) {
  auto found = meshes_.find(mesh_index);
  if (found != meshes_.end()) return found->second;
  const tinygltf::Mesh& gm = model_.meshes[mesh_index];
  std::vector<std::pair<uint32_t, uint32_t>>& ours = meshes_[mesh_index];
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
    ours.emplace_back(shared->second, p.material >= 0 ? uint32_t(p.material) : default_material());
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
    for (auto [mesh, material] : import_mesh(node.mesh)) {
      Instance instance;
      instance.name = node.name.empty() ? where : node.name;
      instance.mesh = mesh;
      instance.material = int32_t(material);
      instance.world_from_object = *world_from_object;
      instance.motion = animations_.world_keys(node_index);
      if (!instance.motion.empty())
        instance.world_from_object = instance.motion.front().world_from_object;
      scene_.instances.push_back(std::move(instance));
    }
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
  animations_ = NodeAnimations(model_, file_, scene_.warnings);
  int scene_index = model_.defaultScene >= 0 ? model_.defaultScene : 0;
  if (!model_.scenes.empty()) {
    if (size_t(scene_index) >= model_.scenes.size()) fail("scene", "scene index is out of range");
    for (int root : model_.scenes[scene_index].nodes) visit_node(root, Matrix4::identity(), 0);
  } else {
    // No scene: show every mesh once, untransformed (the spec leaves this to the application).
    for (size_t m = 0; m < model_.meshes.size(); ++m)
      for (auto [mesh, material] : import_mesh(int(m))) {
        Instance instance;
        instance.name = scene_.meshes[mesh].name;
        instance.mesh = mesh;
        instance.material = int32_t(material);
        scene_.instances.push_back(instance);
      }
  }
  return std::move(scene_);
}

}  // namespace

Scene load_gltf(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw Error(path, "file does not exist");
  tinygltf::TinyGLTF loader;
  ImageStore images{path, {}};
  loader.SetImageLoader(decode_image, &images);
  tinygltf::Model model;
  std::string err, warn;
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  bool ok = ext == ".glb" ? loader.LoadBinaryFromFile(&model, &err, &warn, path)
                          : loader.LoadASCIIFromFile(&model, &err, &warn, path);
  if (!ok || !err.empty()) {
    while (!err.empty() && err.back() == '\n') err.pop_back();
    throw Error(path,
                "not a valid glTF file: " + (err.empty() ? std::string("unknown error") : err));
  }
  // tinygltf only warns when an external image is missing; a missing texture is an error here.
  for (size_t i = 0; i < model.images.size(); ++i)
    if (!images.decoded.count(int(i)))
      throw Error(path + ": " + element("images", i),
                  "image '" + model.images[i].uri + "' does not exist or cannot be decoded" +
                      (warn.empty() ? "" : " (" + warn.substr(0, warn.find('\n')) + ")"));
  Scene scene = GltfImporter(model, path, images).import();
  return scene;
}

}  // namespace obscura
