// The glTF importer's internals, shared by the files that implement it: gltf_loader.cpp (the file,
// its nodes, lights and instances), gltf_materials.cpp (materials, textures, samplers) and
// gltf_primitives.cpp (primitives as meshes). Not part of the library's interface.
#pragma once

#include <tiny_gltf.h>

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "obscura/io/gltf_accessor.h"
#include "obscura/io/gltf_animation.h"
#include "obscura/io/gltf_deformation.h"
#include "obscura/io/gltf_gpu_instancing.h"
#include "obscura/io/gltf_loader.h"
#include "obscura/math/error.h"
#include "obscura/scene/scene.h"

namespace obscura {

inline std::string element(const char* array, size_t index) {
  return std::string(array) + "[" + std::to_string(index) + "]";
}

// `key` of a JSON object as a number, or `fallback` when absent or not a number.
inline double number(const tinygltf::Value& v, const char* key, double fallback) {
  if (!v.Has(key) || !v.Get(key).IsNumber()) return fallback;
  return v.Get(key).GetNumberAsDouble();
}

inline Rgb rgb(const std::vector<double>& v, Rgb fallback) {
  if (v.size() < 3) return fallback;
  return {float(v[0]), float(v[1]), float(v[2])};
}

// Decoded images, filled by tinygltf's image callback (which we route to the image codecs). An
// image that cannot be read is a warning, not an error: its material renders with the factor alone.
struct ImageStore {
  std::string file;
  const tinygltf::Model* model = nullptr;  // filled by tinygltf while it parses
  std::map<int, Texture> decoded;          // by glTF image index
  std::map<int, std::string> failed;       // by glTF image index: why it could not be decoded
  std::vector<std::string> warnings;       // the decoder's (texels it replaced), one per image
};

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

  // The meshes import() posed that change with time (animated skins and morph targets), as
  // indices into its scene's meshes, and the same posed again at another moment (MeshPoser).
  const std::vector<uint32_t>& animated_meshes() const { return animated_meshes_; }
  void pose(std::vector<Mesh>& meshes, double time_s, double exposure_s);

 private:
  // A node's primitive posed by its skin or morph targets: its own mesh.
  struct PosedMesh {
    uint32_t mesh = 0, base = 0;  // the posed mesh and the file's primitive, in Scene::meshes
    int node = 0;
    size_t primitive = 0;
    Matrix4 world_from_node;
    std::string where, label;  // the primitive in the file; the node, for the mesh's name
    bool animated = false;     // its shape changes with time
  };
  Mesh posed_mesh(const PosedMesh& posed, const Mesh& base, double time_s, double exposure_s);
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
  // What pose() needs: the animated posed meshes, and their primitives as the file has them.
  std::vector<PosedMesh> animated_;
  std::vector<uint32_t> animated_meshes_;
  std::map<uint32_t, Mesh> pose_bases_;
};

}  // namespace obscura
