// OpenCV calibration files as cv::FileStorage writes them, in YAML ("%YAML:1.0" first line) and
// JSON: K as the 3×3 !!opencv-matrix "camera_matrix" (aliases "cameraMatrix", "K"), the
// coefficients as "distortion_coefficients" (aliases "distCoeffs", "dist_coeffs", "D"),
// "image_width" and "image_height", and optionally the pose "R" (3×3, or "rvec": Rodrigues) and
// "T" (aliases "t", "tvec") with x_cam = R·X_world + T in OpenCV's camera frame.
//
// Pinhole or fisheye: the model is cv::fisheye's Kannala–Brandt when "distortion_model" is
// "fisheye", "kannala-brandt" or "equidistant" (ROS's name), or "fisheye" is 1/true; it is
// OpenCV's pinhole when "distortion_model" is "opencv", "plumb_bob" or "rational_polynomial",
// or "fisheye" is 0/false. Without either key, 4 coefficients stored under "D" (as cv::fisheye's
// samples and Kalibr do) mean fisheye; anything else is the pinhole model. Obscura writes
// "distortion_model" always, and "max_field_angle_degrees" when the field is limited.
#pragma once

#include <string>

#include "obscura/io/camera_calibration.h"

namespace obscura {

// Throw obscura::Error naming `file`, the line (YAML) or JSON path, and what was expected.
CameraCalibration parse_opencv_yaml(const std::string& text, const std::string& file);
CameraCalibration parse_opencv_json(const std::string& text, const std::string& file);

// The files cv::FileStorage would write for `calibration` (the pose when it has one). Throws
// obscura::Error for a lens model OpenCV has no counterpart for (f-theta, equisolid,
// stereographic, orthographic fisheye; equidistant is written as Kannala–Brandt with k = 0).
std::string opencv_yaml_text(const CameraCalibration& calibration);
std::string opencv_json_text(const CameraCalibration& calibration);

}  // namespace obscura
