// Options of a lens-system camera: --lens NAME (a built-in design) or --lens-file PATH (a
// prescription, docs/camera.md), with the thin lens's --fstop (stops the iris down),
// --focus-distance (from the sensor), --aperture-blades/--aperture-rotation and --sensor (its
// width) applying to it.
#pragma once

#include "camera_options.h"

namespace obscura::app {

// Makes the camera a lens-system camera when --lens or --lens-file is given, then applies the
// options above to a lens-system camera. Returns whether the camera is one (then the perspective
// options do not apply; those given throw UsageError).
bool apply_lens_system_overrides(Camera& camera, const CameraOverrides& overrides);

}  // namespace obscura::app
