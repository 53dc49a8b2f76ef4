// The fidelity suite's scenes (bench/fidelity/gltf_fidelity.py) in the test suite: a Khronos
// sample model from tests/data/gltf/ seen through the camera stored with its Cycles reference in
// data/reference/gltf/, as the suite's JSON scene file places it.
#pragma once

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "obscura/io/scene_loader.h"
#include "test_paths.h"

namespace obscura::test {

inline nlohmann::json read_json_file(const std::string& path) {
  std::ifstream file(path);
  return nlohmann::json::parse(file);
}

// The reference files of sample `name`: NAME.camera.json, NAME.exr, NAME.cycles.json.
inline std::string fidelity_reference(const std::string& name, const std::string& suffix) {
  return source_path("data/reference/gltf/" + name + suffix);
}

// tests/data/gltf/MODEL through sample `name`'s camera, on a square film of `size` pixels.
inline Scene fidelity_scene(const std::string& name, const std::string& model, int size) {
  using nlohmann::json;
  json camera = read_json_file(fidelity_reference(name, ".camera.json"));
  json scene_file = {{"objects", json::array({{{"model", data_path("gltf/" + model)}}})},
                     {"cameras", json::array({{{"name", "fidelity"},
                                               {"position", camera["eye"]},
                                               {"target", camera["target"]},
                                               {"up", camera["up"]},
                                               {"fov_degrees", camera["vfov_deg"]}}})},
                     {"camera", "fidelity"}};
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("obscura-fidelity-" + name);
  fs::create_directories(dir);
  fs::path path = dir / "scene.json";
  std::ofstream(path) << scene_file.dump();
  Scene scene = load_scene_file(path.string());
  fs::remove_all(dir);
  scene.camera.film.width_px = scene.camera.film.height_px = size;
  return scene;
}

}  // namespace obscura::test
