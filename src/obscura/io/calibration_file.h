// Calibration files by name: which format a file is, reading it, and the text of each format.
// The formats and their conventions: opencv_calibration.h, colmap_model.h, nerf_transforms.h.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "obscura/io/camera_calibration.h"

namespace obscura {

enum class CalibrationFormat { opencv_yaml, opencv_json, colmap, nerf };

// "opencv-yaml", "opencv-json", "colmap", "nerf" (the names of `obscura camera --export`).
std::optional<CalibrationFormat> calibration_format_from_name(const std::string& name);
const char* calibration_format_name(CalibrationFormat format);

// Reads a calibration file, by its name and then its content:
//   *.yaml, *.yml               OpenCV FileStorage YAML
//   *.json                      NeRF transforms.json when it has "frames", "fl_x" or
//                               "camera_angle_x"; otherwise OpenCV FileStorage JSON
//   a folder, cameras.txt or    COLMAP's text model: the folder's cameras.txt, with the pose
//   images.txt                  from its images.txt when there is one
// `image_name` picks the image of a COLMAP or NeRF file (empty: the first); other formats hold
// one camera, and naming an image is an error. Throws obscura::Error naming the file.
CameraCalibration read_calibration_file(const std::string& path, const std::string& image_name);

// The same choice made from a file's content alone, for text in memory: YAML when it starts
// with "%YAML", JSON (NeRF or OpenCV, as above) when it starts with '{', otherwise COLMAP's
// cameras.txt. `name` stands for the file in messages.
CameraCalibration parse_calibration_text(const std::string& text, const std::string& name,
                                         const std::string& image_name);

// The text of an OpenCV YAML or JSON file or a transforms.json (COLMAP's two files:
// colmap_model.h). Throws obscura::Error when the format cannot hold the calibration.
std::string calibration_text(CalibrationFormat format, const CameraCalibration& calibration);

// What `format` leaves out of `calibration` without refusing it, one warning each, naming the
// format and the term: COLMAP and NeRF have no field limit, so a lens limited to a narrower field
// than its model reaches (a 190° fisheye circle) is written without the limit ("COLMAP cannot
// hold the fisheye's 190° field limit: left out; ..."). Empty when the file holds everything.
// (What a format cannot hold at all is refused by the writers instead.)
std::vector<std::string> calibration_omissions(CalibrationFormat format,
                                               const CameraCalibration& calibration);

}  // namespace obscura
