// libFuzzer target for the OBJ, MTL, PLY and STL readers. The first byte chooses the reader —
// 'o' OBJ, 'm' MTL, 'p' PLY, 's' STL (any other byte: its value modulo 4, in that order) — and
// the rest is the file's bytes, read from memory by the function load_obj/load_ply/load_stl run
// on a file's bytes, then finished and validated as load_scene_file does for `obscura info`.
// An obscura::Error is the expected outcome for bad input; anything else escaping, a crash, a
// sanitizer report, a leak or > 2 GB is a finding.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "empty_folder.h"
#include "obscura/io/camera_mapping.h"
#include "obscura/io/mtl_reader.h"
#include "obscura/io/obj_loader.h"
#include "obscura/io/ply_loader.h"
#include "obscura/io/stl_loader.h"
#include "obscura/math/error.h"

namespace {

// "mtllib" and texture paths resolve in an empty folder.
const std::string& base_dir() {
  static const std::string dir = obscura::fuzz::make_empty_folder("obscura-mesh-fuzz-empty");
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  std::span<const char> bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  char kind = char(data[0]);
  if (kind != 'o' && kind != 'm' && kind != 'p' && kind != 's') kind = "omps"[data[0] % 4];
  try {
    obscura::Scene scene;
    if (kind == 'm') {
      std::vector<std::string> warnings;
      obscura::parse_mtl(std::string_view(bytes.data(), bytes.size()), "fuzz.mtl", warnings);
      return 0;
    }
    if (kind == 'o') scene = obscura::load_obj_bytes(bytes, "fuzz.obj", base_dir());
    if (kind == 'p') scene = obscura::load_ply_bytes(bytes, "fuzz.ply");
    if (kind == 's') scene = obscura::load_stl_bytes(bytes, "fuzz.stl");
    obscura::finish_cameras(scene, "", "fuzz");
    scene.validate();
  } catch (const obscura::Error&) {
    // a clear error for bad input: the expected outcome
  }
  return 0;
}
