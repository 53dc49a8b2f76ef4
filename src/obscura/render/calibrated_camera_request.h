// The calibrated-camera part of a camera request (render/camera_request.h; docs/camera.md,
// "Calibrated cameras"): calibration, calibration_image, projection "calibrated", intrinsics,
// calibration_size, distortion, max_field_angle_degrees.
#pragma once

#include "obscura/render/camera_request.h"

namespace obscura {

// Loads --calibration into `camera` (projection, image size as the film's, pose when the file
// has one). A file that cannot be read or is malformed throws obscura::Error (exit 1).
void apply_calibration_file(Camera& camera, const CameraRequest& overrides);

// Applies --projection calibrated, --intrinsics, --calibration-size, --distortion and
// --max-field-angle: any of them makes the camera calibrated (a perspective camera keeps its
// framing as K; pose, clipping, shutter and exposure stay). Malformed values throw RequestError
// naming the option and the value.
void apply_calibrated_overrides(Camera& camera, const CameraRequest& overrides);

}  // namespace obscura
