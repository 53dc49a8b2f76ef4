// The ground-truth file: every channel of a GroundTruthBuffer in one OpenEXR file (32-bit float,
// channels named as film/ground_truth_buffer.h lists them), with the exact camera in its header
// as string attributes (docs/ground_truth.md lists them):
//   obscura:camera:projection         the projection's name and its parameters
//   obscura:camera:resolution         "W H" of the full image, pixels
//   obscura:camera:pixel_aspect       a pixel's width / height
//   obscura:camera:crop               "x0 y0 x1 y1": the full-image pixels the file covers
//   obscura:camera:K                  "fx fy cx cy" in OpenCV's convention (integer pixel
//                                      centres), when the projection has intrinsics
//   obscura:camera:fov_degrees        "horizontal vertical"
//   obscura:camera:near_far           "near far" (m)
//   obscura:camera:clip_from_camera   16 numbers, row-major (projections with a matrix)
//   obscura:camera:world_from_camera  16 numbers, row-major, at the reference time
//   obscura:camera:axes               the frames' conventions, in words
//   obscura:ground_truth:times        "first second" (s): the reference time and flow's other end
#pragma once

#include <string>

#include "obscura/camera/camera.h"
#include "obscura/film/ground_truth_buffer.h"
#include "obscura/io/image_io.h"
#include "obscura/scene/ground_truth.h"

namespace obscura {

// The header attributes above, for `camera` and `times`.
ImageMetadata ground_truth_metadata(const Camera& camera, const GroundTruthTimes& times);

// Writes the file atomically (image_io's write_exr_data); `path` must end in .exr. Throws
// obscura::Error naming the path.
void write_ground_truth(const std::string& path, const GroundTruthBuffer& buffer,
                        const Camera& camera, const GroundTruthTimes& times);

}  // namespace obscura
