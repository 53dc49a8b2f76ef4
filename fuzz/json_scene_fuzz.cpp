// libFuzzer target for Obscura's JSON scene reader: the bytes are a scene file, read from memory
// by load_json_scene_text (what load_json_scene runs on a file's bytes) and validated as
// load_scene_file does for `obscura info` and `obscura render`. An obscura::Error is the expected
// outcome for bad input; anything else escaping, a crash, a sanitizer report, a leak or > 2 GB
// is a finding.
#include <cstdint>
#include <filesystem>
#include <string>

#include "obscura/io/json_scene.h"
#include "obscura/math/error.h"

namespace {

// The scene "lives" in an empty folder of this process, so relative model and texture names in
// an input find nothing around the fuzzer.
const std::string& scene_path() {
  static const std::string path = [] {
    std::filesystem::path d = std::filesystem::temp_directory_path() / "obscura-json-fuzz-empty";
    std::error_code ec;
    std::filesystem::create_directories(d, ec);
    return (d / "fuzz.json").string();
  }();
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
