// `obscura camera --export FORMAT [--output PATH]`: the resolved camera as a calibration file
// (K, lens model, image size, and the pose at the shutter's open time).
//   opencv-yaml, opencv-json, nerf: to stdout, or to the file --output names (written
//                                   atomically)
//   colmap: cameras.txt, images.txt and an empty points3D.txt in the folder --output names
//           (created if missing; each file written atomically), as COLMAP's text model is
#pragma once

#include <optional>
#include <string>

#include "obscura/camera/camera.h"

namespace obscura::app {

// Throws UsageError for an unknown format or colmap without --output; obscura::Error when the
// format cannot express the camera (orthographic, spherical, a lens model it lacks) or a file
// cannot be written.
void export_calibration(const Camera& camera, const std::string& format,
                        const std::optional<std::string>& output);

}  // namespace obscura::app
