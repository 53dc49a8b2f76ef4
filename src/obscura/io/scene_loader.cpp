#include "obscura/io/scene_loader.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "obscura/io/binary_location.h"
#include "obscura/io/camera_mapping.h"
#include "obscura/io/gltf_loader.h"
#include "obscura/io/json_scene.h"
#include "obscura/io/model_file.h"
#include "obscura/math/error.h"
#include "obscura/scene/builtin_scenes.h"

namespace obscura {

Scene load_scene_file(const std::string& path, const GltfLoadOptions& gltf) {
  Scene scene;
  const std::string extension = lower_extension(path);
  if (extension == ".json") {
    refuse_gltf_choices(path, gltf);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw Error(path, "scene file does not exist");
    scene = load_json_scene(path);  // chooses its own camera
    scene.input_files.insert(scene.input_files.begin(), path);
  } else if (extension == ".gltf" || extension == ".glb") {
    // Read at the animation's start, where the automatic camera frames the scene whatever the
    // moment shown (each frame of a sequence sees it from the same place), then posed at the
    // moment asked for.
    GltfLoadOptions at_start = gltf;
    at_start.time_s = 0;
    at_start.exposure_s = 0;
    scene = load_model_file(path, at_start);
    finish_cameras(scene, "", path);
    if (gltf.time_s != 0 || gltf.exposure_s != 0) scene.pose(gltf.time_s, gltf.exposure_s);
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

std::vector<std::string> scenes_search_dirs() {
  // The override is the only place looked in, as for plugins: scenes found elsewhere behind it
  // would hide that it points at the wrong folder.
  if (const char* override_dir = std::getenv("OBSCURA_SCENES_DIR"); override_dir && *override_dir)
    return {override_dir};
  std::vector<std::string> dirs;
  std::filesystem::path binary = binary_holding_this_library();
  if (!binary.empty()) {
    std::filesystem::path dir = binary.parent_path();
    dirs.push_back((dir / "../share/obscura/scenes").lexically_normal().string());
    dirs.push_back((dir / "scenes").lexically_normal().string());
  }
#ifdef OBSCURA_SOURCE_SCENES_DIR
  // Last: a build tree's programs and module are not installed, but the tree they were built
  // from usually still exists.
  std::string source_scenes =
      std::filesystem::path(OBSCURA_SOURCE_SCENES_DIR).lexically_normal().string();
  if (std::find(dirs.begin(), dirs.end(), source_scenes) == dirs.end())
    dirs.push_back(source_scenes);
#endif
  return dirs;
}

std::string find_scenes_file(const std::string& relative) {
  for (const std::string& dir : scenes_search_dirs()) {
    std::filesystem::path path = std::filesystem::path(dir) / relative;
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) return path.string();
  }
  return "";
}

std::string scenes_search_report(const std::string& relative) {
  std::string looked;
  for (const std::string& dir : scenes_search_dirs())
    looked += (looked.empty() ? "" : ", ") + (std::filesystem::path(dir) / relative).string();
  return "looked in " + looked +
         "; set OBSCURA_SCENES_DIR to the folder of Obscura's example scenes (scenes/ in its "
         "source tree)";
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
    std::string path = find_scenes_file(b.file);
    if (path.empty())
      throw Error(name, "the built-in scene's file " + b.file +
                            " was not found: " + scenes_search_report(b.file));
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
