// libFuzzer target that renders what the JSON scene reader makes of its input: the bytes are a
// scene file (docs/scene-format.md), read by load_json_scene_text and validated as `obscura
// render` does, then rendered as a tiny frame by both renderers with its ground truth, and with
// glare and flare when the scene asks for them (tiny_render.h clamps the cost). Its seeds are
// scenes with lights, transforms, materials and camera values at the edges of what validates,
// and the values issue 32 found crashing the renderers (a point light at 1e308, an emission
// strength of 1e38, a camera at 2e18, a scale of 1e18, a translation of −1e308, a lens shift of
// 1e20). An obscura::Error is the expected outcome for bad input; anything else escaping, a
// crash, a sanitizer report, a non-finite pixel, a leak or > 2 GB is a finding.
#include <cstdint>
#include <string>

#include "empty_folder.h"
#include "obscura/io/json_scene.h"
#include "obscura/math/error.h"
#include "tiny_render.h"

namespace {

// The scene "lives" in an empty folder, so relative model and texture names find nothing.
const std::string& scene_path() {
  static const std::string path =
      obscura::fuzz::make_empty_folder("obscura-render-scene-fuzz-empty") + "/fuzz.json";
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    std::string text(reinterpret_cast<const char*>(data), size);
    obscura::Scene scene = obscura::load_json_scene_text(text, scene_path());
    scene.validate();
    obscura::fuzz::render_tiny(scene, scene.camera);
  } catch (const obscura::Error&) {
    // a clear error for bad input: the expected outcome
  }
  return 0;
}
