// libFuzzer target that renders through the camera a calibration file makes: the input is the
// `calibration` target's (calibration_input.h: the first byte picks the reader), the calibration
// read is applied to a camera as `--calibration FILE` does, and the camera renders the Cornell
// box as a tiny frame with both renderers, its ground truth and glare (tiny_render.h: a crop
// window of at most 8 × 8 pixels at the film's centre). Seeds: the `calibration`
// target's, and `regress-translation-2e18` (a camera 2e18 m away, where Embree aborted).
// An obscura::Error is the expected outcome for bad input; anything else escaping, a crash, a
// sanitizer report, a non-finite pixel, a leak or > 2 GB is a finding.
#include <cstdint>
#include <string>

#include "calibration_input.h"
#include "obscura/io/calibration_file.h"
#include "obscura/math/error.h"
#include "obscura/scene/builtin_scenes.h"
#include "tiny_render.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const obscura::Scene scene = [] {
    obscura::Scene box = obscura::make_builtin_scene("cornell-box");
    box.validate();
    return box;
  }();
  if (size == 0) return 0;
  try {
    std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    obscura::Camera camera = scene.camera;
    obscura::apply_calibration(camera,
                               obscura::fuzz::read_calibration(static_cast<char>(data[0]), text));
    obscura::fuzz::render_tiny(scene, camera, {.glare = true});
  } catch (const obscura::Error&) {
    // a clear error for bad input: the expected outcome
  }
  return 0;
}
