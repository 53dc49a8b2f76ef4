// The part of reading and writing OpenCV calibration files that YAML and JSON share: the
// top-level entries of a cv::FileStorage file, mapped to and from a CameraCalibration.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "obscura/io/camera_calibration.h"

namespace obscura {

// One top-level value: a number, a string, or a matrix (an !!opencv-matrix, or a sequence of
// numbers as one column).
struct OpenCvEntry {
  enum class Kind { number, text, matrix, other } kind = Kind::other;
  std::vector<double> values;  // number: one; matrix: rows × cols, row by row
  int rows = 0, cols = 0;
  std::string text;
  std::string where;  // "file:line" or "file: $.key", for messages
};
using OpenCvEntries = std::map<std::string, OpenCvEntry>;

OpenCvEntry number_entry(double value, std::string where = "");
OpenCvEntry text_entry(std::string text, std::string where = "");
OpenCvEntry matrix_entry(std::vector<double> values, int rows, int cols, std::string where = "");
OpenCvEntry other_entry(std::string where);

// Throws obscura::Error naming the entry (or `file`) and what was expected.
CameraCalibration calibration_from_opencv_entries(const OpenCvEntries& entries,
                                                  const std::string& file);

// The entries to write, in order: name and value (matrices with their shape).
struct OpenCvOutput {
  std::string name;
  OpenCvEntry entry;
};
std::vector<OpenCvOutput> opencv_entries_of(const CameraCalibration& calibration);

}  // namespace obscura
