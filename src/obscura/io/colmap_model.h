// COLMAP's text model (https://colmap.github.io/format.html): cameras.txt, one camera a line
// ("CAMERA_ID MODEL WIDTH HEIGHT PARAMS[]"), and images.txt, two lines an image
// ("IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME", then its 2D points, possibly empty), the
// quaternion and translation taking world points into the camera's frame, which is OpenCV's.
//
// Pixel convention: COLMAP puts the top-left pixel's corner at (0, 0) and its centre at
// (0.5, 0.5), OpenCV that centre at (0, 0); so COLMAP's cx, cy are OpenCV's plus 0.5 (the focal
// lengths and coefficients are the same). Reading subtracts ½, writing adds it.
//
// Models: SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL, OPENCV, FULL_OPENCV (OpenCV's pinhole
// model), OPENCV_FISHEYE, SIMPLE_RADIAL_FISHEYE, RADIAL_FISHEYE (Kannala–Brandt: θd =
// θ(1 + k1θ² + k2θ⁴ …)). COLMAP has no skew, no thin-prism or tilt terms for the pinhole model
// and no f-theta or classic fisheye but the equidistant one: writing those is an error.
#pragma once

#include <string>
#include <vector>

#include "obscura/io/camera_calibration.h"

namespace obscura {

// The camera of image `image_name` (its NAME; empty: the first image) with that image's pose;
// without images.txt (`images_text` null), the first camera without a pose. `cameras_file` and
// `images_file` name the files in messages. Throws obscura::Error naming the file, line and
// what was expected.
CameraCalibration parse_colmap_model(const std::string& cameras_text,
                                     const std::string& cameras_file,
                                     const std::string* images_text, const std::string& images_file,
                                     const std::string& image_name);

// cameras.txt and images.txt holding `calibration` as camera 1 and image 1 (its image_name, or
// "image.png"; spaces become '_'); a calibration without a pose is written with R = I, t = 0.
struct ColmapModelText {
  std::string cameras, images;
};
ColmapModelText colmap_model_text(const CameraCalibration& calibration);
// The model of many images (image i + 1 is images[i], named by its image_name, posed by its
// pose): images whose intrinsics are the same (model, size and every parameter) share a camera,
// numbered in order of first use.
ColmapModelText colmap_model_text(const std::vector<CameraCalibration>& images);

}  // namespace obscura
