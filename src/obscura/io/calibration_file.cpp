#include "obscura/io/calibration_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "obscura/camera/lens_distortion.h"
#include "obscura/io/colmap_model.h"
#include "obscura/io/input_file.h"
#include "obscura/io/json_reader.h"
#include "obscura/io/nerf_transforms.h"
#include "obscura/io/opencv_calibration.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

// Calibration files are small; NeRF files with thousands of frames stay far below this.
constexpr uint64_t kMaxCalibrationFileBytes = uint64_t(64) << 20;

std::string read_text(const std::string& path) {
  check_input_file(path, kMaxCalibrationFileBytes, "calibration files");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw Error(path, "cannot be read");
  return text.str();
}

bool is_nerf(const std::string& text, const std::string& name) {
  nlohmann::ordered_json root = parse_json_text(text, name);
  return root.is_object() &&
         (root.contains("frames") || root.contains("fl_x") || root.contains("camera_angle_x"));
}

void single_camera(const std::string& image_name, const std::string& path) {
  if (!image_name.empty())
    throw Error(path, "an OpenCV calibration file holds one camera; --calibration-image '" +
                          image_name + "' applies to COLMAP and NeRF files");
}

CameraCalibration parse_json_calibration(const std::string& text, const std::string& name,
                                         const std::string& image_name) {
  if (is_nerf(text, name)) return parse_nerf_transforms(text, name, image_name);
  single_camera(image_name, name);
  return parse_opencv_json(text, name);
}

}  // namespace

std::optional<CalibrationFormat> calibration_format_from_name(const std::string& name) {
  if (name == "opencv-yaml") return CalibrationFormat::opencv_yaml;
  if (name == "opencv-json") return CalibrationFormat::opencv_json;
  if (name == "colmap") return CalibrationFormat::colmap;
  if (name == "nerf") return CalibrationFormat::nerf;
  return std::nullopt;
}

const char* calibration_format_name(CalibrationFormat format) {
  switch (format) {
    case CalibrationFormat::opencv_yaml:
      return "opencv-yaml";
    case CalibrationFormat::opencv_json:
      return "opencv-json";
    case CalibrationFormat::colmap:
      return "colmap";
    case CalibrationFormat::nerf:
      return "nerf";
  }
  return "?";
}

CameraCalibration read_calibration_file(const std::string& path, const std::string& image_name) {
  namespace fs = std::filesystem;
  fs::path p(path);
  std::error_code error;
  bool folder = fs::is_directory(p, error);
  std::string file_name = p.filename().string();
  if (folder || file_name == "cameras.txt" || file_name == "images.txt") {
    fs::path dir = folder ? p : p.parent_path();
    std::string cameras = (dir / "cameras.txt").string(), images = (dir / "images.txt").string();
    if (!fs::exists(cameras, error))
      throw Error(path, "a COLMAP model needs cameras.txt; " + cameras + " does not exist");
    std::string cameras_text = read_text(cameras);
    if (!fs::exists(images, error))
      return parse_colmap_model(cameras_text, cameras, nullptr, images, image_name);
    std::string images_text = read_text(images);
    return parse_colmap_model(cameras_text, cameras, &images_text, images, image_name);
  }
  std::string extension = p.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".yaml" || extension == ".yml") {
    single_camera(image_name, path);
    return parse_opencv_yaml(read_text(path), path);
  }
  if (extension == ".json") return parse_json_calibration(read_text(path), path, image_name);
  throw Error(path,
              "unknown calibration file type; expected an OpenCV .yaml/.yml or .json file, "
              "a NeRF transforms .json, or a COLMAP model (its folder, cameras.txt or "
              "images.txt)");
}

CameraCalibration parse_calibration_text(const std::string& text, const std::string& name,
                                         const std::string& image_name) {
  if (text.rfind("%YAML", 0) == 0) {
    single_camera(image_name, name);
    return parse_opencv_yaml(text, name);
  }
  size_t first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '{')
    return parse_json_calibration(text, name, image_name);
  return parse_colmap_model(text, name, nullptr, "", image_name);
}

std::string calibration_text(CalibrationFormat format, const CameraCalibration& calibration) {
  switch (format) {
    case CalibrationFormat::opencv_yaml:
      return opencv_yaml_text(calibration);
    case CalibrationFormat::opencv_json:
      return opencv_json_text(calibration);
    case CalibrationFormat::nerf:
      return nerf_transforms_text(calibration);
    case CalibrationFormat::colmap:
      break;
  }
  throw Error("COLMAP", "a COLMAP model is two files (colmap_model_text)");
}

namespace {

std::string short_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace

std::vector<std::string> calibration_omissions(CalibrationFormat format,
                                               const CameraCalibration& calibration) {
  std::vector<std::string> out;
  if (format != CalibrationFormat::colmap && format != CalibrationFormat::nerf) return out;
  const CalibratedProjection& p = calibration.projection;
  if (!(p.max_field_angle_degrees > 0)) return out;
  // The limit matters only where it is narrower than what the lens model reaches by itself.
  CalibratedProjection unlimited = p;
  unlimited.max_field_angle_degrees = 0;
  const double own = LensMap(unlimited.lens).max_field_angle() * 180 / 3.14159265358979323846;
  if (p.max_field_angle_degrees >= own - 1e-9) return out;
  const bool fisheye = !is_planar(p.lens);
  const std::string name =
      format == CalibrationFormat::colmap ? "COLMAP" : "NeRF's transforms.json";
  out.push_back(name + " cannot hold the " + (fisheye ? "fisheye" : "lens") + "'s " +
                exact_number(2 * p.max_field_angle_degrees) +
                "° field limit (max_field_angle_degrees " +
                exact_number(p.max_field_angle_degrees) + "): left out; a camera read back from " +
                "it sees as far as its " + lens_model_name(p.lens) + " model reaches (" +
                short_number(2 * own) + "°), not only the circle the images show");
  return out;
}

}  // namespace obscura
