#include "obscura/io/scene_loader.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "obscura/io/camera_mapping.h"
#include "obscura/io/gltf_loader.h"
#include "obscura/io/json_scene.h"
#include "obscura/io/model_file.h"
#include "obscura/math/error.h"
#include "obscura/scene/builtin_scenes.h"

namespace obscura {

namespace {

std::filesystem::path executable_directory() {
  std::error_code ec;
  std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : exe.parent_path();
}

}  // namespace

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
