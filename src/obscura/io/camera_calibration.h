// A camera as calibration toolboxes exchange it: intrinsics K and a lens model on an image of a
// given size, and optionally the pose of one image. The file formats (OpenCV's FileStorage
// YAML/JSON, COLMAP's text model, NeRF's transforms.json) read into and write from this one
// description; docs/camera.md ("Calibrated cameras") sets their conventions side by side.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "obscura/camera/camera.h"
#include "obscura/math/transform.h"

namespace obscura {

struct CameraCalibration {
  // K in OpenCV's pixel convention (integer pixel centres) on an image of width_px × height_px
  // (both > 0), the lens model and its field limit.
  CalibratedProjection projection;
  // Camera → world in Obscura's camera frame (X right, Y up, looking down −Z), when the file
  // gives a pose.
  std::optional<Transform> world_from_camera;
  std::string image_name;  // the image the pose belongs to (COLMAP, NeRF); may be empty
};

// The calibration of `camera` at its film's resolution, posed at the shutter's open time: a
// perspective camera's K (camera/intrinsics.h) with no distortion, a calibrated camera's K
// scaled to the film with its lens model, a lens system's fitted camera
// (camera/lens_system_fit.h: OpenCV's pinhole or Kannala–Brandt model) posed at its centre of
// projection. Throws obscura::Error naming the projection when K
// cannot describe it (orthographic, spherical, fisheye: use a calibrated fisheye lens model).
CameraCalibration calibration_of(const Camera& camera);

// Gives `camera` the calibration's projection, its image size as the film's and, when it has
// one, its pose; near/far, shutter and exposure stay. Depth of field is turned off (calibrated
// lens models are pinholes).
void apply_calibration(Camera& camera, const CameraCalibration& calibration);

// A pose as computer-vision toolboxes write it: x_cam = R·X_world + t, with x_cam in OpenCV's
// camera frame (X right, Y down, Z forward).
struct CvExtrinsics {
  std::array<std::array<double, 3>, 3> r;  // rows
  std::array<double, 3> t;
};
CvExtrinsics cv_extrinsics(const Transform& world_from_camera);
// Throws obscura::Error naming `where` when R is not a rotation (orthonormal, determinant +1,
// to 1e-6) or a value is not finite.
Transform world_from_camera_of(const CvExtrinsics& extrinsics, const std::string& where);

// Throws obscura::Error naming `where` for a calibration that no camera can use (an image size
// ≤ 0 or above the CLI's image limit, an invalid K or lens model).
void validate_calibration(const CameraCalibration& calibration, const std::string& where);

// Numbers as calibration files are written: the shortest text that reads back to the same
// double (std::to_chars), "0" for ±0.
std::string exact_number(double value);

}  // namespace obscura
