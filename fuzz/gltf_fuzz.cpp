// libFuzzer target for the glTF 2.0 / GLB loader: the bytes are a .gltf (JSON) or, when they
// start with "glTF", a .glb, read from memory by load_gltf_bytes (what load_gltf runs after
// reading a file), then finished and validated as load_scene_file does for `obscura info` and
// `obscura render`. An obscura::Error is the expected outcome for bad input; anything else
// escaping, a crash, a sanitizer report, a leak or > 2 GB is a finding.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "empty_folder.h"
#include "obscura/io/camera_mapping.h"
#include "obscura/io/gltf_loader.h"
#include "obscura/math/error.h"

namespace {

// Relative URIs resolve in an empty folder (tinygltf also looks in the working directory;
// nothing writes there).
const std::string& base_dir() {
  static const std::string dir = obscura::fuzz::make_empty_folder("obscura-gltf-fuzz-empty");
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    obscura::Scene scene =
        obscura::load_gltf_bytes(std::span<const uint8_t>(data, size), "fuzz.gltf", base_dir());
    obscura::finish_cameras(scene, "", "fuzz.gltf");
    scene.validate();
  } catch (const obscura::Error&) {
    // a clear error for bad input: the expected outcome
  }
  return 0;
}
