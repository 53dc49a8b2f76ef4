// OpenCV calibration files in YAML, read with yaml-cpp. cv::FileStorage starts its YAML with the
// nonstandard directive "%YAML:1.0", which YAML parsers reject; it is blanked before parsing.
#include <yaml-cpp/yaml.h>

#include <cerrno>
#include <cstdlib>

#include "obscura/io/opencv_calibration.h"
#include "obscura/io/opencv_calibration_entries.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

std::string where(const std::string& file, const YAML::Node& node) {
  return file + ":" + std::to_string(node.Mark().line + 1);
}

bool parse_double(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno == 0;
}

double number(const YAML::Node& node, const std::string& file, const std::string& what) {
  double v = 0;
  if (!node.IsScalar() || !parse_double(node.Scalar(), v))
    throw Error(where(file, node), what + ": expected a number");
  return v;
}

OpenCvEntry read_matrix(const YAML::Node& node, const std::string& key, const std::string& file) {
  OpenCvEntry e = obscura::matrix_entry({}, 0, 0, where(file, node));
  for (const char* field : {"rows", "cols", "data"})
    if (!node[field]) throw Error(e.where, key + ": an opencv-matrix without '" + field + "'");
  double rows = number(node["rows"], file, key + ".rows");
  double cols = number(node["cols"], file, key + ".cols");
  if (!(rows >= 1 && rows <= 64 && cols >= 1 && cols <= 64))
    throw Error(e.where, key + ": expected rows and cols from 1 to 64");
  e.rows = int(rows);
  e.cols = int(cols);
  const YAML::Node& data = node["data"];
  if (!data.IsSequence()) throw Error(where(file, data), key + ".data: expected a [ ... ] list");
  if (data.size() != size_t(e.rows * e.cols))
    throw Error(where(file, data), key + ".data: expected " + std::to_string(e.rows * e.cols) +
                                       " numbers (rows x cols); got " +
                                       std::to_string(data.size()));
  for (const YAML::Node& v : data) e.values.push_back(number(v, file, key + ".data"));
  return e;
}

OpenCvEntry entry(const YAML::Node& node, const std::string& key, const std::string& file) {
  if (node.IsScalar()) {
    double v = 0;
    if (parse_double(node.Scalar(), v)) return number_entry(v, where(file, node));
    return text_entry(node.Scalar(), where(file, node));
  }
  if (node.IsMap() && (node.Tag() == "tag:yaml.org,2002:opencv-matrix" || node["data"]))
    return read_matrix(node, key, file);
  if (node.IsSequence()) {  // a std::vector<double>, as one column
    OpenCvEntry e = obscura::matrix_entry({}, 0, 0, where(file, node));
    for (const YAML::Node& v : node) e.values.push_back(number(v, file, key));
    e.rows = int(e.values.size());
    e.cols = 1;
    return e;
  }
  return other_entry(where(file, node));
}

std::string yaml_number(double v) {
  return exact_number(v);
}

}  // namespace

CameraCalibration parse_opencv_yaml(const std::string& text, const std::string& file) {
  std::string yaml = text;
  if (yaml.rfind("%YAML:", 0) == 0) {
    size_t end = yaml.find('\n');
    yaml.replace(0, end == std::string::npos ? yaml.size() : end, "");
  }
  OpenCvEntries entries;
  try {
    YAML::Node root = YAML::Load(yaml);
    if (!root.IsMap()) throw Error(file, "expected a YAML mapping of calibration entries");
    for (const auto& item : root) {
      if (!item.first.IsScalar()) continue;
      std::string key = item.first.Scalar();
      entries[key] = entry(item.second, key, file);
    }
  } catch (const YAML::Exception& e) {
    throw Error(file + ":" + std::to_string(e.mark.line + 1), "YAML: " + e.msg);
  }
  return calibration_from_opencv_entries(entries, file);
}

std::string opencv_yaml_text(const CameraCalibration& calibration) {
  std::string out = "%YAML:1.0\n---\n";
  for (const OpenCvOutput& o : opencv_entries_of(calibration)) {
    const OpenCvEntry& e = o.entry;
    out += o.name + ": ";
    if (e.kind == OpenCvEntry::Kind::number) {
      out += yaml_number(e.values[0]) + "\n";
    } else if (e.kind == OpenCvEntry::Kind::text) {
      out += "\"" + e.text + "\"\n";
    } else {
      out += "!!opencv-matrix\n   rows: " + std::to_string(e.rows) +
             "\n   cols: " + std::to_string(e.cols) + "\n   dt: d\n   data: [ ";
      for (size_t i = 0; i < e.values.size(); ++i)
        out += (i ? ", " : "") + yaml_number(e.values[i]);
      out += " ]\n";
    }
  }
  return out;
}

}  // namespace obscura
