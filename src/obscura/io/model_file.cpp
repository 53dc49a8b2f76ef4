#include "obscura/io/model_file.h"

#include <assimp/Importer.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "obscura/io/assimp_loader.h"
#include "obscura/io/obj_loader.h"
#include "obscura/io/ply_loader.h"
#include "obscura/io/stl_loader.h"
#include "obscura/math/error.h"

namespace obscura {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void refuse_gltf_choices(const std::string& where, const GltfLoadOptions& gltf) {
  if (!gltf.scene.empty())
    throw Error(where, "--gltf-scene " + gltf.scene + " applies to glTF files (.gltf, .glb)");
  if (!gltf.animation.empty())
    throw Error(where,
                "--gltf-animation " + gltf.animation + " applies to glTF files (.gltf, .glb)");
}

Scene load_model_file(const std::string& path, const GltfLoadOptions& gltf) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error(path, "file does not exist");
  if (std::filesystem::is_directory(path, ec))
    throw Error(path, "is a directory, not a model file");
  std::string ext = lower_extension(path);
  Scene scene;
  if (ext != ".gltf" && ext != ".glb") refuse_gltf_choices(path, gltf);
  if (ext == ".gltf" || ext == ".glb") scene = load_gltf(path, gltf);
  // Obscura's own readers for the common mesh formats: bounded, fast, and they fail with a
  // message where Assimp's asserts abort the process on hostile input.
  else if (ext == ".obj")
    scene = load_obj(path);
  else if (ext == ".ply")
    scene = load_ply(path);
  else if (ext == ".stl")
    scene = load_stl(path);
  else if (ext != ".json" && Assimp::Importer().IsExtensionSupported(ext))
    scene = load_with_assimp(path);
  else
    throw Error(path, "unknown model format '" + ext +
                          "'; expected .gltf, .glb, .obj, .ply, .stl or another mesh format "
                          "Assimp reads (.fbx, .dae, .3ds, …)");
  scene.input_files.insert(scene.input_files.begin(), path);
  return scene;
}

}  // namespace obscura
