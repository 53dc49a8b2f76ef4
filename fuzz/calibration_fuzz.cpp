// libFuzzer target for the calibration-file readers (`--calibration FILE`): the first byte picks
// the reader — 'y' OpenCV YAML, 'j' OpenCV JSON, 'n' NeRF transforms.json, 'c' COLMAP (the rest
// is cameras.txt, then, after a NUL byte when there is one, images.txt); any other byte modulo 4
// in that order. A calibration read is then given to a camera, which projects and unprojects a
// point, and written back in every format. An obscura::Error is the expected outcome for bad
// input; anything else escaping, a crash, a sanitizer report, a leak or > 2 GB is a finding.
#include <cstdint>
#include <string>

#include "calibration_input.h"
#include "obscura/io/calibration_file.h"
#include "obscura/math/error.h"

namespace {

void use(const obscura::CameraCalibration& calibration) {
  obscura::Camera camera;
  obscura::apply_calibration(camera, calibration);
  camera.validate();
  obscura::Point2d centre(0.5 * camera.film.width_px, 0.5 * camera.film.height_px);
  if (auto world = camera.unproject(centre, 2.0)) camera.project(*world);
  for (obscura::CalibrationFormat format :
       {obscura::CalibrationFormat::opencv_yaml, obscura::CalibrationFormat::opencv_json,
        obscura::CalibrationFormat::nerf}) {
    try {
      obscura::calibration_text(format, calibration);
    } catch (const obscura::Error&) {
      // a lens model or skew the format cannot hold
    }
  }
  try {
    obscura::colmap_model_text(calibration);
  } catch (const obscura::Error&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  try {
    std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    use(obscura::fuzz::read_calibration(static_cast<char>(data[0]), text));
  } catch (const obscura::Error&) {
    // a clear error for bad input: the expected outcome
  }
  return 0;
}
