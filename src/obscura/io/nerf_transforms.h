// NeRF's transforms.json as instant-ngp and nerfstudio read it: intrinsics "fl_x", "fl_y"
// (or "camera_angle_x"), "cx", "cy", "w", "h", distortion "k1" "k2" "k3" "k4" "p1" "p2" with
// "camera_model" OPENCV (OpenCV's k1 k2 p1 p2 k3) or OPENCV_FISHEYE (Kannala–Brandt k1..k4), at
// the top level or per frame (a frame's value wins), and "frames" of {"file_path",
// "transform_matrix"}: camera → world, 4×4 rows, in OpenGL's camera frame (X right, Y up,
// looking down −Z), which is Obscura's. Keys this reader does not use (aabb_scale, ...) are
// ignored, as those tools do.
//
// Pixel convention: instant-ngp and nerfstudio shoot a pixel's ray through its centre at
// (x + 0.5, y + 0.5) and measure cx, cy from the top-left corner, as COLMAP does (nerfstudio's
// COLMAP conversion copies COLMAP's cx unchanged): their cx, cy are OpenCV's plus 0.5. A file
// without cx, cy means the image centre, w/2 and h/2.
#pragma once

#include <string>
#include <vector>

#include "obscura/io/camera_calibration.h"

namespace obscura {

// The camera of frame `image_name` (its file_path, or file_path's last component, with or
// without extension; empty: the first frame) with that frame's pose; a file without frames
// gives the camera without a pose. Throws obscura::Error naming the file, the JSON path and what
// was expected.
CameraCalibration parse_nerf_transforms(const std::string& text, const std::string& file,
                                        const std::string& image_name);

// A transforms.json with one frame (file_path the calibration's image_name, or
// "image.png"; the identity pose when it has none). Throws obscura::Error for what the format
// cannot hold: skew, OpenCV's rational (k4..k6), thin-prism or tilt terms, f-theta and classic
// fisheyes other than the equidistant one.
std::string nerf_transforms_text(const CameraCalibration& calibration);
// A transforms.json with a frame for each calibration (its image_name as file_path, its pose):
// intrinsics all frames share at the top level, otherwise each frame's own in the frame.
std::string nerf_transforms_text(const std::vector<CameraCalibration>& frames);

}  // namespace obscura
