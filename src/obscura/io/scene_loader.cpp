#include "obscura/io/scene_loader.h"

#include <unistd.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "obscura/io/assimp_loader.h"
#include "obscura/io/camera_mapping.h"
#include "obscura/io/gltf_loader.h"
#include "obscura/io/json_scene.h"
#include "obscura/io/obj_loader.h"
#include "obscura/io/ply_loader.h"
#include "obscura/io/stl_loader.h"
#include "obscura/math/error.h"
#include "obscura/scene/builtin_scenes.h"

namespace obscura {

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// --gltf-scene and --gltf-animation choose inside a glTF file; anything else refuses them.
void refuse_gltf_choices(const std::string& where, const GltfLoadOptions& gltf) {
  if (!gltf.scene.empty())
    throw Error(where, "--gltf-scene " + gltf.scene + " applies to glTF files (.gltf, .glb)");
  if (!gltf.animation.empty())
    throw Error(where,
                "--gltf-animation " + gltf.animation + " applies to glTF files (.gltf, .glb)");
}

std::filesystem::path executable_directory() {
  std::error_code ec;
  std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : exe.parent_path();
}

}  // namespace

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

Scene load_scene_file(const std::string& path, const GltfLoadOptions& gltf) {
  Scene scene;
  if (lower_extension(path) == ".json") {
    refuse_gltf_choices(path, gltf);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw Error(path, "scene file does not exist");
    scene = load_json_scene(path);  // chooses its own camera
    scene.input_files.insert(scene.input_files.begin(), path);
  } else {
    scene = load_model_file(path, gltf);
    finish_cameras(scene, "", path);
  }
  scene.validate();
  return scene;
}

const std::vector<BuiltinScene>& builtin_scenes() {
  static const std::vector<BuiltinScene> scenes = {
      {"cornell-box", "the measured Cornell box, built in code (default)", ""},
      {"cornell-box-obj", "the same box from the measured OBJ, in a JSON scene",
       "cornell-box.json"},
      {"spheres-and-lights", "one sphere per material type under point, spot and area lights",
       "spheres-and-lights.json"},
      {"depth-of-field", "a row of objects receding from an f/1.8 camera", "depth-of-field.json"},
      {"motion-blur", "a moving sphere seen by a moving camera", "motion-blur.json"},
      {"bunny", "the Stanford bunny on a plane", "bunny.json"},
      {"gltf-spheres", "Khronos MetalRoughSpheresNoTextures: 98 instanced spheres (glTF)",
       "gltf-spheres.json"},
  };
  return scenes;
}

std::string scenes_directory() {
  if (const char* env = std::getenv("OBSCURA_SCENES_DIR"); env && *env) return env;
  std::filesystem::path exe = executable_directory();
  std::error_code ec;
  for (const char* relative : {"../share/obscura/scenes", "../scenes"}) {
    std::filesystem::path candidate = (exe / relative).lexically_normal();
    if (!exe.empty() && std::filesystem::is_directory(candidate, ec)) return candidate.string();
  }
  return "scenes";
}

Scene load_scene(const std::string& name_or_path, const GltfLoadOptions& gltf) {
  const std::vector<BuiltinScene>& builtins = builtin_scenes();
  std::string name = name_or_path.empty() ? builtins.front().name : name_or_path;
  for (const BuiltinScene& b : builtins) {
    if (b.name != name) continue;
    if (b.file.empty()) {
      refuse_gltf_choices(name, gltf);
      Scene scene = make_builtin_scene(name);
      scene.validate();
      return scene;
    }
    std::string path = (std::filesystem::path(scenes_directory()) / b.file).string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
      throw Error(path, "the built-in scene '" + name +
                            "' is missing (set OBSCURA_SCENES_DIR to the scenes folder)");
    return load_scene_file(path, gltf);
  }
  std::error_code ec;
  if (std::filesystem::exists(name, ec) || name.find('.') != std::string::npos ||
      name.find('/') != std::string::npos)
    return load_scene_file(name, gltf);
  std::string known;
  for (const BuiltinScene& b : builtins) known += (known.empty() ? "" : ", ") + b.name;
  throw Error(name, "neither a scene file nor a built-in scene (built-in: " + known + ")");
}

}  // namespace obscura
