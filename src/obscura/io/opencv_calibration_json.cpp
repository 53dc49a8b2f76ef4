// OpenCV calibration files in JSON, as cv::FileStorage writes them: matrices are objects with
// "type_id": "opencv-matrix", "rows", "cols", "dt" and "data".
#include <cmath>

#include "obscura/io/json_reader.h"
#include "obscura/io/opencv_calibration.h"
#include "obscura/io/opencv_calibration_entries.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

using Json = nlohmann::ordered_json;

double number(const Json& value, const std::string& where, const std::string& what) {
  if (!value.is_number()) throw Error(where, what + ": expected a number");
  return value.get<double>();
}

OpenCvEntry read_matrix(const Json& value, const std::string& where) {
  OpenCvEntry e = obscura::matrix_entry({}, 0, 0, where);
  for (const char* field : {"rows", "cols", "data"})
    if (!value.contains(field))
      throw Error(where, std::string("an opencv-matrix without '") + field + "'");
  double rows = number(value["rows"], where, "rows"), cols = number(value["cols"], where, "cols");
  if (!(rows >= 1 && rows <= 64 && cols >= 1 && cols <= 64 && rows == std::floor(rows) &&
        cols == std::floor(cols)))
    throw Error(where, "expected rows and cols from 1 to 64");
  e.rows = int(rows);
  e.cols = int(cols);
  const Json& data = value["data"];
  if (!data.is_array() || data.size() != size_t(e.rows * e.cols))
    throw Error(where + ".data", "expected an array of " + std::to_string(e.rows * e.cols) +
                                     " numbers (rows x cols)");
  for (const Json& v : data) e.values.push_back(number(v, where + ".data", "element"));
  return e;
}

OpenCvEntry entry(const Json& value, const std::string& where) {
  if (value.is_number()) return number_entry(value.get<double>(), where);
  if (value.is_boolean()) return text_entry(value.get<bool>() ? "true" : "false", where);
  if (value.is_string()) return text_entry(value.get<std::string>(), where);
  if (value.is_object() && ((value.contains("type_id") && value["type_id"] == "opencv-matrix") ||
                            value.contains("data")))
    return read_matrix(value, where);
  if (value.is_array()) {  // a std::vector<double>, as one column
    OpenCvEntry e = obscura::matrix_entry({}, 0, 0, where);
    for (const Json& v : value) e.values.push_back(number(v, where, "element"));
    e.rows = int(e.values.size());
    e.cols = 1;
    return e;
  }
  return other_entry(where);
}

}  // namespace

CameraCalibration parse_opencv_json(const std::string& text, const std::string& file) {
  Json root = parse_json_text(text, file);
  if (!root.is_object()) throw Error(file, "expected a JSON object of calibration entries");
  OpenCvEntries entries;
  for (const auto& [key, value] : root.items()) entries[key] = entry(value, file + ": $." + key);
  return calibration_from_opencv_entries(entries, file);
}

std::string opencv_json_text(const CameraCalibration& calibration) {
  std::string out = "{\n";
  std::vector<OpenCvOutput> entries = opencv_entries_of(calibration);
  for (size_t n = 0; n < entries.size(); ++n) {
    const OpenCvEntry& e = entries[n].entry;
    out += "    \"" + entries[n].name + "\": ";
    if (e.kind == OpenCvEntry::Kind::number) {
      out += exact_number(e.values[0]);
    } else if (e.kind == OpenCvEntry::Kind::text) {
      out += "\"" + e.text + "\"";
    } else {
      out += "{\n        \"type_id\": \"opencv-matrix\",\n        \"rows\": " +
             std::to_string(e.rows) + ",\n        \"cols\": " + std::to_string(e.cols) +
             ",\n        \"dt\": \"d\",\n        \"data\": [ ";
      for (size_t i = 0; i < e.values.size(); ++i)
        out += (i ? ", " : "") + exact_number(e.values[i]);
      out += " ]\n    }";
    }
    out += n + 1 < entries.size() ? ",\n" : "\n";
  }
  return out + "}\n";
}

}  // namespace obscura
