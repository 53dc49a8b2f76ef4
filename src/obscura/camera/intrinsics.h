// The computer-vision intrinsics matrix K of a perspective camera, in OpenCV's conventions:
//         | fx  0  cx |
//     K = |  0 fy  cy |,   (u, v) = (fx·X/Z + cx, fy·Y/Z + cy)
//         |  0  0   1 |
// for a point (X, Y, Z) in OpenCV's camera frame (X right, Y down, Z forward, i.e. Obscura's
// camera frame with Y and Z negated) and pixel coordinates whose pixel centres are integers.
// Obscura's pixel centres are half-integers, so raster = (u + ½, v + ½). fx = f·W / film width.
#pragma once

#include "obscura/camera/calibrated_projection.h"
#include "obscura/camera/camera.h"

namespace obscura {

// The intrinsics of a perspective camera (at its current focus: fx uses the image distance), or
// a calibrated camera's K scaled to the film's resolution. Throws obscura::Error for other
// projections.
Intrinsics intrinsics(const Camera& camera);

// A perspective camera reproducing K on a width × height image: horizontal sensor fit on a
// sensor `sensor_width_mm` wide, f = fx · sensor width / W, pixel aspect (pixel width / height)
// fy / fx, and lens shift for an off-centre principal point.
// The pose is the identity; set world_from_camera from the extrinsics. Throws obscura::Error
// naming the bad value (fx, fy ≤ 0, zero resolution).
Camera camera_from_intrinsics(const Intrinsics& k, int width_px, int height_px,
                              double sensor_width_mm = 36);

}  // namespace obscura
