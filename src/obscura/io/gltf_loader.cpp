#include "obscura/io/gltf_loader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
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
#include "obscura/io/gltf_importer.h"
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
                       TextureEncoding::kSrgb, &store->warnings);
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
      const PosedMesh record{
          .mesh = uint32_t(scene_.meshes.size()),
          .base = p.mesh,
          .node = node_index,
          .primitive = p.primitive,
          .world_from_node = world_from_node,
          .where = element("meshes", node.mesh) + "." + element("primitives", p.primitive),
          .label = node.name.empty() ? where : node.name,
          .animated = deformer_->animated(node_index)};
      // Each posed node holds its own copy (and poses across the shutter): bounded in all.
      posed_vertices_ += scene_.meshes[p.mesh].positions.size() * size_t(1 + kDeformationSteps);
      if (posed_vertices_ > kMaxPosedVertices)
        fail(where, "skinned or morphed meshes need more than " +
                        std::to_string(kMaxPosedVertices) + " posed vertices in all");
      Mesh posed = posed_mesh(record, scene_.meshes[p.mesh], options_.time_s, options_.exposure_s);
      mesh = record.mesh;
      scene_.meshes.push_back(std::move(posed));
      if (record.animated) {
        pose_bases_.try_emplace(p.mesh, scene_.meshes[p.mesh]);
        animated_.push_back(record);
        animated_meshes_.push_back(record.mesh);
      }
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

Mesh GltfImporter::posed_mesh(const PosedMesh& r, const Mesh& base, double time_s,
                              double exposure_s) {
  Mesh posed = deformer_->deform(base, r.node, r.primitive, r.world_from_node, r.where, time_s);
  if (exposure_s > 0 && r.animated)
    posed.deformation =
        deformer_->deformation(base, r.node, r.primitive, r.world_from_node, r.where,
                               time_s - exposure_s / 2, time_s + exposure_s / 2);
  posed.name.append(" (").append(r.label).append(")");
  return posed;
}

void GltfImporter::pose(std::vector<Mesh>& meshes, double time_s, double exposure_s) {
  for (const PosedMesh& r : animated_) {
    if (r.mesh >= meshes.size())
      throw Error(file_, "the scene no longer holds the posed mesh " + std::to_string(r.mesh) +
                             " of " + element("nodes", r.node));
    meshes[r.mesh] = posed_mesh(r, pose_bases_.at(r.base), time_s, exposure_s);
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
  animations_ = NodeAnimations(
      model_, file_, choose_gltf_animation(model_, options_.animation, file_, scene_.warnings),
      accessors_, scene_.warnings);
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

namespace {

// A file whose skins or morph targets are animated, kept after loading to pose them again: the
// importer with the model it reads (the deformer has decoded and checked what it needs).
class GltfMeshPoser final : public MeshPoser {
 public:
  GltfMeshPoser(std::unique_ptr<tinygltf::Model> model, std::unique_ptr<ImageStore> images,
                std::unique_ptr<GltfImporter> importer)
      : model_(std::move(model)), images_(std::move(images)), importer_(std::move(importer)) {
    images_->decoded.clear();  // the scene holds its textures
  }
  std::span<const uint32_t> meshes() const override { return importer_->animated_meshes(); }
  void pose(std::vector<Mesh>& meshes, double time_s, double exposure_s) const override {
    std::lock_guard lock(mutex_);  // the deformer keeps what it has read
    importer_->pose(meshes, time_s, exposure_s);
  }

 private:
  // Declared in the order they depend on each other: destroyed importer first.
  std::unique_ptr<tinygltf::Model> model_;
  std::unique_ptr<ImageStore> images_;
  std::unique_ptr<GltfImporter> importer_;
  mutable std::mutex mutex_;
};

}  // namespace

Scene load_gltf_bytes(std::span<const uint8_t> bytes, const std::string& name,
                      const std::string& base_dir, const GltfLoadOptions& options) {
  tinygltf::TinyGLTF loader;
  // On the heap: a poser (below) may keep them.
  auto model_holder = std::make_unique<tinygltf::Model>();
  tinygltf::Model& model = *model_holder;
  auto images_holder = std::make_unique<ImageStore>(ImageStore{name, &model, {}, {}, {}});
  ImageStore& images = *images_holder;
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
    // Neither container: say what the file is not, and how it starts (a web page saved as .glb,
    // an empty download), rather than a JSON parser's complaint about its first byte.
    size_t first = 0;
    if (bytes.size() >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF)
      first = 3;  // a UTF-8 byte order mark, which JSON files may carry
    while (first < bytes.size() && std::isspace(bytes[first])) ++first;
    if (first == bytes.size() || bytes[first] != '{') {
      std::string start;
      for (size_t i = first; i < bytes.size() && start.size() < 24; ++i)
        start += std::isprint(bytes[i]) ? char(bytes[i]) : '.';
      throw Error(name,
                  "not a glTF file: binary glTF (.glb) starts with the bytes 'glTF' and "
                  "glTF JSON (.gltf) with '{'; " +
                      (start.empty() ? std::string("this file is empty")
                                     : "this one starts with \"" + start + "\""));
    }
    ok = loader.LoadASCIIFromString(
        &model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
        unsigned(std::min<size_t>(bytes.size(), kMaxGltfFileBytes)), base_dir);
  }
  if (!ok || !err.empty()) {
    err = shorten(err);
    throw Error(name,
                "not a valid glTF file: " + (err.empty() ? std::string("unknown error") : err));
  }
  // The images' own warnings first (texels replaced), in the order tinygltf decoded them.
  std::vector<std::string> warnings = std::move(images.warnings);
  std::set<std::string> unsupported = validate_gltf_model(model, name, warnings);
  GltfDecompressedBuffers decompressed(model);
  decode_meshopt_buffer_views(model, name, decompressed);
  decode_draco_primitives(model, name, decompressed);
  warn_unapplied_gltf_features(model, name, warnings);
  // A texture that cannot be read is not worth failing the render for: warn once per image.
  resolve_unusable_gltf_images(model, images.decoded, images.failed, name, base_dir, files_read,
                               warnings);
  auto importer = std::make_unique<GltfImporter>(model, name, images, std::move(warnings),
                                                 std::move(unsupported), options);
  Scene scene = importer->import();
  scene.input_files = std::move(files_read);
  if (!importer->animated_meshes().empty())
    scene.poser = std::make_shared<GltfMeshPoser>(std::move(model_holder), std::move(images_holder),
                                                  std::move(importer));
  return scene;
}

Scene load_gltf(const std::string& path, const GltfLoadOptions& options) {
  std::vector<unsigned char> bytes = read_gltf_file(path);
  std::string base_dir = std::filesystem::path(path).parent_path().string();
  return load_gltf_bytes(bytes, path, base_dir, options);
}

}  // namespace obscura
