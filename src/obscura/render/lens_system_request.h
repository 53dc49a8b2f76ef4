// The lens-system part of a camera request (render/camera_request.h): --lens NAME (a built-in
// design) or --lens-file PATH (a prescription, docs/camera.md), with the thin lens's --fstop (stops
// the iris down),
// --focus-distance (from the sensor), --aperture-blades/--aperture-rotation and --sensor (its
// width) applying to it.
#pragma once

#include "obscura/render/camera_request.h"

namespace obscura {

// Makes the camera a lens-system camera when --lens or --lens-file is given, then applies the
// options above to a lens-system camera. Returns whether the camera is one (then the perspective
// options do not apply; those given throw RequestError).
bool apply_lens_system_overrides(Camera& camera, const CameraRequest& overrides);

}  // namespace obscura
