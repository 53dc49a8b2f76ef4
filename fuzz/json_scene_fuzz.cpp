// libFuzzer target for Obscura's JSON scene reader: the bytes are a scene file, read from memory
// by load_json_scene_text (what load_json_scene runs on a file's bytes) and validated as
// load_scene_file does for `obscura info` and `obscura render`. An obscura::Error is the expected
// outcome for bad input; anything else escaping, a crash, a sanitizer report, a leak or > 2 GB
// is a finding.
#include <cstdint>
#include <filesystem>
#include <string>

#include "empty_folder.h"
#include "obscura/io/json_scene.h"
#include "obscura/math/error.h"

namespace {

// The scene "lives" in an empty folder, so relative model and texture names find nothing.
const std::string& scene_path() {
  static const std::string path =
      obscura::fuzz::make_empty_folder("obscura-json-fuzz-empty") + "/fuzz.json";
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    std::string text(reinterpret_cast<const char*>(data), size);
    obscura::Scene scene = obscura::load_json_scene_text(text, scene_path());
    scene.validate();
  } catch (const obscura::Error&) {
    // a clear error for bad input: the expected outcome
  }
  return 0;
}
